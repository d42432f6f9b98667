/*
 * pcl_ext: joining the segments of one cylinder, on plain coordinates.
 */
#include <pcl_ext/segmentation/cylinder_join.h>

#include <pcl_ext/common/random.h>
#include <pcl_ext/common/union_find.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace pcl_ext {
namespace cylinder_join {
namespace {
/** Distance of \a q from the axis of \a c. */
double
offAxis (const Eigen::Vector3d& q, const cylinders::Cylinder& c)
{
  const Eigen::Vector3d w = q - c.point;
  return (w - w.dot (c.axis) * c.axis).norm();
}

/** The end of \a c facing \a target along its axis. */
Eigen::Vector3d
facingEnd (const cylinders::Cylinder& c, const Eigen::Vector3d& target)
{
  const double side = (target - c.point).dot (c.axis) >= 0.0 ? 1.0 : -1.0;
  return c.point + side * c.half_length * c.axis;
}

/** A seed per segment, so that each segment's draws do not depend on the others'. */
std::uint64_t
segmentSeed (std::uint64_t seed, std::size_t segment)
{
  return splitMix64 (seed + 0x9E3779B97F4A7C15ull * segment);
}

/** The coordinates of the inliers of \a run's pieces: \a subset all of them, segment by
 * segment in ascending order and by index within a segment (the order of their
 * positions when the segments lie one after the other), \a own those of each piece of
 * the run in turn; each segment loaded once. \return false when the source fails */
bool
gatherRunInliers (const SegmentSource& source,
                  const std::vector<Piece>& pieces,
                  const std::vector<std::uint32_t>& run,
                  std::vector<Eigen::Vector3d>& subset,
                  std::vector<std::vector<Eigen::Vector3d>>& own)
{
  subset.clear();
  own.assign (run.size(), {});
  std::map<std::uint32_t, std::vector<std::size_t>> by_segment; // segment -> in run
  for (std::size_t r = 0; r < run.size(); ++r)
    by_segment[pieces[run[r]].segment].push_back (r);
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> inliers;
  for (const auto& [segment, held] : by_segment) {
    if (!source.load (segment, points))
      return false;
    inliers.clear();
    for (const auto r : held) {
      const auto& piece_inliers = pieces[run[r]].cylinder.inliers;
      inliers.insert (inliers.end(), piece_inliers.begin(), piece_inliers.end());
      for (const auto i : piece_inliers)
        own[r].push_back (points[i]);
    }
    std::sort (inliers.begin(), inliers.end());
    for (const auto i : inliers)
      subset.push_back (points[i]);
  }
  return true;
}

/** Refits each straight run (pieces joined as continuations along one axis, not
 * through an elbow) as one cylinder, or cone, over all its pieces' inliers, and gives
 * each piece the run's axis, radius and taper over its own extent. A piece alone is
 * often a short strip seen from one side (the underside of a pipe next to a support),
 * whose radius its own points fix poorly: the narrower the arc, the more the radius
 * trades against the axis's position. All the run's points fix it. A run whose fit
 * degenerates or leaves the radius or taper range keeps its pieces' own fits. \return
 * false when the source fails */
bool
refitStraightRuns (const SegmentSource& source,
                   const JoinParameters& p,
                   UnionFind& runs,
                   std::vector<Piece>& pieces)
{
  const std::size_t n = pieces.size();
  std::map<std::uint32_t, std::vector<std::uint32_t>> members; // root -> pieces
  for (std::uint32_t k = 0; k < n; ++k)
    members[runs.find (k)].push_back (k);
  std::vector<Eigen::Vector3d> subset;
  std::vector<std::vector<Eigen::Vector3d>> own;
  std::vector<std::uint32_t> all;
  for (const auto& [root, run] : members) {
    if (run.size() < 2)
      continue;
    // Started from the piece with most inliers, the best fitted alone.
    std::uint32_t largest = run.front();
    for (const auto k : run)
      if (pieces[k].cylinder.inliers.size() > pieces[largest].cylinder.inliers.size())
        largest = k;
    if (!gatherRunInliers (source, pieces, run, subset, own))
      return false;
    all.resize (subset.size());
    std::iota (all.begin(), all.end(), 0u);
    const cylinders::Cylinder& start = pieces[largest].cylinder;
    Eigen::Vector3d point = start.point, axis = start.axis;
    const bool cone = p.detection.max_taper > 0.0;
    double radius = start.radius, taper = cone ? start.taper : 0.0;
    if (!cylinders::refineCylinder (
            subset, all, point, axis, radius, cone ? &taper : nullptr) ||
        radius < p.detection.min_radius || radius > p.detection.max_radius ||
        std::abs (taper) > p.detection.max_taper)
      continue;
    for (std::size_t r = 0; r < run.size(); ++r) {
      cylinders::Cylinder& c = pieces[run[r]].cylinder;
      double t_min = std::numeric_limits<double>::infinity(), t_max = -t_min;
      for (const auto& q : own[r]) {
        const double t = (q - point).dot (axis);
        t_min = std::min (t_min, t);
        t_max = std::max (t_max, t);
      }
      const double middle = 0.5 * (t_min + t_max);
      c.point = point + middle * axis;
      c.axis = axis;
      c.radius = radius + taper * middle;
      c.taper = taper;
      c.half_length = 0.5 * (t_max - t_min);
    }
  }
  return true;
}

/** The segments of joinCylinderSegments, held in memory: each segment's positions in
 * \a xyz. */
class HeldSegments : public SegmentSource {
public:
  HeldSegments (const std::vector<Eigen::Vector3d>& xyz,
                const std::vector<std::vector<std::uint32_t>>& members)
  : xyz_ (xyz), members_ (members)
  {}

  std::size_t
  size () const override
  {
    return members_.size();
  }

  std::size_t
  pointCount (std::size_t s) const override
  {
    return members_[s].size();
  }

  bool
  load (std::size_t s, std::vector<Eigen::Vector3d>& points) const override
  {
    points.resize (members_[s].size());
    for (std::size_t k = 0; k < points.size(); ++k)
      points[k] = xyz_[members_[s][k]];
    return true;
  }

private:
  const std::vector<Eigen::Vector3d>& xyz_;
  const std::vector<std::vector<std::uint32_t>>& members_;
};
} // namespace

bool
validParameters (const JoinParameters& p)
{
  const auto finite_non_negative = [] (double x) {
    return x >= 0.0 && std::isfinite (x);
  };
  return cylinders::validParameters (p.detection) && finite_non_negative (p.max_gap) &&
         finite_non_negative (p.max_axis_angle) && p.max_axis_angle < M_PI / 2 &&
         p.min_elbow_angle > p.max_axis_angle && p.min_elbow_angle <= M_PI / 2 &&
         finite_non_negative (p.max_radius_difference) &&
         p.max_radius_difference < 1.0 && finite_non_negative (p.max_axis_offset) &&
         finite_non_negative (p.whole_segment_fraction) &&
         p.whole_segment_fraction <= 1.0 && finite_non_negative (p.absorb_fraction) &&
         p.absorb_fraction <= 1.0 && p.threads >= 1;
}

bool
continues (const cylinders::Cylinder& a,
           const cylinders::Cylinder& b,
           const JoinParameters& p)
{
  // Radii compared where the two face each other (they differ along a cone).
  const Eigen::Vector3d a_end = facingEnd (a, b.point), b_end = facingEnd (b, a.point);
  const double ra = a.radius + a.taper * (a_end - a.point).dot (a.axis);
  const double rb = b.radius + b.taper * (b_end - b.point).dot (b.axis);
  const double r = std::max (ra, rb);
  if (std::abs (ra - rb) > p.max_radius_difference * r)
    return false;
  const double lateral = p.max_axis_offset * r + p.detection.distance_tolerance;
  const double cosine = std::abs (a.axis.dot (b.axis));
  if (cosine >= std::cos (p.max_axis_angle)) {
    // One straight run: the axis of each passes through the other's facing end (axes
    // fitted to short pieces tilt a little, so they are not extrapolated past the gap).
    if (offAxis (b_end, a) > lateral || offAxis (a_end, b) > lateral)
      return false;
    const double gap =
        std::abs ((b.point - a.point).dot (a.axis)) - a.half_length - b.half_length;
    return gap <= p.max_gap;
  }
  if (cosine > std::cos (p.min_elbow_angle))
    return false;
  // An elbow: the axes (nearly) meet, beyond or at the end of each leg and not farther
  // from it than the longest gap (the bend lies between).
  const Eigen::Vector3d w = a.point - b.point;
  const double ab = a.axis.dot (b.axis), aw = a.axis.dot (w), bw = b.axis.dot (w);
  const double denominator = 1.0 - ab * ab;
  const double s = (ab * bw - aw) / denominator, t = (bw - ab * aw) / denominator;
  if (((a.point + s * a.axis) - (b.point + t * b.axis)).norm() > lateral)
    return false;
  const double beyond_a = std::abs (s) - a.half_length,
               beyond_b = std::abs (t) - b.half_length;
  return beyond_a > -r && beyond_a <= p.max_gap && beyond_b > -r &&
         beyond_b <= p.max_gap;
}

bool
joinSegments (const SegmentSource& source, const JoinParameters& p, SegmentJoin& result)
{
  result = SegmentJoin();
  if (!validParameters (p))
    return false;
  const std::size_t segment_count = source.size();
  if (segment_count >= kNoSegment / 2)
    return false;

  // The cylinders of each segment, in its slot: deterministic for any number of
  // threads.
  std::vector<std::vector<cylinders::Cylinder>> found (segment_count);
  bool loaded = true;
#pragma omp parallel num_threads(static_cast <int> (p.threads))
  {
    std::vector<Eigen::Vector3d> points;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t s = 0; s < static_cast<std::ptrdiff_t> (segment_count); ++s) {
      if (source.pointCount (s) < p.detection.min_points)
        continue;
      if (!source.load (s, points)) {
#pragma omp atomic write
        loaded = false;
        continue;
      }
      cylinders::DetectionParameters detection = p.detection;
      detection.seed = segmentSeed (p.detection.seed, static_cast<std::size_t> (s));
      cylinders::detectCylinders (points, detection, found[s]);
    }
  }
  if (!loaded)
    return false;
  for (std::uint32_t s = 0; s < segment_count; ++s)
    for (auto& cylinder : found[s]) {
      Piece piece;
      piece.segment = s;
      piece.cylinder = std::move (cylinder);
      result.pieces.push_back (std::move (piece));
    }
  found.clear();

  // Groups of pieces that continue one another, and within them the straight runs
  // (pieces joined along one axis), each refitted as one cylinder.
  std::vector<Piece>& pieces = result.pieces;
  const std::size_t n = pieces.size();
  const double parallel = std::cos (p.max_axis_angle);
  UnionFind sets (n), runs (n);
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b) {
      const cylinders::Cylinder &ca = pieces[a].cylinder, &cb = pieces[b].cylinder;
      if (!continues (ca, cb, p))
        continue;
      sets.unite (a, b);
      if (std::abs (ca.axis.dot (cb.axis)) >= parallel)
        runs.unite (a, b);
    }
  if (!refitStraightRuns (source, p, runs, pieces))
    return false;
  std::vector<std::uint32_t> root_of (n), group_size (n, 0);
  for (std::uint32_t k = 0; k < n; ++k)
    ++group_size[root_of[k] = sets.find (k)];

  // Which joined groups each segment holds pieces of, and how much of it each covers.
  std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>>
      cover; // segment -> root -> points
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t root = root_of[k];
    if (group_size[root] >= 2)
      cover[pieces[k].segment][root] += pieces[k].cylinder.inliers.size();
  }
  std::uint32_t next = static_cast<std::uint32_t> (segment_count);
  std::vector<std::uint32_t> label_of_root (n, kNoSegment);
  result.whole.assign (segment_count, kNoSegment);
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t root = root_of[k];
    if (group_size[root] < 2)
      continue;
    if (label_of_root[root] == kNoSegment)
      label_of_root[root] = next++;
    const std::uint32_t label = label_of_root[root];
    pieces[k].joined = label;
    const auto& held = cover[pieces[k].segment];
    if (held.size() == 1 &&
        static_cast<double> (held.begin()->second) >=
            p.whole_segment_fraction * source.pointCount (pieces[k].segment))
      result.whole[pieces[k].segment] = label;
  }
  result.labels = next;

  // Segments without a piece of their own that lie on a joined group's surface, between
  // or next to its pieces (the fragments a segmenter leaves where a branch leaves a
  // trunk): they join the group whole when most of their points are on it.
  std::vector<std::uint32_t> joined_pieces;
  for (std::uint32_t k = 0; k < n; ++k)
    if (group_size[root_of[k]] >= 2)
      joined_pieces.push_back (k);
  if (p.absorb_fraction <= 0.0 || joined_pieces.empty())
    return true;
  const double tol = p.detection.distance_tolerance;
#pragma omp parallel num_threads(static_cast <int> (p.threads))
  {
    std::vector<Eigen::Vector3d> points;
    std::vector<std::size_t> on;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t s = 0; s < static_cast<std::ptrdiff_t> (segment_count); ++s) {
      const std::size_t size = source.pointCount (s);
      if (cover.count (static_cast<std::uint32_t> (s)) || size == 0)
        continue;
      if (!source.load (s, points)) {
#pragma omp atomic write
        loaded = false;
        continue;
      }
      on.assign (n, 0);
      for (const auto& q : points)
        for (const auto k : joined_pieces) {
          const cylinders::Cylinder& c = pieces[k].cylinder;
          const Eigen::Vector3d w = q - c.point;
          const double t = w.dot (c.axis);
          if (std::abs (t) > c.half_length + p.max_gap)
            continue;
          if (std::abs ((w - t * c.axis).norm() - (c.radius + c.taper * t)) <= tol) {
            ++on[root_of[k]];
            break;
          }
        }
      const auto most = std::max_element (on.begin(), on.end());
      if (static_cast<double> (*most) >= p.absorb_fraction * size)
        result.whole[s] = label_of_root[most - on.begin()];
    }
  }
  return loaded;
}

bool
joinCylinderSegments (const std::vector<Eigen::Vector3d>& xyz,
                      const std::vector<std::vector<std::uint32_t>>& segments,
                      const JoinParameters& p,
                      JoinResult& result)
{
  result = JoinResult();
  if (!validParameters (p))
    return false;
  for (const auto& segment : segments)
    for (const auto i : segment)
      if (i >= xyz.size())
        return false;
  result.labels.assign (xyz.size(), kNoSegment);
  for (std::uint32_t s = 0; s < segments.size(); ++s)
    for (const auto i : segments[s])
      if (result.labels[i] == kNoSegment)
        result.labels[i] = s;
  // Each segment's own points (a position listed twice belongs to its first segment).
  std::vector<std::vector<std::uint32_t>> members (segments.size());
  for (std::uint32_t i = 0; i < xyz.size(); ++i)
    if (result.labels[i] != kNoSegment)
      members[result.labels[i]].push_back (i);

  SegmentJoin join;
  if (!joinSegments (HeldSegments (xyz, members), p, join))
    return false;
  for (std::uint32_t s = 0; s < segments.size(); ++s)
    if (join.whole[s] != kNoSegment)
      for (const auto i : members[s])
        result.labels[i] = join.whole[s];
  for (auto& piece : join.pieces) {
    for (auto& i : piece.cylinder.inliers)
      i = members[piece.segment][i];
    if (piece.joined != kNoSegment && join.whole[piece.segment] == kNoSegment)
      for (const auto i : piece.cylinder.inliers)
        result.labels[i] = piece.joined;
  }

  // Consecutive labels: the input segments that kept points, then the joined groups.
  std::vector<std::uint32_t> compact (join.labels, kNoSegment);
  std::uint32_t count = 0;
  for (auto& label : result.labels)
    if (label != kNoSegment) {
      if (compact[label] == kNoSegment)
        compact[label] = count++;
      label = compact[label];
    }
  result.num_segments = count;
  for (auto& piece : join.pieces)
    if (piece.joined != kNoSegment)
      piece.joined = compact[piece.joined];
  result.pieces = std::move (join.pieces);
  return true;
}
} // namespace cylinder_join
} // namespace pcl_ext
