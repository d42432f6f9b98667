/*
 * pcl_ext: where the camera of a picture looks from, and what it frames.
 */
#include <pcl_ext/search/kdtree_3f.h>
#include <pcl_ext/visualization/framing.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

namespace pcl_ext {
namespace visualization {
namespace {
constexpr double kPi = 3.14159265358979323846;

/** The q-quantile (q in [0, 1]) of \a values, which it reorders. */
double
quantile (std::vector<double>& values, double q)
{
  const auto k = static_cast<std::size_t> (q * double (values.size() - 1) + 0.5);
  std::nth_element (values.begin(), values.begin() + k, values.end());
  return values[k];
}

/** Two unit vectors spanning the plane orthogonal to unit \a u. */
std::pair<Eigen::Vector3d, Eigen::Vector3d>
planeBasis (const Eigen::Vector3d& u)
{
  const Eigen::Vector3d seed =
      std::abs (u.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d a = (seed - seed.dot (u) * u).normalized();
  return {a, u.cross (a)};
}

/** The 1st and 99th percentiles of \a values. */
std::pair<double, double>
percentiles (std::vector<double> values)
{
  const double lo = quantile (values, 0.01), hi = quantile (values, 0.99);
  return {lo, hi};
}

/** The box [x0, x1] x [y0, y1] widened to take in every point (x, y) within \a reach of
 * it on both axes. */
std::array<double, 4>
widened (const std::vector<double>& x,
         const std::vector<double>& y,
         const std::array<double, 4>& box,
         double reach)
{
  std::array<double, 4> out = box;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] >= box[0] - reach && x[i] <= box[1] + reach && y[i] >= box[2] - reach &&
        y[i] <= box[3] + reach) {
      out[0] = std::min (out[0], x[i]);
      out[1] = std::max (out[1], x[i]);
      out[2] = std::min (out[2], y[i]);
      out[3] = std::max (out[3], y[i]);
    }
  return out;
}
} // namespace

bool
parseViewKind (const std::string& text, ViewKind& kind)
{
  for (const ViewKind k : {ViewKind::Auto,
                           ViewKind::Top,
                           ViewKind::Side,
                           ViewKind::Oblique,
                           ViewKind::Sensor})
    if (text == viewKindName (k)) {
      kind = k;
      return true;
    }
  return false;
}

std::string
viewKindName (ViewKind kind)
{
  switch (kind) {
  case ViewKind::Top:
    return "top";
  case ViewKind::Side:
    return "side";
  case ViewKind::Oblique:
    return "oblique";
  case ViewKind::Sensor:
    return "sensor";
  case ViewKind::Auto:
  default:
    return "auto";
  }
}

namespace {
/** Along \a across: +1 when the lowest fifth of the points (by height along \a u) lies
 * on the + side of the highest fifth by more than a tenth of the points' extent, -1
 * when on the - side, 0 when neither. */
double
groundSide (const std::vector<Eigen::Vector3d>& points,
            const Eigen::Vector3d& u,
            const Eigen::Vector3d& across)
{
  std::vector<double> height (points.size()), position (points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    height[i] = points[i].dot (u);
    position[i] = points[i].dot (across);
  }
  std::vector<double> sorted = height; // quantile() reorders its values
  const double low = quantile (sorted, 0.2), high = quantile (sorted, 0.8);
  if (!(high > low))
    return 0.0;
  double low_sum = 0.0, high_sum = 0.0;
  std::size_t low_count = 0, high_count = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (height[i] <= low) {
      low_sum += position[i];
      ++low_count;
    }
    else if (height[i] >= high) {
      high_sum += position[i];
      ++high_count;
    }
  }
  if (low_count == 0 || high_count == 0)
    return 0.0;
  sorted = position;
  const double extent = quantile (sorted, 0.95) - quantile (sorted, 0.05);
  const double offset = low_sum / double (low_count) - high_sum / double (high_count);
  if (!(extent > 0.0) || std::abs (offset) <= 0.1 * extent)
    return 0.0;
  return offset > 0.0 ? 1.0 : -1.0;
}
} // namespace

Eigen::Vector3d
viewDirection (const std::vector<Eigen::Vector3d>& points,
               ViewKind kind,
               const Eigen::Vector3d& up,
               const Eigen::Vector3d& sensor)
{
  const Eigen::Vector3d u = up.normalized();
  if (kind == ViewKind::Top)
    return -u;
  const bool sensor_known = sensor.allFinite();
  if (kind == ViewKind::Sensor && sensor_known && !points.empty()) {
    std::vector<double> coordinate (points.size());
    Eigen::Vector3d median;
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t i = 0; i < points.size(); ++i)
        coordinate[i] = points[i][axis];
      median[axis] = quantile (coordinate, 0.5);
    }
    const Eigen::Vector3d towards = median - sensor;
    if (towards.norm() > 1e-9)
      return towards.normalized();
  }
  // Across the longer horizontal axis: the eigenvector of the smaller eigenvalue of the
  // horizontal spread.
  const auto [a, b] = planeBasis (u);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points)
    mean += Eigen::Vector2d (p.dot (a), p.dot (b));
  if (!points.empty())
    mean /= double (points.size());
  Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector2d q = Eigen::Vector2d (p.dot (a), p.dot (b)) - mean;
    spread += q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver (spread);
  const Eigen::Vector2d minor = solver.eigenvectors().col (0);
  Eigen::Vector3d across = minor.x() * a + minor.y() * b;
  // From the sensor's side when it is known. Else from the side of the ground: a scan
  // sees the ground in front of what stands on it (a street in front of its facades),
  // so when the lowest points lie clearly to one side of the tallest ones, across the
  // long axis, the camera goes to that side. Otherwise from a fixed side (so that the
  // same cloud is always seen from the same side).
  Eigen::Vector3d reference = Eigen::Vector3d (-1.0, -1.4, 0.0);
  if (sensor_known && !points.empty()) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : points)
      mean += p;
    reference = mean / double (points.size()) - sensor;
  }
  else if (points.size() >= 100) {
    const double side = groundSide (points, u, across);
    if (side != 0.0)
      reference = -side * across;
  }
  if (across.dot (reference) < 0.0)
    across = -across;
  if (kind == ViewKind::Side)
    return across.normalized();
  // Oblique (and Auto or Sensor without a sensor): turned 30 degrees about the up
  // direction, 35 degrees down.
  const double turn = 30.0 * kPi / 180.0, elevation = 35.0 * kPi / 180.0;
  const Eigen::Vector3d turned =
      std::cos (turn) * across + std::sin (turn) * u.cross (across);
  return (std::cos (elevation) * turned.normalized() - std::sin (elevation) * u)
      .normalized();
}

Framing
frameRobustly (const std::vector<Eigen::Vector3d>& points,
               const Eigen::Vector3d& direction,
               const Eigen::Vector3d& up,
               double aspect,
               double margin)
{
  Framing framing;
  if (points.empty() || !(direction.norm() > 0.0) || !(aspect > 0.0))
    return framing;
  const Eigen::Vector3d f = direction.normalized();
  Eigen::Vector3d v = up - up.dot (f) * f;
  if (v.norm() < 1e-9)
    v = planeBasis (f).first;
  v.normalize();
  const Eigen::Vector3d r = f.cross (v);
  std::vector<double> x (points.size()), y (points.size()), depth (points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    x[i] = points[i].dot (r);
    y[i] = points[i].dot (v);
    depth[i] = points[i].dot (f);
  }
  double px0, px1, py0, py1;
  // Sparse parts (far rings of a scanner's ground, stray returns) do not count: only
  // the points of picture cells holding at least a tenth of the count of the median
  // point's cell, on a 48 x 48 grid over the percentile box.
  {
    const auto [ax0, ax1] = percentiles (x);
    const auto [ay0, ay1] = percentiles (y);
    const double cell = std::max (std::max (ax1 - ax0, ay1 - ay0) / 48.0, 1e-12);
    std::map<std::pair<long, long>, std::size_t> count;
    const auto key = [&] (std::size_t i) {
      return std::make_pair (std::lround (std::floor ((x[i] - ax0) / cell)),
                             std::lround (std::floor ((y[i] - ay0) / cell)));
    };
    for (std::size_t i = 0; i < x.size(); ++i)
      ++count[key (i)];
    // The count of the median point's cell: the density most points lie at, whatever
    // the number of sparse cells.
    std::vector<double> counts (x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      counts[i] = double (count[key (i)]);
    const double least = 0.1 * quantile (counts, 0.5);
    std::vector<double> dense_x, dense_y;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (double (count[key (i)]) >= least) {
        dense_x.push_back (x[i]);
        dense_y.push_back (y[i]);
      }
    if (dense_x.size() * 2 < x.size()) {
      dense_x = x;
      dense_y = y;
    }
    std::tie (px0, px1) = percentiles (dense_x);
    std::tie (py0, py1) = percentiles (dense_y);
  }
  const double reach = 0.5 * std::max (px1 - px0, py1 - py0);
  const auto [x0, x1, y0, y1] = widened (x, y, {px0, px1, py0, py1}, reach);
  const double m = std::clamp (margin, 0.0, 0.45);
  const double scale = std::max ({std::abs (x0), std::abs (x1), std::abs (y0), 1e-3});
  double half_width = std::max (0.5 * (x1 - x0), 1e-6 * scale) / (1.0 - 2.0 * m);
  double half_height = std::max (0.5 * (y1 - y0), 1e-6 * scale) / (1.0 - 2.0 * m);
  half_width = std::max (half_width, half_height * aspect);
  half_height = half_width / aspect;
  framing.direction = f;
  framing.up = v;
  framing.centre =
      0.5 * (x0 + x1) * r + 0.5 * (y0 + y1) * v + quantile (depth, 0.5) * f;
  framing.half_width = half_width;
  framing.half_height = half_height;
  return framing;
}

double
estimateCeilingHeight (const std::vector<Eigen::Vector3d>& points,
                       const Eigen::Vector3d& up)
{
  constexpr double kNone = std::numeric_limits<double>::infinity();
  if (points.size() < 100)
    return kNone;
  const Eigen::Vector3d u = up.normalized();
  std::vector<double> height (points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    height[i] = points[i].dot (u);
  std::vector<double> sorted = height;
  const double lo = quantile (sorted, 0.005), hi = quantile (sorted, 0.995);
  if (!(hi > lo))
    return kNone;
  constexpr int kBins = 64;
  const double bin = (hi - lo) / kBins;
  std::vector<std::size_t> count (kBins, 0);
  for (const double h : height)
    if (h >= lo && h <= hi)
      ++count[std::min (kBins - 1, static_cast<int> ((h - lo) / bin))];
  std::vector<std::size_t> counts = count;
  std::nth_element (counts.begin(), counts.begin() + kBins / 2, counts.end());
  const std::size_t peak = 4 * std::max<std::size_t> (counts[kBins / 2], 1);
  const int top_fifth = kBins - kBins / 5;
  int layer = -1;
  for (int k = kBins - 1; k >= top_fifth && layer < 0; --k)
    if (count[k] >= peak)
      layer = k;
  if (layer < 0)
    return kNone;
  while (layer - 1 >= top_fifth && count[layer - 1] >= peak)
    --layer;
  const double clip = lo + (layer - 0.5) * bin;
  // Does the layer cover most of the footprint? Compare occupied cells of a 48 x 48
  // grid.
  const auto [a, b] = planeBasis (u);
  std::vector<double> pa (points.size()), pb (points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    pa[i] = points[i].dot (a);
    pb[i] = points[i].dot (b);
  }
  std::vector<double> qa = pa, qb = pb;
  const double a0 = quantile (qa, 0.005), a1 = quantile (qa, 0.995);
  const double b0 = quantile (qb, 0.005), b1 = quantile (qb, 0.995);
  const double cell = std::max (std::max (a1 - a0, b1 - b0) / 48.0, 1e-9);
  std::set<std::pair<long, long>> all, top;
  std::size_t below = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (pa[i] < a0 || pa[i] > a1 || pb[i] < b0 || pb[i] > b1)
      continue;
    const std::pair<long, long> key (std::lround ((pa[i] - a0) / cell),
                                     std::lround ((pb[i] - b0) / cell));
    all.insert (key);
    if (height[i] >= clip)
      top.insert (key);
    else
      ++below;
  }
  // A ceiling stands above rooms: the height range is at least a twentieth of the
  // horizontal one (not a flat layer drawn over another, as in a map).
  if (top.size() * 5 < all.size() * 3 || below * 5 < points.size() ||
      hi - lo < 0.05 * std::max (a1 - a0, b1 - b0))
    return kNone;
  return clip;
}

double
estimateSpacing (const std::vector<Eigen::Vector3d>& points)
{
  if (points.size() < 2)
    return std::numeric_limits<double>::quiet_NaN();
  // Relative to the first point, so that float coordinates keep their precision far
  // from the origin (georeferenced scans).
  const Eigen::Vector3d origin = points.front();
  std::vector<float> xyz;
  xyz.reserve (3 * points.size());
  std::vector<pcl::index_t> indices (points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d q = points[i] - origin;
    xyz.insert (xyz.end(), {float (q.x()), float (q.y()), float (q.z())});
    indices[i] = static_cast<pcl::index_t> (i);
  }
  search::KdTree3f tree;
  tree.build (xyz, indices);
  const std::size_t samples = std::min<std::size_t> (2000, points.size());
  std::vector<double> nearest;
  nearest.reserve (samples);
  pcl::index_t found[2];
  float sqr[2];
  for (std::size_t s = 0; s < samples; ++s) {
    const std::size_t i = s * points.size() / samples;
    if (tree.nearestKSearch (&xyz[3 * i], 2, found, sqr) == 2 && sqr[1] > 0.0f)
      nearest.push_back (std::sqrt (double (sqr[1])));
  }
  if (nearest.empty())
    return std::numeric_limits<double>::quiet_NaN();
  return quantile (nearest, 0.5);
}
} // namespace visualization
} // namespace pcl_ext
