/*
 * Tests of atomic output: a failed write never leaves a file, a good one replaces the
 * old.
 */
#include "temp_folder.h"

#include <pcl_ext/io/file_output.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

TEST (FileOutput, FailedWriteLeavesNothingAndKeepsTheOldFile)
{
  const std::string dir = freshFolder ("atomic");
  const std::string path = dir + "/result.txt";
  ASSERT_TRUE (pcl_ext::io::writeTextFile (path, "old"));
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::io::writeFileAtomically (path, [] (const std::string& tmp) {
    std::ofstream (tmp) << "half";
    return false; // the writer failed midway
  }));
  EXPECT_FALSE (
      pcl_ext::io::writeFileAtomically (path, [] (const std::string& tmp) -> bool {
        std::ofstream (tmp) << "half";
        throw std::runtime_error ("disk on fire");
      }));
  testing::internal::GetCapturedStderr();
  EXPECT_EQ (readAll (path), "old");
  EXPECT_EQ (listFolder (dir), std::vector<std::string>{"result.txt"});
  ASSERT_TRUE (pcl_ext::io::writeTextFile (path, "new"));
  EXPECT_EQ (readAll (path), "new");
  std::remove (path.c_str());
  ::rmdir (dir.c_str());
}

TEST (FileOutput, UnwritableTargetsAreRefusedUpFront)
{
  testing::internal::CaptureStderr();
  EXPECT_FALSE (pcl_ext::io::checkWritable ("/nonexistent-folder/out.pcd"));
  EXPECT_FALSE (pcl_ext::io::checkWritable (""));
  EXPECT_FALSE (pcl_ext::io::checkWritable (testing::TempDir())); // a folder
  EXPECT_FALSE (pcl_ext::io::writeTextFile ("/nonexistent-folder/out.txt", "x"));
  testing::internal::GetCapturedStderr();
  EXPECT_EQ (pcl_ext::io::fileExtension ("a/b.c/scan.PCD"), "pcd");
  EXPECT_EQ (pcl_ext::io::fileExtension ("a/b.c/scan"), "");
}

TEST (FileOutput, AtomicOutputAppearsOnlyOnCommit)
{
  const std::string dir = freshFolder ("atomic_output");
  const std::string path = dir + "/result.txt";
  {
    pcl_ext::io::AtomicFileOutput abandoned;
    ASSERT_TRUE (abandoned.open (path));
    std::ofstream (abandoned.getTemporaryPath()) << "half";
  }
  EXPECT_TRUE (listFolder (dir).empty());
  pcl_ext::io::AtomicFileOutput output;
  ASSERT_TRUE (output.open (path));
  testing::internal::CaptureStderr();
  EXPECT_FALSE (output.commit()); // nothing was written to the temporary path
  testing::internal::GetCapturedStderr();
  ASSERT_TRUE (output.open (path));
  std::ofstream (output.getTemporaryPath()) << "whole";
  EXPECT_TRUE (listFolder (dir).size() == 1u && listFolder (dir)[0] != "result.txt");
  ASSERT_TRUE (output.commit());
  EXPECT_EQ (readAll (path), "whole");
  EXPECT_EQ (listFolder (dir), std::vector<std::string>{"result.txt"});
  std::remove (path.c_str());
  ::rmdir (dir.c_str());
}
