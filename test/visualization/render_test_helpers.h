/*
 * Helpers for the rendering tests: a cloud to render and a temporary PNG path.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <unistd.h>

inline pcl::PointCloud<pcl::PointXYZ>
sphereCloud (int n)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < n; ++i) {
    // Fibonacci sphere: even coverage, no randomness.
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt (1.0 - z * z);
    const double phi = i * 2.399963229728653;
    cloud.push_back (pcl::PointXYZ (r * std::cos (phi), r * std::sin (phi), z));
  }
  return cloud;
}

inline std::string
temporaryPng (const std::string& stem)
{
  return testing::TempDir() + "/" + stem + "_" + std::to_string (::getpid()) + ".png";
}
