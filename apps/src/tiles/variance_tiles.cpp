/*
 * pcl_ext_tiles: what Belton & Lichti's classification and segmentation share tile by
 * tile.
 */
#include "variance_tiles.h"
#include "tile_keys.h"

#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/features/local_variance.h>
#include <pcl_ext/tiling/tile_results.h>

#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
constexpr const char* kCurvatures = "curvature";
constexpr const char* kThresholdSetting = "curvature_threshold";
// A tile's part of the noise sample (when the curvature factor is chosen from the
// cloud): each point's key in three parts of at most 22 bits (exact in a float), then
// its neighbourhood's eigenvalues (as floats, as the classifier rounds them) and size.
constexpr const char* kKeyParts[3] = {
    "lv_noise_key_high", "lv_noise_key_mid", "lv_noise_key_low"};
constexpr const char* kSpreadValues[4] = {
    "lv_noise_l0", "lv_noise_l1", "lv_noise_l2", "lv_noise_size"};

/** The tile's points of the whole cloud's noise sample: every core point whose key is
 * at most the cut of the tile's core keys (the whole cloud's cut is at most that). */
void
saveNoiseSample (const TileCloud& tile,
                 std::map<std::string, std::vector<float>>& values)
{
  const auto& cloud = *tile.cloud;
  NoiseSampleCut cut;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (tile.core[i])
      cut.add (noiseSampleKeyOf (cloud[i].x, cloud[i].y, cloud[i].z));
  const auto& nb = *tile.neighbourhoods;
  for (std::size_t i = 0; i < cloud.size() && !cut.empty(); ++i) {
    if (!tile.core[i])
      continue;
    const std::uint64_t key = noiseSampleKeyOf (cloud[i].x, cloud[i].y, cloud[i].z);
    if (key > cut.get())
      continue;
    appendKey (values, kKeyParts, key);
    NeighbourhoodSpread spread;
    const std::ptrdiff_t row = nb.getRowOfPoint (static_cast<pcl::index_t> (i));
    LocalCovariance local;
    if (row >= 0) {
      const auto nn = nb[static_cast<std::size_t> (row)];
      if (computeNeighbourhoodCovariance (cloud, nn.begin(), nn.end(), local)) {
        spread.values = local.eigen.values;
        spread.size = local.size;
      }
    }
    for (int v = 0; v < 3; ++v)
      values[kSpreadValues[v]].push_back (static_cast<float> (spread.values[v]));
    values[kSpreadValues[3]].push_back (static_cast<float> (spread.size));
  }
}

/** The noise sample of every tile of \a folder, keyed. \return false (message printed)
 * when a tile's is missing or broken */
bool
loadNoiseSample (const std::string& folder,
                 std::size_t tiles,
                 std::vector<KeyedSpread>& sample)
{
  sample.clear();
  for (std::size_t t = 0; t < tiles; ++t) {
    std::vector<float> parts[3], spread[4];
    bool read = true;
    for (int p = 0; p < 3; ++p)
      read = read && tiling::loadTileValues (folder, t, kKeyParts[p], parts[p]);
    for (int v = 0; v < 4; ++v)
      read = read && tiling::loadTileValues (folder, t, kSpreadValues[v], spread[v]);
    if (!read)
      return false;
    const std::size_t n = parts[0].size();
    bool sizes = true;
    for (int p = 1; p < 3; ++p)
      sizes = sizes && parts[p].size() == n;
    for (int v = 0; v < 4; ++v)
      sizes = sizes && spread[v].size() == n;
    if (!sizes) {
      std::cerr << "Error: the noise sample of tile " << t << " in " << folder
                << " is broken.\n";
      return false;
    }
    for (std::size_t i = 0; i < n; ++i) {
      KeyedSpread k;
      k.key = keyAt (parts, i);
      k.spread.values = Eigen::Vector3d (spread[0][i], spread[1][i], spread[2][i]);
      k.spread.size = static_cast<std::size_t> (spread[3][i]);
      sample.push_back (k);
    }
  }
  return true;
}
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
  if (curvature_factor_ == 0.0) {
    // Every tile writes its noise sample, empty or not.
    for (const char* name : kKeyParts)
      values[name].clear();
    for (const char* name : kSpreadValues)
      values[name].clear();
  }
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
  if (curvature_factor_ == 0.0)
    saveNoiseSample (tile, values);
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
  // As LocalVarianceClassification derives it: factor * median over every point, the
  // factor chosen from the whole cloud's noise sample when it is not given.
  double factor = curvature_factor_;
  if (factor == 0.0) {
    std::vector<KeyedSpread> sample;
    if (!loadNoiseSample (folder, tiles, sample))
      return false;
    factor = LocalVarianceClassification<pcl::PointXYZ>::curvatureFactorFor (
        estimateNoiseFromSample (std::move (sample)));
  }
  const double threshold = count == 0 ? 0.0 : factor * static_cast<double> (median);
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
