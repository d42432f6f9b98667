/*
 * pcl_ext: cylinders found in a set of points without normals.
 */
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/cylinders.h>
#include <pcl_ext/search/kdtree_3f.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace cylinders {
namespace {
/** A patch of fewer points gives no hypothesis. */
constexpr std::size_t kMinPatchPoints = 10;
/** The surface test's band and the ranking's penalty band, in tolerances. */
constexpr double kShellTolerances = 3.0;

struct Hypothesis {
  double score;
  Eigen::Vector3d point, axis;
  double radius;
  double taper = 0.0;
};

/** Circle through three points of the plane; false when they are (nearly) collinear. */
bool
circleThrough (const Eigen::Vector2d& a,
               const Eigen::Vector2d& b,
               const Eigen::Vector2d& c,
               Eigen::Vector2d& centre,
               double& radius)
{
  const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) +
                          c.x() * (a.y() - b.y()));
  if (std::abs (d) < 1e-12)
    return false;
  const double a2 = a.squaredNorm(), b2 = b.squaredNorm(), c2 = c.squaredNorm();
  centre = Eigen::Vector2d (
      (a2 * (b.y() - c.y()) + b2 * (c.y() - a.y()) + c2 * (a.y() - b.y())) / d,
      (a2 * (c.x() - b.x()) + b2 * (a.x() - c.x()) + c2 * (b.x() - a.x())) / d);
  radius = (a - centre).norm();
  return std::isfinite (radius);
}

/** Signed distance of \a q from the surface (negative inside), along the radius; the
 * radius is \a radius at \a point and changes by \a taper per unit length along the
 * axis. */
double
surfaceDistance (const Eigen::Vector3d& q,
                 const Eigen::Vector3d& point,
                 const Eigen::Vector3d& axis,
                 double radius,
                 double taper)
{
  const Eigen::Vector3d w = q - point;
  const double t = w.dot (axis);
  return (w - t * axis).norm() - (radius + taper * t);
}

/** The alive points within the tolerance of the surface, and within \a window of \a
 * origin along the axis; returns their fit score, a truncated quadratic loss with half
 * the tolerance as its band (MSAC), so that of two cylinders the one the points lie
 * tighter on wins: a circle through the undersides of two pipes side by side holds as
 * many points as either pipe's own, but looser. */
double
collectInliers (const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::uint32_t>& alive,
                const Eigen::Vector3d& point,
                const Eigen::Vector3d& axis,
                double radius,
                double taper,
                const Eigen::Vector3d& origin,
                double window,
                double tolerance,
                std::vector<std::uint32_t>& inliers)
{
  inliers.clear();
  const double band = 0.25 * tolerance * tolerance;
  double score = 0.0;
  for (const auto j : alive) {
    if (std::abs ((points[j] - origin).dot (axis)) > window)
      continue;
    const double e = std::abs (surfaceDistance (points[j], point, axis, radius, taper));
    if (e <= tolerance)
      inliers.push_back (j);
    score += band - std::min (e * e, band);
  }
  return score;
}

/** The angle the points span around the axis: all but the widest empty sector. */
double
inlierArc (const std::vector<Eigen::Vector3d>& points,
           const std::vector<std::uint32_t>& subset,
           const Eigen::Vector3d& point,
           const Eigen::Vector3d& axis)
{
  if (subset.size() < 2)
    return 0.0;
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross (u);
  std::vector<double> angles;
  angles.reserve (subset.size());
  for (const auto j : subset) {
    const Eigen::Vector3d w = points[j] - point;
    angles.push_back (std::atan2 (w.dot (v), w.dot (u)));
  }
  std::sort (angles.begin(), angles.end());
  double widest = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k)
    widest = std::max (widest, angles[k] - angles[k - 1]);
  return 2.0 * M_PI - widest;
}

/** Draw one hypothesis from the patch around a random alive point; false when the patch
 * gives none. */
bool
drawHypothesis (const std::vector<Eigen::Vector3d>& points,
                const search::KdTree3f& tree,
                const std::vector<std::uint8_t>& is_alive,
                std::uint32_t seed_point,
                const DetectionParameters& p,
                RandomStream& rng,
                pcl::Indices& found,
                std::vector<float>& sqr_distances,
                std::vector<std::uint32_t>& patch,
                Hypothesis& h)
{
  const Eigen::Vector3f query = points[seed_point].cast<float>();
  tree.radiusSearch (
      query.data(), p.neighbourhood_radius, found, sqr_distances, 0, false);
  patch.clear();
  for (const auto j : found)
    if (is_alive[j])
      patch.push_back (static_cast<std::uint32_t> (j));
  if (patch.size() < kMinPatchPoints)
    return false;
  std::sort (patch.begin(),
             patch.end()); // the draws must not depend on the tree's order
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto j : patch)
    mean += points[j];
  mean /= static_cast<double> (patch.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto j : patch)
    cov += (points[j] - mean) * (points[j] - mean).transpose();
  EigenDecomposition eigen;
  if (!computeEigenDecomposition (cov, eigen))
    return false;
  const Eigen::Vector3d axis =
      eigen.vectors.col (2); // a strip is longest along its axis
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross (u);
  const auto project = [&] (std::uint32_t j) {
    const Eigen::Vector3d w = points[j] - mean;
    return Eigen::Vector2d (w.dot (u), w.dot (v));
  };
  Eigen::Vector2d centre;
  double radius;
  // Two draws, in this order (the arguments' evaluation order is unspecified).
  const std::uint32_t second = patch[rng.index (patch.size())];
  const std::uint32_t third = patch[rng.index (patch.size())];
  if (!circleThrough (
          project (seed_point), project (second), project (third), centre, radius) ||
      radius < p.min_radius || radius > p.max_radius)
    return false;
  const double tol = p.distance_tolerance;
  double score = 0.0;
  for (const auto j : patch) {
    const double e = std::abs ((project (j) - centre).norm() - radius);
    score += e <= tol ? 1.0 : (e <= kShellTolerances * tol ? -2.0 : 0.0);
  }
  h = {score, mean + centre.x() * u + centre.y() * v, axis, radius};
  return true;
}

/** Grow a hypothesis along its axis over the alive points, refining it at each step;
 * false when it falls apart or leaves the radius range. */
bool
growHypothesis (const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::uint32_t>& alive,
                double extent,
                const DetectionParameters& p,
                Hypothesis& h,
                std::vector<std::uint32_t>& inliers,
                double& score)
{
  const Eigen::Vector3d origin = h.point;
  const double infinite = std::numeric_limits<double>::infinity();
  for (double window = p.neighbourhood_radius;; window *= 2.0) {
    const double w = window > extent ? infinite : window;
    collectInliers (points,
                    alive,
                    h.point,
                    h.axis,
                    h.radius,
                    h.taper,
                    origin,
                    w,
                    p.distance_tolerance,
                    inliers);
    if (inliers.size() < 6 ||
        !refineCylinder (points,
                         inliers,
                         h.point,
                         h.axis,
                         h.radius,
                         p.max_taper > 0.0 ? &h.taper : nullptr) ||
        h.radius < p.min_radius || h.radius > p.max_radius ||
        std::abs (h.taper) > p.max_taper)
      return false;
    if (w == infinite)
      break;
  }
  score = collectInliers (points,
                          alive,
                          h.point,
                          h.axis,
                          h.radius,
                          h.taper,
                          origin,
                          infinite,
                          p.distance_tolerance,
                          inliers);
  return true;
}
} // namespace

bool
validParameters (const DetectionParameters& p)
{
  const auto positive = [] (double x) { return x > 0.0 && std::isfinite (x); };
  return positive (p.distance_tolerance) && positive (p.min_radius) &&
         positive (p.max_radius) && p.max_radius >= p.min_radius &&
         positive (p.neighbourhood_radius) && p.hypotheses >= 1 &&
         p.refined_hypotheses >= 1 && p.min_points >= 3 &&
         p.min_surface_fraction >= 0.0 && p.min_surface_fraction <= 1.0 &&
         p.max_taper >= 0.0 && p.max_taper < 1.0;
}

bool
refineCylinder (const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::uint32_t>& subset,
                Eigen::Vector3d& point,
                Eigen::Vector3d& axis,
                double& radius,
                double* taper)
{
  if (subset.size() < 6)
    return false;
  Eigen::Vector3d c = point, d = axis.normalized();
  double r = radius, k = taper ? *taper : 0.0;
  for (int iteration = 0; iteration < 10; ++iteration) {
    // Parameters: shifts of the axis across itself (u, v), tilts of its direction
    // towards u and v, the radius at c, and (for a cone) the taper.
    const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross (u);
    Eigen::Matrix<double, 6, 6> jtj = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> jtr = Eigen::Matrix<double, 6, 1>::Zero();
    for (const auto i : subset) {
      const Eigen::Vector3d q = points[i] - c;
      const double t = q.dot (d);
      const Eigen::Vector3d w = q - t * d;
      const double rho = w.norm();
      if (rho < 1e-12)
        continue;
      const Eigen::Vector3d n = w / rho;
      Eigen::Matrix<double, 6, 1> j;
      j << -n.dot (u), -n.dot (v), -t * n.dot (u) - k * w.dot (u),
          -t * n.dot (v) - k * w.dot (v), -1.0, -t;
      jtj += j * j.transpose();
      jtr += j * (rho - r - k * t);
    }
    if (!taper) // a cylinder: the taper stays 0
    {
      jtj.row (5).setZero();
      jtj.col (5).setZero();
      jtj (5, 5) = 1.0;
      jtr (5) = 0.0;
    }
    const Eigen::Matrix<double, 6, 1> delta = jtj.ldlt().solve (-jtr);
    if (!delta.allFinite())
      return false;
    c += delta (0) * u + delta (1) * v;
    d = (d + delta (2) * u + delta (3) * v).normalized();
    r += delta (4);
    k += delta (5);
    if (delta.norm() < 1e-9)
      break;
  }
  if (!c.allFinite() || !d.allFinite() || !std::isfinite (r) || !(r > 0.0) ||
      !std::isfinite (k))
    return false;
  point = c;
  axis = d;
  radius = r;
  if (taper)
    *taper = k;
  return true;
}

void
detectCylinders (const std::vector<Eigen::Vector3d>& points,
                 const DetectionParameters& p,
                 std::vector<Cylinder>& cylinders)
{
  cylinders.clear();
  if (!validParameters (p) || points.size() < p.min_points)
    return;
  std::vector<float> xyz;
  xyz.reserve (3 * points.size());
  std::vector<pcl::index_t> ids (points.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite())
      return;
    for (int k = 0; k < 3; ++k)
      xyz.push_back (static_cast<float> (points[i](k)));
    ids[i] = static_cast<pcl::index_t> (i);
    mean += points[i];
  }
  mean /= static_cast<double> (points.size());
  double extent = 0.0; // no window wider than this can add a point
  for (const auto& q : points)
    extent = std::max (extent, 2.0 * (q - mean).norm());
  search::KdTree3f tree;
  tree.build (std::move (xyz), std::move (ids));

  std::vector<std::uint8_t> is_alive (points.size(), 1), is_claimed (points.size(), 0);
  std::vector<std::uint32_t> alive, patch, inliers, best_inliers;
  pcl::Indices found;
  std::vector<float> sqr_distances;
  std::vector<Hypothesis> hypotheses;
  RandomStream rng (p.seed);
  unsigned int failures = 0;
  for (unsigned int round = 0;
       cylinders.size() < p.max_cylinders && failures < std::max (1u, p.max_failures) &&
       round < 4 * p.max_cylinders;
       ++round) {
    alive.clear();
    for (std::uint32_t i = 0; i < points.size(); ++i)
      if (is_alive[i])
        alive.push_back (i);
    if (alive.size() < p.min_points)
      break;
    hypotheses.clear();
    for (unsigned int k = 0; k < p.hypotheses; ++k) {
      Hypothesis h;
      if (drawHypothesis (points,
                          tree,
                          is_alive,
                          alive[rng.index (alive.size())],
                          p,
                          rng,
                          found,
                          sqr_distances,
                          patch,
                          h))
        hypotheses.push_back (h);
    }
    std::stable_sort (
        hypotheses.begin(),
        hypotheses.end(),
        [] (const Hypothesis& a, const Hypothesis& b) { return a.score > b.score; });
    Hypothesis best{};
    best_inliers.clear();
    double best_score = -1.0, score = 0.0;
    const std::size_t refined =
        std::min<std::size_t> (p.refined_hypotheses, hypotheses.size());
    for (std::size_t k = 0; k < refined; ++k) {
      Hypothesis h = hypotheses[k];
      if (growHypothesis (points, alive, extent, p, h, inliers, score) &&
          score > best_score) {
        best = h;
        best_score = score;
        best_inliers.swap (inliers);
      }
    }
    if (best_inliers.size() < p.min_points) {
      ++failures;
      continue;
    }
    // The extent along the axis and the surface test, before the inliers leave the
    // search.
    double t_min = std::numeric_limits<double>::infinity(), t_max = -t_min;
    for (const auto j : best_inliers) {
      const double t = (points[j] - best.point).dot (best.axis);
      t_min = std::min (t_min, t);
      t_max = std::max (t_max, t);
    }
    // The surface test counts every point not on an accepted cylinder (the band a
    // rejected candidate took must still count against the next: the faces of a box
    // give several), and the points inside it: a solid seen from outside has none (a
    // plane through the axis does, where two of its scan rows lie on the surface).
    std::size_t near = 0;
    for (std::uint32_t j = 0; j < points.size(); ++j) {
      if (is_claimed[j])
        continue;
      const double t = (points[j] - best.point).dot (best.axis);
      if (t >= t_min && t <= t_max &&
          surfaceDistance (points[j], best.point, best.axis, best.radius, best.taper) <=
              kShellTolerances * p.distance_tolerance)
        ++near;
    }
    for (const auto j : best_inliers)
      is_alive[j] = 0;
    Cylinder cylinder;
    cylinder.surface_fraction =
        static_cast<double> (best_inliers.size()) / static_cast<double> (near);
    cylinder.arc = inlierArc (points, best_inliers, best.point, best.axis);
    // A curvature the points can show: the arc must bow out of its chord by the
    // tolerance, or a plane (two scan rows of it, say) explains them as well.
    const double middle_radius = best.radius + best.taper * 0.5 * (t_min + t_max);
    const double sagitta =
        middle_radius * (1.0 - std::cos (0.5 * std::min (cylinder.arc, M_PI)));
    if (t_max - t_min < 2.0 * best.radius ||
        cylinder.surface_fraction < p.min_surface_fraction ||
        sagitta < p.distance_tolerance) {
      ++failures;
      continue;
    }
    const double middle = 0.5 * (t_min + t_max);
    cylinder.point = best.point + middle * best.axis;
    cylinder.axis = best.axis;
    cylinder.radius = best.radius + best.taper * middle;
    cylinder.taper = best.taper;
    cylinder.half_length = 0.5 * (t_max - t_min);
    for (const auto j : best_inliers)
      is_claimed[j] = 1;
    cylinder.inliers = best_inliers;
    cylinders.push_back (std::move (cylinder));
  }
}
} // namespace cylinders
} // namespace pcl_ext
