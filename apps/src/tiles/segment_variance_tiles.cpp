/*
 * pcl_ext_tiles segment_variance: Belton & Lichti's segmentation tile by tile, with the
 * options and result of pcl_ext_segment_variance.
 */
#include "../variance/segment_variance_options.h"
#include "reintegration_margin.h"
#include "tile_intersections.h"
#include "variance_tiles.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/tiling/segment_merge.h>

#include <pcl/conversions.h>

#include <algorithm>
#include <iostream>
#include <numeric>

namespace pcl_ext {
namespace apps {
namespace {
/** The segments of the whole cloud are the connected components of the links "seed -
 * surface neighbour before the first stop" (section 3). A tile's own points seed: their
 * links, read from neighbourhoods and classes that are the whole cloud's (getReach),
 * are the whole cloud's links, and every link has its seed in exactly one tile. The
 * halo points they reach carry the tile's segment to the merge, which joins it with the
 * owner's segment of the point (SegmentMerge); the minimum size applies to the joined
 * segments, counted over all tiles, and the ids go largest first, as untiled.
 *
 * Section 4's re-integration (on by default, as in pcl_ext_segment_variance) is a
 * second pass: each tile keeps its core points' classes, the joined segments are
 * numbered over the whole cloud, and each tile then re-integrates its own edge and
 * boundary points into those segments with the whole cloud's segments and classes
 * around it, its margin as wide as neededReintegrationMargin says. */
class SegmentVarianceTiles : public VarianceTileMethod {
public:
  void
  addOptions (CommandLine& cl) override
  {
    options_.addTo (cl);
  }

  bool
  checkOptions (const CommandLine& cl, bool notes) override
  {
    if (!options_.valid (cl) || !checkClassification())
      return false;
    if (!cl.given ("reintegrate") && options_.reintegrate) {
      // Section 4 is on by default in pcl_ext_segment_variance; tile by tile it is a
      // second pass whose margin follows the sparsest points' reach (docs/tiles.md).
      // The new segments among the points left out stay on (unless -no_leftovers):
      // their pass reads two steps of neighbourhoods, and they raise every scene
      // family well above sections 2 and 3 alone.
      if (notes)
        std::cout << "Note: pcl_ext_tiles segment_variance runs sections 2 and 3"
                  << (options_.leftovers
                          ? " and the new segments among the points left "
                            "out (as pcl_ext_segment_variance "
                            "-no_reintegrate -leftovers)"
                          : " (as pcl_ext_segment_variance "
                            "-no_reintegrate)")
                  << " unless -reintegrate is given: section 4's re-integration, a "
                     "second pass over the tiles, reads as far as three neighbourhood "
                     "radii of the sparsest points around, which on a scan's sparse "
                     "edges can be most of the cloud.\n";
      options_.reintegrate = false;
    }
    // Not yet tile by tile: the merging of interleaved pieces of one plane and the
    // assignment of the points left over, which pcl_ext_segment_variance runs after
    // section 4 (docs/tiles.md, "Not yet done").
    if (cl.given ("merge") || cl.given ("assign")) {
      std::cerr
          << "Error: pcl_ext_tiles segment_variance does not yet merge interleaved "
             "pieces of one plane (-merge) or assign the points left over "
             "(-assign); pcl_ext_segment_variance does.\n";
      return false;
    }
    if (notes && options_.reintegrate && (options_.merge || options_.assign))
      std::cout
          << "Note: pcl_ext_tiles segment_variance -reintegrate gives "
             "pcl_ext_segment_variance -no_merge -no_assign's result: the merging "
             "of interleaved pieces of one plane and the assignment of the points "
             "left over do not run tile by tile yet.\n";
    options_.merge = options_.assign = false;
    std::string reason;
    if (!options_.intersections_path.empty() &&
        !io::canWritePointFile (options_.intersections_path, &reason)) {
      std::cerr << "Error: -intersections: " << reason << ".\n";
      return false;
    }
    return true;
  }

  ResultField
  makeResultField () const override
  {
    return segmentIdField();
  }

  tiling::MergedResults::Kind
  getKind () const override
  {
    return tiling::MergedResults::Kind::Segments;
  }

  std::uint64_t
  getMinSegmentSize () const override
  {
    return static_cast<std::uint64_t> (options_.min_size);
  }

  NeighbourhoodReach
  getReach () const override
  {
    NeighbourhoodReach reach;
    reach.k = options_.k;
    reach.max_radius = options_.max_radius;
    // A seed's links read its own neighbourhood and its neighbours' classes.
    reach.hops = getClassificationHops() + 1;
    return reach;
  }

  bool
  run (const TileCloud& tile,
       const std::map<std::string, std::string>& settings,
       std::vector<std::uint32_t>& labels) override
  {
    labels.assign (tile.cloud ? tile.cloud->size() : 0,
                   tiling::SegmentMerge::kNoSegment);
    classes_.assign (labels.size(), 0);
    needed_margin_ = surface_radius_ = refine_margin_ = 0.0;
    if (tile.core_points == 0)
      return true;
    if (!hasNeighbourhoods (tile))
      return false;
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
    pcl_ext::VarianceRegionGrowing<pcl::PointXYZ> rg;
    options_.configure (tile.cloud, tile.neighbourhoods, threads_, classifier, rg);
    configure (classifier, tile);
    if (!applyEstimates (classifier, settings))
      return false;
    auto classes = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
    classifier.classify (*classes);
    if (classes->size() != tile.cloud->size()) {
      std::cerr << "Error: the classification of tile " << tile.tile << " failed.\n";
      return false;
    }
    classes_.resize (classes->size());
    for (std::size_t i = 0; i < classes->size(); ++i) {
      classes_[i] = (*classes)[i].label;
      // The core's largest surface neighbourhood: what bounds the reach of its points
      // in another tile's re-integration.
      if (tile.core[i] &&
          classes_[i] == static_cast<std::uint32_t> (PointClass::Surface))
        surface_radius_ =
            std::max (surface_radius_, neighbourhoodRadius (*tile.neighbourhoods, i));
    }
    bool surface = false;
    for (std::size_t i = 0; i < classes->size() && !surface; ++i)
      surface = (*classes)[i].label == static_cast<std::uint32_t> (PointClass::Surface);
    if (!surface)
      return true; // nothing to grow from: no segment
    // Only the core seeds; every segment kept here, the minimum size is the merge's.
    rg.setSeedIndices (coreIndices (tile));
    rg.setMinClusterSize (1);
    rg.setInputClasses (classes);
    std::vector<pcl::PointIndices> clusters;
    rg.extract (clusters);
    if (clusters.empty()) {
      std::cerr << "Error: the segmentation of tile " << tile.tile << " failed.\n";
      return false;
    }
    // A segment of halo points alone (a halo point no seed links to) adds nothing.
    std::uint32_t next = 0;
    for (const auto& c : clusters) {
      bool own = false;
      for (std::size_t j = 0; j < c.indices.size() && !own; ++j)
        own = tile.core[static_cast<std::size_t> (c.indices[j])];
      if (!own)
        continue;
      for (const auto i : c.indices)
        labels[static_cast<std::size_t> (i)] = next;
      ++next;
    }
    // The second pass's margin as the tile's own segments have it (the whole cloud's
    // differ by their minimum size and across the tiles' borders).
    if (needsRefine())
      refine_margin_ = neededReintegrationMargin (
          tile,
          labels,
          classes_,
          {},
          pcl_ext::LocalSurfaceIntersection<pcl::PointXYZ>().getReachFactor(),
          intersects());
    return true;
  }

  /** The new segments among the points left out are a pass of their own, after the
   * segments are final: their links read the whole cloud's segments around a point. */
  bool
  needsGrow () const override
  {
    return options_.leftovers;
  }

  /** A point's links read its nearest neighbours' normals: two steps of
   * neighbourhoods, the first getNormalK() of each row of k. */
  NeighbourhoodReach
  getGrowReach () const override
  {
    NeighbourhoodReach reach;
    reach.k = options_.k;
    reach.max_radius = options_.max_radius;
    reach.hops = 2;
    return reach;
  }

  bool
  grow (const TileCloud& tile,
        const std::vector<std::uint32_t>& segments,
        std::vector<std::uint32_t>& labels) override
  {
    labels.assign (segments.size(), tiling::SegmentMerge::kNoSegment);
    needed_margin_ = 0.0; // getGrowReach()'s neighbourhoods are all it reads
    if (tile.core_points == 0 ||
        std::find (segments.begin(),
                   segments.end(),
                   tiling::SegmentMerge::kNoSegment) == segments.end())
      return true; // no point left out
    if (!hasNeighbourhoods (tile))
      return false;
    auto input = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
    input->resize (segments.size());
    std::uint32_t largest = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      (*input)[i].label =
          segments[i] == tiling::SegmentMerge::kNoSegment ? 0 : segments[i] + 1;
      largest = std::max (largest, (*input)[i].label);
    }
    pcl_ext::LeftoverRegionGrowing<pcl::PointXYZ> growing;
    options_.configure (tile.cloud, tile.neighbourhoods, threads_, growing);
    // Every group kept: the minimum size is the merge's, over the whole cloud.
    growing.setMinClusterSize (1);
    growing.setSegmentLabels (input);
    growing.setLinkingIndices (coreIndices (tile));
    pcl::PointCloud<pcl::Label> grown;
    if (!growing.compute (grown) || grown.size() != segments.size()) {
      std::cerr << "Error: growing the points left out of tile " << tile.tile
                << " failed.\n";
      return false;
    }
    // The tile's groups, those with a point of its own, numbered from 0; a group of
    // a halo point alone (no point of the tile links to it) adds nothing.
    std::vector<std::uint32_t> number;
    std::vector<char> own;
    for (std::size_t i = 0; i < grown.size(); ++i) {
      if (grown[i].label <= largest)
        continue;
      const std::size_t g = grown[i].label - largest - 1;
      if (own.size() <= g)
        own.resize (g + 1, 0);
      own[g] = own[g] || tile.core[i];
    }
    number.assign (own.size(), tiling::SegmentMerge::kNoSegment);
    std::uint32_t next = 0;
    for (std::size_t g = 0; g < own.size(); ++g)
      if (own[g])
        number[g] = next++;
    for (std::size_t i = 0; i < grown.size(); ++i)
      if (grown[i].label > largest)
        labels[i] = number[grown[i].label - largest - 1];
    return true;
  }

  /** Section 4, re-integration or intersection points, is a second pass. */
  bool
  needsRefine () const override
  {
    return options_.intersects();
  }

  const std::vector<std::uint32_t>*
  getRefineValues () const override
  {
    return &classes_;
  }

  double
  getRefineRadius () const override
  {
    return surface_radius_;
  }

  double
  getRefineMargin () const override
  {
    return refine_margin_;
  }

  bool
  refine (const TileCloud& tile,
          const std::vector<std::uint32_t>& segments,
          const std::vector<std::uint32_t>& classes,
          const std::vector<float>& tile_radii,
          std::vector<std::uint32_t>& labels) override
  {
    labels = segments;
    needed_margin_ = 0.0;
    intersections_.clear();
    if (tile.core_points == 0 || !tile.neighbourhoods || tile.neighbourhoods->empty())
      return true;
    pcl_ext::LocalSurfaceIntersection<pcl::PointXYZ> lsi;
    options_.configure (tile.cloud, tile.neighbourhoods, threads_, lsi);
    needed_margin_ = neededReintegrationMargin (
        tile, segments, classes, tile_radii, lsi.getReachFactor(), intersects());
    const auto surface = static_cast<std::uint32_t> (PointClass::Surface);
    const auto edge = static_cast<std::uint32_t> (PointClass::Edge);
    const auto boundary = static_cast<std::uint32_t> (PointClass::Boundary);
    bool into = false, examined = false;
    auto ids = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
    auto point_classes = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
    ids->resize (segments.size());
    point_classes->resize (segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const bool segmented = segments[i] != tiling::SegmentMerge::kNoSegment;
      (*ids)[i].label = segmented ? segments[i] + 1 : 0;
      (*point_classes)[i].label = classes[i];
      const bool finite = pcl::isFinite ((*tile.cloud)[i]);
      into = into || (segmented && classes[i] == surface && finite);
      examined =
          examined || (tile.core[i] && finite &&
                       (segmented ? intersects() && classes[i] == surface
                                  : classes[i] == edge || classes[i] == boundary));
    }
    // No segment to re-integrate into or intersect within the data, or nothing of the
    // tile's own to re-integrate or to intersect from: the segments stay
    // (LocalSurfaceIntersection would refuse the former).
    if (!into || !examined)
      return true;
    lsi.setSegmentLabels (ids);
    lsi.setPointClasses (point_classes);
    // The points in the whole cloud's order: a pair of points found from both is kept
    // from the first, as the untiled tool keeps it.
    auto in_cloud_order = pcl::make_shared<pcl::Indices> (segments.size());
    std::iota (in_cloud_order->begin(), in_cloud_order->end(), 0);
    std::sort (in_cloud_order->begin(),
               in_cloud_order->end(),
               [&tile] (pcl::index_t a, pcl::index_t b) {
                 return tile.indices[static_cast<std::size_t> (a)] <
                        tile.indices[static_cast<std::size_t> (b)];
               });
    lsi.setIndices (in_cloud_order);
    pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> intersections;
    pcl::PointCloud<pcl::Label> reintegrated;
    if (!lsi.compute (intersections, reintegrated) ||
        reintegrated.size() != segments.size()) {
      std::cerr << "Error: the re-integration of tile " << tile.tile << " failed.\n";
      return false;
    }
    if (options_.reintegrate)
      for (std::size_t i = 0; i < segments.size(); ++i)
        labels[i] = reintegrated[i].label == 0 ? tiling::SegmentMerge::kNoSegment
                                               : reintegrated[i].label - 1;
    // The intersection points the core's points found, by the whole cloud's indices.
    if (intersects())
      for (const auto& p : intersections)
        if (tile.core[static_cast<std::size_t> (p.index_a)])
          intersections_.push_back (
              {p,
               tile.indices[static_cast<std::size_t> (p.index_a)],
               tile.indices[static_cast<std::size_t> (p.index_b)]});
    return true;
  }

  bool
  saveRefineOutputs (const std::string& workdir, const TileCloud& tile) override
  {
    if (!intersects())
      return true;
    const bool saved = saveTileIntersections (workdir, tile.tile, intersections_);
    intersections_.clear(); // a tile whose refine() does not run has none
    return saved;
  }

  bool
  mergeRefineOutputs (const std::string& workdir,
                      std::size_t tiles,
                      const Eigen::Vector3d& origin) override
  {
    if (!intersects())
      return true;
    StageTimer timer ("Saving " + options_.intersections_path);
    pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> points;
    if (!mergeTileIntersections (workdir, tiles, points))
      return false;
    pcl::PCLPointCloud2 blob;
    pcl::toPCLPointCloud2 (points, blob);
    if (!io::savePointFile (options_.intersections_path, blob, origin))
      return false;
    timer.done (points.size());
    return true;
  }

  double
  getNeededMargin () const override
  {
    return needed_margin_;
  }

protected:
  const VarianceClassificationOptions&
  getClassificationOptions () const override
  {
    return options_.classification;
  }

private:
  /** Whether \a tile has its neighbourhoods (else the error printed). */
  bool
  hasNeighbourhoods (const TileCloud& tile) const
  {
    if (tile.neighbourhoods && !tile.neighbourhoods->empty())
      return true;
    std::cerr << "Error: tile " << tile.tile
              << " has fewer points than k = " << options_.k << ".\n";
    return false;
  }

  /** The tile's own points: they alone seed (section 3) and link (the points left out
   * grouped), so that every link of the whole cloud is made in one tile. */
  static pcl::IndicesPtr
  coreIndices (const TileCloud& tile)
  {
    auto core = pcl::make_shared<pcl::Indices>();
    for (std::size_t i = 0; i < tile.core.size(); ++i)
      if (tile.core[i])
        core->push_back (static_cast<pcl::index_t> (i));
    return core;
  }

  /** Whether the intersection points are written (-intersections). */
  bool
  intersects () const
  {
    return !options_.intersections_path.empty();
  }

  SegmentVarianceOptions options_;
  std::vector<TileIntersection> intersections_; ///< of the last refine()
  std::vector<std::uint32_t> classes_;          ///< of every point of the last run()
  double surface_radius_ = 0.0;                 ///< of the last run()
  double refine_margin_ = 0.0;                  ///< of the last run()
  double needed_margin_ = 0.0;                  ///< of the last refine() or grow()
};
} // namespace

std::unique_ptr<TileMethod>
makeSegmentVarianceTiles ()
{
  return std::make_unique<SegmentVarianceTiles>();
}
} // namespace apps
} // namespace pcl_ext
