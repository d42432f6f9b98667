/*
 * pcl_ext_tiles: the points of a tiled run grouped by segment in two work files.
 */
#include "segment_points_file.h"

#include "profile_parts.h"

#include <pcl_ext/tiling/positioned_io.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <numeric>
#include <unistd.h>

namespace pcl_ext {
namespace apps {
namespace {
constexpr std::size_t kXyzBytes = 3 * sizeof (float);
constexpr std::size_t kIndexBytes = sizeof (std::uint64_t);
} // namespace

SegmentPointsFile::~SegmentPointsFile() { close(); }

void
SegmentPointsFile::close()
{
  for (int* fd : {&xyz_, &index_})
    if (*fd >= 0) {
      ::close (*fd);
      *fd = -1;
    }
  for (const std::string* path : {&xyz_path_, &index_path_})
    if (!path->empty())
      std::remove (path->c_str());
  xyz_path_.clear();
  index_path_.clear();
}

bool
SegmentPointsFile::open (const std::string& workdir)
{
  xyz_path_ = workdir + "/segment_points.xyz";
  index_path_ = workdir + "/segment_points.index";
  xyz_ = ::open (xyz_path_.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0644);
  index_ = ::open (index_path_.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0644);
  if (xyz_ < 0 || index_ < 0) {
    std::cerr << "Error: cannot write " << (xyz_ < 0 ? xyz_path_ : index_path_) << ": "
              << std::strerror (errno) << ".\n";
    return false;
  }
  return true;
}

bool
SegmentPointsFile::build (const std::string& workdir,
                          const std::vector<std::string>& point_files,
                          std::uint32_t segments,
                          std::uint64_t total)
{
  close();
  first_.assign (static_cast<std::size_t> (segments) + 1, 0);
  centre_.setZero();
  std::vector<std::uint32_t> ids;
  if (!tiling::TileResults::read (workdir, 0, static_cast<std::size_t> (total), ids))
    return false;
  for (const auto id : ids) {
    if (id == tiling::TileResults::kNoResult)
      continue;
    if (id >= segments) {
      std::cerr << "Error: the segments in " << workdir << " are broken.\n";
      return false;
    }
    ++first_[id + 1];
  }
  std::partial_sum (first_.begin(), first_.end(), first_.begin());
  if (!open (workdir))
    return false;

  // Each part's points to their segments' places, written in runs of consecutive
  // places.
  std::vector<std::uint64_t> next (first_.begin(), first_.end() - 1);
  std::vector<std::uint64_t> indices, place_indices;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> places;
  std::vector<float> place_xyz;
  for (const auto& path : point_files) {
    if (!readProfilePart (path, indices, cloud))
      return false;
    places.clear();
    for (std::size_t k = 0; k < indices.size(); ++k) {
      const std::uint32_t id =
          indices[k] < total ? ids[indices[k]] : tiling::TileResults::kNoResult;
      if (id == tiling::TileResults::kNoResult)
        continue;
      if (next[id] == first_[id + 1]) {
        std::cerr << "Error: " << path << " holds a point of segment " << id
                  << " that another part holds too.\n";
        return false;
      }
      places.emplace_back (next[id]++, static_cast<std::uint32_t> (k));
    }
    std::sort (places.begin(), places.end());
    place_xyz.resize (3 * places.size());
    place_indices.resize (places.size());
    for (std::size_t j = 0; j < places.size(); ++j) {
      const auto& p = cloud[places[j].second];
      place_xyz[3 * j] = p.x;
      place_xyz[3 * j + 1] = p.y;
      place_xyz[3 * j + 2] = p.z;
      place_indices[j] = indices[places[j].second];
    }
    for (std::size_t begin = 0, end = 0; begin < places.size(); begin = end) {
      for (end = begin + 1;
           end < places.size() && places[end].first == places[end - 1].first + 1;
           ++end)
        ;
      const std::uint64_t place = places[begin].first;
      const std::size_t count = end - begin;
      if (!tiling::writeAllAt (xyz_,
                               place_xyz.data() + 3 * begin,
                               count * kXyzBytes,
                               place * kXyzBytes) ||
          !tiling::writeAllAt (index_,
                               place_indices.data() + begin,
                               count * kIndexBytes,
                               place * kIndexBytes)) {
        std::cerr << "Error: cannot write " << xyz_path_
                  << " (disk full?): " << std::strerror (errno) << ".\n";
        return false;
      }
    }
  }
  for (std::size_t s = 0; s < segments; ++s)
    if (next[s] != first_[s + 1]) {
      std::cerr << "Error: points of segment " << s << " are in no part of " << workdir
                << ".\n";
      return false;
    }
  ids.clear();
  ids.shrink_to_fit();
  return sortSegments();
}

bool
SegmentPointsFile::sortSegments()
{
  // Each segment's points by global index (the parts held them by part), and the mean
  // of all, summed in that order.
  std::vector<std::uint64_t> indices, sorted_indices;
  std::vector<float> xyz, sorted_xyz;
  std::vector<std::uint32_t> order;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t s = 0; s < size(); ++s) {
    const std::size_t n = pointCount (s);
    if (!loadIndices (s, indices))
      return false;
    xyz.resize (3 * n);
    if (!tiling::readAllAt (xyz_, xyz.data(), n * kXyzBytes, first_[s] * kXyzBytes)) {
      std::cerr << "Error: cannot read " << xyz_path_ << ".\n";
      return false;
    }
    if (!std::is_sorted (indices.begin(), indices.end())) {
      order.resize (n);
      std::iota (order.begin(), order.end(), 0u);
      std::sort (order.begin(), order.end(), [&] (std::uint32_t a, std::uint32_t b) {
        return indices[a] < indices[b];
      });
      sorted_indices.resize (n);
      sorted_xyz.resize (3 * n);
      for (std::size_t k = 0; k < n; ++k) {
        sorted_indices[k] = indices[order[k]];
        std::copy_n (xyz.begin() + 3 * order[k], 3, sorted_xyz.begin() + 3 * k);
      }
      indices.swap (sorted_indices);
      xyz.swap (sorted_xyz);
      if (!tiling::writeAllAt (
              xyz_, xyz.data(), n * kXyzBytes, first_[s] * kXyzBytes) ||
          !tiling::writeAllAt (
              index_, indices.data(), n * kIndexBytes, first_[s] * kIndexBytes)) {
        std::cerr << "Error: cannot write " << xyz_path_
                  << " (disk full?): " << std::strerror (errno) << ".\n";
        return false;
      }
    }
    for (std::size_t k = 0; k < n; ++k)
      sum +=
          Eigen::Vector3f (xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]).cast<double>();
  }
  if (first_.back() > 0)
    centre_ = sum / static_cast<double> (first_.back());
  return true;
}

bool
SegmentPointsFile::load (std::size_t s, std::vector<Eigen::Vector3d>& points) const
{
  const std::size_t n = pointCount (s);
  std::vector<float> xyz (3 * n);
  if (!tiling::readAllAt (xyz_, xyz.data(), n * kXyzBytes, first_[s] * kXyzBytes)) {
    std::cerr << "Error: cannot read " << xyz_path_ << ".\n";
    return false;
  }
  points.resize (n);
  for (std::size_t k = 0; k < n; ++k)
    points[k] =
        Eigen::Vector3f (xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]).cast<double>() -
        centre_;
  return true;
}

bool
SegmentPointsFile::loadIndices (std::size_t s,
                                std::vector<std::uint64_t>& indices) const
{
  const std::size_t n = pointCount (s);
  indices.resize (n);
  if (!tiling::readAllAt (
          index_, indices.data(), n * kIndexBytes, first_[s] * kIndexBytes)) {
    std::cerr << "Error: cannot read " << index_path_ << ".\n";
    return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
