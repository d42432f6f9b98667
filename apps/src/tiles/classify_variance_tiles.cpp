/*
 * pcl_ext_tiles classify_variance: Belton & Lichti's classification tile by tile, with
 * the options and result of pcl_ext_classify_variance.
 */
#include "variance_tiles.h"

#include "../variance/edge_localisation_option.h"

#include <iostream>

namespace pcl_ext {
namespace apps {
namespace {
class ClassifyVarianceTiles : public VarianceTileMethod {
public:
  void
  addOptions (CommandLine& cl) override
  {
    cl.addOption ("k", k_, "neighbours per point (the paper's k)");
    cl.addOption ("radius", radius_, "neighbourhood radius instead of k (0: use k)");
    cl.addOption (
        "max_radius",
        max_radius_,
        "with k: keep only the neighbours within this distance (0: no cap, the "
        "paper's)");
    options_.addTo (cl);
    edges_.addTo (cl);
  }

  bool
  checkOptions (const CommandLine& cl, bool) override
  {
    if (k_ < 3 && radius_ <= 0.0) {
      std::cerr << "Error: -k must be at least 3.\n";
      return false;
    }
    if (!(radius_ >= 0.0) || !(max_radius_ >= 0.0)) {
      std::cerr << "Error: -radius and -max_radius must be >= 0.\n";
      return false;
    }
    return options_.valid (cl) && checkClassification();
  }

  ResultField
  makeResultField () const override
  {
    return ResultField (
        "lv_class",
        "class (1 surface, 2 edge, 3 boundary, 0 unknown)",
        "",
        "surface, edge and boundary have no ASPRS class code; the classes "
        "go to the -output_field field (LAS: an extra-bytes dimension)");
  }

  tiling::MergedResults::Kind
  getKind () const override
  {
    return tiling::MergedResults::Kind::PerPoint;
  }

  NeighbourhoodReach
  getReach () const override
  {
    NeighbourhoodReach reach;
    reach.k = k_;
    reach.radius = radius_;
    reach.max_radius = max_radius_;
    reach.hops = getClassificationHops();
    return reach;
  }

  bool
  run (const TileCloud& tile,
       const std::map<std::string, std::string>& settings,
       std::vector<std::uint32_t>& labels) override
  {
    labels.assign (tile.cloud ? tile.cloud->size() : 0, 0);
    if (tile.core_points == 0)
      return true;
    if (!tile.neighbourhoods || tile.neighbourhoods->empty()) {
      std::cerr << "Error: tile " << tile.tile << " has fewer points than k = " << k_
                << ".\n";
      return false;
    }
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
    configure (classifier, tile);
    if (!applyEstimates (classifier, settings))
      return false;
    pcl::PointCloud<pcl::Label> result;
    classifier.classify (result);
    if (result.size() != tile.cloud->size()) {
      std::cerr << "Error: the classification of tile " << tile.tile << " failed.\n";
      return false;
    }
    // The narrowing reads an edge point's neighbourhood and its neighbours' nearest
    // points: within the classification's reach (eq. 5), so exact on the core.
    if (edges_.localises (options_.preset)) {
      auto core = pcl::make_shared<pcl::Indices>();
      for (std::size_t i = 0; i < tile.cloud->size(); ++i)
        if (tile.core[i])
          core->push_back (static_cast<pcl::index_t> (i));
      EdgeLocalisation<pcl::PointXYZ> localisation;
      localisation.setInputCloud (tile.cloud);
      localisation.setIndices (core);
      localisation.setNeighbourhoods (tile.neighbourhoods);
      localisation.setNumberOfThreads (threads_);
      localisation.setPointClasses (
          pcl::make_shared<pcl::PointCloud<pcl::Label>> (result));
      pcl::PointCloud<pcl::Label> narrowed;
      if (!localisation.localise (narrowed)) {
        std::cerr << "Error: narrowing the edges of tile " << tile.tile << " failed.\n";
        return false;
      }
      result.swap (narrowed);
    }
    for (std::size_t i = 0; i < result.size(); ++i)
      labels[i] = result[i].label;
    return true;
  }

protected:
  const VarianceClassificationOptions&
  getClassificationOptions () const override
  {
    return options_;
  }

private:
  int k_ = 50;
  double radius_ = 0.0, max_radius_ = 0.0;
  VarianceClassificationOptions options_;
  EdgeLocalisationOption edges_;
};
} // namespace

std::unique_ptr<TileMethod>
makeClassifyVarianceTiles ()
{
  return std::make_unique<ClassifyVarianceTiles>();
}
} // namespace apps
} // namespace pcl_ext
