/*
 * pcl_ext: the vertical direction of a scan from its planes.
 */
#include <pcl_ext/registration/scan_levelling.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pcl_ext {
namespace {
constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The planes \a u makes horizontal or vertical within the tolerance: their sizes
// summed, and the normal matrix whose largest eigenvector refines u.
double
support (const std::vector<Plane>& planes,
         const Eigen::Vector3d& u,
         double tolerance,
         Eigen::Matrix3d& a,
         int& horizontal)
{
  a.setZero();
  horizontal = 0;
  double total = 0.0;
  for (const auto& plane : planes) {
    if (!plane.normal.allFinite())
      continue;
    const double w = static_cast<double> (std::max<std::size_t> (plane.size, 1));
    const double c = std::abs (plane.normal.dot (u));
    if (c >= std::cos (tolerance)) {
      a += w * plane.normal * plane.normal.transpose();
      ++horizontal;
    }
    else if (c <= std::sin (tolerance))
      a += w * (Eigen::Matrix3d::Identity() - plane.normal * plane.normal.transpose());
    else
      continue;
    total += w;
  }
  return total;
}
} // namespace

bool
estimateUpDirection (const std::vector<Plane>& planes,
                     Eigen::Vector3d& up,
                     double max_tilt_deg,
                     double tolerance_deg)
{
  up = Eigen::Vector3d::UnitZ();
  const double tolerance = tolerance_deg * kDegree;
  double best = 0.0;
  Eigen::Vector3d chosen = Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d a;
  int horizontal = 0;
  // Hypotheses: the near-vertical normals, and z itself (a levelled scan whose
  // horizontal planes are all small).
  std::vector<Eigen::Vector3d> hypotheses{Eigen::Vector3d::UnitZ()};
  // Also the common perpendicular of every two walls of different directions (a scan
  // without a horizontal plane).
  const double cos_tilt = std::cos (max_tilt_deg * kDegree);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Eigen::Vector3d& a = planes[i].normal;
    if (!a.allFinite())
      continue;
    if (std::abs (a.z()) >= cos_tilt)
      hypotheses.push_back (a.z() < 0.0 ? -a : a);
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      const Eigen::Vector3d c = a.cross (planes[j].normal);
      if (c.allFinite() && c.norm() > 0.5 && std::abs (c.z()) >= cos_tilt * c.norm())
        hypotheses.push_back ((c.z() < 0.0 ? -c : c).normalized());
    }
  }
  for (const auto& u : hypotheses) {
    const double s = support (planes, u, tolerance, a, horizontal);
    if (s > best) {
      best = s;
      chosen = u;
    }
  }
  if (!(best > 0.0))
    return false;
  for (int pass = 0; pass < 2; ++pass) {
    support (planes, chosen, tolerance, a, horizontal);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (a);
    const Eigen::Vector3d values = solver.eigenvalues();
    // Without a horizontal plane, walls of one direction leave the up direction free
    // about their normal: the two largest eigenvalues are equal.
    if (horizontal == 0 && !(values (2) - values (1) > 1e-3 * values (2)))
      return false;
    Eigen::Vector3d u = solver.eigenvectors().col (2);
    if (u.z() < 0.0)
      u = -u;
    if (std::acos (std::min (1.0, u.z())) > max_tilt_deg * kDegree)
      return false;
    chosen = u;
  }
  up = chosen.normalized();
  return true;
}

bool
estimateFlatPatchNormal (const std::vector<Eigen::Vector3d>& points,
                         const Eigen::Vector3d& plane_normal,
                         Eigen::Vector3d& normal,
                         int cells_across)
{
  constexpr std::size_t kLeastCellPoints = 8;
  constexpr std::size_t kLeastCells = 8;
  constexpr double kRoughness = 3.0;
  constexpr double kUneven = 2.0;
  constexpr double kLeastLeanDeg = 0.1;
  normal = plane_normal;
  if (points.size() < kLeastCellPoints * kLeastCells || cells_across < 2 ||
      !(plane_normal.norm() > 0.0))
    return false;
  // The plane's frame: axes e1, e2 in the plane, heights along n.
  const Eigen::Vector3d n = plane_normal.normalized();
  const Eigen::Vector3d e1 = n.unitOrthogonal();
  const Eigen::Vector3d e2 = n.cross (e1);
  const double h0 = points.front().dot (n); // heights from here: small sums
  Eigen::AlignedBox2d box;
  for (const auto& p : points)
    box.extend (Eigen::Vector2d (p.dot (e1), p.dot (e2)));
  const double cell = box.sizes().maxCoeff() / cells_across;
  if (!(cell > 0.0) || !std::isfinite (cell))
    return false;
  const int columns = static_cast<int> (box.sizes().x() / cell) + 1;
  const int rows = static_cast<int> (box.sizes().y() / cell) + 1;
  // Per cell: the sums of a least-squares fit h = a u + b v + c about the cell's
  // centre. A regression of the height, not the covariance kernel's smallest
  // eigenvector: range noise at grazing angles lies mostly in the plane, and only the
  // height's error should enter the slope (docs/khoshelham_gorte.md).
  struct Sums {
    std::size_t count = 0;
    double u = 0, v = 0, h = 0, uu = 0, vv = 0, uv = 0, uh = 0, vh = 0, hh = 0;
  };
  std::vector<Sums> cells (static_cast<std::size_t> (columns) * rows);
  for (const auto& p : points) {
    const Eigen::Vector2d q =
        (Eigen::Vector2d (p.dot (e1), p.dot (e2)) - box.min()) / cell;
    const int cx = std::min (columns - 1, static_cast<int> (q.x()));
    const int cy = std::min (rows - 1, static_cast<int> (q.y()));
    Sums& c = cells[static_cast<std::size_t> (cy) * columns + cx];
    const double u = (q.x() - cx - 0.5) * cell, v = (q.y() - cy - 0.5) * cell;
    const double h = p.dot (n) - h0;
    ++c.count;
    c.u += u;
    c.v += v;
    c.h += h;
    c.uu += u * u;
    c.vv += v * v;
    c.uv += u * v;
    c.uh += u * h;
    c.vh += v * h;
    c.hh += h * h;
  }
  // The plane's own RMS about its mean height along n.
  double sum_h = 0.0, sum_hh = 0.0;
  for (const auto& c : cells) {
    sum_h += c.h;
    sum_hh += c.hh;
  }
  const double count = static_cast<double> (points.size());
  const double plane_rms =
      std::sqrt (std::max (0.0, sum_hh / count - (sum_h / count) * (sum_h / count)));
  std::vector<Eigen::Vector2d> slopes;
  std::vector<double> roughness;
  for (const auto& c : cells) {
    if (c.count < kLeastCellPoints)
      continue;
    const double k = static_cast<double> (c.count);
    const double mu = c.u / k, mv = c.v / k, mh = c.h / k;
    Eigen::Matrix2d a;
    a << c.uu / k - mu * mu, c.uv / k - mu * mv, c.uv / k - mu * mv, c.vv / k - mv * mv;
    const Eigen::Vector2d b (c.uh / k - mu * mh, c.vh / k - mv * mh);
    // A cell whose points lie along a line gives no slope across it.
    if (!(a.determinant() > 1e-6 * a.trace() * a.trace()))
      continue;
    const Eigen::Vector2d slope = a.ldlt().solve (b);
    const double residual =
        c.hh / k - mh * mh - 2.0 * slope.dot (b) + slope.dot (a * slope);
    if (!slope.allFinite() || !std::isfinite (residual))
      continue;
    slopes.push_back (slope);
    roughness.push_back (std::sqrt (std::max (0.0, residual)));
  }
  if (slopes.size() < kLeastCells)
    return false;
  std::vector<double> ordered = roughness;
  std::nth_element (
      ordered.begin(), ordered.begin() + ordered.size() / 2, ordered.end());
  const double median = ordered[ordered.size() / 2];
  // An even plane (its RMS that of its patches): its fit is the better estimate.
  if (plane_rms <= kUneven * median)
    return false;
  const double limit = kRoughness * median;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t flat = 0;
  for (std::size_t i = 0; i < slopes.size(); ++i)
    if (roughness[i] <= limit) {
      sum += (n - slopes[i].x() * e1 - slopes[i].y() * e2).normalized();
      ++flat;
    }
  if (flat < kLeastCells || !(sum.norm() > 0.0))
    return false;
  normal = sum.normalized();
  // Patches that barely lean from the fit: their own error is of that order.
  if (std::acos (std::min (1.0, normal.dot (n))) < kLeastLeanDeg * kDegree) {
    normal = plane_normal;
    return false;
  }
  return true;
}

Eigen::Matrix4d
levellingTransform (const Eigen::Vector3d& up)
{
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() =
      Eigen::Quaterniond::FromTwoVectors (up.normalized(), Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  return t;
}

bool
refineAboutVertical (const std::vector<Plane>& scan,
                     const std::vector<Plane>& map,
                     const std::vector<PlanePair>& matches,
                     PlaneTransformationResult& estimate)
{
  if (!estimate.valid || std::abs (estimate.scale - 1.0) > 1e-9 || matches.empty())
    return false;
  for (const auto& pair : matches)
    if (pair.scan < 0 || pair.map < 0 || pair.scan >= int (scan.size()) ||
        pair.map >= int (map.size()))
      return false;
  const Eigen::Matrix3d r0 = estimate.transformation.topLeftCorner<3, 3>();
  const Eigen::Vector3d t0 = estimate.transformation.topRightCorner<3, 1>();
  // The rotation about z nearest (Frobenius) to r0.
  const double yaw = std::atan2 (r0 (1, 0) - r0 (0, 1), r0 (0, 0) + r0 (1, 1));
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd (yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // Least squares on n_m . t = -d_m - n_m . R c_s, with a small pull towards t0 that
  // only matters along directions the map normals leave free.
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const auto& pair : matches) {
    const Plane& s = scan[pair.scan];
    const Plane& m = map[pair.map];
    a += m.normal * m.normal.transpose();
    b += m.normal * (-m.d - m.normal.dot (r * s.centroid));
  }
  const double pull = 1e-6 * std::max (a.trace(), 1e-12);
  a += pull * Eigen::Matrix3d::Identity();
  b += pull * t0;
  const Eigen::Vector3d t = a.ldlt().solve (b);
  if (!t.allFinite())
    return false;
  estimate.transformation.setIdentity();
  estimate.transformation.topLeftCorner<3, 3>() = r;
  estimate.transformation.topRightCorner<3, 1>() = t;
  estimate.angle_residuals.clear();
  estimate.distance_residuals.clear();
  estimate.max_angle = estimate.max_distance = 0.0;
  double sum = 0.0;
  for (const auto& pair : matches) {
    const Plane& s = scan[pair.scan];
    const Plane& m = map[pair.map];
    const Eigen::Vector3d n = r * s.normal;
    const double sign = n.dot (m.normal) < 0.0 ? -1.0 : 1.0;
    const double angle = std::acos (std::min (1.0, std::abs (n.dot (m.normal))));
    const double distance = std::abs (m.normal.dot (r * s.centroid + t) + m.d);
    estimate.angle_residuals.push_back (angle);
    estimate.distance_residuals.push_back (distance);
    estimate.max_angle = std::max (estimate.max_angle, angle);
    estimate.max_distance = std::max (estimate.max_distance, distance);
    sum += (s.normal - sign * r.transpose() * m.normal).squaredNorm() +
           distance * distance;
  }
  estimate.residual_norm = std::sqrt (sum / double (matches.size()));
  return true;
}
} // namespace pcl_ext
