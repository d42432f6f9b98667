/*
 * The readers on the real data sets (labelled "data"; skipped when the data is absent).
 */
#include <pcl_ext/evaluation/classification_metrics.h>
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/footprints.h>

#include <pcl/io/pcd_io.h>

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>

namespace {
std::string
shared (const std::string& name)
{
  return std::string (PCL_EXT_SHARED_DATA_DIR) + "/" + name;
}

bool
exists (const std::string& path)
{
  struct stat st;
  return ::stat (path.c_str(), &st) == 0;
}

/** Per-label counts from an Oakland .stats file ("  1203 -- paved_road -- 46085"). */
std::map<std::uint32_t, std::size_t>
readStats (const std::string& path)
{
  std::map<std::uint32_t, std::size_t> counts;
  std::ifstream in (path);
  std::string line;
  while (std::getline (in, line)) {
    std::istringstream s (line);
    std::uint32_t id;
    std::string dash1, name, dash2;
    std::size_t count;
    if (s >> id >> dash1 >> name >> dash2 >> count && dash1 == "--" && count > 0)
      counts[id] = count;
  }
  return counts;
}
} // namespace

TEST (RealData, OaklandMatchesItsStatistics)
{
  const std::string folder = shared ("oakland3d");
  if (!exists (folder + "/classes.txt"))
    GTEST_SKIP() << "Oakland 3-D data not found in " << folder;
  pcl_ext::io::ClassMapping classes;
  classes.load (folder + "/classes.txt");
  ASSERT_EQ (classes.size(), 5u);
  EXPECT_EQ (classes.name (4), "ground");
  std::size_t files = 0, points = 0;
  std::map<std::uint32_t, std::size_t> coarse;
  for (const char* chunk : {"aj", "ak", "al", "am", "an", "ao", "ap"}) {
    const std::string name = std::string ("oakland_part3_") + chunk;
    const std::string path = folder + "/" + name + ".xyz_label_conf";
    if (!exists (path))
      continue;
    pcl_ext::io::PointTable table;
    ASSERT_NO_THROW (pcl_ext::io::loadOaklandFile (path, table));
    std::map<std::uint32_t, std::size_t> counts;
    for (const auto l : table.label)
      ++counts[l];
    const std::string stats = folder + "/stats/" + name + ".stats";
    if (exists (stats))
      EXPECT_EQ (counts, readStats (stats)) << name;
    std::vector<std::uint32_t> labels = table.label;
    classes.apply (labels);
    for (const auto l : labels)
      ++coarse[l];
    points += table.size();
    ++files;
  }
  if (files == 0)
    GTEST_SKIP() << "no Oakland chunk found in " << folder;
  EXPECT_GT (points, 0u);
  // Every coarse class occurs in part 3 (SOURCE.md: chunks am and an contain all of
  // them).
  for (std::uint32_t c = 1; c <= 5; ++c)
    EXPECT_GT (coarse[c], 0u) << classes.name (c);
  std::cout << "[ info ] Oakland part 3: " << files << " files, " << points
            << " points; ignored " << coarse[0] << ", vegetation " << coarse[1]
            << ", trunk_pole " << coarse[2] << ", facade " << coarse[3] << ", ground "
            << coarse[4] << ", wire " << coarse[5] << "\n";
}

TEST (RealData, AmsterdamFootprintsAndLabels)
{
  const std::string folder = shared ("amsterdam_ahn3_bgt_footprints");
  if (!exists (folder + "/bgt_footprints_local_2386_9702.txt"))
    GTEST_SKIP() << "Amsterdam AHN3/BGT data not found in " << folder;
  const std::map<std::string, std::size_t> expected = {
      {"bgt_footprints_local_2386_9702.txt", 13},
      {"bgt_footprints_local_2397_9705.txt", 18},
      {"bag_footprints_local_2386_9702.txt", 13},
      {"bag_footprints_local_2397_9705.txt", 18}};
  for (const auto& [name, count] : expected) {
    std::vector<pcl_ext::io::Footprint> fp;
    ASSERT_NO_THROW (pcl_ext::io::loadFootprints (folder + "/" + name, fp)) << name;
    EXPECT_EQ (fp.size(), count) << name;
    for (const auto& f : fp) {
      ASSERT_EQ (f.polygons.size(), 1u);
      // Buildings of a few to a few thousand square metres, near the 52 m tile.
      const double area = pcl_ext::io::signedArea (f.polygons[0].outer);
      EXPECT_GT (area, 1.0) << name << " " << f.id;
      EXPECT_LT (area, 1e5) << name << " " << f.id;
      for (const auto& v : f.polygons[0].outer)
        EXPECT_LT (v.cwiseAbs().maxCoeff(), 500.0) << name << " " << f.id;
    }
  }

  // The AHN tile's per-point LAS classes read through the generic field access.
  const std::string pcd = folder + "/ahn_2386_9702.pcd";
  if (!exists (pcd))
    return;
  pcl::PCLPointCloud2 cloud;
  ASSERT_EQ (pcl::io::loadPCDFile (pcd, cloud), 0);
  std::vector<std::uint32_t> labels;
  std::string error;
  ASSERT_TRUE (pcl_ext::io::getLabelField (cloud, "label", labels, &error)) << error;
  std::map<std::uint32_t, std::size_t> counts;
  for (const auto l : labels)
    ++counts[l];
  EXPECT_EQ (labels.size(), 43536u);
  EXPECT_EQ (counts[2], 26668u);
  EXPECT_EQ (counts[6], 11992u);
  EXPECT_EQ (counts[1], 4876u);
  // The truth scored against itself.
  pcl_ext::ClassificationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateClassification (labels, labels, m));
  EXPECT_DOUBLE_EQ (m.overall_accuracy, 1.0);
}
