/*
 * pcl_ext: line-by-line text parsing shared by the readers.
 */
#include "text_lines.h"

#include <sys/stat.h>

#include <charconv>
#include <cmath>
#include <limits>

namespace pcl_ext {
namespace io {
namespace detail {
TextLines::TextLines (const std::string& path) : path_ (path)
{
  struct stat st;
  if (::stat (path.c_str(), &st) != 0)
    throw ReadError (path, 0, "no such file");
  if (S_ISDIR (st.st_mode))
    throw ReadError (path, 0, "is a folder, not a file");
  in_.open (path, std::ios::binary);
  if (!in_)
    throw ReadError (path, 0, "cannot be opened for reading");
}

bool
TextLines::next (std::string_view& line)
{
  if (!std::getline (in_, buffer_)) {
    if (in_.bad())
      throw ReadError (path_, line_number_ + 1, "read error");
    return false;
  }
  ++line_number_;
  line = buffer_;
  if (!line.empty() && line.back() == '\r')
    line.remove_suffix (1);
  return true;
}

bool
TextLines::nextData (std::string_view& line, bool slashes)
{
  while (next (line)) {
    line = trim (line);
    if (line.empty() || line.front() == '#' || (slashes && line.substr (0, 2) == "//"))
      continue;
    return true;
  }
  return false;
}

void
TextLines::fail (const std::string& message) const
{
  throw ReadError (path_, line_number_, message);
}

std::string_view
trim (std::string_view text)
{
  const char* blanks = " \t\r\v\f";
  const auto first = text.find_first_not_of (blanks);
  if (first == std::string_view::npos)
    return {};
  const auto last = text.find_last_not_of (blanks);
  return text.substr (first, last - first + 1);
}

void
splitValues (std::string_view line, std::vector<std::string_view>& values)
{
  values.clear();
  if (line.find (',') == std::string_view::npos) {
    splitBlanks (line, values);
    return;
  }
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find (',', start);
    values.push_back (trim (
        line.substr (start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos)
      break;
    start = comma + 1;
  }
}

void
splitBlanks (std::string_view line, std::vector<std::string_view>& tokens)
{
  tokens.clear();
  const char* blanks = " \t\r\v\f";
  std::size_t start = line.find_first_not_of (blanks);
  while (start != std::string_view::npos) {
    const auto end = line.find_first_of (blanks, start);
    tokens.push_back (
        line.substr (start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos)
      break;
    start = line.find_first_not_of (blanks, end);
  }
}

bool
parseDouble (std::string_view text, double& value)
{
  // from_chars refuses a leading '+', which some writers emit.
  if (!text.empty() && text.front() == '+')
    text.remove_prefix (1);
  if (text.empty())
    return false;
  const auto result = std::from_chars (text.data(), text.data() + text.size(), value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

bool
parseLabel (std::string_view text, std::uint32_t& value)
{
  double v = 0.0;
  if (!parseDouble (text, v) || !(v >= 0.0) ||
      v > std::numeric_limits<std::uint32_t>::max() || v != std::floor (v))
    return false;
  value = static_cast<std::uint32_t> (v);
  return true;
}

std::string
quote (std::string_view text)
{
  if (text.size() > 40)
    return "'" + std::string (text.substr (0, 37)) + "...'";
  return "'" + std::string (text) + "'";
}
} // namespace detail
} // namespace io
} // namespace pcl_ext
