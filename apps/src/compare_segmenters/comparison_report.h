/*
 * pcl_ext_compare_segmenters: the results of the methods, as a table, a CSV file and a
 * montage.
 */
#pragma once

#include <pcl_ext/evaluation/segmentation_metrics.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace compare {
/** \brief One method's run. */
struct MethodResult {
  std::string name;
  std::string library;
  bool needs_normals = false;
  bool ok = false;
  std::string error;        ///< why it failed, when !ok
  std::size_t segments = 0; ///< segments holding at least one point of the labels
  std::vector<std::uint32_t> labels; ///< one per (finite) point: segment 1.., 0 = none
  double seconds = 0.0; ///< the method's time, plus the normals' when it needs them
  std::size_t peak_bytes = 0;  ///< its peak memory above the loaded input
  std::size_t unsegmented = 0; ///< points with label 0
  bool evaluated = false;      ///< metrics hold the scores against the ground truth
  SegmentationMetrics metrics;
};

/** \brief Print the table to stdout: with ground truth the scores, otherwise counts and
 * times. */
void
printTable (const std::vector<MethodResult>& results, bool with_truth);

/** \brief The results as CSV, one row per method (full precision; empty cells for
 * scores without ground truth). */
std::string
makeCsv (const std::vector<MethodResult>& results, bool with_truth);

/** \brief The title of a method's tile in the montage: the method and its library, then
 * on a second line its mean best IoU (with truth), segment count and time. */
std::string
tileTitle (const MethodResult& result, bool with_truth);
} // namespace compare
} // namespace pcl_ext
