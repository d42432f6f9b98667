/*
 * Adaptive super-voxels (Lim & Suter 2008, section 3.1) on a generated street scene:
 * how well they keep to the class boundaries, and how much they reduce the cloud.
 */
#include "../classification/crf_test_scenes.h"

#include <pcl_ext/segmentation/supervoxel_set.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

TEST (AdaptiveSupervoxels, StreetBoundaryAdherenceAndReduction)
{
  pcl_ext::CrfInput in;
  std::vector<std::uint32_t> labels;
  ASSERT_TRUE (crf_test::streetScene (3, 60000, in, labels));
  pcl_ext::SupervoxelSet set;
  pcl_ext::SupervoxelParameters p;
  ASSERT_TRUE (pcl_ext::computeAdaptiveSupervoxels (in.xyz, in.colours, p, set));
  // A point is misplaced when it sits in a super-voxel whose majority class is not its
  // own.
  std::vector<char> misplaced (labels.size(), 0);
  for (const auto& sv : set.supervoxels) {
    std::map<std::uint32_t, std::size_t> votes;
    for (const auto i : sv.members)
      ++votes[labels[i]];
    std::uint32_t major = 0;
    std::size_t best = 0;
    for (const auto& [l, n] : votes)
      if (n > best)
        best = n, major = l;
    for (const auto i : sv.members)
      if (labels[i] != major)
        misplaced[i] = 1;
  }
  std::size_t bad = 0;
  for (const char m : misplaced)
    bad += m;
  const double fraction = static_cast<double> (bad) / labels.size();
  std::printf ("street: %zu points, %zu super-voxels (%.1f points per super-voxel), "
               "%.2f %% of points in a super-voxel of another majority class\n",
               labels.size(),
               set.size(),
               static_cast<double> (labels.size()) / set.size(),
               100.0 * fraction);
  EXPECT_LT (fraction, 0.05);
  EXPECT_GT (static_cast<double> (labels.size()) / set.size(), 8.0);
}
