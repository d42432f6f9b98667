/*
 * LasReader and loadLas on small files built in the test: every point format decoded
 * field by field against the specification's record layout, versions, VLRs and EVLRs,
 * extra bytes, chunked reading, the origin, colour, and malformed files.
 */
#include <pcl_ext/io/las_reader.h>

#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include "las_test_files.h"
#include "temp_folder.h"
#include "test_helpers.h"

#include <cmath>

using las_test::get;
using las_test::value;
using pcl_ext::io::LasFileInfo;
using pcl_ext::io::LasReader;

namespace {
const std::string&
folder ()
{
  static const std::string dir = freshFolder ("las_reader");
  return dir;
}

std::string
write (const std::string& name, const las_test::LasFile& f)
{
  const std::string path = folder() + "/" + name;
  las_test::writeBytes (path, f.bytes());
  return path;
}

las_test::LasFile
randomFile (std::uint8_t format, std::size_t n, std::size_t trailing = 0)
{
  las_test::LasFile f;
  f.format_byte = format;
  f.record_length = static_cast<std::uint16_t> (
      pcl_ext::io::lasPointRecordLength (format) + trailing);
  f.randomRecords (n, 17 + format);
  return f;
}

template <typename T>
void
expectBits (const pcl::PCLPointCloud2& cloud,
            const std::string& name,
            std::size_t i,
            const std::uint8_t* at)
{
  EXPECT_EQ (value<T> (cloud, name, i), get<T> (at)) << name << " of point " << i;
}

/** Checks every field of point \a i against record \a r, as LAS 1.4 R15 Tables 7-17
 * lay it out. */
void
expectPoint (const pcl::PCLPointCloud2& c,
             int format,
             std::size_t i,
             const std::uint8_t* r)
{
  for (int a = 0; a < 3; ++a) {
    const std::string axis (1, "xyz"[a]);
    const std::int32_t integer = get<std::int32_t> (r + 4 * a);
    EXPECT_EQ (value<std::int32_t> (c, "las_" + axis, i), integer);
    EXPECT_EQ (value<float> (c, axis, i), static_cast<float> (integer * 0.01)) << axis;
  }
  EXPECT_EQ (value<float> (c, "intensity", i), get<std::uint16_t> (r + 12));
  std::size_t end;
  if (format <= 5) {
    EXPECT_EQ (value<std::uint8_t> (c, "return_number", i), r[14] & 7);
    EXPECT_EQ (value<std::uint8_t> (c, "number_of_returns", i), (r[14] >> 3) & 7);
    EXPECT_EQ (value<std::uint8_t> (c, "scan_direction_flag", i), (r[14] >> 6) & 1);
    EXPECT_EQ (value<std::uint8_t> (c, "edge_of_flight_line", i), r[14] >> 7);
    EXPECT_EQ (value<std::uint8_t> (c, "classification", i), r[15] & 31);
    EXPECT_EQ (value<std::uint8_t> (c, "flags", i), r[15] >> 5);
    expectBits<std::int8_t> (c, "scan_angle_rank", i, r + 16);
    expectBits<std::uint8_t> (c, "user_data", i, r + 17);
    expectBits<std::uint16_t> (c, "point_source_id", i, r + 18);
    EXPECT_FALSE (las_test::hasField (c, "scanner_channel"));
    end = 20;
    if (format != 0 && format != 2) {
      expectBits<std::uint64_t> (c, "gps_time", i, r + 20); // bits: may be NaN
      end = 28;
    }
    else
      EXPECT_FALSE (las_test::hasField (c, "gps_time"));
  }
  else {
    EXPECT_EQ (value<std::uint8_t> (c, "return_number", i), r[14] & 15);
    EXPECT_EQ (value<std::uint8_t> (c, "number_of_returns", i), r[14] >> 4);
    EXPECT_EQ (value<std::uint8_t> (c, "flags", i), r[15] & 15);
    EXPECT_EQ (value<std::uint8_t> (c, "scanner_channel", i), (r[15] >> 4) & 3);
    EXPECT_EQ (value<std::uint8_t> (c, "scan_direction_flag", i), (r[15] >> 6) & 1);
    EXPECT_EQ (value<std::uint8_t> (c, "edge_of_flight_line", i), r[15] >> 7);
    expectBits<std::uint8_t> (c, "classification", i, r + 16);
    expectBits<std::uint8_t> (c, "user_data", i, r + 17);
    expectBits<std::int16_t> (c, "scan_angle", i, r + 18);
    expectBits<std::uint16_t> (c, "point_source_id", i, r + 20);
    expectBits<std::uint64_t> (c, "gps_time", i, r + 22);
    EXPECT_FALSE (las_test::hasField (c, "scan_angle_rank"));
    end = 30;
  }
  const bool colour = format == 2 || format == 3 || format == 5 || format == 7 ||
                      format == 8 || format == 10;
  if (colour) {
    expectBits<std::uint16_t> (c, "red", i, r + end);
    expectBits<std::uint16_t> (c, "green", i, r + end + 2);
    expectBits<std::uint16_t> (c, "blue", i, r + end + 4);
    // Random 16-bit colour: rgb holds the high bytes.
    const std::uint32_t rgb = (std::uint32_t (r[end + 1]) << 16) |
                              (std::uint32_t (r[end + 3]) << 8) | r[end + 5];
    EXPECT_EQ (value<std::uint32_t> (c, "rgb", i), rgb);
    end += 6;
  }
  else
    EXPECT_FALSE (las_test::hasField (c, "red"));
  if (format == 8 || format == 10) {
    expectBits<std::uint16_t> (c, "nir", i, r + end);
    end += 2;
  }
  if (format == 4 || format == 5 || format == 9 || format == 10) {
    expectBits<std::uint8_t> (c, "wave_packet_descriptor_index", i, r + end);
    expectBits<std::uint64_t> (c, "wave_packet_offset", i, r + end + 1);
    expectBits<std::uint32_t> (c, "wave_packet_size", i, r + end + 9);
    expectBits<std::uint32_t> (c, "wave_return_location", i, r + end + 13);
    expectBits<std::uint32_t> (c, "wave_x_t", i, r + end + 17);
    expectBits<std::uint32_t> (c, "wave_y_t", i, r + end + 21);
    expectBits<std::uint32_t> (c, "wave_z_t", i, r + end + 25);
    end += 29;
  }
  EXPECT_EQ (end, pcl_ext::io::lasPointRecordLength (format));
  // The three bytes no descriptor covers.
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ (value<std::uint8_t> (c, "extra_bytes", i, k), r[end + k]);
}
} // namespace

TEST (LasReader, EveryPointFormatFieldByField)
{
  for (int format = 0; format <= 10; ++format) {
    SCOPED_TRACE ("format " + std::to_string (format));
    const auto f = randomFile (static_cast<std::uint8_t> (format), 50, 3);
    const std::string path = write ("format" + std::to_string (format) + ".las", f);
    pcl::PCLPointCloud2 cloud;
    LasFileInfo info;
    pcl_ext::io::loadLas (path, cloud, info);
    ASSERT_EQ (cloud.width, 50u);
    ASSERT_EQ (cloud.height, 1u);
    ASSERT_EQ (cloud.data.size(), 50u * cloud.point_step);
    EXPECT_EQ (info.origin, Eigen::Vector3d::Zero()); // a box of zeros: local data
    EXPECT_EQ (info.header.pointFormat(), format);
    for (std::size_t i = 0; i < 50; ++i)
      expectPoint (cloud, format, i, f.records.data() + i * f.record_length);
  }
}

TEST (LasReader, EveryVersion)
{
  for (int minor = 0; minor <= 4; ++minor) {
    auto f = randomFile (1, 10);
    f.minor = minor;
    pcl::PCLPointCloud2 cloud;
    LasFileInfo info;
    pcl_ext::io::loadLas (
        write ("v" + std::to_string (minor) + ".las", f), cloud, info);
    EXPECT_EQ (info.header.version_minor, minor);
    ASSERT_EQ (cloud.width, 10u);
    expectBits<std::uint64_t> (cloud, "gps_time", 9, f.records.data() + 9 * 28 + 20);
  }
}

TEST (LasReader, RecordsAndPadding)
{
  auto f = randomFile (6, 4);
  f.vlrs.push_back ({"LASF_Projection", 2112, "WKT", {'G', 'E', 'O', 0}});
  f.vlrs.push_back ({"someone", 7, "", {}});
  f.evlrs.push_back ({"LASF_Spec", 65535, "waveform", std::vector<std::uint8_t> (99)});
  f.evlrs.push_back (
      {"big", 3, "an extended record", std::vector<std::uint8_t> (70000, 5)});
  LasReader reader;
  reader.open (write ("records.las", f));
  ASSERT_EQ (reader.getVariableLengthRecords().size(), 2u);
  const auto& wkt = reader.getVariableLengthRecords()[0];
  EXPECT_EQ (wkt.user_id, "LASF_Projection");
  EXPECT_EQ (wkt.record_id, 2112);
  EXPECT_EQ (wkt.description, "WKT");
  EXPECT_EQ (wkt.data, (std::vector<std::uint8_t>{'G', 'E', 'O', 0}));
  EXPECT_FALSE (wkt.extended);
  EXPECT_TRUE (reader.getVariableLengthRecords()[1].data.empty());
  // The waveform packets are not read; the other EVLR is.
  ASSERT_EQ (reader.getExtendedVariableLengthRecords().size(), 1u);
  const auto& big = reader.getExtendedVariableLengthRecords()[0];
  EXPECT_TRUE (big.extended);
  EXPECT_EQ (big.user_id, "big");
  EXPECT_EQ (big.description, "an extended record");
  EXPECT_EQ (big.data, std::vector<std::uint8_t> (70000, 5));
  EXPECT_EQ (reader.getPointCount(), 4u);

  // LAS 1.0 with the start-of-data bytes between the header and the points.
  auto old = randomFile (0, 2);
  old.minor = 0;
  auto bytes = old.bytes();
  bytes.insert (bytes.begin() + 227, {0xDD, 0xCC});
  las_test::put<std::uint32_t> (bytes, 96, 229);
  const std::string path = folder() + "/padded.las";
  las_test::writeBytes (path, bytes);
  pcl::PCLPointCloud2 cloud;
  LasFileInfo info;
  pcl_ext::io::loadLas (path, cloud, info);
  EXPECT_EQ (info.pre_point_bytes, (std::vector<std::uint8_t>{0xDD, 0xCC}));
  ASSERT_EQ (cloud.width, 2u);
  EXPECT_EQ (value<std::int32_t> (cloud, "las_x", 1),
             get<std::int32_t> (&old.records[20]));
}

TEST (LasReader, ExtraBytesFields)
{
  las_test::LasFile f;
  f.minor = 2;
  f.format_byte = 0;
  f.record_length = 20 + 2 + 6 + 5 + 8 + 2 + 1 + 1;
  std::vector<std::uint8_t> d;
  for (const auto& one :
       {las_test::extraBytesDescriptor (3, "height", 0x18, 0.01, 100.0),
        las_test::extraBytesDescriptor (23, "colours"),
        las_test::extraBytesDescriptor (0, "", 5),
        las_test::extraBytesDescriptor (10, "d"),
        las_test::extraBytesDescriptor (12, "pair"),
        las_test::extraBytesDescriptor (1, "intensity")})
    d.insert (d.end(), one.begin(), one.end());
  f.vlrs.push_back ({"LASF_Spec", 4, "Extra Bytes Record", d});
  f.randomRecords (5, 3);
  pcl::PCLPointCloud2 c;
  LasFileInfo info;
  pcl_ext::io::loadLas (write ("extra.las", f), c, info);
  ASSERT_EQ (info.extra_bytes.size(), 6u);
  ASSERT_EQ (c.width, 5u);
  EXPECT_EQ (las_test::field (c, "height")->datatype, pcl::PCLPointField::FLOAT64);
  EXPECT_EQ (las_test::field (c, "colours")->datatype, pcl::PCLPointField::UINT16);
  EXPECT_EQ (las_test::field (c, "colours")->count, 3u);
  EXPECT_EQ (las_test::field (c, "extra_bytes_2")->count, 5u);
  EXPECT_EQ (las_test::field (c, "pair")->datatype, pcl::PCLPointField::INT8);
  EXPECT_EQ (las_test::field (c, "intensity_extra")->datatype,
             pcl::PCLPointField::UINT8);
  EXPECT_EQ (las_test::field (c, "extra_bytes")->count, 1u);
  for (std::size_t i = 0; i < 5; ++i) {
    const std::uint8_t* r = f.records.data() + i * f.record_length + 20;
    EXPECT_EQ (value<double> (c, "height", i), get<std::uint16_t> (r) * 0.01 + 100.0);
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ (value<std::uint16_t> (c, "colours", i, k),
                 get<std::uint16_t> (r + 2 + 2 * k));
    for (std::size_t k = 0; k < 5; ++k)
      EXPECT_EQ (value<std::uint8_t> (c, "extra_bytes_2", i, k), r[8 + k]);
    EXPECT_EQ (value<std::uint64_t> (c, "d", i), get<std::uint64_t> (r + 13));
    EXPECT_EQ (value<std::int8_t> (c, "pair", i, 1), static_cast<std::int8_t> (r[22]));
    EXPECT_EQ (value<std::uint8_t> (c, "intensity_extra", i), r[23]);
    EXPECT_EQ (value<std::uint8_t> (c, "extra_bytes", i), r[24]);
  }

  // Descriptors of more bytes than the records have.
  f.record_length = 20 + 20;
  f.randomRecords (5, 3);
  const std::string path = write ("extra_short.las", f);
  expectReadError ([&path] { LasReader().open (path); },
                   path,
                   0,
                   "describes 24 bytes but records have 20");
}

TEST (LasReader, ChunksEqualTheWholeFile)
{
  const auto f = randomFile (3, 20000);
  const std::string path = write ("chunks.las", f);
  pcl::PCLPointCloud2 whole;
  LasFileInfo info;
  pcl_ext::io::loadLas (path, whole, info);
  ASSERT_EQ (whole.width, 20000u);
  for (const std::size_t size :
       {1u, 7u, 1000u, 8192u, 8193u, 19999u, 20000u, 1000000u}) {
    SCOPED_TRACE ("chunks of " + std::to_string (size));
    LasReader reader;
    reader.open (path);
    std::vector<std::uint8_t> data;
    pcl::PCLPointCloud2 chunk;
    std::size_t n;
    while ((n = reader.read (size, chunk)) > 0) {
      ASSERT_EQ (chunk.width, n);
      ASSERT_LE (n, size);
      ASSERT_EQ (chunk.fields.size(), whole.fields.size());
      ASSERT_EQ (chunk.point_step, whole.point_step);
      data.insert (data.end(), chunk.data.begin(), chunk.data.end());
    }
    EXPECT_EQ (reader.getPointsRead(), 20000u);
    EXPECT_EQ (chunk.width, 0u); // the last call: no point, the fields still named
    EXPECT_EQ (chunk.fields.size(), whole.fields.size());
    EXPECT_TRUE (data == whole.data);
    EXPECT_EQ (reader.read (size, chunk), 0u);
  }
}

TEST (LasReader, OriginAndLocalCoordinates)
{
  las_test::LasFile f = randomFile (0, 0);
  f.scale[0] = f.scale[1] = f.scale[2] = 0.001;
  f.offset[0] = 500000;
  f.offset[1] = 6000000;
  f.min[0] = 500010.5;
  f.max[0] = 501020.0;
  f.min[1] = 6000000.0;
  f.max[1] = 6000900.0;
  f.min[2] = -10;
  f.max[2] = 80;
  f.records.assign (20, 0);
  las_test::put<std::int32_t> (f.records, 0, 765432); // x = 500765.432
  las_test::put<std::int32_t> (f.records, 4, 123456); // y = 6000123.456
  las_test::put<std::int32_t> (f.records, 8, -1234);  // z = -1.234
  f.count = 1;
  LasReader reader;
  reader.open (write ("utm.las", f));
  // Centres 500515.25 and 6000450 rounded to 100 m; z within +-8192 m stays as it is.
  EXPECT_EQ (reader.getOrigin(), Eigen::Vector3d (500500, 6000500, 0));
  pcl::PCLPointCloud2 c;
  ASSERT_EQ (reader.read (10, c), 1u);
  EXPECT_EQ (value<float> (c, "x", 0),
             static_cast<float> (765432 * 0.001 + (500000.0 - 500500)));
  EXPECT_EQ (value<float> (c, "y", 0), static_cast<float> (123456 * 0.001 - 500.0));
  EXPECT_EQ (value<float> (c, "z", 0), static_cast<float> (-1234 * 0.001));
  EXPECT_NEAR (value<float> (c, "x", 0), 265.432, 1e-4);

  LasReader other;
  other.open (folder() + "/utm.las");
  other.setOrigin (Eigen::Vector3d (500000, 6000000, -100));
  EXPECT_EQ (other.getFileInfo().origin, Eigen::Vector3d (500000, 6000000, -100));
  ASSERT_EQ (other.read (10, c), 1u);
  EXPECT_NEAR (value<float> (c, "x", 0), 765.432, 1e-4);
  EXPECT_NEAR (value<float> (c, "z", 0), 98.766, 1e-4);
}

TEST (LasReader, ColourDepthAndPclPointTypes)
{
  las_test::LasFile f = randomFile (2, 3);
  for (std::size_t i = 0; i < 3; ++i) // 8-bit colour stored as it is
    for (std::size_t k = 0; k < 3; ++k)
      las_test::put<std::uint16_t> (
          f.records, i * 26 + 20 + 2 * k, static_cast<std::uint16_t> (10 * i + k + 1));
  pcl::PCLPointCloud2 c;
  LasFileInfo info;
  pcl_ext::io::loadLas (write ("colour8.las", f), c, info);
  pcl::PointCloud<pcl::PointXYZRGB> rgb;
  pcl::fromPCLPointCloud2 (c, rgb);
  ASSERT_EQ (rgb.size(), 3u);
  EXPECT_EQ (rgb[2].r, 21);
  EXPECT_EQ (rgb[2].g, 22);
  EXPECT_EQ (rgb[2].b, 23);
  EXPECT_EQ (rgb[1].x, value<float> (c, "x", 1));

  las_test::put<std::uint16_t> (f.records, 20, 0xAB00); // one 16-bit value
  pcl_ext::io::loadLas (write ("colour16.las", f), c, info);
  pcl::fromPCLPointCloud2 (c, rgb);
  EXPECT_EQ (rgb[0].r, 0xAB);
  EXPECT_EQ (rgb[2].g, 0); // 22 / 256

  pcl::PointCloud<pcl::PointXYZI> xyzi;
  pcl::fromPCLPointCloud2 (c, xyzi);
  EXPECT_EQ (xyzi[1].intensity, las_test::get<std::uint16_t> (&f.records[26 + 12]));
  EXPECT_TRUE (c.is_dense);
}

TEST (LasReader, RefusesMalformedFiles)
{
  auto good = randomFile (3, 10);
  good.minor = 2;
  const auto check = [] (const std::string& name,
                         const std::vector<std::uint8_t>& bytes,
                         const std::string& fragment) {
    const std::string path = folder() + "/" + name;
    las_test::writeBytes (path, bytes);
    expectReadError ([&path] { LasReader().open (path); }, path, 0, fragment);
    pcl::PCLPointCloud2 cloud;
    cloud.width = 77;
    LasFileInfo info;
    expectReadError (
        [&] { pcl_ext::io::loadLas (path, cloud, info); }, path, 0, fragment);
    EXPECT_EQ (cloud.width, 77u); // untouched
  };
  auto b = good.bytes();
  check ("truncated_header.las",
         std::vector<std::uint8_t> (b.begin(), b.begin() + 100),
         "truncated LAS header");
  check ("empty.las", {}, "truncated LAS header");
  b[1] = 'X';
  check ("signature.las", b, "signature");
  b = good.bytes();
  las_test::put<std::uint32_t> (b, 100, 3); // three VLRs, none there
  check ("vlr_count.las", b, "VLR 1 of 3 at byte 227 runs past the point data");

  auto f = good;
  f.vlrs.push_back ({"a", 1, "", std::vector<std::uint8_t> (8)});
  b = f.bytes();
  las_test::put<std::uint16_t> (b, 227 + 20, 5000); // its length runs past the points
  check ("vlr_length.las",
         b,
         "VLR 1 of 1 (\"a\", 1) of 5000 bytes runs past the point data");
  b = f.bytes();
  b.resize (227 + 30);
  las_test::put<std::uint32_t> (b, 96, 227 + 30);
  las_test::put<std::uint32_t> (b, 107, 0);
  check ("vlr_past_file.las", b, "runs past the point data");

  b = good.bytes();
  las_test::put<std::uint32_t> (b, 107, 11);
  check ("count.las", b, "point count 11 is larger than the file holds");
  b = good.bytes();
  las_test::put<std::uint32_t> (b, 96, 1000000);
  check ("offset.las", b, "past the end of the file");
  b = good.bytes();
  las_test::put<std::uint16_t> (b, 105, 30);
  check ("record_length.las", b, "shorter than the 34 bytes of format 3");
  b = good.bytes();
  b.resize (b.size() - 1); // the last record is one byte short
  check ("truncated_points.las", b, "point count 10 is larger than the file holds");

  las_test::LasFile e = randomFile (6, 2);
  e.evlrs.push_back ({"e", 1, "", std::vector<std::uint8_t> (10)});
  b = e.bytes();
  las_test::put<std::uint64_t> (b, b.size() - 10 - 60 + 20, 11);
  check ("evlr_length.las", b, "EVLR 1 of 1 (\"e\", 1) of 11 bytes runs past the end");

  const std::string missing = folder() + "/missing.las";
  expectReadError ([&] { LasReader().open (missing); }, missing, 0, "cannot open");
  expectReadError (
      [&] { LasReader().open (folder()); }, folder(), 0, "not a regular file");
}

TEST (LasReader, CompressedFilesGoThroughTheDecoder)
{
  auto f = randomFile (3, 10);
  f.format_byte = 0x83;
  const std::string no_vlr = write ("no_laszip.laz", f);
  expectReadError (
      [&] { LasReader().open (no_vlr); }, no_vlr, 0, "without a LASzip VLR");
  f.vlrs.push_back ({"laszip encoded", 22204, "", std::vector<std::uint8_t> (4)});
  const std::string garbage = write ("garbage.laz", f);
  LasReader reader;
  // The decoder (or its absence) refuses garbage with an error naming the file.
  EXPECT_THROW (
      {
        reader.open (garbage);
        pcl::PCLPointCloud2 c;
        reader.read (10, c);
      },
      pcl_ext::io::ReadError);
}

TEST (LasReader, ReadWithoutAFile)
{
  LasReader reader;
  pcl::PCLPointCloud2 c;
  EXPECT_THROW (reader.read (1, c), pcl_ext::io::ReadError);
}

TEST (LasReader, FileCutWhileReading)
{
  const auto f = randomFile (1, 20000);
  const std::string path = write ("cut.las", f);
  LasReader reader;
  reader.open (path);
  pcl::PCLPointCloud2 chunk;
  ASSERT_EQ (reader.read (100, chunk), 100u);
  ::truncate (path.c_str(), 375 + 10000 * 28); // another program cuts the file
  expectReadError (
      [&] {
        while (reader.read (1000, chunk) > 0) {
        }
      },
      path,
      0,
      "truncated point data");
  EXPECT_EQ (chunk.width, 0u); // left empty
  EXPECT_TRUE (chunk.data.empty());
}
