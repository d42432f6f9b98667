/*
 * pcl_ext: analytic surfaces the scanner simulator ray-casts against.
 */
#pragma once

#include <pcl_ext/simulation/geometry.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace pcl_ext {
namespace simulation {
/** \brief Appearance of a surface: colour and laser reflectance.
 *
 * A point's colour is \a rgb plus Gaussian jitter of \a rgb_jitter per channel (0-255
 * scale); its intensity is reflectance * (0.2 + 0.8 |cos incidence|) plus Gaussian
 * jitter of \a intensity_jitter, clamped to [0, 1] (a Lambertian return with an ambient
 * floor).
 */
struct Material {
  Eigen::Vector3f rgb = Eigen::Vector3f (180.f, 180.f, 180.f);
  float rgb_jitter = 6.f;
  float reflectance = 0.5f;
  float intensity_jitter = 0.02f;
};

/** \brief What a point on a surface is: its segment, object, scene label and material.
 */
struct SurfaceInfo {
  std::uint32_t segment = 0; ///< surface id, >= 1
  std::uint32_t object = 0;  ///< object id, >= 1
  std::uint32_t label = 0;   ///< scene label (0 = none)
  Material material;
};

/** \brief An analytic surface: one segment of the ground truth (except HeightField,
 * which may carry several regions).
 *
 * \a porosity is the probability that a ray passes through the whole primitive
 * (vegetation); \a roughness is the standard deviation (m) of extra range noise on its
 * returns, modelling leaves scattered around the ideal surface.
 */
class Primitive {
public:
  using Ptr = std::shared_ptr<Primitive>;
  using ConstPtr = std::shared_ptr<const Primitive>;

  virtual ~Primitive() = default;

  /** \brief Nearest intersection with t in (t_min, t_max); writes t and the unit
   * normal. */
  virtual bool
  intersect (
      const Ray& ray, double t_min, double t_max, double& t, Vec3& normal) const = 0;

  /** \brief Bounding box. */
  virtual Aabb
  bounds () const = 0;

  /** \brief Signed implicit function (negative inside/below, zero on the surface), used
   * to trace intersection curves with other surfaces; not necessarily a distance. */
  virtual double
  implicit (const Vec3& p) const = 0;

  /** \brief Segment, object, label and material at a point of the surface. */
  virtual const SurfaceInfo&
  infoAt (const Vec3& /*p*/) const
  {
    return info;
  }

  SurfaceInfo info;
  double porosity = 0.0;
  double roughness = 0.0;
};

/** \brief A planar polygon with holes: rings of 2D vertices in the frame (origin, u,
 * v).
 *
 * Every ring is closed implicitly; inside means inside an odd number of rings, so the
 * first ring is the outline and the others are holes (windows, doors).
 */
class PlanarPolygon : public Primitive {
public:
  PlanarPolygon (const Vec3& origin,
                 const Vec3& u,
                 const Vec3& v,
                 std::vector<std::vector<Vec2>> rings);

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;

  /** \brief 3D position of a 2D polygon vertex. */
  Vec3
  toWorld (const Vec2& q) const
  {
    return origin_ + q.x() * u_ + q.y() * v_;
  }
  const std::vector<std::vector<Vec2>>&
  rings () const
  {
    return rings_;
  }
  const Vec3&
  normal () const
  {
    return normal_;
  }

  /** \brief Whether the 2D point is inside (even-odd rule). */
  bool
  contains (const Vec2& q) const;

private:
  Vec3 origin_, u_, v_, normal_;
  std::vector<std::vector<Vec2>> rings_;
  Eigen::AlignedBox2d box2_;
};

/** \brief A flat disk or annulus: r_inner <= |p - centre| <= r_outer in the plane. */
class Annulus : public Primitive {
public:
  Annulus (const Vec3& centre, const Vec3& normal, double r_inner, double r_outer);

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;

private:
  Vec3 centre_, normal_;
  double r_inner_, r_outer_;
};

/** \brief The open lateral surface of a cone frustum (a cylinder when both radii are
 * equal), seen from outside and from inside (open pipes).
 *
 * Axis from \a base along unit \a axis for \a length; radius r0 at the base and r1 at
 * the top.
 */
class ConeFrustum : public Primitive {
public:
  ConeFrustum (const Vec3& base, const Vec3& axis, double length, double r0, double r1);

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;

  const Vec3&
  base () const
  {
    return base_;
  }
  const Vec3&
  axis () const
  {
    return axis_;
  }
  double
  length () const
  {
    return length_;
  }
  double
  radiusAt (double s) const
  {
    return r0_ + slope_ * s;
  }

private:
  Vec3 base_, axis_;
  double length_, r0_, slope_;
};

/** \brief A sphere, optionally cut open: the part with (p - centre).cut_axis >
 * cut_height is removed (cut_height >= radius keeps the whole sphere). */
class Sphere : public Primitive {
public:
  Sphere (const Vec3& centre,
          double radius,
          const Vec3& cut_axis = Vec3::UnitZ(),
          double cut_height = std::numeric_limits<double>::infinity());

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;

private:
  Vec3 centre_, cut_axis_;
  double radius_, cut_height_;
};

/** \brief A closed ellipsoid with semi-axes \a radii along the columns of \a rotation.
 */
class Ellipsoid : public Primitive {
public:
  Ellipsoid (const Vec3& centre, const Eigen::Matrix3d& rotation, const Vec3& radii);

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;

private:
  Vec3 centre_, radii_;
  Eigen::Matrix3d rotation_;
};

/** \brief A section of a torus (a pipe elbow): tube radius \a minor around a circle of
 * radius \a major in the plane normal to \a axis, from direction \a start through \a
 * sweep radians (counter-clockwise about \a axis). */
class TorusSection : public Primitive {
public:
  TorusSection (const Vec3& centre,
                const Vec3& axis,
                const Vec3& start,
                double major,
                double minor,
                double sweep);

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;

private:
  Vec3 centre_, axis_, e1_, e2_;
  double major_, minor_, sweep_;
};

/** \brief A terrain z = h(x, y) on a regular grid, two triangles per cell, traversed
 * cell by cell along the ray (2D DDA), so long grazing rays cost a few cell tests each.
 *
 * An optional region function splits it into several ground-truth surfaces (grass,
 * road, walkway) that meet without a crease.
 */
class HeightField : public Primitive {
public:
  /** \param heights (nx + 1) * (ny + 1) values, x fastest */
  HeightField (
      double x0, double y0, double cell, int nx, int ny, std::vector<double> heights);

  bool
  intersect (const Ray& ray, double t_min, double t_max, double& t, Vec3& normal)
      const override;
  Aabb
  bounds () const override;
  double
  implicit (const Vec3& p) const override;
  const SurfaceInfo&
  infoAt (const Vec3& p) const override;

  /** \brief Height of the triangulated surface at (x, y) (clamped to the grid). */
  double
  height (double x, double y) const;

  /** \brief Regions: \a region maps (x, y) to an index into \a infos. */
  void
  setRegions (std::function<int (double, double)> region,
              std::vector<SurfaceInfo> infos);
  const std::vector<SurfaceInfo>&
  regions () const
  {
    return region_infos_;
  }

  double
  x0 () const
  {
    return x0_;
  }
  double
  y0 () const
  {
    return y0_;
  }
  double
  x1 () const
  {
    return x0_ + nx_ * cell_;
  }
  double
  y1 () const
  {
    return y0_ + ny_ * cell_;
  }

private:
  bool
  intersectCell (const Ray& ray,
                 int i,
                 int j,
                 double t_min,
                 double t_max,
                 double& t,
                 Vec3& normal) const;
  double
  at (int i, int j) const
  {
    return heights_[static_cast<std::size_t> (j) * (nx_ + 1) + i];
  }

  double x0_, y0_, cell_;
  int nx_, ny_;
  std::vector<double> heights_;
  std::vector<float> cell_min_,
      cell_max_; ///< height range of each cell, to skip cells fast
  double zmin_, zmax_;
  std::function<int (double, double)> region_;
  std::vector<SurfaceInfo> region_infos_;
};
} // namespace simulation
} // namespace pcl_ext
