/*
 * Helpers for the reader tests: fixture paths and error expectations.
 */
#pragma once

#include <pcl_ext/io/read_error.h>

#include <gtest/gtest.h>

#include <string>

inline std::string
fixture (const std::string& name)
{
  return std::string (PCL_EXT_TEST_DATA_DIR) + "/" + name;
}

/** Runs \a read, expects a ReadError naming \a path and \a line whose message contains
 * \a fragment. */
template <typename Read>
void
expectReadError (Read&& read,
                 const std::string& path,
                 std::size_t line,
                 const std::string& fragment)
{
  try {
    read();
    ADD_FAILURE() << "no error reading " << path;
  }
  catch (const pcl_ext::io::ReadError& e) {
    EXPECT_EQ (e.path(), path);
    EXPECT_EQ (e.line(), line) << e.what();
    EXPECT_NE (std::string (e.what()).find (path), std::string::npos) << e.what();
    if (line > 0)
      EXPECT_NE (
          std::string (e.what()).find (path + ":" + std::to_string (line) + ": "),
          std::string::npos)
          << e.what();
    EXPECT_NE (e.message().find (fragment), std::string::npos)
        << "'" << e.message() << "' lacks '" << fragment << "'";
  }
  catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}
