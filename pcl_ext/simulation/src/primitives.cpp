/*
 * pcl_ext: analytic surfaces the scanner simulator ray-casts against.
 */
#include <pcl_ext/simulation/primitives.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace simulation {
namespace {
constexpr double kTwoPi = 6.283185307179586;

// Box of a circle (centre c, unit normal n, radius r) grown by m.
Aabb
circleBounds (const Vec3& c, const Vec3& n, double r, double m = 0.0)
{
  const Vec3 ext = (Vec3::Ones() - n.cwiseProduct (n)).cwiseMax (0.0).cwiseSqrt() * r +
                   Vec3::Constant (m);
  Aabb box;
  box.extend (c - ext);
  box.extend (c + ext);
  return box;
}

// Roots of a t^2 + b t + c in ascending order (numerically stable form).
int
solveQuadratic (double a, double b, double c, double& r0, double& r1)
{
  if (std::abs (a) < 1e-300) {
    if (b == 0.0)
      return 0;
    r0 = -c / b;
    return 1;
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0)
    return 0;
  const double q = -0.5 * (b + std::copysign (std::sqrt (disc), b));
  if (q == 0.0) {
    r0 = r1 = 0.0;
    return 2;
  }
  r0 = q / a;
  r1 = c / q;
  if (r0 > r1)
    std::swap (r0, r1);
  return 2;
}
} // namespace

// ---------------------------------------------------------------------------------------------
PlanarPolygon::PlanarPolygon (const Vec3& origin,
                              const Vec3& u,
                              const Vec3& v,
                              std::vector<std::vector<Vec2>> rings)
: origin_ (origin), u_ (u.normalized()), v_ (v.normalized()), rings_ (std::move (rings))
{
  normal_ = u_.cross (v_).normalized();
  for (const auto& ring : rings_)
    for (const auto& q : ring)
      box2_.extend (q);
}

bool
PlanarPolygon::contains (const Vec2& q) const
{
  bool inside = false;
  for (const auto& ring : rings_) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Vec2& a = ring[i];
      const Vec2& b = ring[j];
      if ((a.y() > q.y()) != (b.y() > q.y()) &&
          q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
        inside = !inside;
    }
  }
  return inside;
}

bool
PlanarPolygon::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  const double denom = ray.direction.dot (normal_);
  if (std::abs (denom) < 1e-12)
    return false;
  const double tt = (origin_ - ray.origin).dot (normal_) / denom;
  if (!(tt > t_min && tt < t_max))
    return false;
  const Vec3 d = ray.origin + tt * ray.direction - origin_;
  const Vec2 q (d.dot (u_), d.dot (v_));
  if (!box2_.contains (q) || !contains (q))
    return false;
  t = tt;
  normal = normal_;
  return true;
}

Aabb
PlanarPolygon::bounds() const
{
  Aabb box;
  for (const auto& ring : rings_)
    for (const auto& q : ring)
      box.extend (toWorld (q));
  return box;
}

double
PlanarPolygon::implicit (const Vec3& p) const
{
  return (p - origin_).dot (normal_);
}

// ---------------------------------------------------------------------------------------------
Annulus::Annulus (const Vec3& centre,
                  const Vec3& normal,
                  double r_inner,
                  double r_outer)
: centre_ (centre)
, normal_ (normal.normalized())
, r_inner_ (r_inner)
, r_outer_ (r_outer)
{}

bool
Annulus::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  const double denom = ray.direction.dot (normal_);
  if (std::abs (denom) < 1e-12)
    return false;
  const double tt = (centre_ - ray.origin).dot (normal_) / denom;
  if (!(tt > t_min && tt < t_max))
    return false;
  const double r2 = (ray.origin + tt * ray.direction - centre_).squaredNorm();
  if (r2 > r_outer_ * r_outer_ || r2 < r_inner_ * r_inner_)
    return false;
  t = tt;
  normal = normal_;
  return true;
}

Aabb
Annulus::bounds() const
{
  return circleBounds (centre_, normal_, r_outer_);
}

double
Annulus::implicit (const Vec3& p) const
{
  return (p - centre_).dot (normal_);
}

// ---------------------------------------------------------------------------------------------
ConeFrustum::ConeFrustum (
    const Vec3& base, const Vec3& axis, double length, double r0, double r1)
: base_ (base)
, axis_ (axis.normalized())
, length_ (length)
, r0_ (r0)
, slope_ ((r1 - r0) / length)
{}

bool
ConeFrustum::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  // |w(t)|^2 = r(s(t))^2 with s the axial and w the radial component of the ray point.
  const Vec3 m = ray.origin - base_;
  const double sm = m.dot (axis_), sd = ray.direction.dot (axis_);
  const Vec3 wm = m - sm * axis_, wd = ray.direction - sd * axis_;
  const double rm = r0_ + slope_ * sm;
  const double a = wd.squaredNorm() - slope_ * slope_ * sd * sd;
  const double b = 2.0 * (wm.dot (wd) - slope_ * rm * sd);
  const double c = wm.squaredNorm() - rm * rm;
  double roots[2];
  const int n = solveQuadratic (a, b, c, roots[0], roots[1]);
  for (int i = 0; i < n; ++i) {
    const double tt = roots[i];
    if (!(tt > t_min && tt < t_max))
      continue;
    const double s = sm + tt * sd;
    if (s < 0.0 || s > length_ || r0_ + slope_ * s < 0.0)
      continue;
    const Vec3 w = wm + tt * wd;
    const double wn = w.norm();
    if (wn == 0.0)
      continue;
    t = tt;
    normal = (w / wn - slope_ * axis_).normalized();
    return true;
  }
  return false;
}

Aabb
ConeFrustum::bounds() const
{
  Aabb box = circleBounds (base_, axis_, r0_);
  box.extend (circleBounds (base_ + length_ * axis_, axis_, radiusAt (length_)));
  return box;
}

double
ConeFrustum::implicit (const Vec3& p) const
{
  const Vec3 m = p - base_;
  const double s = m.dot (axis_);
  return (m - s * axis_).norm() - radiusAt (s);
}

// ---------------------------------------------------------------------------------------------
Sphere::Sphere (const Vec3& centre,
                double radius,
                const Vec3& cut_axis,
                double cut_height)
: centre_ (centre)
, cut_axis_ (cut_axis.normalized())
, radius_ (radius)
, cut_height_ (cut_height)
{}

bool
Sphere::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  const Vec3 m = ray.origin - centre_;
  double roots[2];
  const int n = solveQuadratic (1.0,
                                2.0 * m.dot (ray.direction),
                                m.squaredNorm() - radius_ * radius_,
                                roots[0],
                                roots[1]);
  for (int i = 0; i < n; ++i) {
    const double tt = roots[i];
    if (!(tt > t_min && tt < t_max))
      continue;
    const Vec3 q = m + tt * ray.direction;
    if (q.dot (cut_axis_) > cut_height_)
      continue;
    t = tt;
    normal = q / radius_;
    return true;
  }
  return false;
}

Aabb
Sphere::bounds() const
{
  Aabb box;
  box.extend (centre_ - Vec3::Constant (radius_));
  box.extend (centre_ + Vec3::Constant (radius_));
  return box;
}

double
Sphere::implicit (const Vec3& p) const
{
  return (p - centre_).norm() - radius_;
}

// ---------------------------------------------------------------------------------------------
Ellipsoid::Ellipsoid (const Vec3& centre,
                      const Eigen::Matrix3d& rotation,
                      const Vec3& radii)
: centre_ (centre), radii_ (radii), rotation_ (rotation)
{}

bool
Ellipsoid::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  // In the frame where the ellipsoid is the unit sphere; t keeps its meaning.
  const Vec3 o =
      (rotation_.transpose() * (ray.origin - centre_)).cwiseQuotient (radii_);
  const Vec3 d = (rotation_.transpose() * ray.direction).cwiseQuotient (radii_);
  double roots[2];
  const int n = solveQuadratic (
      d.squaredNorm(), 2.0 * o.dot (d), o.squaredNorm() - 1.0, roots[0], roots[1]);
  for (int i = 0; i < n; ++i) {
    const double tt = roots[i];
    if (!(tt > t_min && tt < t_max))
      continue;
    const Vec3 q = o + tt * d; // on the unit sphere
    t = tt;
    normal = (rotation_ * q.cwiseQuotient (radii_)).normalized();
    return true;
  }
  return false;
}

Aabb
Ellipsoid::bounds() const
{
  // Half extent along world axis k: sqrt(sum_j (R_kj r_j)^2).
  const Vec3 ext = (rotation_ * radii_.asDiagonal()).rowwise().norm();
  Aabb box;
  box.extend (centre_ - ext);
  box.extend (centre_ + ext);
  return box;
}

double
Ellipsoid::implicit (const Vec3& p) const
{
  return (rotation_.transpose() * (p - centre_)).cwiseQuotient (radii_).norm() - 1.0;
}

// ---------------------------------------------------------------------------------------------
TorusSection::TorusSection (const Vec3& centre,
                            const Vec3& axis,
                            const Vec3& start,
                            double major,
                            double minor,
                            double sweep)
: centre_ (centre)
, axis_ (axis.normalized())
, major_ (major)
, minor_ (minor)
, sweep_ (sweep)
{
  e1_ = (start - start.dot (axis_) * axis_).normalized();
  e2_ = axis_.cross (e1_);
}

bool
TorusSection::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  const Vec3 m = ray.origin - centre_;
  Vec3 o (m.dot (e1_), m.dot (e2_), m.dot (axis_));
  const Vec3 d (
      ray.direction.dot (e1_), ray.direction.dot (e2_), ray.direction.dot (axis_));
  // Clip to the local box of the whole torus, then shift the origin to the entry point
  // so that the quartic's coefficients stay small (distant scanners would cost digits).
  const double ext = major_ + minor_;
  Aabb local;
  local.min = Vec3 (-ext, -ext, -minor_);
  local.max = Vec3 (ext, ext, minor_);
  double t0 = t_min, t1 = t_max;
  if (!local.clip (o, d.cwiseInverse(), t0, t1))
    return false;
  o += t0 * d;
  const double R2 = major_ * major_;
  const double b = 2.0 * o.dot (d);
  const double cc = o.squaredNorm() + R2 - minor_ * minor_;
  const double dxy2 = d.x() * d.x() + d.y() * d.y();
  const double odxy = o.x() * d.x() + o.y() * d.y();
  const double oxy2 = o.x() * o.x() + o.y() * o.y();
  const double c[5] = {cc * cc - 4.0 * R2 * oxy2,
                       2.0 * b * cc - 8.0 * R2 * odxy,
                       b * b + 2.0 * cc - 4.0 * R2 * dxy2,
                       2.0 * b,
                       1.0};
  double roots[4];
  const int n = solvePolynomial (c, 4, 0.0, t1 - t0, roots);
  for (int i = 0; i < n; ++i) {
    const double tt = t0 + roots[i];
    if (!(tt > t_min && tt < t_max))
      continue;
    const Vec3 q = o + roots[i] * d;
    double phi = std::atan2 (q.y(), q.x());
    if (phi < 0.0)
      phi += kTwoPi;
    if (phi > sweep_)
      continue;
    const double rho = std::hypot (q.x(), q.y());
    if (rho == 0.0)
      continue;
    const Vec3 local_normal (
        q.x() - major_ * q.x() / rho, q.y() - major_ * q.y() / rho, q.z());
    t = tt;
    normal =
        (local_normal.x() * e1_ + local_normal.y() * e2_ + local_normal.z() * axis_)
            .normalized();
    return true;
  }
  return false;
}

Aabb
TorusSection::bounds() const
{
  return circleBounds (centre_, axis_, major_, minor_);
}

double
TorusSection::implicit (const Vec3& p) const
{
  const Vec3 m = p - centre_;
  const double z = m.dot (axis_);
  const double rho = (m - z * axis_).norm();
  return std::hypot (rho - major_, z) - minor_;
}

// ---------------------------------------------------------------------------------------------
HeightField::HeightField (
    double x0, double y0, double cell, int nx, int ny, std::vector<double> heights)
: x0_ (x0), y0_ (y0), cell_ (cell), nx_ (nx), ny_ (ny), heights_ (std::move (heights))
{
  heights_.resize (static_cast<std::size_t> (nx_ + 1) * (ny_ + 1), 0.0);
  const auto mm = std::minmax_element (heights_.begin(), heights_.end());
  zmin_ = *mm.first;
  zmax_ = *mm.second;
  cell_min_.resize (static_cast<std::size_t> (nx_) * ny_);
  cell_max_.resize (cell_min_.size());
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const double h[4] = {at (i, j), at (i + 1, j), at (i, j + 1), at (i + 1, j + 1)};
      const std::size_t c = static_cast<std::size_t> (j) * nx_ + i;
      // Rounded outwards so that the float range always contains the double heights.
      cell_min_[c] =
          std::nextafter (static_cast<float> (*std::min_element (h, h + 4)), -1e30f);
      cell_max_[c] =
          std::nextafter (static_cast<float> (*std::max_element (h, h + 4)), 1e30f);
    }
}

void
HeightField::setRegions (std::function<int (double, double)> region,
                         std::vector<SurfaceInfo> infos)
{
  region_ = std::move (region);
  region_infos_ = std::move (infos);
}

const SurfaceInfo&
HeightField::infoAt (const Vec3& p) const
{
  if (!region_)
    return info;
  const int r = region_ (p.x(), p.y());
  if (r < 0 || r >= static_cast<int> (region_infos_.size()))
    return info;
  return region_infos_[static_cast<std::size_t> (r)];
}

double
HeightField::height (double x, double y) const
{
  const double fx_all = std::clamp ((x - x0_) / cell_, 0.0, static_cast<double> (nx_));
  const double fy_all = std::clamp ((y - y0_) / cell_, 0.0, static_cast<double> (ny_));
  const int i = std::min (static_cast<int> (fx_all), nx_ - 1);
  const int j = std::min (static_cast<int> (fy_all), ny_ - 1);
  const double fx = fx_all - i, fy = fy_all - j;
  const double h00 = at (i, j), h10 = at (i + 1, j), h01 = at (i, j + 1),
               h11 = at (i + 1, j + 1);
  if (fx >= fy)
    return h00 + fx * (h10 - h00) + fy * (h11 - h10);
  return h00 + fy * (h01 - h00) + fx * (h11 - h01);
}

double
HeightField::implicit (const Vec3& p) const
{
  return p.z() - height (p.x(), p.y());
}

Aabb
HeightField::bounds() const
{
  Aabb box;
  box.extend (Vec3 (x0_, y0_, zmin_));
  box.extend (Vec3 (x1(), y1(), zmax_));
  return box;
}

namespace {
// Moller-Trumbore ray-triangle test.
bool
rayTriangle (const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, double& t)
{
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = ray.direction.cross (e2);
  const double det = e1.dot (p);
  if (std::abs (det) < 1e-15)
    return false;
  const double inv = 1.0 / det;
  const Vec3 s = ray.origin - a;
  const double u = s.dot (p) * inv;
  if (u < -1e-12 || u > 1.0 + 1e-12)
    return false;
  const Vec3 q = s.cross (e1);
  const double v = ray.direction.dot (q) * inv;
  if (v < -1e-12 || u + v > 1.0 + 1e-12)
    return false;
  t = e2.dot (q) * inv;
  return true;
}
} // namespace

bool
HeightField::intersectCell (const Ray& ray,
                            int i,
                            int j,
                            double t_min,
                            double t_max,
                            double& t,
                            Vec3& normal) const
{
  const double xa = x0_ + i * cell_, ya = y0_ + j * cell_;
  const Vec3 p00 (xa, ya, at (i, j)), p10 (xa + cell_, ya, at (i + 1, j));
  const Vec3 p01 (xa, ya + cell_, at (i, j + 1)),
      p11 (xa + cell_, ya + cell_, at (i + 1, j + 1));
  bool found = false;
  double tt;
  if (rayTriangle (ray, p00, p10, p11, tt) && tt > t_min && tt < t_max) {
    t = tt;
    t_max = tt;
    normal = (p10 - p00).cross (p11 - p00).normalized();
    found = true;
  }
  if (rayTriangle (ray, p00, p11, p01, tt) && tt > t_min && tt < t_max) {
    t = tt;
    normal = (p11 - p00).cross (p01 - p00).normalized();
    found = true;
  }
  return found;
}

bool
HeightField::intersect (
    const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const
{
  double t0 = t_min, t1 = t_max;
  if (!bounds().grown (1e-9).clip (ray.origin, ray.direction.cwiseInverse(), t0, t1))
    return false;
  const Vec3 p = ray.origin + t0 * ray.direction;
  int i =
      std::clamp (static_cast<int> (std::floor ((p.x() - x0_) / cell_)), 0, nx_ - 1);
  int j =
      std::clamp (static_cast<int> (std::floor ((p.y() - y0_) / cell_)), 0, ny_ - 1);
  const double dx = ray.direction.x(), dy = ray.direction.y();
  const int step_i = dx > 0.0 ? 1 : -1, step_j = dy > 0.0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double delta_x = dx != 0.0 ? cell_ / std::abs (dx) : inf;
  const double delta_y = dy != 0.0 ? cell_ / std::abs (dy) : inf;
  const double next_x = x0_ + (i + (step_i > 0 ? 1 : 0)) * cell_;
  const double next_y = y0_ + (j + (step_j > 0 ? 1 : 0)) * cell_;
  double tx = dx != 0.0 ? (next_x - ray.origin.x()) / dx : inf;
  double ty = dy != 0.0 ? (next_y - ray.origin.y()) / dy : inf;
  // Cells are visited in order along the ray, so the first cell with a hit holds the
  // nearest. A small overlap of the cell's t-interval catches hits exactly on a cell
  // border.
  const double eps = 1e-9 * (1.0 + std::abs (t1));
  while (true) {
    const double t_exit = std::min ({tx, ty, t1});
    // The ray's height over the cell spans [za, zb]; skip cells whose surface it cannot
    // meet.
    const double za = ray.origin.z() + (t0 - eps) * ray.direction.z();
    const double zb = ray.origin.z() + (t_exit + eps) * ray.direction.z();
    const std::size_t c = static_cast<std::size_t> (j) * nx_ + i;
    if (std::max (za, zb) >= cell_min_[c] && std::min (za, zb) <= cell_max_[c] &&
        intersectCell (ray,
                       i,
                       j,
                       std::max (t_min, t0 - eps),
                       std::min (t_max, t_exit + eps),
                       t,
                       normal))
      return true;
    if (t_exit >= t1)
      return false;
    t0 = t_exit;
    if (tx < ty) {
      i += step_i;
      tx += delta_x;
    }
    else {
      j += step_j;
      ty += delta_y;
    }
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_)
      return false;
  }
}
} // namespace simulation
} // namespace pcl_ext
