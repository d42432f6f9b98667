/*
 * The tools on the real samples of issue 29 (label `data`, skipped without
 * ../shared/data): LAZ in, LAS out with the input's scale, offset and dimensions; E57
 * in, LAS out in the file's frame.
 */
#include "../app_test.h"

#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/las_reader.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <filesystem>
#include <algorithm>
#include <cstdlib>
#include <set>

namespace {
const std::string kData = PCL_EXT_SHARED_DATA_DIR;

class RealFormats : public pcl_ext::test::AppTest {
protected:
  RealFormats() : AppTest (PCL_EXT_CLASSIFY_VARIANCE_EXE) {}
};
} // namespace

TEST_F (RealFormats, ClassifyVarianceLazToLas)
{
  const std::string input = kData + "/las_samples/simple.laz";
  if (!std::filesystem::exists (input))
    GTEST_SKIP() << "no " << input;
  ASSERT_EQ (run (input + " " + path ("out.las") + " -threads 2"), 0) << output_;
  pcl_ext::io::PointFile in, out;
  pcl_ext::io::loadPointFile (input, in);
  pcl_ext::io::loadPointFile (path ("out.las"), out);
  EXPECT_EQ (out.las->header.scale, in.las->header.scale);
  EXPECT_EQ (out.las->header.offset, in.las->header.offset);
  EXPECT_EQ (out.las->header.pointFormat(), in.las->header.pointFormat());
  // Every dimension of the input, with its values; the classes in lv_class.
  for (const auto& f : in.cloud.fields) {
    ASSERT_GE (pcl::getFieldIndex (out.cloud, f.name), 0) << f.name;
    std::vector<std::uint32_t> a, b;
    if (f.name != "x" && f.name != "y" && f.name != "z" && f.name != "gps_time" &&
        f.name != "rgb" && pcl_ext::io::getLabelField (in.cloud, f.name, a))
      EXPECT_TRUE (pcl_ext::io::getLabelField (out.cloud, f.name, b) && a == b)
          << f.name;
  }
  std::vector<std::uint32_t> classes;
  ASSERT_TRUE (pcl_ext::io::getLabelField (out.cloud, "lv_class", classes));
  const std::set<std::uint32_t> seen (classes.begin(), classes.end());
  EXPECT_TRUE (seen.count (1)); // surface points on a real scan
}

TEST_F (RealFormats, SegmentVarianceE57ToLas)
{
  const std::string input = kData + "/tls_exchange_samples/bunnyDouble.e57";
  if (!std::filesystem::exists (input))
    GTEST_SKIP() << "no " << input;
  const std::string command = std::string (PCL_EXT_SEGMENT_VARIANCE_EXE) + " " + input +
                              " " + path ("out.las") + " -threads 2 > " +
                              path ("seg.txt") + " 2>&1";
  ASSERT_EQ (std::system (command.c_str()), 0);
  pcl_ext::io::PointFile in, out;
  pcl_ext::io::loadPointFile (input, in);
  pcl_ext::io::loadPointFile (path ("out.las"), out);
  ASSERT_EQ (out.cloud.width, in.cloud.width);
  std::vector<std::uint32_t> segments;
  ASSERT_TRUE (pcl_ext::io::getLabelField (out.cloud, "segment", segments));
  EXPECT_GT (*std::max_element (segments.begin(), segments.end()), 1u);
  // Coordinates in the file's frame to the LAS output's 1 mm.
  pcl::PointCloud<pcl::PointXYZ> a, b;
  pcl::fromPCLPointCloud2 (in.cloud, a);
  pcl::fromPCLPointCloud2 (out.cloud, b);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max (worst,
                      ((in.origin + a[i].getVector3fMap().cast<double>()) -
                       (out.origin + b[i].getVector3fMap().cast<double>()))
                          .cwiseAbs()
                          .maxCoeff());
  EXPECT_LE (worst, 0.0005 + 1e-6);
}
