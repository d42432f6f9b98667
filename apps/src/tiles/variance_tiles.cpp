/*
 * pcl_ext_tiles: what Belton & Lichti's classification and segmentation share tile by
 * tile.
 */
#include "variance_tiles.h"

#include <pcl_ext/tiling/tile_results.h>

#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
constexpr const char* kCurvatures = "curvature";
constexpr const char* kThresholdSetting = "curvature_threshold";
} // namespace

NeighbourhoodReach
VarianceTileMethod::getEstimateReach() const
{
  NeighbourhoodReach reach = getReach();
  reach.hops = 1; // kappa (eq. 4) reads the point's own neighbourhood only
  return reach;
}

bool
VarianceTileMethod::checkClassification()
{
  pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
  getClassificationOptions().applyTo (classifier);
  if (classifier.getNoiseEstimation()) {
    // Each tile would estimate its own noise, and the tiles would differ from the
    // whole cloud's result.
    std::cerr << "Error: pcl_ext_tiles cannot estimate the noise of the whole cloud "
                 "yet: give -noise_sigma with -preset derived (the value "
                 "pcl_ext_classify_variance -v prints on a part of the cloud).\n";
    return false;
  }
  curvature_factor_ = classifier.getCurvatureThresholdFactor();
  return true;
}

void
VarianceTileMethod::configure (
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ>& classifier,
    const TileCloud& tile) const
{
  const NeighbourhoodReach reach = getReach();
  classifier.setInputCloud (tile.cloud);
  if (reach.radius > 0.0)
    classifier.setRadiusSearch (reach.radius);
  else {
    classifier.setKSearch (reach.k);
    classifier.setMaxRadius (reach.max_radius);
  }
  getClassificationOptions().applyTo (classifier);
  classifier.setNumberOfThreads (threads_);
  classifier.setNeighbourhoods (tile.neighbourhoods);
}

bool
VarianceTileMethod::estimate (const TileCloud& tile,
                              std::map<std::string, std::vector<float>>& values)
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
VarianceTileMethod::reduce (const std::string& folder,
                            std::size_t tiles,
                            std::map<std::string, std::string>& settings)
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
VarianceTileMethod::applyThreshold (
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ>& classifier,
    const std::map<std::string, std::string>& settings) const
{
  if (!needsEstimate())
    return true;
  const auto found = settings.find (kThresholdSetting);
  if (found == settings.end()) {
    std::cerr << "Error: the plan has no curvature threshold (run the estimate step "
                 "on every tile first).\n";
    return false;
  }
  classifier.setCurvatureThreshold (std::stod (found->second));
  return true;
}
} // namespace apps
} // namespace pcl_ext
