/*
 * Tests of the apps' command-line parser.
 */
#include <pcl_ext/apps/command_line.h>

#include <gtest/gtest.h>

#include <vector>

namespace {
struct Args {
  int k = 50;
  unsigned int threads = 0;
  double radius = 0.1;
  std::string method = "mst";
  bool verbose = false;
  std::string input, output, extra;

  int
  parse (std::vector<const char*> argv)
  {
    argv.insert (argv.begin(), "pcl_ext_test");
    pcl_ext::apps::CommandLine cl ("pcl_ext_test", "A test tool.");
    cl.addPositional ("input.pcd", input, "input");
    cl.addPositional ("output.pcd", output, "output");
    cl.addPositional ("extra", extra, "optional", false);
    cl.addOption ("k", k, "neighbours");
    cl.addOption ("threads", threads, "threads");
    cl.addOption ("radius", radius, "radius");
    cl.addOption ("method", method, "method");
    cl.addSwitch ("verbose", verbose, "talk");
    return cl.parse (static_cast<int> (argv.size()), argv.data());
  }
};
} // namespace

TEST (CommandLine, ParsesPositionalsOptionsAndSwitches)
{
  Args a;
  EXPECT_EQ (a.parse ({"in.pcd",
                       "-k",
                       "30",
                       "out.pcd",
                       "-radius",
                       "-0.5",
                       "-verbose",
                       "-method",
                       "curve",
                       "-threads",
                       "2"}),
             -1);
  EXPECT_EQ (a.input, "in.pcd");
  EXPECT_EQ (a.output, "out.pcd");
  EXPECT_EQ (a.extra, "");
  EXPECT_EQ (a.k, 30);
  EXPECT_DOUBLE_EQ (a.radius, -0.5); // range checks belong to each tool
  EXPECT_TRUE (a.verbose);
  EXPECT_EQ (a.method, "curve");
  EXPECT_EQ (a.threads, 2u);
}

TEST (CommandLine, DefaultsStayWhenNotGiven)
{
  Args a;
  EXPECT_EQ (a.parse ({"in.pcd", "out.pcd"}), -1);
  EXPECT_EQ (a.k, 50);
  EXPECT_DOUBLE_EQ (a.radius, 0.1);
  EXPECT_FALSE (a.verbose);
}

TEST (CommandLine, HelpExitsZero)
{
  Args a;
  testing::internal::CaptureStdout();
  EXPECT_EQ (a.parse ({"-h"}), 0);
  const std::string help = testing::internal::GetCapturedStdout();
  EXPECT_NE (help.find ("-k X"), std::string::npos);
  EXPECT_NE (help.find ("(default: 50)"), std::string::npos);
  EXPECT_NE (help.find ("(default: mst)"), std::string::npos);
  EXPECT_NE (help.find ("(default: off)"), std::string::npos);
}

TEST (CommandLine, UsageErrorsExitOne)
{
  const std::vector<std::vector<const char*>> bad = {
      {},                                     // missing positionals
      {"in.pcd"},                             // missing output
      {"in.pcd", "out.pcd", "x", "y"},        // too many
      {"in.pcd", "out.pcd", "-unknown", "1"}, // unknown option
      {"in.pcd", "out.pcd", "-k"},            // missing value
      {"in.pcd", "out.pcd", "-k", "ten"},     // not a number
      {"in.pcd", "out.pcd", "-k", "1.5"},     // not an integer
      {"in.pcd", "out.pcd", "-k", "99999999999"},
      {"in.pcd", "out.pcd", "-threads", "-1"},
      {"in.pcd", "out.pcd", "-radius", "nan"},
      {"in.pcd", "out.pcd", "-radius", "inf"},
      {"in.pcd", "out.pcd", "-radius", "0.1x"},
      {"in.pcd", "out.pcd", "-k", "3", "-k", "4"},
  };
  for (const auto& argv : bad) {
    Args a;
    testing::internal::CaptureStderr();
    EXPECT_EQ (a.parse (argv), 1) << (argv.empty() ? "" : argv.back());
    EXPECT_NE (testing::internal::GetCapturedStderr().find ("error"),
               std::string::npos);
  }
}

TEST (CommandLine, APositionalListTakesWhatTheOthersLeave)
{
  std::string method, output;
  std::vector<std::string> inputs;
  int k = 0;
  pcl_ext::apps::CommandLine cl ("pcl_ext_test", "A test tool.");
  cl.addPositional ("METHOD", method, "method");
  cl.addPositionalList ("input", inputs, "inputs");
  cl.addPositional ("output", output, "output");
  cl.addOption ("k", k, "neighbours");
  std::vector<const char*> argv{
      "pcl_ext_test", "classify", "a.las", "-k", "5", "b.laz", "c.e57", "out.las"};
  ASSERT_EQ (cl.parse (static_cast<int> (argv.size()), argv.data()), -1);
  EXPECT_EQ (method, "classify");
  EXPECT_EQ (inputs, (std::vector<std::string>{"a.las", "b.laz", "c.e57"}));
  EXPECT_EQ (output, "out.las");
  EXPECT_EQ (k, 5);

  std::vector<std::string> few_inputs;
  std::string few_method, few_output;
  pcl_ext::apps::CommandLine few ("pcl_ext_test", "A test tool.");
  few.addPositional ("METHOD", few_method, "method");
  few.addPositionalList ("input", few_inputs, "inputs");
  few.addPositional ("output", few_output, "output");
  std::vector<const char*> two{"pcl_ext_test", "classify", "out.las"};
  testing::internal::CaptureStderr();
  EXPECT_EQ (few.parse (static_cast<int> (two.size()), two.data()), 1);
  const std::string error = testing::internal::GetCapturedStderr();
  EXPECT_NE (error.find ("missing argument"), std::string::npos) << error;
  EXPECT_NE (error.find ("input..."), std::string::npos) << error;
}

TEST (CommandLine, GivenOptionsAreHandedOnAsWritten)
{
  int k = 0;
  double radius = 0.0;
  bool verbose = false;
  std::string workdir, input;
  pcl_ext::apps::CommandLine cl ("pcl_ext_test", "A test tool.");
  cl.addPositional ("input", input, "input");
  cl.addOption ("k", k, "neighbours");
  cl.addOption ("radius", radius, "radius");
  cl.addOption ("workdir", workdir, "work folder");
  cl.addSwitch ("verbose", verbose, "talk");
  std::vector<const char*> argv{
      "pcl_ext_test", "-verbose", "in.las", "-workdir", "w", "-radius", "0.50"};
  ASSERT_EQ (cl.parse (static_cast<int> (argv.size()), argv.data()), -1);
  EXPECT_EQ (cl.getGivenOptions ({"workdir"}),
             (std::vector<std::string>{"-verbose", "-radius", "0.50"}));
  EXPECT_EQ (cl.getGivenOptions().size(), 5u);
}
