/*
 * Helpers for the tests that write files: a fresh folder, its listing, a file's
 * contents.
 */
#pragma once

#include <gtest/gtest.h>

#include <dirent.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

/** A folder of this process for \a name, emptied the first time the process asks for
 * it: a folder of an earlier process with the same id (ids are reused) would hold its
 * files. */
inline std::string
freshFolder (const std::string& name)
{
  const std::string dir =
      testing::TempDir() + "/pcl_ext_" + name + "_" + std::to_string (::getpid());
  static std::set<std::string> made;
  if (made.insert (dir).second) {
    std::error_code ignored;
    std::filesystem::remove_all (dir, ignored);
  }
  ::mkdir (dir.c_str(), 0755);
  return dir;
}

inline std::vector<std::string>
listFolder (const std::string& dir)
{
  std::vector<std::string> names;
  if (DIR* d = ::opendir (dir.c_str())) {
    while (dirent* e = ::readdir (d))
      if (std::string (e->d_name) != "." && std::string (e->d_name) != "..")
        names.push_back (e->d_name);
    ::closedir (d);
  }
  return names;
}

inline std::string
readAll (const std::string& path)
{
  std::ifstream in (path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
