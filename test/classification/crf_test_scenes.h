/*
 * Generated scenes as input of the CRF and super-voxel tests (Lim & Suter's classes).
 */
#pragma once

#include <pcl_ext/apps/scene_crf_input.h>
#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace crf_test {
/** A generated street scene (Lim & Suter's classes) as CRF input plus its labels. */
inline bool
streetScene (std::uint64_t seed,
             std::size_t points,
             pcl_ext::CrfInput& input,
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
} // namespace crf_test
