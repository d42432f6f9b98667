// A downstream project with its own point type: PCL_NO_PRECOMPILE makes pcl_ext's
// headers include their implementations, exactly as PCL's do.
#define PCL_NO_PRECOMPILE
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/search/nanoflann_kdtree.h>

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <iostream>

struct EIGEN_ALIGN16 ScanPoint {
  PCL_ADD_POINT4D;
  float reflectance;
  std::uint16_t ring;
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

POINT_CLOUD_REGISTER_POINT_STRUCT (
    ScanPoint,
    (float, x, x) (float, y, y) (float, z, z) (float,
                                               reflectance,
                                               reflectance) (std::uint16_t, ring, ring))

int
main ()
{
  pcl::PointCloud<ScanPoint>::Ptr cloud (new pcl::PointCloud<ScanPoint>);
  for (int i = 0; i < 200; ++i) {
    ScanPoint p;
    p.x = 0.01f * i;
    p.y = 0.0f;
    p.z = 0.0f;
    p.reflectance = 0.5f;
    p.ring = static_cast<std::uint16_t> (i % 16);
    cloud->push_back (p);
  }
  pcl_ext::search::NanoflannKdTree<ScanPoint>::Ptr tree (
      new pcl_ext::search::NanoflannKdTree<ScanPoint>);
  pcl_ext::Neighbourhoods<ScanPoint> nb;
  nb.setInputCloud (cloud);
  nb.setSearchMethod (tree);
  nb.setRadiusSearch (0.0105);
  if (!nb.compute())
    return 1;
  // Interior points of a line with spacing 0.01 have themselves and two neighbours.
  if (nb[100].size() != 3 || nb[0].size() != 2)
    return 2;
  std::cout << "custom point consumer: " << nb.size() << " neighbourhoods\n";
  return 0;
}
