/*
 * Tests of makeCrfInput: a generated scene's points as the multi-scale CRF takes them.
 */
#include <pcl_ext/apps/scene_crf_input.h>

#include <gtest/gtest.h>

#include <vector>

namespace {
pcl_ext::simulation::SimulatedPoint
point (float x,
       std::uint8_t r,
       std::uint8_t g,
       std::uint8_t b,
       float intensity,
       std::uint32_t label)
{
  pcl_ext::simulation::SimulatedPoint p;
  p.x = x;
  p.y = 2.f * x;
  p.z = -x;
  p.r = r;
  p.g = g;
  p.b = b;
  p.intensity = intensity;
  p.label = label;
  return p;
}
} // namespace

TEST (SceneCrfInput, PointsColoursIntensitiesAndLabelsInSceneOrder)
{
  pcl_ext::simulation::SyntheticScene scene;
  scene.cloud.push_back (point (1.f, 100, 50, 50, 0.25f, 3));
  scene.cloud.push_back (point (2.f, 0, 0, 0, 0.5f, 0)); // black
  scene.cloud.push_back (point (3.f, 0, 0, 255, 1.f, 7));
  std::vector<std::uint32_t> labels = {42}; // replaced, not appended to
  const pcl_ext::CrfInput in = pcl_ext::apps::makeCrfInput (scene, labels);
  ASSERT_TRUE (in.xyz);
  ASSERT_EQ (in.xyz->size(), 3u);
  EXPECT_EQ ((*in.xyz)[2].x, 3.f);
  EXPECT_EQ ((*in.xyz)[2].y, 6.f);
  EXPECT_EQ ((*in.xyz)[2].z, -3.f);
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{3, 0, 7}));
  // Colour normalised to (r, g, b) / (r + g + b); a third each for black.
  ASSERT_EQ (in.colours.size(), 3u);
  EXPECT_FLOAT_EQ (in.colours[0].x(), 0.5f);
  EXPECT_FLOAT_EQ (in.colours[0].y(), 0.25f);
  EXPECT_FLOAT_EQ (in.colours[0].z(), 0.25f);
  EXPECT_FLOAT_EQ (in.colours[1].x(), 1.f / 3.f);
  EXPECT_FLOAT_EQ (in.colours[1].z(), 1.f / 3.f);
  EXPECT_FLOAT_EQ (in.colours[2].z(), 1.f);
  EXPECT_EQ (in.intensity, (std::vector<float>{0.25f, 0.5f, 1.f}));
}

TEST (SceneCrfInput, EmptySceneGivesEmptyInput)
{
  std::vector<std::uint32_t> labels = {1, 2};
  const pcl_ext::CrfInput in =
      pcl_ext::apps::makeCrfInput (pcl_ext::simulation::SyntheticScene(), labels);
  ASSERT_TRUE (in.xyz);
  EXPECT_TRUE (in.xyz->empty());
  EXPECT_TRUE (in.colours.empty());
  EXPECT_TRUE (in.intensity.empty());
  EXPECT_TRUE (labels.empty());
}
