/*
 * pcl_ext: the points of each tile (core and halo) as files of a work folder.
 */
#include <pcl_ext/tiling/tile_points.h>

#include "record_file.h"

#include <pcl/console/print.h>

#include <cstring>
#include <fstream>
#include <utility>

namespace pcl_ext {
namespace tiling {
namespace {
constexpr std::size_t kRecordBytes = 24;

void
encode (const TilePoint& p, char* out)
{
  std::memcpy (out, &p.index, 8);
  std::memcpy (out + 8, &p.x, 4);
  std::memcpy (out + 12, &p.y, 4);
  std::memcpy (out + 16, &p.z, 4);
  std::memcpy (out + 20, &p.owner, 4);
}
} // namespace

std::string
tilePointsPath (const std::string& folder, std::size_t tile)
{
  return folder + "/tile_" + std::to_string (tile) + ".points";
}

TilePointWriter::TilePointWriter (std::string folder,
                                  std::size_t tiles,
                                  std::size_t buffer_points)
: folder_ (std::move (folder))
, buffer_points_ (buffer_points > 0 ? buffer_points : 1)
, buffers_ (tiles)
, counts_ (tiles, 0)
, started_ (tiles, false)
{}

TilePointWriter::~TilePointWriter() = default;

bool
TilePointWriter::add (std::size_t tile, const TilePoint& point)
{
  if (failed_)
    return false;
  buffers_[tile].push_back (point);
  ++counts_[tile];
  if (buffers_[tile].size() >= buffer_points_)
    return flush (tile);
  return true;
}

bool
TilePointWriter::flush (std::size_t tile)
{
  const std::string path = tilePointsPath (folder_, tile);
  std::ofstream out (path,
                     started_[tile] ? std::ios::binary | std::ios::app
                                    : std::ios::binary | std::ios::trunc);
  started_[tile] = true;
  std::vector<char> bytes (buffers_[tile].size() * kRecordBytes);
  for (std::size_t i = 0; i < buffers_[tile].size(); ++i)
    encode (buffers_[tile][i], bytes.data() + i * kRecordBytes);
  out.write (bytes.data(), static_cast<std::streamsize> (bytes.size()));
  out.close();
  buffers_[tile].clear();
  if (!out) {
    PCL_ERROR (
        "[pcl_ext::tiling::TilePointWriter] cannot write %s (disk full or folder "
        "not writable).\n",
        path.c_str());
    failed_ = true;
  }
  return !failed_;
}

bool
TilePointWriter::finish()
{
  for (std::size_t t = 0; t < buffers_.size() && !failed_; ++t)
    if (!buffers_[t].empty() || !started_[t])
      flush (t);
  return !failed_;
}

bool
readTilePoints (const std::string& folder,
                std::size_t tile,
                std::vector<TilePoint>& points)
{
  points.clear();
  const std::string path = tilePointsPath (folder, tile);
  std::vector<char> data;
  const detail::RecordFileRead read = detail::readRecordFile (path, kRecordBytes, data);
  if (read == detail::RecordFileRead::CannotOpen) {
    PCL_ERROR ("[pcl_ext::tiling::readTilePoints] cannot open %s.\n", path.c_str());
    return false;
  }
  if (read == detail::RecordFileRead::NotWholeRecords) {
    PCL_ERROR (
        "[pcl_ext::tiling::readTilePoints] %s is not a whole number of points.\n",
        path.c_str());
    return false;
  }
  if (read == detail::RecordFileRead::CannotRead) {
    PCL_ERROR ("[pcl_ext::tiling::readTilePoints] cannot read %s.\n", path.c_str());
    return false;
  }
  points.resize (data.size() / kRecordBytes);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const char* r = data.data() + i * kRecordBytes;
    std::memcpy (&points[i].index, r, 8);
    std::memcpy (&points[i].x, r + 8, 4);
    std::memcpy (&points[i].y, r + 12, 4);
    std::memcpy (&points[i].z, r + 16, 4);
    std::memcpy (&points[i].owner, r + 20, 4);
    if (i > 0 && points[i].index <= points[i - 1].index) {
      PCL_ERROR ("[pcl_ext::tiling::readTilePoints] %s: point indices not ascending at "
                 "record %zu.\n",
                 path.c_str(),
                 i);
      points.clear();
      return false;
    }
  }
  return true;
}
} // namespace tiling
} // namespace pcl_ext
