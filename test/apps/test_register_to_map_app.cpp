/*
 * pcl_ext_register_to_map run as a command: the building scene registered from a guess
 * within bounds, a classified airborne cloud registered with roof outline walls, and
 * bad option values, footprints and scans refused before anything is written.
 */
#include "../app_test.h"

#include "../registration/roof_outline_scene.h"

#include <pcl_ext/io/point_file.h>
#include <pcl_ext/io/transform_file.h>

#include <pcl/conversions.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace {
class RegisterToMapApp : public pcl_ext::test::AppTest {
protected:
  RegisterToMapApp() : AppTest (PCL_EXT_REGISTER_TO_MAP_EXE) {}

  // The building scene (an H whose courtyards differ, so the pose is unique) scanned
  // from a known pose: b.pcd, b.footprint.wkt and b.transform.txt (scan to map).
  void
  generateBuilding ()
  {
    const std::string command =
        std::string (PCL_EXT_GENERATE_SCENE_EXE) + " building '" + path ("b.pcd") +
        "' -points 30000 -seed 3 -threads 1 -pose 30,0,0,5,-3,0 > /dev/null 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0);
    pcl_ext::io::loadTransform (path ("b.transform.txt"), truth_);
  }

  void
  writeTransform (const std::string& name, const Eigen::Matrix4d& t)
  {
    std::ofstream out (path (name));
    out << std::setprecision (17);
    for (int r = 0; r < 4; ++r)
      out << t (r, 0) << " " << t (r, 1) << " " << t (r, 2) << " " << t (r, 3) << "\n";
  }

  // Largest distance between a registered point (in map coordinates: the file's
  // coordinates, its origin added back) and where \a truth puts the input point.
  double
  largestError (const std::string& input,
                const std::string& registered,
                const Eigen::Matrix4d& truth) const
  {
    pcl_ext::io::PointFile in_file, out_file;
    pcl::PointCloud<pcl::PointXYZ> in, out;
    try {
      pcl_ext::io::loadPointFile (path (input), in_file);
      pcl_ext::io::loadPointFile (path (registered), out_file);
    }
    catch (const std::exception&) {
      return std::numeric_limits<double>::infinity();
    }
    pcl::fromPCLPointCloud2 (in_file.cloud, in);
    pcl::fromPCLPointCloud2 (out_file.cloud, out);
    if (in.size() != out.size())
      return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (std::size_t i = 0; i < in.size(); ++i) {
      const Eigen::Vector3d x = in[i].getVector3fMap().cast<double>() + in_file.origin;
      const Eigen::Vector3d expected = (truth * x.homogeneous()).head<3>();
      worst = std::max (
          worst,
          (out[i].getVector3fMap().cast<double>() + out_file.origin - expected).norm());
    }
    return worst;
  }

  Eigen::Matrix4d truth_ = Eigen::Matrix4d::Identity();
};

Eigen::Matrix4d
rigid (double yaw_deg, const Eigen::Vector3d& translation)
{
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  t.topRightCorner<3, 1>() = translation;
  return t;
}
} // namespace

TEST_F (RegisterToMapApp, GuessWithBoundsFindsTheSamePoseAsTheGlobalSearch)
{
  generateBuilding();
  ASSERT_FALSE (HasFatalFailure());
  // The global search (no guess, no bounds).
  ASSERT_EQ (run (path ("b.pcd") + " " + path ("b.footprint.wkt") + " " +
                  path ("global.pcd") + " -threads 1"),
             0)
      << output_;
  EXPECT_EQ (output_.find ("of the guess"), std::string::npos) << output_;
  EXPECT_LT (largestError ("b.pcd", "global.pcd", truth_), 0.1) << output_;

  // A rough pose: 4 deg and 1.8 m off the truth; the search stays within 10 deg and 5 m
  // of it.
  writeTransform ("guess.txt", rigid (4.0, Eigen::Vector3d (1.5, -1.0, 0.2)) * truth_);
  ASSERT_EQ (run (path ("b.pcd") + " " + path ("b.footprint.wkt") + " " +
                  path ("bounded.pcd") + " -threads 1 -guess " + path ("guess.txt") +
                  " -max_rotation_from_guess 10 -max_translation_from_guess 5"),
             0)
      << output_;
  EXPECT_NE (output_.find ("Search within 10 deg and 5 m of the guess in "),
             std::string::npos)
      << output_;
  EXPECT_LT (largestError ("b.pcd", "bounded.pcd", truth_), 0.1) << output_;

  // A guess a quarter turn off, and bounds that exclude the truth: no pose, no output.
  writeTransform ("far.txt", rigid (90.0, Eigen::Vector3d::Zero()) * truth_);
  EXPECT_EQ (run (path ("b.pcd") + " " + path ("b.footprint.wkt") + " " +
                  path ("far.pcd") + " -threads 1 -guess " + path ("far.txt") +
                  " -max_rotation_from_guess 5 -max_translation_from_guess 2"),
             1)
      << output_;
  EXPECT_NE (output_.find ("did not converge"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("far.pcd"));
}

TEST_F (RegisterToMapApp, TiltedGeoreferencedScanWithDefaults)
{
  // The building scanned with 2 and 1 degrees of tilt, its cloud and its map both at
  // georeferenced coordinates (1e5 m, a float step of 3 cm; the map's floor at the
  // default height, 0): registered with the defaults, the output cloud and
  // -transform_out in map coordinates, every input field kept.
  const std::string command =
      std::string (PCL_EXT_GENERATE_SCENE_EXE) + " building '" + path ("g.pcd") +
      "' -points 30000 -seed 3 -threads 1 -pose 30,2,1,120000,487000,5 -offset "
      "120010,487020,0 > /dev/null 2>&1";
  ASSERT_EQ (std::system (command.c_str()), 0);
  Eigen::Matrix4d truth;
  pcl_ext::io::loadTransform (path ("g.transform.txt"), truth);
  ASSERT_EQ (run (path ("g.pcd") + " " + path ("g.footprint.wkt") + " " +
                  path ("g_out.pcd") + " -threads 1 -transform_out " + path ("T.txt")),
             0)
      << output_;
  EXPECT_LT (largestError ("g.pcd", "g_out.pcd", truth), 0.1) << output_;
  Eigen::Matrix4d written;
  pcl_ext::io::loadTransform (path ("T.txt"), written);
  const Eigen::Matrix3d r =
      written.topLeftCorner<3, 3>().transpose() * truth.topLeftCorner<3, 3>();
  EXPECT_LT (std::acos (std::min (1.0, 0.5 * (r.trace() - 1.0))) * 180.0 / M_PI, 0.2);
  const Eigen::Vector3d centre (120030.0, 487035.0, 8.0); // in the footprint
  const Eigen::Vector3d x = (truth.inverse() * centre.homogeneous()).head<3>();
  EXPECT_LT (((written * x.homogeneous()).head<3>() - centre).norm(), 0.1);
  pcl_ext::io::PointFile out;
  pcl_ext::io::loadPointFile (path ("g_out.pcd"), out);
  for (const char* field : {"segment", "object", "class", "label"})
    EXPECT_GE (pcl::getFieldIndex (out.cloud, field), 0) << field;
}

TEST_F (RegisterToMapApp, RoofOutlineWallsRegisterAClassifiedAirborneCloud)
{
  // The two buildings of the roof outline tests, moved by 2 deg and (0.8, -0.5, 0.3) m;
  // the guess is the identity (a georeferenced cloud), the map the two footprints.
  const auto scene = pcl_ext::test::twoBuildings();
  const Eigen::Matrix4d moved = rigid (2.0, Eigen::Vector3d (0.8, -0.5, 0.3));
  pcl::PointCloud<pcl::PointXYZL> cloud;
  for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
    const Eigen::Vector4d q = moved * (*scene.cloud)[i].getVector4fMap().cast<double>();
    pcl::PointXYZL p;
    p.x = static_cast<float> (q.x());
    p.y = static_cast<float> (q.y());
    p.z = static_cast<float> (q.z());
    p.label = (*scene.labels)[i].label == pcl_ext::test::kGround ? 2u : 6u;
    cloud.push_back (p);
  }
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("airborne.pcd"), cloud), 0);
  std::ofstream (path ("map.wkt")) << pcl_ext::test::twoBuildingsWkt() << "\n";

  const std::string common = path ("airborne.pcd") + " " + path ("map.wkt") + " ";
  ASSERT_EQ (
      run (common + path ("out.pcd") +
           " -threads 1 -walls roof_outline -ground_label 2 -building_label 6 "
           "-m 16 -n 16 -max_rotation_from_guess 10 -max_translation_from_guess 5"),
      0)
      << output_;
  // Outline walls stand half a roof spacing inside the true walls and are fitted to a
  // jagged band: the pose is recovered to a few centimetres per metre, not exactly.
  EXPECT_LT (largestError ("airborne.pcd", "out.pcd", moved.inverse()), 0.3) << output_;

  // The same cloud through sequential RANSAC finds roofs and ground, not the walls: the
  // outline walls are what make the airborne cloud usable (the default, -walls auto,
  // takes them for this reason).
  EXPECT_EQ (run (common + path ("sac.pcd") +
                  " -threads 1 -walls sac -max_rotation_from_guess 10 "
                  "-max_translation_from_guess 5"),
             1)
      << output_;
  EXPECT_FALSE (exists ("sac.pcd"));
}

TEST_F (RegisterToMapApp, BadOptionValuesAreRefusedWithoutOutput)
{
  generateBuilding();
  ASSERT_FALSE (HasFatalFailure());
  std::ofstream (path ("bad_transform.txt")) << "1 0 0 0\n0 1 0 0\n0 0 1\n";
  const std::string common =
      path ("b.pcd") + " " + path ("b.footprint.wkt") + " " + path ("out.pcd") + " ";
  const std::pair<std::string, std::string> bad[] = {
      {"-max_rotation_from_guess 0", "-max_rotation_from_guess must be > 0"},
      {"-max_rotation_from_guess -5", "-max_rotation_from_guess must be > 0"},
      {"-max_rotation_from_guess nan", "max_rotation_from_guess"},
      {"-max_rotation_from_guess ten", "max_rotation_from_guess"},
      {"-max_translation_from_guess 0", "-max_translation_from_guess must be > 0"},
      {"-max_translation_from_guess -1", "-max_translation_from_guess must be > 0"},
      {"-max_translation_from_guess inf", "max_translation_from_guess"},
      {"-guess " + path ("missing.txt"), "missing.txt"},
      {"-guess " + path ("bad_transform.txt"), "bad_transform.txt"},
      {"-guess", "guess"},
      {"-walls planes", "unknown -walls 'planes'"},
      {"-walls sac -ground_label 2",
       "-ground_label applies to -walls roof_outline or auto"},
      {"-walls roof_outline -ground_label -1", "ground_label"},
      {"-walls roof_outline -ground_label 6 -building_label 6", "must differ"},
      {"-walls roof_outline -label_field nothing", "nothing"}};
  for (const auto& [options, message] : bad) {
    EXPECT_EQ (run (common + options), 1) << options << ": " << output_;
    EXPECT_NE (output_.find (message), std::string::npos) << options << ": " << output_;
    EXPECT_FALSE (exists ("out.pcd")) << options;
  }
}

TEST_F (RegisterToMapApp, BadFootprintsScansAndGuessesAreRefusedWithoutOutput)
{
  generateBuilding();
  ASSERT_FALSE (HasFatalFailure());
  std::ofstream (path ("empty.wkt")).flush();
  std::ofstream (path ("one_edge.wkt")) << "1 POLYGON((0 0, 10 0, 0 0))\n";
  std::ofstream (path ("collinear.wkt")) << "1 POLYGON((0 0, 10 0, 20 0, 0 0))\n";
  std::ofstream (path ("far.wkt"))
      << "1 POLYGON((5000 5000, 5010 5000, 5010 5010, 5000 5010, 5000 5000))\n";
  // A level ground plane and nothing else: no wall to match.
  pcl::PointCloud<pcl::PointXYZ> flat;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      flat.push_back (pcl::PointXYZ (0.2f * i, 0.2f * j, 0.0f));
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("flat.pcd"), flat), 0);
  std::ofstream (path ("nan_guess.txt")) << "nan 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  const std::pair<std::string, std::string> bad[] = {
      {"b.pcd empty.wkt", "empty file, no polygons"},
      {"b.pcd one_edge.wkt", "fewer than 3 distinct vertices"},
      {"b.pcd collinear.wkt", "not a valid polygon"},
      {"b.pcd far.wkt", "more than 1 km"},
      {"flat.pcd b.footprint.wkt", "did not converge"},
      {"b.pcd b.footprint.wkt -guess nan_guess.txt", "not a finite number"}};
  for (const auto& [inputs, message] : bad) {
    std::istringstream words (inputs);
    std::string scan, footprint, option, value;
    words >> scan >> footprint >> option >> value;
    const std::string guess = option.empty() ? "" : " " + option + " " + path (value);
    EXPECT_EQ (run (path (scan) + " " + path (footprint) + " " + path ("out.pcd") +
                    " -threads 1" + guess),
               1)
        << inputs << ": " << output_;
    EXPECT_NE (output_.find (message), std::string::npos) << inputs << ": " << output_;
    EXPECT_FALSE (exists ("out.pcd")) << inputs;
  }
}
