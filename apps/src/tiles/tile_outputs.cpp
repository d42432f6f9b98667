/*
 * pcl_ext_tiles: one output file per tile, with an index of the files.
 */
#include "tile_outputs.h"

#include <pcl_ext/io/file_output.h>
#include <pcl_ext/tiling/point_file_chunks.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <sys/resource.h>

namespace pcl_ext {
namespace apps {
namespace {
std::string
fileName (const std::string& path)
{
  const auto slash = path.find_last_of ('/');
  return slash == std::string::npos ? path : path.substr (slash + 1);
}
} // namespace

bool
TileOutputs::isPattern (const std::string& output)
{
  return fileName (output).find ('#') != std::string::npos;
}

std::string
TileOutputs::pathOf (const std::string& pattern, std::size_t tile)
{
  std::string path = pattern;
  const auto at = path.find ('#', path.size() - fileName (path).size());
  return path.replace (at, 1, std::to_string (tile));
}

std::string
TileOutputs::indexPathOf (const std::string& pattern)
{
  std::string path = pattern;
  const auto at = path.find ('#', path.size() - fileName (path).size());
  path.replace (at, 1, "index");
  const auto dot = path.find_last_of ('.');
  const auto slash = path.find_last_of ('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    path.erase (dot);
  return path + ".csv";
}

TileOutputs::TileOutputs (const std::string& pattern,
                          const tiling::TileGrid& grid,
                          const Eigen::Vector3d& origin,
                          const io::LasFileInfo* like)
: pattern_ (pattern), grid_ (grid), origin_ (origin), like_ (like)
{}

TileOutputs::~TileOutputs()
{
  if (!closed_)
    removeWritten();
}

void
TileOutputs::removeWritten()
{
  open_.clear(); // unfinished writers remove their temporary files
  for (const auto& d : done_)
    std::remove (pathOf (pattern_, d.tile).c_str());
  done_.clear();
}

bool
TileOutputs::write (const pcl::PCLPointCloud2& chunk,
                    std::size_t first_tile,
                    std::size_t end_tile)
{
  const std::size_t n = static_cast<std::size_t> (chunk.width) * chunk.height;
  const std::uint8_t* xyz = chunk.data.data() + tiling::xyzOffset (chunk);
  // The owner of every row, as the plan found it: the tile whose core box holds the
  // point's coordinates, in double, from the same floats and origin.
  std::map<std::size_t, pcl::Indices> rows_of_tile;
  for (std::size_t i = 0; i < n; ++i) {
    float p[3];
    std::memcpy (p, xyz + i * chunk.point_step, sizeof (p));
    if (!std::isfinite (p[0]) || !std::isfinite (p[1]) || !std::isfinite (p[2])) {
      points_in_no_tile_ += first_tile == 0 ? 1 : 0; // counted in the first pass
      continue;
    }
    const std::size_t tile = grid_.getTile (origin_.x() + p[0], origin_.y() + p[1]);
    if (tile == tiling::TileGrid::kNoTile) {
      PCL_ERROR ("[pcl_ext_tiles] a point at (%.3f %.3f) lies outside the plan's "
                 "tiles: an input changed since the plan.\n",
                 origin_.x() + p[0],
                 origin_.y() + p[1]);
      return false;
    }
    if (tile >= first_tile && tile < end_tile)
      rows_of_tile[tile].push_back (static_cast<pcl::index_t> (i));
  }
  pcl::PCLPointCloud2 part;
  for (const auto& [tile, rows] : rows_of_tile) {
    pcl::copyPointCloud (chunk, rows, part);
    auto& writer = open_[tile];
    if (!writer) {
      writer = std::make_unique<io::LasWriter>();
      if (!writer->open (pathOf (pattern_, tile), part, origin_, like_))
        return false;
    }
    if (!writer->write (part))
      return false;
  }
  return true;
}

bool
TileOutputs::finishPass()
{
  for (auto& [tile, writer] : open_) {
    const std::uint64_t points = writer->getPointsWritten();
    if (!writer->close())
      return false;
    done_.push_back ({tile, points});
  }
  open_.clear();
  return true;
}

bool
TileOutputs::close()
{
  if (!finishPass())
    return false;
  std::ostringstream csv;
  csv << "file,tile,points,xmin,ymin,xmax,ymax,wkt\n" << std::setprecision (15);
  for (const auto& d : done_) {
    Eigen::Vector2d lo, hi;
    grid_.getCoreBox (d.tile, lo, hi);
    csv << fileName (pathOf (pattern_, d.tile)) << "," << d.tile << "," << d.points
        << "," << lo.x() << "," << lo.y() << "," << hi.x() << "," << hi.y()
        << ",\"POLYGON ((" << lo.x() << " " << lo.y() << ", " << hi.x() << " " << lo.y()
        << ", " << hi.x() << " " << hi.y() << ", " << lo.x() << " " << hi.y() << ", "
        << lo.x() << " " << lo.y() << "))\"\n";
  }
  if (!io::writeTextFile (indexPathOf (pattern_), csv.str())) {
    PCL_ERROR ("[pcl_ext_tiles] cannot write the index %s.\n",
               indexPathOf (pattern_).c_str());
    return false;
  }
  closed_ = true;
  return true;
}

std::size_t
TileOutputs::openFilesAllowed()
{
  rlimit limit{};
  if (::getrlimit (RLIMIT_NOFILE, &limit) != 0)
    return 256;
  if (limit.rlim_cur < limit.rlim_max) {
    rlimit raised = limit;
    raised.rlim_cur = limit.rlim_max;
    if (::setrlimit (RLIMIT_NOFILE, &raised) == 0)
      limit = raised;
  }
  const rlim_t usable = limit.rlim_cur == RLIM_INFINITY ? 65536 : limit.rlim_cur;
  return usable > 96 ? static_cast<std::size_t> (std::min<rlim_t> (usable - 64, 65536))
                     : 32;
}

} // namespace apps
} // namespace pcl_ext
