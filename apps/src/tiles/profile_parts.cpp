/*
 * pcl_ext_tiles segment_profiles: the cloud split by profiles.
 */
#include "profile_parts.h"

#include <pcl_ext/segmentation/profile_stacks.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
/** Bins of profiles counted per stack to place the parts' borders: a border falls
 * between bins, so a bin is a run of whole profiles. */
constexpr std::uint64_t kMaxBins = std::uint64_t (1) << 22;
/** Part files open at once while writing (a pass over the inputs per as many). */
constexpr std::size_t kFilesPerPass = 500;
/** A point in a part file: global index, then x y z. */
constexpr std::size_t kRecordBytes = sizeof (std::uint64_t) + 3 * sizeof (float);

std::vector<Eigen::Vector3d>
directionsOf (const std::vector<Eigen::Vector3f>& normals)
{
  std::vector<Eigen::Vector3d> directions;
  for (Eigen::Vector3f n : normals) {
    n.normalize(); // as ProfileSegmentation, then buildStack through stackDirection
    directions.push_back (profiles::stackDirection (n));
  }
  return directions;
}

struct FileCloser {
  void
  operator() (std::FILE* f) const
  {
    if (f)
      std::fclose (f);
  }
};
} // namespace

std::size_t
ProfileParts::size() const
{
  std::size_t n = 0;
  for (const auto& f : firsts)
    n += f.size();
  return n;
}

void
ProfileParts::locate (std::size_t i, std::size_t& stack, std::size_t& part) const
{
  for (stack = 0; stack < firsts.size() && i >= firsts[stack].size(); ++stack)
    i -= firsts[stack].size();
  part = i;
}

std::size_t
ProfileParts::partOf (std::size_t stack, std::uint64_t profile) const
{
  const auto& f = firsts[stack];
  return static_cast<std::size_t> (std::upper_bound (f.begin(), f.end(), profile) -
                                   f.begin() - 1);
}

void
ProfileParts::saveTo (std::map<std::string, std::string>& settings) const
{
  for (std::size_t s = 0; s < firsts.size(); ++s) {
    std::string text;
    for (const auto f : firsts[s])
      text += (text.empty() ? "" : " ") + std::to_string (f);
    settings["profile_parts_" + std::to_string (s)] = text;
  }
}

bool
ProfileParts::loadFrom (const std::map<std::string, std::string>& settings,
                        std::size_t stacks)
{
  firsts.assign (stacks, {});
  for (std::size_t s = 0; s < stacks; ++s) {
    const auto it = settings.find ("profile_parts_" + std::to_string (s));
    bool ok = it != settings.end();
    if (ok) {
      std::istringstream in (it->second);
      std::uint64_t f;
      while (in >> f)
        firsts[s].push_back (f);
      ok = in.eof() && !firsts[s].empty() && firsts[s].front() == 0 &&
           std::is_sorted (firsts[s].begin(), firsts[s].end());
    }
    if (!ok) {
      std::cerr << "Error: the plan has no valid parts for stack " << s << ".\n";
      return false;
    }
  }
  return true;
}

std::uint64_t
profileNumber (double t, double origin, double width)
{
  const double f = std::floor ((t - origin) / width);
  return f < 1e18 ? static_cast<std::uint64_t> (std::max (0.0, f))
                  : static_cast<std::uint64_t> (1e18);
}

bool
planProfileParts (InputPasses& inputs,
                  const ProfileFrame& frame,
                  double thickness,
                  std::uint64_t max_points,
                  ProfileParts& parts)
{
  const auto directions = directionsOf (frame.normals);
  const std::size_t stacks = directions.size();
  // Bins of whole profiles: a slab each, or runs small enough to place the borders.
  const std::uint64_t slab =
      thickness > 0.0
          ? std::max<std::uint64_t> (
                1, static_cast<std::uint64_t> (std::floor (thickness / frame.width)))
          : 0;
  std::vector<std::uint64_t> group (stacks, 1);
  std::vector<std::vector<std::uint64_t>> counts (stacks);
  for (std::size_t s = 0; s < stacks; ++s) {
    const std::uint64_t profiles =
        profileNumber (frame.ends[s], frame.origins[s], frame.width) + 1;
    group[s] = slab > 0 ? slab : (profiles + kMaxBins - 1) / kMaxBins;
    if (profiles / group[s] + 1 > kMaxBins) {
      std::cerr << "\nError: -tile_size " << thickness << " makes more than "
                << kMaxBins << " parts of stack " << s << ".\n";
      return false;
    }
    counts[s].assign (profiles / group[s] + 1, 0);
  }
  inputs.forEachFinitePoint ([&] (std::uint64_t, const Eigen::Vector3f& local) {
    const Eigen::Vector3d p = centred (local, frame.centre).cast<double>();
    for (std::size_t s = 0; s < stacks; ++s) {
      const std::uint64_t bin =
          profileNumber (directions[s].dot (p), frame.origins[s], frame.width) /
          group[s];
      ++counts[s][std::min<std::uint64_t> (bin, counts[s].size() - 1)];
    }
  });
  parts.firsts.assign (stacks, {});
  for (std::size_t s = 0; s < stacks; ++s) {
    parts.firsts[s].push_back (0);
    std::uint64_t held = 0;
    for (std::size_t b = 0; b < counts[s].size(); ++b) {
      if (held > 0 &&
          (slab > 0 ? counts[s][b] > 0 : held + counts[s][b] > max_points)) {
        parts.firsts[s].push_back (b * group[s]);
        held = 0;
      }
      held += counts[s][b];
    }
  }
  return true;
}

std::string
profilePartPath (const std::string& workdir,
                 std::size_t stack,
                 std::size_t part,
                 const std::string& extension)
{
  return workdir + "/profiles_" + std::to_string (stack) + "_" + std::to_string (part) +
         "." + extension;
}

bool
writeProfileParts (InputPasses& inputs,
                   const ProfileFrame& frame,
                   const ProfileParts& parts,
                   const std::string& workdir)
{
  const auto directions = directionsOf (frame.normals);
  const std::size_t total = parts.size();
  std::vector<std::size_t> first_of_stack (directions.size(), 0);
  for (std::size_t s = 1; s < directions.size(); ++s)
    first_of_stack[s] = first_of_stack[s - 1] + parts.firsts[s - 1].size();
  for (std::size_t begin = 0; begin < total; begin += kFilesPerPass) {
    const std::size_t end = std::min (total, begin + kFilesPerPass);
    std::vector<std::unique_ptr<std::FILE, FileCloser>> files (end - begin);
    std::vector<std::string> paths (end - begin);
    for (std::size_t i = begin; i < end; ++i) {
      std::size_t s, p;
      parts.locate (i, s, p);
      paths[i - begin] = profilePartPath (workdir, s, p, "points");
      files[i - begin].reset (std::fopen (paths[i - begin].c_str(), "wb"));
      if (!files[i - begin]) {
        std::cerr << "\nError: cannot write " << paths[i - begin] << ": "
                  << std::strerror (errno) << ".\n";
        return false;
      }
    }
    bool failed = false;
    unsigned char record[kRecordBytes];
    inputs.forEachFinitePoint ([&] (std::uint64_t index, const Eigen::Vector3f& local) {
      const Eigen::Vector3d p = centred (local, frame.centre).cast<double>();
      std::memcpy (record, &index, sizeof (index));
      std::memcpy (record + sizeof (index), local.data(), 3 * sizeof (float));
      for (std::size_t s = 0; s < directions.size(); ++s) {
        const std::size_t i =
            first_of_stack[s] +
            parts.partOf (
                s,
                profileNumber (directions[s].dot (p), frame.origins[s], frame.width));
        if (i >= begin && i < end &&
            std::fwrite (record, kRecordBytes, 1, files[i - begin].get()) != 1)
          failed = true;
      }
    });
    for (std::size_t i = 0; i < files.size(); ++i)
      if (std::fclose (files[i].release()) != 0 || failed) {
        std::cerr << "\nError: cannot write " << paths[i] << " (disk full?).\n";
        return false;
      }
  }
  return true;
}

bool
readProfilePart (const std::string& path,
                 std::vector<std::uint64_t>& indices,
                 pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  indices.clear();
  cloud.clear();
  std::unique_ptr<std::FILE, FileCloser> file (std::fopen (path.c_str(), "rb"));
  if (!file) {
    std::cerr << "Error: cannot read " << path << ": " << std::strerror (errno)
              << ".\n";
    return false;
  }
  if (std::fseek (file.get(), 0, SEEK_END) != 0 ||
      std::ftell (file.get()) % static_cast<long> (kRecordBytes) != 0 ||
      std::fseek (file.get(), 0, SEEK_SET) != 0) {
    std::cerr << "Error: " << path << " is broken (not whole points).\n";
    return false;
  }
  std::vector<unsigned char> buffer (kRecordBytes * 65536);
  std::size_t n;
  while ((n = std::fread (buffer.data(), kRecordBytes, 65536, file.get())) > 0)
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* r = buffer.data() + i * kRecordBytes;
      std::uint64_t index;
      pcl::PointXYZ p;
      std::memcpy (&index, r, sizeof (index));
      std::memcpy (&p.x, r + sizeof (index), 3 * sizeof (float));
      if (!indices.empty() && index <= indices.back()) {
        std::cerr << "Error: " << path << " is broken (points out of order).\n";
        return false;
      }
      indices.push_back (index);
      cloud.push_back (p);
    }
  if (std::ferror (file.get())) {
    std::cerr << "Error: cannot read " << path << ".\n";
    return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
