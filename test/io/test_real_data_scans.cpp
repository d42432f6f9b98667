/*
 * The E57, PTX and PTS readers on the public sample files of
 * tls_exchange_samples (labelled "data"; skipped when the data is absent). The values
 * checked are those the files declare in their XML or headers (see SOURCE.md there).
 */
#include <pcl_ext/io/e57_reader.h>
#include <pcl_ext/io/ptx_reader.h>

#include "test_helpers.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <sys/stat.h>

using pcl_ext::io::PointTable;

namespace {
std::string
sample (const std::string& name)
{
  return std::string (PCL_EXT_SHARED_DATA_DIR) + "/tls_exchange_samples/" + name;
}

bool
scanFileExists (const std::string& path)
{
  struct stat st;
  return ::stat (path.c_str(), &st) == 0;
}

#define REQUIRE_SAMPLE(path)                                                           \
  if (!scanFileExists (path))                                                          \
  GTEST_SKIP() << "sample not found: " << (path)

/** Every point inside the box (the scan's declared cartesianBounds), to float
 * precision. */
void
expectInside (const PointTable& t,
              std::size_t from,
              std::size_t to,
              const Eigen::Vector3d& min,
              const Eigen::Vector3d& max)
{
  for (std::size_t i = from; i < to; ++i)
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE (t.xyz[i][a], min[a] - 1e-5) << i;
      EXPECT_LE (t.xyz[i][a], max[a] + 1e-5) << i;
    }
}

/** X, Y, Z of a LAS 1.2 file, read minimally: header fields at their fixed offsets. */
std::vector<Eigen::Vector3d>
readLasCoordinates (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  const std::string bytes ((std::istreambuf_iterator<char> (in)),
                           std::istreambuf_iterator<char>());
  std::vector<Eigen::Vector3d> points;
  if (bytes.size() < 227)
    return points;
  std::uint32_t offset, count;
  std::uint16_t length;
  double scale[3], origin[3];
  std::memcpy (&offset, bytes.data() + 96, 4);
  std::memcpy (&length, bytes.data() + 105, 2);
  std::memcpy (&count, bytes.data() + 107, 4);
  std::memcpy (scale, bytes.data() + 131, 24);
  std::memcpy (origin, bytes.data() + 155, 24);
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::size_t at = offset + static_cast<std::size_t> (i) * length;
    if (at + 12 > bytes.size())
      break;
    std::int32_t xyz[3];
    std::memcpy (xyz, bytes.data() + at, 12);
    points.emplace_back (xyz[0] * scale[0] + origin[0],
                         xyz[1] * scale[1] + origin[1],
                         xyz[2] * scale[2] + origin[2]);
  }
  return points;
}

bool
lexicographic (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::lexicographical_compare (a.data(), a.data() + 3, b.data(), b.data() + 3);
}
} // namespace

TEST (RealDataScans, BunnyDoubleAndScaledInt32Agree)
{
  const std::string d = sample ("bunnyDouble.e57"), i = sample ("bunnyInt32.e57");
  REQUIRE_SAMPLE (d);
  REQUIRE_SAMPLE (i);
  PointTable a, b;
  pcl_ext::io::loadE57 (d, a);
  pcl_ext::io::loadE57 (i, b);
  // recordCount="30571" in both, no invalid point.
  ASSERT_EQ (a.size(), 30571u);
  ASSERT_EQ (b.size(), 30571u);
  ASSERT_EQ (a.stations.size(), 1u);
  EXPECT_EQ (a.stations[0].name, "bunny");
  // The int32 file's scale is 1e-6: equal to half a step.
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    worst = std::max (worst, (a.xyz[k] - b.xyz[k]).cwiseAbs().maxCoeff());
  EXPECT_LE (worst, 0.5e-6 + 1e-12);
  // Inside the prototype's declared minimum / maximum.
  expectInside (a,
                0,
                a.size(),
                Eigen::Vector3d::Constant (-9.4689e-2),
                Eigen::Vector3d::Constant (1.87321e-1));
}

TEST (RealDataScans, ColouredCubeAndColourRepresentation)
{
  const std::string cube = sample ("ColouredCubeFloat.e57");
  REQUIRE_SAMPLE (cube);
  PointTable t;
  pcl_ext::io::loadE57 (cube, t);
  ASSERT_EQ (t.size(), 7680u); // recordCount
  ASSERT_EQ (t.rgb.size(), t.size());
  EXPECT_TRUE (t.intensity.empty());
  expectInside (t,
                0,
                t.size(),
                Eigen::Vector3d::Constant (-0.5),
                Eigen::Vector3d::Constant (0.5));
  std::set<std::array<std::uint8_t, 3>> colours (t.rgb.begin(), t.rgb.end());
  EXPECT_GT (colours.size(), 1u);

  const std::string rep = sample ("ColourRepresentation.e57");
  REQUIRE_SAMPLE (rep);
  pcl_ext::io::loadE57 (rep, t);
  ASSERT_EQ (t.size(), 153u);
  ASSERT_EQ (t.rgb.size(), 153u);
  // ScaledInteger -500..500 at 0.001: the cube [-0.5, 0.5].
  expectInside (t,
                0,
                t.size(),
                Eigen::Vector3d::Constant (-0.5),
                Eigen::Vector3d::Constant (0.5));
  // 16-bit colour (prototype 0..65535, no colorLimits) mapped to 0..255: some channel
  // reaches the top of the range.
  std::uint8_t top = 0;
  for (const auto& c : t.rgb)
    top = std::max ({top, c[0], c[1], c[2]});
  EXPECT_GE (top, 254);
}

TEST (RealDataScans, TwoScansEachWithItsStation)
{
  const std::string ab = sample ("A_B.e57");
  REQUIRE_SAMPLE (ab);
  PointTable t;
  pcl_ext::io::loadE57 (ab, t);
  ASSERT_EQ (t.size(), 6u); // recordCount 2 + 4
  ASSERT_EQ (t.stations.size(), 2u);
  EXPECT_EQ (t.stations[0].name, "B2 - Cloud");
  EXPECT_EQ (t.stations[1].name, "A4 - Cloud");
  EXPECT_EQ (t.stations[0].guid, "{d3d0f9b8-6722-4ee4-9ee9-46a7a81f732c}");
  EXPECT_EQ (t.scan, (std::vector<std::uint16_t>{0, 0, 1, 1, 1, 1}));
  // No pose in the file: identity.
  EXPECT_EQ (t.stations[1].position, Eigen::Vector3d::Zero());
  // The declared cartesianBounds of each scan.
  expectInside (t,
                0,
                2,
                Eigen::Vector3d (-42.6423, 1.8726, 0.5101),
                Eigen::Vector3d (-42.6395, 2.0578, 0.6667));
  expectInside (t,
                2,
                6,
                Eigen::Vector3d (-44.9522, -1.3493, -0.6077),
                Eigen::Vector3d (-44.3001, -0.8860, 0.3694));
  // Scan B2's intensity over its intensityLimits 0 .. 0.873: the brightest point is 1.
  ASSERT_EQ (t.intensity.size(), 6u);
  EXPECT_FLOAT_EQ (std::max (t.intensity[0], t.intensity[1]), 1.0f);

  const std::string a4 = sample ("A4.e57");
  REQUIRE_SAMPLE (a4);
  PointTable a;
  pcl_ext::io::loadE57 (a4, a);
  ASSERT_EQ (a.size(), 4u);
  // Same points as the A4 scan of A_B.e57.
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_EQ (a.xyz[k], t.xyz[2 + k]);
  // Degenerate intensityLimits (0 .. 0): kept as written.
  EXPECT_EQ (a.intensity[0], 0.f);

  const std::string dims = sample ("A_B_different_dims.e57");
  REQUIRE_SAMPLE (dims);
  pcl_ext::io::loadE57 (dims, t);
  ASSERT_EQ (t.size(), 2u);
  EXPECT_EQ (t.stations[0].name, "no-color");
  EXPECT_EQ (t.stations[1].name, "with-color");
  // The one point of each scan, as its prototype declares (single precision).
  EXPECT_NEAR (t.xyz[0].x(), 84.174026, 1e-5);
  EXPECT_NEAR (t.xyz[0].y(), 537.27032, 1e-4);
  EXPECT_NEAR (t.xyz[1].z(), 4.5902758, 1e-6);
  // Intensity in the first scan only (its limits are degenerate: kept as written),
  // colour in the second only.
  EXPECT_NEAR (t.intensity[0], 0.75964826, 1e-7);
  EXPECT_TRUE (std::isnan (t.intensity[1]));
  EXPECT_EQ (t.rgb[0], (std::array<std::uint8_t, 3>{0, 0, 0}));
}

TEST (RealDataScans, EdgeCasesAndBrokenFiles)
{
  const std::string zero = sample ("ZeroPoints.e57"), empty = sample ("empty.e57");
  REQUIRE_SAMPLE (zero);
  REQUIRE_SAMPLE (empty);
  PointTable t;
  pcl_ext::io::loadE57 (zero, t);
  EXPECT_TRUE (t.empty());
  EXPECT_EQ (t.stations.size(), 1u);
  pcl_ext::io::loadE57 (empty, t);
  EXPECT_TRUE (t.empty());
  EXPECT_TRUE (t.stations.empty());
  const std::string cv = sample ("InvalidCVHeader.e57"), crc = sample ("bad-crc.e57");
  REQUIRE_SAMPLE (cv);
  REQUIRE_SAMPLE (crc);
  expectReadError ([&] { pcl_ext::io::loadE57 (cv, t); }, cv, 0, "section header");
  expectReadError ([&] { pcl_ext::io::loadE57 (crc, t); }, crc, 0, "bad checksum");
}

TEST (RealDataScans, PtxScansAndTheirTransforms)
{
  const std::string multiple = sample ("multiple-and-transform.ptx");
  REQUIRE_SAMPLE (multiple);
  PointTable t;
  pcl_ext::io::loadPTX (multiple, t);
  ASSERT_EQ (t.size(), 8u);
  ASSERT_EQ (t.stations.size(), 2u);
  EXPECT_EQ (t.stations[0].position, Eigen::Vector3d (600000, 800000, 400));
  // Scan 1 is scan 2 moved by (-600000, -800000, -400) and z halved: its transform
  // brings it back onto scan 2.
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_LT ((t.xyz[k] - t.xyz[4 + k]).norm(), 1e-6) << k;
  EXPECT_TRUE (t.rgb.empty());

  const std::string no_colour = sample ("no-color.ptx");
  REQUIRE_SAMPLE (no_colour);
  pcl_ext::io::loadPTX (no_colour, t);
  ASSERT_EQ (t.size(), 15u); // 15 columns x 1 row
  EXPECT_TRUE (t.rgb.empty());
  EXPECT_EQ (t.column.back(), 14);
  EXPECT_FLOAT_EQ (t.intensity[0], 0.034912f);
}

TEST (RealDataScans, PtxWithColourMatchesItsLasTwin)
{
  const std::string ptx = sample ("1.2-with-color.ptx");
  const std::string las =
      std::string (PCL_EXT_SHARED_DATA_DIR) + "/las_samples/1.2-with-color.las";
  REQUIRE_SAMPLE (ptx);
  PointTable t;
  pcl_ext::io::loadPTX (ptx, t);
  ASSERT_EQ (t.size(), 1065u);
  ASSERT_EQ (t.rgb.size(), 1065u);
  EXPECT_EQ (t.rgb[0], (std::array<std::uint8_t, 3>{68, 77, 88}));
  REQUIRE_SAMPLE (las);
  std::vector<Eigen::Vector3d> expected = readLasCoordinates (las);
  ASSERT_EQ (expected.size(), 1065u);
  std::vector<Eigen::Vector3d> got = t.xyz;
  std::sort (got.begin(), got.end(), lexicographic);
  std::sort (expected.begin(), expected.end(), lexicographic);
  double worst = 0.0;
  for (std::size_t k = 0; k < got.size(); ++k)
    worst = std::max (worst, (got[k] - expected[k]).cwiseAbs().maxCoeff());
  EXPECT_LE (worst, 0.005 + 1e-9); // half the LAS scale of 0.01
}

TEST (RealDataScans, PtsWithCount)
{
  const std::string pts = sample ("autzen.pts");
  REQUIRE_SAMPLE (pts);
  PointTable t;
  pcl_ext::io::loadPTS (pts, t);
  ASSERT_EQ (t.size(), 10u); // the count line
  EXPECT_EQ (t.xyz[0], Eigen::Vector3d (636110.300003, 849345.050003, 512.139999));
  EXPECT_EQ (t.intensity[0], -1613.f);
  EXPECT_EQ (t.rgb[9], (std::array<std::uint8_t, 3>{114, 127, 100}));
}
