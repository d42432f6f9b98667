/*
 * pcl_ext: planes for registration.
 */
#include <pcl_ext/registration/planes.h>

#include <cmath>

namespace pcl_ext
{
RegistrationPlane
transformPlane (const RegistrationPlane& plane, const Eigen::Matrix4d& transformation)
{
  const Eigen::Matrix3d block = transformation.topLeftCorner<3, 3> ();
  const double scale = std::cbrt (block.determinant ());
  const Eigen::Matrix3d rotation = block / scale;
  const Eigen::Vector3d t = transformation.topRightCorner<3, 1> ();
  RegistrationPlane out = plane;
  out.normal = (rotation * plane.normal).normalized ();
  out.d = scale * plane.d + out.normal.dot (t);
  out.centroid = block * plane.centroid + t;
  if (!plane.extent.isEmpty ())
  {
    out.extent.setEmpty ();
    for (int c = 0; c < 8; ++c)
      out.extent.extend (block * plane.extent.corner (static_cast<Eigen::AlignedBox3d::CornerType> (c)) + t);
  }
  return out;
}
}  // namespace pcl_ext
