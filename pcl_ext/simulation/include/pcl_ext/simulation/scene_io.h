/*
 * pcl_ext: saving and loading synthetic scenes with their ground truth.
 */
#pragma once

#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/simulation/simulated_point.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>

#include <string>

namespace pcl_ext {
namespace simulation {
/** \brief Save a scene; every file is written atomically (a temporary file renamed into
 * place).
 *
 * Files:
 * - \a path (PCD, binary-compressed unless \a ascii): one point per return, fields in
 * order
 *   - \c x \c y \c z (F32): measured position in the cloud frame (scene coordinates
 * plus the offset; for \c building, the scan frame);
 *   - \c rgb (F32, PCL's packed colour) and \c intensity (F32, in [0, 1]) when the
 * scene has them (all scenes but cubes, spheres and coaxial);
 *   - \c segment, \c object (U32): true segment (a connected visible piece of a
 * surface, see TlsScanSimulation::setConnectedSegments) and object ids, >= 1;
 *   - \c class (U32): pcl_ext::PointClass, 1 surface, 2 edge, 3 boundary;
 *   - \c label (U32): the scene label when the scene has labels (see scenes.h), 0 =
 * none.
 * - building only, next to it (\a path without its extension is the stem):
 *   - \c <stem>.footprint.wkt: one line `POLYGON((x y, x y, ..., x y))`, the footprint
 * in map coordinates (metres, offset included), counter-clockwise, first vertex
 * repeated last;
 *   - \c <stem>.transform.txt: the true 4 x 4 scan-to-map transform (map = T * scan),
 * four lines of four numbers separated by spaces, row by row. \return false (with an
 * error naming the file) when a file cannot be written
 */
bool
saveScene (const std::string& path, const SyntheticScene& scene, bool ascii = false);

/** \brief The scene's cloud as a PCLPointCloud2 with the fields saveScene writes (the
 * \c point_class member renamed \c class). */
void
sceneToPointCloud2 (const SyntheticScene& scene, pcl::PCLPointCloud2& blob);

/** \brief Load a PCD written by saveScene (fields missing from the file stay 0).
 * \return false with an error naming the file when it is missing or malformed */
bool
loadScene (const std::string& path, pcl::PointCloud<SimulatedPoint>& cloud);

/** \brief The footprint as WKT: `POLYGON((x y, ..., x y))` (closed ring). */
std::string
footprintToWkt (const std::vector<Eigen::Vector2d>& footprint);

/** \brief A 4 x 4 matrix as four lines of four numbers (17 significant digits). */
std::string
matrixToText (const Eigen::Matrix4d& matrix);

/** \brief The stem of \a path: the path without its extension. */
std::string
pathStem (const std::string& path);
} // namespace simulation
} // namespace pcl_ext
