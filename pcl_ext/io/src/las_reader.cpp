/*
 * pcl_ext: LAS 1.0-1.4 files read in chunks (ASPRS LAS 1.4 R15).
 */
#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/laz_record_source.h>
#include <pcl_ext/io/point_table.h>

#include "las_bytes.h"
#include "las_file.h"
#include "las_point_layout.h"

#include <pcl/console/print.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>

namespace pcl_ext {
namespace io {
namespace las {
File::File (const std::string& path) : path_ (path)
{
  fd_ = ::open (path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0)
    throw ReadError (path, 0, std::string ("cannot open: ") + std::strerror (errno));
  struct stat st;
  if (::fstat (fd_, &st) != 0 || !S_ISREG (st.st_mode)) {
    ::close (fd_);
    throw ReadError (path, 0, "not a regular file");
  }
  size_ = static_cast<std::uint64_t> (st.st_size);
}

File::~File() { ::close (fd_); }

void
File::readAt (std::uint64_t offset, std::size_t n, void* out, const char* what) const
{
  auto* p = static_cast<std::uint8_t*> (out);
  while (n > 0) {
    const ssize_t got = ::pread (fd_, p, n, static_cast<off_t> (offset));
    if (got < 0 && errno == EINTR)
      continue;
    if (got <= 0)
      throw ReadError (path_,
                       0,
                       std::string ("truncated ") + what + " (the file ends at " +
                           std::to_string (size_) + " bytes)");
    p += got;
    n -= static_cast<std::size_t> (got);
    offset += static_cast<std::uint64_t> (got);
  }
}
} // namespace las

namespace {
constexpr std::size_t kVlrHeader = 54, kEvlrHeader = 60;
/** Records decoded at a time: small enough for the block and its points to stay in
 * cache, large enough to make the per-block work negligible. */
constexpr std::size_t kBlockPoints = 8192;
/** Bytes between the VLRs and the points kept for the writer (more are dropped). */
constexpr std::size_t kMaxPrePointBytes = 65536;

LasVariableLengthRecord
vlrHeader (const std::uint8_t* p)
{
  LasVariableLengthRecord vlr;
  vlr.reserved = las::get<std::uint16_t> (p);
  vlr.user_id = las::getString (p + 2, 16);
  vlr.record_id = las::get<std::uint16_t> (p + 18);
  return vlr;
}

void
readVlrs (const las::File& file, LasFileInfo& info)
{
  const LasHeader& h = info.header;
  std::uint64_t at = h.header_size;
  const std::uint64_t end = h.offset_to_point_data;
  for (std::uint32_t i = 0; i < h.number_of_vlrs; ++i) {
    const std::string which =
        "VLR " + std::to_string (i + 1) + " of " + std::to_string (h.number_of_vlrs);
    if (end - at < kVlrHeader)
      throw ReadError (file.path(),
                       0,
                       which + " at byte " + std::to_string (at) +
                           " runs past the point data (offset " + std::to_string (end) +
                           ")");
    std::uint8_t p[kVlrHeader];
    file.readAt (at, kVlrHeader, p, "VLR");
    LasVariableLengthRecord vlr = vlrHeader (p);
    const std::uint16_t length = las::get<std::uint16_t> (p + 20);
    vlr.description = las::getString (p + 22, 32);
    at += kVlrHeader;
    if (end - at < length)
      throw ReadError (
          file.path(),
          0,
          which + " (\"" + vlr.user_id + "\", " + std::to_string (vlr.record_id) +
              ") of " + std::to_string (length) +
              " bytes runs past the point data (offset " + std::to_string (end) + ")");
    vlr.data.resize (length);
    file.readAt (at, length, vlr.data.data(), "VLR");
    at += length;
    info.vlrs.push_back (std::move (vlr));
  }
  if (end - at <= kMaxPrePointBytes) {
    info.pre_point_bytes.resize (end - at);
    file.readAt (
        at, info.pre_point_bytes.size(), info.pre_point_bytes.data(), "header");
  }
}

void
readEvlrs (const las::File& file, LasFileInfo& info)
{
  const LasHeader& h = info.header;
  std::uint64_t at = h.evlr_start;
  for (std::uint32_t i = 0; i < h.evlr_count; ++i) {
    const std::string which =
        "EVLR " + std::to_string (i + 1) + " of " + std::to_string (h.evlr_count);
    if (file.size() - at < kEvlrHeader)
      throw ReadError (file.path(), 0, which + " runs past the end of the file");
    std::uint8_t p[kEvlrHeader];
    file.readAt (at, kEvlrHeader, p, "EVLR");
    LasVariableLengthRecord vlr = vlrHeader (p);
    vlr.extended = true;
    const std::uint64_t length = las::get<std::uint64_t> (p + 20);
    vlr.description = las::getString (p + 28, 32);
    at += kEvlrHeader;
    if (file.size() - at < length)
      throw ReadError (file.path(),
                       0,
                       which + " (\"" + vlr.user_id + "\", " +
                           std::to_string (vlr.record_id) + ") of " +
                           std::to_string (length) +
                           " bytes runs past the end of the file");
    // Waveform data packets (LASF_Spec 65535) can be huge and are not read.
    if (!(vlr.user_id == "LASF_Spec" && vlr.record_id == 65535)) {
      vlr.data.resize (static_cast<std::size_t> (length));
      file.readAt (at, vlr.data.size(), vlr.data.data(), "EVLR");
      info.evlrs.push_back (std::move (vlr));
    }
    at += length;
  }
}

/** Large point buffers are filled once, page by page: on Linux, ask for huge pages so
 * that filling them costs 512 times fewer page faults. */
void
adviseHugePages (std::vector<std::uint8_t>& data)
{
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kHuge = 2u << 20;
  const auto begin = reinterpret_cast<std::uintptr_t> (data.data());
  const std::uintptr_t first = (begin + kHuge - 1) / kHuge * kHuge;
  const std::uintptr_t last = (begin + data.capacity()) / kHuge * kHuge;
  if (last > first)
    ::madvise (reinterpret_cast<void*> (first), last - first, MADV_HUGEPAGE);
#else
  (void)data;
#endif
}

Eigen::Vector3d
defaultOrigin (const LasHeader& h)
{
  Eigen::Vector3d origin;
  for (int a = 0; a < 3; ++a) {
    const double lo = h.min[a], hi = h.max[a];
    const double centre = 0.5 * (lo + hi);
    if (std::isfinite (centre) && std::abs (centre) < 1e15) {
      if (std::max (std::abs (lo), std::abs (hi)) <= kFloatSafeCoordinate)
        origin[a] = 0.0;
      else
        origin[a] = std::round (centre / 100.0) * 100.0;
    }
    else
      origin[a] = std::round (h.offset[a] / 100.0) * 100.0;
  }
  return origin;
}
} // namespace

struct LasReader::Decoding {
  las::PointLayout layout;
  las::CoordinateTransform transform;
  bool finite = true; ///< every int32 coordinate gives a finite float
};

LasReader::LasReader() = default;
LasReader::~LasReader() = default;

void
LasReader::open (const std::string& path)
{
  auto file = std::make_shared<const las::File> (path);
  std::vector<std::uint8_t> head (
      static_cast<std::size_t> (std::min<std::uint64_t> (file->size(), 65536)));
  file->readAt (0, head.size(), head.data(), "header");
  LasFileInfo info;
  info.header = parseLasHeader (head.data(), head.size(), file->size(), path);
  const LasHeader& h = info.header;
  readVlrs (*file, info);
  readEvlrs (*file, info);

  const int format = h.pointFormat();
  const std::size_t standard = lasPointRecordLength (format);
  for (const auto& vlr : info.vlrs)
    if (isExtraBytesRecord (vlr)) {
      info.extra_bytes = parseExtraBytes (vlr, path);
      std::size_t bytes = 0;
      for (const auto& e : info.extra_bytes)
        bytes += e.size();
      if (bytes > h.record_length - standard)
        throw ReadError (path,
                         0,
                         "the extra-bytes record describes " + std::to_string (bytes) +
                             " bytes but records have " +
                             std::to_string (h.record_length - standard) +
                             " beyond the standard " + std::to_string (standard));
      break;
    }

  std::unique_ptr<LasRecordSource> source;
  if (h.isCompressed()) {
    const auto laszip =
        std::find_if (info.vlrs.begin(), info.vlrs.end(), isLaszipRecord);
    if (laszip == info.vlrs.end())
      throw ReadError (path,
                       0,
                       "compressed point data (LAZ) without a LASzip VLR "
                       "(\"laszip encoded\", 22204)");
    source = makeLazRecordSource (path,
                                  h.offset_to_point_data,
                                  format,
                                  h.record_length,
                                  h.point_count,
                                  laszip->data);
  }
  else
    source = std::make_unique<las::FileRecordSource> (
        file, h.offset_to_point_data, h.record_length, h.point_count);

  auto decoding = std::make_unique<Decoding>();
  decoding->layout = las::makePointLayout (format, h.record_length, info.extra_bytes);
  info.origin = defaultOrigin (h);

  path_ = path;
  info_ = std::move (info);
  source_ = std::move (source);
  decoding_ = std::move (decoding);
  block_.assign (kBlockPoints * info_.header.record_length, 0);
  block_points_ = block_next_ = 0;
  points_read_ = points_fetched_ = 0;
  colour_shift_ = 8;
  colour_checked_ = !las::hasColour (format);
  setOrigin (info_.origin);
}

void
LasReader::setOrigin (const Eigen::Vector3d& origin)
{
  if (!origin.allFinite()) {
    PCL_ERROR ("[pcl_ext::io::LasReader::setOrigin] the origin must be finite; kept "
               "(%g, %g, %g).\n",
               info_.origin.x(),
               info_.origin.y(),
               info_.origin.z());
    return;
  }
  info_.origin = origin;
  if (!decoding_)
    return;
  const LasHeader& h = info_.header;
  decoding_->transform.scale = h.scale;
  decoding_->transform.shift = h.offset - origin;
  decoding_->finite = true;
  for (int a = 0; a < 3; ++a)
    decoding_->finite =
        decoding_->finite && std::abs (h.scale[a]) * 2147483648.0 +
                                     std::abs (decoding_->transform.shift[a]) <
                                 1e38;
}

bool
LasReader::fillBlock()
{
  const std::uint64_t wanted = std::min<std::uint64_t> (
      kBlockPoints, info_.header.point_count - points_fetched_);
  if (wanted == 0)
    return false;
  const std::size_t got =
      source_->readRecords (static_cast<std::size_t> (wanted), block_.data());
  if (got != wanted)
    throw ReadError (path_,
                     0,
                     "the point data ends after " +
                         std::to_string (points_fetched_ + got) + " of " +
                         std::to_string (info_.header.point_count) + " points");
  points_fetched_ += got;
  block_points_ = got;
  block_next_ = 0;
  if (!colour_checked_) {
    // Files that store 8-bit colour (all values <= 255) keep it as it is in rgb.
    std::size_t red = 0;
    las::hasColour (info_.header.pointFormat(), &red);
    bool wide = false;
    const std::size_t rl = info_.header.record_length;
    for (std::size_t i = 0; i < got && !wide; ++i)
      for (std::size_t c = 0; c < 3; ++c)
        wide = wide || las::get<std::uint16_t> (&block_[i * rl + red + 2 * c]) > 255;
    colour_shift_ = wide ? 8 : 0;
    colour_checked_ = true;
  }
  return true;
}

std::size_t
LasReader::read (std::size_t max_points, pcl::PCLPointCloud2& chunk)
{
  if (!source_)
    throw ReadError (path_.empty() ? "(LasReader)" : path_, 0, "no LAS file is open");
  const las::PointLayout& layout = decoding_->layout;
  const std::size_t step = layout.point_step;
  const std::size_t rl = info_.header.record_length;
  const std::uint64_t remaining = info_.header.point_count - points_read_;
  std::uint64_t expected = std::min<std::uint64_t> (max_points, remaining);
  if (info_.header.isCompressed()) // the count has not been checked against the file
    expected = std::min<std::uint64_t> (expected, 1u << 20);
  // The chunk's memory is reused from one call to the next.
  std::vector<std::uint8_t> data;
  data.swap (chunk.data);
  data.clear();
  if (data.capacity() < expected * step) {
    data = std::vector<std::uint8_t>();
    data.reserve (static_cast<std::size_t> (expected) * step);
    adviseHugePages (data);
  }
  std::size_t count = 0;
  struct EmptyOnError {
    pcl::PCLPointCloud2& chunk;
    bool done = false;
    ~EmptyOnError()
    {
      if (!done)
        chunk = pcl::PCLPointCloud2();
    }
  } guard{chunk};
  while (count < max_points) {
    if (block_next_ == block_points_ && !fillBlock())
      break;
    const std::size_t k = std::min (max_points - count, block_points_ - block_next_);
    data.resize ((count + k) * step);
    las::decodeRecords (layout,
                        decoding_->transform,
                        colour_shift_,
                        block_.data() + block_next_ * rl,
                        rl,
                        k,
                        data.data() + count * step);
    block_next_ += k;
    count += k;
  }
  points_read_ += count;
  chunk.header = pcl::PCLHeader();
  chunk.fields = layout.fields;
  chunk.point_step = static_cast<std::uint32_t> (step);
  chunk.width = static_cast<std::uint32_t> (count);
  chunk.height = 1;
  chunk.row_step = static_cast<std::uint32_t> (step * count);
  chunk.is_bigendian = false;
  chunk.is_dense = decoding_->finite;
  chunk.data = std::move (data);
  guard.done = true;
  return count;
}

void
loadLas (const std::string& path, pcl::PCLPointCloud2& cloud, LasFileInfo& info)
{
  LasReader reader;
  reader.open (path);
  const std::uint64_t n = reader.getPointCount();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw ReadError (path,
                     0,
                     std::to_string (n) +
                         " points do not fit one PCLPointCloud2 (read it in chunks)");
  pcl::PCLPointCloud2 whole;
  reader.read (static_cast<std::size_t> (n), whole);
  cloud = std::move (whole);
  info = reader.getFileInfo();
}
} // namespace io
} // namespace pcl_ext
