/*
 * saveLas: every point format written back byte for byte, new files from PCL clouds,
 * the integer round trip of georeferenced coordinates, extra bytes, header counts, the
 * refusals, and LasWriter's chunks.
 */
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/las_writer.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include "las_test_files.h"
#include "temp_folder.h"
#include "test_helpers.h"

#include <algorithm>
#include <cmath>

using las_test::get;
using las_test::value;
using pcl_ext::io::LasFileInfo;

namespace {
const std::string&
writerFolder ()
{
  static const std::string dir = freshFolder ("las_writer");
  return dir;
}

std::string
pathOf (const std::string& name)
{
  return writerFolder() + "/" + name;
}

struct Loaded {
  pcl::PCLPointCloud2 cloud;
  LasFileInfo info;
};

Loaded
load (const std::string& path)
{
  Loaded l;
  pcl_ext::io::loadLas (path, l.cloud, l.info);
  return l;
}

/** The point records of a LAS file as stored. */
std::vector<std::uint8_t>
records (const std::string& path)
{
  const auto b = las_test::readBytes (path);
  const auto offset = get<std::uint32_t> (&b[96]);
  const auto length = get<std::uint16_t> (&b[105]);
  const std::uint64_t count =
      b[25] >= 4 ? get<std::uint64_t> (&b[247]) : get<std::uint32_t> (&b[107]);
  return std::vector<std::uint8_t> (b.begin() + offset,
                                    b.begin() + offset + count * length);
}

void
removeField (pcl::PCLPointCloud2& cloud, const std::string& name)
{
  for (auto f = cloud.fields.begin(); f != cloud.fields.end(); ++f)
    if (f->name == name) {
      cloud.fields.erase (f);
      return;
    }
}
} // namespace

TEST (LasWriter, EveryPointFormatWritesItsRecordsBack)
{
  for (int format = 0; format <= 10; ++format) {
    SCOPED_TRACE ("format " + std::to_string (format));
    las_test::LasFile f;
    f.format_byte = static_cast<std::uint8_t> (format);
    f.minor = format <= 5 ? 2 : 4;
    // A scaled extra-bytes dimension, then three bytes no descriptor covers.
    f.record_length =
        static_cast<std::uint16_t> (pcl_ext::io::lasPointRecordLength (format) + 2 + 3);
    f.vlrs.push_back ({"LASF_Projection", 2112, "WKT", {'W', 'K', 'T', 0}});
    f.vlrs.push_back (
        {"LASF_Spec",
         4,
         "Extra Bytes Record",
         las_test::extraBytesDescriptor (3, "height", 0x18, 0.01, 100.0)});
    f.randomRecords (300, 40 + format);
    const std::string in = pathOf ("in" + std::to_string (format) + ".las");
    las_test::writeBytes (in, f.bytes());
    const Loaded a = load (in);

    const std::string out = pathOf ("out" + std::to_string (format) + ".las");
    ASSERT_TRUE (pcl_ext::io::saveLas (out, a.cloud, a.info.origin, &a.info));
    EXPECT_TRUE (records (out) == f.records);
    const Loaded b = load (out);
    EXPECT_EQ (b.info.header.version_minor, f.minor);
    EXPECT_EQ (b.info.header.pointFormat(), format);
    EXPECT_EQ (b.info.header.record_length, f.record_length);
    ASSERT_EQ (b.info.vlrs.size(), 2u);
    for (std::size_t v = 0; v < 2; ++v) {
      EXPECT_EQ (b.info.vlrs[v].user_id, a.info.vlrs[v].user_id);
      EXPECT_EQ (b.info.vlrs[v].description, a.info.vlrs[v].description);
      EXPECT_EQ (b.info.vlrs[v].data, a.info.vlrs[v].data);
    }
    EXPECT_EQ (b.info.header.system_identifier, "TEST SYSTEM");
    EXPECT_EQ (b.info.header.point_count, 300u);
    // Read with the first file's origin (the new header's box is the points' own).
    pcl_ext::io::LasReader reader;
    reader.open (out);
    reader.setOrigin (a.info.origin);
    pcl::PCLPointCloud2 again;
    reader.read (300, again);
    EXPECT_TRUE (again.data == a.cloud.data);
  }
}

TEST (LasWriter, NewFileFromPclClouds)
{
  pcl::PointCloud<pcl::PointXYZRGB> rgb;
  for (int i = 0; i < 5; ++i) {
    pcl::PointXYZRGB p (static_cast<std::uint8_t> (50 * i), 7, 255);
    p.x = 1.25f * i;
    p.y = -2.0f;
    p.z = 0.0004f * i;
    rgb.push_back (p);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (rgb, blob);
  const Eigen::Vector3d origin (100000, 200000, 10);
  const std::string path = pathOf ("rgb.las");
  ASSERT_TRUE (pcl_ext::io::saveLas (path, blob, origin));
  const Loaded l = load (path);
  const auto& h = l.info.header;
  EXPECT_EQ (h.version_minor, 4);
  EXPECT_EQ (h.pointFormat(), 7);
  EXPECT_EQ (h.global_encoding, 16);
  EXPECT_EQ (h.scale, Eigen::Vector3d::Constant (0.001));
  EXPECT_EQ (h.offset, origin);
  EXPECT_EQ (h.point_count, 5u);
  EXPECT_EQ (h.legacy_point_count, 0u);
  EXPECT_EQ (h.points_by_return[0], 5u); // return number 1 when absent
  EXPECT_EQ (h.min, Eigen::Vector3d (100000, 199998, 10));
  EXPECT_EQ (h.max.x(), 100005.0);
  EXPECT_DOUBLE_EQ (h.max.z(), 10.002);
  EXPECT_TRUE (l.info.vlrs.empty());
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ (value<std::int32_t> (l.cloud, "las_x", i), 1250 * i);
    EXPECT_EQ (value<std::int32_t> (l.cloud, "las_z", i), std::lround (0.4 * i));
    EXPECT_EQ (value<std::uint16_t> (l.cloud, "red", i), 50 * i * 257);
    EXPECT_EQ (value<std::uint16_t> (l.cloud, "blue", i), 65535);
  }
  pcl::PointCloud<pcl::PointXYZRGB> back;
  pcl::fromPCLPointCloud2 (l.cloud, back);
  EXPECT_EQ (back[4].r, 200);
  EXPECT_EQ (back[4].g, 7);

  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.push_back (pcl::PointXYZ (1, 2, 3));
  pcl::toPCLPointCloud2 (xyz, blob);
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("xyz.las"), blob, Eigen::Vector3d::Zero()));
  EXPECT_EQ (load (pathOf ("xyz.las")).info.header.pointFormat(), 6);
  pcl::PCLPointField nir;
  nir.name = "nir";
  nir.offset = 12;
  nir.datatype = pcl::PCLPointField::UINT16;
  nir.count = 1;
  blob.fields.push_back (nir);
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("nir.las"), blob, Eigen::Vector3d::Zero()));
  EXPECT_EQ (load (pathOf ("nir.las")).info.header.pointFormat(), 8);
}

TEST (LasWriter, UtmCoordinatesKeepTheirIntegers)
{
  las_test::LasFile f;
  f.minor = 2;
  f.format_byte = 1;
  f.record_length = 28;
  f.scale[0] = f.scale[1] = f.scale[2] = 0.001;
  f.offset[0] = 500000;
  f.offset[1] = 6000000;
  f.min[0] = 499000;
  f.max[0] = 501000;
  f.min[1] = 5999000;
  f.max[1] = 6001000;
  f.randomRecords (1000, 5);
  std::mt19937 rng (9);
  for (std::size_t i = 0; i < 1000; ++i) // within +-1 km of the offset
    for (std::size_t a = 0; a < 3; ++a)
      las_test::put<std::int32_t> (f.records,
                                   i * 28 + 4 * a,
                                   static_cast<std::int32_t> (rng() % 2000000) -
                                       1000000);
  const std::string in = pathOf ("utm.las");
  las_test::writeBytes (in, f.bytes());
  Loaded a = load (in);
  EXPECT_EQ (a.info.origin, Eigen::Vector3d (500000, 6000000, 0));
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("utm_out.las"), a.cloud, a.info.origin, &a.info));
  EXPECT_TRUE (records (pathOf ("utm_out.las")) == f.records);

  // Without the record integers the millimetres are recomputed from float x y z: at
  // +-1 km a float holds them, so the integers are the same.
  removeField (a.cloud, "las_x");
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("utm_float.las"), a.cloud, a.info.origin, &a.info));
  EXPECT_TRUE (records (pathOf ("utm_float.las")) == f.records);

  // A moved point gets new integers; the others keep theirs.
  const pcl::PCLPointField* x = las_test::field (a.cloud, "x");
  float moved = get<float> (&a.cloud.data[x->offset]) + 1.0f;
  std::memcpy (&a.cloud.data[x->offset], &moved, 4);
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("utm_moved.las"), a.cloud, a.info.origin, &a.info));
  const Loaded b = load (pathOf ("utm_moved.las"));
  EXPECT_EQ (value<std::int32_t> (b.cloud, "las_x", 0),
             get<std::int32_t> (&f.records[0]) + 1000);
  EXPECT_EQ (value<std::int32_t> (b.cloud, "las_x", 1),
             get<std::int32_t> (&f.records[28]));
}

TEST (LasWriter, FineScaleKeepsItsIntegersOnlyThroughTheRecordIntegers)
{
  las_test::LasFile f;
  f.minor = 4;
  f.format_byte = 6;
  f.record_length = 30;
  f.scale[0] = f.scale[1] = f.scale[2] = 1e-6;
  f.offset[0] = 1700000;
  f.offset[1] = 1800000;
  f.randomRecords (500, 6); // +-2147 m at a micrometre: more digits than a float holds
  const std::string in = pathOf ("fine.las");
  las_test::writeBytes (in, f.bytes());
  Loaded a = load (in);
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("fine_out.las"), a.cloud, a.info.origin, &a.info));
  EXPECT_TRUE (records (pathOf ("fine_out.las")) == f.records);

  removeField (a.cloud, "las_y");
  ASSERT_TRUE (pcl_ext::io::saveLas (
      pathOf ("fine_float.las"), a.cloud, a.info.origin, &a.info));
  const auto r = records (pathOf ("fine_float.las"));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < 500; ++i) {
    const auto y = get<std::int32_t> (&r[i * 30 + 4]);
    const auto y0 = get<std::int32_t> (&f.records[i * 30 + 4]);
    const double local = std::abs (y0 * 1e-6 + 1800000 - a.info.origin.y());
    // Recomputed from float: within half a float step of the original.
    EXPECT_LE (std::abs (y - y0) * 1e-6, std::ldexp (local, -24) + 1e-6);
    differ += y != y0;
    EXPECT_EQ (get<std::int32_t> (&r[i * 30]), get<std::int32_t> (&f.records[i * 30]));
  }
  EXPECT_GT (differ, 0u); // the float alone would not have kept them
}

TEST (LasWriter, ExtraBytesFromFields)
{
  las_test::LasFile f;
  f.minor = 4;
  f.format_byte = 0;
  f.record_length = 21;
  f.vlrs.push_back ({"LASF_Spec",
                     4,
                     "Extra Bytes Record",
                     las_test::extraBytesDescriptor (2, "tag")});
  f.randomRecords (4, 8);
  las_test::writeBytes (pathOf ("eb.las"), f.bytes());
  Loaded a = load (pathOf ("eb.las"));

  // A new field: the descriptor of "tag" is kept, "label" is added after it.
  pcl::PCLPointCloud2 labelled;
  pcl::PointCloud<pcl::Label> labels;
  for (std::uint32_t i = 0; i < 4; ++i)
    labels.push_back (pcl::Label{});
  for (std::uint32_t i = 0; i < 4; ++i)
    labels[i].label = 1000 + i;
  pcl::toPCLPointCloud2 (labels, labelled);
  pcl::PCLPointCloud2 both;
  pcl::concatenateFields (a.cloud, labelled, both);
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("eb_label.las"), both, a.info.origin, &a.info));
  const Loaded b = load (pathOf ("eb_label.las"));
  ASSERT_EQ (b.info.extra_bytes.size(), 2u);
  EXPECT_EQ (b.info.extra_bytes[0].name, "tag");
  EXPECT_EQ (b.info.extra_bytes[0].description, "test tag");
  EXPECT_EQ (b.info.extra_bytes[1].name, "label");
  EXPECT_EQ (b.info.extra_bytes[1].data_type, 5); // unsigned long
  EXPECT_EQ (b.info.header.record_length, 25);
  ASSERT_EQ (b.info.vlrs.size(), 1u); // replaced in place
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ (value<std::uint32_t> (b.cloud, "label", i), 1000 + i);
    EXPECT_EQ (value<std::int8_t> (b.cloud, "tag", i),
               value<std::int8_t> (a.cloud, "tag", i));
  }

  // Arrays: 3 x uint16 as the deprecated type 23, 5 x uint8 as undocumented bytes.
  pcl::PCLPointCloud2 arrays = a.cloud;
  removeField (arrays, "tag");
  const std::uint32_t at = arrays.point_step;
  arrays.point_step += 16;
  std::vector<std::uint8_t> data;
  for (std::size_t i = 0; i < 4; ++i) {
    data.insert (
        data.end(), a.cloud.data.begin() + i * at, a.cloud.data.begin() + (i + 1) * at);
    for (std::uint8_t k = 0; k < 16; ++k)
      data.push_back (static_cast<std::uint8_t> (10 * i + k));
  }
  arrays.data = data;
  arrays.row_step = arrays.point_step * 4;
  arrays.fields.push_back ({"triple", at, pcl::PCLPointField::UINT16, 3});
  arrays.fields.push_back ({"bytes", at + 6, pcl::PCLPointField::UINT8, 5});
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("eb_arrays.las"), arrays, a.info.origin, &a.info));
  const Loaded c = load (pathOf ("eb_arrays.las"));
  ASSERT_EQ (c.info.extra_bytes.size(), 2u);
  EXPECT_EQ (c.info.extra_bytes[0].data_type, 23);
  EXPECT_EQ (c.info.extra_bytes[1].data_type, 0);
  EXPECT_EQ (c.info.extra_bytes[1].options, 5);
  EXPECT_EQ (value<std::uint16_t> (c.cloud, "triple", 3, 2), (35 << 8) | 34);
  EXPECT_EQ (value<std::uint8_t> (c.cloud, "bytes", 2, 4), 30);

  // No field left: the extra-bytes record goes.
  pcl::PCLPointCloud2 plain = a.cloud;
  removeField (plain, "tag");
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pathOf ("eb_none.las"), plain, a.info.origin, &a.info));
  EXPECT_TRUE (load (pathOf ("eb_none.las")).info.vlrs.empty());
  EXPECT_EQ (load (pathOf ("eb_none.las")).info.header.record_length, 20);

  // A count no extra-bytes type holds.
  arrays.fields.back() = {"floats", at, pcl::PCLPointField::FLOAT32, 4};
  EXPECT_FALSE (
      pcl_ext::io::saveLas (pathOf ("eb_refused.las"), arrays, a.info.origin, &a.info));
}

TEST (LasWriter, CountsPerReturnAndLegacyFields)
{
  las_test::LasFile f;
  f.minor = 3;
  f.format_byte = 1;
  f.record_length = 28;
  f.randomRecords (200, 12);
  las_test::writeBytes (pathOf ("returns.las"), f.bytes());
  const Loaded a = load (pathOf ("returns.las"));
  ASSERT_TRUE (pcl_ext::io::saveLas (
      pathOf ("returns_out.las"), a.cloud, a.info.origin, &a.info));
  const auto& h = load (pathOf ("returns_out.las")).info.header;
  std::array<std::uint32_t, 5> expected{};
  for (std::size_t i = 0; i < 200; ++i) {
    const int r = f.records[i * 28 + 14] & 7;
    if (r >= 1 && r <= 5)
      ++expected[r - 1];
  }
  EXPECT_EQ (h.legacy_point_count, 200u);
  EXPECT_EQ (h.legacy_points_by_return, expected);
  EXPECT_EQ (h.waveform_data_start, 0u);
  // The bounds are those of the integers written.
  std::int32_t lo = INT32_MAX;
  for (std::size_t i = 0; i < 200; ++i)
    lo = std::min (lo, get<std::int32_t> (&f.records[i * 28 + 8]));
  EXPECT_EQ (h.min.z(), lo * 0.01);
}

TEST (LasWriter, DropsCompressionAndTheLaszipRecord)
{
  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.push_back (pcl::PointXYZ (1, 2, 3));
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (xyz, blob);
  LasFileInfo like;
  like.header.version_minor = 2;
  like.header.header_size = 227;
  like.header.point_format_byte = 0x83;
  like.header.record_length = 34;
  like.vlrs.push_back ({0, "laszip encoded", 22204, "", {1, 2, 3}, false});
  like.vlrs.push_back ({0, "LASF_Projection", 34735, "GeoKeys", {4, 5}, false});
  ASSERT_TRUE (pcl_ext::io::saveLas (
      pathOf ("unzipped.las"), blob, Eigen::Vector3d::Zero(), &like));
  const Loaded l = load (pathOf ("unzipped.las"));
  EXPECT_EQ (l.info.header.point_format_byte, 3);
  EXPECT_FALSE (l.info.header.isCompressed());
  ASSERT_EQ (l.info.vlrs.size(), 1u);
  EXPECT_EQ (l.info.vlrs[0].record_id, 34735);
  EXPECT_EQ (value<std::int32_t> (l.cloud, "las_y", 0), 2000); // 0.001 m
}

TEST (LasWriter, Refusals)
{
  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.push_back (pcl::PointXYZ (1, 2, 3));
  xyz.push_back (pcl::PointXYZ (3e6f, 2, 3)); // 3e9 mm: beyond int32
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (xyz, blob);
  const std::string path = pathOf ("refused.las");
  pcl_ext::io::writeTextFile (path, "previous");
  EXPECT_FALSE (pcl_ext::io::saveLas (path, blob, Eigen::Vector3d::Zero()));
  EXPECT_EQ (readAll (path), "previous"); // nothing written
  // A new file's offset is the origin: the local coordinates are what must fit.
  EXPECT_FALSE (pcl_ext::io::saveLas (path, blob, Eigen::Vector3d (-2.9e6, 0, 0)));
  // With a file's scale and offset, the origin counts.
  LasFileInfo like;
  like.header.offset = Eigen::Vector3d (3e6, 0, 0);
  EXPECT_TRUE (pcl_ext::io::saveLas (
      pathOf ("shifted.las"), blob, Eigen::Vector3d (1e6, 0, 0), &like));
  EXPECT_EQ (load (pathOf ("shifted.las")).info.header.max.x(), 4e6);
  xyz[1].x =
      std::nanf (""); // an organised cloud's missing point: a message that says so
  pcl::toPCLPointCloud2 (xyz, blob);
  ::testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::io::saveLas (path, blob, Eigen::Vector3d::Zero()));
  const std::string nan_error = ::testing::internal::GetCapturedStderr();
  EXPECT_NE (nan_error.find ("coordinate x is not a number"), std::string::npos)
      << nan_error;
  xyz[1].x = 0.0f;
  pcl::toPCLPointCloud2 (xyz, blob);
  EXPECT_FALSE (
      pcl_ext::io::saveLas (pathOf ("no_folder/a.las"), blob, Eigen::Vector3d::Zero()));
  pcl::PCLPointCloud2 outside = blob; // a field past the end of the point
  outside.fields.push_back (
      {"far", outside.point_step - 2, pcl::PCLPointField::UINT32, 1});
  EXPECT_FALSE (pcl_ext::io::saveLas (path, outside, Eigen::Vector3d::Zero()));
  removeField (blob, "x");
  EXPECT_FALSE (pcl_ext::io::saveLas (path, blob, Eigen::Vector3d::Zero()));
  EXPECT_EQ (readAll (path), "previous");
  const auto names = listFolder (writerFolder());
  for (const auto& n : names)
    EXPECT_EQ (n.find (".tmp"), std::string::npos) << n;
}

TEST (LasWriter, ChunksWriteTheFileSaveLasWrites)
{
  las_test::LasFile f;
  f.format_byte = 7;
  f.minor = 4;
  f.record_length = static_cast<std::uint16_t> (pcl_ext::io::lasPointRecordLength (7));
  f.vlrs.push_back ({"LASF_Projection", 2112, "WKT", {'W', 'K', 'T', 0}});
  f.randomRecords (2500, 7);
  const std::string in = pathOf ("chunks_in.las");
  las_test::writeBytes (in, f.bytes());
  const Loaded whole = load (in);
  ASSERT_TRUE (pcl_ext::io::saveLas (
      pathOf ("whole.las"), whole.cloud, whole.info.origin, &whole.info));

  pcl_ext::io::LasReader reader;
  reader.open (in);
  pcl::PCLPointCloud2 chunk;
  ASSERT_EQ (reader.read (1000, chunk), 1000u);
  pcl_ext::io::LasWriter writer;
  ASSERT_TRUE (writer.open (
      pathOf ("chunks.las"), chunk, reader.getOrigin(), &reader.getFileInfo()));
  do
    ASSERT_TRUE (writer.write (chunk));
  while (reader.read (1000, chunk) > 0);
  EXPECT_EQ (writer.getPointsWritten(), 2500u);
  const auto names = listFolder (writerFolder()); // nothing at the path before close()
  EXPECT_EQ (std::count (names.begin(), names.end(), "chunks.las"), 0);
  ASSERT_TRUE (writer.close());
  EXPECT_TRUE (las_test::readBytes (pathOf ("chunks.las")) ==
               las_test::readBytes (pathOf ("whole.las")));
  EXPECT_TRUE (records (pathOf ("chunks.las")) == f.records);
}

TEST (LasWriter, AnUnfinishedFileLeavesNothing)
{
  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.push_back (pcl::PointXYZ (1, 2, 3));
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (xyz, blob);
  const std::string dir = freshFolder ("las_writer_unfinished");
  const std::string path = dir + "/out.las";
  pcl_ext::io::writeTextFile (path, "previous");
  {
    pcl_ext::io::LasWriter abandoned; // destroyed without close()
    ASSERT_TRUE (abandoned.open (path, blob, Eigen::Vector3d::Zero()));
    ASSERT_TRUE (abandoned.write (blob));
  }
  pcl_ext::io::LasWriter writer;
  ASSERT_TRUE (writer.open (path, blob, Eigen::Vector3d::Zero()));
  pcl::PointCloud<pcl::PointXYZI> other;
  other.push_back (pcl::PointXYZI (1.0f));
  pcl::PCLPointCloud2 other_blob;
  pcl::toPCLPointCloud2 (other, other_blob);
  testing::internal::CaptureStderr();
  EXPECT_FALSE (writer.write (other_blob)); // other fields than open() was given
  EXPECT_FALSE (writer.write (blob));       // a failed writer stays failed
  EXPECT_FALSE (writer.close());
  pcl_ext::io::LasWriter never_opened;
  EXPECT_FALSE (never_opened.write (blob));
  EXPECT_FALSE (never_opened.close());
  testing::internal::GetCapturedStderr();
  EXPECT_EQ (readAll (path), "previous");
  EXPECT_EQ (listFolder (dir), std::vector<std::string>{"out.las"});
}
