/*
 * pcl_ext: the graph of profile edges and its segments (Sithole & Mapurisa, section 2.3
 * and 3).
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcl_ext {
namespace profiles {
/** \brief An edge of the profile graph between two points (indices into the points
 * given). */
struct GraphEdge {
  std::uint32_t source;
  std::uint32_t target;
};

/** \brief Segments of the profile graph G(V, E): the connected components of the union
 * of the edges of every stack (section 3).
 *
 * Breakpoints are the curve ends found by curve fitting (section 4.1.2). Their edges
 * are left out of the components, so that a crease seen by one stack separates the
 * surfaces even where another stack's profile runs along the crease and links across
 * it. Each breakpoint then joins the segment most of its already labelled graph
 * neighbours belong to (ties: the lower segment), wave after wave from the regular
 * points inwards; breakpoints no wave reaches form components of their own. \param[in]
 * num_points number of vertices \param[in] stack_edges the edges of each stack
 * \param[in] breakpoints one flag per vertex, or empty for none
 * \param[out] labels component of each vertex, numbered 0.. in order of first vertex
 * \return the number of components */
std::size_t
labelSegments (std::size_t num_points,
               const std::vector<std::vector<GraphEdge>>& stack_edges,
               const std::vector<std::uint8_t>& breakpoints,
               std::vector<std::uint32_t>& labels);

/** \brief Called with every edge (source, target). */
using EdgeVisitor = std::function<void (std::uint32_t, std::uint32_t)>;
/** \brief Calls its visitor with every edge of every stack, stack after stack, in the
 * same order every time it is called. */
using ForEachEdge = std::function<void (const EdgeVisitor&)>;

/** \brief labelSegments over edges that are not held: \a for_each_edge streams them
 * (from files, say) up to three times. Besides the labels it holds about 9 bytes a
 * point, and the edges of the points that join a segment through the waves (the
 * breakpoints and the components without interior) with their neighbours. The same
 * labels as labelSegments over the same edges in the same order. */
std::size_t
labelSegments (std::size_t num_points,
               const ForEachEdge& for_each_edge,
               const std::vector<std::uint8_t>& breakpoints,
               std::vector<std::uint32_t>& labels);
} // namespace profiles
} // namespace pcl_ext
