/*
 * pcl_ext_tiles: what a method must do to run tile by tile.
 */
#pragma once

#include "tile_cloud.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/tiling/merged_results.h>

#include <pcl/PCLPointCloud2.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The plan's setting of the whole cloud's noise sample cut (NoiseSampleCut),
 * set by the plan of a method that needsEstimate(). */
constexpr const char* kNoiseSampleCutSetting = "noise_sample_cut";

/** \brief A method of pcl_ext_tiles: its options (those of its own tool), what it
 * estimates from the whole cloud before the tiles run, and its result on one tile.
 *
 * A tiled run gives the result of the untiled tool because (1) every core point's
 * neighbourhoods, as far as its result reaches (reach()), are those of the whole cloud
 * (loadTileCloud checks it and widens the tile until they are), and (2) what the
 * method derives from the whole cloud (e.g. a median curvature) is derived once from
 * every tile's values (estimate(), then reduce()) and handed to every tile (run()). */
class TileMethod {
public:
  virtual ~TileMethod() = default;

  /** \brief Declare the method's options on \a cl (the defaults of its own tool). */
  virtual void
  addOptions (CommandLine& cl) = 0;

  /** \brief Check the options (message printed when they are not valid); \a notes:
   * also print what the user should know of them (once, at the plan or a whole run,
   * not in every step). */
  virtual bool
  checkOptions (const CommandLine& cl, bool notes) = 0;

  /** \brief Where the result goes in the output (the field of the method's tool). */
  virtual ResultField
  makeResultField () const = 0;

  /** \brief Classes per point or segment ids (joined across tiles). */
  virtual tiling::MergedResults::Kind
  getKind () const = 0;

  /** \brief For segments: the smallest segment kept, counted over the whole cloud at
   * the merge (the segments then numbered largest first, as pcl_ext's segmenters
   * number theirs); 0: numbered by first point, none dropped. */
  virtual std::uint64_t
  getMinSegmentSize () const
  {
    return 0;
  }

  /** \brief The neighbourhoods a point's result reaches through. */
  virtual NeighbourhoodReach
  getReach () const = 0;

  /** \brief The neighbourhoods estimate() reaches through (default: those of run()). */
  virtual NeighbourhoodReach
  getEstimateReach () const
  {
    return getReach();
  }

  /** \brief Whether the method estimates something from the whole cloud (then
   * estimate() runs on every tile, and reduce() once, before run()). */
  virtual bool
  needsEstimate () const
  {
    return false;
  }

  /** \brief The points of a tile whose neighbourhoods estimate() reads, given the
   * plan's \a settings (default: empty, all of them). */
  virtual PointSelection
  getEstimateSelection (const std::map<std::string, std::string>& /*settings*/) const
  {
    return {};
  }

  /** \brief The values of the tile's core points (order free) that reduce() needs, by
   * statistic name. \return false on error (message printed) */
  virtual bool
  estimate (const TileCloud&, std::map<std::string, std::vector<float>>&)
  {
    return true;
  }

  /** \brief From what estimate() saved for the \a tiles tiles of \a folder
   * (tiling::loadTileValues), the settings run() reads. \return false on error */
  virtual bool
  reduce (const std::string&, std::size_t, std::map<std::string, std::string>&)
  {
    return true;
  }

  /** \brief The result of every point of \a tile (its halo included; only the core's
   * is kept), given the whole cloud's \a settings. Segments are numbered from 0 in the
   * tile; tiling::SegmentMerge::kNoSegment for a point in none. \return false on error
   * (message printed) */
  virtual bool
  run (const TileCloud& tile,
       const std::map<std::string, std::string>& settings,
       std::vector<std::uint32_t>& labels) = 0;

  /** \brief The field of a float per point that the method writes beside its result
   * (e.g. the probability of a point's class), as its tool names it; empty (the
   * default): none. */
  virtual std::string
  getExtraFieldName () const
  {
    return {};
  }

  /** \brief After run(): that float of every point of the tile (its halo included;
   * only the core's are kept), or null. */
  virtual const std::vector<float>*
  getExtraValues () const
  {
    return nullptr;
  }

  /** \brief Whether the method makes a second pass over the tiles once every tile has
   * run and their segments are joined across the tiles (refine()): a step whose result
   * at a point reads the whole cloud's segments around it. */
  virtual bool
  needsRefine () const
  {
    return false;
  }

  /** \brief For refine(): a value of every point of the tile of the last run() (its
   * halo included; only the core's are kept, e.g. the classes), or null. */
  virtual const std::vector<std::uint32_t>*
  getRefineValues () const
  {
    return nullptr;
  }

  /** \brief After run(): the largest neighbourhood radius among the tile's own points
   * that refine() reads beyond a point's neighbourhood (what bounds the reach of the
   * points another tile's second pass did not load); 0 for none. */
  virtual double
  getRefineRadius () const
  {
    return 0.0;
  }

  /** \brief After run(): the margin the tile's second pass will likely need, estimated
   * from what the tile knows after the first (its own segments for the whole cloud's);
   * the second pass starts with it and widens itself where it is short. */
  virtual double
  getRefineMargin () const
  {
    return 0.0;
  }

  /** \brief The second pass on \a tile, loaded with the k-neighbourhoods of getReach():
   * \a segments is the whole cloud's segment of every point (numbered over the whole
   * cloud, tiling::SegmentMerge::kNoSegment for none), \a values what getRefineValues()
   * gave for it in its owner's run, \a tile_radii what getRefineRadius() gave for each
   * tile of the plan; \a labels the segments after the pass, one per point (only the
   * core's are kept). getNeededMargin() then says whether the tile needed a wider
   * margin. \return false on error (message printed) */
  virtual bool
  refine (const TileCloud& /*tile*/,
          const std::vector<std::uint32_t>& segments,
          const std::vector<std::uint32_t>& /*values*/,
          const std::vector<float>& /*tile_radii*/,
          std::vector<std::uint32_t>& labels)
  {
    labels = segments;
    return true;
  }

  /** \brief Whether the method groups points anew after its last pass (grow()): a
   * pass over the tiles once every point's segment over the whole cloud is known (after
   * the second pass, if any), whose groups are joined across the tiles as the first
   * pass's segments are and numbered after them. */
  virtual bool
  needsGrow () const
  {
    return false;
  }

  /** \brief The neighbourhoods grow()'s result at a point reaches through. */
  virtual NeighbourhoodReach
  getGrowReach () const
  {
    return getReach();
  }

  /** \brief The pass on \a tile: \a segments is the whole cloud's segment of every
   * point (kNoSegment for none); \a labels gets the tile's groups among the points
   * without one, numbered from 0 in the tile, kNoSegment for a point in none. Only the
   * tile's own points make links; a halo point is grouped only where they reach it, so
   * that its owner's group and this tile's join it. \return false on error (message
   * printed) */
  virtual bool
  grow (const TileCloud& /*tile*/,
        const std::vector<std::uint32_t>& /*segments*/,
        std::vector<std::uint32_t>& /*labels*/)
  {
    return false;
  }

  /** \brief After refine() on \a tile: save in \a workdir what the pass made besides
   * the segments (e.g. the local intersection points its core points found), for
   * mergeRefineOutputs(). \return false (message printed) when it cannot be saved */
  virtual bool
  saveRefineOutputs (const std::string& /*workdir*/, const TileCloud& /*tile*/)
  {
    return true;
  }

  /** \brief At the merge: write what saveRefineOutputs() saved for the \a tiles tiles
   * of \a workdir, in the inputs' frame (the plan's \a origin added back). \return
   * false (message printed) on error */
  virtual bool
  mergeRefineOutputs (const std::string& /*workdir*/,
                      std::size_t /*tiles*/,
                      const Eigen::Vector3d& /*origin*/)
  {
    return true;
  }

  /** \brief How many values per point the method reads beside x y z (carried in the
   * tiles' files, TileCloud::attributes); 0 (the default): none. */
  virtual std::size_t
  getAttributeCount () const
  {
    return 0;
  }

  /** \brief Those values of the points of a \a chunk of \a input, one point after
   * another. \return false (message printed) when the input does not have them */
  virtual bool
  readAttributes (const pcl::PCLPointCloud2& /*chunk*/,
                  const std::string& /*input*/,
                  std::vector<float>& values) const
  {
    values.clear();
    return true;
  }

  /** \brief With -asprs (when the method's result field offers it): \a values, the
   * merged results of a chunk's points, replaced by their ASPRS codes. \return false
   * when the method has none */
  virtual bool
  toAsprs (std::vector<std::uint32_t>& /*values*/)
  {
    return false;
  }

  /** \brief After estimate() or run() on a tile: the margin around the tile's core
   * that its result needed, measured on what it computed (0: the checks of getReach()
   * are enough). A tile whose margin was narrower is loaded again with this margin and
   * computed again (at worst with the whole cloud). */
  virtual double
  getNeededMargin () const
  {
    return 0.0;
  }

  /** \brief OpenMP threads of the method (0: all cores). */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
  }

protected:
  unsigned int threads_ = 0;
};

/** \brief Load tile \a tile with \a reach from a margin of at least \a margin and run
 * \a compute on it (one of \a method's steps), widening the margin and running again
 * while \a method says it needed more (TileMethod::getNeededMargin), at worst up to the
 * whole cloud; \a select as loadTileCloud's. \return false (message printed) when
 * loading or \a compute fails */
bool
computeOnTile (const tiling::TilePlan& plan,
               const std::string& folder,
               std::size_t tile,
               const NeighbourhoodReach& reach,
               unsigned int threads,
               double margin,
               const TileMethod& method,
               const std::function<bool (const TileCloud&)>& compute,
               TileCloud& cloud,
               const PointSelection& select = {});

/** \brief The method named \a name (classify_variance, ...), or null. */
std::unique_ptr<TileMethod>
makeTileMethod (const std::string& name);

/** \brief The names makeTileMethod knows, for the help text. */
constexpr const char* kTileMethods =
    "classify_variance, segment_variance, crf_classify";

/** \brief Lim & Suter's CRF classification tile by tile (crf_classify_tiles.cpp). */
std::unique_ptr<TileMethod>
makeCrfClassifyTiles ();
} // namespace apps
} // namespace pcl_ext
