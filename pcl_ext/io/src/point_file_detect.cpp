/*
 * pcl_ext: telling a point file's format from its content.
 */
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/point_file.h>

#include "text_lines.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

namespace pcl_ext {
namespace io {
namespace {
/** Whether the first \a size bytes of \a head hold a NUL byte (text files do not). */
bool
isBinary (const char* head, std::size_t size)
{
  return std::memchr (head, '\0', size) != nullptr;
}

/** Whether \a text starts like a PCD header: after '#' comments, a first keyword
 * VERSION or FIELDS. */
bool
startsLikePcd (const std::string& text)
{
  std::istringstream in (text);
  std::string line;
  while (std::getline (in, line)) {
    std::istringstream words (line);
    std::string key;
    if (!(words >> key) || key[0] == '#')
      continue;
    return key == "VERSION" || key == "FIELDS";
  }
  return false;
}

/** Whether \a line holds one non-negative integer and nothing else. */
bool
isSingleInteger (std::string_view line)
{
  std::vector<std::string_view> values;
  detail::splitValues (line, values);
  if (values.size() != 1 || values[0].empty())
    return false;
  return std::all_of (
      values[0].begin(), values[0].end(), [] (char c) { return c >= '0' && c <= '9'; });
}

/** PTX, PTS or ASCII, from the first two non-blank lines of \a text. */
PointFileFormat
detectText (const std::string& text, const std::string& extension)
{
  if (extension == "ptx")
    return PointFileFormat::PTX;
  if (extension == "pts")
    return PointFileFormat::PTS;
  std::istringstream in (text);
  std::string line;
  std::vector<std::string> first_lines;
  while (first_lines.size() < 2 && std::getline (in, line)) {
    const std::string_view trimmed = detail::trim (line);
    if (!trimmed.empty())
      first_lines.emplace_back (trimmed);
  }
  if (first_lines.size() == 2 && isSingleInteger (first_lines[0]))
    return isSingleInteger (first_lines[1]) ? PointFileFormat::PTX
                                            : PointFileFormat::PTS;
  return PointFileFormat::ASCII;
}
} // namespace

const char*
formatName (PointFileFormat format)
{
  switch (format) {
  case PointFileFormat::PCD:
    return "PCD";
  case PointFileFormat::PLY:
    return "PLY";
  case PointFileFormat::LAS:
    return "LAS";
  case PointFileFormat::LAZ:
    return "LAZ";
  case PointFileFormat::E57:
    return "E57";
  case PointFileFormat::PTX:
    return "PTX";
  case PointFileFormat::PTS:
    return "PTS";
  case PointFileFormat::ASCII:
    return "ASCII";
  default:
    return "unknown";
  }
}

PointFileFormat
detectPointFileFormat (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return PointFileFormat::Unknown;
  char head[4096];
  in.read (head, sizeof (head));
  const auto size = static_cast<std::size_t> (in.gcount());
  const std::string extension = fileExtension (path);
  if (size >= 4 && std::memcmp (head, "LASF", 4) == 0) {
    // Point data format byte (LAS 1.4 R15 table 3, offset 104); LASzip sets bit 7
    // (bit 6 in some old writers) on compressed files.
    const bool compressed =
        size > 104 && (static_cast<unsigned char> (head[104]) & 0xC0);
    return compressed || extension == "laz" ? PointFileFormat::LAZ
                                            : PointFileFormat::LAS;
  }
  if (size >= 8 && std::memcmp (head, "ASTM-E57", 8) == 0)
    return PointFileFormat::E57;
  if (size >= 4 && std::memcmp (head, "ply", 3) == 0 &&
      (head[3] == '\n' || head[3] == '\r'))
    return PointFileFormat::PLY;
  // A binary PCD has its header in text before a NUL-bearing body: look at the text
  // part only.
  const char* nul = static_cast<const char*> (std::memchr (head, '\0', size));
  const std::string text (head, nul ? static_cast<std::size_t> (nul - head) : size);
  if (startsLikePcd (text))
    return PointFileFormat::PCD;
  if (size == 0 || isBinary (head, size))
    return PointFileFormat::Unknown;
  return detectText (text, extension);
}
} // namespace io
} // namespace pcl_ext
