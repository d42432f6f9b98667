/*
 * pcl_ext: an app's input cloud, loaded with a timing line.
 */
#pragma once

#include <pcl_ext/io/point_file.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl_ext {
namespace apps {
/** \brief The formats every tool reads, for the -h texts. */
constexpr const char* kInputFormats =
    "LAS, LAZ, E57, PTX, PTS, PCD, PLY or ASCII (told by content)";

/** \brief The formats every tool writes, for the -h texts. */
constexpr const char* kOutputFormats =
    ".las, .pcd or .ply (by extension; coordinates in the input's frame)";

/** \brief Load an app's input with io::loadPointFile: the file in \a input (every
 * field, kept so that the output can carry them; the origin and the LAS header, to
 * write the result back in the input's frame) and its local x, y, z in \a xyz, with a
 * "Loading <path>" timing line and a note of the format and origin. On error prints
 * the reader's message (naming the file) and returns false. */
bool
loadInput (const std::string& path,
           io::PointFile& input,
           pcl::PointCloud<pcl::PointXYZ>& xyz,
           const io::PointFileOptions& options = {});
} // namespace apps
} // namespace pcl_ext
