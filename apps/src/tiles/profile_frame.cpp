/*
 * pcl_ext_tiles segment_profiles: what the profile segmentation derives from the whole
 * cloud, found in passes over the inputs.
 */
#include "profile_frame.h"

#include <pcl_ext/segmentation/profile_stacks.h>
#include <pcl_ext/tiling/point_file_chunks.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace pcl_ext {
namespace apps {
namespace {
/** The samples of profiles::estimatePointSpacing and estimateCloudStatistics. */
constexpr std::size_t kSamples = 2048;
/** The neighbours of the statistics; the spacing reads the 6th of them. */
constexpr std::size_t kSampleNeighbours = 16;
/** Bins of the histogram that ranks the points along the sample axis. */
constexpr std::size_t kRankBins = std::size_t (1) << 20;
/** At most this many points are held to resolve the samples' ranks. */
constexpr std::size_t kMaxRankPoints = std::size_t (1) << 24;

/** An entry of a sample's neighbours: squared distance, then global index, as the
 * untiled sweep orders them (by position in the cloud, which follows the index). */
struct Neighbour {
  float d2;
  std::uint64_t index;
  Eigen::Vector3f point;
  bool
  operator<(const Neighbour& o) const
  {
    return d2 != o.d2 ? d2 < o.d2 : index < o.index;
  }
};

struct CellKey {
  std::int64_t x, y, z;
  bool
  operator== (const CellKey& o) const
  {
    return x == o.x && y == o.y && z == o.z;
  }
};

struct CellHash {
  std::size_t
  operator() (const CellKey& k) const
  {
    std::uint64_t h = static_cast<std::uint64_t> (k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t> (k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t> (k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t> (h);
  }
};

CellKey
cellOf (const Eigen::Vector3f& p, double h)
{
  return {static_cast<std::int64_t> (std::floor (p.x() / h)),
          static_cast<std::int64_t> (std::floor (p.y() / h)),
          static_cast<std::int64_t> (std::floor (p.z() / h))};
}

/** The points profiles::sampleNeighbourhoods samples: ranks along the sample axis
 * (ties by index) resolved through a histogram of the coordinate, then the points of
 * the bins that hold a sampled rank. \return false (message printed) when those bins
 * hold too many points (a cloud of nearly one coordinate) */
bool
findSamples (InputPasses& inputs,
             const ProfileFrame& frame,
             const Eigen::Vector3f& lo,
             const Eigen::Vector3f& hi,
             std::vector<Eigen::Vector3f>& points)
{
  const int axis = profiles::sampleAxis (lo, hi);
  const double low = lo[axis], range = static_cast<double> (hi[axis]) - lo[axis];
  const auto bin = [&] (float c) {
    if (!(range > 0.0))
      return std::size_t (0);
    const double f = (static_cast<double> (c) - low) / range * kRankBins;
    return std::min (kRankBins - 1, static_cast<std::size_t> (std::max (0.0, f)));
  };
  std::vector<std::uint64_t> counts (kRankBins + 1, 0);
  inputs.forEachFinitePoint ([&] (std::uint64_t, const Eigen::Vector3f& local) {
    ++counts[bin (centred (local, frame.centre)[axis]) + 1];
  });
  for (std::size_t b = 0; b < kRankBins; ++b)
    counts[b + 1] += counts[b]; // counts[b]: points in the bins before b
  const std::size_t n = frame.points, m = std::min<std::size_t> (kSamples, n);
  std::vector<std::uint64_t> ranks (m);
  std::vector<std::uint8_t> wanted (kRankBins, 0);
  std::size_t held = 0;
  for (std::size_t s = 0; s < m; ++s) {
    ranks[s] = profiles::sampleRank (s, n, m);
    const std::size_t b = static_cast<std::size_t> (
        std::upper_bound (counts.begin(), counts.end(), ranks[s]) - counts.begin() - 1);
    if (!wanted[b])
      held += counts[b + 1] - counts[b];
    wanted[b] = 1;
  }
  if (held > kMaxRankPoints) {
    std::cerr << "\nError: cannot sample the cloud for its spacing: " << held
              << " points share the coordinates of the samples; give -width and "
                 "-threshold.\n";
    return false;
  }
  struct Ranked {
    float c;
    std::uint64_t index;
    Eigen::Vector3f point;
  };
  std::vector<Ranked> ranked;
  ranked.reserve (held);
  inputs.forEachFinitePoint ([&] (std::uint64_t index, const Eigen::Vector3f& local) {
    const Eigen::Vector3f p = centred (local, frame.centre);
    if (wanted[bin (p[axis])])
      ranked.push_back ({p[axis], index, p});
  });
  // Bins follow the coordinate: sorted by (coordinate, index), each bin's points are
  // together, in the bins' order.
  std::sort (ranked.begin(), ranked.end(), [] (const Ranked& a, const Ranked& b) {
    return a.c != b.c ? a.c < b.c : a.index < b.index;
  });
  std::vector<std::uint64_t> start (kRankBins, 0); // of each wanted bin in ranked
  for (std::size_t b = 0, next = 0; b < kRankBins; ++b)
    if (wanted[b]) {
      start[b] = next;
      next += counts[b + 1] - counts[b];
    }
  points.resize (m);
  for (std::size_t s = 0; s < m; ++s) {
    const std::size_t b = static_cast<std::size_t> (
        std::upper_bound (counts.begin(), counts.end(), ranks[s]) - counts.begin() - 1);
    const Ranked& r = ranked[start[b] + (ranks[s] - counts[b])];
    points[s] = r.point;
  }
  return true;
}

/** The 16 nearest other points (distance above 0) of every sample over the whole
 * cloud: a pass per search radius, the samples in a hash of cells of that size; a
 * sample whose 16th neighbour lies well within the radius is done, the others are
 * searched again with a radius four times as large, until it spans the cloud. */
std::vector<profiles::SampledNeighbourhood>
searchSamples (InputPasses& inputs,
               const ProfileFrame& frame,
               const Eigen::Vector3f& lo,
               const Eigen::Vector3f& hi,
               const std::vector<Eigen::Vector3f>& points)
{
  const std::size_t m = points.size();
  std::vector<profiles::SampledNeighbourhood> result (m);
  std::vector<std::vector<Neighbour>> nearest (m);
  std::vector<std::size_t> pending (m);
  for (std::size_t s = 0; s < m; ++s) {
    pending[s] = s;
    result[s].point = points[s];
  }
  Eigen::Vector3d extent = (hi - lo).cast<double>();
  std::sort (extent.data(), extent.data() + 3);
  const double diagonal = extent.norm();
  double h =
      4.0 * std::sqrt (extent[1] * extent[2] /
                       static_cast<double> (std::max<std::uint64_t> (1, frame.points)));
  if (!(h > 0.0) || !std::isfinite (h))
    h = diagonal > 0.0 ? diagonal : 1.0;
  while (!pending.empty()) {
    // Within 0.99 h a neighbour lies in the 27 cells around its sample.
    const double reach = 0.99 * h;
    const float reach2 = static_cast<float> (reach * reach);
    std::unordered_map<CellKey, std::vector<std::uint32_t>, CellHash> cells;
    for (const std::size_t s : pending) {
      nearest[s].clear();
      const CellKey c = cellOf (points[s], h);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz)
            cells[{c.x + dx, c.y + dy, c.z + dz}].push_back (
                static_cast<std::uint32_t> (s));
    }
    inputs.forEachFinitePoint ([&] (std::uint64_t index, const Eigen::Vector3f& local) {
      const Eigen::Vector3f p = centred (local, frame.centre);
      const auto it = cells.find (cellOf (p, h));
      if (it == cells.end())
        return;
      for (const std::uint32_t s : it->second) {
        const float d2 = (p - points[s]).squaredNorm();
        if (!(d2 > 0.f) || !(d2 < reach2))
          continue;
        auto& list = nearest[s];
        const Neighbour entry{d2, index, p};
        if (list.size() == kSampleNeighbours && !(entry < list.back()))
          continue;
        list.insert (std::upper_bound (list.begin(), list.end(), entry), entry);
        if (list.size() > kSampleNeighbours)
          list.pop_back();
      }
    });
    const bool spans = reach >= diagonal;
    std::vector<std::size_t> still;
    for (const std::size_t s : pending)
      if (nearest[s].size() < kSampleNeighbours && !spans)
        still.push_back (s);
    pending.swap (still);
    h *= 4.0;
  }
  for (std::size_t s = 0; s < m; ++s)
    for (const Neighbour& e : nearest[s])
      result[s].nearest.emplace_back (e.d2, e.point);
  return result;
}
} // namespace

std::string
joinValues (const double* values, std::size_t n, int digits)
{
  std::string text;
  char buffer[64];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf (buffer, sizeof (buffer), "%.*g", digits, values[i]);
    text += (i ? " " : "") + std::string (buffer);
  }
  return text;
}

bool
parseValues (const std::map<std::string, std::string>& settings,
             const std::string& key,
             std::vector<double>& values)
{
  values.clear();
  const auto it = settings.find (key);
  if (it == settings.end())
    return false;
  std::istringstream in (it->second);
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    values.push_back (std::strtod (word.c_str(), &end));
    if (end == word.c_str() || *end != '\0')
      return false;
  }
  return true;
}

void
ProfileFrame::saveTo (std::map<std::string, std::string>& settings) const
{
  settings["profile_points"] = std::to_string (points);
  settings["profile_centre"] = joinValues (centre.data(), 3, 17);
  std::vector<double> n;
  for (const auto& v : normals)
    for (int i = 0; i < 3; ++i)
      n.push_back (v[i]);
  settings["profile_normals"] = joinValues (n.data(), n.size(), 9);
  settings["profile_origins"] = joinValues (origins.data(), origins.size(), 17);
  settings["profile_ends"] = joinValues (ends.data(), ends.size(), 17);
  const double s[] = {spacing,
                      width,
                      statistics.spacing,
                      statistics.spacing_variation,
                      statistics.noise,
                      static_cast<double> (statistics.samples)};
  settings["profile_lengths"] = joinValues (s, 6, 17);
}

bool
ProfileFrame::loadFrom (const std::map<std::string, std::string>& settings)
{
  std::vector<double> c, n, o, e, s;
  const auto points_it = settings.find ("profile_points");
  if (points_it == settings.end() || !parseValues (settings, "profile_centre", c) ||
      c.size() != 3 || !parseValues (settings, "profile_normals", n) ||
      n.size() % 3 != 0 || !parseValues (settings, "profile_origins", o) ||
      !parseValues (settings, "profile_ends", e) || o.size() * 3 != n.size() ||
      e.size() != o.size() || !parseValues (settings, "profile_lengths", s) ||
      s.size() != 6) {
    std::cerr << "Error: the plan has no valid profile frame.\n";
    return false;
  }
  points = std::stoull (points_it->second);
  centre = Eigen::Vector3d (c[0], c[1], c[2]);
  normals.clear();
  for (std::size_t i = 0; i < n.size(); i += 3)
    normals.emplace_back (static_cast<float> (n[i]),
                          static_cast<float> (n[i + 1]),
                          static_cast<float> (n[i + 2]));
  origins = o;
  ends = e;
  spacing = s[0];
  width = s[1];
  statistics.spacing = s[2];
  statistics.spacing_variation = s[3];
  statistics.noise = s[4];
  statistics.samples = static_cast<std::size_t> (s[5]);
  return true;
}

void
InputPasses::forEachFinitePoint (
    const std::function<void (std::uint64_t, const Eigen::Vector3f&)>& visit)
{
  kept_.resize (plan_.inputs.size());
  pcl::PCLPointCloud2 chunk;
  for (std::size_t f = 0; f < plan_.inputs.size(); ++f) {
    std::unique_ptr<tiling::PointFileChunks> opened;
    tiling::PointFileChunks* file = kept_[f].get();
    if (file)
      file->rewind();
    else {
      opened = std::make_unique<tiling::PointFileChunks>();
      opened->open (plan_.inputs[f]);
      opened->setOrigin (plan_.origin);
      file = opened.get();
    }
    std::uint64_t index = plan_.getFirstIndex (f);
    std::size_t n;
    while ((n = file->read (std::size_t (1) << 20, chunk)) > 0) {
      const std::uint8_t* xyz = chunk.data.data() + tiling::xyzOffset (chunk);
      for (std::size_t i = 0; i < n; ++i, ++index) {
        Eigen::Vector3f p;
        std::memcpy (p.data(), xyz + i * chunk.point_step, 3 * sizeof (float));
        if (p.allFinite())
          visit (index, p);
      }
    }
    if (opened && !opened->getDescription().las)
      kept_[f] = std::move (opened);
  }
}

bool
estimateProfileFrame (InputPasses& inputs,
                      const std::vector<Eigen::Vector3f>& normals,
                      bool sample,
                      double width,
                      double width_factor,
                      ProfileFrame& frame)
{
  frame = ProfileFrame();
  frame.normals = normals;
  // The centre as ProfileSegmentation sums it: in double, point after point.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  inputs.forEachFinitePoint ([&] (std::uint64_t, const Eigen::Vector3f& local) {
    sum += local.cast<double>();
    ++frame.points;
  });
  if (frame.points == 0) {
    std::cerr << "\nError: no finite point to segment.\n";
    return false;
  }
  frame.centre = sum / static_cast<double> (frame.points);
  // The box of the centred points and each stack's extent along its direction, with
  // the normals made unit length as ProfileSegmentation and buildStack make them.
  std::vector<Eigen::Vector3d> directions;
  for (Eigen::Vector3f n : normals) {
    n.normalize();
    directions.push_back (profiles::stackDirection (n));
  }
  frame.origins.assign (normals.size(), std::numeric_limits<double>::infinity());
  frame.ends.assign (normals.size(), -std::numeric_limits<double>::infinity());
  Eigen::Vector3f lo = Eigen::Vector3f::Constant (std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo;
  inputs.forEachFinitePoint ([&] (std::uint64_t, const Eigen::Vector3f& local) {
    const Eigen::Vector3f p = centred (local, frame.centre);
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
    for (std::size_t s = 0; s < directions.size(); ++s) {
      const double t = directions[s].dot (p.cast<double>());
      frame.origins[s] = std::min (frame.origins[s], t);
      frame.ends[s] = std::max (frame.ends[s], t);
    }
  });
  if (sample && frame.points >= 2) {
    std::vector<Eigen::Vector3f> points;
    if (!findSamples (inputs, frame, lo, hi, points))
      return false;
    const auto neighbourhoods = searchSamples (inputs, frame, lo, hi, points);
    frame.spacing = profiles::pointSpacingOf (neighbourhoods);
    if (frame.points > kSampleNeighbours)
      frame.statistics = profiles::cloudStatisticsOf (neighbourhoods);
  }
  frame.width = width > 0.0 ? width : width_factor * frame.spacing;
  if (!(frame.width > 0.0) || !std::isfinite (frame.width)) {
    std::cerr << "\nError: cannot estimate the point spacing (fewer than two distinct "
                 "finite points); give -width and -threshold.\n";
    return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
