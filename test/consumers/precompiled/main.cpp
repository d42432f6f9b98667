// A downstream project using pcl_ext's precompiled classes for a stock PCL point type.
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/search/nanoflann_kdtree.h>

#include <cmath>
#include <iostream>

int
main ()
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j)
      cloud->push_back (pcl::PointXYZ (0.1f * i, 0.1f * j, 2.0f));
  pcl_ext::Neighbourhoods<pcl::PointXYZ> nb;
  nb.setInputCloud (cloud);
  nb.setKSearch (9);
  if (!nb.compute() || nb.size() != cloud->size())
    return 1;
  Eigen::Matrix3d cov;
  Eigen::Vector3d centroid;
  const auto row = nb[cloud->size() / 2];
  pcl_ext::computeLocalCovariance (*cloud, row.begin(), row.end(), cov, centroid);
  pcl_ext::EigenDecomposition eig;
  if (!pcl_ext::computeEigenDecomposition (cov, eig) ||
      std::abs (eig.normal().z()) < 0.999)
    return 2;
  std::cout << "precompiled consumer: " << nb.size()
            << " neighbourhoods, normal z = " << eig.normal().z() << "\n";
  return 0;
}
