/*
 * Base fixture of the command-line tool tests: each test gets a fresh temporary folder,
 * and run() executes the tool with arguments and keeps what it printed.
 */
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace pcl_ext {
namespace test {
class AppTest : public ::testing::Test {
protected:
  /** \param[in] executable the tool's path (the tests get it from CMake) */
  explicit AppTest (std::string executable) : executable_ (std::move (executable)) {}

  void
  SetUp () override
  {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "pcl_ext_app_XXXXXX").string();
    ASSERT_NE (::mkdtemp (pattern.data()), nullptr);
    dir_ = pattern;
  }

  void
  TearDown () override
  {
    std::error_code ignored;
    std::filesystem::remove_all (dir_, ignored);
  }

  /** \a name in the test's folder. */
  std::string
  path (const std::string& name) const
  {
    return dir_ + "/" + name;
  }

  bool
  exists (const std::string& name) const
  {
    return std::filesystem::exists (path (name));
  }

  /** Runs the tool with \a args; returns its exit code (-1 when it did not exit, e.g. a
   * crash) and puts its stdout and stderr in output_. */
  int
  run (const std::string& args)
  {
    return run (args, executable_);
  }

  /** Runs \a program (a command line) with \a args, as run() runs the tool. */
  int
  run (const std::string& args, const std::string& program)
  {
    const std::string command =
        program + " " + args + " > '" + path ("log.txt") + "' 2>&1";
    const int status = std::system (command.c_str());
    std::ifstream in (path ("log.txt"));
    std::stringstream s;
    s << in.rdbuf();
    output_ = s.str();
    return WIFEXITED (status) ? WEXITSTATUS (status) : -1;
  }

  /** Runs the tool with \a args as run() does, but with the file size limit \a
   * kilobytes (writes beyond it fail as on a full disk: SIGXFSZ is ignored). */
  int
  runOnFullDisk (const std::string& args, int kilobytes)
  {
    return run ("",
                "bash -c \"trap '' XFSZ; ulimit -f " + std::to_string (kilobytes) +
                    "; exec " + executable_ + " " + args + "\"");
  }

  std::string dir_;
  std::string output_;

private:
  std::string executable_;
};
} // namespace test
} // namespace pcl_ext
