/*
 * pcl_ext_demo step: profile-intersection segmentation (Sithole & Mapurisa) on `cubes` and
 * `spheres`, scored against the scenes' object ground truth.
 */
#include "demo_context.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/tools/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>

#include <pcl/common/io.h>

namespace pcl_ext
{
namespace demo
{
bool
runProfilesStep (DemoContext& context)
{
  bool ok = true;
  for (const std::string name : {"cubes", "spheres"})
  {
    const auto* scene = context.scene (name);
    if (!scene)
      return false;
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
    pcl::copyPointCloud (scene->cloud, *cloud);
    std::vector<std::uint32_t> truth;
    for (const auto& p : scene->cloud)
      truth.push_back (p.object);

    ProfileSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (cloud);
    seg.setNumberOfThreads (context.threads);
    std::vector<pcl::PointIndices> segments;
    tools::StageTimer timer ("Profile segmentation of '" + name + "' (proximity, 4 stacks)");
    seg.extract (segments);
    const double ms = timer.done (cloud->size ());
    if (segments.empty ())
    {
      ok = false;
      continue;
    }
    SegmentationMetrics metrics;
    evaluateSegmentation (segments, truth, metrics);
    context.summary << "  " << name << ": " << segments.size () << " segments in " << ms
                    << " ms; objects: mean best IoU " << metrics.mean_best_iou << ", correct "
                    << metrics.correct << "/" << metrics.num_truth_segments << "\n";

    std::vector<std::uint32_t> labels (cloud->size (), 0);
    for (std::size_t s = 0; s < segments.size (); ++s)
      for (const auto i : segments[s].indices)
        labels[i] = static_cast<std::uint32_t> (s + 1);
    using namespace visualization;
    RenderOptions options;
    options.width = 1600;
    options.height = 700;
    char iou[32];
    std::snprintf (iou, sizeof (iou), "%.3f", metrics.mean_best_iou);
    ok = context.render (
             {{name + ": ground-truth objects",
               {{makeColouredCloud (*cloud, colourByLabel (truth)), 1.5}}},
              {name + ": profile segmentation, mean best IoU " + iou,
               {{makeColouredCloud (*cloud, colourByLabel (labels)), 1.5}}}},
             "profiles_" + name + ".png", options) &&
         ok;
  }
  return ok;
}
}  // namespace demo
}  // namespace pcl_ext
