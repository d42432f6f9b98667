/*
 * The LAS public header block, its checks against the file size, and the extra-bytes
 * descriptors.
 */
#include <pcl_ext/io/las_header.h>

#include "las_test_files.h"
#include "test_helpers.h"

using pcl_ext::io::LasHeader;
using pcl_ext::io::parseLasHeader;

namespace {
LasHeader
parse (const std::vector<std::uint8_t>& b)
{
  return parseLasHeader (b.data(), b.size(), b.size(), "f.las");
}

/** Expects parsing \a b to fail with a message containing \a fragment. */
void
expectRefused (const std::vector<std::uint8_t>& b, const std::string& fragment)
{
  expectReadError ([&b] { parse (b); }, "f.las", 0, fragment);
}

las_test::LasFile
fileWithPoints (int minor, std::uint8_t format, std::uint16_t record_length)
{
  las_test::LasFile f;
  f.minor = minor;
  f.format_byte = format;
  f.record_length = record_length;
  f.randomRecords (3, 1);
  return f;
}
} // namespace

TEST (LasHeader, StandardSizes)
{
  EXPECT_EQ (pcl_ext::io::lasHeaderSize (1, 0), 227u);
  EXPECT_EQ (pcl_ext::io::lasHeaderSize (1, 2), 227u);
  EXPECT_EQ (pcl_ext::io::lasHeaderSize (1, 3), 235u);
  EXPECT_EQ (pcl_ext::io::lasHeaderSize (1, 4), 375u);
  EXPECT_EQ (pcl_ext::io::lasHeaderSize (1, 5), 0u);
  EXPECT_EQ (pcl_ext::io::lasHeaderSize (2, 0), 0u);
  const std::size_t lengths[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  for (int format = 0; format <= 10; ++format)
    EXPECT_EQ (pcl_ext::io::lasPointRecordLength (format), lengths[format]);
  EXPECT_EQ (pcl_ext::io::lasPointRecordLength (11), 0u);
  EXPECT_EQ (pcl_ext::io::lasPointRecordLength (-1), 0u);
}

TEST (LasHeader, EveryVersion)
{
  for (int minor = 0; minor <= 4; ++minor) {
    auto f = fileWithPoints (minor, 1, 28);
    f.scale[1] = 0.001;
    f.offset[0] = 500000.0;
    f.min[2] = -5.5;
    f.max[2] = 99.25;
    f.waveform_start = 1234;
    auto b = f.bytes();
    las_test::put<std::uint32_t> (b, 111 + 4, 2); // two second returns
    if (minor >= 4)
      las_test::put<std::uint64_t> (b, 255 + 8 * 14, 7); // 15th return
    const LasHeader h = parse (b);
    EXPECT_EQ (h.version_major, 1);
    EXPECT_EQ (h.version_minor, minor);
    EXPECT_EQ (h.header_size, pcl_ext::io::lasHeaderSize (1, minor));
    EXPECT_EQ (h.offset_to_point_data, h.header_size);
    EXPECT_EQ (h.system_identifier, "TEST SYSTEM");
    EXPECT_EQ (h.generating_software, "las_test_files.h");
    EXPECT_EQ (h.creation_day, 100);
    EXPECT_EQ (h.creation_year, 2024);
    EXPECT_EQ (h.pointFormat(), 1);
    EXPECT_FALSE (h.isCompressed());
    EXPECT_EQ (h.record_length, 28);
    EXPECT_EQ (h.point_count, 3u);
    EXPECT_EQ (h.legacy_point_count, 3u);
    EXPECT_EQ (h.legacy_points_by_return[1], 2u);
    EXPECT_EQ (h.scale, Eigen::Vector3d (0.01, 0.001, 0.01));
    EXPECT_EQ (h.offset, Eigen::Vector3d (500000.0, 0, 0));
    EXPECT_EQ (h.min.z(), -5.5);
    EXPECT_EQ (h.max.z(), 99.25);
    EXPECT_EQ (h.waveform_data_start, minor >= 3 ? 1234u : 0u);
    EXPECT_EQ (h.points_by_return[14], minor >= 4 ? 7u : 0u);
    EXPECT_TRUE (h.extra_header_bytes.empty());
  }
}

TEST (LasHeader, Extended14Fields)
{
  auto f = fileWithPoints (4, 6, 30);
  las_test::Vlr evlr;
  evlr.user_id = "LASF_Projection";
  evlr.record_id = 2112;
  evlr.data.assign (10, 'w');
  f.evlrs.push_back (evlr);
  const auto b = f.bytes();
  const LasHeader h = parse (b);
  EXPECT_EQ (h.legacy_point_count, 0u); // format 6: legacy fields are 0
  EXPECT_EQ (h.point_count, 3u);
  EXPECT_EQ (h.evlr_count, 1u);
  EXPECT_EQ (h.evlr_start, 375u + 3 * 30);
}

TEST (LasHeader, CompressionBits)
{
  for (const std::uint8_t byte : {std::uint8_t (0x83), std::uint8_t (0x43)}) {
    auto f = fileWithPoints (2, byte, 34);
    f.records.resize (10); // compressed data is shorter than the records
    const LasHeader h = parse (f.bytes());
    EXPECT_TRUE (h.isCompressed());
    EXPECT_EQ (h.pointFormat(), 3);
    EXPECT_EQ (h.point_format_byte, byte);
  }
}

TEST (LasHeader, EncodeThenParse)
{
  auto f = fileWithPoints (4, 7, 40);
  las_test::Vlr vlr;
  vlr.user_id = "x";
  vlr.data.assign (5, 1);
  f.vlrs.push_back (vlr);
  const auto b = f.bytes();
  LasHeader h = parse (b);
  h.project_guid[3] = 9;
  h.global_encoding = 17;
  h.file_source_id = 42;
  auto encoded = pcl_ext::io::encodeLasHeader (h);
  ASSERT_EQ (encoded.size(), 375u);
  // The rest of the file as it was: the header must state the same layout.
  encoded.insert (encoded.end(), b.begin() + 375, b.end());
  const LasHeader again = parse (encoded);
  EXPECT_EQ (again.project_guid, h.project_guid);
  EXPECT_EQ (again.global_encoding, 17);
  EXPECT_EQ (again.file_source_id, 42);
  EXPECT_EQ (again.offset_to_point_data, h.offset_to_point_data);
  EXPECT_EQ (again.number_of_vlrs, 1u);
  EXPECT_EQ (again.point_count, 3u);
  EXPECT_EQ (again.record_length, 40);
  EXPECT_EQ (again.scale, h.scale);
  EXPECT_EQ (pcl_ext::io::encodeLasHeader (again),
             std::vector<std::uint8_t> (encoded.begin(), encoded.begin() + 375));
  // Unchanged, the header is written as the file had it.
  EXPECT_EQ (pcl_ext::io::encodeLasHeader (parse (b)),
             std::vector<std::uint8_t> (b.begin(), b.begin() + 375));
}

TEST (LasHeader, LargerHeaderKeepsItsUserBytes)
{
  auto f = fileWithPoints (2, 0, 20);
  auto b = f.bytes();
  b.insert (b.begin() + 227, {7, 8, 9});
  las_test::put<std::uint16_t> (b, 94, 230);
  las_test::put<std::uint32_t> (b, 96, 230);
  const LasHeader h = parse (b);
  EXPECT_EQ (h.header_size, 230);
  EXPECT_EQ (h.extra_header_bytes, (std::vector<std::uint8_t>{7, 8, 9}));
  EXPECT_EQ (pcl_ext::io::encodeLasHeader (h),
             std::vector<std::uint8_t> (b.begin(), b.begin() + 230));
}

TEST (LasHeader, RefusesMalformedHeaders)
{
  const auto good = fileWithPoints (2, 3, 34).bytes();
  ASSERT_NO_THROW (parse (good));

  expectRefused (std::vector<std::uint8_t> (good.begin(), good.begin() + 2),
                 "truncated");
  expectRefused (std::vector<std::uint8_t> (good.begin(), good.begin() + 200),
                 "truncated");
  auto b = good;
  b[0] = 'X';
  expectRefused (b, "signature");
  b = good;
  b[25] = 5;
  expectRefused (b, "unsupported LAS version 1.5");
  b = good;
  b[24] = 2;
  expectRefused (b, "unsupported LAS version 2.");
  b = good;
  las_test::put<std::uint16_t> (b, 94, 200);
  expectRefused (b, "header size 200 is smaller than the 227");
  b = good;
  las_test::put<std::uint32_t> (b, 96, 100);
  expectRefused (b, "inside the 227-byte header");
  b = good;
  las_test::put<std::uint32_t> (b, 96, 100000);
  expectRefused (b, "past the end of the file");
  b = good;
  b[104] = 11;
  expectRefused (b, "unknown point data record format 11");
  b = good;
  las_test::put<std::uint16_t> (b, 105, 33);
  expectRefused (b, "point record length 33 is shorter than the 34 bytes of format 3");
  b = good;
  las_test::put<std::uint32_t> (b, 107, 4);
  expectRefused (b, "point count 4 is larger than the file holds");
  b = good;
  las_test::put<std::uint32_t> (b, 107, 0xFFFFFFFFu);
  expectRefused (b, "larger than the file holds");
  b = good;
  las_test::put<double> (b, 131, 0.0);
  expectRefused (b, "invalid x scale");
  b = good;
  las_test::put<double> (b, 155 + 16, std::nan (""));
  expectRefused (b, "invalid z scale or offset");
  b = good;
  las_test::put<double> (b, 139, 1e300);
  expectRefused (b, "invalid y scale");
}

TEST (LasHeader, RefusesExtendedRecordsOutsideTheFile)
{
  auto f = fileWithPoints (4, 6, 30);
  las_test::Vlr evlr;
  evlr.user_id = "a";
  f.evlrs.push_back (evlr);
  auto b = f.bytes();
  ASSERT_NO_THROW (parse (b));
  las_test::put<std::uint32_t> (b, 243, 2); // two EVLRs where one fits
  expectRefused (b, "EVLRs");
  b = f.bytes();
  las_test::put<std::uint64_t> (b, 235, 375 + 30); // inside the point data
  expectRefused (b, "EVLRs");
}

TEST (LasHeader, ExtraBytesDescriptors)
{
  pcl_ext::io::LasVariableLengthRecord vlr;
  vlr.user_id = "LASF_Spec";
  vlr.record_id = 4;
  EXPECT_TRUE (pcl_ext::io::isExtraBytesRecord (vlr));
  EXPECT_FALSE (pcl_ext::io::isLaszipRecord (vlr));
  const auto add = [&vlr] (const std::vector<std::uint8_t>& d) {
    vlr.data.insert (vlr.data.end(), d.begin(), d.end());
  };
  add (las_test::extraBytesDescriptor (3, "height", 0x18, 0.01, 100.0));
  add (las_test::extraBytesDescriptor (23, "colours")); // deprecated 3 x ushort
  add (las_test::extraBytesDescriptor (0, "raw", 5));   // 5 undocumented bytes
  add (las_test::extraBytesDescriptor (10, "d"));
  add (las_test::extraBytesDescriptor (12, "pair")); // deprecated 2 x char
  const auto d = pcl_ext::io::parseExtraBytes (vlr, "f.las");
  ASSERT_EQ (d.size(), 5u);
  EXPECT_EQ (d[0].name, "height");
  EXPECT_EQ (d[0].description, "test height");
  EXPECT_EQ (d[0].baseType(), 3);
  EXPECT_EQ (d[0].size(), 2u);
  EXPECT_TRUE (d[0].hasScale());
  EXPECT_TRUE (d[0].hasOffset());
  EXPECT_TRUE (d[0].isScaled());
  EXPECT_EQ (d[0].scale[0], 0.01);
  EXPECT_EQ (d[0].offset[0], 100.0);
  EXPECT_EQ (d[1].elements(), 3);
  EXPECT_EQ (d[1].baseType(), 3);
  EXPECT_EQ (d[1].size(), 6u);
  EXPECT_FALSE (d[1].isScaled());
  EXPECT_EQ (d[2].baseType(), 0);
  EXPECT_EQ (d[2].size(), 5u);
  EXPECT_EQ (d[3].size(), 8u);
  EXPECT_EQ (d[4].elements(), 2);
  EXPECT_EQ (d[4].baseType(), 2);
  EXPECT_EQ (d[4].size(), 2u);
  EXPECT_EQ (pcl_ext::io::encodeExtraBytes (d), vlr.data);

  auto bad = vlr;
  bad.data.resize (191);
  expectReadError ([&bad] { pcl_ext::io::parseExtraBytes (bad, "f.las"); },
                   "f.las",
                   0,
                   "not a multiple of 192");
  bad = vlr;
  bad.data[2] = 31;
  expectReadError ([&bad] { pcl_ext::io::parseExtraBytes (bad, "f.las"); },
                   "f.las",
                   0,
                   "invalid data type 31");
  bad = vlr;
  bad.data[2 + 2 * 192 + 1] = 0; // undocumented bytes of length 0
  expectReadError ([&bad] { pcl_ext::io::parseExtraBytes (bad, "f.las"); },
                   "f.las",
                   0,
                   "with no length");
}
