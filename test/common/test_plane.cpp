/*
 * Tests of pcl_ext::Plane: n . x + d = 0, the convention of pcl::ModelCoefficients.
 */
#include <pcl_ext/common/plane.h>

#include <gtest/gtest.h>

#include <cmath>

using pcl_ext::Plane;

TEST (Plane, ADefaultPlaneIsInvalid)
{
  const Plane plane;
  EXPECT_FALSE (plane.isValid());
  EXPECT_TRUE (std::isnan (plane.signedDistance (Eigen::Vector3d::Zero())));
  EXPECT_EQ (plane.size, 0u);
  EXPECT_TRUE (plane.extent.isEmpty());
}

TEST (Plane, CoefficientsAndSignedDistanceFollowPcl)
{
  Plane plane;
  plane.normal = Eigen::Vector3d (0.6, 0.0, 0.8);
  plane.d = 2.0;
  ASSERT_TRUE (plane.isValid());
  const Eigen::Vector4d pi = plane.coefficients();
  EXPECT_EQ (pi, Eigen::Vector4d (0.6, 0.0, 0.8, 2.0));
  for (const Eigen::Vector3d x : {Eigen::Vector3d (0, 0, 0),
                                  Eigen::Vector3d (1, 2, 3),
                                  Eigen::Vector3d (-4, 5, 0.5)})
    EXPECT_NEAR (plane.signedDistance (x), pi.dot (x.homogeneous()), 1e-12);
  // Points on the plane: n . x + d = 0, at -d along the normal; its side is positive.
  EXPECT_NEAR (plane.signedDistance (-plane.d * plane.normal), 0.0, 1e-12);
  EXPECT_NEAR (plane.signedDistance ((-plane.d + 1.5) * plane.normal), 1.5, 1e-12);
  EXPECT_NEAR (plane.signedDistance ((-plane.d - 0.5) * plane.normal), -0.5, 1e-12);
}

TEST (Plane, ThroughPointNormalisesAndProjects)
{
  // The plane z = 0.5 x + 2 (through (0, 7, 2)), far from the origin in y.
  const Eigen::Vector3d point (0.0, 6.0e6, 2.0);
  const Plane plane = Plane::throughPoint (Eigen::Vector3d (-1.0, 0.0, 2.0), point);
  ASSERT_TRUE (plane.isValid());
  EXPECT_NEAR (plane.normal.norm(), 1.0, 1e-15);
  EXPECT_EQ (plane.centroid, point);
  EXPECT_NEAR (plane.signedDistance (point), 0.0, 1e-9);
  EXPECT_NEAR (plane.signedDistance (Eigen::Vector3d (4.0, 1.0, 4.0)), 0.0, 1e-9);
  const Eigen::Vector3d x (3.0, -2.0, 10.0);
  const Eigen::Vector3d foot = plane.project (x);
  EXPECT_NEAR (plane.signedDistance (foot), 0.0, 1e-9);
  // The foot lies along the normal from x, at x's signed distance.
  EXPECT_TRUE ((x - foot).isApprox (plane.signedDistance (x) * plane.normal, 1e-12));
  // A zero normal gives no plane.
  EXPECT_FALSE (Plane::throughPoint (Eigen::Vector3d::Zero(), point).isValid());
}
