/*
 * Test of pcl_ext::CylinderSegmentJoin's lengths in units of the point spacing: the
 * same scene at any scale gives the same segments.
 */
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/cylinder_segment_join.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Join = pcl_ext::CylinderSegmentJoin<pcl::PointXYZ>;

namespace {
/** A pipe of radius 0.1 along x at height 1, seen from below on a 0.02 grid with 3 mm
 * radial noise, cut at a support at x = 4 (the 0.6 around it missing): two spans, the
 * input segments 0 and 1; the ground below on a 0.03 grid, segment 2. */
void
pipeOnASupport (Cloud& cloud, std::vector<pcl::PointIndices>& segments)
{
  pcl_ext::RandomStream rng (1);
  segments.assign (3, pcl::PointIndices());
  const auto add = [&] (std::size_t segment, double x, double y, double z) {
    segments[segment].indices.push_back (static_cast<pcl::index_t> (cloud.size()));
    cloud.push_back (pcl::PointXYZ (
        static_cast<float> (x), static_cast<float> (y), static_cast<float> (z)));
  };
  for (double x = 0.01; x < 8.0; x += 0.02)
    for (double theta = -0.5 * M_PI + 0.1; theta < 0.5 * M_PI; theta += 0.2) {
      if (std::abs (x - 4.0) < 0.3)
        continue;
      const double r = 0.1 + 0.003 * rng.gaussian();
      add (x < 4.0 ? 0 : 1, x, r * std::sin (theta), 1.0 - r * std::cos (theta));
    }
  for (double x = 0.015; x < 8.0; x += 0.03)
    for (double y = -0.5; y < 0.5; y += 0.03)
      add (2, x, y, 0.003 * rng.gaussian());
}
} // namespace

TEST (CylinderSegmentJoinScale, ScaledCloudGivesTheSameSegments)
{
  // The lengths follow the point spacing: the scene 16 times larger (a pipe of radius
  // 1.6, beyond the 0.6 the join looked for in metres, a gap of 9.6) or 8 times smaller
  // gives the same segments. Powers of two scale floats exactly.
  Cloud::Ptr cloud (new Cloud);
  std::vector<pcl::PointIndices> segments;
  pipeOnASupport (*cloud, segments);
  std::vector<pcl::PointIndices> joined;
  Join j;
  j.setInputCloud (cloud);
  j.setInputSegments (segments);
  j.join (joined);
  // The ground (larger, first) and the two spans as one segment.
  ASSERT_EQ (joined.size(), 2u);
  EXPECT_EQ (joined[0].indices, segments[2].indices);
  EXPECT_EQ (joined[1].indices.size(),
             segments[0].indices.size() + segments[1].indices.size());
  const double spacing = j.getUsedPointSpacing();
  EXPECT_DOUBLE_EQ (j.getUsedParameters().detection.distance_tolerance, 0.6 * spacing);
  for (const double scale : {16.0, 0.125}) {
    Cloud::Ptr scaled (new Cloud (*cloud));
    for (auto& q : *scaled)
      q.getVector3fMap() *= static_cast<float> (scale);
    std::vector<pcl::PointIndices> out;
    Join k;
    k.setInputCloud (scaled);
    k.setInputSegments (segments);
    k.join (out);
    EXPECT_NEAR (k.getUsedPointSpacing(), scale * spacing, 1e-6 * scale) << scale;
    ASSERT_EQ (out.size(), joined.size()) << scale;
    for (std::size_t s = 0; s < out.size(); ++s)
      EXPECT_EQ (out[s].indices, joined[s].indices) << scale;
  }
}
