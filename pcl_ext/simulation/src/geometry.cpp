/*
 * pcl_ext: rays, boxes and ground-truth curves of the scanner simulator.
 */
#include <pcl_ext/simulation/geometry.h>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace simulation {
double
GroundTruthCurve::distance (const Vec3& p) const
{
  if (shape == Shape::Circle) {
    const Vec3 q = p - a;
    const double h = q.dot (b);
    const double rho = (q - h * b).norm();
    return std::hypot (rho - radius, h);
  }
  const Vec3 d = b - a;
  const double len2 = d.squaredNorm();
  double s = len2 > 0.0 ? (p - a).dot (d) / len2 : 0.0;
  s = std::clamp (s, 0.0, 1.0);
  return (p - (a + s * d)).norm();
}

Aabb
GroundTruthCurve::bounds() const
{
  Aabb box;
  if (shape == Shape::Circle) {
    // Extent of a circle along axis k: radius * sqrt(1 - n_k^2).
    const Vec3 ext =
        (Vec3::Ones() - b.cwiseProduct (b)).cwiseMax (0.0).cwiseSqrt() * radius;
    box.extend (a - ext);
    box.extend (a + ext);
  }
  else {
    box.extend (a);
    box.extend (b);
  }
  return box;
}

namespace {
double
evaluate (const double* c, int degree, double t)
{
  double v = c[degree];
  for (int i = degree - 1; i >= 0; --i)
    v = v * t + c[i];
  return v;
}

// Root of a polynomial that is monotone on [lo, hi] with a sign change.
double
bisect (const double* c, int degree, double lo, double hi, double flo)
{
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi)
      break;
    const double fm = evaluate (c, degree, mid);
    if (fm == 0.0)
      return mid;
    if ((fm < 0.0) == (flo < 0.0)) {
      lo = mid;
      flo = fm;
    }
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}
} // namespace

int
solvePolynomial (const double* c, int degree, double lo, double hi, double* roots)
{
  while (degree > 0 && c[degree] == 0.0)
    --degree;
  if (degree <= 0)
    return 0;
  if (degree == 1) {
    const double t = -c[0] / c[1];
    if (t >= lo && t <= hi) {
      roots[0] = t;
      return 1;
    }
    return 0;
  }
  // Split [lo, hi] at the roots of the derivative: the polynomial is monotone between
  // them.
  double derivative[4];
  for (int i = 1; i <= degree; ++i)
    derivative[i - 1] = i * c[i];
  double critical[4];
  const int num_critical = solvePolynomial (derivative, degree - 1, lo, hi, critical);
  double knots[6];
  int num_knots = 0;
  knots[num_knots++] = lo;
  for (int i = 0; i < num_critical; ++i)
    knots[num_knots++] = critical[i];
  knots[num_knots++] = hi;
  int count = 0;
  double fa = evaluate (c, degree, knots[0]);
  for (int i = 0; i + 1 < num_knots; ++i) {
    const double a = knots[i], b = knots[i + 1];
    const double fb = evaluate (c, degree, b);
    if (fa == 0.0) {
      if (count == 0 || roots[count - 1] != a)
        roots[count++] = a;
    }
    else if ((fa < 0.0) != (fb < 0.0) && fb != 0.0)
      roots[count++] = bisect (c, degree, a, b, fa);
    fa = fb;
  }
  if (fa == 0.0 && (count == 0 || roots[count - 1] != hi))
    roots[count++] = hi;
  return count;
}

void
orthonormalFrame (const Vec3& n, Vec3& u, Vec3& v)
{
  const Vec3 helper = std::abs (n.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
  u = helper.cross (n).normalized();
  v = n.cross (u);
}
} // namespace simulation
} // namespace pcl_ext
