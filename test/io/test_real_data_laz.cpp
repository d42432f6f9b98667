/*
 * The LAZ decoder on the PDAL samples (labelled "data"; skipped when the data is
 * absent): decoded records against the uncompressed twins, byte for byte where the twin
 * has the same format and order, as sorted sets of point attributes where it has not
 * (COPC).
 */
#include "las_samples.h"

#include "laz_test_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace {
/** Decodes \a laz and expects its records to equal those of \a las, byte for byte. */
void
expectSameRecords (const std::string& laz, const std::string& las)
{
  const LasTestFile z = readLasTestFile (las_samples::path (laz));
  const LasTestFile s = readLasTestFile (las_samples::path (las));
  ASSERT_TRUE (z.compressed);
  ASSERT_FALSE (z.laszip_vlr.empty());
  ASSERT_EQ (z.point_format, s.point_format);
  ASSERT_EQ (z.record_length, s.record_length);
  ASSERT_EQ (z.point_count, s.point_count);
  const std::vector<std::uint8_t> expected = lasRecords (s);
  const std::vector<std::uint8_t> decoded = lazRecords (las_samples::path (laz), z);
  ASSERT_EQ (decoded.size(), expected.size());
  for (std::size_t i = 0; i < s.point_count; ++i)
    ASSERT_EQ (0,
               std::memcmp (decoded.data() + i * s.record_length,
                            expected.data() + i * s.record_length,
                            s.record_length))
        << "record " << i << " of " << laz;
}

/** The attributes formats 1, 3, 6, 7 share, coordinates scaled and offset to units of
 * 0.01 mm (a grid finer than, and aligned with, those of the samples, so that the same
 * point stored with other scales and offsets compares equal). */
using Attributes = std::tuple<std::int64_t,
                              std::int64_t,
                              std::int64_t,
                              std::uint16_t, // intensity
                              int,           // return number
                              int,           // number of returns
                              int,           // classification
                              std::uint16_t,
                              std::uint16_t,
                              std::uint16_t, // red, green, blue (0 without colour)
                              double>;       // GPS time

std::vector<Attributes>
attributes (const LasTestFile& f, const std::vector<std::uint8_t>& records)
{
  std::vector<Attributes> out;
  const bool v14 = f.point_format >= 6;
  const bool colour = f.point_format == 3 || f.point_format == 7;
  for (std::size_t i = 0; i < records.size() / f.record_length; ++i) {
    const std::vector<std::uint8_t> r (records.begin() + i * f.record_length,
                                       records.begin() + (i + 1) * f.record_length);
    std::int64_t xyz[3];
    for (int k = 0; k < 3; ++k)
      xyz[k] = std::llround (
          (lasField<std::int32_t> (r, 4 * k) * f.scale[k] + f.offset[k]) * 1e5);
    const std::uint16_t intensity = lasField<std::uint16_t> (r, 12);
    const int ret = v14 ? (r[14] & 15) : (r[14] & 7);
    const int returns = v14 ? (r[14] >> 4) : ((r[14] >> 3) & 7);
    const int cls = v14 ? r[16] : (r[15] & 31);
    const double gps = lasField<double> (r, v14 ? 22 : 20);
    std::uint16_t rgb[3] = {0, 0, 0};
    if (colour)
      for (int k = 0; k < 3; ++k)
        rgb[k] = lasField<std::uint16_t> (r, (v14 ? 30 : 28) + 2 * k);
    out.emplace_back (xyz[0],
                      xyz[1],
                      xyz[2],
                      intensity,
                      ret,
                      returns,
                      cls,
                      rgb[0],
                      rgb[1],
                      rgb[2],
                      gps);
  }
  std::sort (out.begin(), out.end());
  return out;
}
} // namespace

TEST (RealDataLaz, SimpleMatchesItsLasTwin)
{
  REQUIRE_LAS_SAMPLE ("simple.laz");
  expectSameRecords ("simple.laz", "simple.las");
}

TEST (RealDataLaz, AutzenTrimMatchesItsLasTwin)
{
  REQUIRE_LAS_SAMPLE ("autzen_trim.laz");
  expectSameRecords ("autzen_trim.laz", "autzen_trim.las");
}

TEST (RealDataLaz, AutzenTrimDecodesInAnyBlockSize)
{
  REQUIRE_LAS_SAMPLE ("autzen_trim.laz");
  const LasTestFile z = readLasTestFile (las_samples::path ("autzen_trim.laz"));
  // Blocks that straddle the chunks of 50,000 points.
  EXPECT_EQ (lazRecords (las_samples::path ("autzen_trim.laz"), z, 1),
             lazRecords (las_samples::path ("autzen_trim.laz"), z, 49999));
}

TEST (RealDataLaz, LoneStarMatchesReturnCountsAndBounds)
{
  REQUIRE_LAS_SAMPLE ("lone-star.laz");
  REQUIRE_LAS_SAMPLE ("lone-star.copc.laz");
  const LasTestFile z = readLasTestFile (las_samples::path ("lone-star.laz"));
  // lone-star.laz states its bounds rounded to a few millimetres; the COPC copy of the
  // same points states them exactly.
  const LasTestFile c = readLasTestFile (las_samples::path ("lone-star.copc.laz"));
  ASSERT_EQ (z.point_format, 1);
  ASSERT_EQ (z.point_count, 518862u);
  const std::vector<std::uint8_t> records =
      lazRecords (las_samples::path ("lone-star.laz"), z);
  ASSERT_EQ (records.size(), z.point_count * z.record_length);
  // The points by return of the header, the bounds of the COPC copy.
  std::int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX};
  std::int32_t hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
  std::uint32_t by_return[5] = {0, 0, 0, 0, 0};
  const std::vector<std::uint8_t> r (records.begin(), records.end());
  for (std::size_t i = 0; i < z.point_count; ++i) {
    for (int k = 0; k < 3; ++k) {
      const auto v = lasField<std::int32_t> (r, i * z.record_length + 4 * k);
      lo[k] = std::min (lo[k], v);
      hi[k] = std::max (hi[k], v);
    }
    const int ret = r[i * z.record_length + 14] & 7;
    if (ret >= 1 && ret <= 5)
      ++by_return[ret - 1];
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR (hi[k] * z.scale[k] + z.offset[k], c.max_min[2 * k], z.scale[k] / 2);
    EXPECT_NEAR (
        lo[k] * z.scale[k] + z.offset[k], c.max_min[2 * k + 1], z.scale[k] / 2);
  }
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ (by_return[k], z.points_by_return[k]) << "return " << k + 1;
}

TEST (RealDataLaz, ColourCopcHoldsThePointsOfItsLasTwin)
{
  REQUIRE_LAS_SAMPLE ("1.2-with-color.copc.laz");
  const LasTestFile z = readLasTestFile (las_samples::path ("1.2-with-color.copc.laz"));
  const LasTestFile s = readLasTestFile (las_samples::path ("1.2-with-color.las"));
  ASSERT_EQ (z.point_format, 7);
  ASSERT_EQ (s.point_format, 3);
  const auto decoded =
      attributes (z, lazRecords (las_samples::path ("1.2-with-color.copc.laz"), z));
  ASSERT_EQ (decoded.size(), 1065u);
  EXPECT_TRUE (decoded == attributes (s, lasRecords (s)));
}

TEST (RealDataLaz, LoneStarCopcHoldsThePointsOfTheLaz)
{
  REQUIRE_LAS_SAMPLE ("lone-star.copc.laz");
  const LasTestFile c = readLasTestFile (las_samples::path ("lone-star.copc.laz"));
  const LasTestFile z = readLasTestFile (las_samples::path ("lone-star.laz"));
  ASSERT_EQ (c.point_format, 6);
  const auto copc =
      attributes (c, lazRecords (las_samples::path ("lone-star.copc.laz"), c));
  ASSERT_EQ (copc.size(), 518862u);
  EXPECT_TRUE (copc ==
               attributes (z, lazRecords (las_samples::path ("lone-star.laz"), z)));
}
