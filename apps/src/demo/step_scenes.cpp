/*
 * pcl_ext_demo step: the ground truth of every generated scene.
 */
#include "demo_context.h"

#include <pcl_ext/visualization/colour_maps.h>

namespace pcl_ext {
namespace demo {
bool
runScenesStep (DemoContext& context)
{
  bool ok = true;
  for (const auto& name : simulation::sceneNames()) {
    const auto* scene = context.scene (name);
    if (!scene) {
      ok = false;
      continue;
    }
    std::vector<std::uint32_t> segments, classes;
    segments.reserve (scene->cloud.size());
    classes.reserve (scene->cloud.size());
    for (const auto& p : scene->cloud) {
      segments.push_back (p.segment);
      classes.push_back (p.point_class);
    }
    using namespace visualization;
    std::vector<View> views = {
        {name + ": segments (ground truth)",
         {{makeColouredCloud (scene->cloud, colourByLabel (segments))}},
         {{"unsegmented", colourByLabel ({0u}).front()}}},
        {name + ": classes (ground truth)",
         {{makeColouredCloud (scene->cloud, colourByClass (classes))}},
         classLegend()}};
    RenderOptions options;
    options.width = 1600;
    options.height = 700;
    ok = context.render (views, "scene_" + name + ".png", options) && ok;
  }
  return ok;
}
} // namespace demo
} // namespace pcl_ext
