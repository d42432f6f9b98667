/*
 * pcl_ext: what a cloud shows and the profile segmentation's configuration chosen from
 * it (Sithole & Mapurisa; not in the paper).
 */
#include <pcl_ext/segmentation/profile_auto.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <utility>

namespace pcl_ext {
namespace profiles {
namespace {
/** Neighbours of a noise neighbourhood: enough for a plane's residual to be a stable
 * estimate (13 degrees of freedom), few enough to stay within about two spacings. */
constexpr std::size_t kNoiseNeighbours = 16;
/** The spacing's neighbour, as estimatePointSpacing. */
constexpr std::size_t kSpacingNeighbour = 6;

double
quantile (std::vector<double> values, double q)
{
  if (values.empty())
    return 0.0;
  const std::size_t i =
      std::min (values.size() - 1, static_cast<std::size_t> (q * values.size()));
  std::nth_element (values.begin(), values.begin() + i, values.end());
  return values[i];
}
} // namespace

CloudStatistics
cloudStatisticsOf (const std::vector<SampledNeighbourhood>& neighbourhoods)
{
  CloudStatistics result;
  std::vector<double> spacings, noises;
  for (const auto& sample : neighbourhoods) {
    if (sample.nearest.size() < kNoiseNeighbours)
      continue;
    const std::size_t k = kNoiseNeighbours;
    spacings.push_back (
        std::sqrt (static_cast<double> (sample.nearest[kSpacingNeighbour - 1].first) *
                   M_PI / kSpacingNeighbour));
    // The plane of the point and its neighbours, relative to the point (precision).
    const Eigen::Vector3f& p = sample.point;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t j = 0; j < k; ++j)
      mean += (sample.nearest[j].second - p).cast<double>();
    mean /= static_cast<double> (k + 1);
    Eigen::Matrix3d covariance = mean * mean.transpose(); // the point itself, at 0
    for (std::size_t j = 0; j < k; ++j) {
      const Eigen::Vector3d d = (sample.nearest[j].second - p).cast<double>() - mean;
      covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (
        covariance, Eigen::EigenvaluesOnly);
    const double dof = static_cast<double> (k + 1 - 3);
    noises.push_back (std::sqrt (std::max (0.0, solver.eigenvalues()[0]) / dof));
  }
  if (spacings.empty())
    return result;
  double sum = 0.0;
  for (const double v : spacings)
    sum += v;
  result.spacing = sum / static_cast<double> (spacings.size());
  const double low = quantile (spacings, 0.1);
  result.spacing_variation = low > 0.0 ? quantile (spacings, 0.9) / low : 0.0;
  result.noise = quantile (noises, 0.5);
  result.samples = spacings.size();
  return result;
}

CloudStatistics
estimateCloudStatistics (const std::vector<Eigen::Vector3f>& xyz, std::size_t samples)
{
  if (xyz.size() <= kNoiseNeighbours || samples == 0)
    return CloudStatistics();
  return cloudStatisticsOf (sampleNeighbourhoods (xyz, samples, kNoiseNeighbours));
}

AutoConfiguration
chooseConfiguration (const CloudStatistics& statistics, double largest_share)
{
  AutoConfiguration c;
  if (!(statistics.spacing > 0.0))
    return c;
  c.curve_fitting = largest_share >= kAutoTouchingShare;
  c.noisy = c.curve_fitting && statistics.noise >= kAutoNoiseRatio * statistics.spacing;
  c.side_frames = c.curve_fitting;
  c.join_cylinders = c.curve_fitting;
  c.local_threshold = statistics.spacing_variation > kAutoLocalThresholdVariation;
  return c;
}

std::string
describeConfiguration (const CloudStatistics& statistics,
                       double largest_share,
                       const AutoConfiguration& configuration)
{
  char line[640];
  std::snprintf (
      line,
      sizeof (line),
      "cloud: spacing %.4g, noise %.3g (%.2f spacings; noisy from %.2f), spacing "
      "variation %.2f (local thresholds above %.2f), largest proximity segment %.2f "
      "of the points (curve fitting from %.2f); chosen: %s%s%s%s",
      statistics.spacing,
      statistics.noise,
      statistics.spacing > 0.0 ? statistics.noise / statistics.spacing : 0.0,
      kAutoNoiseRatio,
      statistics.spacing_variation,
      kAutoLocalThresholdVariation,
      largest_share,
      kAutoTouchingShare,
      configuration.curve_fitting
          ? (configuration.noisy ? "curve fitting for noisy scans" : "curve fitting")
          : "proximity",
      configuration.side_frames ? ", side frames" : "",
      configuration.local_threshold ? ", local thresholds" : "",
      configuration.join_cylinders ? ", cylinder join" : "");
  return line;
}
} // namespace profiles
} // namespace pcl_ext
