/*
 * pcl_ext: building blocks shared by the scene builders (internal).
 */
#pragma once

#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/scene_builder.h>
#include <pcl_ext/simulation/scenes.h>

#include <vector>

namespace pcl_ext {
namespace simulation {
namespace detail {
/** \brief Window holes of a wall: rows per storey, spaced along the wall. */
struct WindowLayout {
  double width = 1.2;
  double height = 1.5;
  double spacing = 4.0; ///< centre to centre along the wall
  double storey = 3.5;  ///< storey height
  double sill = 1.0;    ///< sill above the storey floor
  double margin = 1.5;  ///< from the wall ends to the nearest window edge
};

/** \brief Segment ids of a prism (walls on a footprint, and its roof). */
struct PrismSegments {
  std::vector<std::uint32_t> walls; ///< one per footprint edge k (vertex k to k + 1)
  std::uint32_t roof = 0;
};

/** \brief Vertical walls on a counter-clockwise footprint from z0 to z0 + height,
 * creases at the corners, with the ground (\a ground_segment, border when 0) and with
 * the roof; windows on the walls whose flag is set (all when \a windowed is empty). */
PrismSegments
addPrism (SceneBuilder& builder,
          const std::vector<Vec2>& footprint,
          double z0,
          double height,
          std::uint32_t ground_segment,
          bool roof,
          std::uint32_t object,
          std::uint32_t wall_label,
          std::uint32_t roof_label,
          const Material& wall,
          const Material& roof_material,
          const WindowLayout* windows,
          const std::vector<bool>& windowed = {});

/** \brief A pipe along a polyline with bends of radius \a bend (torus sections, smooth
 * joins). \return the segment ids of its straight parts and elbows, in order */
std::vector<std::uint32_t>
addPipeRun (SceneBuilder& builder,
            const std::vector<Vec3>& polyline,
            double radius,
            double bend,
            std::uint32_t object,
            std::uint32_t label,
            const Material& material,
            EndCondition first,
            EndCondition last);

/** \brief Rotation from yaw (about z), pitch (about y) and roll (about x), radians. */
Eigen::Matrix3d
rotationYpr (double yaw, double pitch, double roll);

/** \brief A uniformly random rotation (from a unit quaternion with Gaussian
 * components). */
Eigen::Matrix3d
randomRotation (RandomStream& rng);

/** \brief Signed area of a 2D polygon (positive when counter-clockwise). */
double
signedArea (const std::vector<Vec2>& polygon);

/** \brief Whether \a q is inside \a polygon (even-odd). */
bool
insidePolygon (const std::vector<Vec2>& polygon, const Vec2& q);

/** \brief Distance from \a q to the outline of \a polygon. */
double
distanceToOutline (const std::vector<Vec2>& polygon, const Vec2& q);

/** \brief Material shorthand. */
Material
material (float r, float g, float b, float reflectance, float jitter = 6.f);

/** \brief A random stream for scene layout, independent of the scan's ray streams. */
inline RandomStream
layoutStream (std::uint64_t seed, std::uint64_t scene_tag)
{
  return RandomStream (hashCombine (seed ^ 0x1a7e5ce9e0000000ULL, scene_tag));
}

/** \brief The first \a count of \a candidates when count > 0, else the first \a
 * fallback. */
std::vector<Eigen::Vector3d>
choosePositions (const std::vector<Eigen::Vector3d>& candidates,
                 int count,
                 int fallback);
} // namespace detail
} // namespace simulation
} // namespace pcl_ext

namespace pcl_ext {
namespace simulation {
namespace detail {
/** \brief A tree: tapering trunk standing in \a ground (its base below the surface, the
 * crease traced along the ground), branches leaving the trunk (traced creases) and
 * porous leaf clusters. Labels are OutdoorLabel. \return the object id */
std::uint32_t
addTree (SceneBuilder& builder,
         RandomStream& rng,
         const Vec3& base,
         const Primitive& ground,
         std::uint32_t ground_segment,
         double height,
         int branches);
} // namespace detail
} // namespace simulation
} // namespace pcl_ext
