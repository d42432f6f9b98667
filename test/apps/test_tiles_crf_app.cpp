/*
 * pcl_ext_tiles crf_classify run as a command: a street scan classified tile by tile
 * with a model trained on another seed (on x y z, or on x y z, colour and intensity)
 * gives pcl_ext_crf_classify's classes on the whole cloud for at least 99 % of the
 * points, whatever the tile size; the same bytes over any number of MPI ranks and in
 * steps; models and options it cannot run are refused without output.
 */
#include "../app_test.h"

#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

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
/** Field \a name of an output (the classes by default), one per point in file order;
 * empty on failure. */
std::vector<std::uint32_t>
readClasses (const std::string& path, const std::string& name = "crf_class")
{
  std::vector<std::uint32_t> classes;
  pcl_ext::io::PointFile file;
  try {
    pcl_ext::io::loadPointFile (path, file);
  }
  catch (const std::exception&) {
    return classes;
  }
  pcl_ext::io::getLabelField (file.cloud, name, classes);
  return classes;
}

std::vector<char>
readBytes (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  return {std::istreambuf_iterator<char> (in), std::istreambuf_iterator<char>()};
}

class TilesCrfApp : public pcl_ext::test::AppTest {
protected:
  TilesCrfApp() : AppTest (PCL_EXT_TILES_EXE) {}

  void
  SetUp () override
  {
    AppTest::SetUp();
    if (HasFatalFailure())
      return;
    // Training: seed 1 with x y z and the labels only (a model on geometry alone, as
    // Oakland's); classified: seed 2, every field of the scene kept.
    for (const int seed : {1, 2}) {
      const std::string generate = std::string (PCL_EXT_GENERATE_SCENE_EXE) +
                                   " street '" + path ("s" + std::to_string (seed)) +
                                   ".pcd' -points 30000 -seed " +
                                   std::to_string (seed) + " > /dev/null 2>&1";
      ASSERT_EQ (std::system (generate.c_str()), 0);
    }
    pcl::PointCloud<pcl::PointXYZL> labelled;
    ASSERT_EQ (pcl::io::loadPCDFile (path ("s1.pcd"), labelled), 0);
    ASSERT_EQ (pcl::io::savePCDFileBinary (path ("train.pcd"), labelled), 0);
    const std::string train = std::string (PCL_EXT_CRF_TRAIN_EXE) + " -o '" +
                              path ("model.txt") + "' '" + path ("train.pcd") +
                              "' -threads 2 > /dev/null 2>&1";
    ASSERT_EQ (std::system (train.c_str()), 0);
    classifyWhole ("model");
  }

  /** A model on the scene's colour and intensity too, and its untiled classes. */
  void
  trainOnColour ()
  {
    const std::string train = std::string (PCL_EXT_CRF_TRAIN_EXE) + " -o '" +
                              path ("colour.txt") + "' '" + path ("s1.pcd") +
                              "' -threads 2 > /dev/null 2>&1";
    ASSERT_EQ (std::system (train.c_str()), 0);
    classifyWhole ("colour");
  }

  /** pcl_ext_crf_classify with \a model on the whole of seed 2. */
  void
  classifyWhole (const std::string& model)
  {
    const std::string whole = std::string (PCL_EXT_CRF_CLASSIFY_EXE) + " '" +
                              path (model + ".txt") + "' '" + path ("s2.pcd") + "' '" +
                              path (model + "_whole.pcd") + "' > /dev/null 2>&1";
    ASSERT_EQ (std::system (whole.c_str()), 0);
    ASSERT_GT (readClasses (path (model + "_whole.pcd")).size(), 25000u);
  }

  /** The share of the points of \a output whose class is the untiled one with \a
   * model. */
  double
  agreement (const std::string& output, const std::string& model = "model")
  {
    const std::vector<std::uint32_t> whole = readClasses (path (model + "_whole.pcd"));
    const std::vector<std::uint32_t> tiled = readClasses (path (output));
    if (tiled.size() != whole.size() || whole.empty())
      return 0.0;
    std::size_t same = 0;
    for (std::size_t i = 0; i < tiled.size(); ++i)
      same += tiled[i] == whole[i];
    return static_cast<double> (same) / static_cast<double> (tiled.size());
  }

  std::string
  classify (const std::string& output,
            const std::string& options,
            const std::string& model = "model")
  {
    return "crf_classify '" + path ("s2.pcd") + "' '" + path (output) + "' -model '" +
           path (model + ".txt") + "' " + options;
  }
};
} // namespace

TEST_F (TilesCrfApp, AnyTileSizeGivesTheWholeCloudsClassesForNearlyEveryPoint)
{
  // Tiles of 20 m hold a few thousand points; their halo (10 m, half the tile) is
  // narrower than the large super-voxels of the sparse parts of the street, so some
  // tiles widen their margin as the super-voxels they computed ask.
  for (const std::string size : {"20", "40", "0"}) {
    const std::string out = "t" + size + ".pcd";
    ASSERT_EQ (run (classify (out, "-tile_size " + size + " -threads 1")), 0)
        << output_;
    EXPECT_GE (agreement (out), 0.99) << "tile size " << size;
  }
  EXPECT_NE (output_.find ("tiles ("), std::string::npos) << output_;
  EXPECT_FALSE (exists ("t0.pcd.tiles")); // the work folder is removed
}

TEST_F (TilesCrfApp, TheProbabilityFieldIsTheUntiledToolsForNearlyEveryPoint)
{
  // -probability_field of pcl_ext_crf_classify: the winning class's probability, a
  // float per point, kept tile by tile as the classes are. Belief propagation's
  // messages from beyond a tile's margin, weakened at every step, move the
  // probabilities of a few points in their fifth decimal.
  const std::string whole = std::string (PCL_EXT_CRF_CLASSIFY_EXE) + " '" +
                            path ("model.txt") + "' '" + path ("s2.pcd") + "' '" +
                            path ("p_whole.pcd") +
                            "' -probability_field prob > /dev/null 2>&1";
  ASSERT_EQ (std::system (whole.c_str()), 0);
  ASSERT_EQ (
      run (classify ("p20.las", "-tile_size 20 -threads 1 -probability_field prob")), 0)
      << output_;
  const auto readProbabilities = [] (const std::string& file) {
    std::vector<float> values;
    pcl_ext::io::PointFile f;
    pcl_ext::io::loadPointFile (file, f);
    for (const auto& field : f.cloud.fields)
      if (field.name == "prob" && field.datatype == pcl::PCLPointField::FLOAT32) {
        const std::size_t n = static_cast<std::size_t> (f.cloud.width) * f.cloud.height;
        values.resize (n);
        for (std::size_t i = 0; i < n; ++i)
          std::memcpy (&values[i],
                       f.cloud.data.data() + i * f.cloud.point_step + field.offset,
                       sizeof (float));
      }
    return values;
  };
  const std::vector<float> untiled = readProbabilities (path ("p_whole.pcd"));
  const std::vector<float> tiled = readProbabilities (path ("p20.las"));
  ASSERT_GT (untiled.size(), 25000u);
  ASSERT_EQ (tiled.size(), untiled.size());
  std::size_t same = 0, in_range = 0;
  for (std::size_t i = 0; i < tiled.size(); ++i) {
    same += std::abs (tiled[i] - untiled[i]) <= 1e-4f;
    in_range += tiled[i] > 0.0f && tiled[i] <= 1.0f;
  }
  EXPECT_GE (static_cast<double> (same) / static_cast<double> (tiled.size()), 0.99);
  EXPECT_EQ (in_range, tiled.size());
  // The classes are still there, and the field cannot be the classes'.
  EXPECT_GE (agreement ("p20.las"), 0.99);
  EXPECT_EQ (run (classify ("no.las", "-probability_field crf_class")), 1);
  EXPECT_FALSE (exists ("no.las"));
}

TEST_F (TilesCrfApp, AModelOnColourAndIntensityReadsThemFromTheTiles)
{
  trainOnColour();
  if (HasFatalFailure())
    return;
  ASSERT_EQ (run (classify ("c20.pcd", "-tile_size 20 -threads 1", "colour")), 0)
      << output_;
  EXPECT_GE (agreement ("c20.pcd", "colour"), 0.99);
  // The two models differ, so the fields were read: the x y z model's classes are not
  // the colour model's.
  EXPECT_LT (agreement ("c20.pcd", "model"), 0.999);
}

TEST_F (TilesCrfApp, StepsGiveTheSameBytesAsOneCommand)
{
  ASSERT_EQ (run (classify ("one.pcd", "-tile_size 20 -threads 1")), 0) << output_;
  const std::string work = " -workdir '" + path ("work") + "'";
  ASSERT_EQ (run ("plan crf_classify '" + path ("s2.pcd") + "' -model '" +
                  path ("model.txt") + "' -tile_size 20" + work),
             0)
      << output_;
  ASSERT_EQ (run ("resume '" + path ("steps.pcd") + "'" + work + " -threads 2"), 0)
      << output_;
  EXPECT_TRUE (readBytes (path ("one.pcd")) == readBytes (path ("steps.pcd")));
}

TEST_F (TilesCrfApp, AsprsCodesGoToTheLasClassificationByClassName)
{
  // The street's labels named (1 vegetation, 2 trunk, 3 man-made, 4 pathway, 5
  // terrain), three of them with an ASPRS code: vegetation 5, building 6, ground 2.
  {
    std::ofstream classes (path ("classes.txt"));
    classes << "1 vegetation : 1\n2 trunk : 2\n3 building : 3\n4 pathway : 4\n"
               "5 ground : 5\n";
  }
  const std::string train = std::string (PCL_EXT_CRF_TRAIN_EXE) + " -o '" +
                            path ("named.txt") + "' -classes '" + path ("classes.txt") +
                            "' '" + path ("train.pcd") +
                            "' -threads 2 > /dev/null 2>&1";
  ASSERT_EQ (std::system (train.c_str()), 0);
  ASSERT_EQ (run (classify ("asprs.las", "-tile_size 20 -asprs", "named")), 0)
      << output_;
  EXPECT_NE (output_.find ("vegetation -> ASPRS 5"), std::string::npos) << output_;
  const std::vector<std::uint32_t> classes = readClasses (path ("asprs.las"));
  const std::vector<std::uint32_t> codes =
      readClasses (path ("asprs.las"), "classification");
  ASSERT_EQ (classes.size(), codes.size());
  ASSERT_FALSE (classes.empty());
  const std::map<std::uint32_t, std::uint32_t> expected{
      {1, 5}, {2, 1}, {3, 6}, {4, 1}, {5, 2}};
  std::set<std::uint32_t> seen;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    ASSERT_EQ (expected.count (classes[i]), 1u) << classes[i];
    EXPECT_EQ (codes[i], expected.at (classes[i])) << "point " << i;
    seen.insert (codes[i]);
  }
  EXPECT_GE (seen.size(), 3u);
  // As pcl_ext_crf_classify -asprs writes them, for nearly every point.
  const std::string whole = std::string (PCL_EXT_CRF_CLASSIFY_EXE) + " '" +
                            path ("named.txt") + "' '" + path ("s2.pcd") + "' '" +
                            path ("named_whole.las") + "' -asprs > /dev/null 2>&1";
  ASSERT_EQ (std::system (whole.c_str()), 0);
  const std::vector<std::uint32_t> untiled =
      readClasses (path ("named_whole.las"), "classification");
  ASSERT_EQ (untiled.size(), codes.size());
  std::size_t same = 0;
  for (std::size_t i = 0; i < codes.size(); ++i)
    same += untiled[i] == codes[i];
  EXPECT_GE (static_cast<double> (same) / static_cast<double> (codes.size()), 0.99);
}

#ifdef PCL_EXT_MPIEXEC
TEST_F (TilesCrfApp, MpiRanksGiveTheSameBytes)
{
  ASSERT_EQ (run (classify ("one.pcd", "-tile_size 20 -threads 1")), 0) << output_;
  for (const int ranks : {2, 4}) {
    const std::string out = "mpi" + std::to_string (ranks) + ".pcd";
    const std::string command = std::string (PCL_EXT_MPIEXEC) +
                                " --allow-run-as-root --oversubscribe -np " +
                                std::to_string (ranks) + " " + PCL_EXT_TILES_EXE + " " +
                                classify (out, "-tile_size 20 -threads 1") + " > '" +
                                path ("mpi.log") + "' 2>&1";
    ASSERT_EQ (std::system (command.c_str()), 0) << ranks << " ranks";
    EXPECT_TRUE (readBytes (path ("one.pcd")) == readBytes (path (out)))
        << ranks << " ranks";
  }
}
#endif

TEST_F (TilesCrfApp, ModelsAndOptionsItCannotRunAreRefused)
{
  EXPECT_EQ (run ("crf_classify '" + path ("s2.pcd") + "' '" + path ("no.pcd") + "'"),
             1);
  EXPECT_NE (output_.find ("-model"), std::string::npos) << output_;
  EXPECT_EQ (run ("crf_classify '" + path ("s2.pcd") + "' '" + path ("no.pcd") +
                  "' -model '" + path ("missing.txt") + "'"),
             1);
  EXPECT_NE (output_.find ("cannot load the model"), std::string::npos) << output_;
  // A model that reads colour and intensity on an input without them.
  trainOnColour();
  if (HasFatalFailure())
    return;
  EXPECT_EQ (run ("crf_classify '" + path ("train.pcd") + "' '" + path ("no.pcd") +
                  "' -model '" + path ("colour.txt") + "'"),
             1);
  EXPECT_NE (output_.find ("which " + path ("train.pcd") + " does not have"),
             std::string::npos)
      << output_;
  EXPECT_EQ (run (classify ("no.pcd", "-asprs")), 1); // ASPRS codes need a LAS output
  EXPECT_FALSE (exists ("no.pcd"));
  EXPECT_FALSE (exists ("no.las"));
}
