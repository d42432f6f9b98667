/*
 * pcl_ext: ASCII point files and the Oakland 3-D format.
 */
#include <pcl_ext/io/ascii_reader.h>

#include "text_lines.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace pcl_ext {
namespace io {
namespace {
const char*
columnName (AsciiColumn c)
{
  switch (c) {
  case AsciiColumn::X:
    return "x";
  case AsciiColumn::Y:
    return "y";
  case AsciiColumn::Z:
    return "z";
  case AsciiColumn::Intensity:
    return "intensity";
  case AsciiColumn::Red:
    return "red";
  case AsciiColumn::Green:
    return "green";
  case AsciiColumn::Blue:
    return "blue";
  case AsciiColumn::Label:
    return "label";
  default:
    return "skipped";
  }
}

std::string
describeColumns (std::size_t count)
{
  return std::to_string (count) + (count == 1 ? " value" : " values");
}

/** Whether no value of \a values is a number: a header line (column names). */
bool
isNameLine (const std::vector<std::string_view>& values)
{
  double v;
  for (const auto& value : values)
    if (detail::parseDouble (value, v))
      return false;
  return !values.empty();
}

/** The column a lower-case name stands for, in a column spec or a header line: x, y, z;
 * i / intensity; r / red, g / green, b / blue; label / l / class / classification;
 * skip / _ / - for a column to ignore. None for any other name. */
std::optional<AsciiColumn>
columnNamed (std::string_view name)
{
  if (name == "x")
    return AsciiColumn::X;
  if (name == "y")
    return AsciiColumn::Y;
  if (name == "z")
    return AsciiColumn::Z;
  if (name == "i" || name == "intensity")
    return AsciiColumn::Intensity;
  if (name == "r" || name == "red")
    return AsciiColumn::Red;
  if (name == "g" || name == "green")
    return AsciiColumn::Green;
  if (name == "b" || name == "blue")
    return AsciiColumn::Blue;
  if (name == "label" || name == "l" || name == "class" || name == "classification")
    return AsciiColumn::Label;
  if (name == "skip" || name == "_" || name == "-")
    return AsciiColumn::Skip;
  return std::nullopt;
}

/** The columns a header line names (quotes and case ignored; names it does not know
 * are skipped columns), or an empty vector when it does not name x, y and z. */
std::vector<AsciiColumn>
columnsFromNames (std::string_view line)
{
  std::string text (line);
  for (char& c : text)
    c = c == '"' || c == '\'' ? ' ' : static_cast<char> (std::tolower (c));
  std::vector<std::string_view> names;
  detail::splitValues (text, names);
  std::vector<AsciiColumn> columns;
  const auto has = [&columns] (AsciiColumn c) {
    return std::find (columns.begin(), columns.end(), c) != columns.end();
  };
  for (auto name : names) {
    name = detail::trim (name);
    // Names a header may hold that are no column of ours are skipped columns.
    const AsciiColumn c = columnNamed (name).value_or (AsciiColumn::Skip);
    columns.push_back (has (c) ? AsciiColumn::Skip : c);
  }
  if (!has (AsciiColumn::X) || !has (AsciiColumn::Y) || !has (AsciiColumn::Z))
    return {};
  if (!(has (AsciiColumn::Red) && has (AsciiColumn::Green) && has (AsciiColumn::Blue)))
    for (auto& c : columns)
      if (c == AsciiColumn::Red || c == AsciiColumn::Green || c == AsciiColumn::Blue)
        c = AsciiColumn::Skip;
  return columns;
}

/** Whether \a text is an integer in [0, 255] (a colour channel). */
bool
isColourValue (std::string_view text)
{
  double v;
  return detail::parseDouble (text, v) && v >= 0.0 && v <= 255.0 && v == std::floor (v);
}

/** The order of a 7-column file without header, from its first 1000 data lines:
 * x y z r g b i (CloudCompare's default export) when columns 4-6 are always colour
 * values and column 7 is not; x y z i r g b (Leica's PTS order) otherwise. */
std::vector<AsciiColumn>
sevenColumns (const std::string& path)
{
  detail::TextLines lines (path);
  std::vector<std::string_view> values;
  std::string_view line;
  bool middle_colour = true, last_colour = true;
  for (int n = 0; n < 1000 && lines.nextData (line);) {
    detail::splitValues (line, values);
    if (values.size() != 7 || isNameLine (values))
      continue;
    ++n;
    middle_colour = middle_colour && isColourValue (values[3]) &&
                    isColourValue (values[4]) && isColourValue (values[5]);
    last_colour = last_colour && isColourValue (values[6]);
  }
  return parseColumnSpec (middle_colour && !last_colour ? "x,y,z,r,g,b,i"
                                                        : "x,y,z,i,r,g,b");
}
} // namespace

std::vector<AsciiColumn>
parseColumnSpec (const std::string& spec)
{
  std::string normalised = spec;
  std::replace (normalised.begin(), normalised.end(), ',', ' ');
  std::vector<std::string_view> names;
  detail::splitBlanks (normalised, names);
  std::vector<AsciiColumn> columns;
  for (const auto& view : names) {
    std::string name (view);
    std::transform (name.begin(), name.end(), name.begin(), [] (unsigned char c) {
      return static_cast<char> (std::tolower (c));
    });
    const std::optional<AsciiColumn> named = columnNamed (name);
    if (!named)
      throw std::invalid_argument ("unknown column '" + name + "' in column spec '" +
                                   spec + "' (known: x y z i r g b label skip)");
    const AsciiColumn c = *named;
    if (c != AsciiColumn::Skip &&
        std::find (columns.begin(), columns.end(), c) != columns.end())
      throw std::invalid_argument ("column '" + name +
                                   "' given twice in column spec '" + spec + "'");
    columns.push_back (c);
  }
  for (const AsciiColumn required : {AsciiColumn::X, AsciiColumn::Y, AsciiColumn::Z})
    if (std::find (columns.begin(), columns.end(), required) == columns.end())
      throw std::invalid_argument ("column spec '" + spec + "' has no '" +
                                   columnName (required) + "' column");
  const auto has = [&columns] (AsciiColumn c) {
    return std::find (columns.begin(), columns.end(), c) != columns.end();
  };
  if ((has (AsciiColumn::Red) || has (AsciiColumn::Green) || has (AsciiColumn::Blue)) &&
      !(has (AsciiColumn::Red) && has (AsciiColumn::Green) && has (AsciiColumn::Blue)))
    throw std::invalid_argument ("column spec '" + spec +
                                 "' needs all of r, g, b or none");
  return columns;
}

std::vector<AsciiColumn>
defaultColumns (std::size_t count)
{
  switch (count) {
  case 3:
    return parseColumnSpec ("x,y,z");
  case 4:
    return parseColumnSpec ("x,y,z,i");
  case 6:
    return parseColumnSpec ("x,y,z,r,g,b");
  case 7:
    return parseColumnSpec ("x,y,z,i,r,g,b");
  case 8:
    return parseColumnSpec ("x,y,z,i,r,g,b,label");
  default:
    return {};
  }
}

void
loadAsciiPoints (const std::string& path,
                 PointTable& table,
                 const std::string& columns_spec)
{
  std::vector<AsciiColumn> columns;
  if (!columns_spec.empty()) {
    try {
      columns = parseColumnSpec (columns_spec);
    }
    catch (const std::invalid_argument& e) {
      throw ReadError (path, 0, e.what());
    }
  }
  detail::TextLines lines (path);
  PointTable result;
  std::vector<std::string_view> values;
  std::string_view line;
  bool first = true;
  bool has_intensity = false, has_rgb = false, has_label = false;
  std::vector<AsciiColumn> named;
  while (lines.next (line)) {
    line = detail::trim (line);
    if (line.empty())
      continue;
    const bool comment = line[0] == '#' || line.substr (0, 2) == "//";
    if (comment) {
      // A commented header (CloudCompare writes "//X,Y,Z,R,G,B,...").
      // Only a comment that starts with x y z: others are prose.
      if (first && named.empty()) {
        named = columnsFromNames (line.substr (line[0] == '#' ? 1 : 2));
        if (named.size() < 3 || named[0] != AsciiColumn::X ||
            named[1] != AsciiColumn::Y || named[2] != AsciiColumn::Z)
          named.clear();
      }
      continue;
    }
    detail::splitValues (line, values);
    if (first && isNameLine (values)) {
      // A header line (PDAL writes "X","Y","Z",...): its names unless a spec is given.
      if (named.empty())
        named = columnsFromNames (line);
      continue;
    }
    if (first) {
      if (columns.empty() && !named.empty())
        columns = named;
      if (columns.empty()) {
        columns =
            values.size() == 7 ? sevenColumns (path) : defaultColumns (values.size());
        if (columns.empty())
          lines.fail ("cannot tell what " + describeColumns (values.size()) +
                      " a line mean: give a column spec such as x,y,z,i,label");
      }
      const auto has = [&columns] (AsciiColumn c) {
        return std::find (columns.begin(), columns.end(), c) != columns.end();
      };
      has_intensity = has (AsciiColumn::Intensity);
      has_rgb = has (AsciiColumn::Red);
      has_label = has (AsciiColumn::Label);
      first = false;
    }
    if (values.size() != columns.size())
      lines.fail ("expected " + describeColumns (columns.size()) + ", found " +
                  std::to_string (values.size()) +
                  (values.size() < columns.size() ? " (truncated line?)" : ""));
    Eigen::Vector3d p;
    float intensity = 0.f;
    std::array<std::uint8_t, 3> rgb{0, 0, 0};
    std::uint32_t label = 0;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const AsciiColumn column = columns[c];
      if (column == AsciiColumn::Skip)
        continue;
      const auto bad = [&] (const std::string& what) {
        lines.fail ("column " + std::to_string (c + 1) + " (" + columnName (column) +
                    "): " + detail::quote (values[c]) + " " + what);
      };
      if (column == AsciiColumn::Label) {
        if (!detail::parseLabel (values[c], label))
          bad ("is not a non-negative integer label");
        continue;
      }
      double v = 0.0;
      if (!detail::parseDouble (values[c], v))
        bad ("is not a number");
      switch (column) {
      case AsciiColumn::X:
      case AsciiColumn::Y:
      case AsciiColumn::Z:
        if (!std::isfinite (v))
          bad ("is not a finite coordinate");
        p[static_cast<int> (column) - static_cast<int> (AsciiColumn::X)] = v;
        break;
      case AsciiColumn::Intensity:
        intensity = static_cast<float> (v);
        break;
      default: // colour
        if (!(v >= 0.0 && v <= 255.0))
          bad ("is not a colour value in [0, 255]");
        rgb[static_cast<int> (column) - static_cast<int> (AsciiColumn::Red)] =
            static_cast<std::uint8_t> (std::lround (v));
        break;
      }
    }
    result.xyz.push_back (p);
    if (has_intensity)
      result.intensity.push_back (intensity);
    if (has_rgb)
      result.rgb.push_back (rgb);
    if (has_label)
      result.label.push_back (label);
  }
  if (result.empty())
    throw ReadError (path,
                     0,
                     lines.lineNumber() == 0
                         ? "empty file, no points"
                         : "no points (only comments or blank lines)");
  table = std::move (result);
}

void
loadOaklandFile (const std::string& path, PointTable& table)
{
  loadAsciiPoints (path, table, "x,y,z,label,skip");
}
} // namespace io
} // namespace pcl_ext
