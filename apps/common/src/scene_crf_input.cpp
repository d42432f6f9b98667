/*
 * pcl_ext: a generated scene as the input of the multi-scale CRF, for the tools and the
 * tests.
 */
#include <pcl_ext/apps/scene_crf_input.h>

#include <pcl/point_types.h>

namespace pcl_ext {
namespace apps {
CrfInput
makeCrfInput (const simulation::SyntheticScene& scene,
              std::vector<std::uint32_t>& labels)
{
  CrfInput in;
  auto xyz = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  labels.clear();
  for (const auto& q : scene.cloud) {
    xyz->push_back (pcl::PointXYZ (q.x, q.y, q.z));
    const float sum = static_cast<float> (q.r) + q.g + q.b;
    in.colours.push_back (sum > 0.f ? Eigen::Vector3f (q.r / sum, q.g / sum, q.b / sum)
                                    : Eigen::Vector3f::Constant (1.f / 3.f));
    in.intensity.push_back (q.intensity);
    labels.push_back (q.label);
  }
  in.xyz = xyz;
  return in;
}
} // namespace apps
} // namespace pcl_ext
