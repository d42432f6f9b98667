/*
 * pcl_ext_tiles: who runs which tile, in one process or shared among MPI ranks.
 */
#include "tile_scheduler.h"

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sys/resource.h>

#ifdef PCL_EXT_HAVE_MPI
#include <mpi.h>
#endif

namespace pcl_ext {
namespace apps {
namespace {
class SerialScheduler : public TileScheduler {
public:
  int
  getRank () const override
  {
    return 0;
  }
  int
  getSize () const override
  {
    return 1;
  }
  void
  startPhase (std::size_t tiles) override
  {
    tiles_ = tiles;
    next_ = 0;
  }
  bool
  next (std::size_t& tile) override
  {
    if (next_ >= tiles_)
      return false;
    tile = next_++;
    return true;
  }
  bool
  allOk (bool ok) override
  {
    return ok;
  }

private:
  std::size_t tiles_ = 0, next_ = 0;
};

#ifdef PCL_EXT_HAVE_MPI
/** Ranks take tiles from a counter on rank 0 (MPI_Fetch_and_op, passive target). */
class MpiScheduler : public TileScheduler {
public:
  MpiScheduler (int& argc, char**& argv)
  {
    MPI_Init (&argc, &argv);
    MPI_Comm_rank (MPI_COMM_WORLD, &rank_);
    MPI_Comm_size (MPI_COMM_WORLD, &size_);
  }

  ~MpiScheduler() override
  {
    freeWindow();
    MPI_Finalize();
  }

  int
  getRank () const override
  {
    return rank_;
  }
  int
  getSize () const override
  {
    return size_;
  }

  void
  startPhase (std::size_t tiles) override
  {
    freeWindow();
    tiles_ = tiles;
    MPI_Win_allocate (rank_ == 0 ? sizeof (long) : 0,
                      sizeof (long),
                      MPI_INFO_NULL,
                      MPI_COMM_WORLD,
                      &counter_,
                      &window_);
    if (rank_ == 0)
      *counter_ = 0;
    MPI_Barrier (MPI_COMM_WORLD);
  }

  bool
  next (std::size_t& tile) override
  {
    const long one = 1;
    long taken = 0;
    MPI_Win_lock (MPI_LOCK_SHARED, 0, 0, window_);
    MPI_Fetch_and_op (&one, &taken, MPI_LONG, 0, 0, MPI_SUM, window_);
    MPI_Win_unlock (0, window_);
    if (taken < 0 || static_cast<std::size_t> (taken) >= tiles_)
      return false;
    tile = static_cast<std::size_t> (taken);
    return true;
  }

  bool
  allOk (bool ok) override
  {
    int mine = ok ? 1 : 0, all = 0;
    MPI_Allreduce (&mine, &all, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
    return all != 0;
  }

private:
  void
  freeWindow ()
  {
    if (window_ != MPI_WIN_NULL)
      MPI_Win_free (&window_);
    window_ = MPI_WIN_NULL;
  }

  int rank_ = 0, size_ = 1;
  std::size_t tiles_ = 0;
  long* counter_ = nullptr;
  MPI_Win window_ = MPI_WIN_NULL;
};
#endif
} // namespace

std::unique_ptr<TileScheduler>
makeTileScheduler (int& argc, char**& argv)
{
#ifdef PCL_EXT_HAVE_MPI
  // MPI only when started by a launcher (mpirun, srun): a plain start stays one process
  // and needs no MPI runtime.
  for (const char* launched : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv (launched))
      return std::make_unique<MpiScheduler> (argc, argv);
#endif
  (void)argc;
  (void)argv;
  return std::make_unique<SerialScheduler>();
}
void
printRunSummary (const TileScheduler& scheduler,
                 bool ok,
                 const std::string& what,
                 std::uint64_t points,
                 double seconds)
{
  rusage usage{};
  ::getrusage (RUSAGE_SELF, &usage);
  std::cout << (scheduler.getSize() > 1
                    ? "Rank " + std::to_string (scheduler.getRank()) + ": "
                    : std::string())
            << (ok ? "done: " : "failed after ") << what << ", " << points
            << " points, " << std::fixed << std::setprecision (1) << seconds
            << " s, peak memory " << usage.ru_maxrss / 1024 << " MB\n";
}

} // namespace apps
} // namespace pcl_ext
