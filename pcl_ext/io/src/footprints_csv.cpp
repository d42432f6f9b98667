/*
 * pcl_ext: building footprint polygons from CSV tables with a geometry column.
 */
#include <pcl_ext/io/footprints.h>

#include "text_lines.h"

#include <boost/algorithm/string/case_conv.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <sstream>

namespace pcl_ext {
namespace io {
namespace {
/** One record of the table: its fields and the line it starts on. */
struct CsvRecord {
  std::vector<std::string> fields;
  std::size_t line = 0;
};

/** The delimiter among ',', ';' and tab that occurs most often outside quotes in the
 * first record; ',' when none does (a table of one column). */
char
detectDelimiter (const std::string& text)
{
  std::size_t counts[3] = {0, 0, 0};
  const char candidates[3] = {',', ';', '\t'};
  bool quoted = false;
  for (const char c : text) {
    if (c == '"')
      quoted = !quoted;
    else if (!quoted && c == '\n')
      break;
    else if (!quoted)
      for (int k = 0; k < 3; ++k)
        counts[k] += c == candidates[k];
  }
  const auto best = std::max_element (counts, counts + 3) - counts;
  return counts[best] > 0 ? candidates[best] : ',';
}

/** Splits \a text into records (RFC 4180: a field in double quotes may hold the
 * delimiter, line breaks and doubled quotes). Unquoted fields are trimmed; blank lines
 * are skipped. */
std::vector<CsvRecord>
parseCsv (const std::string& text, char delimiter, const std::string& path)
{
  std::vector<CsvRecord> records;
  CsvRecord record;
  record.line = 1;
  std::string field;
  std::size_t line = 1, quote_line = 0;
  bool quoted = false, was_quoted = false, blank = true;
  const auto endField = [&] () {
    record.fields.push_back (was_quoted ? field : std::string (detail::trim (field)));
    field.clear();
    was_quoted = false;
  };
  const auto endRecord = [&] () {
    endField();
    if (!blank)
      records.push_back (std::move (record));
    record = CsvRecord();
    blank = true;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        }
        else
          quoted = false;
      }
      else {
        line += c == '\n';
        field += c;
      }
      continue;
    }
    if (c == '"') {
      if (was_quoted || !detail::trim (field).empty())
        throw ReadError (path, line, "a double quote inside an unquoted field");
      quoted = was_quoted = true;
      blank = false;
      quote_line = line;
    }
    else if (c == delimiter) {
      endField();
      blank = false;
    }
    else if (c == '\n') {
      endRecord();
      record.line = ++line;
    }
    else if (was_quoted) {
      if (c != '\r' && c != ' ' && c != '\t')
        throw ReadError (path, line, "text after the closing quote of a field");
    }
    else {
      field += c;
      if (c != '\r' && c != ' ' && c != '\t')
        blank = false;
    }
  }
  if (quoted)
    throw ReadError (path, quote_line, "a quoted field is not closed");
  endRecord();
  return records;
}

/** The index of the first header name in \a names (lower case), or -1. */
long
findColumn (const std::vector<std::string>& header,
            std::initializer_list<const char*> names)
{
  for (const char* name : names)
    for (std::size_t i = 0; i < header.size(); ++i)
      if (boost::algorithm::to_lower_copy (std::string (detail::trim (header[i]))) ==
          name)
        return static_cast<long> (i);
  return -1;
}

/** How deeply \a value nests arrays down to its first number: 1 for [x, y], 2 for a
 * ring, 3 for a polygon's rings, 4 for a multipolygon; 0 when it is not such an array.
 */
int
coordinateDepth (const nlohmann::json& value)
{
  int depth = 0;
  const nlohmann::json* v = &value;
  while (v->is_array() && !v->empty()) {
    ++depth;
    v = &v->front();
  }
  return v->is_number() ? depth : 0;
}

void
appendRingWkt (const nlohmann::json& ring, std::string& wkt, const std::string& what)
{
  if (!ring.is_array())
    throw std::runtime_error (what + " is not an array of [x, y] positions");
  wkt += '(';
  char number[64];
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& p = ring[i];
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
      throw std::runtime_error (what + ": position " + std::to_string (i + 1) +
                                " is not [x, y] numbers: " + detail::quote (p.dump()));
    std::snprintf (number,
                   sizeof (number),
                   "%s%.17g %.17g",
                   i ? ", " : "",
                   p[0].get<double>(),
                   p[1].get<double>());
    wkt += number;
  }
  wkt += ')';
}

void
appendPolygonWkt (const nlohmann::json& rings,
                  std::string& wkt,
                  const std::string& what)
{
  if (!rings.is_array() || rings.empty())
    throw std::runtime_error (what + " is not a non-empty array of rings");
  wkt += '(';
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (r)
      wkt += ", ";
    appendRingWkt (
        rings[r], wkt, r ? what + " hole " + std::to_string (r) : what + " outer ring");
  }
  wkt += ')';
}

/** WKT of JSON coordinates: a ring, a polygon's rings or a multipolygon's polygons. */
std::string
wktOfJsonCoordinates (const std::string& cell)
{
  const nlohmann::json value = nlohmann::json::parse (cell);
  std::string wkt;
  switch (coordinateDepth (value)) {
  case 2:
    wkt = "POLYGON(";
    appendRingWkt (value, wkt, "the ring");
    return wkt + ")";
  case 3:
    wkt = "POLYGON";
    appendPolygonWkt (value, wkt, "the polygon");
    return wkt;
  case 4:
    wkt = "MULTIPOLYGON(";
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i)
        wkt += ", ";
      appendPolygonWkt (value[i], wkt, "part " + std::to_string (i + 1));
    }
    return wkt + ")";
  default:
    throw std::runtime_error ("JSON coordinates are not a ring [[x, y], ...], a "
                              "polygon [[[x, y], ...], ...] or a multipolygon");
  }
}
} // namespace

void
loadCsvFootprints (const std::string& path, std::vector<Footprint>& footprints)
{
  detail::TextLines probe (path); // the same errors for a missing file or a folder
  std::ifstream in (path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad())
    throw ReadError (path, 0, "read error");
  std::string text = buffer.str();
  if (text.compare (0, 3, "\xEF\xBB\xBF") == 0) // a UTF-8 byte order mark
    text.erase (0, 3);
  const std::vector<CsvRecord> records = parseCsv (text, detectDelimiter (text), path);
  if (records.empty())
    throw ReadError (path, 0, "empty file, no polygons");
  const std::vector<std::string>& header = records.front().fields;
  const long geometry =
      findColumn (header, {"wkt", "geometry", "geom", "the_geom", "polygon", "shape"});
  if (geometry < 0)
    throw ReadError (path,
                     records.front().line,
                     "no geometry column in the header (one named wkt, geometry, "
                     "geom, the_geom, polygon or shape)");
  const long id =
      findColumn (header, {"id", "fid", "identificatie", "gml_id", "objectid"});
  std::vector<Footprint> result;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const CsvRecord& record = records[r];
    if (record.fields.size() != header.size())
      throw ReadError (path,
                       record.line,
                       std::to_string (record.fields.size()) +
                           " fields, the header has " + std::to_string (header.size()));
    std::string cell (detail::trim (record.fields[geometry]));
    if (cell.empty())
      continue;
    Footprint f;
    f.line = record.line;
    f.id = id >= 0 && !record.fields[id].empty() ? record.fields[id]
                                                 : std::to_string (record.line);
    if (cell.front() == '[') {
      try {
        cell = wktOfJsonCoordinates (cell);
      }
      catch (const std::exception& e) { // nlohmann's parse and type errors too
        throw ReadError (path, record.line, e.what());
      }
    }
    else if (boost::algorithm::to_lower_copy (cell.substr (0, 5)) == "srid=" &&
             cell.find (';') != std::string::npos)
      cell.erase (0, cell.find (';') + 1); // EWKT
    parseWkt (cell, f, path, record.line);
    result.push_back (std::move (f));
  }
  if (result.empty())
    throw ReadError (path, 0, "no polygons");
  footprints = std::move (result);
}
} // namespace io
} // namespace pcl_ext
