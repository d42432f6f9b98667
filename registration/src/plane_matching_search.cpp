/*
 * pcl_ext: plane matching, the search over combinations (Khoshelham & Gorte 2009,
 * section 3.3, eq. 13): the initial combinations allowed by constraints 1 and 2, depth
 * first, and for each the sign patterns tried, screened, estimated and the best one
 * extended.
 */
#include "plane_matching_worker.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace plane_matching {
Worker::Worker (const Context& c) : c_ (c)
{
  for (auto& outer : outer_)
    outer.setZero();
  // Which last map planes make the ordered map planes of the first k - 1 pairs a
  // degenerate set, known_ and degenerate_ bits per prefix: the leaves share far fewer
  // map tuples than there are leaves.
  const double prefixes =
      std::pow (static_cast<double> (c_.map_init.size()), c_.p.k - 1);
  if (prefixes <= kMaxDegeneracyCache) {
    known_.assign (static_cast<std::size_t> (prefixes), 0);
    degenerate_.assign (static_cast<std::size_t> (prefixes), 0);
  }
}

// All combinations whose first pair is (scan_init[s0], map_init[m0]).
void
Worker::run (int s0, int m0, std::uint64_t task)
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

// Depth-first over the pairs (sp, mp) that extend s_, m_: scan planes in increasing
// order, map planes in any order, each unused map plane allowed by constraints 1 and 2
// with every earlier pair (a bit of Context::compatible), in increasing order. With the
// degeneracy cache, the last pair is chosen here and degenerate combinations are only
// counted.
void
Worker::search (int depth, std::uint64_t used)
{
  const int k = c_.p.k, m = static_cast<int> (c_.scan_init.size());
  const int n = static_cast<int> (c_.map_init.size());
  if (depth >= k || depth >= kMaxK) // k <= kMaxK: the second test is for the compiler
  {
    leaf();
    return;
  }
  const std::uint64_t all = n == 64 ? ~std::uint64_t (0) : (std::uint64_t (1) << n) - 1;
  const bool last = depth == k - 1 && !known_.empty();
  std::size_t prefix = 0;
  if (last)
    for (int i = depth - 1; i >= 0; --i)
      prefix = prefix * n + m_[i];
  for (int sp = s_[depth - 1] + 1; sp <= m - (k - depth); ++sp) {
    std::uint64_t candidates = all & ~used;
    for (int i = 0; i < depth && candidates; ++i)
      candidates &=
          c_.compatible[(static_cast<std::size_t> (s_[i]) * n + m_[i]) * m + sp];
    std::uint64_t degenerate = 0;
    if (last) {
      for (std::uint64_t unknown = candidates & ~known_[prefix]; unknown;
           unknown &= unknown - 1) {
        m_[depth] = __builtin_ctzll (unknown);
        if (degenerateMap())
          degenerate_[prefix] |= std::uint64_t (1) << m_[depth];
      }
      known_[prefix] |= candidates;
      degenerate = degenerate_[prefix];
    }
    for (; candidates; candidates &= candidates - 1) {
      const int mp = __builtin_ctzll (candidates);
      if (degenerate >> mp & 1u) {
        // Degenerate sets (map normals not spanning 3D) are reported, not solved.
        ++stats.orientation;
        ++stats.degenerate;
        ++order_;
        continue;
      }
      s_[depth] = sp;
      m_[depth] = mp;
      if (last)
        leaf();
      else
        search (depth + 1, used | (std::uint64_t (1) << mp));
    }
  }
}

// Whether the map normals of m_ fail to span 3D (min_conditioning). The sum runs in
// pair order, so an ordered map tuple always gives the same answer.
bool
Worker::degenerateMap() const
{
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  for (int i = 0; i < c_.p.k; ++i) {
    const Eigen::Vector3d& normal = c_.map[c_.map_init[m_[i]]].normal;
    normal_matrix.noalias() += normal * normal.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect (normal_matrix, Eigen::EigenvaluesOnly);
  return !(std::max (0.0, eigen.eigenvalues()[0]) >=
           c_.p.min_conditioning * eigen.eigenvalues()[2]);
}

// A combination that passed constraints 1 and 2: its sign patterns, estimates and
// extension.
void
Worker::leaf()
{
  const int k = c_.p.k;
  ++stats.orientation;
  const std::uint64_t order = order_++;
  if (known_.empty() && degenerateMap()) {
    ++stats.degenerate;
    return;
  }
  scan_ptr_.resize (k);
  map_ptr_.resize (k);
  for (int i = 0; i < k; ++i) {
    scan_ptr_[i] = &c_.scan[c_.scan_init[s_[i]]];
    map_ptr_[i] = &c_.map[c_.map_init[m_[i]]];
  }
  screen_ready_ = outer_ready_ = false;

  // The sign patterns to try (bit i of a pattern: pair i flipped), as a bit set over
  // patterns.
  const int words = static_cast<int> (c_.all_patterns.size());
  std::uint64_t patterns[kMaxPatternWords];
  for (int w = 0; w < words; ++w)
    patterns[w] = c_.p.oriented_normals ? (w == 0) : c_.all_patterns[w];
  auto keep = [&] (const std::uint64_t* set, bool inside) {
    for (int w = 0; w < words; ++w)
      patterns[w] &= inside ? set[w] : ~set[w];
  };
  if (!c_.p.oriented_normals) {
    // Signed orientation: each pair (i, j) keeps its relative sign (same or opposite
    // signs) only where the angle of the scan normals, or its supplement, agrees with
    // the map's.
    int t = 0;
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j, ++t) {
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
    // Handedness: a rotation keeps the sign of det(n_i, n_j, n_l) of well-spread
    // triples, so of a sign pattern and its mirror image only one can fit: an odd
    // number of the pairs of the triple are flipped exactly where the scan and map
    // determinants differ in sign.
    t = 0;
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j)
        for (int l = j + 1; l < k; ++l, ++t) {
          const double dm = mapTriple (m_[i], m_[j], m_[l]),
                       ds = scanTriple (s_[i], s_[j], s_[l]);
          if (std::abs (dm) < 0.3 || std::abs (ds) < 0.3)
            continue;
          keep (&c_.triple_odd[t * words], (dm > 0.0) != (ds > 0.0));
        }
  }

  bool found = false;
  for (int w = 0; w < words; ++w)
    for (; patterns[w]; patterns[w] &= patterns[w] - 1) {
      const unsigned mask =
          static_cast<unsigned> (64 * w + __builtin_ctzll (patterns[w]));
      int signs[kMaxK];
      for (int i = 0; i < k; ++i)
        signs[i] = (mask >> i) & 1u ? -1 : 1;
      if (c_.screen && !screen (mask))
        continue;
      if (!estimate (signs, k, trial_))
        continue;
      if (!c_.p.oriented_normals && trial_.affine.leftCols<3>().determinant() < 0.0) {
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
      if (!found || trial_.residual_norm < initial_.residual_norm) {
        initial_ = trial_;
        std::copy (signs, signs + k, initial_signs_);
        found = true;
      }
    }
  if (!found)
    return;
  pairs_.clear();
  for (int i = 0; i < k; ++i)
    pairs_.push_back ({c_.scan_init[s_[i]], c_.map_init[m_[i]], initial_signs_[i]});
  if (c_.p.residual_constraint && !extentsAgree (pairs_, initial_.transformation))
    return;
  ++stats.residual;
  extend (order);
}
} // namespace plane_matching
} // namespace pcl_ext
