/*
 * pcl_ext: mapping of a data set's fine labels to coarse classes.
 */
#pragma once

#include <pcl_ext/io/read_error.h>

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Maps source labels (e.g. Oakland 3-D's 44 fine label ids) to coarse classes.
 *
 * The text format, one class a line, '#' starting a comment line:
 * \code
 * # id name : source labels
 * 1 vegetation : 1300 1304 1305 1306
 * 2 trunk_pole : 1103 1106 1107
 * \endcode
 * Class ids are positive (0 is reserved for "ignore"), names are single words; the part
 * after
 * ':' may be empty or absent (a class that only gets a name, e.g. for printing
 * metrics). A source label that no class lists maps to 0, so it is neither trained on
 * nor scored.
 */
class ClassMapping {
public:
  /** \brief Read a mapping file, replacing the current mapping.
   * \throw ReadError naming the file and line on a missing file, a malformed line, a
   * class id 0 or given twice, or a source label listed under two classes; the mapping
   * is then unchanged */
  void
  load (const std::string& path);

  /** \brief Add one class; returns false (nothing changed) when \a id is 0 or already
   * used, or a source label is already mapped. */
  bool
  addClass (std::uint32_t id,
            const std::string& name,
            const std::vector<std::uint32_t>& sources);

  /** \brief The class of a source label, 0 when unmapped. */
  std::uint32_t
  map (std::uint32_t source) const
  {
    const auto it = map_.find (source);
    return it == map_.end() ? 0u : it->second;
  }

  /** \brief Map every label in place. */
  void
  apply (std::vector<std::uint32_t>& labels) const;

  /** \brief Class names by class id. */
  const std::map<std::uint32_t, std::string>&
  names () const
  {
    return names_;
  }

  /** \brief Name of a class, or its id as text when it has none. */
  std::string
  name (std::uint32_t id) const;

  /** \brief Number of classes. */
  std::size_t
  size () const
  {
    return names_.size();
  }

  bool
  empty () const
  {
    return names_.empty();
  }

private:
  std::unordered_map<std::uint32_t, std::uint32_t> map_;
  std::map<std::uint32_t, std::string> names_;
};
} // namespace io
} // namespace pcl_ext
