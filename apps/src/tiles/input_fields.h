/*
 * pcl_ext_tiles: several inputs in one output: their fields, and their coordinate
 * reference system.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The fields of every input in one layout (io::unionOfFields over the fields
 * their reader gives): the output of a project whose scans carry different fields
 * keeps every field, 0 in the points of an input without it. \throw io::ReadError
 * naming an input that cannot be read \return false (message printed) when two inputs
 * give a field two types */
bool
unionOfInputFields (const std::vector<std::string>& inputs,
                    pcl::PCLPointCloud2& layout);

/** \brief Whether the inputs can share one output's coordinate reference system: no
 * two inputs declare CRSs known to differ (LAS / LAZ: their projection records, E57:
 * its coordinateMetadata, io::textCoordinateSystem; io::matchCoordinateSystems: two
 * EPSG codes, or two WKT CRSs of two names). Those are refused: a scan in UTM beside
 * one in a national grid is not one project until one of them is reprojected, and the
 * output (whose VLRs are the first input's) would misplace the other. Inputs whose CRS
 * cannot be compared with the first's, or that declare none (PCD, PLY, PTX, ASCII, or
 * LAS and E57 without a CRS), beside ones that do, get a warning. \throw io::ReadError
 * naming an input that cannot be read \return false (message printed) when they differ
 */
bool
sameCoordinateSystem (const std::vector<std::string>& inputs);

/** \brief Whether \a cloud's fields are those of \a layout (names, types, offsets). */
bool
hasLayout (const pcl::PCLPointCloud2& cloud, const pcl::PCLPointCloud2& layout);
} // namespace apps
} // namespace pcl_ext
