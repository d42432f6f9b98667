/*
 * pcl_ext: the state of a KdTree3f, shared by its build and its searches (internal).
 */
#pragma once

#include <pcl_ext/search/kdtree_3f.h>

#include <nanoflann.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace pcl_ext {
namespace search {
namespace detail {
/** nanoflann dataset adaptor over a flat xyz array. */
struct FlatCloud {
  std::vector<float> xyz;

  std::size_t
  kdtree_get_point_count () const
  {
    return xyz.size() / 3;
  }

  float
  kdtree_get_pt (std::size_t i, std::size_t dim) const
  {
    return xyz[3 * i + dim];
  }

  template <class BoundingBox>
  bool
  kdtree_get_bbox (BoundingBox&) const
  {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, FlatCloud>,
                                        FlatCloud,
                                        3,
                                        std::uint32_t>;

/** Builds \a tree (made with SkipInitialBuildIndex) as its buildIndex() does, the
 * subtrees below its top levels on up to \a threads threads; their nodes live in the
 * pools of \a parts, which must live as long as the tree. */
void
buildTree (Tree& tree, std::vector<std::unique_ptr<Tree>>& parts, unsigned int threads);
} // namespace detail

struct KdTree3f::Impl {
  detail::FlatCloud data;
  std::vector<pcl::index_t> point_indices; // tree position -> caller's point index
  std::unique_ptr<detail::Tree> tree;
  std::vector<std::unique_ptr<detail::Tree>> parts; // own nodes of the tree
  std::uint64_t generation = 0; // a build number unique in the process
};
} // namespace search
} // namespace pcl_ext
