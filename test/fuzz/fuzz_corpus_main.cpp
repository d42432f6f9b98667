/*
 * Runs a fuzz target over files without libFuzzer: `fuzz_<target>_corpus
 * file_or_folder...` feeds every file (folders: every file directly inside) to
 * LLVMFuzzerTestOneInput once. The test suite runs each target over its seed corpus
 * this way, so that the targets build with any compiler and every seed and past finding
 * keeps passing (under the sanitizers too).
 */
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size);

int
main (int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path p (argv[i]);
    if (fs::is_directory (p)) {
      for (const auto& entry : fs::directory_iterator (p))
        if (entry.is_regular_file())
          files.push_back (entry.path());
    }
    else if (fs::is_regular_file (p))
      files.push_back (p);
    else {
      std::fprintf (stderr, "%s: no such file or folder\n", argv[i]);
      return 1;
    }
  }
  if (files.empty()) {
    std::fprintf (stderr, "usage: %s file_or_folder...  (no input found)\n", argv[0]);
    return 1;
  }
  std::sort (files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in (f, std::ios::binary);
    const std::vector<char> bytes ((std::istreambuf_iterator<char> (in)),
                                   std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput (reinterpret_cast<const std::uint8_t*> (bytes.data()),
                            bytes.size());
  }
  std::printf ("%zu inputs, no failure\n", files.size());
  return 0;
}
