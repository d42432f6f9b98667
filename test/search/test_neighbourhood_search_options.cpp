/*
 * NeighbourhoodSearchOptions: k or a radius (each clears the other), the maximum radius
 * for k and the search method, and the default k of the two classes built on it.
 */
#include <pcl_ext/search/nanoflann_kdtree.h>
#include <pcl_ext/search/neighbourhood_options.h>
#include <pcl_ext/search/neighbourhood_search_options.h>
#include <pcl_ext/search/neighbourhoods.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

namespace {
using Point = pcl::PointXYZ;

/** The options with a default k, as a deriving class sets it. */
class Options : public pcl_ext::NeighbourhoodSearchOptions<Point> {
public:
  explicit Options (int k = 0) : NeighbourhoodSearchOptions<Point> (k) {}
};

TEST (NeighbourhoodSearchOptions, DefaultsAreTheDerivingClasss)
{
  const Options unset;
  EXPECT_EQ (unset.getKSearch(), 0);
  EXPECT_EQ (unset.getRadiusSearch(), 0.0);
  EXPECT_EQ (unset.getMaxRadius(), 0.0);
  EXPECT_FALSE (unset.getSearchMethod());
  EXPECT_EQ (Options (50).getKSearch(), 50);
  EXPECT_EQ (pcl_ext::Neighbourhoods<Point>().getKSearch(), 0);
}

TEST (NeighbourhoodSearchOptions, KAndRadiusClearEachOther)
{
  Options options (50);
  options.setRadiusSearch (0.25);
  EXPECT_EQ (options.getRadiusSearch(), 0.25);
  EXPECT_EQ (options.getKSearch(), 0);
  options.setKSearch (12);
  EXPECT_EQ (options.getKSearch(), 12);
  EXPECT_EQ (options.getRadiusSearch(), 0.0);
}

TEST (NeighbourhoodSearchOptions, MaxRadiusAndSearchMethodAreKept)
{
  Options options (20);
  options.setMaxRadius (0.5);
  const auto search = pcl::make_shared<pcl_ext::search::NanoflannKdTree<Point>>();
  options.setSearchMethod (search);
  EXPECT_EQ (options.getMaxRadius(), 0.5);
  EXPECT_EQ (options.getSearchMethod(), search);
  // Neither changes k nor the radius.
  EXPECT_EQ (options.getKSearch(), 20);
  EXPECT_EQ (options.getRadiusSearch(), 0.0);
}

TEST (NeighbourhoodSearchOptions, TheSearchAndItsUsersAreSetTheSameWay)
{
  pcl_ext::Neighbourhoods<Point> neighbourhoods;
  pcl_ext::NeighbourhoodSearchOptions<Point>& options = neighbourhoods;
  options.setKSearch (8);
  options.setMaxRadius (1.5);
  EXPECT_EQ (neighbourhoods.getKSearch(), 8);
  EXPECT_EQ (neighbourhoods.getMaxRadius(), 1.5);
  static_assert (std::is_base_of_v<pcl_ext::NeighbourhoodSearchOptions<Point>,
                                   pcl_ext::NeighbourhoodOptions<Point>>);
}
} // namespace
