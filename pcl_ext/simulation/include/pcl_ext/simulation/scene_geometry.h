/*
 * pcl_ext: the true geometry of a synthetic scene, with a BVH for ray casting.
 */
#pragma once

#include <pcl_ext/point_types.h>
#include <pcl_ext/simulation/geometry.h>
#include <pcl_ext/simulation/primitives.h>

#include <cstdint>
#include <map>
#include <vector>

namespace pcl_ext {
namespace simulation {
/** \brief Result of casting one ray into a SceneGeometry. */
struct RayHit {
  double t = 0.0;              ///< distance along the (unit) ray
  Vec3 normal = Vec3::UnitZ(); ///< unit surface normal (either orientation)
  int primitive = -1;          ///< index of the primitive hit
};

/** \brief Primitives and ground-truth curves of a scene, with a bounding volume
 * hierarchy.
 *
 * Add primitives and curves, call build(), then cast rays (thread-safe after build()).
 * Each curve applies only to the points of its own segments (segment_a, segment_b): a
 * point of one surface near another surface's crease is not an edge point of its own
 * surface.
 */
class SceneGeometry {
public:
  /** \brief Add a primitive; returns its index. */
  int
  addPrimitive (Primitive::Ptr primitive);

  /** \brief Add a ground-truth crease or border curve. */
  void
  addCurve (const GroundTruthCurve& curve);

  /** \brief Build the BVH and the per-segment curve lists. */
  void
  build ();

  /** \brief Nearest hit in (0, t_max), or false. Porous primitives let the ray through
   * when a uniform number drawn from (\a ray_key, primitive index) is below their
   * porosity. */
  bool
  intersect (const Ray& ray, double t_max, std::uint64_t ray_key, RayHit& hit) const;

  /** \brief The same, testing every primitive (no BVH); a reference for tests. */
  bool
  intersectBruteForce (const Ray& ray,
                       double t_max,
                       std::uint64_t ray_key,
                       RayHit& hit) const;

  /** \brief Distances from \a p (on segment \a segment) to the nearest crease and the
   * nearest border of that segment within \a max_distance (infinity when none is that
   * close). */
  void
  curveDistances (const Vec3& p,
                  std::uint32_t segment,
                  double max_distance,
                  double& crease,
                  double& border) const;

  /** \brief The other surfaces of the creases of segment \a segment within \a
   * max_distance of \a p, appended to \a others (one entry per crease, in curve order).
   */
  void
  creaseFacesNear (const Vec3& p,
                   std::uint32_t segment,
                   double max_distance,
                   std::vector<std::uint32_t>& others) const;

  /** \brief Class of a point at true position \a p on segment \a segment: Edge when a
   * crease is within \a distance (and no border is nearer), Boundary when a border is,
   * else Surface. */
  PointClass
  classify (const Vec3& p, std::uint32_t segment, double distance) const;

  const std::vector<Primitive::Ptr>&
  primitives () const
  {
    return primitives_;
  }
  const std::vector<GroundTruthCurve>&
  curves () const
  {
    return curves_;
  }
  /** \brief Bounding box of all primitives. */
  const Aabb&
  bounds () const
  {
    return bounds_;
  }

private:
  struct Node {
    Aabb box;
    int left = -1;  ///< first child (internal) or -1
    int right = -1; ///< second child
    int first = 0;  ///< first primitive in order_ (leaf)
    int count = 0;  ///< number of primitives (leaf)
  };

  int
  buildNode (int first, int count, const std::vector<Aabb>& boxes);
  bool
  passesThrough (int primitive, std::uint64_t ray_key) const;
  /** Calls \a visit (curve, distance) for every curve of \a segment within \a
   * max_distance of \a p. */
  template <typename Visit>
  void
  visitCurvesNear (const Vec3& p,
                   std::uint32_t segment,
                   double max_distance,
                   Visit&& visit) const;

  std::vector<Primitive::Ptr> primitives_;
  std::vector<GroundTruthCurve> curves_;
  std::vector<Aabb> curve_boxes_;
  /** \brief A run of up to kCurveChunk curves of one segment with their common box:
   * curves are added along their polylines, so consecutive curves are close and most
   * points skip whole chunks. */
  struct CurveChunk {
    Aabb box;
    std::vector<int> curves;
  };
  static constexpr std::size_t kCurveChunk = 16;
  std::map<std::uint32_t, std::vector<CurveChunk>> curves_of_segment_;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  Aabb bounds_;
};
} // namespace simulation
} // namespace pcl_ext
