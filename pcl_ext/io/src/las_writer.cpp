/*
 * pcl_ext: uncompressed LAS files written from pcl::PCLPointCloud2 (ASPRS LAS 1.4 R15).
 */
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_writer.h>

#include "las_bytes.h"
#include "las_record_encoder.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <limits>

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
} // namespace

bool
saveLas (const std::string& path,
         const pcl::PCLPointCloud2& cloud,
         const Eigen::Vector3d& origin,
         const LasFileInfo* like)
{
  auto fail = [&path] (const std::string& reason) {
    PCL_ERROR ("[pcl_ext::io::saveLas] %s: %s\n", path.c_str(), reason.c_str());
    return false;
  };
  const std::uint64_t n = static_cast<std::uint64_t> (cloud.width) * cloud.height;
  if (cloud.data.size() < n * cloud.point_step)
    return fail ("the cloud's data is shorter than its " + std::to_string (n) +
                 " points");
  if (!origin.allFinite())
    return fail ("the origin is not finite");

  LasHeader h = like ? like->header : newHeader (cloud, origin);
  std::vector<LasVariableLengthRecord> vlrs = like ? like->vlrs : decltype (vlrs){};
  std::vector<LasVariableLengthRecord> evlrs;
  if (like && h.version_minor >= 4)
    evlrs = like->evlrs;
  const std::vector<std::uint8_t> pre_points =
      like ? like->pre_point_bytes : std::vector<std::uint8_t>{};
  h.point_format_byte = static_cast<std::uint8_t> (h.pointFormat());
  if (h.version_minor < 4 && n > std::numeric_limits<std::uint32_t>::max())
    return fail ("LAS 1." + std::to_string (h.version_minor) +
                 " cannot hold more than 2^32 - 1 points");

  las::RecordEncoder encoder;
  std::string error;
  if (!encoder.init (cloud, h.pointFormat(), h.scale, h.offset, origin, like, error))
    return fail (error);
  prepareVlrs (vlrs, encoder);
  std::vector<std::uint8_t> head_vlrs;
  for (const auto& vlr : vlrs) {
    if (vlr.data.size() > 65535)
      return fail ("VLR \"" + vlr.user_id + "\" " + std::to_string (vlr.record_id) +
                   " exceeds 65535 bytes");
    const auto bytes = vlrBytes (vlr);
    head_vlrs.insert (head_vlrs.end(), bytes.begin(), bytes.end());
  }
  head_vlrs.insert (head_vlrs.end(), pre_points.begin(), pre_points.end());
  h.record_length = static_cast<std::uint16_t> (encoder.recordLength());
  h.number_of_vlrs = static_cast<std::uint32_t> (vlrs.size());
  h.waveform_data_start = 0; // waveform data is not written
  h.global_encoding &= static_cast<std::uint16_t> (~2u);
  const std::size_t header_size = encodeLasHeader (h).size();
  const std::uint64_t offset = header_size + head_vlrs.size();
  if (offset > std::numeric_limits<std::uint32_t>::max())
    return fail ("the VLRs do not fit before a 32-bit offset to point data");
  h.offset_to_point_data = static_cast<std::uint32_t> (offset);
  h.evlr_count = static_cast<std::uint32_t> (evlrs.size());
  h.evlr_start = evlrs.empty() ? 0 : offset + n * h.record_length;

  const bool written = writeFileAtomically (path, [&] (const std::string& temporary) {
    std::ofstream out (temporary, std::ios::binary);
    const auto header = encodeLasHeader (h); // counts and bounds follow at the end
    out.write (reinterpret_cast<const char*> (header.data()), header.size());
    out.write (reinterpret_cast<const char*> (head_vlrs.data()), head_vlrs.size());
    const std::size_t rl = h.record_length;
    const bool legacy_format = h.pointFormat() <= 5;
    std::vector<std::uint8_t> block (kBlockPoints * rl);
    std::array<std::int64_t, 3> lo, hi;
    lo.fill (std::numeric_limits<std::int64_t>::max());
    hi.fill (std::numeric_limits<std::int64_t>::min());
    std::array<std::uint64_t, 15> by_return{};
    std::array<std::int32_t, 3> xyz;
    for (std::uint64_t first = 0; first < n && out; first += kBlockPoints) {
      const std::size_t k =
          static_cast<std::size_t> (std::min<std::uint64_t> (kBlockPoints, n - first));
      for (std::size_t i = 0; i < k; ++i) {
        std::uint8_t* record = block.data() + i * rl;
        if (!encoder.encode (cloud.data.data() + (first + i) * cloud.point_step,
                             record,
                             xyz,
                             error)) {
          error = "point " + std::to_string (first + i) + ": " + error;
          return false;
        }
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min<std::int64_t> (lo[a], xyz[a]);
          hi[a] = std::max<std::int64_t> (hi[a], xyz[a]);
        }
        const int r = legacy_format ? record[14] & 0x07 : record[14] & 0x0F;
        if (r >= 1)
          ++by_return[r - 1];
      }
      out.write (reinterpret_cast<const char*> (block.data()), k * rl);
    }
    for (const auto& evlr : evlrs) {
      LasVariableLengthRecord e = evlr;
      e.extended = true;
      const auto bytes = vlrBytes (e);
      out.write (reinterpret_cast<const char*> (bytes.data()), bytes.size());
    }
    finishHeader (h, n, lo, hi, by_return);
    const auto final_header = encodeLasHeader (h);
    out.seekp (0);
    out.write (reinterpret_cast<const char*> (final_header.data()),
               final_header.size());
    out.close();
    return static_cast<bool> (out);
  });
  if (!written && !error.empty())
    return fail (error);
  return written;
}
} // namespace io
} // namespace pcl_ext
