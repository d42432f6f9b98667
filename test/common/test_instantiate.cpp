/*
 * instantiate.h: PCL_EXT_INSTANTIATE expands its per-type macro once for each type of a
 * Boost.Preprocessor sequence, as PCL_INSTANTIATE does, and the default list holds the
 * XYZ point types the libraries are precompiled for.
 */
#include <pcl_ext/common/instantiate.h>

#include <pcl/point_types.h>
#include <pcl/type_traits.h>

#include <gtest/gtest.h>

#include <string>
#include <typeinfo>
#include <vector>

namespace {
// Each expansion adds one term: the count of types, whether all have x, y and z.
#define PCL_EXT_INSTANTIATE_Count(T) +1
#define PCL_EXT_INSTANTIATE_HasXyz(T) &&pcl::traits::has_xyz_v<T>

constexpr int kDefaultTypes = 0 PCL_EXT_INSTANTIATE (Count, PCL_EXT_XYZ_POINT_TYPES);
constexpr bool kAllHaveXyz = true PCL_EXT_INSTANTIATE (HasXyz, PCL_EXT_XYZ_POINT_TYPES);

// An explicit instantiation per type, as the src/ files write them.
template <typename PointT>
std::string
typeName ()
{
  return typeid (PointT).name();
}
#define PCL_EXT_INSTANTIATE_typeName(T) template std::string typeName<T>();
PCL_EXT_INSTANTIATE (typeName, (pcl::PointXYZ) (pcl::PointNormal))

TEST (Instantiate, ExpandsOncePerTypeOfTheSequence)
{
  EXPECT_EQ (0 PCL_EXT_INSTANTIATE (Count, (pcl::PointXYZ)), 1);
  EXPECT_EQ (0 PCL_EXT_INSTANTIATE (
                 Count, (pcl::PointXYZ) (pcl::PointXYZI) (pcl::PointNormal)),
             3);
  EXPECT_EQ (typeName<pcl::PointXYZ>(), typeid (pcl::PointXYZ).name());
  EXPECT_EQ (typeName<pcl::PointNormal>(), typeid (pcl::PointNormal).name());
}

TEST (Instantiate, DefaultListIsTheNineXyzTypes)
{
  EXPECT_EQ (kDefaultTypes, 9);
  EXPECT_TRUE (kAllHaveXyz);
}
} // namespace
