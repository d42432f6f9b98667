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

#include <cmath>
#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
constexpr const char* kThresholdSetting = "curvature_threshold";
// A tile's part of the noise sample: each point's key in three parts of at most 22 bits
// (exact in a float), then its neighbourhood's eigenvalues (as floats, as the
// classifier rounds them) and size. The noise, the spacing and the median kappa of the
// whole cloud are estimated from it.
constexpr const char* kKeyParts[3] = {
    "lv_noise_key_high", "lv_noise_key_mid", "lv_noise_key_low"};
constexpr const char* kSpreadValues[4] = {
    "lv_noise_l0", "lv_noise_l1", "lv_noise_l2", "lv_noise_size"};
constexpr const char* kNoiseSetting = "noise_sigma";
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

/** The tile's points of the whole cloud's noise sample: every core point with a
 * neighbourhood (the plan's sample, getEstimateSelection, or all) whose key is at most
 * the cut of the tile's core keys (the whole cloud's cut is at most that). */
void
saveNoiseSample (const TileCloud& tile,
                 std::map<std::string, std::vector<float>>& values)
{
  const auto& cloud = *tile.cloud;
  const auto& nb = *tile.neighbourhoods;
  NoiseSampleCut cut;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (tile.core[i])
      cut.add (noiseSampleKeyOf (cloud[i].x, cloud[i].y, cloud[i].z));
  for (std::size_t i = 0; i < cloud.size() && !cut.empty(); ++i) {
    if (!tile.core[i] || nb.getRowOfPoint (static_cast<pcl::index_t> (i)) < 0)
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
  given_noise_sigma_ = classifier.getNoiseStandardDeviation();
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

PointSelection
VarianceTileMethod::getEstimateSelection (
    const std::map<std::string, std::string>& settings) const
{
  const auto found = settings.find (kNoiseSampleCutSetting);
  if (found == settings.end())
    return {}; // a plan without the cut: every point, each tile's sample cut its own
  const std::uint64_t cut = std::stoull (found->second);
  return [cut] (const TileCloud& tile, std::vector<char>& query) {
    const auto& cloud = *tile.cloud;
    query.assign (cloud.size(), 0);
    for (std::size_t i = 0; i < cloud.size(); ++i)
      query[i] =
          tile.core[i] && noiseSampleKeyOf (cloud[i].x, cloud[i].y, cloud[i].z) <= cut;
    return true;
  };
}

bool
VarianceTileMethod::estimate (const TileCloud& tile,
                              std::map<std::string, std::vector<float>>& values)
{
  // Every tile writes its part, empty or not.
  for (const char* name : kKeyParts)
    values[name].clear();
  for (const char* name : kSpreadValues)
    values[name].clear();
  if (tile.core_points == 0 || !tile.neighbourhoods || tile.neighbourhoods->empty())
    return true;
  saveNoiseSample (tile, values);
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
  std::vector<KeyedSpread> sample;
  if (!loadNoiseSample (folder, tiles, sample))
    return false;
  // The whole cloud's noise, as LocalVarianceClassification estimates it: when the
  // noise is removed or the curvature factor chosen from it.
  using Classification = LocalVarianceClassification<pcl::PointXYZ>;
  const bool noise_needed = estimate_noise_ || curvature_factor_ == 0.0;
  const NoiseEstimate noise =
      noise_needed ? estimateNoiseFromSample (sample) : NoiseEstimate();
  const double sigma = estimate_noise_ ? Classification::noiseSigmaRemovedFor (noise)
                                       : given_noise_sigma_;
  if (estimate_noise_ && !noise.valid)
    std::cerr << "Warning: the noise of the whole cloud cannot be estimated: "
              << noise.reason << "; none is removed (the paper's eq. 4-6).\n";
  if (estimate_noise_)
    settings[kNoiseSetting] = text (sigma);
  if (getClassificationOptions().curvature_threshold != 0.0)
    return true;
  // As LocalVarianceClassification derives it: factor * the sample's median kappa with
  // the noise removed, the factor chosen from the whole cloud's noise when not given.
  const double median = sampleCurvatureMedian (std::move (sample), sigma * sigma);
  const double factor = curvature_factor_ != 0.0
                            ? curvature_factor_
                            : Classification::curvatureFactorFor (noise);
  settings[kThresholdSetting] = text (std::isfinite (median) ? factor * median : 0.0);
  return true;
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
