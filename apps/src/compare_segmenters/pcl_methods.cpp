/*
 * pcl_ext_compare_segmenters: the stock PCL segmenters, with the defaults a PCL user
 * would pick (PCL's tutorials and examples), lengths as multiples of the point spacing
 * s.
 */
#include "segmenter_methods.h"

#include <pcl/common/io.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/conditional_euclidean_clustering.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/lccp_segmentation.h>
#include <pcl/segmentation/region_growing.h>
#include <pcl/segmentation/sac_segmentation.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace pcl_ext {
namespace compare {
namespace {
constexpr double kDegree = M_PI / 180.0;

pcl::search::KdTree<pcl::PointXYZ>::Ptr
makeTree ()
{
  return pcl::search::KdTree<pcl::PointXYZ>::Ptr (
      new pcl::search::KdTree<pcl::PointXYZ>);
}

/** pcl::RegionGrowing as in PCL's region growing tutorial: k neighbours, smoothness
 * angle, curvature threshold, on the shared normals. */
bool
runRegionGrowing (const SegmenterInput& in,
                  const SegmenterSettings& s,
                  std::vector<pcl::PointIndices>& clusters)
{
  pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> rg;
  rg.setInputCloud (in.cloud);
  // RegionGrowing takes a non-const pointer (PCL 1.13) but only reads the normals.
  rg.setInputNormals (
      std::const_pointer_cast<pcl::PointCloud<pcl::Normal>> (in.normals));
  rg.setSearchMethod (makeTree());
  rg.setNumberOfNeighbours (static_cast<unsigned int> (s.k));
  rg.setSmoothnessThreshold (static_cast<float> (s.angle * kDegree));
  rg.setCurvatureThreshold (static_cast<float> (s.curvature));
  rg.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
  rg.setMaxClusterSize (std::numeric_limits<pcl::uindex_t>::max());
  rg.extract (clusters);
  return true;
}

/** pcl::EuclideanClusterExtraction with tolerance * s. */
bool
runEuclidean (const SegmenterInput& in,
              const SegmenterSettings& s,
              std::vector<pcl::PointIndices>& clusters)
{
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> ec;
  ec.setInputCloud (in.cloud);
  ec.setSearchMethod (makeTree());
  ec.setClusterTolerance (s.tolerance * s.spacing);
  ec.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
  ec.setMaxClusterSize (std::numeric_limits<pcl::uindex_t>::max());
  ec.extract (clusters);
  return true;
}

/** pcl::ConditionalEuclideanClustering: points within tolerance * s join when their
 * normals differ by less than the angle (either orientation, as pcl::RegionGrowing
 * compares them). */
bool
runConditionalEuclidean (const SegmenterInput& in,
                         const SegmenterSettings& s,
                         std::vector<pcl::PointIndices>& clusters)
{
  pcl::PointCloud<pcl::PointNormal>::Ptr points (new pcl::PointCloud<pcl::PointNormal>);
  pcl::concatenateFields (*in.cloud, *in.normals, *points);
  const float min_cos = static_cast<float> (std::cos (s.angle * kDegree));
  pcl::ConditionalEuclideanClustering<pcl::PointNormal> cec;
  cec.setInputCloud (points);
  cec.setConditionFunction (
      [min_cos] (const pcl::PointNormal& a, const pcl::PointNormal& b, float) {
        return std::abs (a.getNormalVector3fMap().dot (b.getNormalVector3fMap())) >=
               min_cos;
      });
  cec.setClusterTolerance (static_cast<float> (s.tolerance * s.spacing));
  cec.setMinClusterSize (s.min_size);
  cec.setMaxClusterSize (std::numeric_limits<int>::max());
  cec.segment (clusters);
  return true;
}

/** Sequential RANSAC planes (pcl::SACSegmentation, inliers within plane_distance * s,
 * optimised coefficients), each plane's inliers split into connected parts by
 * pcl::EuclideanClusterExtraction (tolerance * s), as a PCL user does: one plane model
 * holds every coplanar surface of the scene. Stops when a plane has fewer than min_size
 * inliers or after max_planes planes; points in no plane stay unsegmented. */
bool
runSacPlanes (const SegmenterInput& in,
              const SegmenterSettings& s,
              std::vector<pcl::PointIndices>& clusters)
{
  pcl::IndicesPtr remaining (new pcl::Indices (in.cloud->size()));
  for (std::size_t i = 0; i < remaining->size(); ++i)
    (*remaining)[i] = static_cast<pcl::index_t> (i);
  pcl::SACSegmentation<pcl::PointXYZ> sac;
  sac.setInputCloud (in.cloud);
  sac.setModelType (pcl::SACMODEL_PLANE);
  sac.setMethodType (pcl::SAC_RANSAC);
  sac.setOptimizeCoefficients (true);
  sac.setDistanceThreshold (s.plane_distance * s.spacing);
  sac.setMaxIterations (1000);
  sac.setNumberOfThreads (static_cast<int> (s.threads));
  std::vector<char> taken (in.cloud->size(), 0);
  for (int plane = 0; plane < s.max_planes; ++plane) {
    if (remaining->size() < static_cast<std::size_t> (std::max (s.min_size, 3)))
      break;
    pcl::PointIndices::Ptr inliers (new pcl::PointIndices);
    pcl::ModelCoefficients coefficients;
    sac.setIndices (remaining);
    sac.segment (*inliers, coefficients);
    if (inliers->indices.size() < static_cast<std::size_t> (std::max (s.min_size, 1)))
      break;
    std::vector<pcl::PointIndices> parts;
    pcl::EuclideanClusterExtraction<pcl::PointXYZ> ec;
    ec.setInputCloud (in.cloud);
    ec.setIndices (inliers);
    ec.setSearchMethod (makeTree());
    ec.setClusterTolerance (s.tolerance * s.spacing);
    ec.setMinClusterSize (static_cast<pcl::uindex_t> (s.min_size));
    ec.setMaxClusterSize (std::numeric_limits<pcl::uindex_t>::max());
    ec.extract (parts);
    for (auto& part : parts)
      clusters.push_back (std::move (part));
    // Every inlier leaves the pool, kept in a part or not: the next plane is another
    // one.
    for (const auto i : inliers->indices)
      taken[i] = 1;
    pcl::IndicesPtr rest (new pcl::Indices);
    for (const auto i : *remaining)
      if (!taken[i])
        rest->push_back (i);
    remaining = rest;
  }
  return true;
}

/** pcl::SupervoxelClustering + pcl::LCCPSegmentation with the parameters of PCL's LCCP
 * example (colour 0, spatial 1, normal 4; concavity tolerance, smoothness check 0.1, no
 * extended convexity, no sanity criterion), resolutions voxel * s and seed * s.
 * Segments smaller than min_size are left unsegmented, like the other methods' minimum
 * size. */
bool
runLccp (const SegmenterInput& in,
         const SegmenterSettings& s,
         std::vector<pcl::PointIndices>& clusters)
{
  const float voxel = static_cast<float> (s.voxel * s.spacing);
  const float seed = static_cast<float> (s.seed * s.spacing);
  pcl::SupervoxelClustering<pcl::PointXYZ> super (voxel, seed);
  super.setUseSingleCameraTransform (false);
  super.setInputCloud (in.cloud);
  super.setColorImportance (0.0f);
  super.setSpatialImportance (1.0f);
  super.setNormalImportance (4.0f);
  std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZ>::Ptr> supervoxels;
  super.extract (supervoxels);
  std::multimap<std::uint32_t, std::uint32_t> adjacency;
  super.getSupervoxelAdjacency (adjacency);

  pcl::LCCPSegmentation<pcl::PointXYZ> lccp;
  lccp.setConcavityToleranceThreshold (static_cast<float> (s.concavity));
  lccp.setSanityCheck (false);
  lccp.setSmoothnessCheck (true, voxel, seed, 0.1f);
  lccp.setKFactor (0);
  lccp.setInputSupervoxels (supervoxels, adjacency);
  lccp.setMinSegmentSize (0);
  lccp.segment();
  pcl::PointCloud<pcl::PointXYZL>::Ptr labelled = super.getLabeledCloud();
  if (labelled->size() != in.cloud->size())
    return false;
  lccp.relabelCloud (*labelled);

  std::map<std::uint32_t, pcl::PointIndices> by_label;
  for (std::size_t i = 0; i < labelled->size(); ++i)
    if ((*labelled)[i].label != 0)
      by_label[(*labelled)[i].label].indices.push_back (static_cast<pcl::index_t> (i));
  for (auto& entry : by_label)
    if (entry.second.indices.size() >= static_cast<std::size_t> (s.min_size))
      clusters.push_back (std::move (entry.second));
  std::stable_sort (clusters.begin(),
                    clusters.end(),
                    [] (const pcl::PointIndices& a, const pcl::PointIndices& b) {
                      return a.indices.size() > b.indices.size();
                    });
  return true;
}
} // namespace

std::vector<SegmenterMethod>
pclMethods ()
{
  return {
      {"region_growing",
       "PCL",
       true,
       "pcl::RegionGrowing: k neighbours, smoothness angle, curvature threshold, "
       "min_size",
       runRegionGrowing},
      {"euclidean",
       "PCL",
       false,
       "pcl::EuclideanClusterExtraction: tolerance * s, min_size",
       runEuclidean},
      {"cec",
       "PCL",
       true,
       "pcl::ConditionalEuclideanClustering: tolerance * s, normals within the angle, "
       "min_size",
       runConditionalEuclidean},
      {"sac_planes",
       "PCL",
       false,
       "sequential pcl::SACSegmentation planes (RANSAC, plane_distance * s, "
       "max_planes), each "
       "split by pcl::EuclideanClusterExtraction (tolerance * s, min_size)",
       runSacPlanes},
      {"lccp",
       "PCL",
       false,
       "pcl::SupervoxelClustering (voxel * s, seed * s) + pcl::LCCPSegmentation "
       "(concavity), "
       "PCL example weights; min_size",
       runLccp},
  };
}

std::vector<SegmenterMethod>
allMethods ()
{
  std::vector<SegmenterMethod> methods = pclExtMethods();
  for (auto& m : pclMethods())
    methods.push_back (std::move (m));
#ifdef PCL_EXT_HAVE_CGAL
  for (auto& m : cgalMethods())
    methods.push_back (std::move (m));
#endif
  return methods;
}
} // namespace compare
} // namespace pcl_ext
