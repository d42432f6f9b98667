/*
 * pcl_ext_tiles segment_profiles run as a command: split by profiles, over one process
 * or several MPI ranks, it gives pcl_ext_segment_profiles's bytes on the whole cloud.
 */
#include "../app_test.h"
#include "sbatch_shim.h"

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {
class TilesProfilesApp : public pcl_ext::test::AppTest {
protected:
  TilesProfilesApp() : AppTest (PCL_EXT_TILES_EXE) {}

  /** Generate \a scene with \a points points into \a name. */
  void
  generate (const std::string& scene, const std::string& name, int points)
  {
    const std::string command = std::string (PCL_EXT_GENERATE_SCENE_EXE) + " " + scene +
                                " '" + path (name) + "' -points " +
                                std::to_string (points) + " -seed 2 > /dev/null 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0);
  }

  /** pcl_ext_segment_profiles on \a input into \a output with \a options. */
  void
  segmentWhole (const std::string& input,
                const std::string& output,
                const std::string& options)
  {
    const std::string command = std::string (PCL_EXT_SEGMENT_PROFILES_EXE) + " '" +
                                path (input) + "' '" + path (output) + "' " + options +
                                " > '" + path ("whole.log") + "' 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0);
  }

  std::string
  bytes (const std::string& name) const
  {
    std::ifstream in (path (name), std::ios::binary);
    return std::string ((std::istreambuf_iterator<char> (in)),
                        std::istreambuf_iterator<char>());
  }

  void
  expectSameBytes (const std::string& a, const std::string& b)
  {
    ASSERT_TRUE (exists (a)) << a;
    ASSERT_TRUE (exists (b)) << b;
    const std::string x = bytes (a), y = bytes (b);
    EXPECT_GT (x.size(), 1000u);
    EXPECT_TRUE (x == y) << a << " and " << b << " differ";
  }
};
} // namespace

TEST_F (TilesProfilesApp, PartsOfWholeProfilesGiveTheWholeCloudsSegments)
{
  // Cubes on no floor: -method auto keeps proximity chaining. Some points are not
  // finite (segment 0 in both). One part per stack, then slabs of 0.5 m (tens of
  // parts a stack): the same bytes as the whole cloud's.
  generate ("cubes", "cubes.pcd", 20000);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_EQ (pcl::io::loadPCDFile (path ("cubes.pcd"), cloud), 0);
  for (std::size_t i = 0; i < cloud.size(); i += 97)
    cloud[i].x = std::numeric_limits<float>::quiet_NaN();
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("scene.pcd"), cloud), 0);
  segmentWhole ("scene.pcd", "whole.pcd", "-v");
  std::ifstream log (path ("whole.log"));
  const std::string text ((std::istreambuf_iterator<char> (log)),
                          std::istreambuf_iterator<char>());
  ASSERT_NE (text.find ("chosen: proximity"), std::string::npos) << text;
  for (const std::string size : {"0", "0.5"}) {
    ASSERT_EQ (run ("segment_profiles " + path ("scene.pcd") + " " +
                    path ("t" + size + ".pcd") + " -tile_size " + size + " -v"),
               0)
        << output_;
    EXPECT_NE (output_.find ("chosen: proximity"), std::string::npos) << output_;
    expectSameBytes ("whole.pcd", "t" + size + ".pcd");
  }
  EXPECT_NE (output_.find ("peak memory"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("t0.5.pcd.tiles")); // the work folder is removed
}

TEST_F (TilesProfilesApp, LocalThresholdsTakeTheWholeCloudsMeanGaps)
{
  // Six square patches 1.2 m apart, three sampled every 1 cm and three every 5 cm:
  // -method auto adds local thresholds (each stack's mean local gap over the whole
  // cloud, summed over the parts in the points' order) and runs again. The given
  // segmenters with -local_threshold too.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int patch = 0; patch < 6; ++patch) {
    const float step = patch % 2 ? 0.05f : 0.01f;
    const float x0 = 1.2f * static_cast<float> (patch % 3);
    const float y0 = 2.5f * static_cast<float> (patch / 3);
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j)
        cloud.push_back (pcl::PointXYZ (x0 + step * static_cast<float> (i),
                                        y0 + step * static_cast<float> (j),
                                        0.3f * step * static_cast<float> (i + j)));
  }
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("patches.pcd"), cloud), 0);
  segmentWhole ("patches.pcd", "whole.pcd", "-v");
  std::ifstream log (path ("whole.log"));
  const std::string text ((std::istreambuf_iterator<char> (log)),
                          std::istreambuf_iterator<char>());
  ASSERT_NE (text.find ("chosen: proximity, local thresholds"), std::string::npos)
      << text;
  ASSERT_EQ (run ("segment_profiles " + path ("patches.pcd") + " " + path ("t.pcd") +
                  " -tile_size 0.3"),
             0)
      << output_;
  expectSameBytes ("whole.pcd", "t.pcd");
  generate ("spheres", "spheres.pcd", 30000);
  for (const std::string method : {"proximity", "mst"}) {
    segmentWhole (
        "spheres.pcd", method + ".pcd", "-method " + method + " -local_threshold");
    ASSERT_EQ (run ("segment_profiles " + path ("spheres.pcd") + " " +
                    path ("t_" + method + ".pcd") + " -method " + method +
                    " -local_threshold -tile_size 1"),
               0)
        << output_;
    expectSameBytes (method + ".pcd", "t_" + method + ".pcd");
  }
}

TEST_F (TilesProfilesApp, CurveFittingOverPartsGivesTheWholeCloudsBytes)
{
  // A building on the ground: curve fitting's curve ends come from each stack's
  // medians over every part, a breakpoint of any stack is one in all, and the segments
  // around them are labelled over the whole graph. One part per stack, 2 m slabs, and
  // with local thresholds.
  generate ("building", "building.pcd", 20000);
  for (const std::string options :
       {"-method curve", "-method curve -local_threshold"}) {
    segmentWhole ("building.pcd", "whole.pcd", options);
    for (const std::string size : {"0", "2"}) {
      ASSERT_EQ (run ("segment_profiles " + path ("building.pcd") + " " +
                      path ("t.pcd") + " " + options + " -tile_size " + size),
                 0)
          << output_;
      expectSameBytes ("whole.pcd", "t.pcd");
    }
  }
}

TEST_F (TilesProfilesApp, AutoOnTouchingSurfacesFitsCurvesAndJoinsCylinders)
{
  // Coaxial pipes on the ground, a noisy scan for its spacing: -method auto chooses
  // curve fitting for noisy scans (profiles 2.5 spacings wide: the parts are planned
  // again), side frames and the cylinder join, which runs once over the whole cloud's
  // segments and joins two cylinders. Its defaults, one part a stack and 1 m slabs;
  // then the join after proximity chaining (-join_cylinders): the whole cloud's bytes.
  generate ("coaxial", "coaxial.pcd", 30000);
  segmentWhole ("coaxial.pcd", "whole.pcd", "-v");
  std::ifstream log (path ("whole.log"));
  const std::string text ((std::istreambuf_iterator<char> (log)),
                          std::istreambuf_iterator<char>());
  ASSERT_NE (text.find ("chosen: curve fitting for noisy scans, side frames, cylinder "
                        "join"),
             std::string::npos)
      << text;
  ASSERT_NE (text.find (", 2 cylinders joined"), std::string::npos) << text;
  for (const std::string size : {"0", "1"}) {
    ASSERT_EQ (run ("segment_profiles " + path ("coaxial.pcd") + " " + path ("t.pcd") +
                    " -v -tile_size " + size),
               0)
        << output_;
    EXPECT_NE (output_.find ("parts of whole profiles of the noisy-scan width"),
               std::string::npos)
        << output_;
    EXPECT_NE (output_.find ("  2 cylinders joined"), std::string::npos) << output_;
    expectSameBytes ("whole.pcd", "t.pcd");
  }
  generate ("pipes", "pipes.pcd", 30000);
  segmentWhole ("pipes.pcd", "joined.pcd", "-method proximity -join_cylinders");
  ASSERT_EQ (run ("segment_profiles " + path ("pipes.pcd") + " " + path ("tj.pcd") +
                  " -method proximity -join_cylinders -tile_size 1"),
             0)
      << output_;
  expectSameBytes ("joined.pcd", "tj.pcd");
}

TEST_F (TilesProfilesApp, StepsAndTheSlurmScriptFollowTheCommandsPasses)
{
  // -method auto on coaxial pipes in steps: chains, the choice (curve fitting for a
  // noisy scan: parts of the wider profiles planned again), the curve scores, the curve
  // joins and the merge with the cylinder join, each pass named by the step before it.
  // The merge before the passes and parts that do not exist are refused; a run stopped
  // after one part resumes; the Slurm script loops over the passes. All give the whole
  // cloud's bytes, and so does a merge run again after a broken part file or a full
  // disk.
  generate ("coaxial", "coaxial.pcd", 30000);
  segmentWhole ("coaxial.pcd", "whole.pcd", "");
  const std::string work = " -workdir '" + path ("work") + "' -threads 1";
  ASSERT_EQ (run ("plan segment_profiles '" + path ("coaxial.pcd") + "'" + work +
                  " -tile_size 1"),
             0)
      << output_;
  std::string named = output_;
  EXPECT_EQ (run ("merge '" + path ("early.pcd") + "'" + work), 1);
  EXPECT_NE (output_.find ("is at 'chains'"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("early.pcd"));
  std::vector<std::string> stages;
  for (int pass = 0; pass < 6; ++pass) {
    const std::size_t at = named.find ("Next: ");
    ASSERT_NE (at, std::string::npos) << named;
    std::istringstream next (named.substr (at + 6));
    std::string stage, on;
    std::size_t parts = 0;
    next >> stage >> on >> parts;
    stages.push_back (stage);
    if (stage == "merge")
      break;
    ASSERT_GT (parts, 1u);
    EXPECT_EQ (run ("part " + std::to_string (parts) + work), 1);
    for (std::size_t i = 0; i < parts; ++i)
      ASSERT_EQ (run ("part " + std::to_string (i) + work), 0) << output_;
    ASSERT_EQ (run ("next" + work), 0) << output_;
    named = output_;
  }
  EXPECT_EQ (
      stages,
      (std::vector<std::string>{"chains", "curve_scores", "curve_joins", "merge"}));
  // A part's points cut short: the merge names the file and writes nothing.
  const std::string points_file = path ("work/profiles_0_0.points");
  const std::string all_points = bytes ("work/profiles_0_0.points");
  ASSERT_GT (all_points.size(), 5u);
  std::ofstream (points_file, std::ios::binary)
      << all_points.substr (0, all_points.size() - 5);
  EXPECT_EQ (run ("merge '" + path ("steps.pcd") + "'" + work), 1);
  EXPECT_NE (output_.find ("profiles_0_0.points is broken"), std::string::npos)
      << output_;
  EXPECT_FALSE (exists ("steps.pcd"));
  std::ofstream (points_file, std::ios::binary) << all_points;
  // The work folder fills up while the cylinder join groups the points by segment (a
  // file may not exceed 200 KB; their coordinates need 12 bytes a point): a message and
  // no output; the merge then runs again.
  EXPECT_EQ (runOnFullDisk ("merge '" + path ("steps.pcd") + "'" + work, 200), 1);
  EXPECT_NE (output_.find ("segment_points.xyz (disk full?)"), std::string::npos)
      << output_;
  EXPECT_FALSE (exists ("steps.pcd"));
  ASSERT_EQ (run ("merge '" + path ("steps.pcd") + "'" + work), 0) << output_;
  EXPECT_NE (output_.find ("  2 cylinders joined"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("work/segment_points.xyz"));
  expectSameBytes ("whole.pcd", "steps.pcd");

  // Stopped after one part of the first pass, whose links file then lost a value: the
  // reduction names the broken file; a plan that stopped while its parts were written
  // again is refused; resume runs the passes left.
  const std::string again = " -workdir '" + path ("again") + "' -threads 1";
  ASSERT_EQ (run ("plan segment_profiles '" + path ("coaxial.pcd") + "'" + again), 0);
  ASSERT_EQ (run ("part 0" + again), 0) << output_;
  const std::string links = path ("again/profiles_0_0.links");
  const std::string good = bytes ("again/profiles_0_0.links");
  ASSERT_GT (good.size(), 8u);
  std::ofstream (links, std::ios::binary) << good.substr (0, good.size() - 8);
  EXPECT_EQ (run ("next" + again), 1);
  EXPECT_NE (output_.find ("profiles_0_0.links is broken"), std::string::npos)
      << output_;
  const std::string plan = bytes ("again/plan.txt");
  const std::string stage = "setting profile_stage chains";
  ASSERT_NE (plan.find (stage), std::string::npos) << plan;
  std::string stopped = plan;
  stopped.replace (plan.find (stage), stage.size(), "setting profile_stage replanning");
  std::ofstream (path ("again/plan.txt")) << stopped;
  EXPECT_EQ (run ("part 0" + again), 1);
  EXPECT_NE (output_.find ("plan it again"), std::string::npos) << output_;
  std::ofstream (path ("again/plan.txt")) << plan;
  ASSERT_EQ (run ("resume '" + path ("resumed.pcd") + "'" + again), 0) << output_;
  expectSameBytes ("whole.pcd", "resumed.pcd");

  const std::string shims = path ("shims");
  pcl_ext::test::writeSbatchShim (shims);
  const std::string command =
      "PATH=" + shims + ":$PATH PCL_EXT_TILES=" + PCL_EXT_TILES_EXE + " bash " +
      PCL_EXT_SOURCE_DIR + "/scripts/tiles_slurm.sh segment_profiles '" +
      path ("slurm.pcd") + "' '" + path ("coaxial.pcd") + "' -- -tile_size 1 > '" +
      path ("slurm.log") + "' 2>&1";
  ASSERT_EQ (std::system (command.c_str()), 0);
  expectSameBytes ("whole.pcd", "slurm.pcd");
  const std::vector<std::string> jobs = pcl_ext::test::sbatchJobs (shims);
  ASSERT_EQ (jobs.size(), 7u);
  for (const std::size_t pass : {0u, 2u, 4u}) {
    EXPECT_EQ (jobs[pass].rfind ("array=0-", 0), 0u) << jobs[pass];
    EXPECT_NE (jobs[pass].find (" part $SLURM_ARRAY_TASK_ID"), std::string::npos);
    EXPECT_NE (jobs[pass + 1].find (" next"), std::string::npos) << jobs[pass + 1];
  }
  EXPECT_NE (jobs[6].find (" merge "), std::string::npos) << jobs[6];
}

TEST_F (TilesProfilesApp, InputsWithoutFinitePointsOrBadOptionsAreRefused)
{
  // Every point NaN: refused at the plan, no output; nonsense options before any pass.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 100; ++i)
    cloud.push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f));
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("nan.pcd"), cloud), 0);
  EXPECT_EQ (run ("segment_profiles " + path ("nan.pcd") + " " + path ("n.pcd")), 1);
  EXPECT_NE (output_.find ("no point with finite coordinates"), std::string::npos)
      << output_;
  EXPECT_FALSE (exists ("n.pcd"));
  generate ("cubes", "cubes.pcd", 5000);
  for (const std::string option :
       {"-method nonsense",
        "-min_size 0",
        "-tile_size -1",
        "-distribution flat",
        "-join_cylinders -cylinder_tolerance 0",
        "-join_cylinders -cylinder_min_radius 0.5 -cylinder_max_radius 0.1"}) {
    EXPECT_EQ (run ("segment_profiles " + path ("cubes.pcd") + " " + path ("c.pcd") +
                    " " + option),
               1)
        << option;
    EXPECT_FALSE (exists ("c.pcd")) << option;
  }
}

#ifdef PCL_EXT_MPIEXEC
TEST_F (TilesProfilesApp, MpiRanksShareThePartsAndGiveTheSameBytes)
{
  generate ("spheres", "spheres.pcd", 30000);
  segmentWhole ("spheres.pcd", "whole.pcd", "-local_threshold");
  for (const int ranks : {2, 4}) {
    const std::string out = "mpi" + std::to_string (ranks) + ".pcd";
    const std::string command =
        std::string (PCL_EXT_MPIEXEC) + " --allow-run-as-root --oversubscribe -np " +
        std::to_string (ranks) + " " + PCL_EXT_TILES_EXE + " segment_profiles '" +
        path ("spheres.pcd") + "' '" + path (out) +
        "' -local_threshold -tile_size 0.7 -threads 1 > '" + path ("mpi.log") +
        "' 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0) << ranks << " ranks";
    std::ifstream log (path ("mpi.log"));
    const std::string text ((std::istreambuf_iterator<char> (log)),
                            std::istreambuf_iterator<char>());
    EXPECT_NE (text.find ("Rank " + std::to_string (ranks - 1) + ": done"),
               std::string::npos)
        << text;
    expectSameBytes ("whole.pcd", out);
  }
  // Curve fitting: the ranks share the three passes.
  generate ("building", "building.pcd", 20000);
  segmentWhole ("building.pcd", "curve.pcd", "-method curve");
  const std::string command =
      std::string (PCL_EXT_MPIEXEC) + " --allow-run-as-root --oversubscribe -np 2 " +
      PCL_EXT_TILES_EXE + " segment_profiles '" + path ("building.pcd") + "' '" +
      path ("mpi_curve.pcd") + "' -method curve -tile_size 3 -threads 1 > '" +
      path ("mpi.log") + "' 2>&1";
  ASSERT_EQ (std::system (command.c_str()), 0);
  expectSameBytes ("curve.pcd", "mpi_curve.pcd");
  // -method auto's choice, the parts planned again and the cylinder join: the ranks
  // learn the choice and the new parts through the plan.
  generate ("coaxial", "coaxial.pcd", 30000);
  segmentWhole ("coaxial.pcd", "auto.pcd", "");
  const std::string automatic =
      std::string (PCL_EXT_MPIEXEC) + " --allow-run-as-root --oversubscribe -np 2 " +
      PCL_EXT_TILES_EXE + " segment_profiles '" + path ("coaxial.pcd") + "' '" +
      path ("mpi_auto.pcd") + "' -tile_size 1 -threads 1 > '" + path ("mpi.log") +
      "' 2>&1";
  ASSERT_EQ (std::system (automatic.c_str()), 0);
  expectSameBytes ("auto.pcd", "mpi_auto.pcd");
}
#endif
