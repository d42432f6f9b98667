/*
 * pcl_ext: line-by-line text parsing shared by the readers (private header).
 */
#pragma once

#include <pcl_ext/io/read_error.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace pcl_ext {
namespace io {
namespace detail {
/** Reads a text file line by line, counting lines, so errors can name them. */
class TextLines {
public:
  /** Opens \a path; throws ReadError when it is missing, a folder or unreadable. */
  explicit TextLines (const std::string& path);

  /** Next line without its end-of-line (\n or \r\n); false at the end of the file. */
  bool
  next (std::string_view& line);

  /** Next line that is not blank and not a comment ('#', or "//" when \a slashes). */
  bool
  nextData (std::string_view& line, bool slashes = true);

  /** 1-based number of the last line returned. */
  std::size_t
  lineNumber () const
  {
    return line_number_;
  }

  const std::string&
  path () const
  {
    return path_;
  }

  /** Throws ReadError at the current line. */
  [[noreturn]] void
  fail (const std::string& message) const;

private:
  std::string path_;
  std::ifstream in_;
  std::string buffer_;
  std::size_t line_number_ = 0;
};

/** Leading and trailing blanks (space, tab, \r, \v, \f) removed. */
std::string_view
trim (std::string_view text);

/** Values of a data line: split at commas when it has one, else at blanks. Empty values
 * (",,") are kept as empty views so the caller can report them. */
void
splitValues (std::string_view line, std::vector<std::string_view>& values);

/** Blank-separated tokens. */
void
splitBlanks (std::string_view line, std::vector<std::string_view>& tokens);

/** Whole-token, locale-independent number; false on anything else. */
bool
parseDouble (std::string_view text, double& value);

/** Whole-token unsigned 32-bit integer; integral floats such as "3.0" are accepted. */
bool
parseLabel (std::string_view text, std::uint32_t& value);

/** Quote a token for an error message, shortened when long. */
std::string
quote (std::string_view text);
} // namespace detail
} // namespace io
} // namespace pcl_ext
