/*
 * The coarse class mapping file.
 */
#include <pcl_ext/io/class_mapping.h>

#include "test_helpers.h"

TEST (ClassMapping, LoadAndApply)
{
  pcl_ext::io::ClassMapping m;
  m.load (fixture ("classes_sample.txt"));
  EXPECT_EQ (m.size(), 3u);
  EXPECT_EQ (m.map (1203), 1u);
  EXPECT_EQ (m.map (1401), 2u);
  EXPECT_EQ (m.map (1501), 0u); // unlisted: ignored
  EXPECT_EQ (m.name (2), "facade");
  EXPECT_EQ (m.name (3), "wire"); // a class with a name but no sources
  EXPECT_EQ (m.name (9), "9");
  std::vector<std::uint32_t> labels{1200, 1400, 7, 1203};
  m.apply (labels);
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{1, 2, 0, 1}));

  EXPECT_FALSE (m.addClass (0, "zero", {}));
  EXPECT_FALSE (m.addClass (1, "again", {}));
  EXPECT_FALSE (m.addClass (4, "dup", {1203}));
  EXPECT_TRUE (m.addClass (4, "pole", {1103}));
  EXPECT_EQ (m.map (1103), 4u);
}

TEST (ClassMapping, Errors)
{
  pcl_ext::io::ClassMapping m;
  m.load (fixture ("classes_sample.txt"));
  std::string p = fixture ("classes_duplicate.txt");
  expectReadError (
      [&] { m.load (p); }, p, 2, "source label 1203 is already mapped to class 1");
  EXPECT_EQ (m.size(), 3u); // unchanged
  p = fixture ("points_bad_number.txt");
  expectReadError (
      [&] { m.load (p); }, p, 1, "expected '<class id> <name> : <source labels>'");
  p = fixture ("empty.txt");
  expectReadError ([&] { m.load (p); }, p, 0, "empty file");
  p = fixture ("missing_classes.txt");
  expectReadError ([&] { m.load (p); }, p, 0, "no such file");
  EXPECT_EQ (m.map (1400), 2u);
}
