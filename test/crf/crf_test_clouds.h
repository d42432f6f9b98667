/*
 * Test clouds for the super-voxel, saliency feature and CRF tests.
 */
#pragma once

#include <pcl_ext/apps/scene_crf_input.h>
#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <random>
#include <vector>

namespace crf_test
{
/** A horizontal floor (z = 0, 4 x 4 m) meeting a vertical wall (x = 0), grid spacing
  * \a step, Gaussian noise \a sigma along the normal. Labels: floor 1, wall 2. */
inline pcl::PointCloud<pcl::PointXYZ>::Ptr
floorAndWall (double step, double sigma, std::vector<std::uint32_t>* labels = nullptr,
              std::uint64_t seed = 7)
{
  std::mt19937_64 rng (seed);
  std::normal_distribution<float> noise (0.f, static_cast<float> (sigma));
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  const int n = static_cast<int> (std::round (4.0 / step));
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      cloud->push_back (pcl::PointXYZ (static_cast<float> (i * step),
                                       static_cast<float> (j * step), noise (rng)));
      if (labels)
        labels->push_back (1);
    }
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      cloud->push_back (pcl::PointXYZ (noise (rng), static_cast<float> (j * step),
                                       static_cast<float> (i * step)));
      if (labels)
        labels->push_back (2);
    }
  return cloud;
}

/** A generated street scene (Lim & Suter's classes) as CRF input plus its labels. */
inline bool
streetScene (std::uint64_t seed, std::size_t points, pcl_ext::CrfInput& input,
             std::vector<std::uint32_t>& labels,
             pcl_ext::simulation::SyntheticScene* keep = nullptr)
{
  pcl_ext::simulation::SceneParameters p;
  p.seed = seed;
  p.points = points;
  pcl_ext::simulation::SyntheticScene scene;
  if (!pcl_ext::simulation::generateScene ("street", p, scene))
    return false;
  input = pcl_ext::apps::makeCrfInput (scene, labels);
  if (keep)
    *keep = std::move (scene);
  return true;
}
}  // namespace crf_test
