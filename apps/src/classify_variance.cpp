/*
 * pcl_ext_classify_variance: labels every point surface (1), edge (2), boundary (3) or
 * unknown (0) by local variance (Belton & Lichti 2006, section 2) and writes the input
 * points with a `label` field.
 */
#include "variance/variance_options.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/io/file_output.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

#include <pcl/common/io.h>
#include <pcl/conversions.h>

#include <cstring>
#include <cmath>
#include <iostream>

namespace {
/** Write \a labels into the cloud's `label` field (a scene's own labels are replaced;
 * the field is appended when absent). */
bool
attachLabels (const pcl::PCLPointCloud2& input,
              const pcl::PointCloud<pcl::Label>& labels,
              pcl::PCLPointCloud2& output)
{
  std::vector<std::uint32_t> values (labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    values[i] = labels[i].label;
  output = input;
  return pcl_ext::io::setLabelField (output, "label", values);
}
} // namespace

int
main (int argc, char** argv)
{
  std::string input_path, output_path, png_path;
  int k = 50;
  double radius = 0.0, max_radius = 0.0;
  pcl_ext::apps::VarianceClassificationOptions options;
  unsigned int threads = 0;
  pcl_ext::apps::CommandLine cl ("pcl_ext_classify_variance",
                                 "Labels every point 1 surface, 2 edge, 3 boundary or "
                                 "0 unknown from the covariance of its "
                                 "neighbourhood (Belton & Lichti 2006, section 2) and "
                                 "writes the input points with a "
                                 "'label' field.");
  cl.addPositional ("input.pcd", input_path, "input cloud (PCD or PLY)");
  cl.addPositional ("output.pcd", output_path, "output cloud with a 'label' field");
  cl.addOption ("k", k, "neighbours per point (the paper's k)");
  cl.addOption ("radius", radius, "neighbourhood radius instead of k (0: use k)");
  cl.addOption (
      "max_radius",
      max_radius,
      "with k: keep only the neighbours within this distance (0: no cap, the paper's)");
  options.addTo (cl);
  cl.addOption ("threads", threads, "OpenMP threads (0: all cores)");
  cl.addOption ("png",
                png_path,
                "also render the labels to this PNG (blue surface, red edge, "
                "green boundary); needs an X display");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!options.valid())
    return 1;
  if (!pcl_ext::io::checkOutputsWritable (output_path, {png_path}))
    return 1;

  pcl::PCLPointCloud2 input;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  if (!pcl_ext::apps::loadInput (input_path, input, *cloud))
    return 1;

  pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setInputCloud (cloud);
  if (cl.given ("radius"))
    classifier.setRadiusSearch (radius);
  else {
    classifier.setKSearch (k);
    classifier.setMaxRadius (max_radius);
  }
  options.applyTo (classifier);
  classifier.setNumberOfThreads (threads);
  pcl::PointCloud<pcl::Label> labels;
  pcl_ext::apps::StageTimer classify ("Classifying");
  classifier.classify (labels);
  if (labels.size() != cloud->size()) {
    std::cerr << "Error: classification failed (see the message above).\n";
    return 1;
  }
  classify.done (labels.size());
  std::size_t counts[pcl_ext::kNumPointClasses] = {};
  for (const auto& l : labels)
    ++counts[std::min<std::size_t> (l.label, pcl_ext::kNumPointClasses - 1)];
  std::cout << "curvature threshold " << classifier.getCurvatureThresholdUsed()
            << "; surface " << counts[1] << ", edge " << counts[2] << ", boundary "
            << counts[3] << ", unknown " << counts[0] << "\n";

  pcl::PCLPointCloud2 output;
  pcl_ext::apps::StageTimer save ("Saving " + output_path);
  if (!attachLabels (input, labels, output) ||
      !pcl_ext::io::saveCloud (output_path, output))
    return 1;
  save.done (labels.size());

  if (!png_path.empty()) {
#ifdef PCL_EXT_HAVE_VISUALIZATION
    pcl_ext::apps::StageTimer render ("Rendering " + png_path);
    std::vector<std::uint32_t> classes;
    classes.reserve (labels.size());
    for (const auto& l : labels)
      classes.push_back (l.label);
    pcl_ext::visualization::View view;
    view.title = "Belton & Lichti: surface (blue), edge (red), boundary (green)";
    view.layers.push_back (
        {pcl_ext::visualization::makeColouredCloud (
             *cloud, pcl_ext::visualization::colourByClass (classes)),
         2.0});
    if (!pcl_ext::visualization::renderToPng ({view}, png_path))
      return 1;
    render.done (labels.size());
#else
    std::cerr << "Error: built without the renderer; -png is not available.\n";
    return 1;
#endif
  }
  return 0;
}
