/*
 * pcl_ext_compare_segmenters: the input shared by the methods, the normals, one
 * method's run and the labels file.
 */
#pragma once

#include "comparison_report.h"
#include "segmenter_methods.h"

#include <pcl_ext/io/point_file.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace compare {
/** \brief Everything the methods share, and the ground truth of the same points. */
struct Comparison {
  SegmenterInput input;
  std::vector<std::size_t> source_index; ///< input-file index of each finite point
  std::size_t file_points = 0;
  bool organised = false;
  std::vector<std::uint32_t> truth; ///< per finite point; empty without ground truth
};

/** \brief Load \a path (any point file io::loadPointFile reads; the methods work on its
 * local coordinates), keep its finite points (with their colour when it has one) and,
 * when \a truth_field is not empty, their ground truth. Prints an error and returns
 * false when the file or the field cannot be read or no point is finite. */
bool
loadInput (const std::string& path,
           const std::string& truth_field,
           io::PointFile& file,
           Comparison& c);

/** \brief Normals (pcl::NormalEstimationOMP, k nearest) in a child process, so that
 * OpenMP never starts in this one (GNU libgomp does not survive a fork after it started
 * threads); their time and peak memory go to \a cost. */
bool
computeNormals (
    Comparison& c, int k, unsigned int threads, double timeout, MethodResult& cost);

/** \brief Run one method in a child process and score it against the ground truth, if
 * any. */
MethodResult
runMethod (const SegmenterMethod& method,
           const Comparison& c,
           const SegmenterSettings& settings,
           const MethodResult& normals_cost,
           double timeout);

/** \brief Save the input file with one uint32 field per method (its labels; 0 for
 * points that are not finite or in no segment) with io::savePointFile, in the input's
 * frame (and, to LAS, with its header; the labels become extra-bytes dimensions). */
bool
writeLabels (const std::string& path,
             io::PointFile& file,
             const Comparison& c,
             const std::vector<MethodResult>& results);
} // namespace compare
} // namespace pcl_ext
