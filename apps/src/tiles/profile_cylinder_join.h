/*
 * pcl_ext_tiles segment_profiles: the cylinder join over the segments that the parts
 * gave the whole cloud.
 */
#pragma once

#include "../profiles/profile_options.h"
#include "profile_parts.h"

#include <pcl_ext/tiling/tile_plan.h>

#include <cstdint>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief CylinderSegmentJoin (as \a options set it, ProfileOptions::makeJoin) over the
 * \a segments segments saved in \a workdir's results (saveSegments, numbered as the
 * untiled segmenter numbers its clusters). The join fits cylinders to whole segments
 * and bridges gaps of up to 80 spacings along an axis, so it runs over the whole
 * cloud's segments, but one at a time: their points are grouped by segment in work
 * files (SegmentPointsFile, from the parts of the first stack, which hold every finite
 * point once) and read a segment at a time (cylinder_join::joinSegments). Only the
 * estimate of the spacing holds all the segments' points (20 bytes a point), before the
 * join. The results are rewritten with the joined segments' ids, numbered as the join
 * numbers them; \a segments then holds their count and \a cylinders the cylinders
 * joined. \return false (message printed) when a file cannot be read or written or the
 * join fails */
bool
joinProfileCylinders (const tiling::TilePlan& plan,
                      const ProfileParts& parts,
                      const ProfileOptions& options,
                      const std::string& workdir,
                      unsigned int threads,
                      std::uint32_t& segments,
                      std::size_t& cylinders);
} // namespace apps
} // namespace pcl_ext
