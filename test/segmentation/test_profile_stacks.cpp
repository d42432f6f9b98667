/*
 * Tests of the profile stacks (Sithole & Mapurisa, section 2 and 4): stack normals,
 * stacks of profiles, the average point spacing.
 */
#include <pcl_ext/segmentation/profile_stacks.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

using namespace pcl_ext::profiles;

namespace {
double
lineAngleDeg (const Eigen::Vector3f& a, const Eigen::Vector3f& b)
{
  return std::acos (std::min (1.0f, std::abs (a.dot (b)))) * 180.0 / M_PI;
}

double
minPairAngle (const std::vector<Eigen::Vector3f>& normals)
{
  double best = 180;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j)
      best = std::min (best, lineAngleDeg (normals[i], normals[j]));
  return best;
}
} // namespace

TEST (StackNormals, HemisphereSpreadsAsFarAsPossible)
{
  // Best line packings: 3 orthogonal axes (90), 4 cube diagonals (70.53), 6 icosahedron
  // axes (63.43).
  const double expected[7] = {0, 0, 90.0, 90.0, 70.5288, 63.4349, 63.4349};
  for (unsigned int k = 2; k <= 6; ++k) {
    const auto normals = makeStackNormals (k, StackDistribution::Hemisphere);
    ASSERT_EQ (normals.size(), k);
    for (const auto& n : normals) {
      EXPECT_NEAR (n.norm(), 1.0f, 1e-5f);
      EXPECT_GE (n.z(), -1e-6f);
      for (int axis = 0; axis < 3; ++axis) // never along a coordinate axis
        EXPECT_LT (std::abs (n[axis]), 0.999f);
    }
    EXPECT_NEAR (minPairAngle (normals), expected[k], 0.01) << k << " stacks";
  }
  const auto many = makeStackNormals (12, StackDistribution::Hemisphere);
  ASSERT_EQ (many.size(), 12u);
  EXPECT_GT (minPairAngle (many), 25.0);
  EXPECT_TRUE (makeStackNormals (0, StackDistribution::Hemisphere).empty());
}

TEST (StackNormals, HorizontalHalfCircle)
{
  const auto normals = makeStackNormals (3, StackDistribution::HorizontalHalfCircle);
  ASSERT_EQ (normals.size(), 3u);
  for (const auto& n : normals)
    EXPECT_NEAR (n.z(), 0.0f, 1e-6f);
  EXPECT_NEAR (minPairAngle (normals), 60.0, 1e-3);
}

TEST (Stacks, EveryPointInExactlyOneContiguousProfile)
{
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> u (-1.f, 1.f);
  std::vector<Eigen::Vector3f> xyz (5000);
  for (auto& p : xyz)
    p = Eigen::Vector3f (u (rng), 2 * u (rng), 0.5f * u (rng));
  const Eigen::Vector3f normal = Eigen::Vector3f (1, 2, 3).normalized();
  const double width = 0.05;
  Stack stack;
  ASSERT_TRUE (buildStack (xyz, normal, width, stack));
  ASSERT_EQ (stack.order.size(), xyz.size());
  std::set<std::uint32_t> seen (stack.order.begin(), stack.order.end());
  EXPECT_EQ (seen.size(), xyz.size()); // every point exactly once
  double last_max = -1e30;
  for (std::size_t p = 0; p < stack.numProfiles(); ++p) {
    ASSERT_LT (stack.offsets[p], stack.offsets[p + 1]); // no empty profile kept
    double lo = 1e30, hi = -1e30;
    for (std::uint32_t k = stack.offsets[p]; k < stack.offsets[p + 1]; ++k) {
      const double t = normal.dot (xyz[stack.order[k]]);
      lo = std::min (lo, t);
      hi = std::max (hi, t);
      EXPECT_EQ (stack.profile_of_point[stack.order[k]], p);
    }
    EXPECT_LT (hi - lo, width + 1e-6); // a slab no wider than the width
    EXPECT_GT (lo, last_max - 1e-9);   // slabs ordered along the normal
    last_max = hi;
  }
  // A comparison sort takes over when the width is tiny: same partition, still no empty
  // slab.
  Stack fine;
  ASSERT_TRUE (buildStack (xyz, normal, 1e-9, fine));
  EXPECT_EQ (fine.order.size(), xyz.size());
  EXPECT_LE (fine.numProfiles(), xyz.size());
  // Width larger than the cloud: one profile.
  Stack wide;
  ASSERT_TRUE (buildStack (xyz, normal, 100.0, wide));
  EXPECT_EQ (wide.numProfiles(), 1u);
  EXPECT_FALSE (buildStack (xyz, normal, 0.0, wide));
  EXPECT_FALSE (buildStack (xyz, normal, -1.0, wide));
  EXPECT_FALSE (buildStack (xyz, Eigen::Vector3f::Zero(), 0.1, wide));
  EXPECT_FALSE (buildStack ({}, normal, 0.1, wide));
}

TEST (Spacing, GridSpacingIsRecovered)
{
  std::vector<Eigen::Vector3f> xyz;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 100; ++j)
      xyz.emplace_back (0.02f * i, 0.02f * j, 0.f);
  // Square grid of step s: the 6th neighbour is at s sqrt(2), so sqrt(pi 2 s^2 / 6)
  // = 1.023 s.
  EXPECT_NEAR (
      estimatePointSpacing (xyz), 0.02 * std::sqrt (M_PI / 3.0), 5e-4); // borders
  // Anisotropic grid (0.01 along x, 0.04 along y): area per point 0.0004, spacing 0.02
  // within 10%, where the nearest-neighbour distance would say 0.01.
  std::vector<Eigen::Vector3f> lines;
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j < 50; ++j)
      lines.emplace_back (0.01f * i, 0.04f * j, 0.f);
  EXPECT_NEAR (estimatePointSpacing (lines), 0.02, 0.002);
  // Duplicates do not make the spacing zero; they double the density (spacing /
  // sqrt(2)).
  const auto copy = xyz;
  xyz.insert (xyz.end(), copy.begin(), copy.end());
  EXPECT_NEAR (estimatePointSpacing (xyz), 0.02 / std::sqrt (2.0), 0.002);
  EXPECT_EQ (
      estimatePointSpacing (std::vector<Eigen::Vector3f> (10, Eigen::Vector3f::Ones())),
      0.0);
  EXPECT_EQ (estimatePointSpacing ({Eigen::Vector3f::Zero()}), 0.0);
}
