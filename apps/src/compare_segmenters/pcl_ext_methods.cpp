/*
 * pcl_ext_compare_segmenters: pcl_ext's segmenters. To add one, write its runner and
 * add a line to the table at the end.
 */
#include "segmenter_methods.h"

#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/segmentation/adaptive_supervoxel_segmentation.h>
#include <pcl_ext/segmentation/auto_profile_segmentation.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>

namespace pcl_ext {
namespace compare {
namespace {
/** Belton & Lichti region growing over the local variance classes, with the class
 * defaults (the paper's k = 50 neighbours, curvature threshold 3x the median
 * curvature). */
bool
runVarianceRegionGrowing (const SegmenterInput& in,
                          const SegmenterSettings& s,
                          std::vector<pcl::PointIndices>& clusters)
{
  VarianceRegionGrowing<pcl::PointXYZ> rg;
  rg.setInputCloud (in.cloud);
  rg.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
  rg.setNumberOfThreads (s.threads);
  LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setNumberOfThreads (s.threads);
  segmentByLocalVariance (classifier, rg, clusters);
  return true;
}

/** The whole of Belton & Lichti: region growing (section 3), then the edge and boundary
 * points it leaves out re-integrated into the surfaces they fit by local surface
 * intersection (section 4), both with the class defaults on one shared k = 50 search.
 */
bool
runVarianceWithIntersection (const SegmenterInput& in,
                             const SegmenterSettings& s,
                             std::vector<pcl::PointIndices>& clusters)
{
  auto nb = pcl::make_shared<Neighbourhoods<pcl::PointXYZ>>();
  nb->setInputCloud (in.cloud);
  nb->setKSearch (50);
  nb->setNumberOfThreads (s.threads);
  nb->setStoreSquaredDistances (false);
  if (!nb->compute())
    return false;
  VarianceRegionGrowing<pcl::PointXYZ> rg;
  rg.setInputCloud (in.cloud);
  rg.setNeighbourhoods (nb);
  rg.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
  rg.setNumberOfThreads (s.threads);
  LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setNumberOfThreads (s.threads);
  std::vector<pcl::PointIndices> segments;
  segmentByLocalVariance (classifier, rg, segments);
  if (segments.empty())
    return true;
  auto labels = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  rg.getSegmentLabels (*labels);
  const auto classes = rg.getInputClasses();
  LocalSurfaceIntersection<pcl::PointXYZ> lsi;
  lsi.setInputCloud (in.cloud);
  lsi.setNeighbourhoods (nb);
  lsi.setSegmentLabels (labels);
  lsi.setPointClasses (classes);
  lsi.setNumberOfThreads (s.threads);
  pcl::PointCloud<SurfaceIntersectionPoint> intersections;
  pcl::PointCloud<pcl::Label> merged;
  lsi.compute (intersections, merged);
  if (merged.size() != in.cloud->size())
    return false;
  // Segment i + 1 of the labels is segments[i], re-integrated points added.
  clusters.assign (segments.size(), pcl::PointIndices());
  for (std::size_t i = 0; i < merged.size(); ++i)
    if (merged[i].label != 0 && merged[i].label <= clusters.size())
      clusters[merged[i].label - 1].indices.push_back (static_cast<pcl::index_t> (i));
  return true;
}

/** Sithole & Mapurisa with one profile segmenter; the spacing is given (not estimated
 * again), so the proximity threshold is tolerance * s like every other method's
 * distance. */
SegmenterMethod::Runner
profileRunner (profiles::ProfileMethod method)
{
  return [method] (const SegmenterInput& in,
                   const SegmenterSettings& s,
                   std::vector<pcl::PointIndices>& clusters) {
    ProfileSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (in.cloud);
    seg.setPointSpacing (s.spacing);
    seg.setDistanceThresholdFactor (s.tolerance);
    seg.setProfileSegmentation (method);
    seg.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
    seg.setCorrectedAic (s.profile_aicc);
    seg.setTurnSignificance (s.profile_turn_significance);
    seg.setSideFrames (s.profile_side_frames);
    seg.setLocalThreshold (s.profile_local_threshold);
    seg.setNumberOfThreads (s.threads);
    seg.extract (clusters);
    return true;
  };
}

/** Sithole & Mapurisa configured from the cloud (AutoProfileSegmentation), the class
 * defaults as pcl_ext_segment_profiles runs them; min_size. */
bool
runAutoProfiles (const SegmenterInput& in,
                 const SegmenterSettings& s,
                 std::vector<pcl::PointIndices>& clusters)
{
  AutoProfileSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (in.cloud);
  seg.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
  seg.setNumberOfThreads (s.threads);
  seg.extract (clusters);
  return true;
}

template <typename PointT>
void
extractSupervoxels (const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
                    const SegmenterSettings& s,
                    std::vector<pcl::PointIndices>& clusters)
{
  AdaptiveSupervoxelSegmentation<PointT> seg;
  seg.setInputCloud (cloud);
  seg.setNumberOfThreads (s.threads);
  seg.extract (clusters);
}

/** Lim & Suter's adaptive super-voxels with the class defaults, colour included when
 * the cloud has it. Each super-voxel is a segment; super-voxels overlap, and a point
 * held by several belongs to the first one drawn (pcl_ext::labelsFromIndices). They are
 * an over-segmentation by design (the CRF's nodes), listed to show what it gives as
 * segments. */
bool
runAdaptiveSupervoxels (const SegmenterInput& in,
                        const SegmenterSettings& s,
                        std::vector<pcl::PointIndices>& clusters)
{
  if (in.coloured)
    extractSupervoxels<pcl::PointXYZRGBA> (in.coloured, s, clusters);
  else
    extractSupervoxels<pcl::PointXYZ> (in.cloud, s, clusters);
  return true;
}
} // namespace

std::vector<SegmenterMethod>
pclExtMethods ()
{
  using profiles::ProfileMethod;
  return {
      {"variance",
       "pcl_ext",
       false,
       "pcl_ext::VarianceRegionGrowing (Belton & Lichti), class defaults (k = 50, the "
       "paper's); "
       "min_size",
       runVarianceRegionGrowing},
      {"variance_lsi",
       "pcl_ext",
       false,
       "variance, then pcl_ext::LocalSurfaceIntersection (Belton & Lichti section 4) "
       "re-integrating the edge and boundary points; class defaults, one k = 50 search",
       runVarianceWithIntersection},
      {"profiles",
       "pcl_ext",
       false,
       "pcl_ext::AutoProfileSegmentation (Sithole & Mapurisa configured from the "
       "cloud), class defaults; min_size",
       runAutoProfiles},
      {"proximity",
       "pcl_ext",
       false,
       "pcl_ext::ProfileSegmentation (Sithole & Mapurisa), proximity chaining; 4 "
       "stacks, width "
       "1.5 s, threshold tolerance * s, min_size",
       profileRunner (ProfileMethod::Proximity)},
      {"mst",
       "pcl_ext",
       false,
       "pcl_ext::ProfileSegmentation, minimum spanning trees cut at tolerance * s; "
       "min_size",
       profileRunner (ProfileMethod::MinimumSpanningTree)},
      {"curve",
       "pcl_ext",
       false,
       "pcl_ext::ProfileSegmentation, curve fitting (AIC, 30 deg turns); threshold "
       "tolerance * "
       "s, min_size",
       profileRunner (ProfileMethod::CurveFitting)},
      {"crust",
       "pcl_ext",
       false,
       "pcl_ext::ProfileSegmentation, curve reconstruction (nearest-neighbour crust) "
       "cut at tolerance * s; min_size",
       profileRunner (ProfileMethod::CurveReconstruction)},
      {"adaptive_sv",
       "pcl_ext",
       false,
       "pcl_ext::AdaptiveSupervoxelSegmentation (Lim & Suter), class defaults; each "
       "super-voxel "
       "a segment (an over-segmentation)",
       runAdaptiveSupervoxels},
  };
}
} // namespace compare
} // namespace pcl_ext
