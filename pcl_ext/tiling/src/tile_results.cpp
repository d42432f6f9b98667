/*
 * pcl_ext: what the tiles of a run computed, as files of its work folder.
 */
#include <pcl_ext/tiling/tile_results.h>

#include <pcl_ext/tiling/positioned_io.h>

#include "record_file.h"

#include <pcl_ext/io/file_output.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <limits>
#include <fcntl.h>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace pcl_ext {
namespace tiling {
namespace {
constexpr std::size_t kHaloRecordBytes = 16;
constexpr std::size_t kSizeRecordBytes = 20;
constexpr std::size_t kBlockValues = 1 << 16;

std::string
valuesPath (const std::string& folder, std::size_t tile, const std::string& name)
{
  return folder + "/tile_" + std::to_string (tile) + "." + name;
}

/** Writes \a count records of \a size bytes, record i filled by \a fill (i, bytes),
 * to \a path, replacing it atomically. */
template <typename Fill>
bool
writeRecords (const std::string& path, std::size_t count, std::size_t size, Fill fill)
{
  return io::writeFileAtomically (path, [&] (const std::string& temporary) {
    std::vector<char> bytes (count * size);
    for (std::size_t i = 0; i < count; ++i)
      fill (i, bytes.data() + i * size);
    std::ofstream out (temporary, std::ios::binary);
    out.write (bytes.data(), static_cast<std::streamsize> (bytes.size()));
    out.close();
    return static_cast<bool> (out);
  });
}

/** The bytes of \a path, a whole number of records of \a size bytes written by tile
 * \a tile; false (PCL_ERROR) when missing or broken. */
bool
readRecords (const std::string& path,
             std::size_t size,
             std::size_t tile,
             std::vector<char>& bytes)
{
  const detail::RecordFileRead read = detail::readRecordFile (path, size, bytes);
  if (read == detail::RecordFileRead::CannotOpen ||
      read == detail::RecordFileRead::NotWholeRecords) {
    PCL_ERROR ("[pcl_ext::tiling] %s is missing (tile %zu not run) or broken.\n",
               path.c_str(),
               tile);
    return false;
  }
  if (read == detail::RecordFileRead::CannotRead) {
    PCL_ERROR ("[pcl_ext::tiling] cannot read %s.\n", path.c_str());
    return false;
  }
  return true;
}
} // namespace

std::string
TileResults::pathIn (const std::string& folder, const std::string& name)
{
  return folder + "/" + name + ".bin";
}

bool
TileResults::create (const std::string& folder,
                     std::uint64_t points,
                     const std::string& name)
{
  const std::string path = pathIn (folder, name);
  return io::writeFileAtomically (path, [points] (const std::string& temporary) {
    std::ofstream out (temporary, std::ios::binary);
    const std::vector<std::uint32_t> block (kBlockValues, kNoResult);
    for (std::uint64_t done = 0; done < points && out; done += kBlockValues) {
      const std::uint64_t n = std::min<std::uint64_t> (kBlockValues, points - done);
      out.write (reinterpret_cast<const char*> (block.data()),
                 static_cast<std::streamsize> (n * sizeof (std::uint32_t)));
    }
    out.close();
    return static_cast<bool> (out);
  });
}

bool
TileResults::write (const std::string& folder,
                    const std::vector<std::uint64_t>& indices,
                    const std::vector<std::uint32_t>& values,
                    const std::string& name)
{
  const std::string path = pathIn (folder, name);
  const int fd = ::open (path.c_str(), O_WRONLY);
  struct stat st;
  if (fd < 0 || ::fstat (fd, &st) != 0) {
    if (fd >= 0)
      ::close (fd);
    PCL_ERROR ("[pcl_ext::tiling::TileResults] cannot open %s.\n", path.c_str());
    return false;
  }
  bool ok = true;
  // Runs of consecutive indices go in one call each.
  for (std::size_t i = 0; i < indices.size() && ok;) {
    std::size_t j = i + 1;
    while (j < indices.size() && indices[j] == indices[j - 1] + 1)
      ++j;
    const std::uint64_t end = (indices[j - 1] + 1) * sizeof (std::uint32_t);
    ok = end <= static_cast<std::uint64_t> (st.st_size) &&
         writeAllAt (fd,
                     values.data() + i,
                     (j - i) * sizeof (std::uint32_t),
                     indices[i] * sizeof (std::uint32_t));
    i = j;
  }
  ok = (::close (fd) == 0) && ok;
  if (!ok)
    PCL_ERROR ("[pcl_ext::tiling::TileResults] cannot write %s (a point beyond the "
               "file, or the disk is full).\n",
               path.c_str());
  return ok;
}

bool
TileResults::readAt (const std::string& folder,
                     const std::vector<std::uint64_t>& indices,
                     std::vector<std::uint32_t>& values,
                     const std::string& name)
{
  const std::string path = pathIn (folder, name);
  values.resize (indices.size());
  const int fd = ::open (path.c_str(), O_RDONLY);
  bool ok = fd >= 0;
  // Runs of consecutive indices (a tile's points mostly come in runs) in one call each.
  for (std::size_t i = 0; i < indices.size() && ok;) {
    std::size_t j = i + 1;
    while (j < indices.size() && indices[j] == indices[j - 1] + 1)
      ++j;
    ok = readAllAt (fd,
                    values.data() + i,
                    (j - i) * sizeof (std::uint32_t),
                    indices[i] * sizeof (std::uint32_t));
    i = j;
  }
  if (fd >= 0)
    ::close (fd);
  if (!ok) {
    PCL_ERROR ("[pcl_ext::tiling::TileResults] cannot read %s (missing or shorter than "
               "the plan's points).\n",
               path.c_str());
    values.clear();
    return false;
  }
  return true;
}

bool
TileResults::read (const std::string& folder,
                   std::uint64_t first,
                   std::size_t count,
                   std::vector<std::uint32_t>& values,
                   const std::string& name)
{
  const std::string path = pathIn (folder, name);
  values.resize (count);
  std::ifstream in (path, std::ios::binary);
  in.seekg (static_cast<std::streamoff> (first * sizeof (std::uint32_t)));
  in.read (reinterpret_cast<char*> (values.data()),
           static_cast<std::streamsize> (count * sizeof (std::uint32_t)));
  if (!in) {
    PCL_ERROR ("[pcl_ext::tiling::TileResults] cannot read %s (missing or shorter than "
               "the plan's points).\n",
               path.c_str());
    values.clear();
    return false;
  }
  return true;
}

bool
saveHaloLabels (const std::string& folder,
                std::size_t tile,
                const std::vector<HaloLabel>& labels,
                const std::string& name)
{
  return writeRecords (valuesPath (folder, tile, name),
                       labels.size(),
                       kHaloRecordBytes,
                       [&labels] (std::size_t i, char* r) {
                         std::memcpy (r, &labels[i].index, 8);
                         std::memcpy (r + 8, &labels[i].owner, 4);
                         std::memcpy (r + 12, &labels[i].label, 4);
                       });
}

bool
loadHaloLabels (const std::string& folder,
                std::size_t tile,
                std::vector<HaloLabel>& labels,
                const std::string& name)
{
  labels.clear();
  std::vector<char> bytes;
  if (!readRecords (valuesPath (folder, tile, name), kHaloRecordBytes, tile, bytes))
    return false;
  labels.resize (bytes.size() / kHaloRecordBytes);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const char* r = bytes.data() + i * kHaloRecordBytes;
    std::memcpy (&labels[i].index, r, 8);
    std::memcpy (&labels[i].owner, r + 8, 4);
    std::memcpy (&labels[i].label, r + 12, 4);
  }
  return true;
}

bool
saveSegmentSizes (const std::string& folder,
                  std::size_t tile,
                  const std::vector<SegmentSize>& sizes,
                  const std::string& name)
{
  return writeRecords (valuesPath (folder, tile, name),
                       sizes.size(),
                       kSizeRecordBytes,
                       [&sizes] (std::size_t i, char* r) {
                         std::memcpy (r, &sizes[i].label, 4);
                         std::memcpy (r + 4, &sizes[i].points, 8);
                         std::memcpy (r + 12, &sizes[i].first, 8);
                       });
}

bool
loadSegmentSizes (const std::string& folder,
                  std::size_t tile,
                  std::vector<SegmentSize>& sizes,
                  const std::string& name)
{
  sizes.clear();
  std::vector<char> bytes;
  if (!readRecords (valuesPath (folder, tile, name), kSizeRecordBytes, tile, bytes))
    return false;
  sizes.resize (bytes.size() / kSizeRecordBytes);
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const char* r = bytes.data() + i * kSizeRecordBytes;
    std::memcpy (&sizes[i].label, r, 4);
    std::memcpy (&sizes[i].points, r + 4, 8);
    std::memcpy (&sizes[i].first, r + 12, 8);
  }
  return true;
}

bool
saveSegmentIds (const std::string& folder,
                std::size_t tile,
                const std::vector<std::uint32_t>& ids)
{
  return writeRecords (
      valuesPath (folder, tile, "ids"),
      ids.size(),
      sizeof (std::uint32_t),
      [&ids] (std::size_t i, char* r) { std::memcpy (r, &ids[i], 4); });
}

bool
loadSegmentIds (const std::string& folder,
                std::size_t tile,
                std::vector<std::uint32_t>& ids)
{
  ids.clear();
  std::vector<char> bytes;
  if (!readRecords (
          valuesPath (folder, tile, "ids"), sizeof (std::uint32_t), tile, bytes))
    return false;
  ids.resize (bytes.size() / sizeof (std::uint32_t));
  if (!ids.empty())
    std::memcpy (ids.data(), bytes.data(), bytes.size());
  return true;
}

namespace {
std::string
startPath (const std::string& folder, std::size_t tile)
{
  return folder + "/tile_" + std::to_string (tile) + ".running";
}
} // namespace

bool
markTileStarted (const std::string& folder, std::size_t tile)
{
  char host[256] = "unknown";
  ::gethostname (host, sizeof (host) - 1);
  host[sizeof (host) - 1] = '\0';
  const std::time_t now = std::time (nullptr);
  char when[64] = "";
  std::tm utc{};
  if (::gmtime_r (&now, &utc))
    std::strftime (when, sizeof (when), "%Y-%m-%d %H:%M:%S UTC", &utc);
  return io::writeTextFile (startPath (folder, tile),
                            "process " + std::to_string (::getpid()) + " on host " +
                                host + " at " + when + "\n");
}

std::string
describeTileStart (const std::string& folder, std::size_t tile)
{
  std::ifstream in (startPath (folder, tile));
  std::string line;
  std::getline (in, line);
  return line;
}

bool
markTileDone (const std::string& folder, std::size_t tile, const std::string& pass)
{
  if (!io::writeTextFile (folder + "/tile_" + std::to_string (tile) + "." + pass,
                          pass + "\n"))
    return false;
  std::remove (startPath (folder, tile).c_str());
  return true;
}

std::vector<std::size_t>
findTilesNotDone (const std::string& folder, std::size_t tiles, const std::string& pass)
{
  std::vector<std::size_t> missing;
  struct stat st;
  for (std::size_t t = 0; t < tiles; ++t) {
    const std::string path = folder + "/tile_" + std::to_string (t) + "." + pass;
    if (::stat (path.c_str(), &st) != 0)
      missing.push_back (t);
  }
  return missing;
}

bool
saveTileValues (const std::string& folder,
                std::size_t tile,
                const std::string& name,
                const std::vector<float>& values)
{
  return io::writeFileAtomically (
      valuesPath (folder, tile, name), [&values] (const std::string& temporary) {
        std::ofstream out (temporary, std::ios::binary);
        out.write (reinterpret_cast<const char*> (values.data()),
                   static_cast<std::streamsize> (values.size() * sizeof (float)));
        out.close();
        return static_cast<bool> (out);
      });
}

bool
loadTileValues (const std::string& folder,
                std::size_t tile,
                const std::string& name,
                std::vector<float>& values)
{
  values.clear();
  const std::string path = valuesPath (folder, tile, name);
  std::ifstream in (path, std::ios::binary | std::ios::ate);
  if (!in) {
    PCL_ERROR ("[pcl_ext::tiling::loadTileValues] %s is missing (tile %zu not "
               "estimated).\n",
               path.c_str(),
               tile);
    return false;
  }
  const std::streamoff size = in.tellg();
  if (size < 0 || size % static_cast<std::streamoff> (sizeof (float)) != 0) {
    PCL_ERROR ("[pcl_ext::tiling::loadTileValues] %s is broken.\n", path.c_str());
    return false;
  }
  values.resize (static_cast<std::size_t> (size) / sizeof (float));
  in.seekg (0);
  in.read (reinterpret_cast<char*> (values.data()),
           static_cast<std::streamsize> (size));
  if (!in) {
    PCL_ERROR ("[pcl_ext::tiling::loadTileValues] %s is broken.\n", path.c_str());
    values.clear();
    return false;
  }
  return true;
}

} // namespace tiling
} // namespace pcl_ext
