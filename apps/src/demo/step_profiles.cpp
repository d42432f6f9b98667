/*
 * pcl_ext_demo step: profile-intersection segmentation (Sithole & Mapurisa) on the
 * scenes of the paper's section 5 (`cubes`, `spheres`, `coaxial`, `pipes`, `tree`),
 * scored against their ground truth, with the same defaults for every scene: the
 * configuration is chosen from each cloud (AutoProfileSegmentation).
 */
#include "demo_context.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/auto_profile_segmentation.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/montage.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
namespace demo {
namespace {
/** One run of the step: a scene and its truth. */
struct ProfileRun {
  std::string scene;
  bool surfaces; ///< truth at the surface level (connected pieces) instead of objects
  /** \brief Also scored: the truth segments of this scene label (0: none), or with
   * \a below_z > 0 only the one holding most of its points below that height. */
  std::uint32_t focus_label = 0;
  float below_z = 0.0f;
  std::string focus_name;
};

/** Mean best IoU over the truth segments the run focuses on (see ProfileRun). */
double
focusIoU (const ProfileRun& run,
          const simulation::SyntheticScene& scene,
          const std::vector<std::uint32_t>& truth,
          const SegmentationMetrics& metrics)
{
  std::map<std::uint32_t, std::size_t> of_label, total;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    ++total[truth[i]];
    if (scene.cloud[i].label == run.focus_label &&
        (run.below_z <= 0.0f || scene.cloud[i].z < run.below_z))
      ++of_label[truth[i]];
  }
  std::vector<std::uint32_t> chosen;
  if (run.below_z > 0.0f && !of_label.empty())
    chosen.push_back (std::max_element (of_label.begin(),
                                        of_label.end(),
                                        [] (const auto& a, const auto& b) {
                                          return a.second < b.second;
                                        })
                          ->first);
  else
    for (const auto& [segment, count] : of_label)
      if (2 * count > total[segment])
        chosen.push_back (segment);
  double sum = 0.0;
  for (const auto& match : metrics.segments)
    if (std::find (chosen.begin(), chosen.end(), match.truth_label) != chosen.end())
      sum += match.iou;
  return chosen.empty() ? 0.0 : sum / static_cast<double> (chosen.size());
}

/** The configuration chosen, in words. */
std::string
describeChoice (const AutoProfileSegmentation<pcl::PointXYZ>& seg)
{
  const auto& c = seg.getConfiguration();
  if (!c.curve_fitting)
    return c.local_threshold ? "proximity, local thresholds" : "proximity";
  std::string words = c.noisy ? "curve fitting for noise" : "curve fitting";
  if (c.local_threshold)
    words += ", local thresholds";
  if (seg.getCylindersJoined())
    words += ", cylinders joined";
  return words;
}
} // namespace

bool
runProfilesStep (DemoContext& context)
{
  const std::vector<ProfileRun> runs = {
      {"cubes", false, 0, 0.0f, ""},
      {"spheres", false, 0, 0.0f, ""},
      {"coaxial", true, 0, 0.0f, ""},
      {"pipes", false, 3, 0.0f, "the pipes"}, // the scene's label 3: pipe
      {"tree",
       true,
       static_cast<std::uint32_t> (simulation::OutdoorLabel::Trunk),
       3.0f,
       "the trunk"}};
  bool ok = true;
  for (const auto& run : runs) {
    const std::string& name = run.scene;
    const auto* scene = context.scene (name);
    if (!scene)
      return false;
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
    pcl::copyPointCloud (scene->cloud, *cloud);
    std::vector<std::uint32_t> truth;
    for (const auto& p : scene->cloud)
      truth.push_back (run.surfaces ? p.segment : p.object);

    AutoProfileSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (cloud);
    seg.setNumberOfThreads (context.threads);
    std::vector<pcl::PointIndices> segments;
    apps::StageTimer timer ("Profile segmentation of '" + name + "'");
    seg.extract (segments);
    const double ms = timer.done (cloud->size());
    if (segments.empty()) {
      ok = false;
      continue;
    }
    SegmentationMetrics metrics;
    evaluateSegmentation (segments, truth, metrics);
    const std::string settings = describeChoice (seg);
    context.summary << "  " << name << " (" << settings << "): " << segments.size()
                    << " segments in " << ms << " ms; "
                    << (run.surfaces ? "surfaces" : "objects") << ": mean best IoU "
                    << metrics.mean_best_iou << ", weighted "
                    << metrics.weighted_mean_best_iou << ", correct " << metrics.correct
                    << "/" << metrics.num_truth_segments;
    std::string title_metric = "mean best IoU";
    double shown = metrics.mean_best_iou;
    if (run.focus_label != 0) {
      shown = focusIoU (run, *scene, truth, metrics);
      title_metric = run.focus_name + ": mean best IoU";
      context.summary << "; " << run.focus_name << ": mean best IoU " << shown;
    }
    context.summary << "\n";

    std::vector<std::uint32_t> labels (cloud->size(), 0);
    for (std::size_t s = 0; s < segments.size(); ++s)
      for (const auto i : segments[s].indices)
        labels[i] = static_cast<std::uint32_t> (s + 1);
    using namespace visualization;
    RenderOptions options;
    options.width = 1600;
    options.height = 700;
    char iou[32];
    std::snprintf (iou, sizeof (iou), "%.3f", shown);
    ok =
        context.render (
            {{name + ": ground truth (" + (run.surfaces ? "surfaces" : "objects") + ")",
              {{makeColouredCloud (*cloud, colourByLabel (truth))}},
              {{"unsegmented", colourByLabel ({0u}).front()}}},
             {name + ": " + settings + ", " + title_metric + " " + iou,
              {{makeColouredCloud (
                  *cloud, colourByLabel (matchLabelsToReference (labels, truth)))}},
              {{"unsegmented", colourByLabel ({0u}).front()}}}},
            "profiles_" + name + ".png",
            options) &&
        ok;
  }
  return ok;
}
} // namespace demo
} // namespace pcl_ext
