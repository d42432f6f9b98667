/*
 * The E57 building blocks: CRC-32C, the bytestream bit unpacker and the XML section's
 * scan descriptions.
 */
#include <pcl_ext/io/e57_format.h>

#include "e57_test_files.h"

#include <gtest/gtest.h>

#include <limits>

using pcl_ext::io::E57BitUnpacker;
using pcl_ext::io::E57FieldType;

TEST (E57Format, Crc32cKnownVectors)
{
  const std::string digits = "123456789";
  EXPECT_EQ (pcl_ext::io::crc32c (reinterpret_cast<const std::uint8_t*> (digits.data()),
                                  digits.size()),
             0xE3069283u);
  EXPECT_EQ (pcl_ext::io::crc32c (nullptr, 0), 0u);
  // RFC 3720 (iSCSI) appendix B.4: 32 bytes of zeros, 32 bytes of 0xFF.
  const std::vector<std::uint8_t> zeros (32, 0), ones (32, 0xFF);
  EXPECT_EQ (pcl_ext::io::crc32c (zeros.data(), zeros.size()), 0x8A9136AAu);
  EXPECT_EQ (pcl_ext::io::crc32c (ones.data(), ones.size()), 0x62A8AB43u);
  // Offsets: page 1 starts at physical 1024, logical 1020.
  EXPECT_EQ (pcl_ext::io::e57LogicalOffset (1024), 1020u);
  EXPECT_EQ (pcl_ext::io::e57LogicalOffset (2048 + 48), 2040u + 48u);
}

TEST (E57Format, UnpackerReadsValuesAcrossBytesAndPieces)
{
  // 3-bit values 5, 3, 7, 0, 1, least significant bit first:
  // byte 0 = bits 0..7 = 1,0,1, 1,1,0, 1,1 = 0xDD; byte 1 = 1, 0,0,0, 1,0,0, 0 = 0x11.
  E57BitUnpacker u (3);
  const std::uint8_t first = 0xDD, second = 0x11;
  u.append (&first, 1);
  EXPECT_EQ (u.available(), 2u);
  EXPECT_EQ (u.next(), 5u);
  EXPECT_EQ (u.next(), 3u);
  EXPECT_EQ (u.available(), 0u); // 2 bits of the third value so far
  u.append (&second, 1);
  EXPECT_EQ (u.available(), 3u);
  EXPECT_EQ (u.next(), 7u);
  EXPECT_EQ (u.next(), 0u);
  EXPECT_EQ (u.next(), 1u);
  EXPECT_EQ (u.bitsLeft(), 1u);

  // 63-bit values straddle the 64-bit words: (2^63 - 1, 1) then (0, 2^63 - 1).
  E57BitUnpacker wide (63);
  std::vector<std::uint8_t> a (8, 0xFF);
  a.resize (16, 0x00);
  std::vector<std::uint8_t> b (7, 0x00);
  b.push_back (0x80);
  b.resize (15, 0xFF);
  b.push_back (0x3F);
  wide.append (a.data(), a.size());
  ASSERT_EQ (wide.available(), 2u);
  EXPECT_EQ (wide.next(), 0x7FFFFFFFFFFFFFFFu);
  EXPECT_EQ (wide.next(), 1u);
  E57BitUnpacker wide2 (63);
  wide2.append (b.data(), b.size());
  ASSERT_EQ (wide2.available(), 2u);
  EXPECT_EQ (wide2.next(), 0u);
  EXPECT_EQ (wide2.next(), 0x7FFFFFFFFFFFFFFFu);

  // 64 bits: a little-endian word; 0 bits: a constant, always available.
  E57BitUnpacker full (64);
  const std::uint8_t word[] = {0xEF, 0xCD, 0xAB, 0x89, 0x67, 0x45, 0x23, 0x01};
  full.append (word, 8);
  EXPECT_EQ (full.next(), 0x0123456789ABCDEFu);
  E57BitUnpacker constant (0);
  EXPECT_EQ (constant.available(), std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ (constant.next(), 0u);

  // Many values of an odd width through many small pieces, as data packets give them.
  e57_test::BitPacker packer (13);
  for (std::uint64_t v = 0; v < 1000; ++v)
    packer.add ((v * 7919) % 8192);
  E57BitUnpacker odd (13);
  std::uint64_t expected = 0;
  for (std::size_t at = 0; at < packer.bytes().size(); at += 7) {
    odd.append (packer.bytes().data() + at,
                std::min<std::size_t> (7, packer.bytes().size() - at));
    while (odd.available() > 0 && expected < 1000)
      ASSERT_EQ (odd.next(), (expected++ * 7919) % 8192);
  }
  EXPECT_EQ (expected, 1000u);
}

TEST (E57Format, XmlCoordinateMetadataIsTheFilesCrs)
{
  std::string xml = e57_test::e57Xml ("");
  std::string metadata = "unset";
  pcl_ext::io::parseE57Xml (xml, "mem.e57", &metadata);
  EXPECT_EQ (metadata, ""); // absent
  const std::string root = "<e57Root type=\"Structure\" ";
  xml.insert (xml.find (root) + xml.substr (xml.find (root)).find ('>') + 1,
              "\n<coordinateMetadata type=\"String\"><![CDATA[ EPSG:32631 ]]>"
              "</coordinateMetadata>");
  pcl_ext::io::parseE57Xml (xml, "mem.e57", &metadata);
  EXPECT_EQ (metadata, "EPSG:32631");
}

TEST (E57Format, XmlScanPosePrototypeAndLimits)
{
  const std::string xml = e57_test::e57Xml (
      "<vectorChild type=\"Structure\">"
      "<guid type=\"String\"><![CDATA[{abc}]]></guid>"
      "<name type=\"String\"><![CDATA[Station 1]]></name>"
      "<pose type=\"Structure\"><rotation type=\"Structure\">"
      "<w type=\"Float\">2</w><x type=\"Float\"/><y type=\"Float\"/>"
      "<z type=\"Float\">0</z></rotation>"
      "<translation type=\"Structure\"><x type=\"Float\">1.5</x><y type=\"Float\"/>"
      "<z type=\"Float\">-2</z></translation></pose>"
      "<intensityLimits type=\"Structure\"><intensityMinimum type=\"Integer\"/>"
      "<intensityMaximum type=\"Integer\">4095</intensityMaximum></intensityLimits>"
      "<points type=\"CompressedVector\" fileOffset=\"48\" recordCount=\"12\">"
      "<prototype type=\"Structure\">"
      "<cartesianX type=\"ScaledInteger\" minimum=\"-500\" maximum=\"500\" "
      "scale=\"0.001\" offset=\"10\"/>"
      "<cartesianY type=\"Float\" precision=\"single\"/>"
      "<cartesianZ type=\"Float\" minimum=\"-1\" maximum=\"1\"/>"
      "<intensity type=\"Integer\" minimum=\"0\" maximum=\"4095\"/>"
      "<rowIndex type=\"Integer\"/>"
      "<extra type=\"Structure\"><flag type=\"Integer\" minimum=\"3\" maximum=\"3\"/>"
      "</extra>"
      "</prototype><codecs type=\"Vector\" allowHeterogeneousChildren=\"1\"/>"
      "</points></vectorChild>");
  const auto scans = pcl_ext::io::parseE57Xml (xml, "mem.e57");
  ASSERT_EQ (scans.size(), 1u);
  const auto& s = scans[0];
  EXPECT_EQ (s.name, "Station 1");
  EXPECT_EQ (s.guid, "{abc}");
  // w = 2 normalised to the identity.
  EXPECT_DOUBLE_EQ (s.rotation.w(), 1.0);
  EXPECT_EQ (s.translation, Eigen::Vector3d (1.5, 0, -2));
  EXPECT_TRUE (s.has_intensity_limits);
  EXPECT_EQ (s.intensity_maximum, 4095.0);
  EXPECT_FALSE (s.has_color_limits);
  EXPECT_EQ (s.file_offset, 48u);
  EXPECT_EQ (s.record_count, 12u);
  ASSERT_EQ (s.prototype.size(), 6u);
  const auto& x = s.prototype[0];
  EXPECT_EQ (x.name, "cartesianX");
  EXPECT_EQ (x.type, E57FieldType::ScaledInteger);
  EXPECT_EQ (x.minimum, -500);
  EXPECT_EQ (x.bits(), 10u); // 1000 needs 10 bits
  EXPECT_DOUBLE_EQ (x.value_minimum, 9.5);
  EXPECT_DOUBLE_EQ (x.value_maximum, 10.5);
  EXPECT_TRUE (x.has_bounds);
  EXPECT_EQ (s.prototype[1].bits(), 32u);
  EXPECT_FALSE (s.prototype[1].has_bounds);
  EXPECT_EQ (s.prototype[2].bits(), 64u);
  EXPECT_TRUE (s.prototype[2].has_bounds);
  EXPECT_EQ (s.prototype[3].bits(), 12u);
  EXPECT_EQ (s.prototype[4].bits(), 64u); // the whole int64 range by default
  EXPECT_EQ (s.prototype[4].minimum, std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ (s.prototype[5].name, "flag"); // nested, flattened depth-first
  EXPECT_EQ (s.prototype[5].bits(), 0u);

  // A file without scans is valid.
  EXPECT_TRUE (pcl_ext::io::parseE57Xml (e57_test::e57Xml (""), "mem.e57").empty());
}

TEST (E57Format, XmlThatLiesOrIsMalformedIsRefused)
{
  const auto scan = [] (const std::string& prototype, const std::string& extra = "") {
    return e57_test::e57Xml (
        "<vectorChild type=\"Structure\">" + extra +
        "<points type=\"CompressedVector\" fileOffset=\"48\" recordCount=\"1\">"
        "<prototype type=\"Structure\">" +
        prototype + "</prototype></points></vectorChild>");
  };
  const std::string xyz = "<cartesianX type=\"Float\"/><cartesianY type=\"Float\"/>"
                          "<cartesianZ type=\"Float\"/>";
  const auto expectRefused = [] (const std::string& xml, const std::string& fragment) {
    try {
      pcl_ext::io::parseE57Xml (xml, "mem.e57");
      ADD_FAILURE() << "accepted: " << fragment;
    }
    catch (const pcl_ext::io::ReadError& e) {
      EXPECT_EQ (e.path(), "mem.e57");
      EXPECT_NE (e.message().find (fragment), std::string::npos) << e.what();
    }
  };
  EXPECT_NO_THROW (pcl_ext::io::parseE57Xml (scan (xyz), "mem.e57"));
  expectRefused (scan ("<cartesianX type=\"Float\"/><cartesianY type=\"Float\"/>"),
                 "neither cartesianX/Y/Z nor spherical");
  expectRefused (scan (xyz + "<note type=\"String\"/>"), "String elements");
  expectRefused (scan (xyz + "<odd type=\"Complex\"/>"), "unknown type");
  expectRefused (scan (xyz + "<i type=\"Integer\" minimum=\"5\" maximum=\"4\"/>"),
                 "minimum > maximum");
  expectRefused (scan (xyz + "<i type=\"Integer\" maximum=\"1e99\"/>"),
                 "64-bit integer");
  expectRefused (scan ("<cartesianX type=\"Float\" precision=\"half\"/>"), "precision");
  expectRefused (scan (xyz,
                       "<pose type=\"Structure\"><rotation type=\"Structure\">"
                       "</rotation></pose>"),
                 "unit quaternion");
  expectRefused (e57_test::e57Xml ("<vectorChild type=\"Structure\"/>"),
                 "no points CompressedVector");
  expectRefused (
      e57_test::e57Xml ("<vectorChild type=\"Structure\">"
                        "<points type=\"CompressedVector\" fileOffset=\"-1\" "
                        "recordCount=\"1\"/></vectorChild>"),
      "fileOffset or recordCount");
  expectRefused ("<e57Root><data3D>", "XML section: line");
  expectRefused ("<root/>", "no e57Root");
  std::string deep;
  for (int i = 0; i < 100; ++i)
    deep += "<a>";
  expectRefused (deep, "nested deeper");
}
