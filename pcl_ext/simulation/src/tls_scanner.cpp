/*
 * pcl_ext: a terrestrial laser scanner simulator.
 */
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/search/kdtree_3f.h>
#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/tls_scanner.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace pcl_ext
{
namespace simulation
{
namespace
{
constexpr double kDegToRad = 0.017453292519943295;
constexpr double kPi = 3.141592653589793;

struct ColumnTask
{
  int scanner;
  long column;  // azimuth index in [0, num_columns)
  long j_min, j_max;
};

std::uint64_t
rayKey (std::uint64_t scanner_key, long column, long row)
{
  const std::uint64_t packed = (static_cast<std::uint64_t> (column) << 32) |
                               static_cast<std::uint32_t> (row + (1L << 30));
  return hashCombine (scanner_key, packed);
}

std::uint8_t
toByte (double v)
{
  return static_cast<std::uint8_t> (std::clamp (std::lround (v), 0L, 255L));
}
}  // namespace

bool
TlsScanSimulation::checkParameters () const
{
  if (!(step_deg_ >= 1e-3 && step_deg_ <= 10.0))
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Angular step must be in [0.001, 10] degrees, got %g.\n",
               step_deg_);
    return false;
  }
  if (positions_.empty ())
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] No scan position set.\n");
    return false;
  }
  for (const auto& p : positions_)
    if (!p.allFinite ())
    {
      PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Scan position is not finite.\n");
      return false;
    }
  if (!(max_range_ > 0.0 && std::isfinite (max_range_)))
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Maximum range must be positive, got %g.\n",
               max_range_);
    return false;
  }
  if (!(noise_sigma_ >= 0.0 && std::isfinite (noise_sigma_) && noise_per_metre_ >= 0.0 &&
        std::isfinite (noise_per_metre_)))
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Range noise must be finite and >= 0, got %g + %g r.\n",
               noise_sigma_, noise_per_metre_);
    return false;
  }
  if (!(min_elevation_deg_ >= -90.0 && max_elevation_deg_ <= 90.0 &&
        min_elevation_deg_ < max_elevation_deg_))
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Elevation range must satisfy -90 <= min < max <= 90.\n");
    return false;
  }
  if (!(edge_distance_ >= 0.0 && std::isfinite (edge_distance_)))
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Edge distance must be finite and >= 0, got %g.\n",
               edge_distance_);
    return false;
  }
  if (!(max_incidence_deg_ > 0.0 && max_incidence_deg_ <= 90.0))
  {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Maximum incidence must be in (0, 90] degrees.\n");
    return false;
  }
  return true;
}

TlsScanSimulation::ColumnRange
TlsScanSimulation::columnRange (const Vec3& o, const Aabb& box, double step_rad,
                                long num_columns) const
{
  ColumnRange full{0, num_columns};
  const double margin = 1e-6;
  if (o.x () >= box.min.x () - margin && o.x () <= box.max.x () + margin &&
      o.y () >= box.min.y () - margin && o.y () <= box.max.y () + margin)
    return full;
  // The rectangle does not contain the scanner: its corners span less than 180 degrees.
  const double centre = std::atan2 (box.centre ().y () - o.y (), box.centre ().x () - o.x ());
  double lo = 0.0, hi = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    const double x = (k & 1) ? box.max.x () : box.min.x ();
    const double y = (k & 2) ? box.max.y () : box.min.y ();
    double rel = std::atan2 (y - o.y (), x - o.x ()) - centre;
    rel = std::remainder (rel, 2.0 * kPi);
    lo = std::min (lo, rel);
    hi = std::max (hi, rel);
  }
  double start = centre + lo;
  if (start < 0.0)
    start += 2.0 * kPi;
  ColumnRange range;
  range.first = static_cast<long> (std::floor (start / step_rad)) - 1;
  if (range.first < 0)
    range.first += num_columns;
  range.count = static_cast<long> (std::ceil ((hi - lo) / step_rad)) + 3;
  if (range.count >= num_columns)
    return full;
  return range;
}

void
TlsScanSimulation::elevationRange (const Vec3& o, const Aabb& box, double step_rad, long& j_min,
                                   long& j_max) const
{
  const double dx_near = std::max ({0.0, box.min.x () - o.x (), o.x () - box.max.x ()});
  const double dy_near = std::max ({0.0, box.min.y () - o.y (), o.y () - box.max.y ()});
  const double d_near = std::hypot (dx_near, dy_near);
  const double dx_far = std::max (std::abs (box.min.x () - o.x ()), std::abs (box.max.x () - o.x ()));
  const double dy_far = std::max (std::abs (box.min.y () - o.y ()), std::abs (box.max.y () - o.y ()));
  const double d_far = std::hypot (dx_far, dy_far);
  // Steepest angles are reached at the nearest horizontal distance, shallowest at the farthest.
  const double up = box.max.z () - o.z (), down = box.min.z () - o.z ();
  const double el_max = std::atan2 (up, up > 0.0 ? d_near : d_far);
  const double el_min = std::atan2 (down, down < 0.0 ? d_near : d_far);
  const double fov_min = min_elevation_deg_ * kDegToRad, fov_max = max_elevation_deg_ * kDegToRad;
  j_min = static_cast<long> (std::ceil (fov_min / step_rad - 1e-9));
  j_max = static_cast<long> (std::floor (fov_max / step_rad + 1e-9));
  j_min = std::max (j_min, static_cast<long> (std::floor (el_min / step_rad)) - 1);
  j_max = std::min (j_max, static_cast<long> (std::ceil (el_max / step_rad)) + 1);
}

template <typename Visitor> void
TlsScanSimulation::traceColumns (const SceneGeometry& geometry, double step_deg,
                                 Visitor&& visit) const
{
  const double step_rad = step_deg * kDegToRad;
  const long num_columns = static_cast<long> (std::floor (360.0 / step_deg + 1e-9));
  const Aabb box = geometry.bounds ();
  std::vector<ColumnTask> tasks;
  if (!box.empty ())
    for (std::size_t s = 0; s < positions_.size (); ++s)
    {
      long j_min, j_max;
      elevationRange (positions_[s], box, step_rad, j_min, j_max);
      if (j_min > j_max)
        continue;
      const ColumnRange range = columnRange (positions_[s], box, step_rad, num_columns);
      for (long k = 0; k < range.count; ++k)
        tasks.push_back ({static_cast<int> (s), (range.first + k) % num_columns, j_min, j_max});
    }
  const long num_tasks = static_cast<long> (tasks.size ());
  const double cos_max_incidence = std::cos (max_incidence_deg_ * kDegToRad);
  visit.begin (tasks.size ());
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount (threads_))
  for (long k = 0; k < num_tasks; ++k)
  {
    const ColumnTask& task = tasks[k];
    const Vec3& o = positions_[task.scanner];
    const std::uint64_t scanner_key =
        hashCombine (seed_, static_cast<std::uint64_t> (task.scanner));
    const double az = task.column * step_rad;
    const double ca = std::cos (az), sa = std::sin (az);
    for (long j = task.j_min; j <= task.j_max; ++j)
    {
      const double el = j * step_rad;
      const double ce = std::cos (el);
      Ray ray;
      ray.origin = o;
      ray.direction = Vec3 (ce * ca, ce * sa, std::sin (el));
      const std::uint64_t key = rayKey (scanner_key, task.column, j);
      RayHit hit;
      if (!geometry.intersect (ray, max_range_, key, hit))
        continue;
      const double cos_incidence = std::abs (ray.direction.dot (hit.normal));
      if (cos_incidence < cos_max_incidence)
        continue;
      visit (k, task.scanner, j, ray, hit, cos_incidence, key, step_rad);
    }
  }
  visit.end (tasks, num_columns);
}

namespace
{
struct CountVisitor
{
  std::vector<std::size_t> counts;
  void
  begin (std::size_t tasks)
  {
    counts.assign (tasks, 0);
  }
  void
  operator() (long task, int, long, const Ray&, const RayHit&, double, std::uint64_t, double)
  {
    ++counts[task];
  }
  void
  end (const std::vector<ColumnTask>&, long)
  {
  }
};
}  // namespace

std::size_t
TlsScanSimulation::countReturns (const SceneGeometry& geometry, double step_deg) const
{
  CountVisitor visitor;
  traceColumns (geometry, step_deg, visitor);
  std::size_t total = 0;
  for (const auto c : visitor.counts)
    total += c;
  return total;
}

double
TlsScanSimulation::stepForPointCount (const SceneGeometry& geometry, std::size_t points) const
{
  if (points == 0)
    return 0.0;
  // Returns grow as 1 / step^2: count at coarse steps, then scale.
  double step = 2.0;
  std::size_t n = 0;
  const double coarse_target = static_cast<double> (std::min<std::size_t> (points, 20000));
  for (int iteration = 0; iteration < 12; ++iteration)
  {
    n = countReturns (geometry, step);
    if (n == 0)
    {
      if (step < 1e-3)
        return 0.0;
      step /= 4.0;
      continue;
    }
    if (static_cast<double> (n) >= 0.5 * coarse_target)
      break;
    step *= std::max (0.25, std::sqrt (static_cast<double> (n) / coarse_target));
  }
  if (n == 0)
    return 0.0;
  // One refinement at up to 100,000 returns, where discretisation effects are small.
  const double fine_target = static_cast<double> (std::min<std::size_t> (points, 100000));
  step *= std::sqrt (static_cast<double> (n) / fine_target);
  n = countReturns (geometry, step);
  if (n == 0)
    return 0.0;
  return step * std::sqrt (static_cast<double> (n) / static_cast<double> (points));
}

namespace
{
struct ScanVisitor
{
  /** What the coverage test needs of a return: its row, its noise-free position and the
    * distance to the returns of the neighbouring rays on a continuous surface. */
  struct Return
  {
    long row;
    Vec3 truth;
    double range;
    double spacing;
    Eigen::Vector3f normal;  ///< unit surface normal at the true position
    bool porous;  ///< on a porous primitive (vegetation), not a continuous surface
  };

  const SceneGeometry& geometry;
  const Eigen::Isometry3d& transform;
  double noise_sigma, noise_per_metre, edge_distance;
  bool coverage_boundaries;
  bool connected_segments;
  long lowest_row;  ///< the lowest row of the field of view (the blind cone below it)
  unsigned int threads;
  std::vector<std::vector<SimulatedPoint, Eigen::aligned_allocator<SimulatedPoint>>> points;
  std::vector<std::vector<std::uint16_t>> scanners;
  std::vector<std::vector<Return>> returns;
  /** Surface id of every segment id after splitSegmentsIntoPieces (empty otherwise). */
  std::vector<std::uint32_t> surface_of_segment;

  void
  begin (std::size_t tasks)
  {
    points.resize (tasks);
    scanners.resize (tasks);
    returns.resize (tasks);
  }

  /** The return of row \a row in task \a task, or null (rows ascend within a task). */
  const Return*
  find (std::size_t task, long row) const
  {
    const auto& column = returns[task];
    const auto it = std::lower_bound (column.begin (), column.end (), row,
                                      [] (const Return& r, long j) { return r.row < j; });
    return it != column.end () && it->row == row ? &*it : nullptr;
  }

  /** All returns in one numbering, task after task, for the searches across tasks and
    * scanners. */
  struct ReturnIndex
  {
    std::vector<std::size_t> first;          ///< where each task's returns start; last: count
    std::vector<const Return*> of_point;
    std::vector<std::uint32_t> surface_of_point;  ///< segment id before any split into pieces
    std::vector<std::uint32_t> task_of_point;
    bool several_scanners = false;  ///< the tasks come from more than one scanner
    search::KdTree3f tree;  ///< over the true positions, when built
  };

  void
  buildReturnIndex (const std::vector<ColumnTask>& tasks, bool with_tree, ReturnIndex& index) const
  {
    for (std::size_t k = 1; k < tasks.size () && !index.several_scanners; ++k)
      index.several_scanners = tasks[k].scanner != tasks[0].scanner;
    with_tree = with_tree || index.several_scanners;
    index.first.assign (returns.size () + 1, 0);
    for (std::size_t k = 0; k < returns.size (); ++k)
      index.first[k + 1] = index.first[k] + returns[k].size ();
    const std::size_t n = index.first.back ();
    std::vector<float> xyz;
    if (with_tree)
      xyz.reserve (3 * n);
    index.of_point.reserve (n);
    index.surface_of_point.reserve (n);
    index.task_of_point.reserve (n);
    for (std::size_t k = 0; k < returns.size (); ++k)
      for (std::size_t i = 0; i < returns[k].size (); ++i)
      {
        const Vec3& t = returns[k][i].truth;
        if (with_tree)
          xyz.insert (xyz.end (), {static_cast<float> (t.x ()), static_cast<float> (t.y ()),
                                   static_cast<float> (t.z ())});
        index.of_point.push_back (&returns[k][i]);
        index.surface_of_point.push_back (points[k][i].segment);
        index.task_of_point.push_back (static_cast<std::uint32_t> (k));
      }
    if (with_tree && n > 0)
    {
      std::vector<pcl::index_t> ids (n);
      std::iota (ids.begin (), ids.end (), 0);
      index.tree.build (std::move (xyz), std::move (ids));
    }
  }

  /** After the last column: the coverage boundaries, then the pieces, over one index of all
    * returns (built before the pieces change any segment id). */
  void
  end (const std::vector<ColumnTask>& tasks, long num_columns)
  {
    // The tree serves the coverage boundaries and the links between scanners.
    ReturnIndex index;
    if (coverage_boundaries || connected_segments)
      buildReturnIndex (tasks, coverage_boundaries, index);
    if (coverage_boundaries)
      markCoverageBoundaries (tasks, num_columns, index);
    if (connected_segments)
      splitSegmentsIntoPieces (tasks, num_columns, index);
    decltype (returns) ().swap (returns);
  }

  /** The task of the column \a dk columns from task \a k's, same scanner, or -1. */
  static long
  adjacentTask (const std::vector<ColumnTask>& tasks, long num_columns, long k, long dk)
  {
    const long num_tasks = static_cast<long> (tasks.size ());
    // Columns of one scanner are consecutive tasks; a full turn wraps around.
    for (long m : {k + dk, k - dk * (num_columns - 1)})
      if (m >= 0 && m < num_tasks && tasks[m].scanner == tasks[k].scanner &&
          (tasks[m].column - tasks[k].column - dk) % num_columns == 0)
        return m;
    return -1;
  }

  /** Two returns lie on one continuous piece of surface when they are about a spacing apart;
    * a jump of more than 4 spacings is a discontinuity (a shadow, a gap, a silhouette). */
  static bool
  continuous (const Return& a, const Return& b)
  {
    return (a.truth - b.truth).norm () <= 4.0 * std::max (a.spacing, b.spacing);
  }

  /** Surface points where the scanned part of their surface ends become Boundary: a
    * neighbouring ray of the grid returned a point of a discontinuity, or points into the blind
    * cone. A neighbour on the same continuous surface lies about one spacing away (range * step
    * / cos incidence); a jump of more than 4 spacings is a discontinuity. Both sides of a jump
    * are marked: the far side is the edge of a shadow, the near side the occluding contour,
    * where a smooth surface turns away from the scanner (a pipe's or a column's silhouette) and
    * its data end as they do at a shadow. Where the near side ends at a curve of the scene (a
    * box's crease), the scene's own curves have already labelled it. A neighbouring ray that
    * returned nothing marks a border too: past a silhouette the rays meet the surface beyond
    * the maximum incidence angle, or miss it into the sky or beyond the maximum range; so
    * does the edge of the field of view. Not on porous surfaces (vegetation), whose gaps let
    * rays through.
    * A border of one scan is a border of the scanned part only where the returns of all
    * scanners leave the gap open: a point stays marked when the returns of its surface among
    * its 64 nearest, within 4 of its spacings (the continuity distance), leave an angle wider
    * than a right angle free around it in its tangent plane (pcl::BoundaryEstimation's
    * criterion). Another scanner that sees into the shadow, or past the silhouette, fills the
    * gap; so does the far side of a shadow narrower than the continuity distance. */
  void
  markCoverageBoundaries (const std::vector<ColumnTask>& tasks, long num_columns,
                          const ReturnIndex& index)
  {
    std::vector<std::vector<std::uint8_t>> scan_borders;
    if (findScanBorders (tasks, num_columns, scan_borders))
      markOpenBorders (scan_borders, index);
  }

  /** The borders of each scan by itself (see markCoverageBoundaries), per return; false when
    * there is none. */
  bool
  findScanBorders (const std::vector<ColumnTask>& tasks, long num_columns,
                   std::vector<std::vector<std::uint8_t>>& scan_borders) const
  {
    const long num_tasks = static_cast<long> (tasks.size ());
    scan_borders.assign (tasks.size (), {});
    for (long k = 0; k < num_tasks; ++k)
      scan_borders[k].assign (returns[k].size (), 0);
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount (threads))
    for (long k = 0; k < num_tasks; ++k)
    {
      const long left = adjacentTask (tasks, num_columns, k, -1),
                 right = adjacentTask (tasks, num_columns, k, 1);
      for (std::size_t i = 0; i < returns[k].size (); ++i)
      {
        if (points[k][i].point_class != static_cast<std::uint32_t> (PointClass::Surface))
          continue;
        const Return& r = returns[k][i];
        bool border = r.row - 1 < lowest_row;
        // A porous surface (vegetation) lets rays through its gaps: a missing return there
        // is no border of what was scanned.
        const auto check = [&] (const Return* n) {
          border = border || (n ? !continuous (*n, r) : !r.porous);
        };
        check (find (static_cast<std::size_t> (k), r.row - 1));
        check (find (static_cast<std::size_t> (k), r.row + 1));
        check (left < 0 ? nullptr : find (static_cast<std::size_t> (left), r.row));
        check (right < 0 ? nullptr : find (static_cast<std::size_t> (right), r.row));
        scan_borders[k][i] = border;
      }
    }
    for (const auto& column : scan_borders)
      if (std::find (column.begin (), column.end (), 1) != column.end ())
        return true;
    return false;
  }

  /** Widest angle around \a r, in its tangent plane, free of the \a found returns of its own
    * \a surface (2 pi when there are none). */
  static double
  widestFreeAngle (const Return& r, std::uint32_t surface, const pcl::Indices& found,
                   const ReturnIndex& index, std::vector<double>& angles)
  {
    const Vec3 n = r.normal.cast<double> ();
    const Vec3 u = n.unitOrthogonal (), v = n.cross (u);
    angles.clear ();
    for (const auto g : found)
    {
      const Vec3 d = index.of_point[g]->truth - r.truth;
      if (index.surface_of_point[g] != surface || d.squaredNorm () == 0.0)
        continue;
      angles.push_back (std::atan2 (d.dot (v), d.dot (u)));
    }
    if (angles.empty ())
      return 2.0 * M_PI;
    std::sort (angles.begin (), angles.end ());
    double widest = angles.front () + 2.0 * M_PI - angles.back ();
    for (std::size_t a = 1; a < angles.size (); ++a)
      widest = std::max (widest, angles[a] - angles[a - 1]);
    return widest;
  }

  /** Mark as Boundary the scan borders that the returns of all scanners leave open (see
    * markCoverageBoundaries). */
  void
  markOpenBorders (const std::vector<std::vector<std::uint8_t>>& scan_borders,
                   const ReturnIndex& index)
  {
    const long num_tasks = static_cast<long> (returns.size ());
    // At most this many of the nearest returns: enough to surround a point twice over, and
    // a bound on the work where the spacing is long (grazing incidence).
    constexpr std::size_t kMaxNeighbours = 64;
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount (threads))
    for (long k = 0; k < num_tasks; ++k)
    {
      pcl::Indices found (kMaxNeighbours);
      std::vector<float> sqr (kMaxNeighbours);
      std::vector<double> angles;
      for (std::size_t i = 0; i < returns[k].size (); ++i)
      {
        if (!scan_borders[k][i])
          continue;
        const Return& r = returns[k][i];
        const float query[3] = {static_cast<float> (r.truth.x ()), static_cast<float> (r.truth.y ()),
                                static_cast<float> (r.truth.z ())};
        found.resize (kMaxNeighbours);
        found.resize (
            index.tree.nearestKSearch (query, kMaxNeighbours, found.data (), sqr.data ()));
        const float reach = static_cast<float> (4.0 * r.spacing);
        std::size_t within = 0;
        while (within < found.size () && sqr[within] <= reach * reach)
          ++within;
        found.resize (within);
        if (widestFreeAngle (r, points[k][i].segment, found, index, angles) > 0.5 * M_PI)
          points[k][i].point_class = static_cast<std::uint32_t> (PointClass::Boundary);
      }
    }
  }

  /** Split-off pieces smaller than this keep their surface's id. */
  static constexpr std::uint32_t kMinPiecePoints = 10;

  /** Give every connected visible piece of a surface its own segment id (see
    * TlsScanSimulation::setConnectedSegments). Two returns of one surface are linked when
    * - they come from adjacent rays of one scanner (one step in azimuth or elevation) and are
    *   continuous (within 4 spacings, the test of the coverage boundaries), or
    * - they come from different scanners and lie within the spacing of both (where two scans
    *   overlap, every return of one lies inside a grid cell of the other, so within about
    *   0.7 spacing of one of its returns; two pieces that only face each other across a gap
    *   wider than the local spacing, e.g. the two sides of a wall cutting a ceiling, are not).
    * The pieces are the connected components of the links. The largest piece of a surface
    * keeps its id; the others get new ids, above every surface id of the scan, in the order of
    * (surface id, first point), except pieces of fewer than kMinPiecePoints returns (a few rays
    * through a gap, a face seen edge-on), which keep the surface's id. Porous surfaces
    * (vegetation) are scattered returns, not a continuous surface, and are not split. Points
    * are numbered in output order, so the result does not depend on the thread count. */
  void
  splitSegmentsIntoPieces (const std::vector<ColumnTask>& tasks, long num_columns,
                           const ReturnIndex& index)
  {
    const long num_tasks = static_cast<long> (tasks.size ());
    const std::vector<std::size_t>& first = index.first;
    const std::size_t n = first.back ();
    if (n == 0)
      return;

    // Links, collected per task in parallel, united in task order.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> links (tasks.size ());
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount (threads))
    for (long k = 0; k < num_tasks; ++k)
    {
      const long right = adjacentTask (tasks, num_columns, k, 1);
      for (std::size_t i = 0; i < returns[k].size (); ++i)
      {
        const Return& r = returns[k][i];
        const std::uint32_t segment = points[k][i].segment;
        const auto link = [&] (long m, long row) {
          if (m < 0)
            return;
          const Return* other = find (static_cast<std::size_t> (m), row);
          if (!other)
            return;
          const std::size_t j = static_cast<std::size_t> (other - returns[m].data ());
          if (points[m][j].segment == segment && continuous (r, *other))
            links[k].emplace_back (static_cast<std::uint32_t> (first[k] + i),
                                   static_cast<std::uint32_t> (first[m] + j));
        };
        link (k, r.row + 1);
        link (right, r.row);
      }
    }

    // Returns of different scanners within both spacings.
    if (index.several_scanners)
    {
      const auto& of_point = index.of_point;
      const auto& surface_of_point = index.surface_of_point;
      const auto& task_of_point = index.task_of_point;
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount (threads))
      for (long k = 0; k < num_tasks; ++k)
      {
        pcl::Indices found;
        std::vector<float> sqr;
        for (std::size_t i = 0; i < returns[k].size (); ++i)
        {
          const std::size_t p = first[k] + i;
          const Return& r = returns[k][i];
          const float query[3] = {static_cast<float> (r.truth.x ()),
                                  static_cast<float> (r.truth.y ()),
                                  static_cast<float> (r.truth.z ())};
          index.tree.radiusSearch (query, r.spacing, found, sqr, 0, false);
          for (std::size_t f = 0; f < found.size (); ++f)
          {
            const auto q = static_cast<std::size_t> (found[f]);
            if (q <= p || surface_of_point[q] != surface_of_point[p] ||
                tasks[task_of_point[q]].scanner == tasks[k].scanner)
              continue;
            const double d = (of_point[q]->truth - r.truth).norm ();
            if (d <= r.spacing && d <= of_point[q]->spacing)
              links[k].emplace_back (static_cast<std::uint32_t> (p),
                                     static_cast<std::uint32_t> (q));
          }
        }
      }
    }

    std::vector<std::uint32_t> parent (n);
    std::iota (parent.begin (), parent.end (), 0u);
    const auto root = [&parent] (std::uint32_t x) {
      while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
      return x;
    };
    for (const auto& task_links : links)
      for (const auto& [a, b] : task_links)
      {
        const std::uint32_t ra = root (a), rb = root (b);
        if (ra != rb)
          parent[std::max (ra, rb)] = std::min (ra, rb);
      }
    decltype (links) ().swap (links);

    // Pieces by root (the smallest point of the piece), sizes, and the largest of each surface.
    std::vector<std::uint32_t> segment (n), size (n, 0);
    std::uint32_t highest = 0;
    for (long k = 0; k < num_tasks; ++k)
      for (std::size_t i = 0; i < returns[k].size (); ++i)
      {
        segment[first[k] + i] = points[k][i].segment;
        highest = std::max (highest, points[k][i].segment);
      }
    for (std::uint32_t p = 0; p < n; ++p)
      ++size[root (p)];
    std::map<std::uint32_t, std::uint32_t> largest;  // surface -> root of its largest piece
    std::map<std::uint32_t, bool> porous;
    for (long k = 0; k < num_tasks; ++k)
      for (const Return& r : returns[k])
        if (r.porous)
          porous[segment[first[k] + (&r - returns[k].data ())]] = true;
    for (std::uint32_t p = 0; p < n; ++p)
      if (root (p) == p)
      {
        const auto it = largest.find (segment[p]);
        if (it == largest.end () || size[p] > size[it->second])
          largest[segment[p]] = p;  // roots ascend: ties keep the first piece
      }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> others;  // (surface, root)
    std::vector<std::uint32_t> id (n, 0);
    for (std::uint32_t p = 0; p < n; ++p)
      if (root (p) == p)
      {
        if (largest[segment[p]] == p || size[p] < kMinPiecePoints || porous.count (segment[p]))
          id[p] = segment[p];
        else
          others.emplace_back (segment[p], p);
      }
    std::sort (others.begin (), others.end ());
    surface_of_segment.assign (highest + 1 + others.size (), 0);
    for (std::uint32_t s = 1; s <= highest; ++s)
      surface_of_segment[s] = s;
    for (std::size_t o = 0; o < others.size (); ++o)
    {
      id[others[o].second] = highest + 1 + static_cast<std::uint32_t> (o);
      surface_of_segment[highest + 1 + o] = others[o].first;
    }
    for (long k = 0; k < num_tasks; ++k)
      for (std::size_t i = 0; i < returns[k].size (); ++i)
        points[k][i].segment = id[root (static_cast<std::uint32_t> (first[k] + i))];
  }

  void
  operator() (long task, int scanner, long row, const Ray& ray, const RayHit& hit,
              double cos_incidence, std::uint64_t key, double step_rad)
  {
    const Primitive& primitive = *geometry.primitives ()[hit.primitive];
    const Vec3 truth = ray.origin + hit.t * ray.direction;
    const SurfaceInfo& info = primitive.infoAt (truth);
    RandomStream rng (key);
    double noise = (noise_sigma + noise_per_metre * hit.t) * rng.gaussian ();
    if (primitive.roughness > 0.0)
      noise += primitive.roughness * rng.gaussian ();
    const Vec3 measured = transform * (ray.origin + (hit.t + noise) * ray.direction);
    const double distance = edge_distance > 0.0 ? edge_distance : hit.t * step_rad;

    SimulatedPoint p;
    p.x = static_cast<float> (measured.x ());
    p.y = static_cast<float> (measured.y ());
    p.z = static_cast<float> (measured.z ());
    p.data[3] = 1.0f;
    p.rgba = 0;
    const Material& m = info.material;
    p.r = toByte (m.rgb[0] + m.rgb_jitter * rng.gaussian ());
    p.g = toByte (m.rgb[1] + m.rgb_jitter * rng.gaussian ());
    p.b = toByte (m.rgb[2] + m.rgb_jitter * rng.gaussian ());
    p.a = 255;
    p.intensity = static_cast<float> (std::clamp (
        m.reflectance * (0.2 + 0.8 * cos_incidence) + m.intensity_jitter * rng.gaussian (), 0.0,
        1.0));
    p.segment = info.segment;
    p.object = info.object;
    p.label = info.label;
    p.point_class = static_cast<std::uint32_t> (geometry.classify (truth, info.segment, distance));
    points[task].push_back (p);
    scanners[task].push_back (static_cast<std::uint16_t> (scanner));
    if (coverage_boundaries || connected_segments)
      returns[task].push_back (
          {row, truth, hit.t, hit.t * step_rad / std::max (cos_incidence, 0.05),
           hit.normal.cast<float> (), primitive.porosity > 0.0});
  }
};
}  // namespace

bool
TlsScanSimulation::scan (const SceneGeometry& geometry, pcl::PointCloud<SimulatedPoint>& cloud,
                         std::vector<std::uint16_t>* scanner_of_point,
                         std::vector<std::uint32_t>* surface_of_segment) const
{
  cloud.clear ();
  if (scanner_of_point)
    scanner_of_point->clear ();
  if (surface_of_segment)
    surface_of_segment->clear ();
  if (!checkParameters ())
    return false;
  ScanVisitor visitor{geometry, output_transform_, noise_sigma_, noise_per_metre_,
                      edge_distance_, coverage_boundaries_, connected_segments_,
                      static_cast<long> (std::ceil (min_elevation_deg_ / step_deg_ - 1e-9)),
                      threads_, {}, {}, {}, {}};
  traceColumns (geometry, step_deg_, visitor);
  std::size_t total = 0;
  for (const auto& column : visitor.points)
    total += column.size ();
  cloud.reserve (total);
  if (scanner_of_point)
    scanner_of_point->reserve (total);
  for (std::size_t k = 0; k < visitor.points.size (); ++k)
  {
    cloud.insert (cloud.end (), visitor.points[k].begin (), visitor.points[k].end ());
    if (scanner_of_point)
      scanner_of_point->insert (scanner_of_point->end (), visitor.scanners[k].begin (),
                                visitor.scanners[k].end ());
    // Free each column as it is copied: large scans would otherwise need twice the memory.
    decltype (visitor.points)::value_type ().swap (visitor.points[k]);
  }
  if (surface_of_segment)
  {
    if (connected_segments_)
      surface_of_segment->swap (visitor.surface_of_segment);
    else
    {
      std::uint32_t highest = 0;
      for (const auto& p : cloud)
        highest = std::max (highest, p.segment);
      surface_of_segment->resize (cloud.empty () ? 0 : highest + 1);
      std::iota (surface_of_segment->begin (), surface_of_segment->end (), 0u);
    }
  }
  cloud.width = static_cast<std::uint32_t> (cloud.size ());
  cloud.height = 1;
  cloud.is_dense = true;
  return true;
}
}  // namespace simulation
}  // namespace pcl_ext
