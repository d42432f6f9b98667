/*
 * pcl_ext_segment_variance: Belton & Lichti (2006) segmentation: classifies every point
 * surface, edge or boundary by local variance (section 2) and grows segments over the
 * surface points (section 3). Writes the input points and fields with the segment in
 * the field `segment` (-output_field): 1, 2, ... by decreasing size, 0 for points in no
 * segment (edges, boundaries, segments too small), in the input's coordinates.
 * Optionally intersects the segments locally (section 4): writes the intersection
 * points and puts edge and boundary points back into the segments they fit.
 */
#include "variance/segment_variance_options.h"

#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/coplanar_segment_merging.h>
#include <pcl_ext/segmentation/leftover_plane_assignment.h>
#include <pcl_ext/segmentation/leftover_region_growing.h>
#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/apps/picture_options.h>
#include <pcl_ext/io/file_output.h>
#ifdef PCL_EXT_HAVE_VISUALIZATION
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/visualization/offscreen_renderer.h>
#endif

#include <pcl/common/io.h>
#include <pcl/conversions.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

int
main (int argc, char** argv)
{
  std::string input_path, output_path, png_path;
  pcl_ext::apps::SegmentVarianceOptions options;
  unsigned int threads = 0;
  pcl_ext::apps::CommandLine cl ("pcl_ext_segment_variance",
                                 "Segments a cloud by region growing over the Belton & "
                                 "Lichti (2006) classification: "
                                 "surface points link to their nearest surface "
                                 "neighbours, edge and boundary points stop "
                                 "the growth. Writes the input points and fields with "
                                 "the segment (field 'segment': 1.. by decreasing "
                                 "size, 0: none) in the input's coordinates.");
  pcl_ext::apps::ResultField result = pcl_ext::apps::segmentIdField();
  options.addTo (cl);
  result.addTo (cl, input_path, output_path);
  cl.addOption ("threads", threads, "OpenMP threads (0: all cores)");
  cl.addOption (
      "png", png_path, "also render the segments to this PNG; needs an X display");
  pcl_ext::apps::PictureOptions picture;
  picture.addTo (cl);
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (!picture.valid())
    return 1;
  if (!options.valid (cl))
    return 1;
  const std::string& intersections_path = options.intersections_path;
  const bool intersect = options.intersects();
  if (!result.checkOutput (output_path, {png_path, intersections_path}))
    return 1;
  std::string reason;
  if (!intersections_path.empty() &&
      !pcl_ext::io::canWritePointFile (intersections_path, &reason)) {
    std::cerr << "Error: -intersections: " << reason << ".\n";
    return 1;
  }

  pcl_ext::io::PointFile input;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  if (!pcl_ext::apps::loadInput (input_path, input, *cloud) ||
      !result.checkInput (input, input_path))
    return 1;

  // One neighbourhood search for the segmentation and the intersections.
  const auto nb = options.makeNeighbourhoods (cloud, threads);
  pcl_ext::apps::StageTimer search ("Searching " + std::to_string (options.k) +
                                    " neighbours");
  if (!nb->compute()) {
    std::cerr << "Error: the neighbourhood search failed (see the message above).\n";
    return 1;
  }
  search.done (cloud->size());

  pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
  pcl_ext::VarianceRegionGrowing<pcl::PointXYZ> rg;
  options.configure (cloud, nb, threads, classifier, rg);
  std::vector<pcl::PointIndices> clusters;
  pcl_ext::apps::StageTimer segment ("Classifying and segmenting");
  pcl_ext::segmentByLocalVariance (classifier, rg, clusters);
  if (clusters.empty()) {
    std::cerr << "Error: segmentation failed or found no segment of at least "
              << options.min_size << " points (see the message above).\n";
    return 1;
  }
  segment.done (cloud->size());
  options.classification.report (classifier);
  pcl::PointCloud<pcl::Label> labels;
  rg.getSegmentLabels (labels);
  std::size_t segmented = 0, classes[pcl_ext::kNumPointClasses] = {};
  for (const auto& c : clusters)
    segmented += c.indices.size();
  for (const auto& c : *rg.getInputClasses())
    ++classes[std::min<std::size_t> (c.label, pcl_ext::kNumPointClasses - 1)];
  std::cout << clusters.size() << (clusters.size() == 1 ? " segment, " : " segments, ")
            << segmented << " points segmented, " << cloud->size() - segmented
            << " not (surface " << classes[1] << ", edge " << classes[2]
            << ", boundary " << classes[3] << ", unknown " << classes[0] << ")\n";

  pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> intersections;
  if (intersect) {
    pcl_ext::LocalSurfaceIntersection<pcl::PointXYZ> lsi;
    options.configure (cloud, nb, threads, lsi);
    lsi.setSegmentLabels (pcl::make_shared<pcl::PointCloud<pcl::Label>> (labels));
    lsi.setPointClasses (
        pcl::make_shared<pcl::PointCloud<pcl::Label>> (*rg.getInputClasses()));
    pcl::PointCloud<pcl::Label> reintegrated;
    pcl_ext::apps::StageTimer stage ("Intersecting segments");
    if (!lsi.compute (intersections, reintegrated)) {
      std::cerr
          << "Error: the local surface intersection failed (see the message above).\n";
      return 1;
    }
    stage.done (intersections.size());
    const auto& r = lsi.getReport();
    std::cout << intersections.size() << " intersection points from " << r.pairs
              << " pairs of segments' surface points (" << r.parallel << " parallel, "
              << r.beyond_tolerance << " too far, " << r.no_plane
              << " without a plane); " << r.examined
              << " edge and boundary points: " << r.reintegrated << " fit one segment, "
              << r.ambiguous << " several, " << r.left << " none\n";
    if (options.reintegrate)
      labels = reintegrated;
    if (!intersections_path.empty()) {
      pcl_ext::apps::StageTimer save ("Saving " + intersections_path);
      // In the input's frame, as the output.
      pcl::PCLPointCloud2 blob;
      pcl::toPCLPointCloud2 (intersections, blob);
      if (!pcl_ext::io::savePointFile (intersections_path, blob, input.origin))
        return 1;
      save.done (intersections.size());
    }
  }

  if (options.leftovers) {
    pcl_ext::LeftoverRegionGrowing<pcl::PointXYZ> growing;
    options.configure (cloud, nb, threads, growing);
    growing.setSegmentLabels (pcl::make_shared<pcl::PointCloud<pcl::Label>> (labels));
    pcl::PointCloud<pcl::Label> grown;
    pcl_ext::apps::StageTimer stage ("Growing segments among the points left out");
    if (!growing.compute (grown)) {
      std::cerr << "Error: growing the points left out failed (see the message "
                   "above).\n";
      return 1;
    }
    const auto& r = growing.getReport();
    stage.done (r.examined);
    std::cout << r.segments << " more segments of " << r.segmented << " of the "
              << r.examined << " points without one\n";
    labels = grown;
  }

  if (options.merge) {
    pcl_ext::CoplanarSegmentMerging<pcl::PointXYZ> merging;
    options.configure (cloud, nb, threads, merging);
    merging.setSegmentLabels (pcl::make_shared<pcl::PointCloud<pcl::Label>> (labels));
    pcl::PointCloud<pcl::Label> merged;
    pcl_ext::apps::StageTimer stage ("Merging interleaved pieces of one plane");
    if (!merging.compute (merged)) {
      std::cerr << "Error: merging the segments failed (see the message above).\n";
      return 1;
    }
    const auto& r = merging.getReport();
    stage.done (cloud->size());
    std::cout << r.segments << " segments, " << r.merges
              << " merged into others: " << r.result << " left\n";
    labels = merged;
  }

  if (options.assign) {
    pcl_ext::LeftoverPlaneAssignment<pcl::PointXYZ> assignment;
    options.configure (cloud, nb, threads, assignment);
    assignment.setSegmentLabels (
        pcl::make_shared<pcl::PointCloud<pcl::Label>> (labels));
    pcl::PointCloud<pcl::Label> assigned;
    pcl_ext::apps::StageTimer stage ("Assigning the points left over");
    if (!assignment.compute (assigned)) {
      std::cerr << "Error: assigning the points left over failed (see the message "
                   "above).\n";
      return 1;
    }
    const auto& r = assignment.getReport();
    stage.done (r.examined);
    std::cout << r.assigned << " of the " << r.examined
              << " points without a segment lie on a neighbouring segment's plane\n";
    labels = assigned;
  }

  std::vector<std::uint32_t> ids (labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    ids[i] = labels[i].label;
  if (!result.save (output_path, input, ids))
    return 1;

  if (!png_path.empty()) {
#ifdef PCL_EXT_HAVE_VISUALIZATION
    pcl_ext::apps::StageTimer render ("Rendering " + png_path);
    pcl_ext::visualization::View view;
    // The segments of the output, every stage's (not section 3's alone).
    const std::size_t segments =
        std::set<std::uint32_t> (ids.begin(), ids.end()).size() -
        (std::find (ids.begin(), ids.end(), 0u) != ids.end() ? 1 : 0);
    view.title = "Belton & Lichti: " + std::to_string (segments) + " segments";
    view.layers.push_back ({pcl_ext::visualization::makeColouredCloud (
        *cloud, pcl_ext::visualization::colourByLabel (ids))});
    view.legend.push_back (
        {"unsegmented", pcl_ext::visualization::colourByLabel ({0u}).front()});
    // With -intersections: the intersection points in black, larger, on top of the
    // segments (the re-integration alone computes them too, but they are not asked
    // for).
    const bool show_intersections =
        !intersections_path.empty() && !intersections.empty();
    if (show_intersections)
      view.legend.push_back ({"local intersection", {0, 0, 0}});
    if (show_intersections)
      view.layers.push_back (
          {pcl_ext::visualization::makeColouredCloud (
               intersections,
               std::vector<pcl_ext::visualization::Colour> (
                   intersections.size(), pcl_ext::visualization::Colour{0, 0, 0})),
           4.0});
    if (!pcl_ext::visualization::renderToPng (
            {view}, png_path, picture.renderOptions (*cloud)))
      return 1;
    render.done (ids.size());
#else
    std::cerr << "Error: built without the renderer; -png is not available.\n";
    return 1;
#endif
  }
  return 0;
}
