/*
 * The E57 reader on small files made in the test: a cartesian scan of scaled integers
 * with a pose, invalid states, intensity, colour and grid indices, split over two data
 * packets; a spherical scan of doubles; then malformed variants of them.
 */
#include <pcl_ext/io/e57_reader.h>

#include "e57_test_files.h"
#include "temp_folder.h"
#include "test_helpers.h"

#include <cmath>
#include <fstream>

using e57_test::BitPacker;
using e57_test::Bytes;
using pcl_ext::io::PointTable;

namespace {
std::string
writeE57File (const std::string& name, const std::string& bytes)
{
  static const std::string dir = freshFolder ("e57_reader");
  const std::string path = dir + "/" + name;
  std::ofstream (path, std::ios::binary) << bytes;
  return path;
}

/** Records of scan A as written (before the pose). */
struct Record {
  double x, y;
  float z;
  int state, intensity, r, g, b, row, column;
};
const Record kRecords[] = {{1.00, 2.00, 3.0f, 0, 500, 10, 20, 30, 0, 0},
                           {-1.50, 0.25, -0.5f, 0, 1000, 255, 0, 128, 1, 2},
                           {9.99, -9.99, 0.0f, 2, 7, 7, 7, 7, 2, 5},
                           {0.00, 0.00, 1.0f, 1, 7, 7, 7, 7, 2, 6},
                           {5.00, 6.00, 7.0f, 0, 0, 1, 2, 3, 3, 7}};

/** The bytestreams of scan A, in prototype order. */
std::vector<Bytes>
scanAStreams (int bad_state = -1)
{
  BitPacker x (11), y (11), z (32), state (2), intensity (10), r (8), g (8), b (8),
      row (2), column (3);
  for (const Record& rec : kRecords) {
    // ScaledInteger: raw = value / scale, stored as raw - minimum.
    x.add (static_cast<std::uint64_t> (std::lround (rec.x / 0.01) + 1000));
    y.add (static_cast<std::uint64_t> (std::lround (rec.y / 0.01) + 1000));
    std::uint32_t zbits;
    std::memcpy (&zbits, &rec.z, 4);
    z.add (zbits);
    state.add (bad_state >= 0 ? static_cast<std::uint64_t> (bad_state) : rec.state);
    intensity.add (rec.intensity);
    r.add (rec.r);
    g.add (rec.g);
    b.add (rec.b);
    row.add (rec.row);
    column.add (rec.column);
  }
  return {x.bytes(),
          y.bytes(),
          z.bytes(),
          state.bytes(),
          intensity.bytes(),
          r.bytes(),
          g.bytes(),
          b.bytes(),
          row.bytes(),
          column.bytes()};
}

/** Two data packets: every stream cut in the middle (values straddle the packets). */
std::vector<Bytes>
twoPackets (const std::vector<Bytes>& streams)
{
  std::vector<Bytes> first, second;
  for (const auto& s : streams) {
    const std::size_t half = s.size() / 2;
    first.emplace_back (s.begin(), s.begin() + half);
    second.emplace_back (s.begin() + half, s.end());
  }
  return {e57_test::dataPacket (first), e57_test::dataPacket (second)};
}

std::string
scanAXml (std::uint64_t offset, std::uint64_t count, const std::string& x_type = "")
{
  return "<vectorChild type=\"Structure\"><name type=\"String\"><![CDATA[A]]></name>"
         "<guid type=\"String\"><![CDATA[{a}]]></guid>"
         "<pose type=\"Structure\"><rotation type=\"Structure\">"
         "<w type=\"Float\">0.70710678118654757</w><x type=\"Float\"/>"
         "<y type=\"Float\"/><z type=\"Float\">0.70710678118654757</z></rotation>"
         "<translation type=\"Structure\"><x type=\"Float\">100</x>"
         "<y type=\"Float\">200</y><z type=\"Float\">300</z></translation></pose>"
         "<intensityLimits type=\"Structure\"><intensityMinimum type=\"Integer\"/>"
         "<intensityMaximum type=\"Integer\">1000</intensityMaximum></intensityLimits>"
         "<colorLimits type=\"Structure\"><colorRedMaximum type=\"Integer\">255"
         "</colorRedMaximum><colorGreenMaximum type=\"Integer\">255</colorGreenMaximum>"
         "<colorBlueMaximum type=\"Integer\">255</colorBlueMaximum></colorLimits>"
         "<points type=\"CompressedVector\" fileOffset=\"" +
         std::to_string (offset) + "\" recordCount=\"" + std::to_string (count) +
         "\"><prototype type=\"Structure\">"
         "<cartesianX type=\"" +
         (x_type.empty() ? "ScaledInteger" : x_type) +
         "\" minimum=\"-1000\" maximum=\"1000\" scale=\"0.01\"/>"
         "<cartesianY type=\"ScaledInteger\" minimum=\"-1000\" maximum=\"1000\" "
         "scale=\"0.01\"/>"
         "<cartesianZ type=\"Float\" precision=\"single\"/>"
         "<cartesianInvalidState type=\"Integer\" minimum=\"0\" maximum=\"2\"/>"
         "<intensity type=\"Integer\" minimum=\"0\" maximum=\"1000\"/>"
         "<colorRed type=\"Integer\" minimum=\"0\" maximum=\"255\"/>"
         "<colorGreen type=\"Integer\" minimum=\"0\" maximum=\"255\"/>"
         "<colorBlue type=\"Integer\" minimum=\"0\" maximum=\"255\"/>"
         "<rowIndex type=\"Integer\" minimum=\"0\" maximum=\"3\"/>"
         "<columnIndex type=\"Integer\" minimum=\"0\" maximum=\"7\"/>"
         "</prototype><codecs type=\"Vector\" allowHeterogeneousChildren=\"1\"/>"
         "</points></vectorChild>";
}

/** Scan B: spherical coordinates in doubles, no pose, no attributes. */
const double kSpherical[][3] = {
    {2.0, 0.0, 0.0}, {1.0, M_PI / 2, 0.0}, {4.0, 0.0, M_PI / 2}};

std::vector<Bytes>
scanBPackets ()
{
  BitPacker range (64), azimuth (64), elevation (64);
  for (const auto& s : kSpherical) {
    range.addDouble (s[0]);
    azimuth.addDouble (s[1]);
    elevation.addDouble (s[2]);
  }
  return {e57_test::dataPacket ({range.bytes(), azimuth.bytes(), elevation.bytes()})};
}

std::string
scanBXml (std::uint64_t offset)
{
  return "<vectorChild type=\"Structure\"><name type=\"String\"><![CDATA[B]]></name>"
         "<points type=\"CompressedVector\" fileOffset=\"" +
         std::to_string (offset) +
         "\" recordCount=\"3\"><prototype type=\"Structure\">"
         "<sphericalRange type=\"Float\"/><sphericalAzimuth type=\"Float\"/>"
         "<sphericalElevation type=\"Float\"/></prototype></points></vectorChild>";
}

/** Both scans; the count of scan A as given. */
std::string
twoScans (std::uint64_t count_a = 5)
{
  e57_test::FileBuilder file;
  const std::uint64_t a = file.addSection (twoPackets (scanAStreams()));
  const std::uint64_t b = file.addSection (scanBPackets());
  return file.finish (e57_test::e57Xml (scanAXml (a, count_a) + scanBXml (b)));
}
} // namespace

TEST (E57Reader, TwoScansPosesInvalidStatesAndAttributes)
{
  const std::string bytes = twoScans();
  ASSERT_EQ (bytes.size() % 1024, 0u);
  const std::string path = writeE57File ("two.e57", bytes);
  PointTable t;
  pcl_ext::io::loadE57 (path, t);
  // Scan A: records 2 (state 2) and 3 (state 1) dropped; scan B: all three.
  ASSERT_EQ (t.size(), 6u);
  ASSERT_EQ (t.intensity.size(), 6u);
  ASSERT_EQ (t.rgb.size(), 6u);
  ASSERT_EQ (t.row.size(), 6u);
  ASSERT_EQ (t.column.size(), 6u);
  EXPECT_EQ (t.scan, (std::vector<std::uint16_t>{0, 0, 0, 1, 1, 1}));
  // A quarter turn about z, (x, y, z) -> (-y, x, z), then + (100, 200, 300).
  const Eigen::Vector3d a[] = {
      {98.0, 201.0, 303.0}, {99.75, 198.5, 299.5}, {94.0, 205.0, 307.0}};
  for (int i = 0; i < 3; ++i)
    EXPECT_LT ((t.xyz[i] - a[i]).norm(), 1e-9) << i << ": " << t.xyz[i].transpose();
  // Spherical: x = r cos(e) cos(a), y = r cos(e) sin(a), z = r sin(e).
  EXPECT_LT ((t.xyz[3] - Eigen::Vector3d (2, 0, 0)).norm(), 1e-12);
  EXPECT_LT ((t.xyz[4] - Eigen::Vector3d (0, 1, 0)).norm(), 1e-12);
  EXPECT_LT ((t.xyz[5] - Eigen::Vector3d (0, 0, 4)).norm(), 1e-12);
  // Intensity over intensityLimits 0..1000; scan B has none (NaN).
  EXPECT_FLOAT_EQ (t.intensity[0], 0.5f);
  EXPECT_FLOAT_EQ (t.intensity[1], 1.0f);
  EXPECT_FLOAT_EQ (t.intensity[2], 0.0f);
  EXPECT_TRUE (std::isnan (t.intensity[4]));
  EXPECT_EQ (t.rgb[1], (std::array<std::uint8_t, 3>{255, 0, 128}));
  EXPECT_EQ (t.rgb[2], (std::array<std::uint8_t, 3>{1, 2, 3}));
  EXPECT_EQ (t.rgb[3], (std::array<std::uint8_t, 3>{0, 0, 0}));
  EXPECT_EQ (t.row, (std::vector<std::int32_t>{0, 1, 3, -1, -1, -1}));
  EXPECT_EQ (t.column, (std::vector<std::int32_t>{0, 2, 7, -1, -1, -1}));

  ASSERT_EQ (t.stations.size(), 2u);
  EXPECT_EQ (t.stations[0].name, "A");
  EXPECT_EQ (t.stations[0].guid, "{a}");
  EXPECT_EQ (t.stations[0].position, Eigen::Vector3d (100, 200, 300));
  EXPECT_TRUE (t.stations[0].orientation.isApprox (
      Eigen::Quaterniond (Eigen::AngleAxisd (M_PI / 2, Eigen::Vector3d::UnitZ()))));
  EXPECT_EQ (t.stations[1].name, "B");
  EXPECT_TRUE (t.stations[1].orientation.isApprox (Eigen::Quaterniond::Identity()));
  Eigen::Vector3d sensor;
  ASSERT_TRUE (pcl_ext::io::sensorPosition (t, 1, sensor));
  EXPECT_EQ (sensor, Eigen::Vector3d (100, 200, 300));

  // Scanner frame and raw intensity.
  pcl_ext::io::E57Options options;
  options.keep_scanner_frame = true;
  options.normalise_intensity = false;
  PointTable raw;
  pcl_ext::io::loadE57 (path, raw, options);
  ASSERT_EQ (raw.size(), 6u);
  EXPECT_LT ((raw.xyz[0] - Eigen::Vector3d (1, 2, 3)).norm(), 1e-12);
  EXPECT_LT ((raw.xyz[1] - Eigen::Vector3d (-1.5, 0.25, -0.5)).norm(), 1e-12);
  EXPECT_EQ (raw.intensity[0], 500.f);
  EXPECT_TRUE (raw.stations[0].points_in_scanner_frame);
  EXPECT_LT (
      (raw.stations[0].orientation * raw.xyz[1] + raw.stations[0].position - t.xyz[1])
          .norm(),
      1e-9);
}

TEST (E57Reader, FilesWithoutPointsAreEmptyNotErrors)
{
  e57_test::FileBuilder none;
  PointTable t;
  t.xyz.push_back (Eigen::Vector3d::Ones());
  pcl_ext::io::loadE57 (writeE57File ("none.e57", none.finish (e57_test::e57Xml (""))),
                        t);
  EXPECT_TRUE (t.empty());
  EXPECT_TRUE (t.stations.empty());
  e57_test::FileBuilder zero;
  const std::uint64_t at = zero.addSection ({});
  pcl_ext::io::loadE57 (
      writeE57File ("zero.e57", zero.finish (e57_test::e57Xml (scanAXml (at, 0)))), t);
  EXPECT_TRUE (t.empty());
  ASSERT_EQ (t.stations.size(), 1u);
  EXPECT_EQ (t.stations[0].name, "A");
}

TEST (E57Reader, MalformedFilesAreRefusedWithoutCrashing)
{
  const std::string good = twoScans();
  const auto expectRefused = [] (const std::string& name,
                                 const std::string& bytes,
                                 const std::string& fragment) {
    const std::string path = writeE57File (name, bytes);
    PointTable t;
    t.xyz.push_back (Eigen::Vector3d::Ones());
    expectReadError ([&] { pcl_ext::io::loadE57 (path, t); }, path, 0, fragment);
    EXPECT_EQ (t.size(), 1u) << "the table is untouched";
  };
  const auto edited = [&good] (std::size_t at, std::uint64_t value, int bytes) {
    std::string f = good;
    for (int i = 0; i < bytes; ++i)
      f[at + i] = static_cast<char> ((value >> (8 * i)) & 0xFFu);
    e57_test::resealPages (f);
    return f;
  };

  std::string f = good;
  f[0] = 'X';
  expectRefused ("signature.e57", f, "signature");
  f = good;
  f[200] = static_cast<char> (f[200] ^ 0x40); // inside scan A's data, page 0
  expectRefused ("crc0.e57", f, "bad checksum on page 0");
  f = good;
  f[f.size() - 1030] = static_cast<char> (f[f.size() - 1030] ^ 1);
  expectRefused ("crc.e57", f, "bad checksum on page");
  expectRefused ("empty.e57", "", "too short");
  expectRefused ("partial.e57", good.substr (0, good.size() - 100), "whole number");
  expectRefused ("truncated.e57", good.substr (0, good.size() - 1024), "truncated");
  expectRefused ("version.e57", edited (8, 2, 4), "version 2");
  expectRefused ("xml_offset.e57", edited (24, 1u << 30, 8), "XML section");
  expectRefused ("xml_length.e57", edited (32, 1u << 30, 8), "XML section");
  expectRefused ("page_size.e57", edited (40, 2048, 8), "page size");
  // Scan A's section header at logical 48: id, then its data offset.
  expectRefused ("section_id.e57", edited (48, 7, 1), "section header");
  expectRefused ("data_offset.e57", edited (48 + 16, 1u << 20, 8), "data offset");
  expectRefused ("section_length.e57", edited (48 + 8, 1u << 20, 8), "section length");
  // The first packet's length field (logical 80 + 2) pointing far past the section.
  expectRefused (
      "packet_length.e57", edited (82, 0xFFFF, 2), "past the end of the section");
  expectRefused ("packet_type.e57", edited (80, 9, 1), "unknown packet type");
  expectRefused ("bytestreams.e57", edited (84, 3, 2), "3 bytestreams");

  // An XML that lies: more records than the data holds; far more than the section
  // can hold; a fileOffset past the end; a constant that is not.
  expectRefused ("count.e57", twoScans (6), "exceeds the data");
  expectRefused (
      "huge_count.e57", twoScans (1000000000000ull), "exceeds what the section");
  e57_test::FileBuilder lying;
  lying.addSection (twoPackets (scanAStreams()));
  expectRefused ("offset.e57",
                 lying.finish (e57_test::e57Xml (scanAXml (1u << 30, 5))),
                 "not inside the file");
  e57_test::FileBuilder range;
  const std::uint64_t at = range.addSection (twoPackets (scanAStreams (3)));
  expectRefused ("range.e57",
                 range.finish (e57_test::e57Xml (scanAXml (at, 5))),
                 "cartesianInvalidState lies outside");
  e57_test::FileBuilder string_type;
  const std::uint64_t at2 = string_type.addSection (twoPackets (scanAStreams()));
  expectRefused ("string.e57",
                 string_type.finish (e57_test::e57Xml (scanAXml (at2, 5, "String"))),
                 "String elements");
  const std::string folder = freshFolder ("e57_reader") + "/a_folder.e57";
  ::mkdir (folder.c_str(), 0755);
  PointTable t;
  expectReadError ([&] { pcl_ext::io::loadE57 (folder, t); }, folder, 0, "folder");
}
