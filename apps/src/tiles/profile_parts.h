/*
 * pcl_ext_tiles segment_profiles: the cloud split by profiles, each stack's profiles
 * in runs of whole profiles, one file of points per run.
 */
#pragma once

#include "profile_frame.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The parts of a run split by profiles: per stack, the first profile of each
 * part (ascending, the first 0); a part holds its profiles' every point, so that
 * ProfileSegmentation on it gives the whole cloud's edges among them. */
struct ProfileParts {
  std::vector<std::vector<std::uint64_t>> firsts;

  /** \brief Parts of all stacks. */
  std::size_t
  size () const;

  /** \brief The stack and the part within it of part \a i of all stacks (stack after
   * stack). */
  void
  locate (std::size_t i, std::size_t& stack, std::size_t& part) const;

  /** \brief The part of stack \a stack that holds profile \a profile. */
  std::size_t
  partOf (std::size_t stack, std::uint64_t profile) const;

  void
  saveTo (std::map<std::string, std::string>& settings) const;

  /** \return false (message printed) when the settings have no valid parts */
  bool
  loadFrom (const std::map<std::string, std::string>& settings, std::size_t stacks);
};

/** \brief The profile of the point at \a t along its stack's direction, numbered as
 * profiles::buildStack numbers it from \a origin with \a width. */
std::uint64_t
profileNumber (double t, double origin, double width);

/** \brief Split each stack of \a frame into parts of whole profiles (a pass over the
 * inputs counting the points of runs of profiles): with \a thickness > 0, slabs of as
 * many whole profiles as fit in it (at least one), those that hold points; otherwise
 * runs of at most \a max_points points where no single profile holds more. \throw
 * io::ReadError naming an input that cannot be read \return false (message printed)
 * when the thickness makes too many slabs */
bool
planProfileParts (InputPasses& inputs,
                  const ProfileFrame& frame,
                  double thickness,
                  std::uint64_t max_points,
                  ProfileParts& parts);

/** \brief The file of part \a part of stack \a stack in \a workdir, with \a extension
 * ("points": its points; "links": what its segmentation found). */
std::string
profilePartPath (const std::string& workdir,
                 std::size_t stack,
                 std::size_t part,
                 const std::string& extension);

/** \brief Write every finite point into the file of its part in each stack (its
 * global index and its x y z relative to the plan's origin, in the inputs' order): a
 * pass over the inputs. \throw io::ReadError naming an input that cannot be read
 * \return false (message printed) when a file cannot be written (a full disk) */
bool
writeProfileParts (InputPasses& inputs,
                   const ProfileFrame& frame,
                   const ProfileParts& parts,
                   const std::string& workdir);

/** \brief Read the points of a part file (writeProfileParts): \a indices their global
 * indices, \a cloud their x y z. \return false (message printed) when the file is
 * missing or broken */
bool
readProfilePart (const std::string& path,
                 std::vector<std::uint64_t>& indices,
                 pcl::PointCloud<pcl::PointXYZ>& cloud);
} // namespace apps
} // namespace pcl_ext
