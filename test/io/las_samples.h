/*
 * Paths of the LAS / LAZ samples of the shared data folder, for the data tests.
 */
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <sys/stat.h>

namespace las_samples {
/** The path of the sample \a name (e.g. "simple.las"). */
inline std::string
path (const std::string& name)
{
  return std::string (PCL_EXT_SHARED_DATA_DIR) + "/las_samples/" + name;
}

/** True when \a file exists. */
inline bool
exists (const std::string& file)
{
  struct stat st;
  return ::stat (file.c_str(), &st) == 0;
}
} // namespace las_samples

/** Skips the test when the sample \a name is not there (the data folder is optional).
 */
#define REQUIRE_LAS_SAMPLE(name)                                                       \
  if (!las_samples::exists (las_samples::path (name)))                                 \
  GTEST_SKIP() << "LAS sample not found: " << las_samples::path (name)
