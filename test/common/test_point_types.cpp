/*
 * Tests of pcl_ext's point types and classes: the class labels, the registered fields
 * of CovarianceFeatures and CurvatureVariance, and their use through PCL (copy, PCD
 * files).
 */
#include <pcl_ext/point_types.h>

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

namespace {
template <typename PointT>
std::vector<std::string>
fieldNames ()
{
  std::vector<std::string> names;
  for (const auto& f : pcl::getFields<PointT>())
    names.push_back (f.name);
  return names;
}

pcl_ext::CovarianceFeatures
features (float base)
{
  pcl_ext::CovarianceFeatures f;
  f.normal_x = base;
  f.normal_y = base + 1;
  f.normal_z = base + 2;
  f.lambda0 = base + 3;
  f.lambda1 = base + 4;
  f.lambda2 = base + 5;
  f.surface_variance = base + 6;
  f.linearity = base + 7;
  f.planarity = base + 8;
  f.scattering = base + 9;
  f.omnivariance = base + 10;
  f.anisotropy = base + 11;
  f.eigenentropy = base + 12;
  f.verticality = base + 13;
  return f;
}
} // namespace

TEST (PointTypes, ClassLabelsAndNames)
{
  EXPECT_EQ (static_cast<std::uint32_t> (pcl_ext::PointClass::Unknown), 0u);
  EXPECT_EQ (static_cast<std::uint32_t> (pcl_ext::PointClass::Surface), 1u);
  EXPECT_EQ (static_cast<std::uint32_t> (pcl_ext::PointClass::Edge), 2u);
  EXPECT_EQ (static_cast<std::uint32_t> (pcl_ext::PointClass::Boundary), 3u);
  EXPECT_EQ (pcl_ext::kNumPointClasses, 4u);
  EXPECT_STREQ (pcl_ext::pointClassName (pcl_ext::PointClass::Unknown), "unknown");
  EXPECT_STREQ (pcl_ext::pointClassName (pcl_ext::PointClass::Surface), "surface");
  EXPECT_STREQ (pcl_ext::pointClassName (pcl_ext::PointClass::Edge), "edge");
  EXPECT_STREQ (pcl_ext::pointClassName (pcl_ext::PointClass::Boundary), "boundary");
  EXPECT_STREQ (pcl_ext::pointClassName (static_cast<pcl_ext::PointClass> (9)),
                "unknown");
}

TEST (PointTypes, RegisteredFields)
{
  const std::vector<std::string> covariance = {"normal_x",
                                               "normal_y",
                                               "normal_z",
                                               "lambda0",
                                               "lambda1",
                                               "lambda2",
                                               "surface_variance",
                                               "linearity",
                                               "planarity",
                                               "scattering",
                                               "omnivariance",
                                               "anisotropy",
                                               "eigenentropy",
                                               "verticality"};
  EXPECT_EQ (fieldNames<pcl_ext::CovarianceFeatures>(), covariance);
  // The normal is laid out as in pcl::Normal (four floats, the fourth padding), the
  // features follow; the type is 16-byte aligned for Eigen.
  EXPECT_EQ (offsetof (pcl_ext::CovarianceFeatures, normal_x), 0u);
  EXPECT_EQ (offsetof (pcl_ext::CovarianceFeatures, normal_z), 8u);
  EXPECT_EQ (offsetof (pcl_ext::CovarianceFeatures, lambda0), 16u);
  EXPECT_EQ (alignof (pcl_ext::CovarianceFeatures), 16u);
  EXPECT_EQ (sizeof (pcl_ext::CovarianceFeatures) % 16, 0u);
  for (const auto& f : pcl::getFields<pcl_ext::CovarianceFeatures>()) {
    EXPECT_EQ (f.datatype, pcl::PCLPointField::FLOAT32) << f.name;
    EXPECT_EQ (f.count, 1u) << f.name;
  }
  EXPECT_EQ (fieldNames<pcl_ext::CurvatureVariance>(),
             std::vector<std::string>{"curvature_variance"});
  EXPECT_EQ (pcl_ext::CurvatureVariance().curvature_variance, 0.f);
}

TEST (PointTypes, CopyToNormalsAndPcdRoundTrip)
{
  pcl::PointCloud<pcl_ext::CovarianceFeatures> cloud;
  for (int i = 0; i < 3; ++i)
    cloud.push_back (features (100.f * i));
  // Field by field into pcl::Normal: the normal comes across.
  pcl::PointCloud<pcl::Normal> normals;
  pcl::copyPointCloud (cloud, normals);
  ASSERT_EQ (normals.size(), 3u);
  EXPECT_EQ (normals[2].normal_x, 200.f);
  EXPECT_EQ (normals[2].normal_y, 201.f);
  EXPECT_EQ (normals[2].normal_z, 202.f);

  const std::string path = testing::TempDir() + "/covariance_features_" +
                           std::to_string (::getpid()) + ".pcd";
  ASSERT_EQ (pcl::io::savePCDFileBinary (path, cloud), 0);
  pcl::PointCloud<pcl_ext::CovarianceFeatures> back;
  ASSERT_EQ (pcl::io::loadPCDFile (path, back), 0);
  ASSERT_EQ (back.size(), 3u);
  EXPECT_EQ (back[1].normal_x, 100.f);
  EXPECT_EQ (back[1].lambda2, 105.f);
  EXPECT_EQ (back[1].verticality, 113.f);
  EXPECT_EQ (back[2].eigenentropy, 212.f);
  std::remove (path.c_str());

  pcl::PointCloud<pcl_ext::CurvatureVariance> variance;
  variance.resize (2);
  variance[1].curvature_variance = 0.25f;
  ASSERT_EQ (pcl::io::savePCDFileASCII (path, variance), 0);
  pcl::PointCloud<pcl_ext::CurvatureVariance> variance_back;
  ASSERT_EQ (pcl::io::loadPCDFile (path, variance_back), 0);
  ASSERT_EQ (variance_back.size(), 2u);
  EXPECT_EQ (variance_back[0].curvature_variance, 0.f);
  EXPECT_EQ (variance_back[1].curvature_variance, 0.25f);
  std::remove (path.c_str());
}
