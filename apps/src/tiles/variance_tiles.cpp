/*
 * pcl_ext_tiles: what Belton & Lichti's classification and segmentation share tile by
 * tile.
 */
#include "variance_tiles.h"
#include "tile_keys.h"

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/features/local_variance.h>
#include <pcl_ext/tiling/tile_results.h>

#include <cstring>
#include <iostream>
#include <limits>
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
// With the noise estimated from the cloud (-preset derived), eq. 4 has the noise
// removed, which is known only once every tile's sample is in: each core point's
// eigenvalues (doubles, as the classifier computes them, each in three parts of at most
// 22 bits), and, in reduce(), the curvatures with the whole cloud's noise removed.
constexpr const char* kEigenParts[3][3] = {{"lv_l0_high", "lv_l0_mid", "lv_l0_low"},
                                           {"lv_l1_high", "lv_l1_mid", "lv_l1_low"},
                                           {"lv_l2_high", "lv_l2_mid", "lv_l2_low"}};
constexpr const char* kDenoisedCurvatures = "curvature_noise_removed";
constexpr const char* kNoiseSetting = "noise_sigma";
/** Setting: "1" when the whole cloud's noise is a range camera's. */
constexpr const char* kRangeCameraSetting = "range_camera_noise";

/** The eigenvalues and size of the neighbourhood of the tile's point \a i, as the
 * classifier computes them; size 0 (eigenvalues 0) where it has none. */
NeighbourhoodSpread
spreadOf (const TileCloud& tile, std::size_t i)
{
  NeighbourhoodSpread spread;
  const auto& nb = *tile.neighbourhoods;
  const std::ptrdiff_t row = nb.getRowOfPoint (static_cast<pcl::index_t> (i));
  LocalCovariance local;
  if (row >= 0) {
    const auto nn = nb[static_cast<std::size_t> (row)];
    if (computeNeighbourhoodCovariance (*tile.cloud, nn.begin(), nn.end(), local)) {
      spread.values = local.eigen.values;
      spread.size = local.size;
    }
  }
  return spread;
}

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
  for (std::size_t i = 0; i < cloud.size() && !cut.empty(); ++i) {
    if (!tile.core[i])
      continue;
    const std::uint64_t key = noiseSampleKeyOf (cloud[i].x, cloud[i].y, cloud[i].z);
    if (key > cut.get())
      continue;
    appendKey (values, kKeyParts, key);
    const NeighbourhoodSpread spread = spreadOf (tile, i);
    for (int v = 0; v < 3; ++v)
      values[kSpreadValues[v]].push_back (static_cast<float> (spread.values[v]));
    values[kSpreadValues[3]].push_back (static_cast<float> (spread.size));
  }
}

/** Every core point's eigenvalues (NaN where its neighbourhood has no covariance).
 * The few thousand points of the noise sample among them are decomposed a second time
 * by saveNoiseSample: keeping every point's spread to share would cost more memory
 * than the repeated work costs time. */
void
saveEigenvalues (const TileCloud& tile,
                 std::map<std::string, std::vector<float>>& values)
{
  for (std::size_t i = 0; i < tile.cloud->size(); ++i) {
    if (!tile.core[i])
      continue;
    const NeighbourhoodSpread spread = spreadOf (tile, i);
    const Eigen::Vector3d eigenvalues =
        spread.size > 0
            ? spread.values
            : Eigen::Vector3d::Constant (std::numeric_limits<double>::quiet_NaN());
    for (int v = 0; v < 3; ++v) {
      std::uint64_t bits;
      std::memcpy (&bits, &eigenvalues[v], sizeof (bits));
      appendKey (values, kEigenParts[v], bits);
    }
  }
}

/** Each tile's curvatures (eq. 4) with the noise variance \a noise_variance removed
 * from l0, as LocalVarianceClassification computes them, saved for nthOfTileValues.
 * \return false (message printed) when a tile's eigenvalues are missing or broken */
bool
saveDenoisedCurvatures (const std::string& folder,
                        std::size_t tiles,
                        double noise_variance)
{
  std::vector<float> parts[3][3], kappa;
  for (std::size_t t = 0; t < tiles; ++t) {
    bool read = true;
    for (int v = 0; v < 3; ++v)
      for (int p = 0; p < 3; ++p)
        read =
            read && tiling::loadTileValues (folder, t, kEigenParts[v][p], parts[v][p]);
    if (!read)
      return false;
    const std::size_t n = parts[0][0].size();
    for (int v = 0; v < 3; ++v)
      for (int p = 0; p < 3; ++p)
        if (parts[v][p].size() != n) {
          std::cerr << "Error: the eigenvalues of tile " << t << " in " << folder
                    << " are broken.\n";
          return false;
        }
    kappa.assign (n, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::Vector3d values;
      for (int v = 0; v < 3; ++v) {
        const std::uint64_t bits = keyAt (parts[v], i);
        std::memcpy (&values[v], &bits, sizeof (bits));
      }
      if (!values.allFinite())
        continue;
      values[0] = std::max (values[0] - noise_variance, 0.0);
      kappa[i] = static_cast<float> (surfaceVariance (values));
    }
    if (!tiling::saveTileValues (folder, t, kDenoisedCurvatures, kappa))
      return false;
  }
  return true;
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
  // The noise is the whole cloud's, estimated once from every tile's part of its
  // sample (reduce()), never each tile's own.
  estimate_noise_ = classifier.getNoiseEstimation();
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
  const bool derived_threshold = getClassificationOptions().curvature_threshold == 0.0;
  // Every tile writes what it is asked for, empty or not.
  if (derived_threshold && !estimate_noise_)
    values[kCurvatures].clear();
  if (derived_threshold && estimate_noise_)
    for (const auto& names : kEigenParts)
      for (const char* name : names)
        values[name].clear();
  if (needsNoiseSample()) {
    for (const char* name : kKeyParts)
      values[name].clear();
    for (const char* name : kSpreadValues)
      values[name].clear();
  }
  if (tile.core_points == 0 || !tile.neighbourhoods || tile.neighbourhoods->empty())
    return true;
  if (needsNoiseSample())
    saveNoiseSample (tile, values);
  if (!derived_threshold)
    return true;
  if (estimate_noise_) {
    saveEigenvalues (tile, values);
    return true;
  }
  auto& curvatures = values[kCurvatures];
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
  const auto text = [] (double value) {
    std::ostringstream out;
    out.precision (17);
    out << value;
    return out.str();
  };
  // The whole cloud's noise, as LocalVarianceClassification estimates it.
  NoiseEstimate noise;
  if (needsNoiseSample()) {
    std::vector<KeyedSpread> sample;
    if (!loadNoiseSample (folder, tiles, sample))
      return false;
    noise = estimateNoiseFromSample (std::move (sample));
  }
  using Classification = LocalVarianceClassification<pcl::PointXYZ>;
  const double sigma =
      estimate_noise_ ? Classification::noiseSigmaRemovedFor (noise) : 0.0;
  if (estimate_noise_ && !noise.valid)
    std::cerr << "Warning: the noise of the whole cloud cannot be estimated: "
              << noise.reason << "; none is removed (the paper's eq. 4-6).\n";
  if (estimate_noise_)
    settings[kNoiseSetting] = text (sigma);
  // Whether the whole cloud's noise is a range camera's, where the untiled classifier
  // estimates it (the edges are then not narrowed).
  if (estimate_noise_ || (getClassificationOptions().curvature_threshold == 0.0 &&
                          curvature_factor_ == 0.0))
    settings[kRangeCameraSetting] =
        Classification::isRangeCameraNoise (noise) ? "1" : "0";
  if (getClassificationOptions().curvature_threshold != 0.0)
    return true;
  // As LocalVarianceClassification derives it: factor * median over every point, the
  // factor chosen from the whole cloud's noise sample when it is not given.
  const char* curvatures = kCurvatures;
  if (estimate_noise_) {
    if (!saveDenoisedCurvatures (folder, tiles, sigma * sigma))
      return false;
    curvatures = kDenoisedCurvatures;
  }
  float median = 0.0f;
  std::uint64_t count = 0;
  if (!tiling::nthOfTileValues (folder, tiles, curvatures, 0.5, median, count))
    return false;
  const double factor = curvature_factor_ != 0.0
                            ? curvature_factor_
                            : Classification::curvatureFactorFor (noise);
  settings[kThresholdSetting] =
      text (count == 0 ? 0.0 : factor * static_cast<double> (median));
  return true;
}

bool
VarianceTileMethod::hasRangeCameraNoise (
    const std::map<std::string, std::string>& settings)
{
  const auto found = settings.find (kRangeCameraSetting);
  return found != settings.end() && found->second == "1";
}

bool
VarianceTileMethod::applyEstimates (
    pcl_ext::LocalVarianceClassification<pcl::PointXYZ>& classifier,
    const std::map<std::string, std::string>& settings) const
{
  if (!needsEstimate())
    return true;
  const auto setting = [&] (const char* name, double& value) {
    const auto found = settings.find (name);
    if (found == settings.end()) {
      std::cerr << "Error: the plan has no " << name
                << " (run the estimate step on every tile first).\n";
      return false;
    }
    value = std::stod (found->second);
    return true;
  };
  double value = 0.0;
  if (getClassificationOptions().curvature_threshold == 0.0) {
    if (!setting (kThresholdSetting, value))
      return false;
    classifier.setCurvatureThreshold (value);
  }
  if (estimate_noise_) {
    if (!setting (kNoiseSetting, value))
      return false;
    classifier.setNoiseStandardDeviation (value); // the whole cloud's, not the tile's
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
