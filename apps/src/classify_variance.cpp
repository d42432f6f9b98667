/*
 * pcl_ext_classify_variance: labels every point surface (1), edge (2), boundary (3) or
 * unknown (0) by local variance (Belton & Lichti 2006, section 2) and writes the input
 * points, every input field and the class in the field `lv_class` (-output_field), in
 * the input's coordinates.
 */
#include "variance/edge_localisation_option.h"
#include "variance/variance_options.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/output.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

#include <pcl/common/io.h>
#include <pcl/conversions.h>

#include <pcl_ext/apps/picture_options.h>

#include <cstring>
#include <cmath>
#include <iostream>

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
                                 "writes the input points, their fields and the class "
                                 "(field 'lv_class') in the input's coordinates.");
  pcl_ext::apps::ResultField result (
      "lv_class",
      "class (1 surface, 2 edge, 3 boundary, 0 unknown)",
      "",
      "surface, edge and boundary have no ASPRS class code; the classes go to the "
      "-output_field field (LAS: an extra-bytes dimension)");
  cl.addOption ("k", k, "neighbours per point (the paper's k)");
  cl.addOption ("radius", radius, "neighbourhood radius instead of k (0: use k)");
  cl.addOption (
      "max_radius",
      max_radius,
      "with k: keep only the neighbours within this distance (0: no cap, the paper's)");
  options.addTo (cl);
  pcl_ext::apps::EdgeLocalisationOption edges;
  edges.addTo (cl);
  result.addTo (cl, input_path, output_path);
  cl.addOption ("threads", threads, "OpenMP threads (0: all cores)");
  cl.addOption ("png",
                png_path,
                "also render the classes to this PNG, with a legend; needs an X "
                "display");
  pcl_ext::apps::PictureOptions picture;
  picture.addTo (cl);
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!picture.valid())
    return 1;
  if (!options.valid (cl))
    return 1;
  if (!cl.given ("radius") && k < 3) {
    std::cerr << "Error: -k must be at least 3 (a plane needs three points).\n";
    return 1;
  }
  if (!result.checkOutput (output_path, {png_path}))
    return 1;

  pcl_ext::io::PointFile input;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  if (!pcl_ext::apps::loadInput (input_path, input, *cloud) ||
      !result.checkInput (input, input_path))
    return 1;

  // One search for the classification and the narrowing of the edges.
  auto nb = pcl::make_shared<pcl_ext::Neighbourhoods<pcl::PointXYZ>>();
  nb->setInputCloud (cloud);
  if (cl.given ("radius"))
    nb->setRadiusSearch (radius);
  else {
    nb->setKSearch (k);
    nb->setMaxRadius (max_radius);
  }
  nb->setNumberOfThreads (threads);
  nb->setStoreSquaredDistances (false);
  pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setInputCloud (cloud);
  classifier.setNeighbourhoods (nb);
  options.applyTo (classifier);
  classifier.setNumberOfThreads (threads);
  pcl::PointCloud<pcl::Label> labels;
  pcl_ext::apps::StageTimer classify ("Classifying");
  if (nb->compute())
    classifier.classify (labels);
  if (labels.size() != cloud->size()) {
    std::cerr << "Error: classification failed (see the message above).\n";
    return 1;
  }
  std::size_t wide_edges = 0;
  for (const auto& l : labels)
    wide_edges += l.label == static_cast<std::uint32_t> (pcl_ext::PointClass::Edge);
  const bool narrowed = edges.localises (options.preset);
  if (narrowed && !pcl_ext::apps::EdgeLocalisationOption::localise<pcl::PointXYZ> (
                      cloud, nb, threads, labels))
    return 1;
  classify.done (labels.size());
  options.report (classifier);
  std::size_t counts[pcl_ext::kNumPointClasses] = {};
  for (const auto& l : labels)
    ++counts[std::min<std::size_t> (l.label, pcl_ext::kNumPointClasses - 1)];
  std::cout << "curvature threshold " << classifier.getCurvatureThresholdUsed()
            << "; surface " << counts[1] << ", edge " << counts[2] << ", boundary "
            << counts[3] << ", unknown " << counts[0];
  if (narrowed)
    std::cout << " (edges narrowed to their creases; " << wide_edges << " before)";
  std::cout << "\n";

  std::vector<std::uint32_t> classes (labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    classes[i] = labels[i].label;
  if (!result.save (output_path, input, classes))
    return 1;

  if (!png_path.empty()) {
#ifdef PCL_EXT_HAVE_VISUALIZATION
    pcl_ext::apps::StageTimer render ("Rendering " + png_path);
    pcl_ext::visualization::View view;
    view.title = "Belton & Lichti: local variance classes";
    view.layers.push_back ({pcl_ext::visualization::makeColouredCloud (
        *cloud, pcl_ext::visualization::colourByClass (classes))});
    view.legend = pcl_ext::visualization::classLegend();
    if (!pcl_ext::visualization::renderToPng (
            {view}, png_path, picture.renderOptions (*cloud)))
      return 1;
    render.done (labels.size());
#else
    std::cerr << "Error: built without the renderer; -png is not available.\n";
    return 1;
#endif
  }
  return 0;
}
