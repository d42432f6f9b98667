/*
 * pcl_ext: mapping of a data set's fine labels to coarse classes.
 */
#include <pcl_ext/io/class_mapping.h>

#include "text_lines.h"

namespace pcl_ext {
namespace io {
bool
ClassMapping::addClass (std::uint32_t id,
                        const std::string& name,
                        const std::vector<std::uint32_t>& sources)
{
  if (id == 0 || names_.count (id))
    return false;
  for (const auto s : sources)
    if (map_.count (s))
      return false;
  names_[id] = name;
  for (const auto s : sources)
    map_[s] = id;
  return true;
}

void
ClassMapping::load (const std::string& path)
{
  detail::TextLines lines (path);
  ClassMapping result;
  std::string_view line;
  std::vector<std::string_view> tokens;
  while (lines.nextData (line, false)) {
    const auto colon = line.find (':');
    detail::splitBlanks (line.substr (0, colon), tokens);
    if (tokens.size() != 2)
      lines.fail ("expected '<class id> <name> : <source labels>', found " +
                  detail::quote (line));
    std::uint32_t id = 0;
    if (!detail::parseLabel (tokens[0], id) || id == 0)
      lines.fail ("class id " + detail::quote (tokens[0]) +
                  " is not a positive integer");
    if (result.names_.count (id))
      lines.fail ("class id " + std::to_string (id) + " is given twice");
    const std::string name (tokens[1]);
    std::vector<std::uint32_t> sources;
    if (colon != std::string_view::npos) {
      detail::splitBlanks (line.substr (colon + 1), tokens);
      for (const auto& t : tokens) {
        std::uint32_t s = 0;
        if (!detail::parseLabel (t, s))
          lines.fail ("source label " + detail::quote (t) +
                      " is not a non-negative integer");
        if (result.map_.count (s))
          lines.fail ("source label " + std::to_string (s) +
                      " is already mapped to class " +
                      std::to_string (result.map_.at (s)));
        sources.push_back (s);
      }
    }
    result.addClass (id, name, sources);
  }
  if (result.empty())
    throw ReadError (
        path, 0, lines.lineNumber() == 0 ? "empty file, no classes" : "no classes");
  *this = std::move (result);
}

void
ClassMapping::apply (std::vector<std::uint32_t>& labels) const
{
  for (auto& l : labels)
    l = map (l);
}

std::string
ClassMapping::name (std::uint32_t id) const
{
  const auto it = names_.find (id);
  return it == names_.end() ? std::to_string (id) : it->second;
}
} // namespace io
} // namespace pcl_ext
