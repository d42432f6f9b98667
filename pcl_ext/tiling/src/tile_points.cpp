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

std::string
tileAttributesPath (const std::string& folder, std::size_t tile)
{
  return folder + "/tile_" + std::to_string (tile) + ".attributes";
}

TilePointWriter::TilePointWriter (std::string folder,
                                  std::size_t tiles,
                                  std::size_t buffer_points,
                                  std::size_t attributes)
: folder_ (std::move (folder))
, buffer_points_ (buffer_points > 0 ? buffer_points : 1)
, attributes_ (attributes)
, buffers_ (tiles)
, attribute_buffers_ (attributes > 0 ? tiles : 0)
, counts_ (tiles, 0)
, started_ (tiles, false)
{}

TilePointWriter::~TilePointWriter() = default;

bool
TilePointWriter::add (std::size_t tile, const TilePoint& point, const float* attributes)
{
  if (failed_)
    return false;
  buffers_[tile].push_back (point);
  if (attributes_ > 0)
    attribute_buffers_[tile].insert (
        attribute_buffers_[tile].end(), attributes, attributes + attributes_);
  ++counts_[tile];
  if (buffers_[tile].size() >= buffer_points_)
    return flush (tile);
  return true;
}

bool
TilePointWriter::append (const std::string& path,
                         bool started,
                         const std::vector<char>& bytes)
{
  std::ofstream out (path,
                     started ? std::ios::binary | std::ios::app
                             : std::ios::binary | std::ios::trunc);
  out.write (bytes.data(), static_cast<std::streamsize> (bytes.size()));
  out.close();
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
TilePointWriter::flush (std::size_t tile)
{
  std::vector<char> bytes (buffers_[tile].size() * kRecordBytes);
  for (std::size_t i = 0; i < buffers_[tile].size(); ++i)
    encode (buffers_[tile][i], bytes.data() + i * kRecordBytes);
  buffers_[tile].clear();
  const bool started = started_[tile];
  started_[tile] = true;
  if (!append (tilePointsPath (folder_, tile), started, bytes))
    return false;
  if (attributes_ == 0)
    return true;
  auto& values = attribute_buffers_[tile];
  bytes.resize (values.size() * sizeof (float));
  std::memcpy (bytes.data(), values.data(), bytes.size());
  values.clear();
  return append (tileAttributesPath (folder_, tile), started, bytes);
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
bool
readTileAttributes (const std::string& folder,
                    std::size_t tile,
                    std::size_t attributes,
                    std::vector<float>& values)
{
  values.clear();
  if (attributes == 0)
    return true;
  const std::string path = tileAttributesPath (folder, tile);
  std::vector<char> data;
  const detail::RecordFileRead read =
      detail::readRecordFile (path, attributes * sizeof (float), data);
  if (read != detail::RecordFileRead::Done) {
    PCL_ERROR ("[pcl_ext::tiling::readTileAttributes] %s %s.\n",
               path.c_str(),
               read == detail::RecordFileRead::NotWholeRecords
                   ? "is not a whole number of points"
                   : "cannot be read");
    return false;
  }
  values.resize (data.size() / sizeof (float));
  std::memcpy (values.data(), data.data(), data.size());
  return true;
}
} // namespace tiling
} // namespace pcl_ext
