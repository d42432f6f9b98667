/*
 * pcl_ext_tiles segment_variance -intersections: the tiles' intersection points saved
 * as tile values (floats, integers in parts exact in a float) and merged.
 */
#include "tile_intersections.h"
#include "tile_keys.h"

#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <iostream>
#include <limits>

namespace pcl_ext {
namespace apps {
namespace {
constexpr const char* kIntersections = "intersections";
/** Floats per point: two indices of three parts, two segments of two, x y z. */
constexpr std::size_t kValuesPerPoint = 13;

void
appendIndex (std::vector<float>& values, std::uint64_t index)
{
  float parts[3];
  splitKey (index, parts);
  values.insert (values.end(), parts, parts + 3);
}

void
appendSegment (std::vector<float>& values, std::uint32_t segment)
{
  values.push_back (static_cast<float> (segment >> 16));
  values.push_back (static_cast<float> (segment & 0xFFFF));
}

std::uint32_t
segmentAt (const float* v)
{
  return (static_cast<std::uint32_t> (v[0]) << 16) | static_cast<std::uint32_t> (v[1]);
}

/** Whether the parts at \a v are integers of the ranges the append functions write. */
bool
validParts (const float* v)
{
  const float limits[] = {4194303.0f,
                          4194303.0f,
                          1048575.0f,
                          4194303.0f,
                          4194303.0f,
                          1048575.0f,
                          65535.0f,
                          65535.0f,
                          65535.0f,
                          65535.0f};
  for (std::size_t i = 0; i < 10; ++i)
    if (!(v[i] >= 0.0f && v[i] <= limits[i]) ||
        v[i] != static_cast<float> (static_cast<std::uint32_t> (v[i])))
      return false;
  return true;
}
} // namespace

bool
saveTileIntersections (const std::string& workdir,
                       std::size_t tile,
                       const std::vector<TileIntersection>& intersections)
{
  std::vector<float> values;
  values.reserve (intersections.size() * kValuesPerPoint);
  for (const auto& i : intersections) {
    appendIndex (values, i.index_a);
    appendIndex (values, i.index_b);
    appendSegment (values, i.point.segment_a);
    appendSegment (values, i.point.segment_b);
    values.push_back (i.point.x);
    values.push_back (i.point.y);
    values.push_back (i.point.z);
  }
  if (!tiling::saveTileValues (workdir, tile, kIntersections, values)) {
    std::cerr << "Error: the intersection points of tile " << tile
              << " cannot be saved in " << workdir << ".\n";
    return false;
  }
  return true;
}

bool
mergeTileIntersections (const std::string& workdir,
                        std::size_t tiles,
                        pcl::PointCloud<SurfaceIntersectionPoint>& intersections)
{
  intersections.clear();
  std::vector<TileIntersection> all;
  std::vector<float> values;
  for (std::size_t t = 0; t < tiles; ++t) {
    if (!tiling::loadTileValues (workdir, t, kIntersections, values) ||
        values.size() % kValuesPerPoint != 0) {
      std::cerr << "Error: the intersection points of tile " << t << " in " << workdir
                << " are missing or broken: run its second pass again (refine " << t
                << ").\n";
      return false;
    }
    for (std::size_t k = 0; k < values.size(); k += kValuesPerPoint) {
      const float* v = values.data() + k;
      if (!validParts (v)) {
        std::cerr << "Error: the intersection points of tile " << t << " in " << workdir
                  << " are broken: run its second pass again (refine " << t << ").\n";
        return false;
      }
      TileIntersection i;
      i.index_a = joinKey (v);
      i.index_b = joinKey (v + 3);
      i.point.segment_a = segmentAt (v + 6);
      i.point.segment_b = segmentAt (v + 8);
      i.point.x = v[10];
      i.point.y = v[11];
      i.point.z = v[12];
      all.push_back (i);
    }
  }
  // A point's intersections are all in its owner's file, in their order.
  std::stable_sort (all.begin(),
                    all.end(),
                    [] (const TileIntersection& a, const TileIntersection& b) {
                      return a.index_a < b.index_a;
                    });
  constexpr auto kLargest =
      static_cast<std::uint64_t> (std::numeric_limits<std::int32_t>::max());
  intersections.reserve (all.size());
  for (auto& i : all) {
    if (i.index_a > kLargest || i.index_b > kLargest) {
      std::cerr << "Error: the intersection points name points by 32-bit indices, and "
                   "point "
                << std::max (i.index_a, i.index_b)
                << " is beyond them: leave out -intersections for a cloud of more than "
                << kLargest + 1 << " points.\n";
      intersections.clear();
      return false;
    }
    i.point.index_a = static_cast<std::int32_t> (i.index_a);
    i.point.index_b = static_cast<std::int32_t> (i.index_b);
    intersections.push_back (i.point);
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
