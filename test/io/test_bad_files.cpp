/*
 * Every reader against the same bad files: missing, a folder, empty, truncated in the
 * middle of a line, binary garbage. Each must throw a ReadError naming the file (never
 * crash or hang), leave its output untouched and leave the file as it was.
 */
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/footprints.h>
#include <pcl_ext/io/transform_file.h>

#include "test_helpers.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace fs = std::filesystem;

namespace {
/** A reader, a good file for it, and a run that checks, when the reader throws, that
 * its output is still the sentinel it was given ("untouched after an error"). */
struct Reader {
  std::string name;
  std::string good_text;
  std::string truncated_text; ///< the good text cut short where the format can tell
  std::function<void (const std::string&)>
      read_into_sentinel; ///< throws; checks the output
};

std::vector<Reader>
readers ()
{
  using namespace pcl_ext::io;
  std::vector<Reader> r;
  r.push_back ({"ascii",
                "1 2 3 4\n5 6 7 8\n9 10 11 12\n",
                "1 2 3 4\n5 6 7",
                [] (const std::string& p) {
                  PointTable t;
                  t.xyz.emplace_back (42, 42, 42);
                  try {
                    loadAsciiPoints (p, t);
                  }
                  catch (...) {
                    EXPECT_EQ (t.size(), 1u);
                    throw;
                  }
                }});
  r.push_back ({"oakland",
                "1 2 3 1004 0\n4 5 6 1004 0\n7 8 9 1200 0\n",
                "1 2 3 1004 0\n4 5 6",
                [] (const std::string& p) {
                  PointTable t;
                  t.xyz.emplace_back (42, 42, 42);
                  try {
                    loadOaklandFile (p, t);
                  }
                  catch (...) {
                    EXPECT_EQ (t.size(), 1u);
                    throw;
                  }
                }});
  r.push_back ({"classes",
                "1 ground : 1200 1203\n2 facade : 1400 1401\n",
                // A line cut after its id; cut later it may still be a valid line.
                "1 ground : 1200 1203\n2",
                [] (const std::string& p) {
                  ClassMapping m;
                  m.addClass (9, "kept", {9001});
                  try {
                    m.load (p);
                  }
                  catch (...) {
                    EXPECT_EQ (m.map (9001), 9u);
                    throw;
                  }
                }});
  const auto footprint_reader =
      [] (void (*load) (const std::string&, std::vector<Footprint>&)) {
        return [load] (const std::string& p) {
          std::vector<Footprint> f (1);
          f[0].id = "kept";
          try {
            load (p, f);
          }
          catch (...) {
            EXPECT_TRUE (f.size() == 1 && f[0].id == "kept");
            throw;
          }
        };
      };
  r.push_back (
      {"wkt",
       "a; POLYGON((0 0, 10 0, 10 10, 0 10, 0 0))\nb; POLYGON((0 0, 5 0, 5 5, 0 0))\n",
       "a; POLYGON((0 0, 10 0, 10 10, 0 10, 0 0))\nb; POLYGON((0 0, 5",
       footprint_reader (loadWktFootprints)});
  r.push_back (
      {"geojson",
       "{\"type\": \"FeatureCollection\", \"features\": [\n"
       "{\"type\": \"Feature\", \"id\": 1, \"geometry\": {\"type\": \"Polygon\",\n"
       "\"coordinates\": [[[0, 0], [10, 0], [10, 10], [0, 0]]]}}]}\n",
       "{\"type\": \"FeatureCollection\", \"features\": [\n{\"type\": \"Feature\", "
       "\"id\"",
       footprint_reader (loadGeoJsonFootprints)});
  r.push_back ({"footprint_text",
                "a 4 0 0 10 0 10 10 0 0\nb 4 0 0 5 0 5 5 0 0\n",
                "a 4 0 0 10 0 10 10 0 0\nb 4 0 0 5",
                footprint_reader (loadTextFootprints)});
  r.push_back ({"transform",
                "1 0 0 10\n0 1 0 20\n0 0 1 30\n0 0 0 1\n",
                "1 0 0 10\n0 1 0 20\n0 0 1 30\n0 0",
                [] (const std::string& p) {
                  Eigen::Matrix4d t = Eigen::Matrix4d::Constant (42.0);
                  try {
                    loadTransform (p, t);
                  }
                  catch (...) {
                    EXPECT_EQ (t, Eigen::Matrix4d::Constant (42.0));
                    throw;
                  }
                }});
  return r;
}

class BadFiles : public ::testing::Test {
protected:
  void
  SetUp () override
  {
    char pattern[] = "/tmp/pcl_ext_bad_files_XXXXXX";
    ASSERT_NE (::mkdtemp (pattern), nullptr);
    dir_ = pattern;
  }

  void
  TearDown () override
  {
    std::error_code ec;
    fs::remove_all (dir_, ec);
  }

  std::string
  write (const std::string& name, const std::string& bytes)
  {
    const std::string p = dir_ + "/" + name;
    std::ofstream (p, std::ios::binary) << bytes;
    return p;
  }

  static std::string
  read (const std::string& p)
  {
    std::ifstream in (p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  std::string dir_;
};

/** Runs \a reader on \a path: a ReadError naming the path, the output untouched
 * (checked by the reader), the file unchanged. */
void
expectRefused (const Reader& reader, const std::string& path, const std::string& what)
{
  const bool is_file = fs::is_regular_file (path);
  std::string before;
  if (is_file) {
    std::ifstream in (path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    before = s.str();
  }
  try {
    reader.read_into_sentinel (path);
    ADD_FAILURE() << reader.name << ", " << what << ": no error";
  }
  catch (const pcl_ext::io::ReadError& e) {
    EXPECT_EQ (e.path(), path) << reader.name << ", " << what;
    EXPECT_FALSE (e.message().empty());
  }
  catch (const std::exception& e) {
    ADD_FAILURE() << reader.name << ", " << what << ": not a ReadError: " << e.what();
  }
  if (is_file) {
    std::ifstream in (path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ (s.str(), before)
        << reader.name << ", " << what << ": the file was modified";
  }
}
} // namespace

TEST_F (BadFiles, GoodFilesAreRead)
{
  // The good texts below are what the bad files are made from: they must read.
  for (const auto& reader : readers()) {
    const std::string p = write (reader.name + "_good.txt", reader.good_text);
    EXPECT_NO_THROW ({
      try {
        reader.read_into_sentinel (p);
      }
      catch (const pcl_ext::io::ReadError& e) {
        ADD_FAILURE() << reader.name << ": " << e.what();
      }
    });
  }
}

TEST_F (BadFiles, MissingFolderEmptyTruncatedAndGarbageAreRefused)
{
  std::string garbage;
  for (int i = 0; i < 512; ++i)
    garbage.push_back (static_cast<char> ((i * 131 + 7) % 256));
  for (const auto& reader : readers()) {
    testing::internal::CaptureStderr();
    expectRefused (reader, dir_ + "/" + reader.name + "_missing.txt", "missing file");
    const std::string folder = dir_ + "/" + reader.name + "_folder.txt";
    fs::create_directories (folder);
    expectRefused (reader, folder, "a folder");
    expectRefused (reader, write (reader.name + "_empty.txt", ""), "empty file");
    expectRefused (reader,
                   write (reader.name + "_truncated.txt", reader.truncated_text),
                   "truncated file");
    expectRefused (
        reader, write (reader.name + "_garbage.txt", garbage), "binary garbage");
    testing::internal::GetCapturedStderr();
  }
}
