/*
 * pcl_ext_convert between the formats (small LAS files written by the test with the
 * project's writer; the LAZ samples of ../shared/data when present): every field and
 * the double-precision frame kept, outputs it cannot write refused before any work.
 */
#include "../app_test.h"

#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {
const std::string kData = PCL_EXT_SHARED_DATA_DIR;

/** The file coordinates of every point: origin + x y z. */
std::vector<Eigen::Vector3d>
fileCoordinates (const pcl_ext::io::PointFile& file)
{
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::fromPCLPointCloud2 (file.cloud, xyz);
  std::vector<Eigen::Vector3d> result;
  for (const auto& p : xyz)
    result.push_back (file.origin + p.getVector3fMap().cast<double>());
  return result;
}

double
largestDistance (const std::vector<Eigen::Vector3d>& a,
                 const std::vector<Eigen::Vector3d>& b)
{
  EXPECT_EQ (a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    worst = std::max (worst, (a[i] - b[i]).cwiseAbs().maxCoeff());
  return worst;
}

class ConvertFormats : public pcl_ext::test::AppTest {
protected:
  ConvertFormats() : AppTest (PCL_EXT_CONVERT_EXE) {}

  /** A georeferenced LAS file (UTM-like coordinates, 1 mm scale) of 60 points with
   * colour and ASPRS classes 2 (ground) and 6 (building). */
  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    pcl::PointCloud<pcl::PointXYZRGBL> points;
    for (int i = 0; i < 60; ++i) {
      pcl::PointXYZRGBL p;
      p.x = 0.125f * static_cast<float> (i % 10);
      p.y = 0.25f * static_cast<float> (i / 10);
      p.z = i < 30 ? 0.0f : 3.5f;
      p.r = static_cast<std::uint8_t> (4 * i);
      p.g = 7;
      p.b = 200;
      p.label = i < 30 ? 2 : 6;
      points.push_back (p);
    }
    pcl::PCLPointCloud2 cloud;
    pcl::toPCLPointCloud2 (points, cloud);
    for (auto& f : cloud.fields)
      if (f.name == "label")
        f.name = "classification";
    ASSERT_TRUE (pcl_ext::io::savePointFile (path ("in.las"), cloud, kOrigin));
    pcl_ext::io::loadPointFile (path ("in.las"), in_);
  }

  const Eigen::Vector3d kOrigin{512000.0, 5400000.0, 210.0};
  pcl_ext::io::PointFile in_;
};
} // namespace

TEST_F (ConvertFormats, LasToEveryOutputKeepsFieldsAndFrame)
{
  for (const std::string name : {"out.pcd", "out.ply", "out.las"}) {
    SCOPED_TRACE (name);
    ASSERT_EQ (run (path ("in.las") + " " + path (name)), 0) << output_;
    pcl_ext::io::PointFile out;
    pcl_ext::io::loadPointFile (path (name), out);
    // The file's coordinates to well under the LAS millimetre.
    EXPECT_LE (largestDistance (fileCoordinates (in_), fileCoordinates (out)), 1e-6);
    // Every field of the input with its values (the LAS integers only in LAS).
    for (const auto& f : in_.cloud.fields) {
      if (f.name == "x" || f.name == "y" || f.name == "z" ||
          (name != "out.las" && f.name.rfind ("las_", 0) == 0))
        continue;
      ASSERT_GE (pcl::getFieldIndex (out.cloud, f.name), 0) << f.name;
      std::vector<std::uint32_t> a, b;
      if (pcl_ext::io::getLabelField (in_.cloud, f.name, a))
        EXPECT_TRUE (pcl_ext::io::getLabelField (out.cloud, f.name, b) && a == b)
            << f.name;
    }
  }
  pcl_ext::io::PointFile las;
  pcl_ext::io::loadPointFile (path ("out.las"), las);
  EXPECT_EQ (las.las->header.offset, in_.las->header.offset);
  EXPECT_EQ (las.las->header.scale, in_.las->header.scale);
  EXPECT_EQ (las.las->header.pointFormat(), in_.las->header.pointFormat());
  // -ascii writes text PLY.
  ASSERT_EQ (run (path ("in.las") + " " + path ("text.ply") + " -ascii"), 0) << output_;
  std::ifstream text (path ("text.ply"));
  std::string magic, format;
  text >> magic >> format >> format;
  EXPECT_EQ (format, "ascii");
}

TEST_F (ConvertFormats, LasClassesMappedFromAnyField)
{
  {
    std::ofstream (path ("classes.txt")) << "1 ground : 2\n2 building : 6\n";
  }
  ASSERT_EQ (run (path ("in.las") + " " + path ("m.pcd") + " -classes " +
                  path ("classes.txt") + " -label_field classification"),
             0)
      << output_;
  pcl_ext::io::PointFile out;
  pcl_ext::io::loadPointFile (path ("m.pcd"), out);
  std::vector<std::uint32_t> labels;
  ASSERT_TRUE (pcl_ext::io::getLabelField (out.cloud, "label", labels));
  ASSERT_EQ (labels.size(), 60u);
  EXPECT_EQ (labels.front(), 1u);
  EXPECT_EQ (labels.back(), 2u);
}

TEST_F (ConvertFormats, TextToLasStoresTheOriginAsOffset)
{
  const std::string input = std::string (PCL_EXT_TEST_DATA_DIR) + "/points_georef.txt";
  ASSERT_EQ (run (input + " " + path ("g.las") + " -columns x,y,z,label"), 0)
      << output_;
  pcl_ext::io::PointFile out;
  pcl_ext::io::loadPointFile (path ("g.las"), out);
  const auto xyz = fileCoordinates (out);
  ASSERT_EQ (xyz.size(), 3u);
  EXPECT_NEAR (xyz[0].x(), 119305.125, 5e-4);
  EXPECT_NEAR (xyz[0].y(), 485140.5, 5e-4);
  EXPECT_NEAR (xyz[2].y(), 485199.999, 5e-4);
  std::vector<std::uint32_t> labels;
  ASSERT_TRUE (pcl_ext::io::getLabelField (out.cloud, "label", labels));
  EXPECT_EQ (labels[1], 6u);
}

TEST_F (ConvertFormats, UnwritableOutputRefusedBeforeAnyWork)
{
  // The input does not exist: the refusal names the output, so nothing was read.
  for (const std::string name : {"o.laz", "o.e57", "o.xyz", "o"}) {
    SCOPED_TRACE (name);
    EXPECT_EQ (run (path ("missing.las") + " " + path (name)), 1);
    EXPECT_NE (output_.find (path (name)), std::string::npos) << output_;
    EXPECT_EQ (output_.find ("Loading"), std::string::npos) << output_;
    EXPECT_FALSE (exists (name));
  }
  EXPECT_EQ (run (path ("in.las") + " " + path ("o.laz")), 1);
  EXPECT_NE (output_.find ("writing LAZ is not supported"), std::string::npos)
      << output_;
  EXPECT_FALSE (exists ("o.laz"));
  // Options of text input are refused for a LAS input, -ascii for a LAS output.
  EXPECT_EQ (run (path ("in.las") + " " + path ("o.pcd") + " -columns x,y,z"), 1);
  EXPECT_EQ (run (path ("in.las") + " " + path ("o.pcd") + " -origin 1,2,3"), 1);
  EXPECT_EQ (run (path ("in.las") + " " + path ("o.las") + " -ascii"), 1);
  EXPECT_FALSE (exists ("o.pcd"));
  EXPECT_FALSE (exists ("o.las"));
}

TEST_F (ConvertFormats, LazSamplesMatchTheirLasTwins)
{
  const std::string laz = kData + "/las_samples/simple.laz";
  if (!std::filesystem::exists (laz))
    GTEST_SKIP() << "no " << laz;
  ASSERT_EQ (run (laz + " " + path ("simple.pcd")), 0) << output_;
  ASSERT_EQ (run (kData + "/las_samples/simple.las " + path ("twin.pcd")), 0)
      << output_;
  pcl_ext::io::PointFile a, b;
  pcl_ext::io::loadPointFile (path ("simple.pcd"), a);
  pcl_ext::io::loadPointFile (path ("twin.pcd"), b);
  EXPECT_EQ (a.cloud.fields.size(), b.cloud.fields.size());
  EXPECT_EQ (a.cloud.data, b.cloud.data);
  EXPECT_EQ (a.origin, b.origin);
}
