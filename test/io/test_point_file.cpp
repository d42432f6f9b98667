/*
 * loadPointFile / savePointFile: formats told by their content when the extension
 * lies, double PCD and PLY coordinates read and written back, LAS round trips through
 * the one entry point, ASCII headers, and the refused outputs.
 */
#include <pcl_ext/io/las_writer.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include "las_test_files.h"
#include "temp_folder.h"
#include "test_helpers.h"

#include <cmath>
#include <cstdio>
#include <fstream>

using las_test::hasField;
using las_test::value;
using pcl_ext::io::PointFile;
using pcl_ext::io::PointFileFormat;

namespace {
const std::string&
pointFileFolder ()
{
  static const std::string dir = freshFolder ("point_file");
  return dir;
}

std::string
pointFilePath (const std::string& name)
{
  return pointFileFolder() + "/" + name;
}

/** A 10 x 10 grid of points at a UTM-like place: file coordinate = base + (i, j, 0.1 i)
 * in metres, intensity i + j. */
pcl::PCLPointCloud2
gridCloud (std::uint8_t datatype, const Eigen::Vector3d& base)
{
  pcl::PCLPointCloud2 cloud;
  const std::uint32_t size = datatype == pcl::PCLPointField::FLOAT64 ? 8 : 4;
  const char* names[4] = {"x", "y", "z", "intensity"};
  for (std::uint32_t k = 0; k < 4; ++k) {
    pcl::PCLPointField f;
    f.name = names[k];
    f.offset = k * size;
    f.datatype = k < 3 ? datatype : pcl::PCLPointField::FLOAT32;
    f.count = 1;
    cloud.fields.push_back (f);
  }
  cloud.point_step = 3 * size + 4;
  cloud.width = 100;
  cloud.height = 1;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.is_dense = true;
  cloud.data.resize (cloud.row_step);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      std::uint8_t* p = cloud.data.data() + (i * 10 + j) * cloud.point_step;
      const double xyz[3] = {
          base.x() + i + 0.001, base.y() + j + 0.002, base.z() + 0.1 * i};
      for (int axis = 0; axis < 3; ++axis) {
        if (size == 8)
          std::memcpy (p + axis * 8, &xyz[axis], 8);
        else {
          const float f = static_cast<float> (xyz[axis]);
          std::memcpy (p + axis * 4, &f, 4);
        }
      }
      const float intensity = static_cast<float> (i + j);
      std::memcpy (p + 3 * size, &intensity, 4);
    }
  return cloud;
}

/** File coordinate of point \a i of \a file (origin + local float). */
Eigen::Vector3d
fileCoordinate (const PointFile& file, std::size_t i)
{
  return file.origin + Eigen::Vector3d (value<float> (file.cloud, "x", i),
                                        value<float> (file.cloud, "y", i),
                                        value<float> (file.cloud, "z", i));
}

void
copyFile (const std::string& from, const std::string& to)
{
  std::ifstream in (from, std::ios::binary);
  std::ofstream out (to, std::ios::binary);
  out << in.rdbuf();
}

/** Binary PCD and PLY files of a blob, as PDAL or PCL tools write them. */
int
writePcd (const std::string& path, const pcl::PCLPointCloud2& cloud)
{
  return pcl::PCDWriter().writeBinary (path, cloud);
}

int
writePly (const std::string& path, const pcl::PCLPointCloud2& cloud)
{
  return pcl::io::savePLYFile (
      path, cloud, Eigen::Vector4f::Zero(), Eigen::Quaternionf::Identity(), true);
}

const Eigen::Vector3d kUtm (500123.0, 6000456.0, 52.0);
} // namespace

TEST (PointFile, DoublePcdAndPlyAreReadToTheMillimetre)
{
  const pcl::PCLPointCloud2 grid = gridCloud (pcl::PCLPointField::FLOAT64, kUtm);
  ASSERT_EQ (writePcd (pointFilePath ("double.pcd"), grid), 0);
  ASSERT_EQ (writePly (pointFilePath ("double.ply"), grid), 0);
  for (const std::string name : {"double.pcd", "double.ply"}) {
    PointFile file;
    pcl_ext::io::loadPointFile (pointFilePath (name), file);
    EXPECT_TRUE (file.double_coordinates) << name;
    ASSERT_EQ (file.cloud.width * file.cloud.height, 100u) << name;
    // x y z are float, first, local; the origin is a round value near the data.
    EXPECT_EQ (file.cloud.fields[0].datatype, pcl::PCLPointField::FLOAT32);
    EXPECT_EQ (file.origin, Eigen::Vector3d (500100.0, 6000400.0, 0.0)) << name;
    for (std::size_t i = 0; i < 100; ++i) {
      const Eigen::Vector3d expected =
          kUtm + Eigen::Vector3d (i / 10 + 0.001, i % 10 + 0.002, 0.1 * (i / 10));
      EXPECT_LT ((fileCoordinate (file, i) - expected).cwiseAbs().maxCoeff(), 1e-4)
          << name << " point " << i;
      EXPECT_EQ (value<float> (file.cloud, "intensity", i), float (i / 10 + i % 10));
    }
    // A typed cloud reads it (PCL refuses FLOAT64 x y z into pcl::PointXYZ).
    pcl::PointCloud<pcl::PointXYZI> typed;
    pcl::fromPCLPointCloud2 (file.cloud, typed);
    EXPECT_NEAR (typed[99].x + file.origin.x(), kUtm.x() + 9.001, 1e-3);
  }
}

TEST (PointFile, DoubleOutputCarriesTheOrigin)
{
  const pcl::PCLPointCloud2 grid = gridCloud (pcl::PCLPointField::FLOAT64, kUtm);
  ASSERT_EQ (writePly (pointFilePath ("in.ply"), grid), 0);
  PointFile in;
  pcl_ext::io::loadPointFile (pointFilePath ("in.ply"), in);
  for (const std::string name : {"out.pcd", "out.ply"}) {
    ASSERT_TRUE (
        pcl_ext::io::savePointFile (pointFilePath (name), in.cloud, in.origin, &in));
    pcl::PCLPointCloud2 raw;
    if (name == "out.pcd")
      ASSERT_EQ (pcl::io::loadPCDFile (pointFilePath (name), raw), 0);
    else
      ASSERT_EQ (pcl::io::loadPLYFile (pointFilePath (name), raw), 0);
    ASSERT_EQ (raw.fields[0].datatype, pcl::PCLPointField::FLOAT64) << name;
    for (std::size_t i = 0; i < 100; ++i) {
      EXPECT_NEAR (value<double> (raw, "x", i), kUtm.x() + i / 10 + 0.001, 1e-4);
      EXPECT_NEAR (value<double> (raw, "y", i), kUtm.y() + i % 10 + 0.002, 1e-4);
    }
    EXPECT_TRUE (hasField (raw, "intensity"));
  }
}

TEST (PointFile, LocalFloatInputIsWrittenAsItWas)
{
  pcl::PointCloud<pcl::PointXYZL> cloud;
  for (int i = 0; i < 20; ++i) {
    pcl::PointXYZL p;
    p.x = 0.1f * i;
    p.y = -0.2f * i;
    p.z = 1.f;
    p.label = i;
    cloud.push_back (p);
  }
  ASSERT_EQ (pcl::io::savePCDFileBinary (pointFilePath ("local.pcd"), cloud), 0);
  PointFile in;
  pcl_ext::io::loadPointFile (pointFilePath ("local.pcd"), in);
  EXPECT_EQ (in.format, PointFileFormat::PCD);
  EXPECT_TRUE (in.origin.isZero());
  EXPECT_FALSE (in.double_coordinates);
  ASSERT_TRUE (pcl_ext::io::savePointFile (
      pointFilePath ("local_out.pcd"), in.cloud, in.origin, &in));
  pcl::PointCloud<pcl::PointXYZL> back;
  ASSERT_EQ (pcl::io::loadPCDFile (pointFilePath ("local_out.pcd"), back), 0);
  ASSERT_EQ (back.size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_EQ (back[i].x, cloud[i].x);
    EXPECT_EQ (back[i].label, cloud[i].label);
  }
}

TEST (PointFile, FloatCoordinatesFarFromTheOriginAreShiftedExactly)
{
  const pcl::PCLPointCloud2 grid = gridCloud (pcl::PCLPointField::FLOAT32, kUtm);
  ASSERT_EQ (writePcd (pointFilePath ("float_utm.pcd"), grid), 0);
  PointFile file;
  pcl_ext::io::loadPointFile (pointFilePath ("float_utm.pcd"),
                              file); // warns: float at UTM
  EXPECT_FALSE (file.double_coordinates);
  EXPECT_EQ (file.origin, Eigen::Vector3d (500100.0, 6000400.0, 0.0));
  for (std::size_t i = 0; i < 100; ++i)
    for (int axis = 0; axis < 3; ++axis) {
      const char* names[3] = {"x", "y", "z"};
      // The file's float, shifted: the sum gives it back bit for bit.
      EXPECT_EQ (static_cast<float> (fileCoordinate (file, i)[axis]),
                 value<float> (grid, names[axis], i));
    }
}

TEST (PointFile, FormatByContentWhenTheExtensionLies)
{
  // A LAS file named .pcd, a PCD named .ply, a PLY named .las.
  pcl::PCLPointCloud2 grid =
      gridCloud (pcl::PCLPointField::FLOAT32, Eigen::Vector3d::Zero());
  ASSERT_TRUE (pcl_ext::io::saveLas (
      pointFilePath ("real_las.pcd"), grid, Eigen::Vector3d::Zero()));
  ASSERT_EQ (
      pcl::PCDWriter().writeBinaryCompressed (pointFilePath ("real_pcd.ply"), grid), 0);
  ASSERT_EQ (writePly (pointFilePath ("real_ply.las"), grid), 0);
  {
    std::ofstream (pointFilePath ("points.las")) << "1 2 3\n4 5 6\n";
    std::ofstream (pointFilePath ("points.txt")) << "\"X\",\"Y\",\"Z\"\n1,2,3\n4,5,6\n";
    std::ofstream (pointFilePath ("scan.txt")) << "2\n1.0 2.0 3.0 0.5\n4 5 6 0.25\n";
    std::ofstream (pointFilePath ("random.pcd"))
        << std::string ("\x01\x02\0\x03garbage", 11);
  }
  using pcl_ext::io::detectPointFileFormat;
  EXPECT_EQ (detectPointFileFormat (pointFilePath ("real_las.pcd")),
             PointFileFormat::LAS);
  EXPECT_EQ (detectPointFileFormat (pointFilePath ("real_pcd.ply")),
             PointFileFormat::PCD);
  EXPECT_EQ (detectPointFileFormat (pointFilePath ("real_ply.las")),
             PointFileFormat::PLY);
  EXPECT_EQ (detectPointFileFormat (pointFilePath ("points.txt")),
             PointFileFormat::ASCII);
  EXPECT_EQ (detectPointFileFormat (pointFilePath ("scan.txt")), PointFileFormat::PTS);
  EXPECT_EQ (detectPointFileFormat (pointFilePath ("random.pcd")),
             PointFileFormat::Unknown);
  for (const std::string name : {"real_las.pcd", "real_pcd.ply", "real_ply.las"}) {
    PointFile file;
    pcl_ext::io::loadPointFile (pointFilePath (name), file);
    ASSERT_EQ (file.cloud.width * file.cloud.height, 100u) << name;
    EXPECT_NEAR (value<float> (file.cloud, "x", 99), 9.001f, 1e-3) << name;
    EXPECT_NEAR (value<float> (file.cloud, "intensity", 99), 18.f, 1e-6) << name;
    EXPECT_EQ (file.las.has_value(), name == "real_las.pcd");
  }
  PointFile before;
  pcl_ext::io::loadPointFile (pointFilePath ("points.txt"), before);
  EXPECT_EQ (before.format, PointFileFormat::ASCII);
  EXPECT_EQ (before.cloud.width, 2u);
  PointFile file = before;
  expectReadError (
      [&] { pcl_ext::io::loadPointFile (pointFilePath ("points.las"), file); },
      pointFilePath ("points.las"),
      0,
      "not a point file");
  expectReadError (
      [&] { pcl_ext::io::loadPointFile (pointFilePath ("random.pcd"), file); },
      pointFilePath ("random.pcd"),
      0,
      "not a point file");
  expectReadError (
      [&] { pcl_ext::io::loadPointFile (pointFilePath ("missing.las"), file); },
      pointFilePath ("missing.las"),
      0,
      "no such file");
  expectReadError ([&] { pcl_ext::io::loadPointFile (pointFileFolder(), file); },
                   pointFileFolder(),
                   0,
                   "folder");
  EXPECT_EQ (file.cloud.data, before.cloud.data); // untouched by the failures
}

TEST (PointFile, AsciiHeadersNameTheColumns)
{
  std::ofstream (pointFilePath ("pdal.csv"))
      << "\"X\",\"Y\",\"Z\",\"Intensity\",\"Red\",\"Green\",\"Blue\"\n"
         "500000.5,6000000.25,10,300,1,2,3\n500001.5,6000001.25,11,400,4,5,6\n";
  std::ofstream (pointFilePath ("cloudcompare.txt"))
      << "//X,Y,Z,R,G,B,Intensity\n1,2,3,10,20,30,0.5\n4,5,6,40,50,60,0.25\n";
  std::ofstream (pointFilePath ("cloudcompare_plain.txt"))
      << "1 2 3 10 20 30 0.5\n4 5 6 40 50 60 1200\n";
  for (const std::string name :
       {"pdal.csv", "cloudcompare.txt", "cloudcompare_plain.txt"}) {
    PointFile file;
    pcl_ext::io::loadPointFile (pointFilePath (name), file);
    ASSERT_EQ (file.cloud.width, 2u) << name;
    pcl::PointCloud<pcl::PointXYZRGB> rgb;
    pcl::fromPCLPointCloud2 (file.cloud, rgb);
    pcl::PointCloud<pcl::PointXYZI> xyzi;
    pcl::fromPCLPointCloud2 (file.cloud, xyzi);
    if (name == "pdal.csv") {
      EXPECT_EQ (file.origin, Eigen::Vector3d (500000.0, 6000000.0, 0.0));
      EXPECT_NEAR (fileCoordinate (file, 1).y(), 6000001.25, 1e-6);
      EXPECT_EQ (xyzi[1].intensity, 400.f);
      EXPECT_EQ (rgb[1].b, 6);
    }
    else {
      EXPECT_EQ (rgb[1].r, 40) << name;
      EXPECT_EQ (rgb[1].b, 60) << name;
      EXPECT_EQ (xyzi[0].intensity, 0.5f) << name;
    }
  }
}

TEST (PointFile, LasRoundTripKeepsEveryDimensionAndTheIntegers)
{
  // A LAS 1.4 format 7 file with a georeferenced offset, written by saveLas.
  pcl::PCLPointCloud2 grid = gridCloud (pcl::PCLPointField::FLOAT64, kUtm);
  PointFile made;
  {
    ASSERT_EQ (writePly (pointFilePath ("src.ply"), grid), 0);
    pcl_ext::io::loadPointFile (pointFilePath ("src.ply"), made);
  }
  ASSERT_TRUE (
      pcl_ext::io::saveLas (pointFilePath ("in.las"), made.cloud, made.origin));
  PointFile in;
  pcl_ext::io::loadPointFile (pointFilePath ("in.las"), in);
  ASSERT_TRUE (in.las.has_value());
  pcl::PCLPointCloud2 out = in.cloud;
  ASSERT_TRUE (
      pcl_ext::io::savePointFile (pointFilePath ("out.las"), out, in.origin, &in));
  PointFile back;
  pcl_ext::io::loadPointFile (pointFilePath ("out.las"), back);
  ASSERT_EQ (back.cloud.fields.size(), in.cloud.fields.size());
  for (std::size_t f = 0; f < in.cloud.fields.size(); ++f)
    EXPECT_EQ (back.cloud.fields[f].name, in.cloud.fields[f].name);
  EXPECT_EQ (back.cloud.data, in.cloud.data); // every dimension, every integer
  EXPECT_EQ (back.las->header.scale, in.las->header.scale);
  EXPECT_EQ (back.las->header.offset, in.las->header.offset);
}

TEST (PointFile, RefusedOutputs)
{
  std::string reason;
  EXPECT_TRUE (pcl_ext::io::canWritePointFile ("a.las"));
  EXPECT_TRUE (pcl_ext::io::canWritePointFile ("a.PCD"));
  EXPECT_TRUE (pcl_ext::io::canWritePointFile ("a.ply"));
  EXPECT_FALSE (pcl_ext::io::canWritePointFile ("a.laz", &reason));
  EXPECT_NE (reason.find ("writing LAZ is not supported"), std::string::npos) << reason;
  EXPECT_NE (reason.find (".las"), std::string::npos) << reason;
  EXPECT_FALSE (pcl_ext::io::canWritePointFile ("a.e57", &reason));
  EXPECT_NE (reason.find ("a.e57"), std::string::npos);
  EXPECT_FALSE (pcl_ext::io::canWritePointFile ("a", &reason));
  const pcl::PCLPointCloud2 grid =
      gridCloud (pcl::PCLPointField::FLOAT32, Eigen::Vector3d::Zero());
  EXPECT_FALSE (pcl_ext::io::savePointFile (
      pointFilePath ("x.laz"), grid, Eigen::Vector3d::Zero()));
  EXPECT_FALSE (std::ifstream (pointFilePath ("x.laz")).good());
}
