/*
 * pcl_ext_tiles segment_variance: Belton & Lichti's segmentation tile by tile, with the
 * options and result of pcl_ext_segment_variance.
 */
#include "../variance/segment_variance_options.h"
#include "variance_tiles.h"

#include <pcl_ext/apps/output.h>
#include <pcl_ext/tiling/segment_merge.h>

#include <iostream>

namespace pcl_ext {
namespace apps {
namespace {
/** The segments of the whole cloud are the connected components of the links "seed -
 * surface neighbour before the first stop" (section 3). A tile's own points seed: their
 * links, read from neighbourhoods and classes that are the whole cloud's (getReach),
 * are the whole cloud's links, and every link has its seed in exactly one tile. The
 * halo points they reach carry the tile's segment to the merge, which joins it with the
 * owner's segment of the point (SegmentMerge); the minimum size applies to the joined
 * segments, counted over all tiles, and the ids go largest first, as untiled. */
class SegmentVarianceTiles : public VarianceTileMethod {
public:
  void
  addOptions (CommandLine& cl) override
  {
    options_.addTo (cl);
  }

  bool
  checkOptions (const CommandLine& cl) override
  {
    if (!options_.valid (cl) || !checkClassification())
      return false;
    if (!cl.given ("reintegrate") && options_.intersections_path.empty() &&
        options_.reintegrate) {
      // Section 4 by default in pcl_ext_segment_variance; not yet tile by tile.
      std::cout << "Note: pcl_ext_tiles segment_variance runs sections 2 and 3 (as "
                   "pcl_ext_segment_variance -no_reintegrate): section 4's "
                   "re-integration does not run tile by tile yet.\n";
      options_.reintegrate = false;
    }
    if (options_.intersects()) {
      std::cerr << "Error: pcl_ext_tiles segment_variance cannot run section 4 (the "
                   "local intersections and -reintegrate) yet: run "
                   "pcl_ext_segment_variance.\n";
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
    if (tile.core_points == 0)
      return true;
    if (!tile.neighbourhoods || tile.neighbourhoods->empty()) {
      std::cerr << "Error: tile " << tile.tile
                << " has fewer points than k = " << options_.k << ".\n";
      return false;
    }
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
    pcl_ext::VarianceRegionGrowing<pcl::PointXYZ> rg;
    options_.configure (tile.cloud, tile.neighbourhoods, threads_, classifier, rg);
    configure (classifier, tile);
    if (!applyThreshold (classifier, settings))
      return false;
    auto classes = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
    classifier.classify (*classes);
    if (classes->size() != tile.cloud->size()) {
      std::cerr << "Error: the classification of tile " << tile.tile << " failed.\n";
      return false;
    }
    bool surface = false;
    for (std::size_t i = 0; i < classes->size() && !surface; ++i)
      surface = (*classes)[i].label == static_cast<std::uint32_t> (PointClass::Surface);
    if (!surface)
      return true; // nothing to grow from: no segment
    // Only the core seeds; every segment kept here, the minimum size is the merge's.
    auto seeds = pcl::make_shared<pcl::Indices>();
    for (std::size_t i = 0; i < tile.core.size(); ++i)
      if (tile.core[i])
        seeds->push_back (static_cast<pcl::index_t> (i));
    rg.setSeedIndices (seeds);
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
    return true;
  }

protected:
  const VarianceClassificationOptions&
  getClassificationOptions () const override
  {
    return options_.classification;
  }

private:
  SegmentVarianceOptions options_;
};
} // namespace

std::unique_ptr<TileMethod>
makeSegmentVarianceTiles ()
{
  return std::make_unique<SegmentVarianceTiles>();
}
} // namespace apps
} // namespace pcl_ext
