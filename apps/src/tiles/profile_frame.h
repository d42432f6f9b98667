/*
 * pcl_ext_tiles segment_profiles: what the profile segmentation derives from the whole
 * cloud (centre, spacing, statistics, stack origins), found in passes over the inputs.
 */
#pragma once

#include <pcl_ext/segmentation/profile_auto.h>
#include <pcl_ext/tiling/point_file_chunks.h>
#include <pcl_ext/tiling/tile_plan.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The whole cloud as pcl_ext::ProfileSegmentation sees it, so that a part of it
 * is segmented as the whole would be (ProfileSegmentation::setCloudFrame). */
struct ProfileFrame {
  std::uint64_t points = 0; ///< finite points
  /** \brief Mean of the finite points, relative to the plan's origin, summed in the
   * points' order as ProfileSegmentation does. */
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  /** \brief The stacks' normals as profiles::makeStackNormals gives them. */
  std::vector<Eigen::Vector3f> normals;
  /** \brief Per stack, the lowest coordinate of a point along profiles::stackDirection
   * (where profile 0 starts) and the highest. */
  std::vector<double> origins, ends;
  /** \brief The sampled neighbourhoods' spacing (profiles::pointSpacingOf; 0 when the
   * options give width and threshold and the method is not automatic). */
  double spacing = 0.0;
  /** \brief Their statistics, for -method auto (profiles::cloudStatisticsOf). */
  profiles::CloudStatistics statistics;
  double width = 0.0; ///< the profile width

  /** \brief Into a plan's settings (exact text: every double to 17 digits). */
  void
  saveTo (std::map<std::string, std::string>& settings) const;

  /** \brief From a plan's settings. \return false (message printed) when missing */
  bool
  loadFrom (const std::map<std::string, std::string>& settings);
};

/** \brief Passes over the points of a plan's inputs, in chunks. An input that is not
 * LAS / LAZ (read whole by tiling::PointFileChunks) is kept between the passes; LAS
 * and LAZ inputs are opened again for each. */
class InputPasses {
public:
  explicit InputPasses (const tiling::TilePlan& plan) : plan_ (plan) {}

  const tiling::TilePlan&
  getPlan () const
  {
    return plan_;
  }

  /** \brief Call \a visit (global index, x y z relative to the plan's origin) for every
   * finite point, in order. \throw io::ReadError naming an input that cannot be read */
  void
  forEachFinitePoint (
      const std::function<void (std::uint64_t, const Eigen::Vector3f&)>& visit);

private:
  const tiling::TilePlan& plan_;
  std::vector<std::unique_ptr<tiling::PointFileChunks>> kept_;
};

/** \brief The frame of the inputs for \a normals: the centre and the stack
 * origins (two passes over the inputs) and, when \a sample, the neighbourhoods of the
 * points profiles::sampleNeighbourhoods samples, found exactly over the whole cloud
 * (a pass to rank the points along the sample axis, one to pick the samples, then one
 * per search radius), whence the spacing and statistics; the width is \a width, or
 * \a width_factor spacings. \throw io::ReadError naming an input that cannot be read
 * \return false (message printed) when the cloud has no finite point, a spacing is
 * needed and cannot be estimated, or the samples' ranks cannot be resolved */
bool
estimateProfileFrame (InputPasses& inputs,
                      const std::vector<Eigen::Vector3f>& normals,
                      bool sample,
                      double width,
                      double width_factor,
                      ProfileFrame& frame);

/** \brief \a n values as a plan setting's text, \a digits significant digits each. */
std::string
joinValues (const double* values, std::size_t n, int digits);

/** \brief The values of a plan setting \a key written by joinValues. \return false when
 * it is missing or not a list of numbers */
bool
parseValues (const std::map<std::string, std::string>& settings,
             const std::string& key,
             std::vector<double>& values);

/** \brief The point as ProfileSegmentation computes it: relative to the centre, in
 * float. */
inline Eigen::Vector3f
centred (const Eigen::Vector3f& local, const Eigen::Vector3d& centre)
{
  return (local.cast<double>() - centre).cast<float>();
}
} // namespace apps
} // namespace pcl_ext
