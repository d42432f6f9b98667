/*
 * pcl_ext: a terrestrial laser scanner simulator: the rays and the points they return.
 * The passes over all returns are in coverage_boundaries.cpp and connected_pieces.cpp.
 */
#include "connected_pieces.h"
#include "coverage_boundaries.h"
#include "one_sided_creases.h"
#include "scan_grid.h"

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/simulation/random.h>
#include <pcl_ext/simulation/tls_scanner.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcl_ext {
namespace simulation {
namespace {
constexpr double kDegToRad = 0.017453292519943295;
constexpr double kPi = 3.141592653589793;

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
} // namespace

bool
TlsScanSimulation::checkParameters() const
{
  if (!(step_deg_ >= 1e-3 && step_deg_ <= 10.0)) {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Angular step must be in [0.001, 10] "
               "degrees, "
               "got %g.\n",
               step_deg_);
    return false;
  }
  if (positions_.empty()) {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] No scan position set.\n");
    return false;
  }
  for (const auto& p : positions_)
    if (!p.allFinite()) {
      PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Scan position is not finite.\n");
      return false;
    }
  if (!(max_range_ > 0.0 && std::isfinite (max_range_))) {
    PCL_ERROR (
        "[pcl_ext::TlsScanSimulation::scan] Maximum range must be positive, got %g.\n",
        max_range_);
    return false;
  }
  if (!(noise_sigma_ >= 0.0 && std::isfinite (noise_sigma_) &&
        noise_per_metre_ >= 0.0 && std::isfinite (noise_per_metre_))) {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Range noise must be finite and >= "
               "0, got %g + "
               "%g r.\n",
               noise_sigma_,
               noise_per_metre_);
    return false;
  }
  if (!(min_elevation_deg_ >= -90.0 && max_elevation_deg_ <= 90.0 &&
        min_elevation_deg_ < max_elevation_deg_)) {
    PCL_ERROR ("[pcl_ext::TlsScanSimulation::scan] Elevation range must satisfy -90 <= "
               "min < max "
               "<= 90.\n");
    return false;
  }
  if (!(edge_distance_ >= 0.0 && std::isfinite (edge_distance_))) {
    PCL_ERROR (
        "[pcl_ext::TlsScanSimulation::scan] Edge distance must be finite and >= 0, got "
        "%g.\n",
        edge_distance_);
    return false;
  }
  if (!(max_incidence_deg_ > 0.0 && max_incidence_deg_ <= 90.0)) {
    PCL_ERROR (
        "[pcl_ext::TlsScanSimulation::scan] Maximum incidence must be in (0, 90] "
        "degrees.\n");
    return false;
  }
  return true;
}

TlsScanSimulation::ColumnRange
TlsScanSimulation::columnRange (const Vec3& o,
                                const Aabb& box,
                                double step_rad,
                                long num_columns) const
{
  ColumnRange full{0, num_columns};
  const double margin = 1e-6;
  if (o.x() >= box.min.x() - margin && o.x() <= box.max.x() + margin &&
      o.y() >= box.min.y() - margin && o.y() <= box.max.y() + margin)
    return full;
  // The rectangle does not contain the scanner: its corners span less than 180 degrees.
  const double centre = std::atan2 (box.centre().y() - o.y(), box.centre().x() - o.x());
  double lo = 0.0, hi = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double x = (k & 1) ? box.max.x() : box.min.x();
    const double y = (k & 2) ? box.max.y() : box.min.y();
    double rel = std::atan2 (y - o.y(), x - o.x()) - centre;
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
TlsScanSimulation::elevationRange (
    const Vec3& o, const Aabb& box, double step_rad, long& j_min, long& j_max) const
{
  const double dx_near = std::max ({0.0, box.min.x() - o.x(), o.x() - box.max.x()});
  const double dy_near = std::max ({0.0, box.min.y() - o.y(), o.y() - box.max.y()});
  const double d_near = std::hypot (dx_near, dy_near);
  const double dx_far =
      std::max (std::abs (box.min.x() - o.x()), std::abs (box.max.x() - o.x()));
  const double dy_far =
      std::max (std::abs (box.min.y() - o.y()), std::abs (box.max.y() - o.y()));
  const double d_far = std::hypot (dx_far, dy_far);
  // Steepest angles are reached at the nearest horizontal distance, shallowest at the
  // farthest.
  const double up = box.max.z() - o.z(), down = box.min.z() - o.z();
  const double el_max = std::atan2 (up, up > 0.0 ? d_near : d_far);
  const double el_min = std::atan2 (down, down < 0.0 ? d_near : d_far);
  const double fov_min = min_elevation_deg_ * kDegToRad,
               fov_max = max_elevation_deg_ * kDegToRad;
  j_min = static_cast<long> (std::ceil (fov_min / step_rad - 1e-9));
  j_max = static_cast<long> (std::floor (fov_max / step_rad + 1e-9));
  j_min = std::max (j_min, static_cast<long> (std::floor (el_min / step_rad)) - 1);
  j_max = std::min (j_max, static_cast<long> (std::ceil (el_max / step_rad)) + 1);
}

template <typename Visitor>
void
TlsScanSimulation::traceColumns (const SceneGeometry& geometry,
                                 double step_deg,
                                 Visitor&& visit) const
{
  const double step_rad = step_deg * kDegToRad;
  const long num_columns = static_cast<long> (std::floor (360.0 / step_deg + 1e-9));
  const Aabb box = geometry.bounds();
  std::vector<detail::ColumnTask> tasks;
  if (!box.empty())
    for (std::size_t s = 0; s < positions_.size(); ++s) {
      long j_min, j_max;
      elevationRange (positions_[s], box, step_rad, j_min, j_max);
      if (j_min > j_max)
        continue;
      const ColumnRange range = columnRange (positions_[s], box, step_rad, num_columns);
      for (long k = 0; k < range.count; ++k)
        tasks.push_back (
            {static_cast<int> (s), (range.first + k) % num_columns, j_min, j_max});
    }
  const long num_tasks = static_cast<long> (tasks.size());
  const double cos_max_incidence = std::cos (max_incidence_deg_ * kDegToRad);
  visit.begin (tasks.size());
#pragma omp parallel for schedule(dynamic, 8) num_threads(resolveThreadCount(threads_))
  for (long k = 0; k < num_tasks; ++k) {
    const detail::ColumnTask& task = tasks[k];
    const Vec3& o = positions_[task.scanner];
    const std::uint64_t scanner_key =
        hashCombine (seed_, static_cast<std::uint64_t> (task.scanner));
    const double az = task.column * step_rad;
    const double ca = std::cos (az), sa = std::sin (az);
    for (long j = task.j_min; j <= task.j_max; ++j) {
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

namespace {
struct CountVisitor {
  std::vector<std::size_t> counts;
  void
  begin (std::size_t tasks)
  {
    counts.assign (tasks, 0);
  }
  void
  operator() (
      long task, int, long, const Ray&, const RayHit&, double, std::uint64_t, double)
  {
    ++counts[task];
  }
  void
  end (const std::vector<detail::ColumnTask>&, long)
  {}
};
} // namespace

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
TlsScanSimulation::stepForPointCount (const SceneGeometry& geometry,
                                      std::size_t points) const
{
  if (points == 0)
    return 0.0;
  // Returns grow as 1 / step^2: count at coarse steps, then scale.
  double step = 2.0;
  std::size_t n = 0;
  const double coarse_target =
      static_cast<double> (std::min<std::size_t> (points, 20000));
  for (int iteration = 0; iteration < 12; ++iteration) {
    n = countReturns (geometry, step);
    if (n == 0) {
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
  const double fine_target =
      static_cast<double> (std::min<std::size_t> (points, 100000));
  step *= std::sqrt (static_cast<double> (n) / fine_target);
  n = countReturns (geometry, step);
  if (n == 0)
    return 0.0;
  return step * std::sqrt (static_cast<double> (n) / static_cast<double> (points));
}

namespace {
/** What scan() makes of each return: its point (measured position, colour, intensity
 * and truth) and, for the passes after the last column, its place on the grid of rays.
 */
struct ScanVisitor {
  const SceneGeometry& geometry;
  const Eigen::Isometry3d& transform;
  double noise_sigma, noise_per_metre, edge_distance;
  bool coverage_boundaries;
  bool connected_segments;
  long lowest_row; ///< the lowest row of the field of view (the blind cone below it)
  unsigned int threads;
  std::vector<detail::ColumnPoints> points;
  std::vector<std::vector<std::uint16_t>> scanners;
  std::vector<std::vector<detail::ScanReturn>> returns;
  /** Surface id of every segment id after splitSegmentsIntoPieces (empty otherwise). */
  std::vector<std::uint32_t> surface_of_segment;

  void
  begin (std::size_t tasks)
  {
    points.resize (tasks);
    scanners.resize (tasks);
    returns.resize (tasks);
  }

  /** After the last column: the coverage boundaries, then the pieces, over one index of
   * all returns (built before the pieces change any segment id). */
  void
  end (const std::vector<detail::ColumnTask>& tasks, long num_columns)
  {
    if (coverage_boundaries || connected_segments) {
      const detail::ScanGrid grid{tasks, num_columns, lowest_row, returns};
      // The tree serves the coverage boundaries and the links between scanners.
      detail::ReturnIndex index;
      detail::buildReturnIndex (grid, points, coverage_boundaries, index);
      if (coverage_boundaries) {
        detail::markCoverageBoundaries (grid, index, threads, points);
        detail::markOneSidedCreases (grid, index, geometry, threads, points);
      }
      if (connected_segments)
        detail::splitSegmentsIntoPieces (
            grid, index, threads, points, surface_of_segment);
    }
    decltype (returns)().swap (returns);
  }

  void
  operator() (long task,
              int scanner,
              long row,
              const Ray& ray,
              const RayHit& hit,
              double cos_incidence,
              std::uint64_t key,
              double step_rad)
  {
    const Primitive& primitive = *geometry.primitives()[hit.primitive];
    const Vec3 truth = ray.origin + hit.t * ray.direction;
    const SurfaceInfo& info = primitive.infoAt (truth);
    RandomStream rng (key);
    double noise = (noise_sigma + noise_per_metre * hit.t) * rng.gaussian();
    if (primitive.roughness > 0.0)
      noise += primitive.roughness * rng.gaussian();
    const Vec3 measured = transform * (ray.origin + (hit.t + noise) * ray.direction);
    const double distance = edge_distance > 0.0 ? edge_distance : hit.t * step_rad;

    SimulatedPoint p;
    p.x = static_cast<float> (measured.x());
    p.y = static_cast<float> (measured.y());
    p.z = static_cast<float> (measured.z());
    p.data[3] = 1.0f;
    p.rgba = 0;
    const Material& m = info.material;
    p.r = toByte (m.rgb[0] + m.rgb_jitter * rng.gaussian());
    p.g = toByte (m.rgb[1] + m.rgb_jitter * rng.gaussian());
    p.b = toByte (m.rgb[2] + m.rgb_jitter * rng.gaussian());
    p.a = 255;
    p.intensity =
        static_cast<float> (std::clamp (m.reflectance * (0.2 + 0.8 * cos_incidence) +
                                            m.intensity_jitter * rng.gaussian(),
                                        0.0,
                                        1.0));
    p.segment = info.segment;
    p.object = info.object;
    p.label = info.label;
    p.point_class =
        static_cast<std::uint32_t> (geometry.classify (truth, info.segment, distance));
    points[task].push_back (p);
    scanners[task].push_back (static_cast<std::uint16_t> (scanner));
    if (coverage_boundaries || connected_segments)
      returns[task].push_back ({row,
                                truth,
                                hit.t,
                                hit.t * step_rad / std::max (cos_incidence, 0.05),
                                distance,
                                hit.normal.cast<float>(),
                                primitive.porosity > 0.0});
  }
};
} // namespace

bool
TlsScanSimulation::scan (const SceneGeometry& geometry,
                         pcl::PointCloud<SimulatedPoint>& cloud,
                         std::vector<std::uint16_t>* scanner_of_point,
                         std::vector<std::uint32_t>* surface_of_segment) const
{
  cloud.clear();
  if (scanner_of_point)
    scanner_of_point->clear();
  if (surface_of_segment)
    surface_of_segment->clear();
  if (!checkParameters())
    return false;
  ScanVisitor visitor{
      geometry,
      output_transform_,
      noise_sigma_,
      noise_per_metre_,
      edge_distance_,
      coverage_boundaries_,
      connected_segments_,
      static_cast<long> (std::ceil (min_elevation_deg_ / step_deg_ - 1e-9)),
      threads_,
      {},
      {},
      {},
      {}};
  traceColumns (geometry, step_deg_, visitor);
  std::size_t total = 0;
  for (const auto& column : visitor.points)
    total += column.size();
  cloud.reserve (total);
  if (scanner_of_point)
    scanner_of_point->reserve (total);
  for (std::size_t k = 0; k < visitor.points.size(); ++k) {
    cloud.insert (cloud.end(), visitor.points[k].begin(), visitor.points[k].end());
    if (scanner_of_point)
      scanner_of_point->insert (scanner_of_point->end(),
                                visitor.scanners[k].begin(),
                                visitor.scanners[k].end());
    // Free each column as it is copied: large scans would otherwise need twice the
    // memory.
    decltype (visitor.points)::value_type().swap (visitor.points[k]);
  }
  if (surface_of_segment) {
    if (connected_segments_)
      surface_of_segment->swap (visitor.surface_of_segment);
    else {
      std::uint32_t highest = 0;
      for (const auto& p : cloud)
        highest = std::max (highest, p.segment);
      surface_of_segment->resize (cloud.empty() ? 0 : highest + 1);
      std::iota (surface_of_segment->begin(), surface_of_segment->end(), 0u);
    }
  }
  cloud.width = static_cast<std::uint32_t> (cloud.size());
  cloud.height = 1;
  cloud.is_dense = true;
  return true;
}
} // namespace simulation
} // namespace pcl_ext