/*
 * pcl_ext_demo: shared state of the demo steps.
 */
#include "demo_context.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/cloud_io.h>

#include <fstream>
#include <iostream>

namespace pcl_ext {
namespace demo {
const simulation::SyntheticScene*
DemoContext::scene (const std::string& name)
{
  auto& slot = scenes_[name];
  if (slot)
    return slot.get();
  simulation::SceneParameters parameters;
  parameters.seed = seed;
  parameters.points = points;
  parameters.threads = threads;
  auto scene = std::make_unique<simulation::SyntheticScene>();
  apps::StageTimer timer ("Generating scene '" + name + "'");
  if (!simulation::generateScene (name, parameters, *scene)) {
    std::cerr << "Error: could not generate scene '" << name << "'.\n";
    scenes_.erase (name);
    return nullptr;
  }
  const double ms = timer.done (scene->cloud.size());
  summary << "  generated " << name << ": " << scene->cloud.size() << " points in "
          << ms << " ms\n";
  slot = std::move (scene);
  return slot.get();
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
DemoContext::loadRoomScan()
{
  if (shared_data_dir.empty())
    return nullptr;
  const std::string room = shared_data_dir + "/pcl_data_tutorials/room_scan1.pcd";
  if (!std::ifstream (room).good()) {
    summary << "  room_scan1.pcd: not found under " << shared_data_dir << ", skipped\n";
    return nullptr;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  if (!io::loadCloud (room, *cloud))
    cloud->clear();
  return cloud;
}

std::string
DemoContext::path (const std::string& file) const
{
  return out_dir + "/" + file;
}

bool
DemoContext::render (const std::vector<visualization::View>& views,
                     const std::string& file,
                     const visualization::RenderOptions& options)
{
  apps::StageTimer timer ("Rendering " + file);
  if (!visualization::renderToPng (views, path (file), options))
    return false;
  timer.done (0);
  summary << "  image: " << file << "\n";
  ++images;
  return true;
}
} // namespace demo
} // namespace pcl_ext
