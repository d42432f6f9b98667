/*
 * pcl_ext: KdTree3f::nearestKSearchOfPoints, the k nearest neighbours of a run of tree
 * points found together.
 */
#include "kdtree_3f_impl.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace pcl_ext {
namespace search {
namespace {
/** nanoflann result set that keeps every point within a fixed squared radius, unsorted.
 */
class CollectingResultSet {
public:
  CollectingResultSet (std::vector<std::uint32_t>& positions, float sqr_radius)
  : positions_ (positions), sqr_radius_ (sqr_radius)
  {
    positions_.clear();
  }

  std::size_t
  size () const
  {
    return positions_.size();
  }
  bool
  full () const
  {
    return true;
  }
  float
  worstDist () const
  {
    return sqr_radius_;
  }

  bool
  addPoint (float, std::uint32_t pos)
  {
    positions_.push_back (pos);
    return true;
  }

private:
  std::vector<std::uint32_t>& positions_;
  float sqr_radius_;
};

/** Buckets of the counting sorts on squared distance. */
constexpr std::size_t num_buckets = 64;

/** A query's first, tighter limit: r_p + guess_share * |q - p| for the nearest ranked
 * point p, where r_p + |q - p| is the bound the k-th distance cannot exceed. Within a
 * leaf the k-th distance changes far less than the points' separation (neighbouring
 * points share most neighbours), so the tighter limit nearly always holds k candidates
 * and leaves fewer to sort; when it does not, the query is ranked again under the
 * bound. 0.15-0.3 were equally fast on the 1M-point indoor scene (docs/benchmarks.md).
 */
constexpr float guess_share = 0.25f;

/** Scratch space of nearestKSearchOfPoints, one per thread so that calls need no
 * allocation once warm. */
struct BatchScratch {
  std::vector<std::uint32_t> candidates;
  std::vector<float> x, y, z, sqr_dist;
  std::vector<std::uint64_t> keys, sorted;
  std::vector<std::uint8_t> buckets;
  std::vector<std::uint32_t> sorted_candidates;
  std::size_t shell_end[num_buckets];
  float shell_scale = 0.0f;
  std::vector<pcl::index_t> first_indices;
  std::vector<float> first_sqr_dist;
  std::vector<std::size_t> done_pos;
  std::vector<float> done_kth;
  // The last anchor, to bound the next one's search: its tree (pointer and build), k,
  // k-th distance and coordinates.
  const void* tree = nullptr;
  std::uint64_t generation = 0;
  std::size_t anchor_k = 0;
  float anchor_kth = 0.0f;
  float anchor[3] = {0.0f, 0.0f, 0.0f};
};

/** Squared distance (non-negative, so its bits order like the value) above, the point's
 * index in the cloud below: sorting the keys orders by distance, then by index, so that
 * ties are broken the same way by any tree over the same points. */
inline std::uint64_t
rankKey (float sqr_dist, pcl::index_t index)
{
  std::uint32_t bits;
  std::memcpy (&bits, &sqr_dist, sizeof (bits));
  return (static_cast<std::uint64_t> (bits) << 32) | static_cast<std::uint32_t> (index);
}

inline float
keyDistance (std::uint64_t key)
{
  const auto bits = static_cast<std::uint32_t> (key >> 32);
  float d;
  std::memcpy (&d, &bits, sizeof (d));
  return d;
}

/** Copies the candidates' coordinates into one array per axis, so that ranking them
 * against a query is a loop the compiler vectorises. */
void
gatherCoordinates (const std::vector<float>& xyz, BatchScratch& s)
{
  const std::size_t m = s.candidates.size();
  s.x.resize (m);
  s.y.resize (m);
  s.z.resize (m);
  for (std::size_t i = 0; i < m; ++i) {
    const float* p = &xyz[3 * static_cast<std::size_t> (s.candidates[i])];
    s.x[i] = p[0];
    s.y[i] = p[1];
    s.z[i] = p[2];
  }
}

/** Bucket of a squared distance among num_buckets equal-width buckets of [0, limit],
 * given scale = num_buckets / limit; anything beyond the limit goes to the last. */
inline std::size_t
bucketOf (float sqr_dist, float scale)
{
  // Clamped in float, then a 32-bit conversion: no branch in the callers' loops (about
  // half the candidates lie beyond the limit, a branch the processor cannot predict;
  // compilers branch on std::min here, so the minimum is taken by the instruction).
#if defined(__SSE__)
  const float b =
      _mm_cvtss_f32 (_mm_min_ss (_mm_set_ss (sqr_dist * scale),
                                 _mm_set_ss (static_cast<float> (num_buckets - 1))));
#else
  const float b = std::min (sqr_dist * scale, static_cast<float> (num_buckets - 1));
#endif
  return static_cast<std::size_t> (static_cast<std::int32_t> (b));
}

/** Orders the candidates by shells of squared distance from the anchor \a a (a counting
 * sort over equal-width buckets of [0, sqr_radius]) and records where each shell ends,
 * so that a query needing only the candidates within some distance of the anchor ranks
 * a prefix of them. */
void
orderByShells (const std::vector<float>& xyz,
               const float* a,
               float sqr_radius,
               BatchScratch& s)
{
  const std::size_t m = s.candidates.size();
  const float scale = static_cast<float> (num_buckets) / sqr_radius;
  s.buckets.resize (m);
  std::size_t start[num_buckets + 1] = {0};
  for (std::size_t i = 0; i < m; ++i) {
    const float* p = &xyz[3 * static_cast<std::size_t> (s.candidates[i])];
    const float dx = p[0] - a[0], dy = p[1] - a[1], dz = p[2] - a[2];
    const std::size_t b = bucketOf (dx * dx + dy * dy + dz * dz, scale);
    s.buckets[i] = static_cast<std::uint8_t> (b);
    ++start[b + 1];
  }
  for (std::size_t b = 0; b < num_buckets; ++b)
    start[b + 1] += start[b];
  s.sorted_candidates.resize (m);
  for (std::size_t i = 0; i < m; ++i)
    s.sorted_candidates[start[s.buckets[i]]++] = s.candidates[i];
  // After the scatter, start[b] is where shell b ends.
  std::copy_n (start, num_buckets, s.shell_end);
  s.shell_scale = scale;
  s.candidates.swap (s.sorted_candidates);
  gatherCoordinates (xyz, s);
}

/** The k candidates of \a s nearest to \a q by (squared distance, point index), among
 * those within \a sqr_limit, as keys in s.sorted[0 .. k). Returns false if fewer than k
 * lie within the limit. */
bool
rankCandidates (const float* q,
                std::size_t m,
                std::size_t k,
                float sqr_limit,
                const pcl::index_t* point_indices,
                BatchScratch& s)
{
  s.sqr_dist.resize (m);
  const float qx = q[0], qy = q[1], qz = q[2];
  const float* x = s.x.data();
  const float* y = s.y.data();
  const float* z = s.z.data();
  float* d = s.sqr_dist.data();
  for (std::size_t i = 0; i < m; ++i) {
    const float dx = x[i] - qx, dy = y[i] - qy, dz = z[i] - qz;
    d[i] = dx * dx + dy * dy + dz * dz;
  }
  // Branch-free compaction of those within the limit, each with its bucket of squared
  // distance. On a surface the squared distances of a neighbourhood spread evenly over
  // [0, limit] (area grows with r^2), so equal-width buckets hold one or two each and a
  // counting sort followed by insertion sort orders them in linear time, where a
  // comparison sort of the same keys costs several times more.
  s.keys.resize (m);
  s.buckets.resize (m);
  std::uint64_t* keys = s.keys.data();
  std::uint8_t* buckets = s.buckets.data();
  const std::uint32_t* positions = s.candidates.data();
  const float scale = static_cast<float> (num_buckets) / sqr_limit;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < m; ++i) {
    keys[kept] = rankKey (d[i], point_indices[positions[i]]);
    buckets[kept] = static_cast<std::uint8_t> (bucketOf (d[i], scale));
    kept += d[i] <= sqr_limit;
  }
  if (kept < k)
    return false;

  std::size_t start[num_buckets + 1] = {0};
  for (std::size_t i = 0; i < kept; ++i)
    ++start[buckets[i] + 1];
  std::size_t largest = 0;
  for (std::size_t b = 0; b < num_buckets; ++b) {
    largest = std::max (largest, start[b + 1]);
    start[b + 1] += start[b];
  }
  s.sorted.resize (kept);
  std::uint64_t* sorted = s.sorted.data();
  for (std::size_t i = 0; i < kept; ++i)
    sorted[start[buckets[i]]++] = keys[i];
  if (largest > 32) {
    // Crowded buckets (duplicate points, a limit far above the k-th distance): sort
    // instead.
    std::nth_element (sorted, sorted + (k - 1), sorted + kept);
    std::sort (sorted, sorted + k);
  }
  else
    for (std::size_t i = 1; i < kept; ++i) {
      const std::uint64_t key = sorted[i];
      std::size_t j = i;
      for (; j > 0 && sorted[j - 1] > key; --j)
        sorted[j] = sorted[j - 1];
      sorted[j] = key;
    }
  return true;
}
} // namespace

std::size_t
KdTree3f::nearestKSearchOfPoints (std::size_t first,
                                  std::size_t last,
                                  std::size_t k,
                                  pcl::index_t* indices,
                                  float* sqr_distances) const
{
  if (!impl_->tree || k == 0)
    return 0;
  k = std::min (k, size());
  last = std::min (last, size());
  if (first >= last)
    return k;
  thread_local BatchScratch scratch;
  BatchScratch& s = scratch; // one thread-local lookup, not one per use
  const std::vector<float>& xyz = impl_->data.xyz;
  const auto distance = [] (const float* a, const float* b) {
    const float dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return std::sqrt (dx * dx + dy * dy + dz * dz);
  };

  // The anchor: the point nearest the middle of the run's bounding box.
  float lo[3], hi[3];
  std::copy_n (&xyz[3 * first], 3, lo);
  std::copy_n (&xyz[3 * first], 3, hi);
  for (std::size_t pos = first + 1; pos < last; ++pos)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min (lo[d], xyz[3 * pos + d]);
      hi[d] = std::max (hi[d], xyz[3 * pos + d]);
    }
  const float middle[3] = {
      0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2])};
  std::size_t anchor = first;
  float spread = std::numeric_limits<float>::max();
  for (std::size_t pos = first; pos < last; ++pos) {
    const float d = distance (&xyz[3 * pos], middle);
    if (d < spread) {
      spread = d;
      anchor = pos;
    }
  }
  const float* a = &xyz[3 * anchor];
  spread = 0.0f;
  for (std::size_t pos = first; pos < last; ++pos)
    spread = std::max (spread, distance (&xyz[3 * pos], a));

  // The anchor's exact k-th distance r. The previous anchor this thread searched in
  // this tree bounds it (any bound only prunes; r does not depend on it).
  float hint = std::numeric_limits<float>::max();
  const bool same_tree =
      s.tree == impl_.get() && s.generation == impl_->generation && s.anchor_k == k;
  if (same_tree) {
    const float reach = (s.anchor_kth + distance (a, s.anchor)) * (1.0f + 1e-4f);
    hint = reach * reach + 1e-30f;
  }
  // k or more points at the previous anchor's very position, and this anchor there too:
  // its k nearest are the same, the k of them with the smallest indices (a search would
  // walk every copy, so a stack of m copies would cost m^2).
  const bool on_previous_stack = same_tree && s.anchor_kth == 0.0f &&
                                 std::equal (a, a + 3, s.anchor) &&
                                 s.first_indices.size() == k;
  if (!on_previous_stack) {
    s.first_indices.resize (k);
    s.first_sqr_dist.resize (k);
    nearestKSearch (a, k, s.first_indices.data(), s.first_sqr_dist.data(), hint);
  }
  const float r = std::sqrt (s.first_sqr_dist[k - 1]);
  s.tree = impl_.get();
  s.generation = impl_->generation;
  s.anchor_k = k;
  s.anchor_kth = r;
  std::copy_n (a, 3, s.anchor);
  if (r == 0.0f && spread == 0.0f) {
    // The whole run is a stack of k or more copies of one point: every point's k
    // nearest are the anchor's.
    for (std::size_t pos = first; pos < last; ++pos) {
      std::copy (
          s.first_indices.begin(), s.first_indices.end(), indices + (pos - first) * k);
      std::copy (s.first_sqr_dist.begin(),
                 s.first_sqr_dist.end(),
                 sqr_distances + (pos - first) * k);
    }
    return k;
  }
  // r bounds the k-th distance of every point q of the run by r + |q - anchor|, and all
  // points within that bound of q lie within r + 2 * spread of the anchor: the
  // candidates. Relative margins keep float rounding on the safe side.
  constexpr float margin = 1.0f + 1e-4f;
  const float gather = ((r + spread) * margin + spread) * margin;
  const float sqr_gather = gather * gather + 1e-30f;
  // A run spread wide compared with its neighbourhoods (a leaf straddling sparse
  // points) would share too many candidates: each of its points then finds its own k-th
  // distance and ranks only the points within it.
  bool shared = spread <= 1.5f * r;
  if (shared) {
    CollectingResultSet collect (s.candidates, sqr_gather);
    impl_->tree->findNeighbors (collect, a, nanoflann::SearchParams());
    shared = s.candidates.size() <= 32 * k + 1024;
  }
  if (shared)
    orderByShells (xyz, a, sqr_gather, s);

  // Points are ranked anchor first. Each ranked point p bounds the k-th distance of the
  // next ones by r_p + |q - p| too; the nearest of them gives the tightest limit, and
  // the fewer candidates pass it, the less there is to sort.
  s.done_pos.clear();
  s.done_kth.clear();
  const pcl::index_t* point_indices = impl_->point_indices.data();
  // Ranks the shared candidates within \a limit of q (those within limit + |q - a| of
  // the anchor); false if fewer than k lie within it.
  const auto rankShared = [&] (const float* q, float limit) {
    const float reach = (limit + distance (q, a)) * margin;
    const std::size_t m = s.shell_end[bucketOf (reach * reach, s.shell_scale)];
    return rankCandidates (q, m, k, limit * limit + 1e-30f, point_indices, s);
  };
  // The same for a run whose points search on their own: the points within the limit.
  const auto rankAround = [&] (const float* q, float limit) {
    const float sqr_limit = limit * limit + 1e-30f;
    CollectingResultSet collect (s.candidates, sqr_limit * margin);
    impl_->tree->findNeighbors (collect, q, nanoflann::SearchParams());
    gatherCoordinates (xyz, s);
    return rankCandidates (q, s.candidates.size(), k, sqr_limit, point_indices, s);
  };
  for (std::size_t step = 0; step < last - first; ++step) {
    const std::size_t pos =
        step == 0 ? anchor : first + step - (first + step <= anchor ? 1 : 0);
    const float* q = &xyz[3 * pos];
    float bound = std::numeric_limits<float>::max();
    float guess = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < s.done_pos.size(); ++i) {
      const float d = distance (q, &xyz[3 * s.done_pos[i]]);
      bound = std::min (bound, s.done_kth[i] + d);
      guess = std::min (guess, s.done_kth[i] + guess_share * d);
    }
    pcl::index_t* out_indices = indices + (pos - first) * k;
    float* out_sqr = sqr_distances + (pos - first) * k;
    bool ranked = false;
    if (step == 0)
      ranked = shared ? rankShared (q, r * margin) : rankAround (q, r * margin);
    else if (shared)
      ranked = rankShared (q, guess * margin) || rankShared (q, bound * margin);
    else {
      // The exact k-th distance, by a search that the bound prunes from the start.
      const float reach = bound * margin;
      nearestKSearch (q, k, out_indices, out_sqr, reach * reach + 1e-30f);
      ranked = rankAround (q, std::sqrt (out_sqr[k - 1]) * margin);
    }
    if (ranked)
      for (std::size_t j = 0; j < k; ++j) {
        out_indices[j] =
            static_cast<pcl::index_t> (static_cast<std::uint32_t> (s.sorted[j]));
        out_sqr[j] = keyDistance (s.sorted[j]);
      }
    else // cannot happen with exact arithmetic; stay exact if rounding defeats the
         // margins
      nearestKSearch (q, k, out_indices, out_sqr);
    s.done_pos.push_back (pos);
    s.done_kth.push_back (std::sqrt (out_sqr[k - 1]));
  }
  return k;
}
} // namespace search
} // namespace pcl_ext
