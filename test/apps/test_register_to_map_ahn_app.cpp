/*
 * pcl_ext_register_to_map with its defaults on a real airborne tile (label "data";
 * skipped without the data folder, PCL_EXT_SHARED_DATA_DIR): AHN3 tile 2397_9705 and
 * every BGT building footprint of the data set, both in RD New (written so), so that
 * the true cloud-to-map transform is the identity. The labelled cloud is moved by a
 * known rigid transform and given to the tool with the footprint file and nothing else:
 * the wall source, the footprints near the scan, m and n and the floor height all come
 * from the data (Khoshelham & Gorte 2009, with airborne data).
 */
#include "../app_test.h"

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/io/transform_file.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <string>
#include <vector>

namespace {
const std::string kDir =
    std::string (PCL_EXT_SHARED_DATA_DIR) + "/amsterdam_ahn3_bgt_footprints";

// The BGT polygons of the data set's CSV (one JSON list of [x, y] per row, RD New), as
// text footprints: "id n x1 y1 ... xn yn".
bool
writeFootprints (const std::string& csv, const std::string& path)
{
  std::ifstream in (csv);
  std::ofstream out (path);
  std::string line;
  int id = 0;
  const std::regex number ("-?[0-9]+(\\.[0-9]+)?");
  while (std::getline (in, line)) {
    const auto open = line.find ("[[");
    const auto close = line.find ("]]");
    if (open == std::string::npos || close == std::string::npos)
      continue;
    const std::string list = line.substr (open, close - open);
    std::vector<double> values;
    for (std::sregex_iterator i (list.begin(), list.end(), number), end; i != end; ++i)
      values.push_back (std::stod (i->str()));
    out << id++ << " " << values.size() / 2 << std::setprecision (12);
    for (std::size_t v = 0; v + 1 < values.size(); v += 2)
      out << " " << values[v] << " " << values[v + 1];
    out << "\n";
  }
  return id > 0 && bool (out);
}

// The errors of the tool's transform and of doing nothing.
struct AhnErrors {
  pcl_ext::TransformationError estimate, nothing;
};

class RegisterToMapAhn : public pcl_ext::test::AppTest {
protected:
  RegisterToMapAhn() : AppTest (PCL_EXT_REGISTER_TO_MAP_EXE) {}

  // The tool with its defaults on tile 2397_9705 turned about its centre by \a yaw_deg
  // about the vertical and \a tilt_deg about the horizontal axis \a axis_deg from x,
  // then shifted by (\a dx, \a dy, 0) m. The map has no heights, so the floor is the
  // cloud's ground, and a vertical shift of the cloud is not observable: the
  // perturbation keeps the height of the cloud's centre. false without the data.
  bool
  registerPerturbed (double yaw_deg,
                     double tilt_deg,
                     double axis_deg,
                     double dx,
                     double dy,
                     AhnErrors& e)
  {
    const std::string cloud_path = kDir + "/ahn_2397_9705.pcd";
    const std::string csv = kDir + "/bgt_buildings_demo.csv";
    if (!std::filesystem::exists (cloud_path) || !std::filesystem::exists (csv))
      return false;
    EXPECT_TRUE (writeFootprints (csv, path ("footprints.txt")));
    pcl::PointCloud<pcl::PointXYZL> points;
    EXPECT_EQ (pcl::io::loadPCDFile (cloud_path, points), 0);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : points)
      centre += p.getVector3fMap().cast<double>();
    centre /= double (points.size());
    const double axis = axis_deg * M_PI / 180.0;
    Eigen::Matrix4d perturbation = Eigen::Matrix4d::Identity();
    perturbation.topLeftCorner<3, 3>() =
        (Eigen::AngleAxisd (yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd (tilt_deg * M_PI / 180.0,
                            Eigen::Vector3d (std::cos (axis), std::sin (axis), 0.0)))
            .toRotationMatrix();
    perturbation.topRightCorner<3, 1>() = Eigen::Vector3d (dx, dy, 0.0) + centre -
                                          perturbation.topLeftCorner<3, 3>() * centre;
    for (auto& p : points)
      p.getVector3fMap() =
          (perturbation * p.getVector3fMap().cast<double>().homogeneous())
              .head<3>()
              .cast<float>();
    centre = (perturbation * centre.homogeneous()).head<3>();
    // In RD New (the tile's corner added back, SOURCE.md of the data set), x y z in
    // double precision.
    const Eigen::Vector3d corner (119850.0, 485250.0, 0.0);
    {
      std::ofstream out (path ("tile.pcd"));
      out << "VERSION 0.7\nFIELDS x y z label\nSIZE 8 8 8 4\nTYPE F F F U\nCOUNT 1 1 1 "
             "1\nWIDTH "
          << points.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS "
          << points.size() << "\nDATA ascii\n"
          << std::fixed << std::setprecision (4);
      for (const auto& p : points) {
        const Eigen::Vector3d q = p.getVector3fMap().cast<double>() + corner;
        out << q.x() << " " << q.y() << " " << q.z() << " " << p.label << "\n";
      }
      EXPECT_TRUE (bool (out));
    }
    EXPECT_EQ (run (path ("tile.pcd") + " " + path ("footprints.txt") + " " +
                    path ("out.pcd") + " -transform_out " + path ("T.txt")),
               0)
        << output_;
    Eigen::Matrix4d estimate;
    pcl_ext::io::loadTransform (path ("T.txt"), estimate);
    // The perturbation in RD New: corner, perturbed, back.
    Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
    shift.topRightCorner<3, 1>() = corner;
    const Eigen::Matrix4d truth = (shift * perturbation * shift.inverse()).inverse();
    centre += corner;
    e.estimate = pcl_ext::computeTransformationError (estimate, truth, centre);
    e.nothing = pcl_ext::computeTransformationError (
        Eigen::Matrix4d::Identity(), truth, centre);
    RecordProperty ("rotation_error_deg", std::to_string (e.estimate.rotation_deg));
    RecordProperty ("translation_error_m", std::to_string (e.estimate.translation));
    return true;
  }
};
} // namespace

// 3 degrees of yaw, 1 of tilt about x, a shift of (2, -1.5, 0) m: doing nothing is 3.16
// degrees and 2.5 m off at the centre. The bounds are those the tool meets here with a
// margin, and that doing nothing fails; the goal (1 degree, 0.5 m) is met on
// the untouched tile but not under this perturbation (figures and causes in
// docs/khoshelham_gorte.md).
TEST_F (RegisterToMapAhn, Tile2397_9705WithTheDefaults)
{
  AhnErrors e;
  if (!registerPerturbed (3.0, 1.0, 0.0, 2.0, -1.5, e))
    GTEST_SKIP() << "real data not found in " << kDir;
  ASSERT_GT (e.nothing.rotation_deg, 2.5);
  ASSERT_GT (e.nothing.translation, 1.0);
  EXPECT_LT (e.estimate.rotation_deg, 2.5) << output_;
  EXPECT_LT (e.estimate.translation, 1.0) << output_;
}

// A pose where the search's best match set (7 pairs) was the tile turned half a turn,
// 21 m off: the walls of a street of buildings pair as well both ways. The roofs lie
// over the footprints in one of them only (docs/khoshelham_gorte.md, the forty
// perturbations, case 17).
TEST_F (RegisterToMapAhn, Tile2397_9705NotHalfTurnedOntoItsStreet)
{
  AhnErrors e;
  if (!registerPerturbed (3.6182828465870696,
                          0.7081792504833336,
                          85.08979255455706,
                          1.9817250564585063,
                          -2.1395275785681585,
                          e))
    GTEST_SKIP() << "real data not found in " << kDir;
  ASSERT_GT (e.nothing.rotation_deg, 3.0);
  ASSERT_GT (e.nothing.translation, 1.0);
  EXPECT_LT (e.estimate.rotation_deg, 2.5) << output_;
  EXPECT_LT (e.estimate.translation, 1.0) << output_;
}
