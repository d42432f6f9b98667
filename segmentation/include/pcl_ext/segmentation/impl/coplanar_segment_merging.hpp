/*
 * pcl_ext: CoplanarSegmentMerging implementation.
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/segmentation/coplanar_segment_merging.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

template <typename PointT>
bool
pcl_ext::CoplanarSegmentMerging<PointT>::checkInputs (const char* name,
                                                      const pcl::Indices* linking) const
{
  const std::size_t n = input_->size();
  if (n == 0) {
    PCL_ERROR ("%s The input cloud is empty.\n", name);
    return false;
  }
  if (!onePerPoint (segments_.get(), n, name, "segment label", "setSegmentLabels") ||
      !indicesInRange (*indices_, n, name) ||
      (linking && !indicesInRange (*linking, n, name)))
    return false;
  if (!this->checkNeighbourhoodOptions (name, 2))
    return false;
  if (contact_k_ < 1) {
    PCL_ERROR ("%s contact k = %d; it must be at least 1.\n", name, contact_k_);
    return false;
  }
  const CoplanarMergeCriteria& c = criteria_;
  if (!(c.min_contact_fraction > 0.0 && c.min_contact_fraction <= 1.0)) {
    PCL_ERROR ("%s minimum contact fraction = %g; valid: (0, 1].\n",
               name,
               c.min_contact_fraction);
    return false;
  }
  if (!(c.max_angle >= 0.0 && c.max_angle <= 0.5 * M_PI)) {
    PCL_ERROR ("%s maximum angle = %g rad; valid: 0 .. pi/2.\n", name, c.max_angle);
    return false;
  }
  if (!(c.distance_factor > 0.0) || !std::isfinite (c.distance_factor)) {
    PCL_ERROR ("%s distance factor = %g; it must be finite and > 0.\n",
               name,
               c.distance_factor);
    return false;
  }
  return true;
}

template <typename PointT>
bool
pcl_ext::CoplanarSegmentMerging<PointT>::accumulate (
    SegmentContacts& contacts, const pcl::IndicesConstPtr& linking)
{
  const char* const name = "[pcl_ext::CoplanarSegmentMerging::accumulate]";
  if (!initCompute()) {
    PCL_ERROR ("%s No input cloud.\n", name);
    return false;
  }
  if (!checkInputs (name, linking.get())) {
    deinitCompute();
    return false;
  }
  // The points that count (indexed or linking, finite, in a segment), in index order.
  std::vector<pcl::index_t> points;
  for (const auto i : linking ? *linking : *indices_)
    if ((*segments_)[i].label != 0 && pcl::isFinite ((*input_)[i]))
      points.push_back (i);
  std::sort (points.begin(), points.end());
  points.erase (std::unique (points.begin(), points.end()), points.end());
  const Neighbourhoods<PointT>* const nb = this->prepareNeighbourhoodsCovering (
      "CoplanarSegmentMerging::accumulate", input_, points);
  if (!nb) {
    deinitCompute();
    return false;
  }

  // Chunks of a fixed number of points, each summed on its own and the chunks' sums
  // added in order: the same sums for any thread count. Contacts are counts.
  constexpr std::size_t kChunk = 16384;
  const std::size_t chunks = (points.size() + kChunk - 1) / kChunk;
  std::vector<SegmentContacts> parts (chunks);
  const std::size_t k = static_cast<std::size_t> (contact_k_);
  const std::ptrdiff_t num_chunks = static_cast<std::ptrdiff_t> (chunks);
#pragma omp parallel num_threads(resolveThreadCount(this->threads_))
  {
    std::vector<std::uint32_t> others;
    std::unordered_map<std::uint32_t, SegmentContacts::PlaneSums> sums;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> found;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t c = 0; c < num_chunks; ++c) {
      sums.clear();
      found.clear();
      const std::size_t begin = static_cast<std::size_t> (c) * kChunk;
      const std::size_t end = std::min (points.size(), begin + kChunk);
      std::uint32_t last = 0;
      SegmentContacts::PlaneSums* last_sums = nullptr;
      for (std::size_t s = begin; s < end; ++s) {
        const pcl::index_t i = points[s];
        const std::uint32_t a = (*segments_)[i].label;
        if (a != last || !last_sums) {
          last = a;
          last_sums = &sums[a];
        }
        const auto& p = (*input_)[i];
        last_sums->add (Eigen::Vector3d (p.x, p.y, p.z));
        const std::ptrdiff_t r = nb->getRowOfPoint (i);
        if (r < 0)
          continue;
        const auto row = (*nb)[static_cast<std::size_t> (r)];
        others.clear();
        std::size_t taken = 0;
        for (auto it = row.begin(); it != row.end() && taken < k; ++it) {
          const pcl::index_t j = *it;
          if (j == i || j < 0)
            continue;
          ++taken;
          const std::uint32_t b = (*segments_)[j].label;
          if (b != 0 && b != a &&
              std::find (others.begin(), others.end(), b) == others.end())
            others.push_back (b);
        }
        for (const auto b : others)
          ++found[{a, b}];
      }
      SegmentContacts& part = parts[static_cast<std::size_t> (c)];
      std::vector<std::uint32_t> labels;
      for (const auto& entry : sums)
        labels.push_back (entry.first);
      std::sort (labels.begin(), labels.end());
      for (const auto label : labels)
        part.addPoints (label, sums[label]);
      for (const auto& [pair, n] : found)
        part.addContacts (pair.first, pair.second, n);
    }
  }
  for (const auto& part : parts)
    contacts.add (part);
  this->releaseNeighbourhoods();
  deinitCompute();
  return true;
}

template <typename PointT>
bool
pcl_ext::CoplanarSegmentMerging<PointT>::compute (LabelCloud& output)
{
  output.clear();
  output.width = output.height = 0;
  report_ = Report();
  SegmentContacts contacts;
  if (!accumulate (contacts))
    return false;
  const auto map =
      mergeInterleavedCoplanarSegments (contacts, criteria_, &report_.merges);
  report_.segments = contacts.planes().size();
  report_.result = report_.segments - report_.merges;
  output = *segments_;
  // Points of a label with no finite indexed point (none in the map) get 0.
  std::uint32_t last = 0, last_new = 0;
  for (auto& l : output) {
    if (l.label == 0)
      continue;
    if (l.label != last) {
      last = l.label;
      const auto it =
          std::lower_bound (map.begin(),
                            map.end(),
                            l.label,
                            [] (const std::pair<std::uint32_t, std::uint32_t>& e,
                                std::uint32_t v) { return e.first < v; });
      last_new = it != map.end() && it->first == l.label ? it->second : 0;
    }
    l.label = last_new;
  }
  return true;
}

#define PCL_EXT_INSTANTIATE_CoplanarSegmentMerging(T)                                  \
  template class pcl_ext::CoplanarSegmentMerging<T>;
