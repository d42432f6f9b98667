/*
 * pcl_ext: assembling scene geometry with consistent ids and ground-truth curves.
 */
#pragma once

#include <pcl_ext/simulation/scene_geometry.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace simulation {
/** \brief How the end of a pipe, cone or cylinder is finished, which decides its ground
 * truth. */
struct EndCondition {
  enum class Kind {
    Open,   ///< a free end: a border circle (the inside can be seen through it)
    Capped, ///< closed by a flat disk: a new segment and a crease circle
    Joined, ///< meets the surface \c segment at a right angle: a crease circle with it
    Smooth  ///< continues tangentially into another surface (an elbow): no curve
  };
  Kind kind = Kind::Open;
  std::uint32_t segment = 0; ///< the surface met, for Joined

  static EndCondition
  open ()
  {
    return {Kind::Open, 0};
  }
  static EndCondition
  capped ()
  {
    return {Kind::Capped, 0};
  }
  static EndCondition
  joined (std::uint32_t s)
  {
    return {Kind::Joined, s};
  }
  static EndCondition
  smooth ()
  {
    return {Kind::Smooth, 0};
  }
};

/** \brief Builds a SceneGeometry: hands out segment and object ids (from 1) and records
 * the crease and border curves implied by each shape, so that scenes only state how
 * shapes meet.
 */
class SceneBuilder {
public:
  /** \brief Marks a polygon edge that has no ground-truth curve (e.g. hidden below
   * ground). */
  static constexpr std::uint32_t kNoCurve = 0xffffffffu;

  SceneGeometry&
  geometry ()
  {
    return geometry_;
  }

  /** \brief A new object id. */
  std::uint32_t
  newObject ()
  {
    return ++last_object_;
  }

  /** \brief Surface info with a new segment id. */
  SurfaceInfo
  newSurface (std::uint32_t object, std::uint32_t label, const Material& material)
  {
    SurfaceInfo info;
    info.segment = ++last_segment_;
    info.object = object;
    info.label = label;
    info.material = material;
    return info;
  }

  /** \brief Add a primitive as one surface; returns its segment id. */
  std::uint32_t
  add (const Primitive::Ptr& primitive,
       std::uint32_t object,
       std::uint32_t label,
       const Material& material);

  /** \brief Add a primitive as (part of) an existing surface \a info (shared segment
   * id). */
  void
  addPart (const Primitive::Ptr& primitive, const SurfaceInfo& info)
  {
    primitive->info = info;
    geometry_.addPrimitive (primitive);
  }

  /** \brief A planar polygon with holes (see PlanarPolygon).
   * \param neighbours per ring and edge (edge k joins vertex k to k + 1): the segment
   * meeting that edge (a crease), 0 for a free edge (a border), kNoCurve for none;
   * empty means every edge is a border \return the segment id */
  std::uint32_t
  addPolygon (const Vec3& origin,
              const Vec3& u,
              const Vec3& v,
              const std::vector<std::vector<Vec2>>& rings,
              std::uint32_t object,
              std::uint32_t label,
              const Material& material,
              const std::vector<std::vector<std::uint32_t>>& neighbours = {});

  /** \brief A box with centre, rotation (columns: box axes) and half sizes; faces are
   * segments (order -x, +x, -y, +y, -z, +z) and its 12 edges creases. With \a
   * ground_segment != 0 the bottom face (-z, which must be horizontal) is left out and
   * the bottom edges become creases with the ground. \return the six face segment ids
   * (0 for a face left out) */
  std::array<std::uint32_t, 6>
  addBox (const Vec3& centre,
          const Eigen::Matrix3d& rotation,
          const Vec3& half,
          std::uint32_t object,
          std::uint32_t label,
          const Material& material,
          std::uint32_t ground_segment = 0);

  /** \brief The lateral surface of a cylinder (r0 == r1) or cone frustum, with its two
   * ends. \return the lateral segment id (caps get the following ids) */
  std::uint32_t
  addFrustum (const Vec3& base,
              const Vec3& axis,
              double length,
              double r0,
              double r1,
              std::uint32_t object,
              std::uint32_t label,
              const Material& material,
              EndCondition base_end,
              EndCondition top_end);

  /** \brief A straight line crease or border of \a segment_a (and \a segment_b). */
  void
  addLine (const Vec3& a,
           const Vec3& b,
           std::uint32_t segment_a,
           std::uint32_t segment_b);

  /** \brief A circular crease (segment_b != 0) or border. */
  void
  addCircle (const Vec3& centre,
             const Vec3& normal,
             double radius,
             std::uint32_t segment_a,
             std::uint32_t segment_b);

  /** \brief The crease where the frustum \a f (segment \a segment_f) leaves the surface
   * \a other (segment \a segment_other): along each of \a samples generator lines, the
   * first point where other.implicit() turns from negative to positive, found by
   * bisection; the points are joined into a closed chain of line segments. Used for
   * branches leaving a trunk and trunks or poles standing on uneven terrain. */
  void
  addIntersection (const ConeFrustum& f,
                   std::uint32_t segment_f,
                   const Primitive& other,
                   std::uint32_t segment_other,
                   int samples = 128);

private:
  SceneGeometry geometry_;
  std::uint32_t last_segment_ = 0;
  std::uint32_t last_object_ = 0;
};
} // namespace simulation
} // namespace pcl_ext
