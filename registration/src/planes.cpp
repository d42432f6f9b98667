/*
 * pcl_ext: planes for registration.
 */
#include <pcl_ext/registration/planes.h>

#include <cmath>

namespace pcl_ext {
PlaneTransformer::PlaneTransformer (const Eigen::Matrix4d& transformation)
: block_ (transformation.topLeftCorner<3, 3>())
{
  scale_ = std::cbrt (block_.determinant());
  rotation_ = block_ / scale_;
  t_ = transformation.topRightCorner<3, 1>();
}

Eigen::AlignedBox3d
PlaneTransformer::extent (const Plane& plane) const
{
  Eigen::AlignedBox3d out;
  if (!plane.extent.isEmpty())
    for (int c = 0; c < 8; ++c)
      out.extend (point (
          plane.extent.corner (static_cast<Eigen::AlignedBox3d::CornerType> (c))));
  return out;
}

Plane
PlaneTransformer::operator() (const Plane& plane) const
{
  Plane out = plane;
  out.normal = normal (plane);
  out.d = scale_ * plane.d - out.normal.dot (t_);
  out.centroid = point (plane.centroid);
  if (!plane.extent.isEmpty())
    out.extent = extent (plane);
  return out;
}

Plane
transformPlane (const Plane& plane, const Eigen::Matrix4d& transformation)
{
  return PlaneTransformer (transformation) (plane);
}
} // namespace pcl_ext
