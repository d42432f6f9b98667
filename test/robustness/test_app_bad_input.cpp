/*
 * The bad-input matrix of the command-line tools (test/README.md): each tool, run as a
 * user would, on each kind of bad input that applies to it.
 *
 * Each run is one test named AppBadInput/AppMatrix.Run/<tool>_<Input>. A bad input must
 * end with a message and a non-zero exit, no output file (not even a partial or
 * temporary one) and the input files unchanged; a cloud with some NaN points must be
 * processed (exit 0, output written).
 */
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {
enum class Bad {
  SomeNaN, ///< a valid cloud with NaN points: processed
  EmptyCloud,
  AllNaN,
  OnePoint,
  KLargerThanCloud,
  MissingFile,
  Directory, ///< the input path is a folder
  TruncatedPcd,
  MalformedPcd,
  MalformedModel, ///< crf_classify: a model file that is not one
  NegativeParameter,
  ZeroParameter,
  NaNParameter,
  OutputNotWritable, ///< the output folder does not exist
  OutputIsDirectory
};

const std::map<Bad, const char*> kNames = {
    {Bad::SomeNaN, "SomeNaN"},
    {Bad::EmptyCloud, "EmptyCloud"},
    {Bad::AllNaN, "AllNaN"},
    {Bad::OnePoint, "OnePoint"},
    {Bad::KLargerThanCloud, "KLargerThanCloud"},
    {Bad::MissingFile, "MissingFile"},
    {Bad::Directory, "InputIsADirectory"},
    {Bad::TruncatedPcd, "TruncatedPcd"},
    {Bad::MalformedPcd, "MalformedPcd"},
    {Bad::MalformedModel, "MalformedModel"},
    {Bad::NegativeParameter, "NegativeParameter"},
    {Bad::ZeroParameter, "ZeroParameter"},
    {Bad::NaNParameter, "NaNParameter"},
    {Bad::OutputNotWritable, "OutputNotWritable"},
    {Bad::OutputIsDirectory, "OutputIsADirectory"}};

/** Files of one run: the cloud given as input, the output, and the tool's other inputs.
 */
struct Files {
  std::string dir;    ///< the run's folder (outputs go here)
  std::string input;  ///< the cloud (good or bad)
  std::string output; ///< the output path
  std::string truth;  ///< a good labelled cloud (evaluate's truth)
  std::string model;  ///< a good CRF model
  std::string footprint;
  std::string
      param; ///< the value of the tool's checked option, when the input is about it
};

struct Tool {
  std::string name;
  std::string exe;
  std::set<Bad> applies;
  std::function<std::string (const Files&)> args;
  std::set<Bad> succeeds = {Bad::SomeNaN}; ///< inputs that must succeed
};

std::string
quote (const std::string& s)
{
  return "'" + s + "'";
}

/** Option \a name with the parameter of the run, when it has one. */
std::string
option (const Files& f, const std::string& name)
{
  return f.param.empty() ? "" : " -" + name + " " + f.param;
}

std::vector<Tool>
tools ()
{
  const std::set<Bad> cloud_inputs = {Bad::SomeNaN,
                                      Bad::EmptyCloud,
                                      Bad::AllNaN,
                                      Bad::OnePoint,
                                      Bad::MissingFile,
                                      Bad::Directory,
                                      Bad::TruncatedPcd,
                                      Bad::MalformedPcd,
                                      Bad::OutputNotWritable,
                                      Bad::OutputIsDirectory};
  auto with = [] (std::set<Bad> s, std::initializer_list<Bad> more) {
    s.insert (more);
    return s;
  };
  const auto params = {Bad::NegativeParameter, Bad::ZeroParameter, Bad::NaNParameter};
  std::vector<Tool> t;
  // Converting keeps every point as it is: NaN points and single points are converted.
  t.push_back (
      {"convert",
       PCL_EXT_CONVERT_EXE,
       {Bad::SomeNaN,
        Bad::EmptyCloud,
        Bad::AllNaN,
        Bad::OnePoint,
        Bad::MissingFile,
        Bad::Directory,
        Bad::TruncatedPcd,
        Bad::MalformedPcd,
        Bad::OutputNotWritable,
        Bad::OutputIsDirectory},
       [] (const Files& f) { return quote (f.input) + " " + quote (f.output); },
       {Bad::SomeNaN, Bad::AllNaN, Bad::OnePoint}});
  t.push_back ({"classify_variance",
                PCL_EXT_CLASSIFY_VARIANCE_EXE,
                with (with (cloud_inputs, params), {Bad::KLargerThanCloud}),
                [] (const Files& f) {
                  return quote (f.input) + " " + quote (f.output) + " -threads 2" +
                         option (f, "k");
                }});
  t.push_back ({"segment_variance",
                PCL_EXT_SEGMENT_VARIANCE_EXE,
                with (with (cloud_inputs, params), {Bad::KLargerThanCloud}),
                [] (const Files& f) {
                  return quote (f.input) + " " + quote (f.output) +
                         " -threads 2 -min_size 5" + option (f, "k");
                }});
  t.push_back ({"compare_segmenters",
                PCL_EXT_COMPARE_SEGMENTERS_EXE,
                with (cloud_inputs, params),
                [] (const Files& f) {
                  return quote (f.input) +
                         " -methods variance,euclidean -threads 2 -min_size 5 -csv " +
                         quote (f.output) + option (f, "tolerance");
                }});
  t.push_back ({"segment_profiles",
                PCL_EXT_SEGMENT_PROFILES_EXE,
                with (cloud_inputs, params),
                [] (const Files& f) {
                  return quote (f.input) + " " + quote (f.output) +
                         " -threads 2 -join_cylinders" + option (f, "width_factor");
                }});
  // The box is no building: a cloud with NaN points is read, planes extracted, and the
  // match fails; that failure must be reported like any other (non-zero exit, no
  // output).
  auto reg = with (cloud_inputs, params);
  t.push_back ({"register_to_map",
                PCL_EXT_REGISTER_TO_MAP_EXE,
                reg,
                [] (const Files& f) {
                  return quote (f.input) + " " + quote (f.footprint) + " " +
                         quote (f.output) + option (f, "angle");
                },
                {}});
  t.push_back ({"crf_train",
                PCL_EXT_CRF_TRAIN_EXE,
                with (cloud_inputs, params),
                [] (const Files& f) {
                  return "-o " + quote (f.output) + " -threads 2 -iterations 10 " +
                         quote (f.input) + option (f, "sigma");
                }});
  t.push_back ({"crf_classify",
                PCL_EXT_CRF_CLASSIFY_EXE,
                with (cloud_inputs, {Bad::MalformedModel}),
                [] (const Files& f) {
                  return quote (f.model) + " " + quote (f.input) + " " +
                         quote (f.output) + " -threads 2";
                }});
  t.push_back ({"evaluate",
                PCL_EXT_EVALUATE_EXE,
                with (cloud_inputs, params),
                [] (const Files& f) {
                  return "-segments " + quote (f.input) + " " + quote (f.truth) +
                         " -truth_field label -csv " + quote (f.output) +
                         option (f, "tolerance");
                },
                // Metrics compare labels only: coordinates, NaN or not, are not read.
                {Bad::SomeNaN, Bad::AllNaN}});
  // No input cloud; zero noise is valid (a perfect scan).
  t.push_back ({"generate_scene",
                PCL_EXT_GENERATE_SCENE_EXE,
                {Bad::NegativeParameter,
                 Bad::NaNParameter,
                 Bad::OutputNotWritable,
                 Bad::OutputIsDirectory},
                [] (const Files& f) {
                  return "cubes " + quote (f.output) + " -points 3000" +
                         option (f, "noise");
                },
                {}});
  return t;
}

const std::vector<Tool>&
allTools ()
{
  static const std::vector<Tool> t = tools();
  return t;
}

std::string
readFile (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/** The points of the good cloud: a box open at the top, labelled by face (1 floor, 2
 * walls). */
pcl::PointCloud<pcl::PointXYZL>
box ()
{
  pcl::PointCloud<pcl::PointXYZL> cloud;
  const int n = 20;
  const float s = 1.f / n;
  auto add = [&cloud] (float x, float y, float z, std::uint32_t label) {
    pcl::PointXYZL p;
    p.x = x;
    p.y = y;
    p.z = z;
    p.label = label;
    cloud.push_back (p);
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      add (i * s, j * s, 0.f, 1);
      if (j > 0) {
        add (i * s, 0.f, j * s, 2);
        add (i * s, 1.f, j * s, 2);
        add (0.f, i * s, j * s, 2);
        add (1.f, i * s, j * s, 2);
      }
    }
  return cloud;
}

/** Shared, good inputs: the labelled box and a footprint. */
struct Shared {
  std::string dir, good, footprint;
};

const Shared&
shared ()
{
  static const Shared s = [] {
    Shared s;
    char pattern[] = "/tmp/pcl_ext_app_bad_input_XXXXXX";
    EXPECT_NE (::mkdtemp (pattern), nullptr);
    s.dir = pattern;
    s.good = s.dir + "/good.pcd";
    EXPECT_EQ (pcl::io::savePCDFileBinary (s.good, box()), 0);
    s.footprint = s.dir + "/footprint.wkt";
    std::ofstream (s.footprint) << "POLYGON((0 0, 20 0, 20 10, 0 10, 0 0))\n";
    return s;
  }();
  return s;
}

/** A good CRF model of the box, trained on first use: ctest runs every case in its own
 * process and only the crf_classify cases read a model, so the others do not pay for
 * the training. */
const std::string&
sharedModel ()
{
  static const std::string model = [] {
    const std::string path = shared().dir + "/model.txt";
    const std::string train = std::string (PCL_EXT_CRF_TRAIN_EXE) + " -o " +
                              quote (path) + " -threads 2 -iterations 10 " +
                              quote (shared().good) + " > /dev/null 2>&1";
    EXPECT_EQ (std::system (train.c_str()), 0) << train;
    return path;
  }();
  return model;
}

struct Case {
  std::size_t tool;
  Bad bad;
};

class AppMatrix : public ::testing::TestWithParam<Case> {
protected:
  static void
  TearDownTestSuite ()
  {
    std::error_code ec;
    fs::remove_all (shared().dir, ec);
  }
};

TEST_P (AppMatrix, Run)
{
  const Tool& tool = allTools()[GetParam().tool];
  const Bad bad = GetParam().bad;
  const Shared& s = shared();
  Files f;
  f.dir = s.dir + "/" + tool.name + "_" + kNames.at (bad);
  fs::create_directories (f.dir);
  f.input = f.dir + "/input.pcd";
  f.output = f.dir + "/output." +
             (tool.name == "evaluate" || tool.name == "compare_segmenters" ? "csv"
              : tool.name == "crf_train"                                   ? "txt"
                                                                           : "pcd");
  f.truth = s.good;
  if (tool.name == "crf_classify")
    f.model = sharedModel();
  f.footprint = s.footprint;

  pcl::PointCloud<pcl::PointXYZL> cloud = box();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  switch (bad) {
  case Bad::SomeNaN:
    for (std::size_t i = 0; i < cloud.size(); i += 13)
      cloud[i].x = cloud[i].y = cloud[i].z = nan;
    cloud.is_dense = false;
    break;
  case Bad::EmptyCloud:
    cloud.clear();
    break;
  case Bad::AllNaN:
    for (auto& p : cloud)
      p.x = p.y = p.z = nan;
    cloud.is_dense = false;
    break;
  case Bad::OnePoint:
    cloud.resize (1);
    break;
  case Bad::KLargerThanCloud:
    f.param = "5000";
    break;
  case Bad::NegativeParameter:
    f.param = "-1";
    break;
  case Bad::ZeroParameter:
    f.param = "0";
    break;
  case Bad::NaNParameter:
    f.param = "nan";
    break;
  default:
    break;
  }
  if (bad == Bad::MissingFile)
    f.input = f.dir + "/missing.pcd";
  else if (bad == Bad::Directory) {
    f.input = f.dir + "/folder.pcd";
    fs::create_directories (f.input);
  }
  else if (bad == Bad::MalformedPcd)
    std::ofstream (f.input)
        << "# .PCD v0.7\nVERSION 0.7\nFIELDS x y\nSIZE 4\nWIDTH many\n";
  else {
    if (cloud.empty()) {
      // PCL refuses to write an empty cloud: write its header by hand.
      std::ofstream (f.input)
          << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
             "FIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
             "WIDTH 0\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 0\nDATA ascii\n";
    }
    else
      ASSERT_EQ (pcl::io::savePCDFileBinary (f.input, cloud), 0);
    if (bad == Bad::TruncatedPcd)
      fs::resize_file (f.input, fs::file_size (f.input) - 1000);
  }
  if (bad == Bad::MalformedModel) {
    f.model = f.dir + "/model.txt";
    std::ofstream (f.model) << "pcl_ext_crf_model 2\nmode mcrf\nsupervoxels 15 0.2\n";
  }
  if (bad == Bad::OutputNotWritable)
    f.output = f.dir + "/no/such/folder/" + fs::path (f.output).filename().string();
  if (bad == Bad::OutputIsDirectory)
    fs::create_directories (f.output);

  // Inputs as they were, to check that nothing touches them.
  std::map<std::string, std::string> before;
  for (const auto& p : {f.input, f.truth, f.model, f.footprint})
    if (fs::is_regular_file (p))
      before[p] = readFile (p);
  std::set<std::string> listing_before;
  for (const auto& e : fs::directory_iterator (f.dir))
    listing_before.insert (e.path().filename().string());

  const std::string log = f.dir + "/log.txt";
  // A hang is a failure too: timeout ends the run with 124 after 10 minutes.
  const std::string command = tool.exe + " " + tool.args (f);
  const int status =
      std::system (("timeout 600 " + command + " > " + quote (log) + " 2>&1").c_str());
  ASSERT_TRUE (WIFEXITED (status)) << "crashed: " << command;
  const int code = WEXITSTATUS (status);
  ASSERT_NE (code, 124) << "did not finish within 10 minutes: " << command;
  const std::string output = readFile (log);
  fs::remove (log);

  for (const auto& entry : before)
    EXPECT_EQ (readFile (entry.first), entry.second) << entry.first << " was modified";
  if (tool.succeeds.count (bad)) {
    EXPECT_EQ (code, 0) << command << "\n" << output;
    EXPECT_TRUE (fs::is_regular_file (f.output)) << "no output: " << command << "\n"
                                                 << output;
    return;
  }
  EXPECT_NE (code, 0) << "bad input accepted: " << command << "\n" << output;
  EXPECT_LT (code, 128) << "killed by a signal or sanitizer: " << command << "\n"
                        << output;
  EXPECT_FALSE (output.empty()) << "no message: " << command;
  if (bad != Bad::OutputIsDirectory)
    EXPECT_FALSE (fs::exists (f.output))
        << "output written despite the failure: " << command;
  // Nothing else left behind (temporary files of an atomic write).
  std::set<std::string> listing_after;
  for (const auto& e : fs::directory_iterator (f.dir))
    listing_after.insert (e.path().filename().string());
  EXPECT_EQ (listing_after, listing_before) << "files left behind: " << command;
}

std::vector<Case>
allCases ()
{
  std::vector<Case> cases;
  for (std::size_t i = 0; i < allTools().size(); ++i)
    for (const auto& entry : kNames)
      if (allTools()[i].applies.count (entry.first))
        cases.push_back ({i, entry.first});
  return cases;
}

/** Names a case in gtest's messages (otherwise printed as the struct's bytes). */
void
PrintTo (const Case& c, std::ostream* os)
{
  *os << allTools()[c.tool].name << " on " << kNames.at (c.bad);
}

std::string
caseName (const ::testing::TestParamInfo<Case>& info)
{
  return allTools()[info.param.tool].name + "_" + kNames.at (info.param.bad);
}

INSTANTIATE_TEST_SUITE_P (AppBadInput,
                          AppMatrix,
                          ::testing::ValuesIn (allCases()),
                          caseName);
} // namespace
