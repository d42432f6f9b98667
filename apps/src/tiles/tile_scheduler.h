/*
 * pcl_ext_tiles: who runs which tile, in one process or shared among MPI ranks.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief Hands out the tiles of a phase (estimate, tile) to the processes of a run:
 * all to the one process without MPI; under `mpirun`, to whichever rank asks next (an
 * atomic counter on rank 0, so fast ranks take more tiles), with rank 0 planning and
 * merging. */
class TileScheduler {
public:
  virtual ~TileScheduler() = default;

  /** \brief This process's rank and the number of processes. */
  virtual int
  getRank () const = 0;
  virtual int
  getSize () const = 0;

  /** \brief Start a phase of \a tiles tiles (every process calls it). */
  virtual void
  startPhase (std::size_t tiles) = 0;

  /** \brief The next tile of the phase for this process; false when none is left. */
  virtual bool
  next (std::size_t& tile) = 0;

  /** \brief Wait for every process; \return whether all of them passed \a ok. */
  virtual bool
  allOk (bool ok) = 0;
};

/** \brief Print this process's summary line: "[Rank r: ]done: <what>, <points> points,
 * <seconds> s, peak memory <MB> MB" (or "failed after <what>, ..."). */
void
printRunSummary (const TileScheduler& scheduler,
                 bool ok,
                 const std::string& what,
                 std::uint64_t points,
                 double seconds);

/** \brief The scheduler of this process: MPI when the tool was built with it and
 * started by an MPI launcher (argc and argv go to MPI_Init), one process otherwise. */
std::unique_ptr<TileScheduler>
makeTileScheduler (int& argc, char**& argv);
} // namespace apps
} // namespace pcl_ext
