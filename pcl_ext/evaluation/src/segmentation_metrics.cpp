/*
 * pcl_ext: segmentation metrics against a ground-truth labelling.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pcl_ext {
namespace {
/** Dense ids for the labels of one labelling, in order of first appearance. */
class LabelIndex {
public:
  std::size_t
  idOf (std::uint32_t label)
  {
    // Segments are usually stored in runs: remembering the last label skips most
    // lookups.
    if (label == last_label_ && have_last_)
      return last_id_;
    const auto [it, inserted] = ids_.try_emplace (label, labels_.size());
    if (inserted) {
      labels_.push_back (label);
      sizes_.push_back (0);
    }
    last_label_ = label;
    last_id_ = it->second;
    have_last_ = true;
    return last_id_;
  }

  std::vector<std::uint32_t> labels_;
  std::vector<std::size_t> sizes_;

private:
  std::unordered_map<std::uint32_t, std::size_t> ids_;
  std::uint32_t last_label_ = 0;
  std::size_t last_id_ = 0;
  bool have_last_ = false;
};

struct Overlap {
  std::size_t other; // dense id of the segment in the other labelling
  std::size_t count;
};

/** Hoover et al.'s over- or under-segmentation of one segment of \a size points, whose
 * overlaps with the other labelling are \a overlaps: the unused segments of the other
 * labelling (sizes \a other_size) with at least T of their points in it, when there
 * are two or more and they hold at least T of its points. Those are marked used in
 * \a other_used and returned (their dense ids); none otherwise. \a covers (overlap,
 * size) tells overlap >= T size. */
template <typename Covers>
std::vector<std::size_t>
claimParts (const std::vector<Overlap>& overlaps,
            std::size_t size,
            const std::vector<std::size_t>& other_size,
            std::vector<bool>& other_used,
            const Covers& covers)
{
  std::vector<std::size_t> parts;
  std::size_t covered = 0;
  for (const Overlap& o : overlaps)
    if (!other_used[o.other] && covers (o.count, other_size[o.other])) {
      parts.push_back (o.other);
      covered += o.count;
    }
  if (parts.size() < 2 || !covers (covered, size))
    return {};
  for (const std::size_t other : parts)
    other_used[other] = true;
  return parts;
}
} // namespace

const char*
segmentOutcomeName (SegmentOutcome outcome)
{
  switch (outcome) {
  case SegmentOutcome::Correct:
    return "correct";
  case SegmentOutcome::OverSegmented:
    return "over";
  case SegmentOutcome::UnderSegmented:
    return "under";
  default:
    return "missed";
  }
}

bool
evaluateSegmentation (const std::vector<std::uint32_t>& predicted,
                      const std::vector<std::uint32_t>& truth,
                      SegmentationMetrics& metrics,
                      double tolerance)
{
  metrics = SegmentationMetrics();
  metrics.tolerance = tolerance;
  if (predicted.size() != truth.size()) {
    PCL_ERROR (
        "[pcl_ext::evaluateSegmentation] %zu predicted labels for %zu ground-truth "
        "labels: the sizes must be equal.\n",
        predicted.size(),
        truth.size());
    return false;
  }
  if (!(tolerance > 0.5 && tolerance <= 1.0)) {
    PCL_ERROR ("[pcl_ext::evaluateSegmentation] tolerance %g is outside (0.5, 1].\n",
               tolerance);
    return false;
  }

  // Count points per segment and per (truth, predicted) pair, sparsely.
  LabelIndex truth_ids, predicted_ids;
  std::unordered_map<std::uint64_t, std::size_t> pair_counts;
  std::uint64_t last_key = ~std::uint64_t (0);
  std::size_t* last_count = nullptr;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i] == 0) {
      ++metrics.ignored_points;
      continue;
    }
    ++metrics.evaluated_points;
    const std::size_t t = truth_ids.idOf (truth[i]);
    ++truth_ids.sizes_[t];
    if (predicted[i] == 0) {
      ++metrics.unsegmented_points;
      continue;
    }
    const std::size_t p = predicted_ids.idOf (predicted[i]);
    ++predicted_ids.sizes_[p];
    const std::uint64_t key = (static_cast<std::uint64_t> (t) << 32) | p;
    if (key != last_key) {
      last_count = &pair_counts[key]; // references into unordered_map survive rehashing
      last_key = key;
    }
    ++*last_count;
  }
  const std::size_t num_truth = truth_ids.labels_.size();
  const std::size_t num_predicted = predicted_ids.labels_.size();
  metrics.num_truth_segments = num_truth;
  metrics.num_predicted_segments = num_predicted;
  if (metrics.evaluated_points > 0)
    metrics.unsegmented_fraction =
        static_cast<double> (metrics.unsegmented_points) / metrics.evaluated_points;

  std::vector<std::vector<Overlap>> by_truth (num_truth), by_predicted (num_predicted);
  for (const auto& [key, count] : pair_counts) {
    const std::size_t t = key >> 32, p = key & 0xffffffffu;
    by_truth[t].push_back ({p, count});
    by_predicted[p].push_back ({t, count});
  }
  const auto& tsize = truth_ids.sizes_;
  const auto& psize = predicted_ids.sizes_;

  // Best IoU per ground-truth segment.
  std::vector<SegmentMatch> matches (num_truth);
  for (std::size_t t = 0; t < num_truth; ++t) {
    SegmentMatch& m = matches[t];
    m.truth_label = truth_ids.labels_[t];
    m.truth_size = tsize[t];
    for (const Overlap& o : by_truth[t]) {
      const double iou = static_cast<double> (o.count) /
                         static_cast<double> (tsize[t] + psize[o.other] - o.count);
      const std::uint32_t label = predicted_ids.labels_[o.other];
      if (iou > m.iou ||
          (iou == m.iou && m.best_predicted != 0 && label < m.best_predicted)) {
        m.iou = iou;
        m.best_predicted = label;
        m.predicted_size = psize[o.other];
        m.overlap = o.count;
      }
    }
  }

  // Hoover et al. (1996): correct, then over-, then under-segmentation; each segment
  // once. Integer comparisons O >= T |s| are done in double: sizes are far below 2^53.
  const auto covers = [tolerance] (std::size_t overlap, std::size_t size) {
    return static_cast<double> (overlap) >= tolerance * static_cast<double> (size);
  };
  std::vector<bool> truth_used (num_truth, false),
      predicted_used (num_predicted, false);
  for (std::size_t t = 0; t < num_truth; ++t)
    for (const Overlap& o : by_truth[t])
      if (!predicted_used[o.other] && covers (o.count, tsize[t]) &&
          covers (o.count, psize[o.other])) {
        matches[t].outcome = SegmentOutcome::Correct;
        truth_used[t] = predicted_used[o.other] = true;
        ++metrics.correct;
        break;
      }
  for (std::size_t t = 0; t < num_truth; ++t) {
    if (truth_used[t])
      continue;
    const std::vector<std::size_t> parts =
        claimParts (by_truth[t], tsize[t], psize, predicted_used, covers);
    if (parts.empty())
      continue;
    matches[t].outcome = SegmentOutcome::OverSegmented;
    truth_used[t] = true;
    ++metrics.over_segmented;
    metrics.over_segmenting += parts.size();
  }
  for (std::size_t p = 0; p < num_predicted; ++p) {
    if (predicted_used[p])
      continue;
    const std::vector<std::size_t> parts =
        claimParts (by_predicted[p], psize[p], tsize, truth_used, covers);
    if (parts.empty())
      continue;
    predicted_used[p] = true;
    ++metrics.under_segmenting;
    metrics.under_segmented += parts.size();
    for (const std::size_t t : parts)
      matches[t].outcome = SegmentOutcome::UnderSegmented;
  }
  metrics.missed = static_cast<std::size_t> (
      std::count (truth_used.begin(), truth_used.end(), false));
  metrics.noise = static_cast<std::size_t> (
      std::count (predicted_used.begin(), predicted_used.end(), false));

  double iou_sum = 0.0, weighted_sum = 0.0;
  for (const SegmentMatch& m : matches) {
    iou_sum += m.iou;
    weighted_sum += m.iou * static_cast<double> (m.truth_size);
  }
  if (num_truth > 0) {
    metrics.mean_best_iou = iou_sum / static_cast<double> (num_truth);
    metrics.weighted_mean_best_iou =
        weighted_sum / static_cast<double> (metrics.evaluated_points);
  }
  std::sort (matches.begin(),
             matches.end(),
             [] (const SegmentMatch& a, const SegmentMatch& b) {
               return a.truth_label < b.truth_label;
             });
  metrics.segments = std::move (matches);
  return true;
}

std::size_t
labelsFromIndices (const std::vector<pcl::PointIndices>& clusters,
                   std::size_t num_points,
                   std::vector<std::uint32_t>& labels)
{
  labels.assign (num_points, 0);
  std::size_t rejected = 0;
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (const auto index : clusters[c].indices) {
      if (index < 0 || static_cast<std::size_t> (index) >= num_points ||
          labels[index] != 0) {
        ++rejected;
        continue;
      }
      labels[index] = static_cast<std::uint32_t> (c + 1);
    }
  return rejected;
}

bool
evaluateSegmentation (const std::vector<pcl::PointIndices>& predicted,
                      const std::vector<std::uint32_t>& truth,
                      SegmentationMetrics& metrics,
                      double tolerance)
{
  std::vector<std::uint32_t> labels;
  if (const std::size_t rejected = labelsFromIndices (predicted, truth.size(), labels))
    PCL_WARN (
        "[pcl_ext::evaluateSegmentation] %zu predicted indices are out of range or in "
        "several clusters; they were skipped.\n",
        rejected);
  return evaluateSegmentation (labels, truth, metrics, tolerance);
}

bool
evaluateSegmentation (const std::vector<pcl::PointIndices>& predicted,
                      const std::vector<pcl::PointIndices>& truth,
                      std::size_t num_points,
                      SegmentationMetrics& metrics,
                      double tolerance)
{
  std::vector<std::uint32_t> truth_labels;
  if (const std::size_t rejected = labelsFromIndices (truth, num_points, truth_labels))
    PCL_WARN ("[pcl_ext::evaluateSegmentation] %zu ground-truth indices are out of "
              "range or in "
              "several clusters; they were skipped.\n",
              rejected);
  return evaluateSegmentation (predicted, truth_labels, metrics, tolerance);
}
} // namespace pcl_ext
