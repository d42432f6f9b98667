/*
 * pcl_ext: the adaptive super-voxel radius (Lim & Suter 2008, eq. 1-4).
 */
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/adaptive_radius.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace {
constexpr double kPi = 3.14159265358979323846;
// Fewer than this many points give no plane: the radius never shrinks below the
// distance to the 5th neighbour (pcl_ext's floor; the paper does not say).
constexpr std::size_t kMinPoints = 5;

double
maxColourVariance (const std::vector<Eigen::Vector3f>& colours,
                   const pcl::Indices& indices)
{
  if (colours.empty() || indices.size() < 2)
    return 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sq = Eigen::Vector3d::Zero();
  for (const auto i : indices) {
    const Eigen::Vector3d c = colours[static_cast<std::size_t> (i)].cast<double>();
    sum += c;
    sq += c.cwiseProduct (c);
  }
  const double n = static_cast<double> (indices.size());
  const Eigen::Vector3d var = sq / n - (sum / n).cwiseProduct (sum / n);
  return std::max (0.0, var.maxCoeff());
}
} // namespace

bool
checkAdaptiveRadiusParameters (const AdaptiveRadiusParameters& p, const char* caller)
{
  const char* bad = nullptr;
  if (p.initial_k < 3)
    bad = "initial k must be at least 3";
  else if (!(p.damping > 0.0 && p.damping <= 1.0))
    bad = "damping must be in (0, 1]";
  else if (p.max_iterations < 1)
    bad = "the number of iterations must be at least 1";
  else if (p.max_k <= p.initial_k)
    bad = "the k threshold must exceed the initial k";
  else if (!(p.saturation >= 0.0) || !std::isfinite (p.saturation))
    bad = "the saturation tolerance must be finite and >= 0";
  else if (!(p.noise >= 0.0) || !std::isfinite (p.noise))
    bad = "the noise constant must be finite and >= 0";
  else if (!(p.c1 > 0.0) || !std::isfinite (p.c1) || !(p.c2 >= 0.0) ||
           !std::isfinite (p.c2))
    bad = "c1 must be > 0 and c2 >= 0, both finite";
  else if (!(p.epsilon > 0.0 && p.epsilon <= 1.0))
    bad = "epsilon must be in (0, 1]";
  else if (!(p.colour_weight >= 0.0) || !std::isfinite (p.colour_weight))
    bad = "the colour weight must be finite and >= 0";
  else if (!(p.min_radius >= 0.0) || !(p.max_radius > p.min_radius) ||
           std::isnan (p.max_radius))
    bad = "the radius bounds must satisfy 0 <= min < max";
  if (bad) {
    PCL_ERROR ("[pcl_ext::%s] Invalid adaptive radius parameters: %s.\n", caller, bad);
    return false;
  }
  return true;
}

double
estimateNoiseFromPlanarPatch (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                              const std::vector<pcl::index_t>& patch)
{
  Eigen::Matrix3d cov;
  Eigen::Vector3d centroid;
  if (computeLocalCovariance (cloud, patch, cov, centroid) < 3)
    return std::numeric_limits<double>::quiet_NaN();
  EigenDecomposition eig;
  if (!computeEigenDecomposition (cov, eig))
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d n = eig.normal();
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto i : patch) {
    const auto& p = cloud[static_cast<std::size_t> (i)];
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      continue;
    sum += std::abs ((p.getVector3fMap().cast<double>() - centroid).dot (n));
    ++count;
  }
  return sum / static_cast<double> (count);
}

bool
AdaptiveRadiusEstimator::initialize (
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
    const std::vector<Eigen::Vector3f>& colours,
    const AdaptiveRadiusParameters& parameters)
{
  cloud_.reset();
  finite_ = 0;
  if (!checkAdaptiveRadiusParameters (parameters,
                                      "AdaptiveRadiusEstimator::initialize"))
    return false;
  if (!cloud || (!colours.empty() && colours.size() != cloud->size())) {
    PCL_ERROR (
        "[pcl_ext::AdaptiveRadiusEstimator::initialize] No cloud, or colours do not "
        "match it.\n");
    return false;
  }
  std::vector<float> xyz;
  std::vector<pcl::index_t> ids;
  xyz.reserve (cloud->size() * 3);
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const auto& p = (*cloud)[i];
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      continue;
    xyz.insert (xyz.end(), {p.x, p.y, p.z});
    ids.push_back (static_cast<pcl::index_t> (i));
  }
  if (ids.size() < static_cast<std::size_t> (parameters.initial_k)) {
    PCL_ERROR (
        "[pcl_ext::AdaptiveRadiusEstimator::initialize] %zu finite points, fewer than "
        "k = %d.\n",
        ids.size(),
        parameters.initial_k);
    return false;
  }
  finite_ = ids.size();
  tree_.build (std::move (xyz), std::move (ids));
  cloud_ = cloud;
  colours_ = colours;
  parameters_ = parameters;
  noise_ = parameters.noise > 0.0 ? parameters.noise : estimateNoise();
  return true;
}

std::uint64_t
noiseSampleKey (const pcl::PointXYZ& point)
{
  return hashPosition (point.x, point.y, point.z, 0x6e6f697365ULL);
}

double
noiseFromSamples (std::vector<NoiseSample> samples)
{
  if (samples.empty())
    return 0.0;
  std::sort (samples.begin(), samples.end(), [] (const auto& a, const auto& b) {
    return a.flatness < b.flatness || (a.flatness == b.flatness && a.rms < b.rms);
  });
  const std::size_t flattest = std::max<std::size_t> (1, samples.size() / 10);
  std::vector<float> rms;
  for (std::size_t i = 0; i < flattest; ++i)
    rms.push_back (samples[i].rms);
  std::nth_element (rms.begin(), rms.begin() + rms.size() / 2, rms.end());
  double sigma = rms[rms.size() / 2];
  if (!(sigma > 0.0)) {
    std::vector<float> spacing;
    for (const auto& s : samples)
      spacing.push_back (s.spacing);
    std::nth_element (
        spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
    sigma = 0.01 * spacing[spacing.size() / 2];
  }
  return sigma;
}

std::vector<pcl::index_t>
AdaptiveRadiusEstimator::selectNoiseSamplePoints (
    const std::vector<char>* eligible) const
{
  std::vector<std::pair<std::uint64_t, pcl::index_t>> keyed;
  for (std::size_t i = 0; i < cloud_->size(); ++i) {
    const auto& p = (*cloud_)[i];
    if ((eligible && !(*eligible)[i]) || !std::isfinite (p.x) || !std::isfinite (p.y) ||
        !std::isfinite (p.z))
      continue;
    keyed.emplace_back (noiseSampleKey (p), static_cast<pcl::index_t> (i));
  }
  const std::size_t n = std::min (kNoiseSamples, keyed.size());
  std::partial_sort (keyed.begin(), keyed.begin() + n, keyed.end());
  std::vector<pcl::index_t> chosen (n);
  for (std::size_t i = 0; i < n; ++i)
    chosen[i] = keyed[i].second;
  return chosen;
}

bool
AdaptiveRadiusEstimator::measureNoiseSample (pcl::index_t index,
                                             NoiseSample& sample) const
{
  const std::size_t k = static_cast<std::size_t> (parameters_.initial_k);
  pcl::Indices nn (k);
  std::vector<float> d2 (k);
  const auto& p = (*cloud_)[static_cast<std::size_t> (index)];
  const float q[3] = {p.x, p.y, p.z};
  const std::size_t found = tree_.nearestKSearch (q, k, nn.data(), d2.data());
  Eigen::Matrix3d cov;
  Eigen::Vector3d c;
  EigenDecomposition eig;
  if (found < 3 ||
      computeLocalCovariance (*cloud_, nn.begin(), nn.begin() + found, cov, c) < 3 ||
      !computeEigenDecomposition (cov, eig))
    return false;
  const double total = eig.values.sum();
  if (!(total > 0.0))
    return false;
  sample.flatness = static_cast<float> (eig.values (0) / total);
  sample.rms = static_cast<float> (std::sqrt (std::max (0.0, eig.values (0))));
  sample.spacing = std::sqrt (d2[found - 1]);
  return true;
}

double
AdaptiveRadiusEstimator::estimateNoise() const
{
  std::vector<NoiseSample> samples;
  for (const auto i : selectNoiseSamplePoints()) {
    NoiseSample s;
    if (measureNoiseSample (i, s))
      samples.push_back (s);
  }
  return noiseFromSamples (std::move (samples));
}

float
AdaptiveRadiusEstimator::estimate (pcl::index_t index, int* steps) const
{
  const auto& p = (*cloud_)[static_cast<std::size_t> (index)];
  const float q[3] = {p.x, p.y, p.z};
  const std::size_t k0 = static_cast<std::size_t> (parameters_.initial_k);
  pcl::Indices nn (k0);
  std::vector<float> d2 (k0);
  const std::size_t found = tree_.nearestKSearch (q, k0, nn.data(), d2.data());
  nn.resize (found);
  d2.resize (found);
  double r = std::sqrt (static_cast<double> (d2.back()));
  const double r_floor =
      std::max (parameters_.min_radius,
                static_cast<double> (std::sqrt (d2[std::min (found, kMinPoints) - 1])));
  const double bracket_base = parameters_.c2 * noise_ * noise_;
  const Eigen::Vector3d pd (p.x, p.y, p.z);
  int it = 0;
  for (; it < parameters_.max_iterations && r > 0.0;) {
    const double n = static_cast<double> (nn.size());
    const double rho = n / (kPi * r * r); // eq. 1
    Eigen::Matrix3d cov;
    Eigen::Vector3d centroid;
    EigenDecomposition eig;
    if (computeLocalCovariance (*cloud_, nn, cov, centroid) < 3 ||
        !computeEigenDecomposition (cov, eig))
      break;
    const double d = std::abs ((pd - centroid).dot (eig.normal()));
    double mu = 0.0;
    for (const float s : d2)
      mu += std::sqrt (static_cast<double> (s));
    mu /= std::max (1.0, n - 1.0); // the point itself is at distance 0
    const double kappa = std::max (2.0 * d / (mu * mu), 1e-12); // eq. 2
    const double colour = std::max (
        0.05, 1.0 - parameters_.colour_weight * maxColourVariance (colours_, nn));
    const double r_opt =
        std::cbrt ((parameters_.c1 * noise_ / std::sqrt (parameters_.epsilon * rho) +
                    bracket_base) /
                   kappa) *
        colour;
    double r_new =
        (1.0 - parameters_.damping) * r + parameters_.damping * r_opt; // eq. 3
    r_new = std::min (std::max (r_new, r_floor), parameters_.max_radius);
    const double k_new = kPi * rho * r_new * r_new; // eq. 4
    ++it;
    if (k_new >= parameters_.max_k) {
      r = std::min (r_new, std::sqrt (parameters_.max_k / (kPi * rho)));
      break;
    }
    const bool saturated = std::abs (k_new - n) < parameters_.saturation;
    r = r_new;
    if (saturated || it == parameters_.max_iterations)
      break;
    tree_.radiusSearch (q, r, nn, d2, static_cast<std::size_t> (4 * parameters_.max_k));
    if (nn.size() < 3)
      break;
  }
  if (steps)
    *steps = it;
  return static_cast<float> (std::max (r, r_floor));
}

void
AdaptiveRadiusEstimator::neighbours (pcl::index_t index,
                                     float radius,
                                     pcl::Indices& result) const
{
  const auto& p = (*cloud_)[static_cast<std::size_t> (index)];
  const float q[3] = {p.x, p.y, p.z};
  std::vector<float> d2;
  tree_.radiusSearch (q, radius, result, d2);
}

void
AdaptiveRadiusEstimator::nearest (const Eigen::Vector3f& position,
                                  std::size_t k,
                                  pcl::Indices& result) const
{
  k = std::min (k, finite_);
  result.resize (k);
  std::vector<float> d2 (k);
  result.resize (tree_.nearestKSearch (position.data(), k, result.data(), d2.data()));
}
} // namespace pcl_ext
