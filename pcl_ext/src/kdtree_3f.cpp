/*
 * pcl_ext: KdTree3f, a k-d tree over float coordinates stored in leaf order.
 */
#include <pcl_ext/search/kdtree_3f.h>

#include <nanoflann.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace pcl_ext
{
namespace search
{
namespace
{
/** nanoflann dataset adaptor over a flat xyz array. */
struct FlatCloud
{
  std::vector<float> xyz;

  std::size_t
  kdtree_get_point_count () const { return xyz.size () / 3; }

  float
  kdtree_get_pt (std::size_t i, std::size_t dim) const { return xyz[3 * i + dim]; }

  template <class BoundingBox>
  bool
  kdtree_get_bbox (BoundingBox&) const { return false; }
};

/** nanoflann's sorted k-nearest result set, with an optional starting bound on the distance.
  *
  * nanoflann cannot prune until k candidates are found, so every query first walks whole
  * sibling subtrees. A caller that knows at least k points lie within some distance (for
  * instance from the previous, nearby query) passes it as \a bound, and pruning starts at
  * once. The result is the same: points beyond the bound cannot be among the k nearest.
  */
class BoundedKnnResultSet
{
public:
  BoundedKnnResultSet (std::uint32_t* positions, float* dists, std::size_t capacity, float bound)
    : positions_ (positions), dists_ (dists), capacity_ (capacity), bound_ (bound)
  {}

  std::size_t size () const { return count_; }
  bool full () const { return count_ == capacity_; }

  float
  worstDist () const
  {
    return count_ < capacity_ ? bound_ : std::min (bound_, dists_[capacity_ - 1]);
  }

  bool
  addPoint (float dist, std::uint32_t pos)
  {
    // Sorted insertion; equal distances keep the first found first.
    std::size_t i = count_;
    for (; i > 0 && dists_[i - 1] > dist; --i)
      if (i < capacity_)
      {
        dists_[i] = dists_[i - 1];
        positions_[i] = positions_[i - 1];
      }
    if (i < capacity_)
    {
      dists_[i] = dist;
      positions_[i] = pos;
    }
    if (count_ < capacity_)
      ++count_;
    return true;
  }

private:
  std::uint32_t* positions_;
  float* dists_;
  std::size_t capacity_;
  float bound_;
  std::size_t count_ = 0;
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<float, FlatCloud>, FlatCloud, 3, std::uint32_t>;
/** Spreads the low 10 bits of x so that two zero bits separate each (3D Morton interleave). */
std::uint32_t
spreadBits (std::uint32_t x)
{
  x &= 0x3ff;
  x = (x | (x << 16)) & 0x030000ff;
  x = (x | (x << 8)) & 0x0300f00f;
  x = (x | (x << 4)) & 0x030c30c3;
  x = (x | (x << 2)) & 0x09249249;
  return x;
}

/** Reorders points (and their indices) along a Z-order curve over a 1024^3 grid of their
  * bounding box. nanoflann's build then reads nearby memory when it partitions a subtree,
  * which halves its time on clouds stored in arbitrary order. LSD radix sort: linear, stable,
  * deterministic. */
void
sortAlongZOrder (std::vector<float>& xyz, std::vector<pcl::index_t>& ids)
{
  const std::size_t n = ids.size ();
  if (n < 2)
    return;
  float lo[3], hi[3];
  for (int d = 0; d < 3; ++d)
    lo[d] = hi[d] = xyz[d];
  for (std::size_t i = 1; i < n; ++i)
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::min (lo[d], xyz[3 * i + d]);
      hi[d] = std::max (hi[d], xyz[3 * i + d]);
    }
  double scale[3];
  for (int d = 0; d < 3; ++d)
    scale[d] = hi[d] > lo[d] ? 1023.0 / (static_cast<double> (hi[d]) - lo[d]) : 0.0;
  std::vector<std::uint32_t> code (n), order (n), code_tmp (n), order_tmp (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    std::uint32_t c = 0;
    for (int d = 0; d < 3; ++d)
      c |= spreadBits (static_cast<std::uint32_t> ((xyz[3 * i + d] - lo[d]) * scale[d])) << d;
    code[i] = c;
    order[i] = static_cast<std::uint32_t> (i);
  }
  for (int shift = 0; shift < 32; shift += 8)
  {
    std::size_t count[257] = {0};
    for (std::size_t i = 0; i < n; ++i)
      ++count[((code[i] >> shift) & 0xff) + 1];
    for (int b = 0; b < 256; ++b)
      count[b + 1] += count[b];
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t dst = count[(code[i] >> shift) & 0xff]++;
      code_tmp[dst] = code[i];
      order_tmp[dst] = order[i];
    }
    code.swap (code_tmp);
    order.swap (order_tmp);
  }
  std::vector<float> sorted_xyz (3 * n);
  std::vector<pcl::index_t> sorted_ids (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    std::copy_n (&xyz[3 * order[i]], 3, &sorted_xyz[3 * i]);
    sorted_ids[i] = ids[order[i]];
  }
  xyz.swap (sorted_xyz);
  ids.swap (sorted_ids);
}
}  // namespace

struct KdTree3f::Impl
{
  FlatCloud data;
  std::vector<pcl::index_t> point_indices;  // tree position -> caller's point index
  std::unique_ptr<Tree> tree;
};

KdTree3f::KdTree3f () : impl_ (new Impl) {}

KdTree3f::~KdTree3f () = default;

void
KdTree3f::build (std::vector<float> xyz, std::vector<pcl::index_t> point_indices,
                 unsigned int leaf_size)
{
  impl_->tree.reset ();
  sortAlongZOrder (xyz, point_indices);
  impl_->data.xyz = std::move (xyz);
  impl_->point_indices = std::move (point_indices);
  const std::size_t n = impl_->data.kdtree_get_point_count ();
  if (n == 0)
    return;
  impl_->tree.reset (new Tree (3, impl_->data,
                               nanoflann::KDTreeSingleIndexAdaptorParams (std::max (1u, leaf_size))));

  // Reorder the coordinates into the tree's leaf order and make the tree's permutation the
  // identity: a leaf's points then sit next to each other in memory, and so do the points of
  // nearby leaves, which is what makes a whole-cloud neighbourhood pass cache friendly.
  auto& order = impl_->tree->vAcc;
  std::vector<float> sorted_xyz (3 * n);
  std::vector<pcl::index_t> sorted_indices (n);
  for (std::size_t pos = 0; pos < n; ++pos)
  {
    const std::size_t old = order[pos];
    std::copy_n (&impl_->data.xyz[3 * old], 3, &sorted_xyz[3 * pos]);
    sorted_indices[pos] = impl_->point_indices[old];
    order[pos] = static_cast<std::uint32_t> (pos);
  }
  impl_->data.xyz.swap (sorted_xyz);
  impl_->point_indices.swap (sorted_indices);
}

std::size_t
KdTree3f::size () const
{
  return impl_->tree ? impl_->point_indices.size () : 0;
}

std::size_t
KdTree3f::nearestKSearch (const float* query, std::size_t k, pcl::index_t* indices,
                          float* sqr_distances, float bound) const
{
  if (!impl_->tree || k == 0)
    return 0;
  k = std::min (k, size ());
  // nanoflann writes tree positions; map them to point indices in place.
  static_assert (sizeof (pcl::index_t) == sizeof (std::uint32_t), "index width");
  auto* positions = reinterpret_cast<std::uint32_t*> (indices);
  BoundedKnnResultSet result (positions, sqr_distances, k, bound);
  impl_->tree->findNeighbors (result, query, nanoflann::SearchParams ());
  std::size_t found = result.size ();
  if (found < k && bound < std::numeric_limits<float>::max ())
  {
    // The caller's bound was wrong (fewer than k points inside it): search again without it.
    BoundedKnnResultSet unbounded (positions, sqr_distances, k,
                                   std::numeric_limits<float>::max ());
    impl_->tree->findNeighbors (unbounded, query, nanoflann::SearchParams ());
    found = unbounded.size ();
  }
  for (std::size_t i = 0; i < found; ++i)
    indices[i] = impl_->point_indices[positions[i]];
  return found;
}

std::size_t
KdTree3f::radiusSearch (const float* query, double radius, pcl::Indices& indices,
                        std::vector<float>& sqr_distances, std::size_t max_nn,
                        bool sorted) const
{
  indices.clear ();
  sqr_distances.clear ();
  if (!impl_->tree || !(radius > 0.0))
    return 0;
  std::vector<std::pair<std::uint32_t, float>> matches;
  nanoflann::SearchParams params;
  params.sorted = sorted || max_nn > 0;
  impl_->tree->radiusSearch (query, static_cast<float> (radius * radius), matches, params);
  if (max_nn > 0 && matches.size () > max_nn)
    matches.resize (max_nn);
  indices.resize (matches.size ());
  sqr_distances.resize (matches.size ());
  for (std::size_t i = 0; i < matches.size (); ++i)
  {
    indices[i] = impl_->point_indices[matches[i].first];
    sqr_distances[i] = matches[i].second;
  }
  return matches.size ();
}

const float*
KdTree3f::point (std::size_t pos) const
{
  return &impl_->data.xyz[3 * pos];
}

pcl::index_t
KdTree3f::pointIndex (std::size_t pos) const
{
  return impl_->point_indices[pos];
}
}  // namespace search
}  // namespace pcl_ext
