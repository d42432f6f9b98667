/*
 * pcl_ext_demo: what the demo steps share.
 */
#pragma once

#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>

namespace pcl_ext {
namespace demo {
/** \brief Options, the scenes generated so far, and the summary being written. */
struct DemoContext {
  std::string out_dir = "out";
  std::size_t points = 0; ///< target points per scene; 0: each scene's default
  std::uint64_t seed = 1;
  int k = 50;
  unsigned int threads = 0;
  std::string shared_data_dir; ///< real scans, when present (optional steps)

  std::ostringstream
      summary; ///< the text summary, written to out/summary.txt at the end
  std::size_t images = 0;

  /** \brief The scene \a name, generated on first use with the demo's seed and size. */
  const simulation::SyntheticScene*
  scene (const std::string& name);

  /** \brief Render views to out/<file>.png; notes the image in the summary. */
  bool
  render (const std::vector<visualization::View>& views,
          const std::string& file,
          const visualization::RenderOptions& options = visualization::RenderOptions());

  /** \brief PCL's room_scan1.pcd from the shared data folder, for the steps that also
   * run on a real scan: null when there is none (no folder given, or not in it, which
   * the summary notes); an empty cloud when it could not be read. */
  pcl::PointCloud<pcl::PointXYZ>::Ptr
  loadRoomScan ();

  /** \brief Path of \a file inside the output folder. */
  std::string
  path (const std::string& file) const;

private:
  std::map<std::string, std::unique_ptr<simulation::SyntheticScene>> scenes_;
};

/** \name Demo steps: each adds its images and a section of the summary. \{ */
bool
runScenesStep (DemoContext& context);
bool
runNeighbourhoodsStep (DemoContext& context);
bool
runProfilesStep (DemoContext& context);
bool
runClassificationStep (DemoContext& context);
/** \brief Belton & Lichti region growing over the classification. */
bool
runVarianceSegmentationStep (DemoContext& context);
bool
runRegistrationStep (DemoContext& context);
/** \brief Lim & Suter's multi-scale CRF: train on one street scene, classify another.
 */
bool
runCrfStep (DemoContext& context);

/** \} */
} // namespace demo
} // namespace pcl_ext
