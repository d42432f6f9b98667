/*
 * pcl_ext: uncompressed LAS files written from pcl::PCLPointCloud2 (ASPRS LAS 1.4 R15).
 */
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_writer.h>

#include "las_bytes.h"
#include "las_record_encoder.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <array>
#include <ctime>
#include <fstream>
#include <limits>
#include <memory>

namespace pcl_ext {
namespace io {
namespace {
constexpr std::size_t kBlockPoints = 8192;

bool
hasField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  return std::any_of (cloud.fields.begin(),
                      cloud.fields.end(),
                      [&name] (const pcl::PCLPointField& f) { return f.name == name; });
}

/** The header of a new LAS 1.4 file for \a cloud (no \a like). */
LasHeader
newHeader (const pcl::PCLPointCloud2& cloud, const Eigen::Vector3d& origin)
{
  LasHeader h;
  const bool colour = hasField (cloud, "rgb") ||
                      (hasField (cloud, "red") && hasField (cloud, "green") &&
                       hasField (cloud, "blue"));
  h.point_format_byte = hasField (cloud, "nir") ? 8 : colour ? 7 : 6;
  h.version_major = 1;
  h.version_minor = 4;
  h.header_size = 375;
  h.global_encoding = 16; // the CRS, if any, is WKT (required of formats 6-10)
  h.system_identifier = "OTHER";
  h.generating_software = "pcl_ext";
  const std::time_t now = std::time (nullptr);
  std::tm utc{};
  if (gmtime_r (&now, &utc)) {
    h.creation_day = static_cast<std::uint16_t> (utc.tm_yday + 1);
    h.creation_year = static_cast<std::uint16_t> (utc.tm_year + 1900);
  }
  h.scale = Eigen::Vector3d::Constant (0.001);
  h.offset = origin;
  return h;
}

/** Sets the VLR list: no LASzip record, the extra-bytes record as \a encoder needs. */
void
prepareVlrs (std::vector<LasVariableLengthRecord>& vlrs,
             const las::RecordEncoder& encoder)
{
  vlrs.erase (std::remove_if (vlrs.begin(), vlrs.end(), isLaszipRecord), vlrs.end());
  auto extra = std::find_if (vlrs.begin(), vlrs.end(), isExtraBytesRecord);
  if (encoder.descriptors().empty()) {
    if (extra != vlrs.end())
      vlrs.erase (extra);
    return;
  }
  if (extra != vlrs.end() && encoder.keepsLikeDescriptors())
    return;
  LasVariableLengthRecord vlr;
  vlr.user_id = "LASF_Spec";
  vlr.record_id = 4;
  vlr.description = "Extra Bytes Record";
  vlr.data = encodeExtraBytes (encoder.descriptors());
  if (extra != vlrs.end())
    *extra = std::move (vlr);
  else
    vlrs.push_back (std::move (vlr));
}

std::vector<std::uint8_t>
vlrBytes (const LasVariableLengthRecord& vlr)
{
  std::vector<std::uint8_t> out (vlr.extended ? 60 : 54);
  las::put (out.data(), vlr.reserved);
  las::putString (out.data() + 2, 16, vlr.user_id);
  las::put (out.data() + 18, vlr.record_id);
  std::size_t description = 22;
  if (vlr.extended) {
    las::put (out.data() + 20, static_cast<std::uint64_t> (vlr.data.size()));
    description = 28;
  }
  else
    las::put (out.data() + 20, static_cast<std::uint16_t> (vlr.data.size()));
  las::putString (out.data() + description, 32, vlr.description);
  out.insert (out.end(), vlr.data.begin(), vlr.data.end());
  return out;
}

/** The header counts, bounds and offsets for the points written. */
void
finishHeader (LasHeader& h,
              std::uint64_t n,
              const std::array<std::int64_t, 3>& lo,
              const std::array<std::int64_t, 3>& hi,
              const std::array<std::uint64_t, 15>& by_return)
{
  for (int a = 0; a < 3; ++a) {
    h.min[a] = n == 0 ? 0.0 : static_cast<double> (lo[a]) * h.scale[a] + h.offset[a];
    h.max[a] = n == 0 ? 0.0 : static_cast<double> (hi[a]) * h.scale[a] + h.offset[a];
  }
  h.point_count = n;
  h.points_by_return = by_return;
  const bool legacy =
      h.version_minor < 4 ||
      (h.pointFormat() <= 5 && n <= std::numeric_limits<std::uint32_t>::max());
  h.legacy_point_count = legacy ? static_cast<std::uint32_t> (n) : 0;
  for (std::size_t r = 0; r < 5; ++r)
    h.legacy_points_by_return[r] =
        legacy ? static_cast<std::uint32_t> (by_return[r]) : 0;
}

bool
fail (const std::string& path, const std::string& reason)
{
  PCL_ERROR ("[pcl_ext::io::LasWriter] %s: %s\n", path.c_str(), reason.c_str());
  return false;
}

bool
sameFields (const pcl::PCLPointCloud2& a, const pcl::PCLPointCloud2& b)
{
  if (a.point_step != b.point_step || a.fields.size() != b.fields.size())
    return false;
  for (std::size_t i = 0; i < a.fields.size(); ++i)
    if (a.fields[i].name != b.fields[i].name ||
        a.fields[i].offset != b.fields[i].offset ||
        a.fields[i].datatype != b.fields[i].datatype ||
        a.fields[i].count != b.fields[i].count)
      return false;
  return true;
}
} // namespace

struct LasWriter::State {
  std::string path;
  AtomicFileOutput output;
  std::ofstream out;
  pcl::PCLPointCloud2 layout; ///< fields only
  LasHeader header;
  std::vector<LasVariableLengthRecord> evlrs;
  las::RecordEncoder encoder;
  std::vector<std::uint8_t> block;
  std::array<std::int64_t, 3> lo, hi;
  std::array<std::uint64_t, 15> by_return{};
  std::uint64_t written = 0;
  bool failed = false;
};

LasWriter::LasWriter() = default;

LasWriter::~LasWriter() = default;

bool
LasWriter::open (const std::string& path,
                 const pcl::PCLPointCloud2& layout,
                 const Eigen::Vector3d& origin,
                 const LasFileInfo* like)
{
  state_.reset();
  if (!origin.allFinite())
    return fail (path, "the origin is not finite");
  auto s = std::make_unique<State>();
  s->path = path;
  s->layout.fields = layout.fields;
  s->layout.point_step = layout.point_step;
  s->layout.is_bigendian = layout.is_bigendian;
  LasHeader& h = s->header;
  h = like ? like->header : newHeader (layout, origin);
  std::vector<LasVariableLengthRecord> vlrs = like ? like->vlrs : decltype (vlrs){};
  if (like && h.version_minor >= 4)
    s->evlrs = like->evlrs;
  const std::vector<std::uint8_t> pre_points =
      like ? like->pre_point_bytes : std::vector<std::uint8_t>{};
  h.point_format_byte = static_cast<std::uint8_t> (h.pointFormat());

  std::string error;
  if (!s->encoder.init (
          layout, h.pointFormat(), h.scale, h.offset, origin, like, error))
    return fail (path, error);
  prepareVlrs (vlrs, s->encoder);
  std::vector<std::uint8_t> head_vlrs;
  for (const auto& vlr : vlrs) {
    if (vlr.data.size() > 65535)
      return fail (path,
                   "VLR \"" + vlr.user_id + "\" " + std::to_string (vlr.record_id) +
                       " exceeds 65535 bytes");
    const auto bytes = vlrBytes (vlr);
    head_vlrs.insert (head_vlrs.end(), bytes.begin(), bytes.end());
  }
  head_vlrs.insert (head_vlrs.end(), pre_points.begin(), pre_points.end());
  h.record_length = static_cast<std::uint16_t> (s->encoder.recordLength());
  h.number_of_vlrs = static_cast<std::uint32_t> (vlrs.size());
  h.waveform_data_start = 0; // waveform data is not written
  h.global_encoding &= static_cast<std::uint16_t> (~2u);
  const std::size_t header_size = encodeLasHeader (h).size();
  const std::uint64_t offset = header_size + head_vlrs.size();
  if (offset > std::numeric_limits<std::uint32_t>::max())
    return fail (path, "the VLRs do not fit before a 32-bit offset to point data");
  h.offset_to_point_data = static_cast<std::uint32_t> (offset);
  h.evlr_count = static_cast<std::uint32_t> (s->evlrs.size());

  if (!s->output.open (path))
    return false;
  s->out.open (s->output.getTemporaryPath(), std::ios::binary);
  const auto header = encodeLasHeader (h); // counts and bounds follow in close()
  s->out.write (reinterpret_cast<const char*> (header.data()), header.size());
  s->out.write (reinterpret_cast<const char*> (head_vlrs.data()), head_vlrs.size());
  if (!s->out)
    return fail (path, "cannot write the temporary file");
  s->block.resize (kBlockPoints * h.record_length);
  s->lo.fill (std::numeric_limits<std::int64_t>::max());
  s->hi.fill (std::numeric_limits<std::int64_t>::min());
  state_ = std::move (s);
  return true;
}

bool
LasWriter::write (const pcl::PCLPointCloud2& chunk)
{
  if (!state_)
    return fail ("", "no file is open");
  State& s = *state_;
  if (s.failed)
    return false;
  s.failed = true; // until this chunk is written
  if (!sameFields (chunk, s.layout))
    return fail (s.path, "a chunk's fields differ from those given to open()");
  const std::uint64_t n = static_cast<std::uint64_t> (chunk.width) * chunk.height;
  if (chunk.data.size() < n * chunk.point_step)
    return fail (s.path,
                 "the chunk's data is shorter than its " + std::to_string (n) +
                     " points");
  const std::size_t rl = s.header.record_length;
  const bool legacy_format = s.header.pointFormat() <= 5;
  std::array<std::int32_t, 3> xyz;
  std::string error;
  for (std::uint64_t first = 0; first < n; first += kBlockPoints) {
    const std::size_t k =
        static_cast<std::size_t> (std::min<std::uint64_t> (kBlockPoints, n - first));
    for (std::size_t i = 0; i < k; ++i) {
      std::uint8_t* record = s.block.data() + i * rl;
      if (!s.encoder.encode (
              chunk.data.data() + (first + i) * chunk.point_step, record, xyz, error))
        return fail (s.path,
                     "point " + std::to_string (s.written + first + i) + ": " + error);
      for (int a = 0; a < 3; ++a) {
        s.lo[a] = std::min<std::int64_t> (s.lo[a], xyz[a]);
        s.hi[a] = std::max<std::int64_t> (s.hi[a], xyz[a]);
      }
      const int r = legacy_format ? record[14] & 0x07 : record[14] & 0x0F;
      if (r >= 1)
        ++s.by_return[r - 1];
    }
    s.out.write (reinterpret_cast<const char*> (s.block.data()), k * rl);
    if (!s.out)
      return fail (s.path, "cannot write the points (disk full?)");
  }
  s.written += n;
  s.failed = false;
  return true;
}

bool
LasWriter::close()
{
  if (!state_)
    return fail ("", "no file is open");
  std::unique_ptr<State> s = std::move (state_);
  if (s->failed)
    return false;
  LasHeader& h = s->header;
  const std::uint64_t n = s->written;
  if (h.version_minor < 4 && n > std::numeric_limits<std::uint32_t>::max())
    return fail (s->path,
                 "LAS 1." + std::to_string (h.version_minor) +
                     " cannot hold more than 2^32 - 1 points");
  h.evlr_start = s->evlrs.empty() ? 0 : h.offset_to_point_data + n * h.record_length;
  for (const auto& evlr : s->evlrs) {
    LasVariableLengthRecord e = evlr;
    e.extended = true;
    const auto bytes = vlrBytes (e);
    s->out.write (reinterpret_cast<const char*> (bytes.data()), bytes.size());
  }
  finishHeader (h, n, s->lo, s->hi, s->by_return);
  const auto final_header = encodeLasHeader (h);
  s->out.seekp (0);
  s->out.write (reinterpret_cast<const char*> (final_header.data()),
                final_header.size());
  s->out.close();
  if (!s->out)
    return fail (s->path, "cannot finish the file (disk full?)");
  return s->output.commit();
}

std::uint64_t
LasWriter::getPointsWritten() const
{
  return state_ ? state_->written : 0;
}

bool
saveLas (const std::string& path,
         const pcl::PCLPointCloud2& cloud,
         const Eigen::Vector3d& origin,
         const LasFileInfo* like)
{
  LasWriter writer;
  return writer.open (path, cloud, origin, like) && writer.write (cloud) &&
         writer.close();
}
} // namespace io
} // namespace pcl_ext
