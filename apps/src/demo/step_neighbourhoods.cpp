/*
 * pcl_ext_demo step: the shared neighbourhood pass and the covariance kernel on
 * `indoor`.
 */
#include "demo_context.h"

#include <pcl_ext/common/covariance.h>
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/visualization/colour_maps.h>

#include <pcl/common/io.h>

namespace pcl_ext {
namespace demo {
bool
runNeighbourhoodsStep (DemoContext& context)
{
  const auto* scene = context.scene ("indoor");
  if (!scene)
    return false;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::copyPointCloud (scene->cloud, *cloud);

  Neighbourhoods<pcl::PointXYZ> nb;
  nb.setInputCloud (cloud);
  nb.setKSearch (context.k);
  nb.setNumberOfThreads (context.threads);
  apps::StageTimer search ("Searching neighbourhoods, k = " +
                           std::to_string (context.k));
  if (!nb.compute())
    return false;
  const double search_ms = search.done (cloud->size());

  apps::StageTimer features ("Covariance and surface variance (eq. 4)");
  std::vector<float> variance (cloud->size());
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (cloud->size());
  const unsigned int threads = resolveThreadCount (context.threads);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1024)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    Eigen::Matrix3d cov;
    Eigen::Vector3d centroid;
    EigenDecomposition eig;
    const auto row = nb[i];
    variance[i] =
        computeLocalCovariance (*cloud, row.begin(), row.end(), cov, centroid) > 2 &&
                computeEigenDecomposition (cov, eig)
            ? static_cast<float> (surfaceVariance (eig.values))
            : std::numeric_limits<float>::quiet_NaN();
  }
  const double features_ms = features.done (cloud->size());

  context.summary << "  indoor: " << cloud->size() << " points, k = " << context.k
                  << ": neighbourhoods " << search_ms << " ms, covariance + eigen "
                  << features_ms << " ms\n";
  using namespace visualization;
  // The colour bar's range: colourByScalar's own (2nd to 98th percentile).
  std::vector<float> finite;
  for (const float v : variance)
    if (std::isfinite (v))
      finite.push_back (v);
  float lo = 0.0f, hi = 1.0f / 3.0f;
  if (!finite.empty()) {
    std::sort (finite.begin(), finite.end());
    lo = finite[finite.size() * 2 / 100];
    hi = std::max (finite[finite.size() * 98 / 100], lo + 1e-6f);
  }
  RenderOptions options;
  options.width = 1200;
  options.height = 800;
  return context.render (
      {{"indoor: surface variance l0 / (l0 + l1 + l2), k = " +
            std::to_string (context.k),
        {{makeColouredCloud (*cloud,
                             colourByScalar (variance, ColourMap::Viridis, lo, hi))}},
        {},
        {"surface variance", lo, hi, ColourMap::Viridis}}},
      "indoor_surface_variance.png",
      options);
}
} // namespace demo
} // namespace pcl_ext
