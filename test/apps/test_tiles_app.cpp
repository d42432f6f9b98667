/*
 * pcl_ext_tiles run as a command: a georeferenced scene classified tile by tile, in one
 * command, in steps and shared among MPI ranks, gives pcl_ext_classify_variance's
 * output point for point, for any tile size, order of the tiles and number of ranks;
 * bad input is refused without output.
 */
#include "../app_test.h"
#include "sbatch_shim.h"

#include <pcl_ext/common/random.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <set>
#include <sstream>
#include <csignal>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {
/** The point records of a LAS file and its scale and offset bytes. */
struct LasContent {
  std::vector<char> scale_and_offset;
  std::vector<char> records;
};

LasContent
readLas (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  const std::vector<char> b ((std::istreambuf_iterator<char> (in)),
                             std::istreambuf_iterator<char>());
  LasContent c;
  if (b.size() < 375)
    return c;
  std::uint32_t offset;
  std::memcpy (&offset, &b[96], 4);
  c.scale_and_offset.assign (b.begin() + 131, b.begin() + 179);
  if (offset <= b.size())
    c.records.assign (b.begin() + offset, b.end());
  return c;
}

class TilesApp : public pcl_ext::test::AppTest {
protected:
  TilesApp() : AppTest (PCL_EXT_TILES_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // An indoor scan at UTM-like coordinates: the tiles must keep the input's frame.
    const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) +
                                 " indoor '" + path ("scene.pcd") +
                                 "' -points 60000 -seed 2 -offset 500000,6000000,100 "
                                 "> /dev/null 2>&1";
    ASSERT_EQ (std::system (generate.c_str()), 0);
    const std::string whole = std::string (PCL_EXT_CLASSIFY_VARIANCE_EXE) + " '" +
                              path ("scene.pcd") + "' '" + path ("whole.las") +
                              "' > /dev/null 2>&1";
    ASSERT_EQ (std::system (whole.c_str()), 0);
    whole_ = readLas (path ("whole.las"));
    ASSERT_FALSE (whole_.records.empty());
  }

  void
  expectSameAsWhole (const std::string& output)
  {
    const LasContent tiled = readLas (path (output));
    EXPECT_TRUE (tiled.scale_and_offset == whole_.scale_and_offset) << output;
    EXPECT_EQ (tiled.records.size(), whole_.records.size()) << output;
    EXPECT_TRUE (tiled.records == whole_.records) << output;
  }

  LasContent whole_;
};

/** The LAS point record length and the X, Y of record \a i in the file's frame. */
struct LasXy {
  double x, y;
};

LasXy
recordXy (const std::vector<char>& header,
          const std::vector<char>& records,
          std::size_t i)
{
  std::uint16_t length;
  std::memcpy (&length, &header[105], 2);
  double scale[2], offset[2];
  std::memcpy (scale, &header[131], 16);
  std::memcpy (offset, &header[155], 16);
  std::int32_t xy[2];
  std::memcpy (xy, &records[i * length], 8);
  return {xy[0] * scale[0] + offset[0], xy[1] * scale[1] + offset[1]};
}
} // namespace

TEST_F (TilesApp, AnyTileSizeGivesTheWholeCloudsClasses)
{
  ASSERT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("t3.las") +
                  " -tile_size 3 -threads 1"),
             0)
      << output_;
  EXPECT_NE (output_.find ("tiles ("), std::string::npos) << output_;
  EXPECT_NE (output_.find ("peak memory"), std::string::npos) << output_;
  expectSameAsWhole ("t3.las");
  ASSERT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("t7.las") +
                  " -tile_size 7 -halo 0.05"),
             0)
      << output_;
  expectSameAsWhole ("t7.las"); // a halo far too small: the tiles widen themselves
  EXPECT_FALSE (exists ("t7.las.tiles")); // the work folder is removed
}

#ifdef PCL_EXT_MPIEXEC
TEST_F (TilesApp, MpiRanksShareTheTilesAndGiveTheSameOutput)
{
  for (const int ranks : {2, 4}) {
    const std::string out = "mpi" + std::to_string (ranks) + ".las";
    const std::string command =
        std::string (PCL_EXT_MPIEXEC) + " --allow-run-as-root --oversubscribe -np " +
        std::to_string (ranks) + " " + PCL_EXT_TILES_EXE + " classify_variance '" +
        path ("scene.pcd") + "' '" + path (out) + "' -tile_size 3 -threads 1 > '" +
        path ("mpi.log") + "' 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0) << ranks << " ranks";
    std::ifstream log (path ("mpi.log"));
    const std::string text ((std::istreambuf_iterator<char> (log)),
                            std::istreambuf_iterator<char>());
    EXPECT_NE (text.find ("Rank " + std::to_string (ranks - 1) + ": done"),
               std::string::npos)
        << text;
    expectSameAsWhole (out);
  }
}
#endif

#ifdef PCL_EXT_MPIEXEC
TEST_F (TilesApp, ARankThatDiesIsNamedAndResumeCompletesTheRun)
{
  // Over two ranks, a process is killed (SIGKILL) in the middle of a tile: the job
  // fails and writes no output; the merge names the tile and the process; 'resume',
  // over two ranks again, runs what is left and gives the whole cloud's bytes.
  const std::string work = path ("dying");
  const std::string mpi = std::string (PCL_EXT_MPIEXEC) +
                          " --allow-run-as-root --oversubscribe -np 2 " +
                          PCL_EXT_TILES_EXE;
  const std::string command =
      "(" + mpi + " classify_variance '" + path ("scene.pcd") + "' '" +
      path ("died.las") + "' -tile_size 1 -threads 1 -workdir '" + work + "' > '" +
      path ("mpi.log") + "' 2>&1; echo $? > '" + path ("rc.tmp") + "'; mv '" +
      path ("rc.tmp") + "' '" + path ("rc.txt") + "') &";
  ASSERT_EQ (std::system (command.c_str()), 0);
  // A tile's record names its process: the process is stopped (SIGSTOP) and killed if
  // it is still in a tile (a record of its own, the tile not done: it may be stopped
  // between the two), else let go and another tried.
  const auto recordOf = [&work] (const std::string& process) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator (work, error)) {
      const std::string name = entry.path().filename().string();
      if (name.size() < 14 || name.compare (0, 5, "tile_") != 0 ||
          name.compare (name.size() - 8, 8, ".running") != 0)
        continue;
      std::ifstream in (entry.path());
      std::string word, pid;
      in >> word >> pid; // "process <pid> on host ..."
      if (word == "process" && !pid.empty() && (process.empty() || pid == process))
        return std::make_pair (name.substr (5, name.size() - 13), pid);
    }
    return std::make_pair (std::string(), std::string());
  };
  std::string killed_tile, killed_process;
  for (int i = 0; i < 12000 && killed_tile.empty() && !exists ("rc.txt"); ++i) {
    const auto seen = recordOf ("");
    if (!seen.second.empty() && ::kill (std::stoi (seen.second), SIGSTOP) == 0) {
      ::usleep (20000);
      const auto in_tile = recordOf (seen.second);
      if (!in_tile.first.empty() &&
          !std::filesystem::exists (work + "/tile_" + in_tile.first + ".done") &&
          ::kill (std::stoi (seen.second), SIGKILL) == 0)
        std::tie (killed_tile, killed_process) = in_tile;
      else
        ::kill (std::stoi (seen.second), SIGCONT);
    }
    ::usleep (2000);
  }
  for (int i = 0; i < 24000 && !exists ("rc.txt"); ++i)
    ::usleep (5000);
  ASSERT_FALSE (killed_tile.empty()) << "no tile was seen running";
  std::ifstream rc (path ("rc.txt"));
  int code = 0;
  rc >> code;
  EXPECT_NE (code, 0);
  EXPECT_FALSE (exists ("died.las"));

  ASSERT_EQ (run ("merge " + path ("died.las") + " -workdir " + work), 1);
  EXPECT_NE (output_.find ("tile " + killed_tile + " was started by process " +
                           killed_process + " on host"),
             std::string::npos)
      << "killed process " << killed_process << " in tile " << killed_tile << "\n"
      << output_;
  EXPECT_NE (output_.find ("resume"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("died.las"));

  const std::string resume = mpi + " resume '" + path ("resumed.las") + "' -workdir '" +
                             work + "' -threads 1 > '" + path ("mpi.log") + "' 2>&1";
  ASSERT_EQ (std::system (resume.c_str()), 0);
  expectSameAsWhole ("resumed.las");
}
#endif

TEST_F (TilesApp, StepsInAnyOrderGiveTheSameOutput)
{
  const std::string work = " -workdir " + path ("work");
  ASSERT_EQ (
      run ("plan classify_variance " + path ("scene.pcd") + work + " -tile_size 4"), 0)
      << output_;
  std::ifstream plan (path ("work/plan.txt"));
  ASSERT_TRUE (plan.good());
  std::size_t tiles = 0;
  while (exists ("work/tile_" + std::to_string (tiles) + ".points"))
    ++tiles;
  ASSERT_GT (tiles, 2u);
  ASSERT_EQ (run ("merge " + path ("early.las") + work), 1); // no tile has run
  EXPECT_NE (output_.find ("have not run"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("early.las"));
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("estimate " + std::to_string (t) + work), 0) << output_;
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("tile " + std::to_string (t) + work + " -threads 2"), 0) << output_;
  ASSERT_EQ (run ("merge " + path ("steps.las") + work), 0) << output_;
  expectSameAsWhole ("steps.las");
  EXPECT_EQ (run ("tile " + std::to_string (tiles) + work), 1); // no such tile
  EXPECT_EQ (run ("tile x" + work), 1);
}

namespace {
/** Field \a name of every point of \a path (as labels; empty when missing). */
std::vector<std::uint32_t>
readField (const std::string& path, const std::string& name)
{
  pcl_ext::io::PointFile file;
  std::vector<std::uint32_t> values;
  try {
    pcl_ext::io::loadPointFile (path, file);
  }
  catch (const std::exception&) {
    return values;
  }
  pcl_ext::io::getLabelField (file.cloud, name, values);
  return values;
}
} // namespace

TEST_F (TilesApp, InputsWithDifferentFieldsGoIntoOneOutputWithEveryField)
{
  // The scene cut in two files: its first half with x y z only, the second with every
  // field (colour, intensity, truth). Together they are the scene, so the classes are
  // the untiled tool's on it; the output has every field, 0 where an input lacks it.
  pcl::PCLPointCloud2 scene;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("scene.pcd"), scene), 0);
  const std::size_t n = static_cast<std::size_t> (scene.width) * scene.height;
  pcl::Indices first, second;
  for (std::size_t i = 0; i < n; ++i)
    (i < n / 2 ? first : second).push_back (static_cast<pcl::index_t> (i));
  pcl::PCLPointCloud2 a, b;
  pcl::copyPointCloud (scene, first, a);
  pcl::copyPointCloud (scene, second, b);
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::fromPCLPointCloud2 (a, xyz);
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("a.pcd"), xyz), 0);
  ASSERT_EQ (pcl::io::savePCDFile (path ("b.pcd"),
                                   b,
                                   Eigen::Vector4f::Zero(),
                                   Eigen::Quaternionf::Identity(),
                                   true),
             0);
  ASSERT_EQ (run ("classify_variance " + path ("a.pcd") + " " + path ("b.pcd") + " " +
                  path ("ab.pcd") + " -tile_size 4"),
             0)
      << output_;
  EXPECT_EQ (readField (path ("ab.pcd"), "lv_class"),
             readField (path ("whole.las"), "lv_class"));
  const std::vector<std::uint32_t> truth = readField (path ("scene.pcd"), "label");
  const std::vector<std::uint32_t> written = readField (path ("ab.pcd"), "label");
  ASSERT_EQ (written.size(), n);
  std::size_t labelled = 0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ (written[i], i < n / 2 ? 0u : truth[i]) << "point " << i;
    labelled += truth[i] != 0;
  }
  EXPECT_GT (labelled, n / 4);
  // The same into LAS (the truth as an extra-bytes dimension).
  ASSERT_EQ (run ("classify_variance " + path ("a.pcd") + " " + path ("b.pcd") + " " +
                  path ("ab.las") + " -tile_size 4"),
             0)
      << output_;
  EXPECT_EQ (readField (path ("ab.las"), "lv_class"),
             readField (path ("whole.las"), "lv_class"));
  EXPECT_EQ (readField (path ("ab.las"), "label"), written);
}

TEST_F (TilesApp, BadUsageIsRefusedWithoutOutput)
{
  const std::string scene = path ("scene.pcd");
  EXPECT_EQ (run ("no_method " + scene + " " + path ("a.las")), 1);
  EXPECT_NE (output_.find ("unknown method"), std::string::npos) << output_;
  EXPECT_EQ (run ("classify_variance " + scene + " " + path ("a.laz")),
             1); // not written
  EXPECT_EQ (
      run ("classify_variance " + scene + " " + path ("a.las") + " -tile_size -2"), 1);
  EXPECT_EQ (run ("classify_variance " + scene + " " + path ("a.las") + " -k 2"), 1);
  EXPECT_EQ (run ("classify_variance " + path ("none.las") + " " + path ("a.las")), 1);
  EXPECT_EQ (run ("tile 0"), 1); // no work folder
  EXPECT_EQ (run ("tile 0 -workdir " + path ("nowhere")), 1);
  EXPECT_FALSE (exists ("a.las"));
  EXPECT_FALSE (exists ("a.laz"));
}

TEST_F (TilesApp, OneFilePerTileWithAnIndex)
{
  // 'tile_#.las': a file per tile that owns points, each holding exactly the points of
  // its core box, together the whole cloud's records; the index names each file with
  // its box.
  ASSERT_EQ (run ("classify_variance " + path ("scene.pcd") + " " +
                  path ("tile_#.las") + " -tile_size 3 -threads 2"),
             0)
      << output_;
  std::ifstream index (path ("tile_index.csv"));
  ASSERT_TRUE (index.good()) << output_;
  std::string line;
  std::getline (index, line);
  EXPECT_EQ (line, "file,tile,points,xmin,ymin,xmax,ymax,wkt");
  std::ifstream whole_file (path ("whole.las"), std::ios::binary);
  const std::vector<char> whole_bytes ((std::istreambuf_iterator<char> (whole_file)),
                                       std::istreambuf_iterator<char>());
  std::uint16_t length;
  std::memcpy (&length, &whole_bytes[105], 2);
  ASSERT_GT (length, 0);
  std::multiset<std::string> expected, found;
  for (std::size_t i = 0; i < whole_.records.size() / length; ++i)
    expected.insert (std::string (&whole_.records[i * length], length));
  std::size_t files = 0;
  while (std::getline (index, line)) {
    std::stringstream row (line);
    std::string file, tile, points, box[4];
    std::getline (row, file, ',');
    std::getline (row, tile, ',');
    std::getline (row, points, ',');
    for (auto& b : box)
      std::getline (row, b, ',');
    EXPECT_EQ (file, "tile_" + tile + ".las");
    std::ifstream in (path (file), std::ios::binary);
    const std::vector<char> bytes ((std::istreambuf_iterator<char> (in)),
                                   std::istreambuf_iterator<char>());
    const LasContent content = readLas (path (file));
    EXPECT_TRUE (content.scale_and_offset == whole_.scale_and_offset) << file;
    ASSERT_EQ (content.records.size(), std::stoull (points) * length) << file;
    ASSERT_GT (std::stoull (points), 0u) << file;
    for (std::size_t i = 0; i < std::stoull (points); ++i) {
      const LasXy p = recordXy (bytes, content.records, i);
      // Within the core box, up to the LAS coordinates' rounding.
      EXPECT_GE (p.x, std::stod (box[0]) - 0.001) << file;
      EXPECT_GE (p.y, std::stod (box[1]) - 0.001) << file;
      EXPECT_LE (p.x, std::stod (box[2]) + 0.001) << file;
      EXPECT_LE (p.y, std::stod (box[3]) + 0.001) << file;
      found.insert (std::string (&content.records[i * length], length));
    }
    ++files;
  }
  EXPECT_GT (files, 3u);
  EXPECT_TRUE (found == expected)
      << found.size() << " records against " << expected.size();
  // Only .las can be split.
  EXPECT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path ("t_#.pcd") +
                  " -tile_size 3"),
             1);
  EXPECT_FALSE (exists ("t_index.csv"));
}

TEST_F (TilesApp, AFullDiskStopsTheRunWithAMessageAndNoOutput)
{
  // The work folder fills up while planning (a file may not exceed 50 KB; the
  // results alone need 240 KB).
  const std::string work = " -workdir " + path ("work");
  EXPECT_EQ (runOnFullDisk ("classify_variance " + path ("scene.pcd") + " " +
                                path ("full.las") + work + " -tile_size 3",
                            50),
             1);
  EXPECT_NE (output_.find ("disk full"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("full.las"));
  // The output fills it up while merging: no output, and the merge runs again.
  ASSERT_EQ (
      run ("plan classify_variance " + path ("scene.pcd") + work + " -tile_size 3"), 0)
      << output_;
  std::size_t tiles = 0;
  while (exists ("work/tile_" + std::to_string (tiles) + ".points"))
    ++tiles;
  for (std::size_t t = 0; t < tiles; ++t)
    ASSERT_EQ (run ("estimate " + std::to_string (t) + work), 0) << output_;
  for (std::size_t t = 0; t < tiles; ++t)
    ASSERT_EQ (run ("tile " + std::to_string (t) + work + " -threads 2"), 0) << output_;
  // (The limit is per file: the tiles' files are smaller than the whole cloud's.)
  for (const auto& [out, kilobytes] : std::vector<std::pair<std::string, int>>{
           {"full.las", 1000}, {"full_#.las", 20}}) {
    EXPECT_EQ (runOnFullDisk ("merge " + path (out) + work, kilobytes), 1) << out;
    EXPECT_NE (output_.find ("disk full"), std::string::npos) << output_;
    EXPECT_FALSE (exists (out));
    EXPECT_FALSE (exists ("full_0.las"));
    EXPECT_FALSE (exists ("full_index.csv"));
  }
  ASSERT_EQ (run ("merge " + path ("full.las") + work), 0) << output_;
  expectSameAsWhole ("full.las");
}

TEST_F (TilesApp, SlurmScriptRunsTheStepsAsArrayJobsOrHere)
{
  // scripts/tiles_slurm.sh with an sbatch that runs each job at once (every task of an
  // array in turn), then without sbatch: the untiled tool's bytes both times, and the
  // jobs are the estimates over every tile, tile 0 alone, then the other tiles.
  const std::string shims = path ("shims");
  pcl_ext::test::writeSbatchShim (shims);
  const std::string script = std::string ("PCL_EXT_TILES=") + PCL_EXT_TILES_EXE +
                             " bash " + PCL_EXT_SOURCE_DIR + "/scripts/tiles_slurm.sh";
  const std::string job = " classify_variance '" + path ("slurm.las") + "' '" +
                          path ("scene.pcd") + "' -- -tile_size 4 > '" +
                          path ("slurm.log") + "' 2>&1";
  ASSERT_EQ (std::system (("PATH=" + shims + ":$PATH " + script + job).c_str()), 0);
  expectSameAsWhole ("slurm.las");
  const std::vector<std::string> jobs = pcl_ext::test::sbatchJobs (shims);
  ASSERT_EQ (jobs.size(), 4u);
  EXPECT_EQ (jobs[0].rfind ("array=0-", 0), 0u) << jobs[0];
  EXPECT_NE (jobs[0].find (" estimate $SLURM_ARRAY_TASK_ID"), std::string::npos);
  EXPECT_EQ (jobs[1].rfind ("array=none ", 0), 0u) << jobs[1];
  EXPECT_NE (jobs[1].find (" tile 0"), std::string::npos) << jobs[1];
  EXPECT_EQ (jobs[2].rfind ("array=1-", 0), 0u) << jobs[2];
  const auto lastTile = [] (const std::string& job) {
    return job.substr (8, job.find (' ') - 8);
  };
  EXPECT_EQ (lastTile (jobs[0]), lastTile (jobs[2]));
  EXPECT_NE (lastTile (jobs[0]), "0");
  EXPECT_NE (jobs[3].find (" merge "), std::string::npos) << jobs[3];

  if (std::system ("PATH=/usr/bin:/bin command -v sbatch > /dev/null 2>&1") == 0)
    return; // a machine with Slurm: the script would submit
  std::filesystem::remove_all (path ("slurm.las.tiles"));
  std::filesystem::remove (path ("slurm.las"));
  ASSERT_EQ (std::system (("PATH=/usr/bin:/bin " + script + job).c_str()), 0);
  expectSameAsWhole ("slurm.las");
}

TEST_F (TilesApp, TheCurvatureFactorChosenFromTheWholeCloudsNoise)
{
  // A floor and a box, 5 cm apart with 1.5 cm of noise: a range camera's share (above
  // 0.2 spacings), for which the classifier takes the median curvature itself as the
  // threshold; the tiles choose it from the whole cloud's noise sample, as untiled.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl_ext::RandomStream noise (7);
  const auto add = [&] (double x, double y, double z, int axis) {
    double p[3] = {x, y, z};
    p[axis] +=
        0.015 * (noise.uniform() + noise.uniform() + noise.uniform() - 1.5) * 2.0;
    cloud.push_back (pcl::PointXYZ (static_cast<float> (p[0]),
                                    static_cast<float> (p[1]),
                                    static_cast<float> (p[2])));
  };
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 120; ++j)
      add (i * 0.05, j * 0.05, 0.0, 2);
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      add (2.0 + i * 0.05, 2.0 + j * 0.05, 1.0, 2); // the lid
      add (2.0 + i * 0.05, 2.0, j * 0.05, 1);       // two sides
      add (2.0, 2.0 + i * 0.05, j * 0.05, 0);
    }
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("noisy.pcd"), cloud), 0);
  const std::string whole = std::string (PCL_EXT_CLASSIFY_VARIANCE_EXE) + " '" +
                            path ("noisy.pcd") + "' '" + path ("noisy_whole.las") +
                            "' -v > '" + path ("whole.log") + "' 2>&1";
  ASSERT_EQ (std::system (whole.c_str()), 0);
  std::ifstream log (path ("whole.log"));
  const std::string text ((std::istreambuf_iterator<char> (log)),
                          std::istreambuf_iterator<char>());
  ASSERT_NE (text.find ("(1 x the median curvature)"), std::string::npos) << text;
  whole_ = readLas (path ("noisy_whole.las"));
  ASSERT_EQ (run ("classify_variance " + path ("noisy.pcd") + " " + path ("n2.las") +
                  " -tile_size 2 -threads 1"),
             0)
      << output_;
  expectSameAsWhole ("n2.las");
}

TEST_F (TilesApp, TheDerivedPresetRemovesTheWholeCloudsNoise)
{
  // The noise estimated once from every tile's part of the whole cloud's sample,
  // removed from eq. 4-6 on every tile, the threshold at the median of the curvatures
  // with it removed: the classes of pcl_ext_classify_variance -preset derived.
  const std::string whole = std::string (PCL_EXT_CLASSIFY_VARIANCE_EXE) + " '" +
                            path ("scene.pcd") + "' '" + path ("derived.las") +
                            "' -preset derived -v > '" + path ("derived.log") +
                            "' 2>&1";
  ASSERT_EQ (std::system (whole.c_str()), 0);
  std::ifstream log (path ("derived.log"));
  const std::string text ((std::istreambuf_iterator<char> (log)),
                          std::istreambuf_iterator<char>());
  ASSERT_NE (text.find ("Estimated from the cloud: noise sigma"), std::string::npos)
      << text;
  ASSERT_EQ (text.find ("not removed"), std::string::npos) << text;
  const LasContent defaults = whole_;
  whole_ = readLas (path ("derived.las"));
  ASSERT_FALSE (whole_.records == defaults.records); // the preset changes classes
  for (const char* tile_size : {"3", "7"}) {
    const std::string out = std::string ("d") + tile_size + ".las";
    ASSERT_EQ (run ("classify_variance " + path ("scene.pcd") + " " + path (out) +
                    " -preset derived -threads 1 -tile_size " + tile_size),
               0)
        << output_;
    expectSameAsWhole (out);
  }
}
