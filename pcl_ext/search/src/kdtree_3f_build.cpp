/*
 * pcl_ext: the k-d tree of a KdTree3f built with its subtrees on several threads.
 */
#include "kdtree_3f_impl.h"

#include <algorithm>

namespace pcl_ext {
namespace search {
namespace detail {
namespace {
using Node = Tree::Node;
using BoundingBox = Tree::BoundingBox;

/** A node of the top levels, split as nanoflann's divideTree splits, or a part below
 * them (node null) that one thread builds whole. */
struct Planned {
  Node* node = nullptr;
  std::size_t left = 0, right = 0;
  BoundingBox box;                   // a part's: tightened to its points by its build
  Tree::Dimension cut = 0;           // a node's split axis
  std::size_t first = 0, second = 0; // a node's children in the plan
  Node* part_root = nullptr;
};

/** Plans [left, right): \a levels more levels of nodes split here, then parts. Returns
 * the entry's place in \a plan. */
std::size_t
planTop (Tree& tree,
         std::size_t left,
         std::size_t right,
         const BoundingBox& box,
         unsigned int levels,
         std::vector<Planned>& plan)
{
  const std::size_t at = plan.size();
  plan.emplace_back();
  plan[at].left = left;
  plan[at].right = right;
  plan[at].box = box;
  if (levels == 0 || right - left <= tree.m_leaf_max_size)
    return at;
  std::size_t idx;
  Tree::Dimension cut;
  float cutval;
  tree.middleSplit_ (tree, left, right - left, idx, cut, cutval, box);
  BoundingBox left_box (box), right_box (box);
  left_box[cut].high = cutval;
  right_box[cut].low = cutval;
  Node* node = tree.pool.template allocate<Node>();
  node->node_type.sub.divfeat = cut;
  const std::size_t first =
      planTop (tree, left, left + idx, left_box, levels - 1, plan);
  const std::size_t second =
      planTop (tree, left + idx, right, right_box, levels - 1, plan);
  plan[at].node = node;
  plan[at].cut = cut;
  plan[at].first = first;
  plan[at].second = second;
  return at;
}

/** Links the planned node \a at to its children, as divideTree does once they are
 * built, and leaves its box tightened to its points. Returns its root. */
Node*
linkTop (std::size_t at, std::vector<Planned>& plan)
{
  Planned& p = plan[at];
  if (!p.node)
    return p.part_root;
  Node* const first = linkTop (p.first, plan);
  Node* const second = linkTop (p.second, plan);
  const BoundingBox& left_box = plan[p.first].box;
  const BoundingBox& right_box = plan[p.second].box;
  p.node->child1 = first;
  p.node->child2 = second;
  p.node->node_type.sub.divlow = left_box[p.cut].high;
  p.node->node_type.sub.divhigh = right_box[p.cut].low;
  for (std::size_t d = 0; d < 3; ++d) {
    p.box[d].low = std::min (left_box[d].low, right_box[d].low);
    p.box[d].high = std::max (left_box[d].high, right_box[d].high);
  }
  return p.node;
}
} // namespace

void
buildTree (Tree& tree, std::vector<std::unique_ptr<Tree>>& parts, unsigned int threads)
{
  parts.clear();
  const std::size_t n = tree.dataset.kdtree_get_point_count();
  if (threads < 2 || n < 65536) {
    tree.buildIndex();
    return;
  }
  // As Tree::buildIndex, with the subtrees below the top levels (about four per thread)
  // built in parallel, each from its own copy of the positions into its own node pool:
  // every split is the one the serial build makes, so the tree is the same.
  tree.init_vind();
  tree.freeIndex (tree);
  tree.m_size_at_index_build = tree.m_size;
  tree.computeBoundingBox (tree.root_bbox);
  unsigned int levels = 0;
  while ((1u << levels) < 4 * threads && levels < 6)
    ++levels;
  std::vector<Planned> plan;
  planTop (tree, 0, n, tree.root_bbox, levels, plan);
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < plan.size(); ++i)
    if (!plan[i].node)
      todo.push_back (i);
  parts.resize (todo.size());
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (todo.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1) default(none)       \
    shared(tree, parts, plan, todo, count)
  for (std::ptrdiff_t t = 0; t < count; ++t) {
    Planned& p = plan[todo[static_cast<std::size_t> (t)]];
    parts[t].reset (new Tree (
        3,
        tree.dataset,
        nanoflann::KDTreeSingleIndexAdaptorParams (
            tree.m_leaf_max_size,
            nanoflann::KDTreeSingleIndexAdaptorFlags::SkipInitialBuildIndex)));
    Tree& part = *parts[t];
    // Positions below p.left are never read: only the part's are copied.
    part.vAcc.resize (p.right);
    std::copy (tree.vAcc.begin() + p.left,
               tree.vAcc.begin() + p.right,
               part.vAcc.begin() + p.left);
    p.part_root = part.divideTree (part, p.left, p.right, p.box);
    std::copy (part.vAcc.begin() + p.left,
               part.vAcc.begin() + p.right,
               tree.vAcc.begin() + p.left);
    part.vAcc = std::vector<std::uint32_t>();
  }
  tree.root_node = linkTop (0, plan);
  tree.root_bbox = plan[0].box;
}
} // namespace detail
} // namespace search
} // namespace pcl_ext
