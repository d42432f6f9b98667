/*
 * pcl_ext: plane matching, candidate generation (Khoshelham & Gorte 2009, section 3.3):
 * the initial planes, the tables of constraints 1 and 2, the bounds around a guess and
 * the counts of eq. 13, prepared once and shared by every search worker.
 */
#include "plane_matching_context.h"

#include <pcl/console/print.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pcl_ext {
namespace plane_matching {
namespace {
int
classify (const Eigen::Vector3d& n, double tolerance_deg)
{
  const double z = std::abs (n.z());
  if (z <= std::sin (tolerance_deg * kDegree))
    return Vertical;
  if (z >= std::cos (tolerance_deg * kDegree))
    return Horizontal;
  return Other;
}

// Largest first: support, then extent, then input order (a stable, total order).
std::vector<int>
bySize (const std::vector<Plane>& planes)
{
  std::vector<int> order (planes.size());
  std::iota (order.begin(), order.end(), 0);
  auto size = [&] (int i) {
    return planes[i].extent.isEmpty() ? 0.0 : planes[i].extent.diagonal().norm();
  };
  std::stable_sort (order.begin(), order.end(), [&] (int a, int b) {
    if (planes[a].size != planes[b].size)
      return planes[a].size > planes[b].size;
    return size (a) > size (b);
  });
  return order;
}

// The angle of a rotation bound around the guess, in [0, pi], and the chord of that
// angle:
// |(R - R_g) x| <= chord |x|.
double
rotationBound (const PlaneMatchingParameters& p)
{
  return std::min (p.max_rotation_from_guess_deg * kDegree, M_PI);
}

double
chordOf (double rotation_bound)
{
  return 2.0 * std::sin (0.5 * rotation_bound);
}

// Bounds around the guess. The guess's rotation is the nearest rotation to its 3 x 3
// block, and the centre is that of the bounding box of the scan planes' centroids.
// Returns which map planes are within reach of the scan planes (all of them unless
// bounded, see below).
std::vector<char>
boundAroundGuess (Context& c, const Eigen::Matrix4d& guess)
{
  const PlaneMatchingParameters& parameters = c.p;
  c.bounded = std::isfinite (parameters.max_rotation_from_guess_deg) ||
              std::isfinite (parameters.max_translation_from_guess);
  const double rotation_bound = rotationBound (parameters);
  const double chord = chordOf (rotation_bound);
  std::vector<char> map_within_reach (c.map.size(), 1);
  if (!c.bounded)
    return map_within_reach;
  c.cos_rotation_bound =
      rotation_bound >= M_PI ? -2.0 : std::cos (rotation_bound); // -2: any
  c.translation_bound = parameters.max_translation_from_guess;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd (guess.topLeftCorner<3, 3>(),
                                         Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d (2, 2) =
      (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  c.guess_rotation = svd.matrixU() * d * svd.matrixV().transpose();
  Eigen::AlignedBox3d centroids, extents;
  for (const auto& plane : c.scan) {
    centroids.extend (plane.centroid);
    extents.extend (plane.extent.isEmpty() ? Eigen::AlignedBox3d (plane.centroid)
                                           : plane.extent);
  }
  c.centre = centroids.center();
  c.guess_centre =
      guess.topLeftCorner<3, 3>() * c.centre + guess.topRightCorner<3, 1>();
  // Map planes out of reach: a pair must pass the extent test (residual constraint for
  // the initial pairs, extension always), and a transform within the bounds puts every
  // scan point x within translation_bound + chord |x - centre| of where the guess puts
  // it. A map plane whose extent is farther than that (plus the extent margin) from the
  // guessed image of the scan planes' bounding box can pair with none of them: it
  // neither initiates nor extends, and the n initial map planes are the largest of the
  // others (rigid model: a similarity's scale is not bounded).
  if (parameters.check_extents && parameters.residual_constraint &&
      std::isfinite (c.translation_bound) &&
      parameters.model == PlaneTransformationModel::Rigid) {
    Eigen::AlignedBox3d image;
    double radius = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d x =
          extents.corner (static_cast<Eigen::AlignedBox3d::CornerType> (corner));
      image.extend (c.guess_rotation * (x - c.centre) + c.guess_centre);
      radius = std::max (radius, (x - c.centre).norm());
    }
    const double margin =
        parameters.extent_margin + c.translation_bound + chord * radius + 1e-6;
    for (std::size_t i = 0; i < c.map.size(); ++i)
      map_within_reach[i] = extentsOverlap (image, c.map[i].extent, margin);
  }
  return map_within_reach;
}

// Walls first (beyond the paper, PlaneMatchingParameters::walls_first): the largest
// horizontal plane (ground, floor: the one that fixes the height), then the vertical
// planes longest in plan (those a footprint edge can match: interior walls and clutter
// are short), then the other planes largest first.
std::vector<int>
wallsFirst (const std::vector<Plane>& planes, double tolerance_deg)
{
  const std::vector<int> by_size = bySize (planes);
  std::vector<int> order, walls, rest;
  for (const int i : by_size) {
    const int cls = classify (planes[i].normal, tolerance_deg);
    if (cls == Horizontal && order.empty())
      order.push_back (i);
    else if (cls == Vertical)
      walls.push_back (i);
    else
      rest.push_back (i);
  }
  auto plan_length = [&] (int i) {
    const auto& e = planes[i].extent;
    return e.isEmpty() ? 0.0 : Eigen::Vector2d (e.sizes().x(), e.sizes().y()).norm();
  };
  std::stable_sort (walls.begin(), walls.end(), [&] (int a, int b) {
    return plan_length (a) > plan_length (b);
  });
  order.insert (order.end(), walls.begin(), walls.end());
  order.insert (order.end(), rest.begin(), rest.end());
  return order;
}

// The initial planes: the largest (or walls first), among the near-vertical/horizontal
// ones under constraint 1.
void
chooseInitialPlanes (const std::vector<Plane>& planes,
                     const PlaneMatchingParameters& p,
                     int count,
                     std::vector<int>& init,
                     std::vector<int>& classes,
                     const std::vector<char>* allowed)
{
  const std::vector<int> order =
      p.walls_first ? wallsFirst (planes, p.vertical_tolerance_deg) : bySize (planes);
  for (const int i : order) {
    const int cls = classify (planes[i].normal, p.vertical_tolerance_deg);
    if (p.vertical_constraint && cls == Other)
      continue;
    if (allowed && !(*allowed)[i])
      continue;
    if (static_cast<int> (init.size()) == count)
      break;
    init.push_back (i);
    classes.push_back (cls);
  }
}

std::vector<double>
angleTable (const std::vector<Plane>& planes, const std::vector<int>& init)
{
  std::vector<double> table (init.size() * init.size());
  for (std::size_t a = 0; a < init.size(); ++a)
    for (std::size_t b = 0; b < init.size(); ++b)
      table[a * init.size() + b] = std::acos (
          std::clamp (planes[init[a]].normal.dot (planes[init[b]].normal), -1.0, 1.0));
  return table;
}

std::vector<double>
tripleTable (const std::vector<Plane>& planes, const std::vector<int>& init)
{
  const std::size_t size = init.size();
  std::vector<double> table (size * size * size);
  for (std::size_t a = 0; a < size; ++a)
    for (std::size_t b = 0; b < size; ++b)
      for (std::size_t l = 0; l < size; ++l)
        table[(a * size + b) * size + l] = planes[init[a]].normal.dot (
            planes[init[b]].normal.cross (planes[init[l]].normal));
  return table;
}

// The anchors of the initial scan planes, the angle tables and constraints 1 and 2 as
// bits.
void
tabulateConstraints (Context& c)
{
  const PlaneMatchingParameters& parameters = c.p;
  const int m = static_cast<int> (c.scan_init.size()),
            n = static_cast<int> (c.map_init.size());
  for (const int i : c.scan_init) {
    const Plane& plane = c.scan[i];
    c.scan_anchor.push_back (plane.project (plane.centroid));
    c.scan_anchor_norm.push_back (c.scan_anchor.back().norm());
  }
  c.scan_angle = angleTable (c.scan, c.scan_init);
  c.map_angle = angleTable (c.map, c.map_init);
  // Constraint 2 without oriented normals compares the angles of lines, in [0, 90]
  // degrees.
  auto lines = [&] (std::vector<double> table) {
    if (!parameters.oriented_normals)
      for (double& a : table)
        a = std::min (a, M_PI - a);
    return table;
  };
  const std::vector<double> scan_line = lines (c.scan_angle),
                            map_line = lines (c.map_angle);
  c.compatible.assign (static_cast<std::size_t> (m) * n * m, 0);
  for (int s = 0; s < m; ++s)
    for (int t = 0; t < n; ++t)
      for (int sp = 0; sp < m; ++sp) {
        std::uint64_t& bits =
            c.compatible[(static_cast<std::size_t> (s) * n + t) * m + sp];
        for (int mp = 0; mp < n; ++mp) {
          if (parameters.vertical_constraint &&
              (c.scan_class[sp] == Other || c.scan_class[sp] != c.map_class[mp]))
            continue;
          if (parameters.orientation_constraint &&
              std::abs (scan_line[s * m + sp] - map_line[t * n + mp]) >
                  c.orientation_tol)
            continue;
          bits |= std::uint64_t (1) << mp;
        }
      }
}

// Bounds around the guess, and their necessary conditions on the initial pairs.
void
boundInitialPairs (Context& c)
{
  const PlaneMatchingParameters& parameters = c.p;
  const int m = static_cast<int> (c.scan_init.size()),
            n = static_cast<int> (c.map_init.size());
  c.guess_pairs.assign (m, n == 64 ? ~std::uint64_t (0) : (std::uint64_t (1) << n) - 1);
  if (!c.bounded || !parameters.residual_constraint)
    return;
  // An accepted pair has angle(R n_s, s n_m) <= angle_tol and angle(R, R_g) <= the
  // rotation bound, hence angle(R_g n_s, s n_m) <= their sum. For a rigid estimate T
  // within the bounds, |T a - T_g a| <= translation_bound + 2 sin(rotation_bound / 2)
  // |a - centre| for T_g = (R_g, guess_centre - R_g centre), so the anchor a, whose
  // image is within distance_tol of the map plane, has its guessed image within the sum
  // of the two.
  const double rotation_bound = rotationBound (parameters);
  const double chord = chordOf (rotation_bound);
  const double reach = std::min (M_PI, rotation_bound + c.angle_tol) + 1e-9;
  const bool by_distance = std::isfinite (c.translation_bound) &&
                           parameters.model == PlaneTransformationModel::Rigid;
  for (int sp = 0; sp < m; ++sp) {
    const Eigen::Vector3d normal = c.guess_rotation * c.scan[c.scan_init[sp]].normal;
    const Eigen::Vector3d anchor =
        c.guess_rotation * (c.scan_anchor[sp] - c.centre) + c.guess_centre;
    const double allowance = c.distance_tol + c.translation_bound +
                             chord * (c.scan_anchor[sp] - c.centre).norm();
    for (int mp = 0; mp < n; ++mp) {
      const Plane& target = c.map[c.map_init[mp]];
      double cosine = normal.dot (target.normal);
      if (!parameters.oriented_normals)
        cosine = std::abs (cosine);
      bool keep = std::acos (std::clamp (cosine, -1.0, 1.0)) <= reach;
      if (keep && by_distance)
        keep = std::abs (target.signedDistance (anchor)) <=
               allowance * (1.0 + 1e-9) + 1e-9;
      if (!keep)
        c.guess_pairs[sp] &= ~(std::uint64_t (1) << mp);
    }
  }
  for (int s = 0; s < m; ++s)
    for (int t = 0; t < n; ++t)
      for (int sp = 0; sp < m; ++sp)
        c.compatible[(static_cast<std::size_t> (s) * n + t) * m + sp] &=
            c.guess_pairs[sp];
}

// Extension under the vertical and residual constraints: every transform it applies
// keeps the scan's up axis within vertical_tol of the map's, so it changes the
// elevation of a line by vertical_tol at most, and a pair within angle_tol differs in
// elevation by angle_tol + vertical_tol at most (plus 1e-4 rad for normals of length 1
// +- 1e-6 and rounding). Other map planes are not looked at.
void
findReachable (Context& c, const std::vector<char>& map_within_reach)
{
  const PlaneMatchingParameters& parameters = c.p;
  auto elevation = [] (const Plane& plane) {
    return std::asin (
        std::min (1.0, std::abs (plane.normal.z()) / plane.normal.norm()));
  };
  const bool by_elevation =
      parameters.vertical_constraint && parameters.residual_constraint;
  const double elevation_tol =
      c.angle_tol + parameters.vertical_tolerance_deg * kDegree + 1e-4;
  c.reachable.resize (c.scan.size());
  for (std::size_t j = 0; j < c.scan.size(); ++j)
    for (std::size_t i = 0; i < c.map.size(); ++i)
      if (map_within_reach[i] &&
          (!by_elevation ||
           std::abs (elevation (c.scan[j]) - elevation (c.map[i])) <= elevation_tol))
        c.reachable[j].push_back (static_cast<int> (i));
}

// The 4-subsets of the k pairs (distance screen) and the sets of sign patterns.
void
tabulatePatterns (Context& c)
{
  const int k = c.p.k;
  for (int a = 0; a < k; ++a)
    for (int b = a + 1; b < k; ++b)
      for (int d = b + 1; d < k; ++d)
        for (int e = d + 1; e < k; ++e)
          c.subsets.push_back ({a, b, d, e});

  const unsigned patterns = 1u << k;
  const std::size_t words = (patterns + 63) / 64;
  auto patternSet = [&] (auto test) {
    std::vector<std::uint64_t> set (words, 0);
    for (unsigned mask = 0; mask < patterns; ++mask)
      if (test (mask))
        set[mask / 64] |= std::uint64_t (1) << (mask % 64);
    return set;
  };
  c.all_patterns = patternSet ([] (unsigned) { return true; });
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j) {
      const auto set =
          patternSet ([&] (unsigned mask) { return ((mask >> i) ^ (mask >> j)) & 1u; });
      c.pair_opposite.insert (c.pair_opposite.end(), set.begin(), set.end());
      for (int l = j + 1; l < k; ++l) {
        const auto odd = patternSet ([&] (unsigned mask) {
          return ((mask >> i) ^ (mask >> j) ^ (mask >> l)) & 1u;
        });
        c.triple_odd.insert (c.triple_odd.end(), odd.begin(), odd.end());
      }
    }
}

// Eq. 13 and the count after constraint 1: vertical scan planes pair with vertical map
// planes.
void
countCombinations (const Context& c, PlaneMatchingStatistics& stats)
{
  const int k = c.p.k, m = stats.m, n = stats.n;
  stats.unconstrained = countInitialCombinations (m, n, k);
  if (!c.p.vertical_constraint) {
    stats.vertical = stats.unconstrained;
    return;
  }
  const int mv = static_cast<int> (
      std::count (c.scan_class.begin(), c.scan_class.end(), Vertical));
  const int nv =
      static_cast<int> (std::count (c.map_class.begin(), c.map_class.end(), Vertical));
  double count = 0.0;
  for (int v = 0; v <= k; ++v)
    count += binomial (mv, v) * binomial (m - mv, k - v) * permutations (nv, v) *
             permutations (n - nv, k - v);
  stats.vertical = saturate (count);
}
} // namespace

double
binomial (int n, int k)
{
  if (k < 0 || k > n)
    return 0.0;
  double r = 1.0;
  for (int i = 1; i <= k; ++i)
    r = r * (n - k + i) / i;
  return std::round (r);
}

double
permutations (int n, int k)
{
  if (k < 0 || k > n)
    return 0.0;
  double r = 1.0;
  for (int i = 0; i < k; ++i)
    r *= n - i;
  return r;
}

std::uint64_t
saturate (double x)
{
  return x >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max()
                     : static_cast<std::uint64_t> (x);
}

bool
prepareContext (Context& c,
                const Eigen::Matrix4d& guess,
                PlaneMatchingStatistics& stats)
{
  const PlaneMatchingParameters& parameters = c.p;
  const int k = parameters.k;
  c.scan_order = bySize (c.scan);
  const std::vector<char> map_within_reach = boundAroundGuess (c, guess);
  chooseInitialPlanes (
      c.scan, parameters, parameters.scan_initial, c.scan_init, c.scan_class, nullptr);
  chooseInitialPlanes (c.map,
                       parameters,
                       parameters.map_initial,
                       c.map_init,
                       c.map_class,
                       &map_within_reach);
  const int m = static_cast<int> (c.scan_init.size()),
            n = static_cast<int> (c.map_init.size());
  stats.m = m;
  stats.n = n;
  stats.k = k;
  if (m < k || n < k) {
    const bool out_of_reach =
        std::count (map_within_reach.begin(), map_within_reach.end(), 0) > 0;
    PCL_ERROR ("[pcl_ext::matchPlanes] %d scan and %d map planes%s%s: at least k = %d "
               "of each are "
               "needed.\n",
               m,
               n,
               parameters.vertical_constraint ? " (near-vertical or horizontal)" : "",
               out_of_reach ? " within reach of the guess" : "",
               k);
    return false;
  }
  tabulateConstraints (c);
  boundInitialPairs (c);
  c.scan_triple = tripleTable (c.scan, c.scan_init);
  c.map_triple = tripleTable (c.map, c.map_init);
  findReachable (c, map_within_reach);
  tabulatePatterns (c);
  countCombinations (c, stats);
  return true;
}
} // namespace plane_matching
} // namespace pcl_ext
