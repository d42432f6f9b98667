/*
 * pcl_ext: KdTree3f, a k-d tree over float coordinates stored in leaf order: its build
 * and its layout. The searches are in kdtree_3f_search.cpp and
 * kdtree_3f_batch_search.cpp.
 */
#include "kdtree_3f_impl.h"

#include <algorithm>
#include <atomic>

namespace pcl_ext {
namespace search {
namespace {
/** Spreads the low 10 bits of x so that two zero bits separate each (3D Morton
 * interleave). */
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

/** Reorders points (and their indices) along a Z-order curve over a 1024^3 grid of
 * their bounding box. nanoflann's build then reads nearby memory when it partitions a
 * subtree, which makes it much faster on clouds stored in arbitrary order
 * (docs/shared_machinery.md). LSD radix sort: linear, stable, deterministic; the codes
 * and the gather on \a threads threads. */
void
sortAlongZOrder (std::vector<float>& xyz,
                 std::vector<pcl::index_t>& ids,
                 unsigned int threads)
{
  const std::size_t n = ids.size();
  if (n < 2)
    return;
  float lo[3], hi[3];
  for (int d = 0; d < 3; ++d)
    lo[d] = hi[d] = xyz[d];
  for (std::size_t i = 1; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min (lo[d], xyz[3 * i + d]);
      hi[d] = std::max (hi[d], xyz[3 * i + d]);
    }
  double scale[3];
  for (int d = 0; d < 3; ++d)
    scale[d] = hi[d] > lo[d] ? 1023.0 / (static_cast<double> (hi[d]) - lo[d]) : 0.0;
  std::vector<std::uint32_t> code (n), order (n), code_tmp (n), order_tmp (n);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    std::uint32_t c = 0;
    for (int d = 0; d < 3; ++d)
      c |= spreadBits (static_cast<std::uint32_t> ((xyz[3 * i + d] - lo[d]) * scale[d]))
           << d;
    code[i] = c;
    order[i] = static_cast<std::uint32_t> (i);
  }
  // The codes have 30 bits: three passes of 10.
  constexpr int digit = 10;
  constexpr std::size_t buckets = std::size_t{1} << digit;
  std::vector<std::size_t> start (buckets + 1);
  for (int shift = 0; shift < 30; shift += digit) {
    std::fill (start.begin(), start.end(), 0);
    for (std::size_t i = 0; i < n; ++i)
      ++start[((code[i] >> shift) & (buckets - 1)) + 1];
    for (std::size_t b = 0; b < buckets; ++b)
      start[b + 1] += start[b];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t dst = start[(code[i] >> shift) & (buckets - 1)]++;
      code_tmp[dst] = code[i];
      order_tmp[dst] = order[i];
    }
    code.swap (code_tmp);
    order.swap (order_tmp);
  }
  std::vector<float> sorted_xyz (3 * n);
  std::vector<pcl::index_t> sorted_ids (n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    std::copy_n (&xyz[3 * static_cast<std::size_t> (order[i])], 3, &sorted_xyz[3 * i]);
    sorted_ids[i] = ids[order[i]];
  }
  xyz.swap (sorted_xyz);
  ids.swap (sorted_ids);
}
} // namespace

KdTree3f::KdTree3f() : impl_ (new Impl) {}

KdTree3f::~KdTree3f() = default;

void
KdTree3f::build (std::vector<float> xyz,
                 std::vector<pcl::index_t> point_indices,
                 unsigned int leaf_size,
                 unsigned int threads)
{
  static std::atomic<std::uint64_t> builds{0};
  impl_->generation = ++builds;
  impl_->tree.reset();
  impl_->parts.clear();
  sortAlongZOrder (xyz, point_indices, std::max (1u, threads));
  impl_->data.xyz = std::move (xyz);
  impl_->point_indices = std::move (point_indices);
  const std::size_t n = impl_->data.kdtree_get_point_count();
  if (n == 0)
    return;
  impl_->tree.reset (new detail::Tree (
      3,
      impl_->data,
      nanoflann::KDTreeSingleIndexAdaptorParams (
          std::max (1u, leaf_size),
          nanoflann::KDTreeSingleIndexAdaptorFlags::SkipInitialBuildIndex)));
  detail::buildTree (*impl_->tree, impl_->parts, std::max (1u, threads));

  // Reorder the coordinates into the tree's leaf order and make the tree's permutation
  // the identity: a leaf's points then sit next to each other in memory, and so do the
  // points of nearby leaves, which is what makes a whole-cloud neighbourhood pass cache
  // friendly.
  auto& order = impl_->tree->vAcc;
  std::vector<float> sorted_xyz (3 * n);
  std::vector<pcl::index_t> sorted_indices (n);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
#pragma omp parallel for num_threads(std::max(1u, threads)) schedule(static)
  for (std::ptrdiff_t pos = 0; pos < count; ++pos) {
    const std::size_t old = order[pos];
    std::copy_n (&impl_->data.xyz[3 * old], 3, &sorted_xyz[3 * pos]);
    sorted_indices[pos] = impl_->point_indices[old];
    order[pos] = static_cast<std::uint32_t> (pos);
  }
  impl_->data.xyz.swap (sorted_xyz);
  impl_->point_indices.swap (sorted_indices);
}

std::size_t
KdTree3f::size() const
{
  return impl_->tree ? impl_->point_indices.size() : 0;
}

std::vector<std::pair<std::size_t, std::size_t>>
KdTree3f::leafRanges() const
{
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  if (!impl_->tree)
    return ranges;
  // Depth first, first child first: leaves come out in position order.
  std::vector<const detail::Tree::Node*> stack{impl_->tree->root_node};
  while (!stack.empty()) {
    const detail::Tree::Node* node = stack.back();
    stack.pop_back();
    if (!node->child1 && !node->child2) {
      ranges.emplace_back (node->node_type.lr.left, node->node_type.lr.right);
      continue;
    }
    if (node->child2)
      stack.push_back (node->child2);
    if (node->child1)
      stack.push_back (node->child1);
  }
  return ranges;
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
} // namespace search
} // namespace pcl_ext
