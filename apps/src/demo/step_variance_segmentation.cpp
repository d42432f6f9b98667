/*
 * pcl_ext_demo step: Belton & Lichti region growing over the local variance classes on
 * `indoor` (scored against the scene's true surfaces) and, when the real-data folder is given,
 * on PCL's room_scan1.pcd.
 */
#include "demo_context.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/tools/cloud_io.h>
#include <pcl_ext/tools/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>

#include <pcl/common/io.h>

#include <cstdio>
#include <fstream>

namespace pcl_ext
{
namespace demo
{
namespace
{
/** Segment \a cloud; one label per point (0: none) and a line in the summary. */
bool
segment (DemoContext& context, const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
         const std::string& name, std::vector<std::uint32_t>& ids)
{
  VarianceRegionGrowing<pcl::PointXYZ> rg;
  rg.setInputCloud (cloud);
  rg.setKSearch (context.k);
  rg.setMinClusterSize (50);
  rg.setNumberOfThreads (context.threads);
  std::vector<pcl::PointIndices> clusters;
  tools::StageTimer timer ("Classifying and growing segments of '" + name + "'");
  rg.extract (clusters);
  const double ms = timer.done (cloud->size ());
  if (clusters.empty ())
    return false;
  pcl::PointCloud<pcl::Label> labels;
  rg.getSegmentLabels (labels);
  ids.resize (labels.size ());
  std::size_t segmented = 0;
  for (std::size_t i = 0; i < labels.size (); ++i)
  {
    ids[i] = labels[i].label;
    segmented += ids[i] != 0;
  }
  context.summary << "  " << name << ": " << clusters.size () << " segments of at least 50 "
                  << "points in " << ms << " ms (k = " << context.k << ", classification "
                  << "included); " << segmented << " of " << cloud->size ()
                  << " points segmented, the rest edges, boundaries and small segments\n";
  return true;
}
}  // namespace

bool
runVarianceSegmentationStep (DemoContext& context)
{
  const auto* scene = context.scene ("indoor");
  if (!scene)
    return false;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::copyPointCloud (scene->cloud, *cloud);
  std::vector<std::uint32_t> predicted, truth;
  if (!segment (context, cloud, "indoor", predicted))
    return false;
  for (const auto& p : scene->cloud)
    truth.push_back (p.segment);
  SegmentationMetrics metrics;
  evaluateSegmentation (predicted, truth, metrics);
  context.summary << "  indoor against the true surfaces: mean best IoU "
                  << metrics.mean_best_iou << " (weighted by size "
                  << metrics.weighted_mean_best_iou << "), correct " << metrics.correct << "/"
                  << metrics.num_truth_segments << ", unsegmented "
                  << metrics.unsegmented_fraction << "\n";

  using namespace visualization;
  RenderOptions options;
  options.width = 1600;
  options.height = 700;
  char iou[32];
  std::snprintf (iou, sizeof (iou), "%.3f", metrics.mean_best_iou);
  bool ok = context.render (
      {{"indoor: true surfaces", {{makeColouredCloud (*cloud, colourByLabel (truth)), 1.5}}},
       {std::string ("indoor: Belton & Lichti region growing, mean best IoU ") + iou,
        {{makeColouredCloud (*cloud, colourByLabel (predicted)), 1.5}}}},
      "variance_segmentation_indoor.png", options);

  // A real indoor scan, when available.
  if (context.shared_data_dir.empty ())
    return ok;
  const std::string room = context.shared_data_dir + "/pcl_data_tutorials/room_scan1.pcd";
  if (!std::ifstream (room).good ())
  {
    context.summary << "  room_scan1.pcd: not found under " << context.shared_data_dir
                    << ", skipped\n";
    return ok;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr real (new pcl::PointCloud<pcl::PointXYZ>);
  if (!tools::loadCloud (room, *real) || !segment (context, real, "room_scan1", predicted))
    return false;
  RenderOptions room_options;
  room_options.width = 1200;
  room_options.height = 800;
  return context.render ({{"room_scan1.pcd: Belton & Lichti region growing",
                           {{makeColouredCloud (*real, colourByLabel (predicted)), 1.0}}}},
                         "variance_segmentation_room_scan1.png", room_options) &&
         ok;
}
}  // namespace demo
}  // namespace pcl_ext
