/*
 * pcl_ext_tiles segment_variance run as a command: generated scenes segmented tile by
 * tile, in one command, in steps and shared among MPI ranks, give the segments of
 * pcl_ext_segment_variance on the whole cloud (the same partition of the points, and
 * the same ids: largest first), with section 4's re-integration and the new segments
 * among the points left out (-reintegrate: a second and a third pass over the tiles),
 * with the new segments alone (the tiles' default) and without either; a wall across
 * four tiles' corner is one segment; a tile that owns no point, a tile of one point and
 * points without coordinates change nothing.
 */
#include "../app_test.h"
#include "sbatch_shim.h"

#include <pcl_ext/io/point_file.h>

#include <pcl/PCLPointCloud2.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {
/** An output's points (x, y relative to the file's origin) and segment ids. */
struct Segments {
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> ids;
  std::vector<char> bytes; ///< the whole file
};

Segments
readSegments (const std::string& path)
{
  Segments s;
  std::ifstream in (path, std::ios::binary);
  s.bytes.assign (std::istreambuf_iterator<char> (in),
                  std::istreambuf_iterator<char>());
  pcl_ext::io::PointFile file;
  try {
    pcl_ext::io::loadPointFile (path, file);
  }
  catch (const std::exception&) {
    return s;
  }
  const auto& c = file.cloud;
  int seg = -1;
  for (std::size_t f = 0; f < c.fields.size(); ++f)
    if (c.fields[f].name == "seg")
      seg = static_cast<int> (f);
  if (seg < 0 || c.fields[seg].datatype != pcl::PCLPointField::UINT32)
    return s;
  const std::size_t n = static_cast<std::size_t> (c.width) * c.height;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = c.data.data() + i * c.point_step;
    float xyz[3];
    std::memcpy (xyz, p, sizeof (xyz)); // x y z come first
    std::uint32_t id;
    std::memcpy (&id, p + c.fields[seg].offset, 4);
    s.x.push_back (xyz[0]);
    s.y.push_back (xyz[1]);
    s.z.push_back (xyz[2]);
    s.ids.push_back (id);
  }
  return s;
}

/** The points whose segment differs between \a a and \a b up to renumbering: in a
 * segment in one and in none in the other, or breaking the one-to-one map of ids. */
std::size_t
differingPoints (const std::vector<std::uint32_t>& a,
                 const std::vector<std::uint32_t>& b)
{
  if (a.size() != b.size())
    return std::max (a.size(), b.size());
  std::map<std::uint32_t, std::uint32_t> a_to_b, b_to_a;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if ((a[i] == 0) != (b[i] == 0)) {
      ++differ;
      continue;
    }
    if (a[i] == 0)
      continue;
    const auto ab = a_to_b.emplace (a[i], b[i]).first;
    const auto ba = b_to_a.emplace (b[i], a[i]).first;
    differ += ab->second != b[i] || ba->second != a[i];
  }
  return differ;
}

class TilesSegmentsApp : public pcl_ext::test::AppTest {
protected:
  TilesSegmentsApp() : AppTest (PCL_EXT_TILES_EXE) {}

  /** Generate \a scene (60,000 points, seed 2) and segment it whole with \a options
   * (none: the defaults, section 4's re-integration and the new segments among the
   * points left out included) and -no_merge -no_assign: the tiles do not yet merge
   * interleaved pieces of one plane or assign the points left over (docs/tiles.md). */
  void
  makeScene (const std::string& scene, const std::string& options = "")
  {
    const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) + " " +
                                 scene + " '" + path ("scene.pcd") +
                                 "' -points 60000 -seed 2 > /dev/null 2>&1";
    ASSERT_EQ (std::system (generate.c_str()), 0);
    const std::string whole = std::string (PCL_EXT_SEGMENT_VARIANCE_EXE) + " '" +
                              path ("scene.pcd") + "' '" + path ("whole.las") +
                              "' -output_field seg " + options +
                              " -no_merge -no_assign > /dev/null 2>&1";
    ASSERT_EQ (std::system (whole.c_str()), 0);
    whole_ = readSegments (path ("whole.las"));
    ASSERT_FALSE (whole_.ids.empty());
    const std::set<std::uint32_t> ids (whole_.ids.begin(), whole_.ids.end());
    ASSERT_GT (ids.size(), 10u); // a dozen segments or more
  }

  /** Segment the scene tile by tile into \a output with \a options. */
  int
  runTiled (const std::string& output, const std::string& options)
  {
    return run ("segment_variance '" + path ("scene.pcd") + "' '" + path (output) +
                "' -output_field seg " + options);
  }

  void
  expectSameAsWhole (const std::string& output)
  {
    const Segments tiled = readSegments (path (output));
    EXPECT_EQ (tiled.ids.size(), whole_.ids.size()) << output;
    EXPECT_EQ (differingPoints (whole_.ids, tiled.ids), 0u) << output;
    EXPECT_TRUE (tiled.bytes == whole_.bytes) << output; // the ids too: largest first
  }

  Segments whole_;
};
} // namespace

TEST_F (TilesSegmentsApp, AnyTileSizeGivesTheWholeCloudsSegments)
{
  // Section 4 (-reintegrate) as the whole cloud's default.
  makeScene ("indoor");
  ASSERT_EQ (runTiled ("t3.las", "-tile_size 3 -threads 1 -reintegrate"), 0) << output_;
  expectSameAsWhole ("t3.las");
  // The tool says which stages of the untiled defaults it leaves out.
  EXPECT_NE (output_.find ("-no_merge -no_assign's result"), std::string::npos)
      << output_;
  // A halo far too small: the tiles widen themselves, in both passes.
  ASSERT_EQ (runTiled ("t7.las", "-tile_size 7 -halo 0.05 -reintegrate"), 0) << output_;
  expectSameAsWhole ("t7.las");
}

TEST_F (TilesSegmentsApp, WithoutSectionFourByDefault)
{
  // By default sections 2 and 3 and the new segments among the points left out, as
  // pcl_ext_segment_variance -no_reintegrate -leftovers: the tool says so.
  makeScene ("indoor", "-no_reintegrate -leftovers");
  ASSERT_EQ (runTiled ("t3.las", "-tile_size 3"), 0) << output_;
  expectSameAsWhole ("t3.las");
  EXPECT_EQ (output_.find (", second pass"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("points left out grouped"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("unless -reintegrate"), std::string::npos) << output_;
  const Segments grown = whole_;
  // -no_reintegrate: sections 2 and 3 alone, as untiled.
  makeScene ("indoor", "-no_reintegrate");
  ASSERT_EQ (runTiled ("n3.las", "-tile_size 3 -no_reintegrate"), 0) << output_;
  expectSameAsWhole ("n3.las");
  EXPECT_EQ (output_.find ("unless -reintegrate"), std::string::npos) << output_;
  EXPECT_EQ (output_.find ("points left out grouped"), std::string::npos) << output_;
  // -reintegrate puts edge and boundary points into segments: more points in them.
  ASSERT_EQ (runTiled ("d3.las", "-tile_size 3 -reintegrate -no_leftovers"), 0)
      << output_;
  EXPECT_NE (output_.find (", second pass"), std::string::npos) << output_;
  const Segments reintegrated = readSegments (path ("d3.las"));
  ASSERT_EQ (reintegrated.ids.size(), whole_.ids.size());
  ASSERT_EQ (grown.ids.size(), whole_.ids.size());
  std::size_t before = 0, after = 0, left_out_grouped = 0;
  for (std::size_t i = 0; i < whole_.ids.size(); ++i) {
    before += whole_.ids[i] != 0;
    after += reintegrated.ids[i] != 0;
    left_out_grouped += grown.ids[i] != 0;
    // A point segmented by sections 2 and 3 keeps its segment in either.
    if (whole_.ids[i] != 0) {
      ASSERT_NE (reintegrated.ids[i], 0u);
      ASSERT_EQ (grown.ids[i], whole_.ids[i]);
    }
  }
  EXPECT_GT (after, before + whole_.ids.size() / 20);
  EXPECT_GT (left_out_grouped, before);
}

TEST_F (TilesSegmentsApp, TheNewSegmentsAmongThePointsLeftOutAreTheWholeClouds)
{
  // The pipes of the pipes scene have no surface point to grow from: the new segments
  // among the points left out (on by default with section 4) are most of them. Their
  // links reach across the tiles' borders and are joined there; their sizes and ids
  // are the whole cloud's.
  makeScene ("pipes");
  const std::string without =
      std::string (PCL_EXT_SEGMENT_VARIANCE_EXE) + " '" + path ("scene.pcd") + "' '" +
      path ("without.las") +
      "' -output_field seg -no_leftovers -no_merge -no_assign > /dev/null 2>&1";
  ASSERT_EQ (std::system (without.c_str()), 0);
  const Segments before = readSegments (path ("without.las"));
  const std::set<std::uint32_t> ids_before (before.ids.begin(), before.ids.end());
  const std::set<std::uint32_t> ids (whole_.ids.begin(), whole_.ids.end());
  ASSERT_GT (ids.size(), ids_before.size() + 5); // new segments
  ASSERT_EQ (runTiled ("t4.las", "-tile_size 4 -reintegrate"), 0) << output_;
  EXPECT_NE (output_.find ("points left out grouped"), std::string::npos) << output_;
  expectSameAsWhole ("t4.las");

  // Without section 4 (the tiles' default): a second pass, not a third.
  makeScene ("pipes", "-no_reintegrate -leftovers");
  ASSERT_EQ (runTiled ("l4.las", "-tile_size 4"), 0) << output_;
  EXPECT_EQ (output_.find (", second pass"), std::string::npos) << output_;
  EXPECT_NE (output_.find ("points left out grouped"), std::string::npos) << output_;
  expectSameAsWhole ("l4.las");
}

TEST_F (TilesSegmentsApp, AWallAcrossFourTilesCornerIsOneSegment)
{
  // The room's wall y = 0 lies on a row of tile borders (tiles on multiples of 3 m),
  // its points on both sides of it (range noise); x = 3 is a column of borders. Its
  // points around the corner (3, 0) lie in four tiles, and are one segment after
  // section 3 (the tiles' segments joined through their halos). Section 4
  // (-reintegrate) keeps that segment's points in it, also in all four tiles; it may
  // give a few of the wall's edge points to a segment they fit better, as untiled.
  makeScene ("indoor");
  ASSERT_EQ (runTiled ("t3.las", "-tile_size 3 -no_leftovers"), 0) << output_;
  ASSERT_EQ (runTiled ("d3.las", "-tile_size 3 -reintegrate -no_leftovers"), 0)
      << output_;
  const Segments tiled = readSegments (path ("t3.las"));
  const Segments reintegrated = readSegments (path ("d3.las"));
  ASSERT_EQ (tiled.ids.size(), whole_.ids.size());
  ASSERT_EQ (reintegrated.ids.size(), whole_.ids.size());
  std::set<std::uint32_t> ids;
  std::size_t in_quadrant[4] = {};
  for (std::size_t i = 0; i < tiled.ids.size(); ++i) {
    const float x = tiled.x[i], y = tiled.y[i], z = tiled.z[i];
    if (std::abs (x - 3.0f) > 1.0f || std::abs (y) > 0.05f || z < 0.5f || z > 2.5f ||
        tiled.ids[i] == 0)
      continue;
    ids.insert (tiled.ids[i]);
    EXPECT_EQ (reintegrated.ids[i], tiled.ids[i]) << i;
    ++in_quadrant[(x >= 3.0f ? 1 : 0) + (y >= 0.0f ? 2 : 0)];
  }
  for (int q = 0; q < 4; ++q)
    EXPECT_GT (in_quadrant[q], 0u) << "no wall point in quadrant " << q;
  EXPECT_EQ (ids.size(), 1u);
}

TEST_F (TilesSegmentsApp, StepsInAnyOrderGiveTheSameSegments)
{
  makeScene ("indoor");
  const std::string work = " -workdir " + path ("work");
  ASSERT_EQ (run ("plan segment_variance " + path ("scene.pcd") + work +
                  " -output_field seg -tile_size 4 -reintegrate"),
             0)
      << output_;
  std::size_t tiles = 0;
  while (exists ("work/tile_" + std::to_string (tiles) + ".points"))
    ++tiles;
  ASSERT_GT (tiles, 2u);
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("estimate " + std::to_string (t) + work), 0) << output_;
  ASSERT_EQ (run ("merge " + path ("early.las") + work), 1); // no tile has run
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("tile " + std::to_string (t) + work + " -threads 2"), 0) << output_;
  // Section 4: a second pass over the tiles, after all of them.
  ASSERT_EQ (run ("merge " + path ("early.las") + work), 1);
  EXPECT_NE (output_.find ("refine I"), std::string::npos) << output_;
  // The new segments among the points left out: a third pass, once every tile has
  // run the second.
  ASSERT_EQ (run ("grow 0" + work), 1);
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("refine " + std::to_string (t) + work), 0) << output_;
  ASSERT_EQ (run ("merge " + path ("early.las") + work), 1);
  EXPECT_NE (output_.find ("grow I"), std::string::npos) << output_;
  for (std::size_t t = tiles; t-- > 0;)
    ASSERT_EQ (run ("grow " + std::to_string (t) + work), 0) << output_;
  ASSERT_EQ (run ("merge " + path ("steps.las") + work), 0) << output_;
  expectSameAsWhole ("steps.las");
}

TEST_F (TilesSegmentsApp, SlurmScriptRunsTheSecondPassAfterTheTiles)
{
  // scripts/tiles_slurm.sh with a stand-in sbatch: estimates, tile 0, the other tiles,
  // then the second pass (tile 0 alone, as it joins the segments, then the others), the
  // third (the points left out grouped, likewise) and the merge; the untiled tool's
  // bytes.
  makeScene ("indoor");
  const std::string shims = path ("shims");
  pcl_ext::test::writeSbatchShim (shims);
  const std::string command =
      "PATH=" + shims + ":$PATH PCL_EXT_TILES=" + PCL_EXT_TILES_EXE + " bash " +
      PCL_EXT_SOURCE_DIR + "/scripts/tiles_slurm.sh segment_variance '" +
      path ("slurm.las") + "' '" + path ("scene.pcd") +
      "' -- -output_field seg -tile_size 4 -reintegrate > '" + path ("slurm.log") +
      "' 2>&1";
  ASSERT_EQ (std::system (command.c_str()), 0);
  expectSameAsWhole ("slurm.las");
  const std::vector<std::string> jobs = pcl_ext::test::sbatchJobs (shims);
  ASSERT_EQ (jobs.size(), 8u);
  EXPECT_NE (jobs[0].find (" estimate $SLURM_ARRAY_TASK_ID"), std::string::npos);
  EXPECT_NE (jobs[1].find (" tile 0"), std::string::npos) << jobs[1];
  EXPECT_NE (jobs[2].find (" tile $SLURM_ARRAY_TASK_ID"), std::string::npos);
  EXPECT_EQ (jobs[3].rfind ("array=none ", 0), 0u) << jobs[3];
  EXPECT_NE (jobs[3].find (" refine 0"), std::string::npos) << jobs[3];
  EXPECT_EQ (jobs[4].rfind ("array=1-", 0), 0u) << jobs[4];
  EXPECT_NE (jobs[4].find (" refine $SLURM_ARRAY_TASK_ID"), std::string::npos);
  EXPECT_EQ (jobs[5].rfind ("array=none ", 0), 0u) << jobs[5];
  EXPECT_NE (jobs[5].find (" grow 0"), std::string::npos) << jobs[5];
  EXPECT_EQ (jobs[6].rfind ("array=1-", 0), 0u) << jobs[6];
  EXPECT_NE (jobs[6].find (" grow $SLURM_ARRAY_TASK_ID"), std::string::npos);
  EXPECT_NE (jobs[7].find (" merge "), std::string::npos) << jobs[7];
}

TEST_F (TilesSegmentsApp, AnEarlierRunsWorkFolderIsClearedByANewPlan)
{
  // A run that kept its work folder, then another scene in the same folder: the marks
  // of the first (tiles run, segments joined, second passes done) would pass for the
  // second's.
  makeScene ("indoor");
  const std::string work = " -workdir " + path ("work") + " -keep_workdir -reintegrate";
  ASSERT_EQ (runTiled ("first.las", "-tile_size 3" + work), 0) << output_;
  ASSERT_TRUE (exists ("work/segments.joined"));
  std::ofstream (path ("work/notes.txt")) << "the user's\n";
  const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) + " indoor '" +
                               path ("scene.pcd") +
                               "' -points 60000 -seed 5 > /dev/null 2>&1";
  ASSERT_EQ (std::system (generate.c_str()), 0);
  const std::string whole = std::string (PCL_EXT_SEGMENT_VARIANCE_EXE) + " '" +
                            path ("scene.pcd") + "' '" + path ("whole.las") +
                            "' -output_field seg -no_merge -no_assign > /dev/null 2>&1";
  ASSERT_EQ (std::system (whole.c_str()), 0);
  whole_ = readSegments (path ("whole.las"));
  ASSERT_EQ (runTiled ("second.las", "-tile_size 3" + work), 0) << output_;
  expectSameAsWhole ("second.las");
  EXPECT_TRUE (exists ("work/notes.txt")); // only the steps' own files are removed
}

TEST_F (TilesSegmentsApp, ATileThatOwnsNoPointChangesNothing)
{
  // Spheres on the ground, far apart: 2 m tiles between them own no point.
  makeScene ("spheres");
  ASSERT_EQ (runTiled ("t2.las", "-tile_size 2 -reintegrate"), 0) << output_;
  EXPECT_NE (output_.find (": 0 points]"), std::string::npos) << output_;
  expectSameAsWhole ("t2.las");
}

TEST_F (TilesSegmentsApp, ATileOfOnePointAndPointsWithoutCoordinates)
{
  // Two floor patches with a 20 cm step between them, a point alone in a 3 m tile of
  // its own, and points with NaN coordinates (in no tile): segmented tile by tile as
  // whole (PCD: LAS has no point without coordinates).
  std::vector<std::string> points;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double x = 0.1 * i, y = 0.1 * j;
      const double z = (x > 3.2 ? 0.2 : 0.0) + 0.002 * std::sin (7.0 * x + 3.0 * y);
      points.push_back (std::to_string (x) + " " + std::to_string (y) + " " +
                        std::to_string (z));
      if ((i * 41 + j) % 500 == 0)
        points.push_back ("nan nan nan");
    }
  points.push_back ("10.5 1.5 0.0"); // tile [9, 12) x [0, 3): this point alone
  std::ofstream pcd (path ("scene.pcd"));
  pcd << "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH "
      << points.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS "
      << points.size() << "\nDATA ascii\n";
  for (const auto& p : points)
    pcd << p << "\n";
  pcd.close();
  const std::string whole = std::string (PCL_EXT_SEGMENT_VARIANCE_EXE) + " '" +
                            path ("scene.pcd") + "' '" + path ("whole.pcd") +
                            "' -output_field seg -no_merge -no_assign > '" +
                            path ("whole.log") + "' 2>&1";
  ASSERT_EQ (std::system (whole.c_str()), 0);
  whole_ = readSegments (path ("whole.pcd"));
  ASSERT_EQ (whole_.ids.size(), points.size());
  ASSERT_EQ (runTiled ("t3.pcd", "-tile_size 3 -reintegrate"), 0) << output_;
  EXPECT_NE (output_.find (": 1 points]"), std::string::npos) << output_;
  expectSameAsWhole ("t3.pcd");
  const std::set<std::uint32_t> ids (whole_.ids.begin(), whole_.ids.end());
  EXPECT_GE (ids.size(), 3u); // the two patches and the unsegmented points
}

#ifdef PCL_EXT_MPIEXEC
TEST_F (TilesSegmentsApp, MpiRanksGiveTheSameSegments)
{
  makeScene ("indoor");
  for (const int ranks : {2, 4}) {
    const std::string out = "mpi" + std::to_string (ranks) + ".las";
    const std::string command =
        std::string (PCL_EXT_MPIEXEC) + " --allow-run-as-root --oversubscribe -np " +
        std::to_string (ranks) + " " + PCL_EXT_TILES_EXE + " segment_variance '" +
        path ("scene.pcd") + "' '" + path (out) +
        "' -output_field seg -tile_size 3 -threads 1 -reintegrate > '" +
        path ("mpi.log") + "' 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0) << ranks << " ranks";
    expectSameAsWhole (out);
  }
}
#endif

TEST_F (TilesSegmentsApp, TheDerivedPresetRemovesTheWholeCloudsNoise)
{
  // -preset derived: the noise estimated from the whole cloud's sample and removed from
  // every tile's eq. 4-6, and the threshold at the median of the curvatures with it
  // removed, which the tiles know only after all of them have run.
  makeScene ("indoor", "-preset derived -no_reintegrate -leftovers");
  ASSERT_EQ (runTiled ("d3.las", "-tile_size 3 -threads 1 -preset derived"), 0)
      << output_;
  expectSameAsWhole ("d3.las");
}

TEST_F (TilesSegmentsApp, IntersectionPointsAreTheWholeClouds)
{
  // Section 4's local intersection points, found by the tiles' own points in a second
  // pass and merged in the whole cloud's order: the untiled tool's bytes, with sections
  // 2 and 3's segments and with the re-integration, whatever the tile size.
  makeScene ("indoor",
             "-no_reintegrate -leftovers -intersections '" + path ("whole_i.pcd") +
                 "'");
  ASSERT_EQ (
      runTiled ("t3.las",
                "-tile_size 3 -threads 1 -intersections '" + path ("t3_i.pcd") + "'"),
      0)
      << output_;
  expectSameAsWhole ("t3.las");
  const std::vector<char> whole = readSegments (path ("whole_i.pcd")).bytes;
  EXPECT_GT (whole.size(), 10000u); // thousands of points
  EXPECT_TRUE (readSegments (path ("t3_i.pcd")).bytes == whole);

  makeScene ("indoor", "-intersections '" + path ("whole_r.pcd") + "'");
  ASSERT_EQ (runTiled ("t7.las",
                       "-tile_size 7 -halo 0.05 -reintegrate -intersections '" +
                           path ("t7_i.pcd") + "'"),
             0)
      << output_;
  expectSameAsWhole ("t7.las");
  EXPECT_TRUE (readSegments (path ("t7_i.pcd")).bytes ==
               readSegments (path ("whole_r.pcd")).bytes);
}

TEST_F (TilesSegmentsApp, WhatCannotRunTileByTileIsRefused)
{
  const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) + " cubes '" +
                               path ("scene.pcd") + "' -points 2000 > /dev/null 2>&1";
  ASSERT_EQ (std::system (generate.c_str()), 0);
  // Intersection points go to a point file the tools can write.
  EXPECT_EQ (runTiled ("a.las", "-intersections " + path ("i.xyz")), 1);
  EXPECT_NE (output_.find ("-intersections"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("i.xyz"));
  EXPECT_EQ (runTiled ("a.las", "-reintegrate -no_reintegrate"), 1);
  EXPECT_EQ (runTiled ("a.las", "-min_size 0"), 1);
  // The merging of interleaved pieces and the assignment of the points left over do
  // not run tile by tile yet: asked for, they are refused, not left out silently.
  EXPECT_EQ (runTiled ("a.las", "-reintegrate -merge"), 1);
  EXPECT_NE (output_.find ("-merge"), std::string::npos) << output_;
  EXPECT_EQ (runTiled ("a.las", "-reintegrate -assign"), 1);
  EXPECT_NE (output_.find ("-assign"), std::string::npos) << output_;
  EXPECT_FALSE (exists ("a.las"));
}
