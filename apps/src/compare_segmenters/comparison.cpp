/*
 * pcl_ext_compare_segmenters: the input shared by the methods, the normals, one
 * method's run and the labels file.
 */
#include "comparison.h"
#include "isolated_run.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/apps/command_line.h>

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/conversions.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace pcl_ext {
namespace compare {
bool
loadInput (const std::string& path,
           const std::string& truth_field,
           io::PointFile& file,
           Comparison& c)
{
  pcl_ext::apps::StageTimer timer ("Loading " + path);
  try {
    io::loadPointFile (path, file);
  }
  catch (const io::ReadError& e) {
    std::cout << std::endl;
    std::cerr << "Error: " << e.what() << "\n";
    return false;
  }
  const pcl::PCLPointCloud2& blob = file.cloud;
  std::vector<std::uint32_t> truth;
  if (!truth_field.empty()) {
    std::string error;
    if (!pcl_ext::io::getLabelField (blob, truth_field, truth, &error)) {
      std::cout << std::endl;
      std::cerr << "Error: " << path << ": " << error << ".\n";
      return false;
    }
  }
  pcl::PointCloud<pcl::PointXYZ> all;
  pcl::fromPCLPointCloud2 (blob, all);
  const bool colour =
      pcl::getFieldIndex (blob, "rgb") >= 0 || pcl::getFieldIndex (blob, "rgba") >= 0;
  pcl::PointCloud<pcl::PointXYZRGBA> all_coloured;
  if (colour)
    pcl::fromPCLPointCloud2 (blob, all_coloured);
  c.file_points = all.size();
  c.organised = all.isOrganized();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::PointXYZRGBA>::Ptr coloured (
      new pcl::PointCloud<pcl::PointXYZRGBA>);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (pcl::isFinite (all[i])) {
      cloud->push_back (all[i]);
      if (colour)
        coloured->push_back (all_coloured[i]);
      if (!truth.empty())
        c.truth.push_back (truth[i]);
      c.source_index.push_back (i);
    }
  if (cloud->empty()) {
    std::cout << std::endl;
    std::cerr << "Error: " << path << " has no point with finite coordinates.\n";
    return false;
  }
  c.input.cloud = cloud;
  if (colour)
    c.input.coloured = coloured;
  timer.done (cloud->size());
  if (cloud->size() < all.size())
    std::cout << "  " << all.size() - cloud->size()
              << " points with non-finite coordinates left out (no method can segment "
                 "them)\n";
  return true;
}

bool
computeNormals (
    Comparison& c, int k, unsigned int threads, double timeout, MethodResult& cost)
{
  pcl_ext::apps::StageTimer timer (
      "Estimating normals (pcl::NormalEstimationOMP, k = " + std::to_string (k) + ")");
  pcl::PointCloud<pcl::Normal> normals;
  const auto run = runIsolated (
      [&] {
        pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne (threads);
        ne.setInputCloud (c.input.cloud);
        ne.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
            new pcl::search::KdTree<pcl::PointXYZ>));
        ne.setKSearch (k);
        ne.compute (normals);
        return normals.size() == c.input.cloud->size();
      },
      [&] {
        std::vector<char> bytes;
        appendBytes (std::vector<pcl::Normal> (normals.begin(), normals.end()), bytes);
        return bytes;
      },
      timeout);
  std::vector<pcl::Normal> values;
  std::size_t offset = 0;
  if (!run.ok || !readBytes (run.result, offset, c.input.cloud->size(), values)) {
    std::cout << std::endl;
    std::cerr << "Error: normal estimation "
              << (run.ok ? "sent a short result" : run.error) << ".\n";
    return false;
  }
  pcl::PointCloud<pcl::Normal>::Ptr cloud (new pcl::PointCloud<pcl::Normal>);
  cloud->assign (
      values.begin(), values.end(), static_cast<pcl::index_t> (values.size()));
  c.input.normals = cloud;
  cost.seconds = run.seconds;
  cost.peak_bytes = run.peak_bytes;
  timer.done (values.size());
  char line[128];
  std::snprintf (line,
                 sizeof (line),
                 "  %.3f s, peak %.1f MB (counted in the methods that use them)\n",
                 run.seconds,
                 static_cast<double> (run.peak_bytes) / (1024.0 * 1024.0));
  std::cout << line;
  return true;
}

MethodResult
runMethod (const SegmenterMethod& method,
           const Comparison& c,
           const SegmenterSettings& settings,
           const MethodResult& normals_cost,
           double timeout)
{
  MethodResult r;
  r.name = method.name;
  r.library = method.library;
  r.needs_normals = method.needs_normals;
  const std::size_t n = c.input.cloud->size();
  pcl_ext::apps::StageTimer timer ("Running " + method.name);
  std::vector<pcl::PointIndices> clusters;
  const auto run =
      runIsolated ([&] { return method.run (c.input, settings, clusters); },
                   [&] {
                     // Overlapping clusters (super-voxels) keep their points in the
                     // first cluster that holds them; the segments counted are those
                     // left with a point.
                     std::vector<std::uint32_t> labels;
                     pcl_ext::labelsFromIndices (clusters, n, labels);
                     std::vector<char> used (clusters.size() + 1, 0);
                     for (const auto l : labels)
                       used[l] = 1;
                     const std::uint64_t segments = static_cast<std::uint64_t> (
                         std::count (used.begin() + 1, used.end(), 1));
                     std::vector<char> bytes;
                     appendBytes (std::vector<std::uint64_t>{segments}, bytes);
                     appendBytes (labels, bytes);
                     return bytes;
                   },
                   timeout);
  std::vector<std::uint64_t> count;
  std::size_t offset = 0;
  if (!run.ok || !readBytes (run.result, offset, 1, count) ||
      !readBytes (run.result, offset, n, r.labels)) {
    r.error = run.ok ? "short result" : run.error;
    std::cout << "[failed: " << r.error << "]" << std::endl;
    return r;
  }
  r.ok = true;
  r.segments = static_cast<std::size_t> (count[0]);
  r.seconds = run.seconds;
  r.peak_bytes = run.peak_bytes;
  if (method.needs_normals) {
    // As if the method had estimated them itself: their time, and the larger of their
    // estimation's peak and their storage plus the method's own peak.
    r.seconds += normals_cost.seconds;
    r.peak_bytes =
        std::max (normals_cost.peak_bytes, run.peak_bytes + n * sizeof (pcl::Normal));
  }
  for (const auto l : r.labels)
    r.unsegmented += l == 0;
  timer.done (n);
  if (!c.truth.empty())
    r.evaluated = pcl_ext::evaluateSegmentation (r.labels, c.truth, r.metrics);
  return r;
}

bool
writeLabels (const std::string& path,
             io::PointFile& file,
             const Comparison& c,
             const std::vector<MethodResult>& results)
{
  pcl_ext::apps::StageTimer timer ("Saving " + path);
  for (const auto& r : results) {
    if (!r.ok)
      continue;
    std::vector<std::uint32_t> labels (c.file_points, 0);
    for (std::size_t i = 0; i < r.labels.size(); ++i)
      labels[c.source_index[i]] = r.labels[i];
    if (!pcl_ext::io::setLabelField (file.cloud, r.name, labels))
      return false;
  }
  if (!pcl_ext::io::savePointFile (path, file.cloud, file.origin, &file))
    return false;
  timer.done (c.file_points);
  return true;
}
} // namespace compare
} // namespace pcl_ext
