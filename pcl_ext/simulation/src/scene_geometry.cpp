/*
 * pcl_ext: the true geometry of a synthetic scene, with a BVH for ray casting.
 */
#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/scene_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace simulation {
int
SceneGeometry::addPrimitive (Primitive::Ptr primitive)
{
  primitives_.push_back (std::move (primitive));
  return static_cast<int> (primitives_.size()) - 1;
}

void
SceneGeometry::addCurve (const GroundTruthCurve& curve)
{
  curves_.push_back (curve);
}

void
SceneGeometry::build()
{
  std::vector<Aabb> boxes (primitives_.size());
  bounds_ = Aabb();
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    boxes[i] = primitives_[i]->bounds().grown (1e-9);
    bounds_.extend (boxes[i]);
  }
  order_.resize (primitives_.size());
  for (std::size_t i = 0; i < order_.size(); ++i)
    order_[i] = static_cast<int> (i);
  nodes_.clear();
  if (!primitives_.empty())
    buildNode (0, static_cast<int> (primitives_.size()), boxes);

  curve_boxes_.resize (curves_.size());
  curves_of_segment_.clear();
  auto append = [this] (std::uint32_t segment, int curve) {
    auto& chunks = curves_of_segment_[segment];
    if (chunks.empty() || chunks.back().curves.size() >= kCurveChunk)
      chunks.emplace_back();
    chunks.back().curves.push_back (curve);
    chunks.back().box.extend (curve_boxes_[curve]);
  };
  for (std::size_t i = 0; i < curves_.size(); ++i) {
    curve_boxes_[i] = curves_[i].bounds();
    append (curves_[i].segment_a, static_cast<int> (i));
    if (curves_[i].segment_b != 0 && curves_[i].segment_b != curves_[i].segment_a)
      append (curves_[i].segment_b, static_cast<int> (i));
  }
}

int
SceneGeometry::buildNode (int first, int count, const std::vector<Aabb>& boxes)
{
  const int index = static_cast<int> (nodes_.size());
  nodes_.emplace_back();
  Aabb box, centres;
  for (int i = first; i < first + count; ++i) {
    box.extend (boxes[order_[i]]);
    centres.extend (boxes[order_[i]].centre());
  }
  nodes_[index].box = box;
  if (count <= 2) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  // Surface area heuristic over 16 bins of the centres along each axis; median split
  // when the centres coincide.
  auto area = [] (const Aabb& b) {
    if (b.empty())
      return 0.0;
    const Vec3 e = b.max - b.min;
    return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
  };
  constexpr int kBins = 16;
  int best_axis = -1, best_split = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = centres.min[axis], extent = centres.max[axis] - lo;
    if (!(extent > 0.0))
      continue;
    Aabb bin_box[kBins];
    int bin_count[kBins] = {};
    for (int i = first; i < first + count; ++i) {
      const int b = std::min (
          kBins - 1,
          static_cast<int> (kBins * (boxes[order_[i]].centre()[axis] - lo) / extent));
      bin_box[b].extend (boxes[order_[i]]);
      ++bin_count[b];
    }
    // Cost of splitting after bin s: area-weighted counts of both sides.
    Aabb right_box[kBins];
    int right_count[kBins] = {};
    Aabb acc;
    int n = 0;
    for (int b = kBins - 1; b > 0; --b) {
      acc.extend (bin_box[b]);
      n += bin_count[b];
      right_box[b] = acc;
      right_count[b] = n;
    }
    acc = Aabb();
    n = 0;
    for (int b = 0; b + 1 < kBins; ++b) {
      acc.extend (bin_box[b]);
      n += bin_count[b];
      if (n == 0 || right_count[b + 1] == 0)
        continue;
      const double cost = area (acc) * n + area (right_box[b + 1]) * right_count[b + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_split = b;
      }
    }
  }
  int mid = first + count / 2;
  if (best_axis >= 0) {
    const double lo = centres.min[best_axis], extent = centres.max[best_axis] - lo;
    const auto middle = std::stable_partition (
        order_.begin() + first, order_.begin() + first + count, [&] (int p) {
          return std::min (kBins - 1,
                           static_cast<int> (
                               kBins * (boxes[p].centre()[best_axis] - lo) / extent)) <=
                 best_split;
        });
    mid = static_cast<int> (middle - order_.begin());
  }
  else {
    int axis = 0;
    (centres.max - centres.min).maxCoeff (&axis);
    std::nth_element (order_.begin() + first,
                      order_.begin() + mid,
                      order_.begin() + first + count,
                      [&] (int a, int b) {
                        const double ca = boxes[a].centre()[axis],
                                     cb = boxes[b].centre()[axis];
                        return ca < cb || (ca == cb && a < b);
                      });
  }
  const int left = buildNode (first, mid - first, boxes);
  const int right = buildNode (mid, first + count - mid, boxes);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

bool
SceneGeometry::passesThrough (int primitive, std::uint64_t ray_key) const
{
  const double porosity = primitives_[primitive]->porosity;
  if (porosity <= 0.0)
    return false;
  RandomStream rng (
      hashCombine (ray_key, static_cast<std::uint64_t> (primitive) + 0x5eedULL));
  return rng.uniform() < porosity;
}

bool
SceneGeometry::intersect (const Ray& ray,
                          double t_max,
                          std::uint64_t ray_key,
                          RayHit& hit) const
{
  if (nodes_.empty())
    return false;
  const Vec3 inv = ray.direction.cwiseInverse();
  double best = t_max;
  bool found = false;
  // Each stack entry carries the distance at which the ray enters the node's box, so a
  // node farther than the best hit so far is skipped without testing its box again.
  struct Entry {
    int node;
    double t_enter;
  };
  Entry stack[128];
  int top = 0;
  {
    double t0 = 0.0, t1 = best;
    if (!nodes_[0].box.clip (ray.origin, inv, t0, t1))
      return false;
    stack[top++] = {0, t0};
  }
  while (top > 0) {
    const Entry entry = stack[--top];
    if (entry.t_enter > best)
      continue;
    const Node& node = nodes_[entry.node];
    if (node.left < 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        const int p = order_[k];
        double t;
        Vec3 n;
        if (primitives_[p]->intersect (ray, 0.0, best, t, n) &&
            !passesThrough (p, ray_key)) {
          best = t;
          hit.t = t;
          hit.normal = n;
          hit.primitive = p;
          found = true;
        }
      }
      continue;
    }
    // Push the farther child first so that the nearer one is visited first.
    double la0 = 0.0, la1 = best, ra0 = 0.0, ra1 = best;
    const bool hl = nodes_[node.left].box.clip (ray.origin, inv, la0, la1);
    const bool hr = nodes_[node.right].box.clip (ray.origin, inv, ra0, ra1);
    if (hl && hr) {
      if (la0 <= ra0) {
        stack[top++] = {node.right, ra0};
        stack[top++] = {node.left, la0};
      }
      else {
        stack[top++] = {node.left, la0};
        stack[top++] = {node.right, ra0};
      }
    }
    else if (hl)
      stack[top++] = {node.left, la0};
    else if (hr)
      stack[top++] = {node.right, ra0};
  }
  return found;
}

bool
SceneGeometry::intersectBruteForce (const Ray& ray,
                                    double t_max,
                                    std::uint64_t ray_key,
                                    RayHit& hit) const
{
  double best = t_max;
  bool found = false;
  for (std::size_t p = 0; p < primitives_.size(); ++p) {
    double t;
    Vec3 n;
    if (primitives_[p]->intersect (ray, 0.0, best, t, n) &&
        !passesThrough (static_cast<int> (p), ray_key)) {
      best = t;
      hit.t = t;
      hit.normal = n;
      hit.primitive = static_cast<int> (p);
      found = true;
    }
  }
  return found;
}

template <typename Visit>
void
SceneGeometry::visitCurvesNear (const Vec3& p,
                                std::uint32_t segment,
                                double max_distance,
                                Visit&& visit) const
{
  const auto it = curves_of_segment_.find (segment);
  if (it == curves_of_segment_.end())
    return;
  auto far = [&] (const Aabb& box) {
    return (p.array() < box.min.array() - max_distance).any() ||
           (p.array() > box.max.array() + max_distance).any();
  };
  for (const CurveChunk& chunk : it->second) {
    if (far (chunk.box))
      continue;
    for (const int c : chunk.curves) {
      if (far (curve_boxes_[c]))
        continue;
      const double d = curves_[c].distance (p);
      if (d <= max_distance)
        visit (curves_[c], d);
    }
  }
}

void
SceneGeometry::curveDistances (const Vec3& p,
                               std::uint32_t segment,
                               double max_distance,
                               double& crease,
                               double& border) const
{
  const double inf = std::numeric_limits<double>::infinity();
  crease = border = inf;
  visitCurvesNear (p, segment, max_distance, [&] (const GroundTruthCurve& c, double d) {
    if (c.kind == GroundTruthCurve::Kind::Crease)
      crease = std::min (crease, d);
    else
      border = std::min (border, d);
  });
}

void
SceneGeometry::creaseFacesNear (const Vec3& p,
                                std::uint32_t segment,
                                double max_distance,
                                std::vector<std::uint32_t>& others) const
{
  visitCurvesNear (p, segment, max_distance, [&] (const GroundTruthCurve& c, double) {
    if (c.kind == GroundTruthCurve::Kind::Crease)
      others.push_back (c.segment_a == segment ? c.segment_b : c.segment_a);
  });
}

PointClass
SceneGeometry::classify (const Vec3& p, std::uint32_t segment, double distance) const
{
  double crease, border;
  curveDistances (p, segment, distance, crease, border);
  if (crease <= distance && crease <= border)
    return PointClass::Edge;
  if (border <= distance)
    return PointClass::Boundary;
  return PointClass::Surface;
}
} // namespace simulation
} // namespace pcl_ext
