/*
 * pcl_ext: rigid / similarity transforms stored as text.
 */
#pragma once

#include <pcl_ext/io/read_error.h>

#include <Eigen/Core>

#include <string>

namespace pcl_ext {
namespace io {
/** \brief Read a transform written as text, row by row: 16 numbers (4 x 4) or 12 (3 x
 * 4, the bottom row 0 0 0 1 implied), separated by blanks, commas or line breaks; '#'
 * comment lines.
 *
 * The four-lines-of-four layout is what the synthetic building scene writes next to its
 * cloud (map = T * scan). The bottom row of a 4 x 4 must be 0 0 0 1 (within 1e-9).
 * \throw ReadError naming the file (and the line of a bad number) when it is missing,
 * holds something else than 12 or 16 finite numbers, or a 4 x 4 with another bottom
 * row; \a transform is untouched then
 */
void
loadTransform (const std::string& path, Eigen::Matrix4d& transform);
} // namespace io
} // namespace pcl_ext
