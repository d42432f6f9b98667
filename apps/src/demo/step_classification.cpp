/*
 * pcl_ext_demo step: Belton & Lichti surface / edge / boundary classification on
 * `indoor` (scored against the scene's ground-truth classes) and, when the real-data
 * folder is given, on PCL's room_scan1.pcd.
 */
#include "demo_context.h"

#include <pcl_ext/classification/edge_localisation.h>
#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/evaluation/classification_metrics.h>
#include <pcl_ext/point_types.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>

#include <pcl/common/io.h>

namespace pcl_ext {
namespace demo {
namespace {
bool
classify (DemoContext& context,
          const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
          const std::string& name,
          std::vector<std::uint32_t>& classes)
{
  // As pcl_ext_classify_variance: one search, the classes, the edges narrowed to
  // their creases.
  auto nb = pcl::make_shared<Neighbourhoods<pcl::PointXYZ>>();
  nb->setInputCloud (cloud);
  nb->setKSearch (context.k);
  nb->setNumberOfThreads (context.threads);
  nb->setStoreSquaredDistances (false);
  LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setInputCloud (cloud);
  classifier.setNeighbourhoods (nb);
  classifier.setNumberOfThreads (context.threads);
  auto labels = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  apps::StageTimer timer ("Classifying '" + name + "' (surface / edge / boundary)");
  if (nb->compute())
    classifier.classify (*labels);
  if (labels->size() != cloud->size())
    return false;
  EdgeLocalisation<pcl::PointXYZ> localisation;
  localisation.setInputCloud (cloud);
  localisation.setNeighbourhoods (nb);
  localisation.setNumberOfThreads (context.threads);
  localisation.setPointClasses (labels);
  pcl::PointCloud<pcl::Label> narrowed;
  if (!localisation.localise (narrowed))
    return false;
  labels->swap (narrowed);
  const double ms = timer.done (labels->size());
  classes.resize (labels->size());
  std::size_t count[kNumPointClasses] = {0};
  for (std::size_t i = 0; i < labels->size(); ++i) {
    classes[i] = (*labels)[i].label;
    ++count[std::min<std::size_t> (classes[i], kNumPointClasses - 1)];
  }
  context.summary << "  " << name << ": " << cloud->size() << " points classified in "
                  << ms << " ms (k = " << context.k << "): surface " << count[1]
                  << ", edge " << count[2] << ", boundary " << count[3] << ", unknown "
                  << count[0] << "\n";
  return true;
}
} // namespace

bool
runClassificationStep (DemoContext& context)
{
  const auto* scene = context.scene ("indoor");
  if (!scene)
    return false;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::copyPointCloud (scene->cloud, *cloud);
  std::vector<std::uint32_t> predicted, truth;
  if (!classify (context, cloud, "indoor", predicted))
    return false;
  for (const auto& p : scene->cloud)
    truth.push_back (p.point_class);
  ClassificationMetrics metrics;
  const std::map<std::uint32_t, std::string> names = {
      {1, "surface"}, {2, "edge"}, {3, "boundary"}};
  evaluateClassification (predicted, truth, metrics, names);
  context.summary
      << "  indoor against the scene's classes (band = scan spacing): accuracy "
      << metrics.overall_accuracy;
  for (const auto& c : metrics.classes)
    context.summary << ", " << c.name << " F1 " << c.f1;
  context.summary << "\n";

  using namespace visualization;
  RenderOptions options;
  options.width = 1600;
  options.height = 700;
  bool ok = context.render ({{"indoor: ground-truth classes",
                              {{makeColouredCloud (*cloud, colourByClass (truth))}},
                              classLegend()},
                             {"indoor: Belton & Lichti",
                              {{makeColouredCloud (*cloud, colourByClass (predicted))}},
                              classLegend()}},
                            "classification_indoor.png",
                            options);

  // A real indoor scan, when available.
  const pcl::PointCloud<pcl::PointXYZ>::Ptr real = context.loadRoomScan();
  if (!real)
    return ok;
  if (real->empty() || !classify (context, real, "room_scan1", predicted))
    return false;
  RenderOptions room_options;
  room_options.width = 1200;
  room_options.height = 800;
  return context.render ({{"room_scan1.pcd: Belton & Lichti classification",
                           {{makeColouredCloud (*real, colourByClass (predicted))}},
                           classLegend()}},
                         "classification_room_scan1.png",
                         room_options) &&
         ok;
}
} // namespace demo
} // namespace pcl_ext
