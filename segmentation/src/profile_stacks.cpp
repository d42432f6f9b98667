/*
 * pcl_ext: stacks of contiguous profiles (Sithole & Mapurisa, section 2 and 4).
 */
#include <pcl_ext/segmentation/profile_stacks.h>

#include "sampled_neighbours.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace pcl_ext {
namespace profiles {
namespace {
Eigen::Vector3f
fromAngles (double azimuth, double elevation)
{
  return Eigen::Vector3f (
      static_cast<float> (std::cos (elevation) * std::cos (azimuth)),
      static_cast<float> (std::cos (elevation) * std::sin (azimuth)),
      static_cast<float> (std::sin (elevation)));
}

std::vector<Eigen::Vector3f>
hemisphereNormals (unsigned int count)
{
  // Equal-elevation sets (1 to 4 stacks): the elevation that makes the normals of 3
  // stacks orthogonal and those of 4 stacks the cube diagonals; 2 stacks are 90 degrees
  // apart.
  const double deg = M_PI / 180.0;
  const double diagonal = std::asin (1.0 / std::sqrt (3.0));
  std::vector<Eigen::Vector3f> normals;
  switch (count) {
  case 1:
    normals.push_back (fromAngles (45 * deg, diagonal));
    break;
  case 2:
    normals = {fromAngles (45 * deg, 45 * deg), fromAngles (225 * deg, 45 * deg)};
    break;
  case 3:
    for (int k = 0; k < 3; ++k)
      normals.push_back (fromAngles ((30 + 120 * k) * deg, diagonal));
    break;
  case 4:
    for (int k = 0; k < 4; ++k)
      normals.push_back (fromAngles ((45 + 90 * k) * deg, diagonal));
    break;
  case 5:
  case 6: {
    // The icosahedron's six axes (63.4 degrees apart), turned off the coordinate
    // planes.
    const float g = static_cast<float> ((1.0 + std::sqrt (5.0)) / 2.0);
    const Eigen::Vector3f axes[6] = {
        {0, 1, g}, {0, -1, g}, {1, g, 0}, {-1, g, 0}, {g, 0, 1}, {-g, 0, 1}};
    const Eigen::Matrix3f turn =
        Eigen::AngleAxisf (0.3f, Eigen::Vector3f (1.f, 2.f, 3.f).normalized())
            .toRotationMatrix();
    for (unsigned int k = 0; k < count; ++k) {
      Eigen::Vector3f n = (turn * axes[k]).normalized();
      normals.push_back (n.z() < 0 ? Eigen::Vector3f (-n) : n);
    }
    break;
  }
  default: {
    // Fibonacci spiral: equal-area bands in z, golden-angle steps in azimuth.
    const double golden = M_PI * (3.0 - std::sqrt (5.0));
    for (unsigned int k = 0; k < count; ++k)
      normals.push_back (fromAngles (golden * k, std::asin ((k + 0.5) / count)));
  }
  }
  return normals;
}
} // namespace

std::vector<Eigen::Vector3f>
makeStackNormals (unsigned int count, StackDistribution distribution)
{
  if (count == 0)
    return {};
  if (distribution == StackDistribution::Hemisphere)
    return hemisphereNormals (count);
  std::vector<Eigen::Vector3f> normals;
  for (unsigned int k = 0; k < count; ++k)
    normals.push_back (fromAngles (M_PI * k / count, 0.0));
  return normals;
}

std::vector<SampledNeighbourhood>
sampleNeighbourhoods (const std::vector<Eigen::Vector3f>& xyz,
                      std::size_t samples,
                      std::size_t k)
{
  std::vector<SampledNeighbourhood> result;
  detail::forEachSampledNeighbourhood (
      xyz, samples, k, [&] (std::uint32_t point, const auto& nearest) {
        SampledNeighbourhood sample;
        sample.index = point;
        sample.point = xyz[point];
        for (const auto& e : nearest)
          sample.nearest.emplace_back (e.first, xyz[e.second]);
        result.push_back (std::move (sample));
      });
  return result;
}

double
pointSpacingOf (const std::vector<SampledNeighbourhood>& neighbourhoods)
{
  constexpr std::size_t k = 6;
  double sum = 0.0;
  std::size_t found = 0;
  for (const auto& sample : neighbourhoods)
    if (sample.nearest.size() >= k) {
      // k points within r on a surface: pi r^2 / k of surface per point.
      sum += std::sqrt (static_cast<double> (sample.nearest[k - 1].first) * M_PI / k);
      ++found;
    }
  return found ? sum / static_cast<double> (found) : 0.0;
}

double
estimatePointSpacing (const std::vector<Eigen::Vector3f>& xyz, std::size_t samples)
{
  return pointSpacingOf (sampleNeighbourhoods (xyz, samples, 6));
}

bool
buildStack (const std::vector<Eigen::Vector3f>& xyz,
            const Eigen::Vector3f& normal,
            double width,
            Stack& stack,
            double origin)
{
  stack = Stack();
  const std::size_t n = xyz.size();
  if (n == 0 || !(width > 0.0) || !std::isfinite (width) || !normal.allFinite() ||
      normal.norm() < 1e-6f)
    return false;
  stack.normal = normal.normalized();
  // Any orthonormal in-profile basis; start from the coordinate axis least along the
  // normal.
  int least = 0;
  stack.normal.cwiseAbs().minCoeff (&least);
  stack.u = stack.normal.cross (Eigen::Vector3f::Unit (least)).normalized();
  stack.v = stack.normal.cross (stack.u);
  stack.width = width;

  const Eigen::Vector3d nd = stackDirection (normal);
  std::vector<double> t (n);
  double lo = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = nd.dot (xyz[i].cast<double>());
    lo = std::min (lo, t[i]);
  }
  if (!std::isnan (origin)) {
    if (!(lo >= origin) || !std::isfinite (origin)) {
      stack = Stack();
      return false;
    }
    lo = origin;
  }
  stack.origin = lo;
  std::vector<std::uint64_t> id (n);
  std::uint64_t max_id = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Clamped: a width tiny against the extent must not overflow (those profiles are
    // empty).
    const double f = std::floor ((t[i] - lo) / width);
    id[i] =
        f < 1e18 ? static_cast<std::uint64_t> (f) : static_cast<std::uint64_t> (1e18);
    max_id = std::max (max_id, id[i]);
  }

  stack.order.resize (n);
  stack.profile_of_point.resize (n);
  if (max_id <= 4 * n + 16) {
    // Counting sort by profile number; positions stay ascending within each profile.
    std::vector<std::uint32_t> count (max_id + 2, 0);
    for (std::size_t i = 0; i < n; ++i)
      ++count[id[i] + 1];
    std::partial_sum (count.begin(), count.end(), count.begin());
    std::vector<std::uint32_t> next (count.begin(), count.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      stack.order[next[id[i]]++] = static_cast<std::uint32_t> (i);
    stack.offsets.push_back (0);
    std::vector<std::uint32_t> compact (max_id + 1, 0);
    for (std::uint64_t p = 0; p <= max_id; ++p) {
      compact[p] = static_cast<std::uint32_t> (stack.offsets.size() - 1);
      if (count[p + 1] > count[p])
        stack.offsets.push_back (count[p + 1]);
    }
    for (std::size_t i = 0; i < n; ++i)
      stack.profile_of_point[i] = compact[id[i]];
  }
  else {
    std::iota (stack.order.begin(), stack.order.end(), 0u);
    std::stable_sort (stack.order.begin(),
                      stack.order.end(),
                      [&] (std::uint32_t a, std::uint32_t b) { return id[a] < id[b]; });
    stack.offsets.push_back (0);
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0 && id[stack.order[k]] != id[stack.order[k - 1]])
        stack.offsets.push_back (static_cast<std::uint32_t> (k));
      stack.profile_of_point[stack.order[k]] =
          static_cast<std::uint32_t> (stack.offsets.size() - 1);
    }
    stack.offsets.push_back (static_cast<std::uint32_t> (n));
  }
  return true;
}
} // namespace profiles
} // namespace pcl_ext
