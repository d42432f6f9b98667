/*
 * Analytic plane sets for the registration tests: the H-shaped building of the building
 * scene, seen from a scanner in a known pose.
 */
#pragma once

#include <pcl_ext/registration/map_planes.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace pcl_ext {
namespace test {
/** The default plan of the simulated building: 40 x 30 m with two 16 x 10 m courtyards.
 */
inline io::Ring2d
hShape ()
{
  return {{0, 0},
          {12, 0},
          {12, 10},
          {28, 10},
          {28, 0},
          {40, 0},
          {40, 30},
          {28, 30},
          {28, 20},
          {12, 20},
          {12, 30},
          {0, 30}};
}

/** The same plan with the northern courtyard 2 m shallower: no symmetry left that a
 * rotation can realise, so the right match is unique. */
inline io::Ring2d
asymmetricH ()
{
  return {{0, 0},
          {12, 0},
          {12, 10},
          {28, 10},
          {28, 0},
          {40, 0},
          {40, 30},
          {28, 30},
          {28, 22},
          {12, 22},
          {12, 30},
          {0, 30}};
}

/** A random scan pose: yaw any angle, tilt up to \a tilt_deg, translation up to \a
 * shift. */
inline Eigen::Matrix4d
randomPose (std::mt19937& rng, double tilt_deg = 3.0, double shift = 100.0)
{
  std::uniform_real_distribution<double> unit (-1.0, 1.0);
  const double pi = 3.14159265358979323846;
  const Eigen::Vector3d axis =
      Eigen::Vector3d (unit (rng), unit (rng), 0.0).normalized();
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd (pi * unit (rng), Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd (tilt_deg * pi / 180.0 * std::abs (unit (rng)), axis))
          .toRotationMatrix();
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() = r;
  t.topRightCorner<3, 1>() =
      shift * Eigen::Vector3d (unit (rng), unit (rng), 0.1 * unit (rng));
  return t;
}

/** Scan planes: the distinct map planes (coplanar walls merged, as a plane extractor
 * merges them) moved into the scan frame by the inverse of \a scan_to_map, with normal
 * noise of \a angle_sigma (rad) and offset noise \a distance_sigma (m), minus the first
 * \a missing walls, plus \a superfluous random vertical planes. Supports follow the
 * wall areas. */
inline std::vector<Plane>
scanPlanes (const std::vector<MapPlane>& map,
            const Eigen::Matrix4d& scan_to_map,
            std::mt19937& rng,
            double angle_sigma,
            double distance_sigma,
            int missing = 0,
            int superfluous = 0)
{
  std::normal_distribution<double> gauss (0.0, 1.0);
  std::uniform_real_distribution<double> unit (-1.0, 1.0);
  const Eigen::Matrix4d map_to_scan = scan_to_map.inverse();
  std::vector<Plane> distinct;
  std::vector<double> single_length; // wall length, 0 for merged walls and the floor
  for (const auto& plane : map) {
    bool seen = false;
    for (std::size_t i = 0; i < distinct.size(); ++i)
      if (distinct[i].normal.dot (plane.normal) > 0.9999 &&
          std::abs (distinct[i].d - plane.d) < 1e-6) {
        distinct[i].size += static_cast<std::size_t> (plane.length() * 100);
        distinct[i].extent.extend (plane.extent);
        single_length[i] = 0.0;
        seen = true;
      }
    if (!seen) {
      Plane p = plane;
      p.size =
          plane.isFloor() ? 20000 : static_cast<std::size_t> (plane.length() * 100);
      distinct.push_back (p);
      single_length.push_back (plane.length());
    }
  }
  // The longest walls go missing, as in the building scene (hidden by vegetation).
  std::vector<double> sorted = single_length;
  std::sort (sorted.rbegin(), sorted.rend());
  const double cut =
      missing > 0 ? sorted[std::min<std::size_t> (missing, sorted.size()) - 1] : 1e300;
  std::vector<Plane> scan;
  int dropped = 0;
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const Plane& plane = distinct[i];
    if (dropped < missing && single_length[i] > 0.0 && single_length[i] >= cut) {
      ++dropped;
      continue;
    }
    Plane p = transformPlane (plane, map_to_scan);
    const Eigen::Vector3d tilt (gauss (rng), gauss (rng), gauss (rng));
    p.normal =
        (p.normal + angle_sigma * (tilt - tilt.dot (p.normal) * p.normal)).normalized();
    p.d = -(p.normal.dot (p.centroid) + distance_sigma * gauss (rng));
    scan.push_back (p);
  }
  for (int i = 0; i < superfluous; ++i) {
    Plane p;
    const double angle = 3.14159265358979323846 * unit (rng);
    p.normal = Eigen::Vector3d (std::cos (angle), std::sin (angle), 0.0);
    p.centroid = Eigen::Vector3d (60.0 * unit (rng), 60.0 * unit (rng), 3.0);
    p.d = -p.normal.dot (p.centroid);
    p.size = static_cast<std::size_t> (800 + 800 * std::abs (unit (rng)));
    const Eigen::Vector3d along (-p.normal.y(), p.normal.x(), 0.0);
    p.extent.extend (p.centroid - 4.0 * along - Eigen::Vector3d (0, 0, 3));
    p.extent.extend (p.centroid + 4.0 * along + Eigen::Vector3d (0, 0, 3));
    p = transformPlane (p, map_to_scan);
    scan.push_back (p);
  }
  return scan;
}

inline std::vector<Plane>
slice (const std::vector<MapPlane>& planes)
{
  return std::vector<Plane> (planes.begin(), planes.end());
}
} // namespace test
} // namespace pcl_ext
