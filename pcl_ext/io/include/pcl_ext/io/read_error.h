/*
 * pcl_ext: the one exception the pcl_ext readers throw.
 */
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace pcl_ext {
namespace io {
/** \brief A file could not be read: missing, unreadable, empty or malformed.
 *
 * what() reads "<path>:<line>: <message>", or "<path>: <message>" when the problem is
 * not on one line (line() == 0), so that it can be printed as it is. Every pcl_ext
 * reader throws this and nothing else (besides std::bad_alloc), and leaves its output
 * untouched when it does.
 */
class ReadError : public std::runtime_error {
public:
  /** \param[in] path the file
   * \param[in] line 1-based line number, 0 when the error concerns the whole file
   * \param[in] message what is wrong, without the path */
  ReadError (const std::string& path, std::size_t line, const std::string& message)
  : std::runtime_error (line > 0 ? path + ":" + std::to_string (line) + ": " + message
                                 : path + ": " + message)
  , path_ (path)
  , line_ (line)
  , message_ (message)
  {}

  /** \brief The file that could not be read. */
  const std::string&
  path () const
  {
    return path_;
  }

  /** \brief 1-based line of the problem, 0 when it concerns the whole file. */
  std::size_t
  line () const
  {
    return line_;
  }

  /** \brief The message without path and line. */
  const std::string&
  message () const
  {
    return message_;
  }

private:
  std::string path_;
  std::size_t line_;
  std::string message_;
};
} // namespace io
} // namespace pcl_ext
