/*
 * pcl_ext_demo step: Belton & Lichti region growing over the local variance classes on
 * `indoor` (scored against the scene's true surfaces) and, when the real-data folder is
 * given, on PCL's room_scan1.pcd; then the local intersection of the segments (section
 * 4), drawn on top and, on `indoor`, measured against the true creases.
 */
#include "demo_context.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/montage.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace pcl_ext {
namespace demo {
namespace {
using Intersections = pcl::PointCloud<SurfaceIntersectionPoint>;

/** Segment \a cloud and intersect the segments; one label per point (0: none), the
 * intersection points, and lines in the summary. */
bool
segment (DemoContext& context,
         const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
         const std::string& name,
         std::vector<std::uint32_t>& ids,
         Intersections& intersections)
{
  apps::StageTimer timer ("Classifying and growing segments of '" + name + "'");
  // One neighbourhood search for the segmentation and the intersections.
  auto nb = pcl::make_shared<Neighbourhoods<pcl::PointXYZ>>();
  nb->setInputCloud (cloud);
  nb->setKSearch (context.k);
  nb->setNumberOfThreads (context.threads);
  nb->setStoreSquaredDistances (false);
  if (!nb->compute())
    return false;
  VarianceRegionGrowing<pcl::PointXYZ> rg;
  rg.setInputCloud (cloud);
  rg.setNeighbourhoods (nb);
  rg.setMinClusterSize (50);
  rg.setNumberOfThreads (context.threads);
  LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setNumberOfThreads (context.threads);
  std::vector<pcl::PointIndices> clusters;
  segmentByLocalVariance (classifier, rg, clusters);
  const double ms = timer.done (cloud->size());
  if (clusters.empty())
    return false;
  pcl::PointCloud<pcl::Label> labels;
  rg.getSegmentLabels (labels);
  ids.resize (labels.size());
  std::size_t segmented = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    ids[i] = labels[i].label;
    segmented += ids[i] != 0;
  }
  context.summary
      << "  " << name << ": " << clusters.size() << " segments of at least 50 "
      << "points in " << ms << " ms (k = " << context.k << ", classification "
      << "included); " << segmented << " of " << cloud->size()
      << " points segmented, the rest edges, boundaries and small segments\n";

  LocalSurfaceIntersection<pcl::PointXYZ> lsi;
  lsi.setInputCloud (cloud);
  lsi.setNeighbourhoods (nb);
  lsi.setSegmentLabels (pcl::make_shared<pcl::PointCloud<pcl::Label>> (labels));
  lsi.setPointClasses (
      pcl::make_shared<pcl::PointCloud<pcl::Label>> (*rg.getInputClasses()));
  lsi.setNumberOfThreads (context.threads);
  pcl::PointCloud<pcl::Label> reintegrated;
  apps::StageTimer lsi_timer ("Intersecting the segments of '" + name + "'");
  if (!lsi.compute (intersections, reintegrated))
    return false;
  const double lsi_ms = lsi_timer.done (intersections.size());
  const auto& r = lsi.getReport();
  context.summary << "  " << name
                  << ", local surface intersection: " << intersections.size()
                  << " intersection points in " << lsi_ms << " ms (" << r.parallel
                  << " pairs parallel, " << r.beyond_tolerance << " too far); of "
                  << r.examined << " edge and boundary points " << r.reintegrated
                  << " fit one segment, " << r.ambiguous << " several, " << r.left
                  << " none\n";
  return true;
}

/** Median distance of \a points to the nearest true crease of \a scene. */
double
medianCreaseDistance (const simulation::SyntheticScene& scene,
                      const Intersections& points)
{
  const auto& curves = scene.description->geometry.curves();
  const Eigen::Isometry3d scene_from_cloud = scene.cloud_from_scene.inverse();
  std::vector<double> d;
  for (const auto& p : points) {
    const Eigen::Vector3d x = scene_from_cloud * Eigen::Vector3d (p.x, p.y, p.z);
    double best = std::numeric_limits<double>::infinity();
    for (const auto& c : curves)
      if (c.kind == simulation::GroundTruthCurve::Kind::Crease)
        best = std::min (best, c.distance (x));
    d.push_back (best);
  }
  if (d.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::nth_element (d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

/** The intersection points in black, drawn over the segments. */
visualization::Layer
intersectionLayer (const Intersections& points)
{
  return {visualization::makeColouredCloud (
              points, std::vector<visualization::Colour> (points.size(), {0, 0, 0})),
          3.0};
}
} // namespace

bool
runVarianceSegmentationStep (DemoContext& context)
{
  const auto* scene = context.scene ("indoor");
  if (!scene)
    return false;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::copyPointCloud (scene->cloud, *cloud);
  std::vector<std::uint32_t> predicted, truth;
  Intersections intersections;
  if (!segment (context, cloud, "indoor", predicted, intersections))
    return false;
  for (const auto& p : scene->cloud)
    truth.push_back (p.segment);
  SegmentationMetrics metrics;
  evaluateSegmentation (predicted, truth, metrics);
  context.summary
      << "  indoor against the true surfaces: mean best IoU " << metrics.mean_best_iou
      << " (weighted by size " << metrics.weighted_mean_best_iou << "), correct "
      << metrics.correct << "/" << metrics.num_truth_segments << ", unsegmented "
      << metrics.unsegmented_fraction << "\n"
      << "  indoor intersection points: median distance to the nearest true "
      << "crease " << medianCreaseDistance (*scene, intersections) << " m (range "
      << "noise sigma " << scene->noise << " m)\n";

  using namespace visualization;
  RenderOptions options;
  options.width = 1600;
  options.height = 700;
  char iou[32];
  std::snprintf (iou, sizeof (iou), "%.3f", metrics.mean_best_iou);
  bool ok = context.render (
      {{"indoor: true surfaces",
        {{makeColouredCloud (*cloud, colourByLabel (truth))}},
        {{"unsegmented", colourByLabel ({0u}).front()}}},
       {std::string ("indoor: Belton & Lichti region growing, mean best IoU ") + iou,
        {{makeColouredCloud (
             *cloud, colourByLabel (matchLabelsToReference (predicted, truth)))},
         intersectionLayer (intersections)},
        {{"unsegmented", colourByLabel ({0u}).front()},
         {"local intersection", {0, 0, 0}}}}},
      "variance_segmentation_indoor.png",
      options);

  // A real indoor scan, when available.
  const pcl::PointCloud<pcl::PointXYZ>::Ptr real = context.loadRoomScan();
  if (!real)
    return ok;
  if (real->empty() || !segment (context, real, "room_scan1", predicted, intersections))
    return false;
  RenderOptions room_options;
  room_options.width = 1200;
  room_options.height = 800;
  return context.render ({{"room_scan1.pcd: Belton & Lichti region growing",
                           {{makeColouredCloud (*real, colourByLabel (predicted))},
                            intersectionLayer (intersections)},
                           {{"unsegmented", colourByLabel ({0u}).front()},
                            {"local intersection", {0, 0, 0}}}}},
                         "variance_segmentation_room_scan1.png",
                         room_options) &&
         ok;
}
} // namespace demo
} // namespace pcl_ext
