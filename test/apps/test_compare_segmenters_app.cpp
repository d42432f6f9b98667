/*
 * pcl_ext_compare_segmenters run as a command on a small generated scene: the table's
 * numbers are the metrics library's numbers for the labels the tool wrote; a LAS input
 * gives LAS labels in its frame; bad usage fails without output.
 */
#include "../app_test.h"

#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/simulation/scene_io.h>
#include <pcl_ext/simulation/scenes.h>
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
using Row = std::map<std::string, std::string>;

/** A CSV file as rows keyed by the header's column names (the tool writes no quoted
 * cells). */
std::vector<Row>
readCsv (const std::string& path, std::vector<std::string>& header)
{
  std::ifstream in (path);
  std::string line;
  std::vector<Row> rows;
  header.clear();
  while (std::getline (in, line)) {
    std::vector<std::string> cells;
    std::stringstream s (line);
    std::string cell;
    while (std::getline (s, cell, ','))
      cells.push_back (cell);
    if (!line.empty() && line.back() == ',')
      cells.emplace_back();
    if (header.empty()) {
      header = cells;
      continue;
    }
    Row row;
    for (std::size_t i = 0; i < header.size(); ++i)
      row[header[i]] = i < cells.size() ? cells[i] : std::string ("<missing>");
    rows.push_back (row);
  }
  return rows;
}

double
number (const Row& row, const std::string& column)
{
  const auto it = row.find (column);
  if (it == row.end() || it->second.empty())
    return -1e300;
  return std::stod (it->second);
}

class CompareSegmentersApp : public pcl_ext::test::AppTest {
protected:
  CompareSegmentersApp() : AppTest (COMPARE_SEGMENTERS_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // Eight floating cubes (28 visible faces), small enough for every method in
    // seconds.
    pcl_ext::simulation::SceneParameters parameters;
    parameters.points = 12000;
    parameters.threads = 2;
    pcl_ext::simulation::SyntheticScene scene;
    ASSERT_TRUE (pcl_ext::simulation::generateScene ("cubes", parameters, scene));
    ASSERT_TRUE (pcl_ext::simulation::saveScene (path ("cubes.pcd"), scene));
  }
};
} // namespace

TEST_F (CompareSegmentersApp, TableHoldsTheMetricsOfTheWrittenLabels)
{
  ASSERT_EQ (run (path ("cubes.pcd") + " -truth_field segment -threads 2 -csv " +
                  path ("t.csv") + " -labels " + path ("labels.pcd")),
             0)
      << output_;
  EXPECT_NE (output_.find ("mean IoU"), std::string::npos) << output_;

  std::vector<std::string> header;
  const auto rows = readCsv (path ("t.csv"), header);
  pcl::PCLPointCloud2 labelled;
  ASSERT_TRUE (pcl_ext::io::loadCloud (path ("labels.pcd"), labelled));
  std::vector<std::uint32_t> truth;
  ASSERT_TRUE (pcl_ext::io::getLabelField (labelled, "segment", truth));
  ASSERT_GE (rows.size(), 9u); // four or more pcl_ext methods and the five stock ones

  std::set<std::string> libraries;
  std::set<std::vector<std::uint32_t>> distinct_labellings;
  for (const auto& row : rows) {
    const std::string name = row.at ("method");
    SCOPED_TRACE (name);
    libraries.insert (row.at ("library"));
    ASSERT_EQ (row.at ("status"), "ok");
    // The labels the tool wrote for this method, scored by the metrics library.
    std::vector<std::uint32_t> predicted;
    ASSERT_TRUE (pcl_ext::io::getLabelField (labelled, name, predicted));
    ASSERT_EQ (predicted.size(), truth.size());
    distinct_labellings.insert (predicted);
    pcl_ext::SegmentationMetrics m;
    ASSERT_TRUE (pcl_ext::evaluateSegmentation (predicted, truth, m));

    EXPECT_DOUBLE_EQ (number (row, "mean_best_iou"), m.mean_best_iou);
    EXPECT_DOUBLE_EQ (number (row, "weighted_mean_best_iou"), m.weighted_mean_best_iou);
    EXPECT_EQ (number (row, "correct"), static_cast<double> (m.correct));
    EXPECT_EQ (number (row, "over_segmented"), static_cast<double> (m.over_segmented));
    EXPECT_EQ (number (row, "under_segmented"),
               static_cast<double> (m.under_segmented));
    EXPECT_EQ (number (row, "missed"), static_cast<double> (m.missed));
    EXPECT_EQ (number (row, "noise"), static_cast<double> (m.noise));
    EXPECT_EQ (number (row, "truth_segments"),
               static_cast<double> (m.num_truth_segments));
    EXPECT_EQ (number (row, "evaluated_points"),
               static_cast<double> (m.evaluated_points));
    EXPECT_DOUBLE_EQ (number (row, "unsegmented_fraction"), m.unsegmented_fraction);
    std::set<std::uint32_t> segments (predicted.begin(), predicted.end());
    segments.erase (0);
    EXPECT_EQ (number (row, "segments"), static_cast<double> (segments.size()));
    EXPECT_GT (number (row, "seconds"), 0.0);
    EXPECT_GE (number (row, "peak_memory_bytes"), 0.0);
    EXPECT_EQ (row.at ("normals") == "yes", name == "region_growing" || name == "cec");
  }
#ifdef PCL_EXT_HAVE_CGAL
  EXPECT_EQ (libraries, (std::set<std::string>{"CGAL", "PCL", "pcl_ext"}));
#else
  EXPECT_EQ (libraries, (std::set<std::string>{"PCL", "pcl_ext"}));
#endif
  // Each method's own labels, not one labelling copied into every field.
  EXPECT_GT (distinct_labellings.size(), rows.size() / 2);
}

#ifdef PCL_EXT_HAVE_CGAL
// CGAL's plane region growing gets the cloud, its PCA normals and its distance from the
// spacing: on the cubes' 29 faces it finds 21 whole ones (measured; PCL's region
// growing 14) with a mean best IoU of 0.671.
TEST_F (CompareSegmentersApp, CgalPlanesFindTheCubesFaces)
{
  ASSERT_EQ (run (path ("cubes.pcd") +
                  " -truth_field segment -methods cgal_planes -csv " + path ("t.csv")),
             0)
      << output_;
  std::vector<std::string> header;
  const auto rows = readCsv (path ("t.csv"), header);
  ASSERT_EQ (rows.size(), 1u);
  EXPECT_EQ (rows[0].at ("library"), "CGAL");
  EXPECT_EQ (rows[0].at ("status"), "ok");
  EXPECT_GE (number (rows[0], "correct"), 16.0) << output_;
  EXPECT_GT (number (rows[0], "mean_best_iou"), 0.55) << output_;
}
#endif

TEST_F (CompareSegmentersApp, WithoutTruthOnlyCountsAndTimes)
{
  ASSERT_EQ (run (path ("cubes.pcd") +
                  " -methods euclidean,proximity -threads 2 -csv " + path ("t.csv")),
             0)
      << output_;
  EXPECT_EQ (output_.find ("mean IoU"), std::string::npos) << output_;
  std::vector<std::string> header;
  const auto rows = readCsv (path ("t.csv"), header);
  ASSERT_EQ (rows.size(), 2u);
  EXPECT_EQ (rows[0].at ("method"), "proximity"); // table order, not command-line order
  EXPECT_EQ (rows[1].at ("method"), "euclidean");
  for (const auto& row : rows) {
    EXPECT_GT (number (row, "segments"), 0.0);
    EXPECT_EQ (row.at ("mean_best_iou"), "");
    EXPECT_EQ (row.at ("correct"), "");
    EXPECT_GT (number (row, "seconds"), 0.0);
  }
}

TEST_F (CompareSegmentersApp, MontageHasOneTilePerResultAndTheTruth)
{
  ASSERT_NE (std::getenv ("DISPLAY"), nullptr)
      << "this test needs an X display; scripts/test.sh starts Xvfb when none is set";
  ASSERT_EQ (run (path ("cubes.pcd") +
                  " -truth_field object -methods euclidean,proximity "
                  "-threads 2 -tile_width 300 -tile_height 200 -png " +
                  path ("m.png")),
             0)
      << output_;
  // PNG: 8-byte signature, then the IHDR chunk: length, type, width and height
  // (big-endian).
  std::ifstream in (path ("m.png"), std::ios::binary);
  unsigned char header[24] = {0};
  in.read (reinterpret_cast<char*> (header), sizeof (header));
  ASSERT_TRUE (in.good());
  EXPECT_EQ (std::string (reinterpret_cast<char*> (header + 12), 4), "IHDR");
  const auto big_endian = [&header] (int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) |
           header[at + 3];
  };
  EXPECT_EQ (big_endian (16), 3 * 300); // truth, proximity, euclidean in one row
  EXPECT_EQ (big_endian (20), 200);
}

TEST_F (CompareSegmentersApp, ProfileOptionsReachTheSegmenter)
{
  // The options not in the paper change what the profile segmenters return.
  const auto labels_of = [&] (const std::string& options, const std::string& method) {
    EXPECT_EQ (run (path ("cubes.pcd") + " -threads 2 -methods " + method +
                    " -labels " + path ("l.pcd") + options),
               0)
        << output_;
    pcl::PCLPointCloud2 labelled;
    std::vector<std::uint32_t> labels;
    EXPECT_TRUE (pcl_ext::io::loadCloud (path ("l.pcd"), labelled));
    EXPECT_TRUE (pcl_ext::io::getLabelField (labelled, method, labels));
    return labels;
  };
  const auto curve = labels_of ("", "curve");
  ASSERT_FALSE (curve.empty());
  EXPECT_NE (labels_of (" -aicc -turn_significance 3", "curve"), curve);
  EXPECT_NE (labels_of (" -side_frames", "curve"), curve);
  const auto proximity = labels_of ("", "proximity");
  ASSERT_FALSE (proximity.empty());
  EXPECT_NE (labels_of (" -local_threshold", "proximity"), proximity);
}

TEST_F (CompareSegmentersApp, BadUsageFailsWithoutOutput)
{
  const std::string cubes = path ("cubes.pcd"), csv = path ("t.csv");
  EXPECT_EQ (run ("-h"), 0);
  EXPECT_NE (output_.find ("region_growing"), std::string::npos)
      << output_; // methods listed

  EXPECT_EQ (run (cubes + " -methods euclidean,watershed -csv " + csv), 1);
  EXPECT_NE (output_.find ("unknown method 'watershed'"), std::string::npos) << output_;
  EXPECT_EQ (run (cubes + " -truth_field no_such_field -methods euclidean -csv " + csv),
             1);
  EXPECT_NE (output_.find ("no_such_field"), std::string::npos) << output_;
  EXPECT_EQ (run (path ("missing.pcd") + " -methods euclidean -csv " + csv), 1);
  EXPECT_NE (output_.find ("missing.pcd"), std::string::npos) << output_;
  {
    std::ofstream (path ("garbage.pcd")) << "not a point cloud\n";
  }
  EXPECT_EQ (run (path ("garbage.pcd") + " -methods euclidean -csv " + csv), 1);
  EXPECT_EQ (run (cubes + " -methods euclidean -csv " + path ("no_dir/t.csv")), 1);
  EXPECT_NE (output_.find ("no_dir/t.csv"), std::string::npos) << output_;
  EXPECT_EQ (run (cubes + " -methods euclidean -labels " + path ("no_dir/l.pcd")), 1);
  EXPECT_EQ (run (cubes + " -k 0 -csv " + csv), 1);
  EXPECT_EQ (run (cubes + " -tolerance -1 -csv " + csv), 1);
  EXPECT_EQ (run (cubes + " -turn_significance -1 -csv " + csv), 1);
  EXPECT_EQ (run (cubes + " -no_such_option 1 -csv " + csv), 1);
  EXPECT_EQ (run (""), 1);
  EXPECT_FALSE (fs::exists (csv));
  EXPECT_FALSE (fs::exists (path ("no_dir")));
}

TEST_F (CompareSegmentersApp, ReadsAndWritesLasInTheInputsFrame)
{
  // The scene as a georeferenced LAS file: coordinates far from 0, the truth an
  // extra-bytes dimension of the same name.
  pcl_ext::io::PointFile scene;
  pcl_ext::io::loadPointFile (path ("cubes.pcd"), scene);
  ASSERT_TRUE (pcl_ext::io::savePointFile (
      path ("cubes.las"), scene.cloud, Eigen::Vector3d (512000.0, 5400000.0, 200.0)));
  ASSERT_EQ (run (path ("cubes.las") +
                  " -truth_field segment -methods euclidean -threads 2 -labels " +
                  path ("labels.las")),
             0)
      << output_;
  EXPECT_NE (output_.find ("mean IoU"), std::string::npos) << output_;

  pcl_ext::io::PointFile in, out;
  pcl_ext::io::loadPointFile (path ("cubes.las"), in);
  pcl_ext::io::loadPointFile (path ("labels.las"), out);
  ASSERT_TRUE (out.las.has_value());
  EXPECT_EQ (out.las->header.offset, in.las->header.offset);
  EXPECT_EQ (out.las->header.scale, in.las->header.scale);
  EXPECT_EQ (out.origin, in.origin);
  EXPECT_EQ (out.cloud.width * out.cloud.height, in.cloud.width * in.cloud.height);
  std::vector<std::uint32_t> truth_in, truth_out;
  ASSERT_TRUE (pcl_ext::io::getLabelField (in.cloud, "segment", truth_in));
  ASSERT_TRUE (pcl_ext::io::getLabelField (out.cloud, "segment", truth_out));
  EXPECT_EQ (truth_in, truth_out);
  pcl::PointCloud<pcl::PointXYZ> a, b; // the same integers read the same way
  pcl::fromPCLPointCloud2 (in.cloud, a);
  pcl::fromPCLPointCloud2 (out.cloud, b);
  ASSERT_EQ (a.size(), b.size());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    moved += a[i].getVector3fMap() != b[i].getVector3fMap();
  EXPECT_EQ (moved, 0u);
  std::vector<std::uint32_t> euclidean;
  ASSERT_TRUE (pcl_ext::io::getLabelField (out.cloud, "euclidean", euclidean));
  EXPECT_GT (*std::max_element (euclidean.begin(), euclidean.end()), 1u);

  // A labels file of a format that cannot be written is refused before any work.
  EXPECT_EQ (
      run (path ("cubes.las") + " -methods euclidean -labels " + path ("labels.laz")),
      1);
  EXPECT_NE (output_.find ("writing LAZ is not supported"), std::string::npos)
      << output_;
  EXPECT_EQ (output_.find ("Loading"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("labels.laz"));
}
