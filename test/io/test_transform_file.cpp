/*
 * Transforms stored as text.
 */
#include <pcl_ext/io/transform_file.h>

#include "test_helpers.h"

TEST (TransformFile, ReadsFourByFourAndThreeByFour)
{
  Eigen::Matrix4d t;
  pcl_ext::io::loadTransform (fixture ("transform_translation.txt"), t);
  Eigen::Matrix4d expected = Eigen::Matrix4d::Identity();
  expected.topRightCorner<3, 1>() = Eigen::Vector3d (10, 20, 0.5);
  EXPECT_EQ (t, expected);

  pcl_ext::io::loadTransform (fixture ("transform_3x4.txt"), t);
  EXPECT_EQ (t (1, 0), 1.0);
  EXPECT_EQ (t (2, 3), 3.0);
  EXPECT_EQ (t.row (3), Eigen::RowVector4d (0, 0, 0, 1));

  const Eigen::Matrix4d before = t;
  std::string p = fixture ("transform_short.txt");
  expectReadError ([&] { pcl_ext::io::loadTransform (p, t); }, p, 0, "found 11");
  p = fixture ("transform_bad.txt");
  expectReadError (
      [&] { pcl_ext::io::loadTransform (p, t); }, p, 2, "'x' is not a finite number");
  p = fixture ("empty.txt");
  expectReadError ([&] { pcl_ext::io::loadTransform (p, t); }, p, 0, "empty file");
  p = fixture ("no_transform.txt");
  expectReadError ([&] { pcl_ext::io::loadTransform (p, t); }, p, 0, "no such file");
  EXPECT_EQ (t, before);
}
