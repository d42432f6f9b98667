/*
 * Tests of ReadError, the one exception the pcl_ext readers throw: its message and
 * parts.
 */
#include <pcl_ext/io/read_error.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using pcl_ext::io::ReadError;

TEST (ReadError, MessageNamesFileAndLine)
{
  const ReadError e ("scans/a.txt", 12, "expected 3 numbers, got 2");
  EXPECT_STREQ (e.what(), "scans/a.txt:12: expected 3 numbers, got 2");
  EXPECT_EQ (e.path(), "scans/a.txt");
  EXPECT_EQ (e.line(), 12u);
  EXPECT_EQ (e.message(), "expected 3 numbers, got 2");
}

TEST (ReadError, WholeFileProblemsHaveNoLine)
{
  const ReadError e ("missing.wkt", 0, "cannot open");
  EXPECT_STREQ (e.what(), "missing.wkt: cannot open");
  EXPECT_EQ (e.line(), 0u);
  EXPECT_EQ (e.message(), "cannot open");
}

TEST (ReadError, CaughtAsARuntimeError)
{
  try {
    throw ReadError ("b.txt", 3, "bad colour");
  }
  catch (const std::runtime_error& e) {
    EXPECT_STREQ (e.what(), "b.txt:3: bad colour");
    const auto* read_error = dynamic_cast<const ReadError*> (&e);
    ASSERT_NE (read_error, nullptr);
    EXPECT_EQ (read_error->line(), 3u);
    return;
  }
  ADD_FAILURE() << "not caught as std::runtime_error";
}
