/*
 * pcl_ext_tiles classify_variance: Belton & Lichti's classification tile by tile, with
 * the options and result of pcl_ext_classify_variance.
 */
#include "../variance/variance_options.h"
#include "tile_method.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/tiling/tile_results.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
constexpr const char* kCurvatures = "curvature";
constexpr const char* kThresholdSetting = "curvature_threshold";

class ClassifyVarianceTiles : public TileMethod {
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
  }

  bool
  checkOptions (const CommandLine& cl) override
  {
    if (k_ < 3 && radius_ <= 0.0) {
      std::cerr << "Error: -k must be at least 3.\n";
      return false;
    }
    if (!(radius_ >= 0.0) || !(max_radius_ >= 0.0)) {
      std::cerr << "Error: -radius and -max_radius must be >= 0.\n";
      return false;
    }
    if (!options_.valid (cl))
      return false;
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
    options_.applyTo (classifier);
    if (classifier.getNoiseEstimation()) {
      // Each tile would estimate its own noise, and the tiles would differ from the
      // whole cloud's classification.
      std::cerr << "Error: pcl_ext_tiles cannot estimate the noise of the whole cloud "
                   "yet: give -noise_sigma with -preset derived (the value "
                   "pcl_ext_classify_variance -v prints on a part of the cloud).\n";
      return false;
    }
    curvature_factor_ = classifier.getCurvatureThresholdFactor();
    return true;
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
    // Eq. 5 reads the neighbours' curvatures; the boundary band the neighbours' labels.
    reach.hops = options_.boundary_band ? 3 : 2;
    return reach;
  }

  NeighbourhoodReach
  getEstimateReach () const override
  {
    NeighbourhoodReach reach = getReach();
    reach.hops = 1; // kappa (eq. 4) reads the point's own neighbourhood only
    return reach;
  }

  bool
  needsEstimate () const override
  {
    return options_.curvature_threshold == 0.0;
  }

  bool
  estimate (const TileCloud& tile,
            std::map<std::string, std::vector<float>>& values) override
  {
    auto& curvatures = values[kCurvatures];
    curvatures.clear();
    if (tile.core_points == 0 || !tile.neighbourhoods || tile.neighbourhoods->empty())
      return true;
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
    configure (classifier, tile);
    // Curvatures only: any threshold but 0 (0 would derive one from this tile).
    classifier.setTests (decltype (classifier)::CURVATURE_TEST);
    classifier.setCurvatureThreshold (1.0);
    pcl::PointCloud<pcl::Label> labels;
    classifier.classify (labels);
    const auto& kappa = classifier.getCurvatures();
    if (kappa.size() != tile.cloud->size()) {
      std::cerr << "Error: the curvatures of tile " << tile.tile << " failed.\n";
      return false;
    }
    for (std::size_t i = 0; i < kappa.size(); ++i)
      if (tile.core[i])
        curvatures.push_back (kappa[i]);
    return true;
  }

  bool
  reduce (const std::string& folder,
          std::size_t tiles,
          std::map<std::string, std::string>& settings) override
  {
    float median = 0.0f;
    std::uint64_t count = 0;
    if (!tiling::nthOfTileValues (folder, tiles, kCurvatures, 0.5, median, count))
      return false;
    // As LocalVarianceClassification derives it: factor * median over every point.
    const double threshold =
        count == 0 ? 0.0 : curvature_factor_ * static_cast<double> (median);
    std::ostringstream text;
    text.precision (17);
    text << threshold;
    settings[kThresholdSetting] = text.str();
    return true;
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
    if (needsEstimate()) {
      const auto found = settings.find (kThresholdSetting);
      if (found == settings.end()) {
        std::cerr
            << "Error: the plan has no curvature threshold (run the estimate step "
               "on every tile first).\n";
        return false;
      }
      classifier.setCurvatureThreshold (std::stod (found->second));
    }
    pcl::PointCloud<pcl::Label> result;
    classifier.classify (result);
    if (result.size() != tile.cloud->size()) {
      std::cerr << "Error: the classification of tile " << tile.tile << " failed.\n";
      return false;
    }
    for (std::size_t i = 0; i < result.size(); ++i)
      labels[i] = result[i].label;
    return true;
  }

private:
  void
  configure (pcl_ext::LocalVarianceClassification<pcl::PointXYZ>& classifier,
             const TileCloud& tile) const
  {
    classifier.setInputCloud (tile.cloud);
    if (radius_ > 0.0)
      classifier.setRadiusSearch (radius_);
    else {
      classifier.setKSearch (k_);
      classifier.setMaxRadius (max_radius_);
    }
    options_.applyTo (classifier);
    classifier.setNumberOfThreads (threads_);
    classifier.setNeighbourhoods (tile.neighbourhoods);
  }

  int k_ = 50;
  double radius_ = 0.0, max_radius_ = 0.0;
  double curvature_factor_ = 3.0; ///< the classifier's, after the options
  VarianceClassificationOptions options_;
};
} // namespace

std::unique_ptr<TileMethod>
makeTileMethod (const std::string& name)
{
  if (name == "classify_variance")
    return std::make_unique<ClassifyVarianceTiles>();
  return nullptr;
}
} // namespace apps
} // namespace pcl_ext
