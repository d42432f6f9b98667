/*
 * Tests of the point-type-free part of Lim & Suter's features (saliency_features.h):
 * the local ground, the feature names and scales.
 */
#include <pcl_ext/features/saliency_features.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {
/** A KdTree3f over every point of \a cloud (all finite), indexed as in the cloud. */
void
buildTree (const pcl::PointCloud<pcl::PointXYZ>& cloud, pcl_ext::search::KdTree3f& tree)
{
  std::vector<float> xyz;
  std::vector<pcl::index_t> ids;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    xyz.insert (xyz.end(), {cloud[i].x, cloud[i].y, cloud[i].z});
    ids.push_back (static_cast<pcl::index_t> (i));
  }
  tree.build (std::move (xyz), std::move (ids));
}
} // namespace

TEST (SaliencyFeatures, NamesScalesAndGroundEstimates)
{
  pcl_ext::SaliencyFeatureOptions options;
  const std::vector<std::string> single = {"clutterness",
                                           "surfaceness",
                                           "curveness",
                                           "normal_angle",
                                           "tangent_angle",
                                           "height",
                                           "log_radius"};
  EXPECT_EQ (pcl_ext::saliencyFeatureNames (options), single);
  options.colour = options.intensity = true;
  options.scales = {0.25f, 2.f};
  const auto names = pcl_ext::saliencyFeatureNames (options);
  ASSERT_EQ (names.size(), 7u + 4u + 2u * 11u + 1u);
  EXPECT_EQ (names[7], "red");
  EXPECT_EQ (names[9], "blue");
  EXPECT_EQ (names[10], "intensity");
  EXPECT_EQ (names[11], "clutterness@0.25");
  EXPECT_EQ (names[21], "bottom_below@0.25");
  EXPECT_EQ (names[22], "clutterness@2");
  EXPECT_EQ (names[32], "bottom_below@2");
  EXPECT_EQ (names.back(), "dimension@2");

  EXPECT_EQ (pcl_ext::defaultFeatureScales(), (std::vector<float>{0.5f, 1.f, 2.f}));
  EXPECT_EQ (pcl_ext::featureScaleSuffix (0.5f), "@0.5");
  EXPECT_EQ (pcl_ext::featureScaleSuffix (1.f), "@1");
  EXPECT_TRUE (pcl_ext::validFeatureScales ({}));
  EXPECT_TRUE (pcl_ext::validFeatureScales ({0.5f, 1.f, 2.f}));
  EXPECT_FALSE (pcl_ext::validFeatureScales ({1.f, 0.5f}));
  EXPECT_FALSE (pcl_ext::validFeatureScales ({0.5f, 0.5f}));
  EXPECT_FALSE (pcl_ext::validFeatureScales ({0.f}));
  EXPECT_FALSE (pcl_ext::validFeatureScales ({std::numeric_limits<float>::infinity()}));
  EXPECT_FALSE (
      pcl_ext::validFeatureScales ({std::numeric_limits<float>::quiet_NaN()}));

  for (const auto estimate :
       {pcl_ext::GroundEstimate::LowestInBlock, pcl_ext::GroundEstimate::Opening}) {
    pcl_ext::GroundEstimate parsed = estimate == pcl_ext::GroundEstimate::Opening
                                         ? pcl_ext::GroundEstimate::LowestInBlock
                                         : pcl_ext::GroundEstimate::Opening;
    ASSERT_TRUE (
        pcl_ext::parseGroundEstimate (pcl_ext::groundEstimateName (estimate), parsed));
    EXPECT_EQ (parsed, estimate);
  }
  EXPECT_STREQ (pcl_ext::groundEstimateName (pcl_ext::GroundEstimate::LowestInBlock),
                "lowest_in_block");
}

TEST (SaliencyFeatures, FeaturesOfAFlatGroundPatch)
{
  // A horizontal 1 m square at z = 0 on a 5 cm grid, one colour and intensity
  // everywhere.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      cloud.push_back (pcl::PointXYZ (0.05f * i, 0.05f * j, 0.f));
  const std::vector<Eigen::Vector3f> colours (cloud.size(),
                                              Eigen::Vector3f (0.5f, 0.3f, 0.2f));
  const std::vector<float> intensity (cloud.size(), 0.7f);
  pcl_ext::search::KdTree3f tree;
  buildTree (cloud, tree);
  pcl_ext::LocalGround ground;
  ground.build (cloud, Eigen::Vector3f::UnitZ(), 1.f, 3);
  pcl_ext::SaliencyFeatureOptions options;
  options.colour = options.intensity = true;
  const pcl::index_t centre = 10 * 21 + 10; // (0.5, 0.5, 0)
  Eigen::MatrixXf f;
  ASSERT_TRUE (pcl_ext::computeSaliencyFeatures (
      cloud, tree, colours, intensity, ground, {centre}, {0.3f}, options, f, 1));
  ASSERT_EQ (f.rows(), 1);
  ASSERT_EQ (f.cols(), 11);
  // No spread across the plane: l1 is 0, clamped to 1e-12 before the log.
  EXPECT_NEAR (f (0, 0), std::log (1e-12), 1e-3);
  EXPECT_NEAR (f (0, 3), 0.f, 1e-4f);     // normal along the up axis
  EXPECT_NEAR (f (0, 4), M_PI / 2, 1e-4); // directions horizontal
  EXPECT_NEAR (f (0, 5), 0.f, 1e-6f);     // on the ground
  EXPECT_NEAR (f (0, 6), std::log (0.3f), 1e-6f);
  EXPECT_NEAR (f (0, 7), 0.5f, 1e-6f);
  EXPECT_NEAR (f (0, 8), 0.3f, 1e-6f);
  EXPECT_NEAR (f (0, 9), 0.2f, 1e-6f);
  EXPECT_NEAR (f (0, 10), 0.7f, 1e-6f);

  // Refused, with empty output: radii not matching the centres, colour or intensity
  // asked for without one per point, bad scales, an empty tree.
  EXPECT_FALSE (pcl_ext::computeSaliencyFeatures (
      cloud, tree, colours, intensity, ground, {centre}, {}, options, f));
  EXPECT_EQ (f.size(), 0);
  EXPECT_FALSE (pcl_ext::computeSaliencyFeatures (
      cloud, tree, {}, intensity, ground, {centre}, {0.3f}, options, f));
  EXPECT_FALSE (pcl_ext::computeSaliencyFeatures (
      cloud, tree, colours, {}, ground, {centre}, {0.3f}, options, f));
  options.scales = {1.f, 0.5f};
  EXPECT_FALSE (pcl_ext::computeSaliencyFeatures (
      cloud, tree, colours, intensity, ground, {centre}, {0.3f}, options, f));
  options.scales.clear();
  pcl_ext::search::KdTree3f empty;
  EXPECT_FALSE (pcl_ext::computeSaliencyFeatures (
      cloud, empty, colours, intensity, ground, {centre}, {0.3f}, options, f));
  EXPECT_EQ (f.size(), 0);
}

// The local ground on a sloping street (10 % grade along x, 20 m x 20 m at 0.1 m
// spacing) with a pole (0.2 m across, 6 m tall) standing on it: the block minimum puts
// the ground under the lower edge of its block, so ground points sit up to (reach + 1)
// cells of slope above it; the opening follows the slope, and both see the pole's foot
// as ground and its top 6 m above it. Points within reach cells of the cloud's edge are
// left out: there the block is cut short.
TEST (SaliencyFeatures, LocalGroundOnASlope)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const float grade = 0.1f;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
      cloud.push_back (pcl::PointXYZ (0.1f * i, 0.1f * j, grade * 0.1f * i));
  const float px = 10.05f, py = 10.05f, base = grade * px;
  for (int k = 0; k <= 60; ++k)
    for (int a = 0; a < 8; ++a)
      cloud.push_back (pcl::PointXYZ (px + 0.1f * std::cos (a * M_PI / 4),
                                      py + 0.1f * std::sin (a * M_PI / 4),
                                      base + 0.1f * k));
  for (const auto estimate :
       {pcl_ext::GroundEstimate::LowestInBlock, pcl_ext::GroundEstimate::Opening}) {
    pcl_ext::LocalGround ground;
    ground.build (cloud, Eigen::Vector3f::UnitZ(), 1.f, 3, estimate);
    double worst = 0.0, sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < 200 * 200; ++i)
      if (cloud[i].x >= 3.f && cloud[i].x < 17.f && cloud[i].y >= 3.f &&
          cloud[i].y < 17.f) {
        const double h = ground.heightAbove (cloud[i].getVector3fMap());
        worst = std::max (worst, std::abs (h));
        sum += h;
        ++n;
      }
    const double mean = sum / static_cast<double> (n);
    const float top = ground.heightAbove (Eigen::Vector3f (px, py, base + 6.f));
    SCOPED_TRACE (pcl_ext::groundEstimateName (estimate));
    if (estimate == pcl_ext::GroundEstimate::Opening) {
      // Exact on a plane up to the 1 m cell: a cell's lowest point is its lower edge.
      EXPECT_LT (worst, grade * 1.f + 1e-3);
      EXPECT_NEAR (mean, grade * 0.5, 0.01);
      EXPECT_NEAR (top, 6.f, grade * 1.f + 0.01f);
    }
    else {
      // reach to (reach + 1) cells of slope above the ground under it: 0.35 m on
      // average.
      EXPECT_NEAR (mean, grade * 3.5, 0.01);
      EXPECT_LT (worst, grade * 4.f + 1e-3);
      EXPECT_GT (top, 6.f);
      EXPECT_LT (top, 6.f + grade * 4.f + 0.01f);
    }
  }
  pcl_ext::GroundEstimate parsed;
  EXPECT_TRUE (pcl_ext::parseGroundEstimate ("opening", parsed));
  EXPECT_EQ (parsed, pcl_ext::GroundEstimate::Opening);
  EXPECT_FALSE (pcl_ext::parseGroundEstimate ("lowest", parsed));
}

// One point 1e6 m away from a 20 m x 20 m street (a distant outlier): a grid over the
// bounding box would need 1e12 cells. The ground under every street point is the same
// with and without it; the cells stored are those within reach of a street cell (twice
// the reach with the opening), and the outlier adds those within reach of its own.
TEST (SaliencyFeatures, LocalGroundFarOutlier)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
      cloud.push_back (pcl::PointXYZ (0.1f * i, 0.1f * j, 0.05f * std::sin (0.3f * i)));
  for (int k = 0; k <= 60; ++k)
    cloud.push_back (pcl::PointXYZ (10.05f, 10.05f, 0.1f * k));
  pcl::PointCloud<pcl::PointXYZ> with_outlier = cloud;
  with_outlier.push_back (pcl::PointXYZ (1e6f, 1e6f, -30.f));
  const int reach = 3;
  for (const auto estimate :
       {pcl_ext::GroundEstimate::LowestInBlock, pcl_ext::GroundEstimate::Opening}) {
    SCOPED_TRACE (pcl_ext::groundEstimateName (estimate));
    pcl_ext::LocalGround clean, dirty;
    clean.build (cloud, Eigen::Vector3f::UnitZ(), 1.f, reach, estimate);
    dirty.build (with_outlier, Eigen::Vector3f::UnitZ(), 1.f, reach, estimate);
    // The street spans 20 m: 20 or 21 cells of 1 m along each axis of the plane,
    // depending on where the cell edges fall; the cells within reach of them (twice
    // the reach with the opening) are stored.
    const std::size_t spread =
        estimate == pcl_ext::GroundEstimate::Opening ? 2 * reach : reach;
    EXPECT_GE (clean.getCellCount(), (20 + 2 * spread) * (20 + 2 * spread));
    EXPECT_LE (clean.getCellCount(), (21 + 2 * spread) * (21 + 2 * spread));
    EXPECT_EQ (dirty.getCellCount(),
               clean.getCellCount() + (2 * spread + 1) * (2 * spread + 1));
    for (const auto& p : cloud)
      ASSERT_EQ (dirty.heightAbove (p.getVector3fMap()),
                 clean.heightAbove (p.getVector3fMap()));
    // The outlier is its own ground; the pole's top is 6 m above the street.
    EXPECT_EQ (dirty.heightAbove (Eigen::Vector3f (1e6f, 1e6f, -30.f)), 0.f);
    EXPECT_GT (dirty.heightAbove (Eigen::Vector3f (10.05f, 10.05f, 6.f)), 5.9f);
  }
}
