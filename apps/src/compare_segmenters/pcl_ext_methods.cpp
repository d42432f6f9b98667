/*
 * pcl_ext_compare_segmenters: pcl_ext's segmenters. To add one, write its runner and add a
 * line to the table at the end.
 */
#include "segmenter_methods.h"

#include <pcl_ext/segmentation/adaptive_supervoxel_segmentation.h>
#include <pcl_ext/segmentation/profile_segmentation.h>

namespace pcl_ext
{
namespace compare
{
namespace
{
/** Sithole & Mapurisa with one profile segmenter; the spacing is given (not estimated again),
  * so the proximity threshold is tolerance * s like every other method's distance. */
SegmenterMethod::Runner
profileRunner (profiles::ProfileMethod method)
{
  return [method] (const SegmenterInput& in, const SegmenterSettings& s,
                   std::vector<pcl::PointIndices>& clusters) {
    ProfileSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (in.cloud);
    seg.setPointSpacing (s.spacing);
    seg.setDistanceThresholdFactor (s.tolerance);
    seg.setProfileSegmentation (method);
    seg.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
    seg.setNumberOfThreads (s.threads);
    seg.extract (clusters);
    return true;
  };
}

template <typename PointT> void
extractSupervoxels (const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
                    const SegmenterSettings& s, std::vector<pcl::PointIndices>& clusters)
{
  AdaptiveSupervoxelSegmentation<PointT> seg;
  seg.setInputCloud (cloud);
  seg.setNumberOfThreads (s.threads);
  seg.extract (clusters);
}

/** Lim & Suter's adaptive super-voxels with the class defaults, colour included when the
  * cloud has it. Each super-voxel is a segment; super-voxels overlap, and a point held by
  * several belongs to the first one drawn (pcl_ext::labelsFromIndices). They are an
  * over-segmentation by design (the CRF's nodes), listed to show what it gives as segments. */
bool
runAdaptiveSupervoxels (const SegmenterInput& in, const SegmenterSettings& s,
                        std::vector<pcl::PointIndices>& clusters)
{
  if (in.coloured)
    extractSupervoxels<pcl::PointXYZRGBA> (in.coloured, s, clusters);
  else
    extractSupervoxels<pcl::PointXYZ> (in.cloud, s, clusters);
  return true;
}
}  // namespace

std::vector<SegmenterMethod>
pclExtMethods ()
{
  using profiles::ProfileMethod;
  return {
      {"proximity", "pcl_ext", false,
       "pcl_ext::ProfileSegmentation (Sithole & Mapurisa), proximity chaining; 4 stacks, width "
       "1.5 s, threshold tolerance * s, min_size",
       profileRunner (ProfileMethod::Proximity)},
      {"mst", "pcl_ext", false,
       "pcl_ext::ProfileSegmentation, minimum spanning trees cut at tolerance * s; min_size",
       profileRunner (ProfileMethod::MinimumSpanningTree)},
      {"curve", "pcl_ext", false,
       "pcl_ext::ProfileSegmentation, curve fitting (AIC, 30 deg turns); threshold tolerance * "
       "s, min_size",
       profileRunner (ProfileMethod::CurveFitting)},
      {"adaptive_sv", "pcl_ext", false,
       "pcl_ext::AdaptiveSupervoxelSegmentation (Lim & Suter), class defaults; each super-voxel "
       "a segment (an over-segmentation)",
       runAdaptiveSupervoxels},
  };
}
}  // namespace compare
}  // namespace pcl_ext
