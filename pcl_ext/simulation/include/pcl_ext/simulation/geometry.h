/*
 * pcl_ext: rays, boxes and ground-truth curves of the scanner simulator.
 */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <utility>

namespace pcl_ext {
namespace simulation {
using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

/** \brief A ray with a unit direction. */
struct Ray {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
};

/** \brief Axis-aligned bounding box; empty when min > max. */
struct Aabb {
  Vec3 min = Vec3::Constant (std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant (-std::numeric_limits<double>::infinity());

  void
  extend (const Vec3& p)
  {
    min = min.cwiseMin (p);
    max = max.cwiseMax (p);
  }
  void
  extend (const Aabb& b)
  {
    min = min.cwiseMin (b.min);
    max = max.cwiseMax (b.max);
  }
  bool
  empty () const
  {
    return (min.array() > max.array()).any();
  }
  Vec3
  centre () const
  {
    return 0.5 * (min + max);
  }
  /** \brief Box grown by \a margin on every side. */
  Aabb
  grown (double margin) const
  {
    Aabb b = *this;
    b.min.array() -= margin;
    b.max.array() += margin;
    return b;
  }
  /** \brief Slab test: clips [t0, t1] to the box; false when the ray misses it. */
  bool
  clip (const Vec3& origin, const Vec3& inv_direction, double& t0, double& t1) const
  {
    for (int k = 0; k < 3; ++k) {
      double ta = (min[k] - origin[k]) * inv_direction[k];
      double tb = (max[k] - origin[k]) * inv_direction[k];
      if (ta > tb)
        std::swap (ta, tb);
      // NaN (0 * inf, a ray in the slab's plane) compares false: the interval is
      // unchanged.
      if (ta > t0)
        t0 = ta;
      if (tb < t1)
        t1 = tb;
      if (t0 > t1)
        return false;
    }
    return true;
  }
};

/** \brief A curve of the true geometry along which the class ground truth changes.
 *
 * A \c Crease is where two surfaces (segments) meet at an angle: box edges, a wall
 * meeting the floor, a pipe meeting a wall, a branch leaving a trunk. A \c Border is
 * where a surface ends without meeting another one: the rim of a window hole, the free
 * end of a pipe, the outer edge of the terrain. Curves are exact line segments or
 * circles; intersection curves without closed form are stored as chains of line
 * segments sampled finely enough that the chord error stays below 0.5 mm.
 */
struct GroundTruthCurve {
  enum class Kind : std::uint8_t { Crease, Border };
  enum class Shape : std::uint8_t { LineSegment, Circle };

  Kind kind = Kind::Crease;
  Shape shape = Shape::LineSegment;
  Vec3 a = Vec3::Zero();       ///< segment start, or circle centre
  Vec3 b = Vec3::Zero();       ///< segment end, or circle unit normal
  double radius = 0.0;         ///< circle radius
  std::uint32_t segment_a = 0; ///< surface the curve belongs to
  std::uint32_t segment_b = 0; ///< the other surface of a crease (0 for a border)

  /** \brief Euclidean distance from \a p to the curve. */
  double
  distance (const Vec3& p) const;

  /** \brief Bounding box of the curve. */
  Aabb
  bounds () const;
};

/** \brief Real roots of c[0] + c[1] t + ... + c[degree] t^degree in [lo, hi],
 * ascending.
 *
 * Roots are isolated recursively between the roots of the derivative (where the
 * polynomial is monotone) and refined by bisection to machine precision; robust for the
 * torus quartic, where closed forms lose digits. degree <= 4. \return the number of
 * roots written to \a roots
 */
int
solvePolynomial (const double* c, int degree, double lo, double hi, double* roots);

/** \brief Two unit vectors completing \a n (unit) to a right-handed orthonormal frame.
 */
void
orthonormalFrame (const Vec3& n, Vec3& u, Vec3& v);
} // namespace simulation
} // namespace pcl_ext
