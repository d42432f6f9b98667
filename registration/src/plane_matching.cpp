/*
 * pcl_ext: initiate-and-extend plane matching (Khoshelham & Gorte 2009, section 3.3).
 */
#include <pcl_ext/registration/plane_matching.h>

#include <pcl/console/print.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace pcl_ext
{
namespace
{
constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr int kMaxInitial = 64;  // map positions in use are kept in a 64-bit mask
constexpr int kMaxK = 8;
constexpr int kMaxSubsets = 70;  // C(kMaxK, 4)
constexpr int kMaxPatternWords = (1 << kMaxK) / 64;  // sign patterns as a bit set
constexpr double kMaxDegeneracyCache = 1 << 20;  // prefixes in a worker's degeneracy cache

enum PlaneClass { Other = -1, Vertical = 0, Horizontal = 1 };

int
classify (const Eigen::Vector3d& n, double tolerance_deg)
{
  const double z = std::abs (n.z ());
  if (z <= std::sin (tolerance_deg * kDegree))
    return Vertical;
  if (z >= std::cos (tolerance_deg * kDegree))
    return Horizontal;
  return Other;
}

// Largest first: support, then extent, then input order (a stable, total order).
std::vector<int>
bySize (const std::vector<RegistrationPlane>& planes)
{
  std::vector<int> order (planes.size ());
  std::iota (order.begin (), order.end (), 0);
  auto size = [&] (int i) {
    return planes[i].extent.isEmpty () ? 0.0 : planes[i].extent.diagonal ().norm ();
  };
  std::stable_sort (order.begin (), order.end (), [&] (int a, int b) {
    if (planes[a].support != planes[b].support)
      return planes[a].support > planes[b].support;
    return size (a) > size (b);
  });
  return order;
}

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
  return x >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max () : static_cast<std::uint64_t> (x);
}

bool
extentsOverlap (const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double margin)
{
  if (a.isEmpty () || b.isEmpty ())
    return true;
  const Eigen::Vector3d m = Eigen::Vector3d::Constant (margin);
  return (a.min ().array () - m.array () <= b.max ().array ()).all () &&
         (b.min ().array () - m.array () <= a.max ().array ()).all ();
}

struct Candidate
{
  bool valid = false;
  std::vector<PlanePair> matches;
  PlaneTransformationResult estimate;
  std::size_t support = 0;  // inliers of the matched scan planes
  std::uint64_t order = 0;
};

bool
better (const Candidate& a, const Candidate& b)
{
  if (!a.valid || !b.valid)
    return a.valid && !b.valid;
  if (a.matches.size () != b.matches.size ())
    return a.matches.size () > b.matches.size ();
  if (a.estimate.residual_norm != b.estimate.residual_norm)
    return a.estimate.residual_norm < b.estimate.residual_norm;
  return a.order < b.order;
}

// What every worker shares: the planes, the initial sets and their angle tables.
struct Context
{
  const std::vector<RegistrationPlane>& scan;
  const std::vector<RegistrationPlane>& map;
  const PlaneMatchingParameters& p;
  std::vector<int> scan_order;          // all scan planes, largest first (extension order)
  std::vector<int> scan_init, map_init;  // the m and n initial planes
  std::vector<int> scan_class, map_class;
  std::vector<double> scan_angle, map_angle;  // angle between normals, row-major m x m, n x n
  // Extension: the map planes each scan plane may pair with (all of them, or see matchPlanes).
  std::vector<std::vector<int>> reachable;
  std::vector<std::array<int, 4>> subsets;  // the 4-subsets of k pairs, for the distance screen
  // Constraints 1 and 2: bit mp of compatible[(s * n + m) * m + sp] is set when the pair
  // (sp, mp) may join a combination that holds the pair (s, m) (initial plane positions).
  std::vector<std::uint64_t> compatible;
  std::vector<double> scan_triple, map_triple;  // det(n_a, n_b, n_c), row-major m^3, n^3
  // Sets of sign patterns (bit i of a pattern: pair i flipped), kMaxPatternWords words at most:
  // all of them; per index pair (i < j, in order) those flipping one of the two; per index
  // triple (i < j < l, in order) those flipping an odd number of the three.
  std::vector<std::uint64_t> all_patterns, pair_opposite, triple_odd;
  std::vector<Eigen::Vector3d> scan_anchor;   // of the m initial scan planes, as the estimate's
  std::vector<double> scan_anchor_norm;
  double angle_tol, cos_angle_tol, distance_tol, orientation_tol, cos_up_tol;
  double normal_slack;   // largest |R^T n_m - s n_s| of a pair within the angle tolerance
  // Bounds around the guess: its rotation (nearest rotation to its 3 x 3 block), the centre of
  // the scan planes and where the guess puts it; guess_pairs[sp] has bit mp set when the initial
  // pair (sp, mp) passes the necessary conditions of the bounds (all bits without them).
  bool bounded = false;
  Eigen::Matrix3d guess_rotation = Eigen::Matrix3d::Identity ();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero (), guess_centre = Eigen::Vector3d::Zero ();
  double cos_rotation_bound = -1.0, translation_bound = 0.0;
  std::vector<std::uint64_t> guess_pairs;
  bool distance_screen, up_screen, screen;  // the screens of constraint 3 in use (Worker::screen)

  Context (const std::vector<RegistrationPlane>& s, const std::vector<RegistrationPlane>& m,
           const PlaneMatchingParameters& params)
    : scan (s), map (m), p (params)
  {
    angle_tol = p.angle_tolerance_deg * kDegree;
    cos_angle_tol = std::cos (angle_tol);
    distance_tol = p.distance_tolerance;
    orientation_tol = p.orientation_tolerance_deg * kDegree;
    cos_up_tol = std::cos (p.vertical_tolerance_deg * kDegree);
    // |R^T n_m - s n_s|^2 = |n_m|^2 + |n_s|^2 - 2 cos, the norms within 1e-6 of 1 (checkPlanes).
    normal_slack = std::sqrt (2.0 * (1.0 + 1e-6) * (1.0 + 1e-6) - 2.0 * cos_angle_tol) + 1e-9;
    distance_screen = p.residual_constraint && p.k >= 4 && p.model == PlaneTransformationModel::Rigid;
    up_screen = p.residual_constraint && p.vertical_constraint &&
                2.0 * p.vertical_tolerance_deg + p.angle_tolerance_deg < 89.0;
    screen = distance_screen || up_screen;
  }
};

class Worker
{
public:
  explicit Worker (const Context& c) : c_ (c)
  {
    for (auto& outer : outer_)
      outer.setZero ();
    // Which last map planes make the ordered map planes of the first k - 1 pairs a degenerate
    // set, known_ and degenerate_ bits per prefix: the leaves share far fewer map tuples than
    // there are leaves.
    const double prefixes = std::pow (static_cast<double> (c_.map_init.size ()), c_.p.k - 1);
    if (prefixes <= kMaxDegeneracyCache)
    {
      known_.assign (static_cast<std::size_t> (prefixes), 0);
      degenerate_.assign (static_cast<std::size_t> (prefixes), 0);
    }
  }

  // All combinations whose first pair is (scan_init[s0], map_init[m0]).
  void
  run (int s0, int m0, std::uint64_t task)
  {
    order_ = task << 40;
    if (c_.p.vertical_constraint && c_.scan_class[s0] != c_.map_class[m0])
      return;
    if (c_.p.vertical_constraint && c_.scan_class[s0] == Other)
      return;
    if (!(c_.guess_pairs[s0] >> m0 & 1u))
      return;
    s_[0] = s0;
    m_[0] = m0;
    search (1, std::uint64_t (1) << m0);
  }

  PlaneMatchingStatistics stats;
  Candidate best;

private:
  double
  scanAngle (int a, int b) const { return c_.scan_angle[a * c_.scan_init.size () + b]; }
  double
  mapAngle (int a, int b) const { return c_.map_angle[a * c_.map_init.size () + b]; }
  double
  scanTriple (int a, int b, int l) const
  {
    const std::size_t m = c_.scan_init.size ();
    return c_.scan_triple[(a * m + b) * m + l];
  }
  double
  mapTriple (int a, int b, int l) const
  {
    const std::size_t n = c_.map_init.size ();
    return c_.map_triple[(a * n + b) * n + l];
  }

  // Depth-first over the pairs (sp, mp) that extend s_, m_: scan planes in increasing order, map
  // planes in any order, each unused map plane allowed by constraints 1 and 2 with every earlier
  // pair (a bit of Context::compatible), in increasing order. With the degeneracy cache, the
  // last pair is chosen here and degenerate combinations are only counted.
  void
  search (int depth, std::uint64_t used)
  {
    const int k = c_.p.k, m = static_cast<int> (c_.scan_init.size ()), n = static_cast<int> (c_.map_init.size ());
    if (depth >= k || depth >= kMaxK)  // k <= kMaxK: the second test is for the compiler
    {
      leaf ();
      return;
    }
    const std::uint64_t all = n == 64 ? ~std::uint64_t (0) : (std::uint64_t (1) << n) - 1;
    const bool last = depth == k - 1 && !known_.empty ();
    std::size_t prefix = 0;
    if (last)
      for (int i = depth - 1; i >= 0; --i)
        prefix = prefix * n + m_[i];
    for (int sp = s_[depth - 1] + 1; sp <= m - (k - depth); ++sp)
    {
      std::uint64_t candidates = all & ~used;
      for (int i = 0; i < depth && candidates; ++i)
        candidates &= c_.compatible[(static_cast<std::size_t> (s_[i]) * n + m_[i]) * m + sp];
      std::uint64_t degenerate = 0;
      if (last)
      {
        for (std::uint64_t unknown = candidates & ~known_[prefix]; unknown; unknown &= unknown - 1)
        {
          m_[depth] = __builtin_ctzll (unknown);
          if (degenerateMap ())
            degenerate_[prefix] |= std::uint64_t (1) << m_[depth];
        }
        known_[prefix] |= candidates;
        degenerate = degenerate_[prefix];
      }
      for (; candidates; candidates &= candidates - 1)
      {
        const int mp = __builtin_ctzll (candidates);
        if (degenerate >> mp & 1u)
        {
          // Degenerate sets (map normals not spanning 3D) are reported, not solved.
          ++stats.orientation;
          ++stats.degenerate;
          ++order_;
          continue;
        }
        s_[depth] = sp;
        m_[depth] = mp;
        if (last)
          leaf ();
        else
          search (depth + 1, used | (std::uint64_t (1) << mp));
      }
    }
  }

  bool
  estimate (const int* signs, int count, PlaneTransformationResult& result, bool per_pair = false)
  {
    ++stats.estimations;
    return estimatePlaneTransformation (scan_ptr_.data (), map_ptr_.data (), signs, count, c_.p.model,
                                        result, c_.p.min_conditioning, per_pair);
  }

  bool
  withinTolerance (const PlaneTransformationResult& r) const
  {
    return r.valid && r.max_angle <= c_.angle_tol && r.max_distance <= c_.distance_tol &&
           (!c_.p.vertical_constraint || r.transformation (2, 2) >= c_.cos_up_tol * r.scale);
  }

  // The bounds around the guess: the rotation of R_g^T R (cos = (trace - 1) / 2) and the
  // distance between the images of the centre.
  bool
  withinBounds (const PlaneTransformationResult& r) const
  {
    if (!c_.bounded)
      return true;
    const Eigen::Matrix3d rotation = r.transformation.topLeftCorner<3, 3> () / r.scale;
    const double cosine = 0.5 * ((c_.guess_rotation.transpose () * rotation).trace () - 1.0);
    if (!(cosine >= c_.cos_rotation_bound))
      return false;
    const Eigen::Vector3d moved =
        r.transformation.topLeftCorner<3, 3> () * c_.centre + r.transformation.topRightCorner<3, 1> ();
    return (moved - c_.guess_centre).norm () <= c_.translation_bound;
  }

  bool
  extentsAgree (const std::vector<PlanePair>& pairs, const Eigen::Matrix4d& t) const
  {
    if (!c_.p.check_extents)
      return true;
    for (const auto& pair : pairs)
      if (!extentsOverlap (transformPlane (c_.scan[pair.scan], t).extent, c_.map[pair.map].extent,
                           c_.p.extent_margin))
        return false;
    return true;
  }

  // Whether the map normals of m_ fail to span 3D (min_conditioning). The sum runs in pair
  // order, so an ordered map tuple always gives the same answer.
  bool
  degenerateMap () const
  {
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero ();
    for (int i = 0; i < c_.p.k; ++i)
    {
      const Eigen::Vector3d& normal = c_.map[c_.map_init[m_[i]]].normal;
      normal_matrix.noalias () += normal * normal.transpose ();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect (normal_matrix, Eigen::EigenvaluesOnly);
    return !(std::max (0.0, eigen.eigenvalues ()[0]) >= c_.p.min_conditioning * eigen.eigenvalues ()[2]);
  }

  // Constraint 3 screened before the estimate by necessary conditions that need none: a sign
  // pattern that breaks one cannot pass, so its estimate is skipped, and no combination the
  // estimate would accept is rejected.
  // 1. Distance (rigid transform, k >= 4). For any four pairs whose map normals span 3D, lambda_i
  //    = (-1)^i det(the other three normals) gives sum lambda_i n_m,i = 0, which eliminates the
  //    translation: for any point p,
  //      sum lambda_i r_i = sum lambda_i (R^T n_m,i . (a_i - p) - d_m,i),
  //    r_i the distance residual of pair i at its anchor a_i. If the combination passes, |r_i|
  //    <= distance_tol and R^T n_m,i = s_i n_s,i + e_i with |e_i| <= normal_slack, hence
  //      |sum lambda_i (s_i n_s,i . (a_i - p) - d_m,i)| <= sum |lambda_i| (distance_tol +
  //                                                       normal_slack |a_i - p|).
  //    A margin of 1e-9 of the magnitudes involved covers rounding (sum lambda_i n_m,i is zero
  //    only to rounding, times the map coordinates).
  // 2. Up axis (vertical constraint). A near-horizontal pair, both normals within
  //    vertical_tol of the z axes, R within angle_tol, turns the scan's up axis within
  //    2 vertical_tol + angle_tol (< 90 degrees) of the map's times the sign of
  //    s_i n_s,z n_m,z: where that sign is negative, R(2, 2) < 0 and the up test fails.
  void
  prepareScreen ()
  {
    const int k = c_.p.k;
    subsets_ = 0;
    if (c_.distance_screen)
    {
      // The scan side (p the mean of the four anchors) is shared by the leaves of a scan tuple.
      if (!std::equal (s_, s_ + k, screen_scan_))
      {
        std::copy (s_, s_ + k, screen_scan_);
        for (std::size_t t = 0; t < c_.subsets.size (); ++t)
        {
          const auto& index = c_.subsets[t];
          Eigen::Vector3d p = Eigen::Vector3d::Zero ();
          for (int i = 0; i < 4; ++i)
            p += 0.25 * c_.scan_anchor[s_[index[i]]];
          for (int i = 0; i < 4; ++i)
          {
            const Eigen::Vector3d arm = c_.scan_anchor[s_[index[i]]] - p;
            const double q = c_.scan[c_.scan_init[s_[index[i]]]].normal.dot (arm), length = arm.norm ();
            scan_side_[t].q[i] = q;
            scan_side_[t].allowance[i] = c_.distance_tol + c_.normal_slack * length;
            scan_side_[t].magnitude[i] = std::abs (q) + length + c_.scan_anchor_norm[s_[index[i]]];
          }
        }
      }
      for (std::size_t t = 0; t < c_.subsets.size (); ++t)
      {
        const auto& index = c_.subsets[t];
        Subset& sub = subset_[subsets_];
        int n[4];
        for (int i = 0; i < 4; ++i)
          n[i] = m_[index[i]];
        const double lambda[4] = {mapTriple (n[1], n[2], n[3]), -mapTriple (n[0], n[2], n[3]),
                                  mapTriple (n[0], n[1], n[3]), -mapTriple (n[0], n[1], n[2])};
        if (lambda[0] == 0.0 && lambda[1] == 0.0 && lambda[2] == 0.0 && lambda[3] == 0.0)
          continue;  // normals in a plane: no condition
        double bound = 0.0, magnitude = 1.0;
        sub.offset = 0.0;
        for (int i = 0; i < 4; ++i)
        {
          const double dm = map_ptr_[index[i]]->d;
          sub.index[i] = index[i];
          sub.lambda_q[i] = lambda[i] * scan_side_[t].q[i];
          sub.offset += lambda[i] * dm;
          bound += std::abs (lambda[i]) * scan_side_[t].allowance[i];
          magnitude += std::abs (lambda[i]) * (scan_side_[t].magnitude[i] + std::abs (dm));
        }
        sub.bound = bound + 1e-9 * magnitude;
        ++subsets_;
      }
    }
    up_pairs_ = up_flipped_ = 0;
    if (c_.up_screen)
      for (int i = 0; i < k; ++i)
        if (c_.scan_class[s_[i]] == Horizontal)
        {
          up_pairs_ |= 1u << i;
          if (scan_ptr_[i]->normal.z () * map_ptr_[i]->normal.z () < 0.0)
            up_flipped_ |= 1u << i;
        }
  }

  // The screen of the pattern \a mask (bit i set: pair i flipped).
  bool
  passesScreen (unsigned mask) const
  {
    if ((mask ^ up_flipped_) & up_pairs_)
      return false;
    for (int t = 0; t < subsets_; ++t)
    {
      const Subset& sub = subset_[t];
      double sum = -sub.offset;
      for (int i = 0; i < 4; ++i)
        sum += (mask >> sub.index[i] & 1u ? -1.0 : 1.0) * sub.lambda_q[i];
      if (std::abs (sum) > sub.bound)
        return false;
    }
    return true;
  }

  // Whether the pattern \a mask, as the estimate will keep it (mirrored when its affine block
  // has a negative determinant), can pass constraint 3.
  bool
  screen (unsigned mask)
  {
    const int k = c_.p.k;
    if (!screen_ready_)
    {
      prepareScreen ();
      screen_ready_ = true;
    }
    if (c_.p.oriented_normals)
      return passesScreen (mask);
    const bool direct = passesScreen (mask), mirror = passesScreen (mask ^ ((1u << k) - 1));
    if (direct == mirror)
      return direct;
    // det (sum s_i n_s,i n_m,i^T) has the sign of the estimate's affine block (N^-1 is positive
    // definite): it tells which of a pattern and its mirror the estimate keeps.
    if (!outer_ready_)
    {
      for (int i = 0; i < k; ++i)
        outer_[i] = scan_ptr_[i]->normal * map_ptr_[i]->normal.transpose ();
      outer_ready_ = true;
    }
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero ();
    for (int i = 0; i < k; ++i)
      c += (mask >> i & 1u ? -1.0 : 1.0) * outer_[i];
    const double det = c.determinant ();
    return det > 1e-6 ? direct : det < -1e-6 ? mirror : true;
  }

  // A combination that passed constraints 1 and 2: its sign patterns, estimates and extension.
  void
  leaf ()
  {
    const int k = c_.p.k;
    ++stats.orientation;
    const std::uint64_t order = order_++;
    if (known_.empty () && degenerateMap ())
    {
      ++stats.degenerate;
      return;
    }
    scan_ptr_.resize (k);
    map_ptr_.resize (k);
    for (int i = 0; i < k; ++i)
    {
      scan_ptr_[i] = &c_.scan[c_.scan_init[s_[i]]];
      map_ptr_[i] = &c_.map[c_.map_init[m_[i]]];
    }
    screen_ready_ = outer_ready_ = false;

    // The sign patterns to try (bit i of a pattern: pair i flipped), as a bit set over patterns.
    const int words = static_cast<int> (c_.all_patterns.size ());
    std::uint64_t patterns[kMaxPatternWords];
    for (int w = 0; w < words; ++w)
      patterns[w] = c_.p.oriented_normals ? (w == 0) : c_.all_patterns[w];
    auto keep = [&] (const std::uint64_t* set, bool inside) {
      for (int w = 0; w < words; ++w)
        patterns[w] &= inside ? set[w] : ~set[w];
    };
    if (!c_.p.oriented_normals)
    {
      // Signed orientation: each pair (i, j) keeps its relative sign (same or opposite signs)
      // only where the angle of the scan normals, or its supplement, agrees with the map's.
      int t = 0;
      for (int i = 0; i < k; ++i)
        for (int j = i + 1; j < k; ++j, ++t)
        {
          if (!c_.p.orientation_constraint)
            continue;
          const double a = scanAngle (s_[i], s_[j]), b = mapAngle (m_[i], m_[j]);
          const bool same = !(std::abs (a - b) > c_.orientation_tol);
          const bool opposite = !(std::abs ((M_PI - a) - b) > c_.orientation_tol);
          if (!same && !opposite)
            return;
          if (!same || !opposite)
            keep (&c_.pair_opposite[t * words], opposite);
        }
      // Handedness: a rotation keeps the sign of det(n_i, n_j, n_l) of well-spread triples, so
      // of a sign pattern and its mirror image only one can fit: an odd number of the pairs of
      // the triple are flipped exactly where the scan and map determinants differ in sign.
      t = 0;
      for (int i = 0; i < k; ++i)
        for (int j = i + 1; j < k; ++j)
          for (int l = j + 1; l < k; ++l, ++t)
          {
            const double dm = mapTriple (m_[i], m_[j], m_[l]), ds = scanTriple (s_[i], s_[j], s_[l]);
            if (std::abs (dm) < 0.3 || std::abs (ds) < 0.3)
              continue;
            keep (&c_.triple_odd[t * words], (dm > 0.0) != (ds > 0.0));
          }
    }

    bool found = false;
    for (int w = 0; w < words; ++w)
      for (; patterns[w]; patterns[w] &= patterns[w] - 1)
      {
        const unsigned mask = static_cast<unsigned> (64 * w + __builtin_ctzll (patterns[w]));
        int signs[kMaxK];
        for (int i = 0; i < k; ++i)
          signs[i] = (mask >> i) & 1u ? -1 : 1;
        if (c_.screen && !screen (mask))
          continue;
        if (!estimate (signs, k, trial_))
          continue;
        if (!c_.p.oriented_normals && trial_.affine.leftCols<3> ().determinant () < 0.0)
        {
          // A mirror image: the pattern with every sign flipped is the rotation.
          for (int i = 0; i < k; ++i)
            signs[i] = -signs[i];
          if (!estimate (signs, k, trial_))
            continue;
        }
        if (c_.p.residual_constraint && !withinTolerance (trial_))
          continue;
        if (!withinBounds (trial_))
          continue;
        if (!found || trial_.residual_norm < initial_.residual_norm)
        {
          initial_ = trial_;
          std::copy (signs, signs + k, initial_signs_);
          found = true;
        }
      }
    if (!found)
      return;
    pairs_.clear ();
    for (int i = 0; i < k; ++i)
      pairs_.push_back ({c_.scan_init[s_[i]], c_.map_init[m_[i]], initial_signs_[i]});
    if (c_.p.residual_constraint && !extentsAgree (pairs_, initial_.transformation))
      return;
    ++stats.residual;
    extend (order);
  }

  void
  extend (std::uint64_t order)
  {
    used_scan_.assign (c_.scan.size (), 0);
    used_map_.assign (c_.map.size (), 0);
    for (const auto& pair : pairs_)
    {
      used_scan_[pair.scan] = 1;
      used_map_[pair.map] = 1;
    }
    PlaneTransformationResult current = initial_;
    PlaneTransformer mover (current.transformation);
    // A pass that reaches, unchanged, the plane the previous pass last added sees the state that
    // pass saw from there on, so it would add nothing more: it ends there.
    std::size_t last_added = c_.scan_order.size ();
    bool changed = true;
    while (changed)
    {
      changed = false;
      for (std::size_t position = 0; position < c_.scan_order.size (); ++position)
      {
        if (!changed && position == last_added)
          break;
        const int j = c_.scan_order[position];
        if (used_scan_[j])
          continue;
        const std::vector<int>& reachable = c_.reachable[j];
        if (std::all_of (reachable.begin (), reachable.end (), [&] (int i) { return used_map_[i]; }))
          continue;
        // The image of the scan plane, its extent only once a map plane is near enough.
        const Eigen::Vector3d normal = mover.normal (c_.scan[j]);
        const Eigen::Vector3d centroid = mover.point (c_.scan[j].centroid);
        Eigen::AlignedBox3d extent;
        bool have_extent = false;
        int best_map = -1, best_sign = 1;
        double best_score = std::numeric_limits<double>::infinity ();
        for (const int i : reachable)
        {
          if (used_map_[i])
            continue;
          const double dot = normal.dot (c_.map[i].normal);
          const int sign = c_.p.oriented_normals || dot >= 0.0 ? 1 : -1;
          const double cosine = sign * dot;
          if (cosine < c_.cos_angle_tol)
            continue;
          const double distance = std::abs (c_.map[i].signedDistance (centroid));
          if (distance > c_.distance_tol)
            continue;
          if (c_.p.check_extents)
          {
            if (!have_extent)
            {
              extent = mover.extent (c_.scan[j]);
              have_extent = true;
            }
            if (!extentsOverlap (extent, c_.map[i].extent, c_.p.extent_margin))
              continue;
          }
          const double score = std::acos (std::min (1.0, cosine)) / c_.angle_tol + distance / c_.distance_tol;
          if (score < best_score)
          {
            best_score = score;
            best_map = i;
            best_sign = sign;
          }
        }
        if (best_map < 0)
          continue;
        pairs_.push_back ({j, best_map, best_sign});
        scan_ptr_.clear ();
        map_ptr_.clear ();
        signs_.clear ();
        for (const auto& pair : pairs_)
        {
          scan_ptr_.push_back (&c_.scan[pair.scan]);
          map_ptr_.push_back (&c_.map[pair.map]);
          signs_.push_back (pair.sign);
        }
        if (estimate (signs_.data (), static_cast<int> (pairs_.size ()), trial_) && withinTolerance (trial_) &&
            withinBounds (trial_))
        {
          current = trial_;
          mover = PlaneTransformer (current.transformation);
          used_scan_[j] = 1;
          used_map_[best_map] = 1;
          changed = true;
          last_added = position;
        }
        else
          pairs_.pop_back ();
      }
    }
    Candidate candidate;
    candidate.valid = true;
    candidate.order = order;
    candidate.estimate = current;
    candidate.matches = pairs_;
    if (better (candidate, best))
    {
      // Per-pair residuals for the report: only for a new best.
      scan_ptr_.clear ();
      map_ptr_.clear ();
      signs_.clear ();
      for (const auto& pair : pairs_)
      {
        scan_ptr_.push_back (&c_.scan[pair.scan]);
        map_ptr_.push_back (&c_.map[pair.map]);
        signs_.push_back (pair.sign);
      }
      estimate (signs_.data (), static_cast<int> (pairs_.size ()), candidate.estimate, true);
    }
    for (const auto& pair : pairs_)
      candidate.support += c_.scan[pair.scan].support;
    if (better (candidate, best))
      best = std::move (candidate);
  }

  struct Subset
  {
    int index[4];
    double lambda_q[4];  // lambda_i n_s,i . (a_i - p)
    double offset;       // sum lambda_i d_m,i
    double bound;
  };
  struct ScanSide
  {
    double q[4];          // n_s,i . (a_i - p)
    double allowance[4];  // distance_tol + normal_slack |a_i - p|
    double magnitude[4];  // for the rounding margin
  };

  const Context& c_;
  int s_[kMaxK] = {}, m_[kMaxK] = {};
  Subset subset_[kMaxSubsets] = {};
  ScanSide scan_side_[kMaxSubsets] = {};
  int screen_scan_[kMaxK] = {-1, -1, -1, -1, -1, -1, -1, -1};  // the scan tuple of scan_side_
  int subsets_ = 0;
  Eigen::Matrix3d outer_[kMaxK];  // n_s,i n_m,i^T
  bool screen_ready_ = false, outer_ready_ = false;
  unsigned up_pairs_ = 0, up_flipped_ = 0;  // near-horizontal pairs; those whose z signs differ
  std::vector<std::uint64_t> known_, degenerate_;  // degeneracy cache, see the constructor
  int initial_signs_[kMaxK] = {};
  std::uint64_t order_ = 0;
  std::vector<const RegistrationPlane*> scan_ptr_, map_ptr_;
  std::vector<int> signs_;
  std::vector<PlanePair> pairs_;
  std::vector<char> used_scan_, used_map_;
  PlaneTransformationResult trial_, initial_;
};

bool
checkPlanes (const std::vector<RegistrationPlane>& planes, const char* which)
{
  for (std::size_t i = 0; i < planes.size (); ++i)
    if (!planes[i].normal.allFinite () || !std::isfinite (planes[i].d) ||
        std::abs (planes[i].normal.norm () - 1.0) > 1e-6)
    {
      PCL_ERROR ("[pcl_ext::matchPlanes] %s plane %zu is not finite or its normal is not of unit "
                 "length.\n", which, i);
      return false;
    }
  return true;
}
}  // namespace

std::uint64_t
countInitialCombinations (int m, int n, int k)
{
  return saturate (binomial (m, k) * permutations (n, k));
}

bool
checkPlaneMatchingParameters (const PlaneMatchingParameters& p)
{
  const char* bad = nullptr;
  if (p.k < 3 || p.k > kMaxK)
    bad = "k must be in [3, 8]";
  else if (p.scan_initial < p.k || p.scan_initial > kMaxInitial)
    bad = "m (scan planes to initiate) must be in [k, 64]";
  else if (p.map_initial < p.k || p.map_initial > kMaxInitial)
    bad = "n (map planes to initiate) must be in [k, 64]";
  else if (!(p.vertical_tolerance_deg > 0.0 && p.vertical_tolerance_deg < 45.0))
    bad = "the vertical tolerance must be in (0, 45) degrees";
  else if (!(p.orientation_tolerance_deg > 0.0 && p.orientation_tolerance_deg < 90.0))
    bad = "the orientation tolerance must be in (0, 90) degrees";
  else if (!(p.angle_tolerance_deg > 0.0 && p.angle_tolerance_deg < 90.0))
    bad = "the angle tolerance must be in (0, 90) degrees";
  else if (!(p.distance_tolerance > 0.0) || !std::isfinite (p.distance_tolerance))
    bad = "the distance tolerance must be positive and finite";
  else if (!(p.extent_margin >= 0.0) || !std::isfinite (p.extent_margin))
    bad = "the extent margin must be >= 0 and finite";
  else if (!(p.max_rotation_from_guess_deg > 0.0))
    bad = "the rotation bound around the guess must be positive (infinity: no bound)";
  else if (!(p.max_translation_from_guess > 0.0))
    bad = "the translation bound around the guess must be positive (infinity: no bound)";
  else if (p.min_matches < 0)
    bad = "the minimum number of matches must be >= 0";
  else if (!(p.min_conditioning > 0.0 && p.min_conditioning < 1.0))
    bad = "the minimum conditioning must be in (0, 1)";
  if (bad)
  {
    PCL_ERROR ("[pcl_ext::matchPlanes] Invalid parameters: %s.\n", bad);
    return false;
  }
  return true;
}

bool
matchPlanes (const std::vector<RegistrationPlane>& scan, const std::vector<RegistrationPlane>& map,
             const PlaneMatchingParameters& parameters, PlaneMatchingResult& result,
             const Eigen::Matrix4d& guess)
{
  const auto start = std::chrono::steady_clock::now ();
  result = PlaneMatchingResult ();
  if (!checkPlaneMatchingParameters (parameters) || !checkPlanes (scan, "scan") ||
      !checkPlanes (map, "map"))
    return false;
  if (!guess.allFinite ())
  {
    PCL_ERROR ("[pcl_ext::matchPlanes] The guess is not finite.\n");
    return false;
  }
  const int k = parameters.k;
  Context c (scan, map, parameters);
  c.scan_order = bySize (scan);

  // Bounds around the guess. The guess's rotation is the nearest rotation to its 3 x 3 block,
  // and the centre is that of the bounding box of the scan planes' centroids.
  c.bounded = std::isfinite (parameters.max_rotation_from_guess_deg) ||
              std::isfinite (parameters.max_translation_from_guess);
  const double rotation_bound = std::min (parameters.max_rotation_from_guess_deg * kDegree, M_PI);
  const double chord = 2.0 * std::sin (0.5 * rotation_bound);  // |(R - R_g) x| <= chord |x|
  std::vector<char> map_within_reach (map.size (), 1);
  if (c.bounded)
  {
    c.cos_rotation_bound = rotation_bound >= M_PI ? -2.0 : std::cos (rotation_bound);  // -2: any
    c.translation_bound = parameters.max_translation_from_guess;
    Eigen::JacobiSVD<Eigen::Matrix3d> svd (guess.topLeftCorner<3, 3> (), Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d d = Eigen::Matrix3d::Identity ();
    d (2, 2) = (svd.matrixU () * svd.matrixV ().transpose ()).determinant () < 0.0 ? -1.0 : 1.0;
    c.guess_rotation = svd.matrixU () * d * svd.matrixV ().transpose ();
    Eigen::AlignedBox3d centroids, extents;
    for (const auto& plane : scan)
    {
      centroids.extend (plane.centroid);
      extents.extend (plane.extent.isEmpty () ? Eigen::AlignedBox3d (plane.centroid) : plane.extent);
    }
    c.centre = centroids.center ();
    c.guess_centre = guess.topLeftCorner<3, 3> () * c.centre + guess.topRightCorner<3, 1> ();
    // Map planes out of reach: a pair must pass the extent test (residual constraint for the
    // initial pairs, extension always), and a transform within the bounds puts every scan
    // point x within translation_bound + chord |x - centre| of where the guess puts it. A map
    // plane whose extent is farther than that (plus the extent margin) from the guessed image
    // of the scan planes' bounding box can pair with none of them: it neither initiates nor
    // extends, and the n initial map planes are the largest of the others (rigid model: a
    // similarity's scale is not bounded).
    if (parameters.check_extents && parameters.residual_constraint && std::isfinite (c.translation_bound) &&
        parameters.model == PlaneTransformationModel::Rigid)
    {
      Eigen::AlignedBox3d image;
      double radius = 0.0;
      for (int corner = 0; corner < 8; ++corner)
      {
        const Eigen::Vector3d x = extents.corner (static_cast<Eigen::AlignedBox3d::CornerType> (corner));
        image.extend (c.guess_rotation * (x - c.centre) + c.guess_centre);
        radius = std::max (radius, (x - c.centre).norm ());
      }
      const double margin = parameters.extent_margin + c.translation_bound + chord * radius + 1e-6;
      for (std::size_t i = 0; i < map.size (); ++i)
        map_within_reach[i] = extentsOverlap (image, map[i].extent, margin);
    }
  }

  // The initial planes: the largest, among the near-vertical/horizontal ones under constraint 1.
  auto initial = [&] (const std::vector<RegistrationPlane>& planes, int count, std::vector<int>& init,
                      std::vector<int>& classes, const std::vector<char>* allowed) {
    for (const int i : bySize (planes))
    {
      const int cls = classify (planes[i].normal, parameters.vertical_tolerance_deg);
      if (parameters.vertical_constraint && cls == Other)
        continue;
      if (allowed && !(*allowed)[i])
        continue;
      if (static_cast<int> (init.size ()) == count)
        break;
      init.push_back (i);
      classes.push_back (cls);
    }
  };
  initial (scan, parameters.scan_initial, c.scan_init, c.scan_class, nullptr);
  initial (map, parameters.map_initial, c.map_init, c.map_class, &map_within_reach);
  const int m = static_cast<int> (c.scan_init.size ()), n = static_cast<int> (c.map_init.size ());
  auto& stats = result.statistics;
  stats.m = m;
  stats.n = n;
  stats.k = k;
  if (m < k || n < k)
  {
    PCL_ERROR ("[pcl_ext::matchPlanes] %d scan and %d map planes%s%s: at least k = %d of each are "
               "needed.\n", m, n, parameters.vertical_constraint ? " (near-vertical or horizontal)" : "",
               std::count (map_within_reach.begin (), map_within_reach.end (), 0) > 0 ? " within reach of the guess" : "",
               k);
    return false;
  }
  auto angles = [] (const std::vector<RegistrationPlane>& planes, const std::vector<int>& init) {
    std::vector<double> table (init.size () * init.size ());
    for (std::size_t a = 0; a < init.size (); ++a)
      for (std::size_t b = 0; b < init.size (); ++b)
        table[a * init.size () + b] =
            std::acos (std::clamp (planes[init[a]].normal.dot (planes[init[b]].normal), -1.0, 1.0));
    return table;
  };
  for (const int i : c.scan_init)
  {
    const RegistrationPlane& plane = scan[i];
    c.scan_anchor.push_back (plane.centroid - (plane.normal.dot (plane.centroid) - plane.d) * plane.normal);
    c.scan_anchor_norm.push_back (c.scan_anchor.back ().norm ());
  }
  c.scan_angle = angles (scan, c.scan_init);
  c.map_angle = angles (map, c.map_init);
  // Constraint 2 without oriented normals compares the angles of lines, in [0, 90] degrees.
  auto lines = [&] (std::vector<double> table) {
    if (!parameters.oriented_normals)
      for (double& a : table)
        a = std::min (a, M_PI - a);
    return table;
  };
  const std::vector<double> scan_line = lines (c.scan_angle), map_line = lines (c.map_angle);
  c.compatible.assign (static_cast<std::size_t> (m) * n * m, 0);
  for (int s = 0; s < m; ++s)
    for (int t = 0; t < n; ++t)
      for (int sp = 0; sp < m; ++sp)
      {
        std::uint64_t& bits = c.compatible[(static_cast<std::size_t> (s) * n + t) * m + sp];
        for (int mp = 0; mp < n; ++mp)
        {
          if (parameters.vertical_constraint &&
              (c.scan_class[sp] == Other || c.scan_class[sp] != c.map_class[mp]))
            continue;
          if (parameters.orientation_constraint &&
              std::abs (scan_line[s * m + sp] - map_line[t * n + mp]) > c.orientation_tol)
            continue;
          bits |= std::uint64_t (1) << mp;
        }
      }
  // Bounds around the guess, and their necessary conditions on the initial pairs.
  c.guess_pairs.assign (m, n == 64 ? ~std::uint64_t (0) : (std::uint64_t (1) << n) - 1);
  if (c.bounded)
  {
    if (parameters.residual_constraint)
    {
      // An accepted pair has angle(R n_s, s n_m) <= angle_tol and angle(R, R_g) <= the rotation
      // bound, hence angle(R_g n_s, s n_m) <= their sum. For a rigid estimate T within the
      // bounds, |T a - T_g a| <= translation_bound + 2 sin(rotation_bound / 2) |a - centre|
      // for T_g = (R_g, guess_centre - R_g centre), so the anchor a, whose image is within
      // distance_tol of the map plane, has its guessed image within the sum of the two.
      const double reach = std::min (M_PI, rotation_bound + c.angle_tol) + 1e-9;
      const bool by_distance = std::isfinite (c.translation_bound) && parameters.model == PlaneTransformationModel::Rigid;
      for (int sp = 0; sp < m; ++sp)
      {
        const Eigen::Vector3d normal = c.guess_rotation * scan[c.scan_init[sp]].normal;
        const Eigen::Vector3d anchor =
            c.guess_rotation * (c.scan_anchor[sp] - c.centre) + c.guess_centre;
        const double allowance = c.distance_tol + c.translation_bound +
                                 chord * (c.scan_anchor[sp] - c.centre).norm ();
        for (int mp = 0; mp < n; ++mp)
        {
          const RegistrationPlane& target = map[c.map_init[mp]];
          double cosine = normal.dot (target.normal);
          if (!parameters.oriented_normals)
            cosine = std::abs (cosine);
          bool keep = std::acos (std::clamp (cosine, -1.0, 1.0)) <= reach;
          if (keep && by_distance)
            keep = std::abs (target.signedDistance (anchor)) <= allowance * (1.0 + 1e-9) + 1e-9;
          if (!keep)
            c.guess_pairs[sp] &= ~(std::uint64_t (1) << mp);
        }
      }
      for (int s = 0; s < m; ++s)
        for (int t = 0; t < n; ++t)
          for (int sp = 0; sp < m; ++sp)
            c.compatible[(static_cast<std::size_t> (s) * n + t) * m + sp] &= c.guess_pairs[sp];
    }
  }
  auto triples = [] (const std::vector<RegistrationPlane>& planes, const std::vector<int>& init) {
    const std::size_t size = init.size ();
    std::vector<double> table (size * size * size);
    for (std::size_t a = 0; a < size; ++a)
      for (std::size_t b = 0; b < size; ++b)
        for (std::size_t l = 0; l < size; ++l)
          table[(a * size + b) * size + l] =
              planes[init[a]].normal.dot (planes[init[b]].normal.cross (planes[init[l]].normal));
    return table;
  };
  c.scan_triple = triples (scan, c.scan_init);
  c.map_triple = triples (map, c.map_init);
  // Extension under the vertical and residual constraints: every transform it applies keeps the
  // scan's up axis within vertical_tol of the map's, so it changes the elevation of a line by
  // vertical_tol at most, and a pair within angle_tol differs in elevation by angle_tol +
  // vertical_tol at most (plus 1e-4 rad for normals of length 1 +- 1e-6 and rounding). Other
  // map planes are not looked at.
  auto elevation = [] (const RegistrationPlane& plane) {
    return std::asin (std::min (1.0, std::abs (plane.normal.z ()) / plane.normal.norm ()));
  };
  const bool by_elevation = parameters.vertical_constraint && parameters.residual_constraint;
  const double elevation_tol = c.angle_tol + parameters.vertical_tolerance_deg * kDegree + 1e-4;
  c.reachable.resize (scan.size ());
  for (std::size_t j = 0; j < scan.size (); ++j)
    for (std::size_t i = 0; i < map.size (); ++i)
      if (map_within_reach[i] &&
          (!by_elevation || std::abs (elevation (scan[j]) - elevation (map[i])) <= elevation_tol))
        c.reachable[j].push_back (static_cast<int> (i));

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
    for (int j = i + 1; j < k; ++j)
    {
      const auto set = patternSet ([&] (unsigned mask) { return ((mask >> i) ^ (mask >> j)) & 1u; });
      c.pair_opposite.insert (c.pair_opposite.end (), set.begin (), set.end ());
      for (int l = j + 1; l < k; ++l)
      {
        const auto odd =
            patternSet ([&] (unsigned mask) { return ((mask >> i) ^ (mask >> j) ^ (mask >> l)) & 1u; });
        c.triple_odd.insert (c.triple_odd.end (), odd.begin (), odd.end ());
      }
    }

  stats.unconstrained = countInitialCombinations (m, n, k);
  if (parameters.vertical_constraint)
  {
    const int mv = static_cast<int> (std::count (c.scan_class.begin (), c.scan_class.end (), Vertical));
    const int nv = static_cast<int> (std::count (c.map_class.begin (), c.map_class.end (), Vertical));
    double count = 0.0;
    for (int v = 0; v <= k; ++v)
      count += binomial (mv, v) * binomial (m - mv, k - v) * permutations (nv, v) * permutations (n - nv, k - v);
    stats.vertical = saturate (count);
  }
  else
    stats.vertical = stats.unconstrained;

  // Tasks: the first pair of each combination. Dynamic scheduling balances them; the best match
  // set is chosen by a total order that includes the enumeration order, so threads do not matter.
  std::vector<std::pair<int, int>> tasks;
  for (int s0 = 0; s0 <= m - k; ++s0)
    for (int m0 = 0; m0 < n; ++m0)
      tasks.emplace_back (s0, m0);
  int threads = 1;
#ifdef _OPENMP
  threads = parameters.threads == 0 ? omp_get_max_threads () : static_cast<int> (parameters.threads);
#endif
  threads = std::max (1, std::min<int> (threads, static_cast<int> (tasks.size ())));
  std::vector<Worker> workers (threads, Worker (c));
#pragma omp parallel for num_threads (threads) schedule (dynamic, 1)
  for (std::ptrdiff_t t = 0; t < static_cast<std::ptrdiff_t> (tasks.size ()); ++t)
  {
    int id = 0;
#ifdef _OPENMP
    id = omp_get_thread_num ();
#endif
    workers[id].run (tasks[t].first, tasks[t].second, static_cast<std::uint64_t> (t));
  }

  Candidate best;
  for (auto& w : workers)
  {
    stats.orientation += w.stats.orientation;
    stats.degenerate += w.stats.degenerate;
    stats.residual += w.stats.residual;
    stats.estimations += w.stats.estimations;
    if (better (w.best, best))
      best = std::move (w.best);
  }
  stats.seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  const std::size_t needed = parameters.min_matches > 0 ? parameters.min_matches : k;
  if (!best.valid)
  {
    PCL_ERROR ("[pcl_ext::matchPlanes] No combination of %d pairs gave a valid transform (%llu "
               "combinations after the constraints, %llu degenerate).\n", k,
               static_cast<unsigned long long> (stats.orientation),
               static_cast<unsigned long long> (stats.degenerate));
    return false;
  }
  result.matches = best.matches;
  result.estimate = best.estimate;
  if (best.matches.size () < needed)
  {
    PCL_ERROR ("[pcl_ext::matchPlanes] The best match set has %zu pairs, fewer than the %zu "
               "required.\n", best.matches.size (), needed);
    return false;
  }
  result.converged = true;
  return true;
}
}  // namespace pcl_ext
