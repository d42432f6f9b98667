/*
 * pcl_ext_compare_segmenters: CGAL's plane region growing (Shape_detection, CGAL 5.5),
 * with the defaults its manual documents, lengths as multiples of the point spacing s.
 */
#include "segmenter_methods.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <iterator>
#include <utility>

namespace pcl_ext {
namespace compare {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using PointWithNormal = std::pair<Kernel::Point_3, Kernel::Vector_3>;
using Points = std::vector<PointWithNormal>;
using PointMap = CGAL::First_of_pair_property_map<PointWithNormal>;
using NormalMap = CGAL::Second_of_pair_property_map<PointWithNormal>;
using NeighbourQuery =
    CGAL::Shape_detection::Point_set::K_neighbor_query<Kernel, Points, PointMap>;
using PlaneRegion = CGAL::Shape_detection::Point_set::
    Least_squares_plane_fit_region<Kernel, Points, PointMap, NormalMap>;
using PlaneSorting = CGAL::Shape_detection::Point_set::
    Least_squares_plane_fit_sorting<Kernel, Points, NeighbourQuery, PointMap>;
using RegionGrowing = CGAL::Shape_detection::
    Region_growing<Points, NeighbourQuery, PlaneRegion, PlaneSorting::Seed_map>;

// The manual's defaults (CGAL 5.5, Shape Detection, "Region Growing on Point Sets"):
// 12 nearest neighbours, for the normals (PCA) and the growing alike, and 25 degrees
// between a point's normal and its region's plane.
constexpr std::size_t kNeighbours = 12;
constexpr double kMaxAngleDeg = 25.0;
// The distance to the region's plane: the manual's example takes 1 in its data's
// units; here twice the point spacing, the distance of pcl::SACSegmentation's planes
// (plane_distance, 2 by default).

/** CGAL::Shape_detection::Region_growing with Least_squares_plane_fit_region, seeds in
 * the order of Least_squares_plane_fit_sorting (the manual's example), PCA normals. */
bool
runCgalPlanes (const SegmenterInput& in,
               const SegmenterSettings& s,
               std::vector<pcl::PointIndices>& clusters)
{
  clusters.clear();
  Points points;
  points.reserve (in.cloud->size());
  for (const auto& p : *in.cloud)
    points.emplace_back (Kernel::Point_3 (p.x, p.y, p.z), Kernel::Vector_3 (0, 0, 0));
  // The neighbour query and the PCA need more points than neighbours.
  if (points.size() <= kNeighbours)
    return true;
  CGAL::pca_estimate_normals<CGAL::Sequential_tag> (
      points,
      static_cast<unsigned int> (kNeighbours),
      CGAL::parameters::point_map (PointMap()).normal_map (NormalMap()));
  NeighbourQuery query (points, kNeighbours, PointMap());
  PlaneRegion region (points,
                      s.plane_distance * s.spacing,
                      kMaxAngleDeg,
                      static_cast<std::size_t> (std::max (s.min_size, 1)),
                      PointMap(),
                      NormalMap());
  PlaneSorting sorting (points, query, PointMap());
  sorting.sort();
  RegionGrowing growing (points, query, region, sorting.seed_map());
  std::vector<std::vector<std::size_t>> regions;
  growing.detect (std::back_inserter (regions));
  clusters.reserve (regions.size());
  for (const auto& r : regions) {
    pcl::PointIndices cluster;
    cluster.indices.assign (r.begin(), r.end());
    std::sort (cluster.indices.begin(), cluster.indices.end());
    clusters.push_back (std::move (cluster));
  }
  return true;
}
} // namespace

std::vector<SegmenterMethod>
cgalMethods ()
{
  return {
      {"cgal_planes",
       "CGAL",
       false,
       "CGAL Shape_detection::Region_growing with Least_squares_plane_fit_region: its "
       "documented defaults (PCA normals and growing over 12 neighbours, 25 degrees), "
       "distance plane_distance * s, min_size",
       runCgalPlanes},
  };
}
} // namespace compare
} // namespace pcl_ext
