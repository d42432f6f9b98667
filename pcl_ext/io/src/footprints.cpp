/*
 * pcl_ext: building footprint polygons from WKT, GeoJSON and plain text files.
 */
#include <pcl_ext/io/footprints.h>

#include "text_lines.h"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace bg = boost::geometry;

namespace pcl_ext {
namespace io {
namespace {
using BoostPoint = bg::model::d2::point_xy<double>;
// Clockwise, closed: Boost.Geometry's defaults, which its algorithms are best tested
// with.
using BoostPolygon = bg::model::polygon<BoostPoint>;
using BoostMultiPolygon = bg::model::multi_polygon<BoostPolygon>;
using BoostPoint3 = bg::model::point<double, 3, bg::cs::cartesian>;
using BoostPolygon3 = bg::model::polygon<BoostPoint3>;
using BoostMultiPolygon3 = bg::model::multi_polygon<BoostPolygon3>;

/** Reports errors of one geometry at one place. */
struct Where {
  const std::string& source;
  std::size_t line;
  std::string context; // e.g. "feature 3: ", prefixed to messages

  [[noreturn]] void
  fail (const std::string& message) const
  {
    throw ReadError (source, line, context + message);
  }
};

std::string
pointText (const Eigen::Vector2d& p)
{
  std::ostringstream s;
  s.precision (12);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

/** Checks a closed ring as read and returns it open, without consecutive duplicates. */
Ring2d
openRing (const std::vector<Eigen::Vector2d>& closed,
          const std::string& name,
          const Where& where)
{
  for (const auto& p : closed) {
    if (!p.allFinite())
      where.fail (name + " has a coordinate that is not finite");
    if (p.cwiseAbs().maxCoeff() > kMaxFootprintCoordinate)
      where.fail (name + " has a coordinate beyond 1e9 m: " + pointText (p));
  }
  if (closed.size() < 2 || closed.front() != closed.back()) {
    if (closed.empty())
      where.fail (name + " is empty");
    where.fail (name + " is not closed: its first vertex " +
                pointText (closed.front()) + " differs from its last " +
                pointText (closed.back()));
  }
  Ring2d ring;
  for (std::size_t i = 0; i + 1 < closed.size(); ++i)
    if (ring.empty() || closed[i] != ring.back())
      ring.push_back (closed[i]);
  if (ring.size() > 1 && ring.back() == ring.front())
    ring.pop_back();
  if (ring.size() < 3)
    where.fail (name + " has fewer than 3 distinct vertices");
  return ring;
}

/** Builds a checked, normalised polygon from closed rings as read. */
FootprintPolygon
makePolygon (const std::vector<std::vector<Eigen::Vector2d>>& rings,
             const std::string& name,
             const Where& where)
{
  if (rings.empty())
    where.fail (name + " has no ring (empty polygon)");
  FootprintPolygon polygon;
  polygon.outer = openRing (rings[0], name + " outer ring", where);
  for (std::size_t h = 1; h < rings.size(); ++h)
    polygon.holes.push_back (
        openRing (rings[h], name + " hole " + std::to_string (h), where));

  // Validity through Boost.Geometry: self-intersections, holes outside, spikes.
  BoostPolygon b;
  const auto fill = [] (const Ring2d& ring, auto& out) {
    for (const auto& p : ring)
      out.push_back (BoostPoint (p.x(), p.y()));
    out.push_back (BoostPoint (ring.front().x(), ring.front().y()));
  };
  fill (polygon.outer, b.outer());
  for (const auto& hole : polygon.holes) {
    b.inners().emplace_back();
    fill (hole, b.inners().back());
  }
  std::string reason;
  bool valid = false;
  try {
    bg::correct (b);
    valid = bg::is_valid (b, reason);
  }
  catch (
      const std::exception& e) // e.g. boost::numeric::bad_numeric_cast in its rescaling
  {
    reason = std::string ("the validity check failed (") + e.what() + ")";
  }
  if (!valid)
    where.fail (name + " is not a valid polygon: " + reason);

  // Outer counter-clockwise, holes clockwise (interior on the left of every edge).
  if (signedArea (polygon.outer) < 0.0)
    std::reverse (polygon.outer.begin(), polygon.outer.end());
  for (auto& hole : polygon.holes)
    if (signedArea (hole) > 0.0)
      std::reverse (hole.begin(), hole.end());
  return polygon;
}

template <typename BoostRing>
std::vector<Eigen::Vector2d>
ringFromBoost (const BoostRing& ring)
{
  std::vector<Eigen::Vector2d> out;
  for (const auto& p : ring)
    out.emplace_back (bg::get<0> (p), bg::get<1> (p));
  return out;
}

template <typename BoostPolygonT>
std::vector<std::vector<Eigen::Vector2d>>
ringsFromBoost (const BoostPolygonT& polygon)
{
  std::vector<std::vector<Eigen::Vector2d>> rings{ringFromBoost (polygon.outer())};
  for (const auto& inner : polygon.inners())
    rings.push_back (ringFromBoost (inner));
  return rings;
}

std::string
upper (std::string_view text)
{
  std::string s (text);
  std::transform (s.begin(), s.end(), s.begin(), [] (unsigned char c) {
    return static_cast<char> (std::toupper (c));
  });
  return s;
}

/** Position of the geometry keyword in a line, npos when none. */
std::size_t
findWktKeyword (std::string_view line)
{
  const std::string u = upper (line);
  const auto multi = u.find ("MULTIPOLYGON");
  const auto single = u.find ("POLYGON");
  return multi != std::string::npos ? multi : single;
}

/** Reads a whole file (for JSON). */
std::string
readAll (const std::string& path)
{
  detail::TextLines probe (path); // the same clear errors for missing files and folders
  std::ifstream in (path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad())
    throw ReadError (path, 0, "read error");
  return s.str();
}
} // namespace

double
signedArea (const Ring2d& ring)
{
  if (ring.size() < 3)
    return 0.0;
  // Relative to the first vertex, so large georeferenced coordinates keep their digits.
  double twice = 0.0;
  const Eigen::Vector2d o = ring.front();
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const Eigen::Vector2d a = ring[i] - o, b = ring[i + 1] - o;
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

void
parseWkt (const std::string& wkt,
          Footprint& footprint,
          const std::string& source,
          std::size_t line)
{
  const Where where{source, line, ""};
  const std::string u = upper (wkt);
  const bool multi = u.find ("MULTIPOLYGON") != std::string::npos;
  if (!multi && u.find ("POLYGON") == std::string::npos)
    where.fail ("expected a WKT POLYGON or MULTIPOLYGON, found " + detail::quote (wkt));
  // "POLYGON Z ((x y z, ...))": read with a 3-D point type and keep x, y.
  std::string keyword_rest = u.substr (u.find ("POLYGON") + 7);
  const bool has_z = detail::trim (keyword_rest).substr (0, 1) == "Z";
  std::vector<std::vector<std::vector<Eigen::Vector2d>>> parts;
  try {
    std::string text = wkt;
    if (has_z) {
      // Boost 1.74 wants "POLYGON((x y z ...))" for 3-D points, without the Z tag.
      const auto z = u.find ('Z', u.find ("POLYGON") + 7);
      text.erase (z, 1);
      if (multi) {
        BoostMultiPolygon3 mp;
        bg::read_wkt (text, mp);
        for (const auto& p : mp)
          parts.push_back (ringsFromBoost (p));
      }
      else {
        BoostPolygon3 p;
        bg::read_wkt (text, p);
        parts.push_back (ringsFromBoost (p));
      }
    }
    else if (multi) {
      BoostMultiPolygon mp;
      bg::read_wkt (wkt, mp);
      for (const auto& p : mp)
        parts.push_back (ringsFromBoost (p));
    }
    else {
      BoostPolygon p;
      bg::read_wkt (wkt, p);
      parts.push_back (ringsFromBoost (p));
    }
  }
  catch (const std::exception& e) // bg::read_wkt_exception, boost::bad_lexical_cast
  {
    where.fail (std::string ("WKT syntax error: ") + e.what());
  }
  if (parts.empty())
    where.fail ("empty MULTIPOLYGON");
  std::vector<FootprintPolygon> polygons;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].front().empty())
      where.fail (std::string (multi ? "part " + std::to_string (i + 1) : "polygon") +
                  " is empty");
    polygons.push_back (makePolygon (
        parts[i], multi ? "part " + std::to_string (i + 1) : "polygon", where));
  }
  footprint.polygons = std::move (polygons);
}

void
loadWktFootprints (const std::string& path, std::vector<Footprint>& footprints)
{
  detail::TextLines lines (path);
  std::vector<Footprint> result;
  std::string_view line;
  while (lines.nextData (line, false)) {
    const auto keyword = findWktKeyword (line);
    if (keyword == std::string::npos)
      lines.fail ("expected a WKT POLYGON or MULTIPOLYGON, found " +
                  detail::quote (line));
    Footprint f;
    f.line = lines.lineNumber();
    std::string_view id = line.substr (0, keyword);
    while (!id.empty() &&
           std::string_view (" \t,;|").find (id.back()) != std::string_view::npos)
      id.remove_suffix (1);
    f.id = id.empty() ? std::to_string (f.line) : std::string (detail::trim (id));
    parseWkt (std::string (line.substr (keyword)), f, path, f.line);
    result.push_back (std::move (f));
  }
  if (result.empty())
    throw ReadError (
        path, 0, lines.lineNumber() == 0 ? "empty file, no polygons" : "no polygons");
  footprints = std::move (result);
}

namespace {
using nlohmann::json;

std::vector<std::vector<Eigen::Vector2d>>
ringsFromJson (const json& rings, const Where& where)
{
  if (!rings.is_array())
    where.fail ("polygon coordinates are not an array of rings");
  std::vector<std::vector<Eigen::Vector2d>> out;
  for (const auto& ring : rings) {
    if (!ring.is_array())
      where.fail ("a ring is not an array of positions");
    out.emplace_back();
    for (const auto& position : ring) {
      if (!position.is_array() || position.size() < 2 || !position[0].is_number() ||
          !position[1].is_number())
        where.fail ("a position is not [x, y] numbers: " +
                    detail::quote (position.dump()));
      out.back().emplace_back (position[0].get<double>(), position[1].get<double>());
    }
  }
  return out;
}

void
geometryFromJson (const json& geometry, Footprint& f, const Where& where)
{
  if (!geometry.is_object() || !geometry.contains ("type") ||
      !geometry["type"].is_string())
    where.fail ("geometry has no \"type\"");
  const std::string type = geometry["type"].get<std::string>();
  if (!geometry.contains ("coordinates"))
    where.fail ("geometry has no \"coordinates\"");
  const json& coordinates = geometry["coordinates"];
  if (type == "Polygon")
    f.polygons.push_back (
        makePolygon (ringsFromJson (coordinates, where), "polygon", where));
  else if (type == "MultiPolygon") {
    if (!coordinates.is_array() || coordinates.empty())
      where.fail ("MultiPolygon coordinates are not a non-empty array of polygons");
    for (std::size_t i = 0; i < coordinates.size(); ++i)
      f.polygons.push_back (makePolygon (ringsFromJson (coordinates[i], where),
                                         "part " + std::to_string (i + 1),
                                         where));
  }
  else
    where.fail ("geometry type \"" + type + "\" is not Polygon or MultiPolygon");
}

std::string
idText (const json& value)
{
  return value.is_string() ? value.get<std::string>() : value.dump();
}

/** 1-based line of byte offset \a byte in \a text. */
std::size_t
lineOfByte (const std::string& text, std::size_t byte)
{
  const std::size_t end = std::min (byte, text.size());
  return 1 +
         static_cast<std::size_t> (std::count (text.begin(), text.begin() + end, '\n'));
}

/** Line where the index-th feature's object starts, found by scanning for '"type"' keys
 * of Feature objects; 0 when it cannot be told. Only used to make messages easier to
 * follow. */
std::size_t
lineOfFeature (const std::string& text, std::size_t index)
{
  std::size_t found = 0, pos = 0;
  while ((pos = text.find ("\"Feature\"", pos)) != std::string::npos) {
    if (found++ == index)
      return lineOfByte (text, pos);
    pos += 9;
  }
  return 0;
}
} // namespace

void
loadGeoJsonFootprints (const std::string& path, std::vector<Footprint>& footprints)
{
  const std::string text = readAll (path);
  if (detail::trim (text).empty())
    throw ReadError (path, 0, "empty file, no polygons");
  json root;
  try {
    root = json::parse (text);
  }
  catch (const json::parse_error& e) {
    // e.byte is 1-based, pointing just past the offending character.
    throw ReadError (path,
                     lineOfByte (text, e.byte > 0 ? e.byte - 1 : 0),
                     std::string ("JSON syntax error: ") + e.what());
  }
  catch (const json::exception& e) // e.g. out_of_range: a number too large for a double
  {
    throw ReadError (path, 0, std::string ("JSON error: ") + e.what());
  }
  std::vector<Footprint> result;
  try {
    if (!root.is_object() || !root.contains ("type") || !root["type"].is_string())
      throw ReadError (path, 0, "not GeoJSON: no top-level \"type\"");
    const std::string type = root["type"].get<std::string>();
    std::vector<const json*> features;
    if (type == "FeatureCollection") {
      if (!root.contains ("features") || !root["features"].is_array())
        throw ReadError (path, 0, "FeatureCollection without a \"features\" array");
      for (const auto& feature : root["features"])
        features.push_back (&feature);
    }
    else if (type == "Feature")
      features.push_back (&root);
    else {
      Footprint f;
      f.id = "0";
      f.line = 1;
      geometryFromJson (root, f, Where{path, 0, ""});
      result.push_back (std::move (f));
    }
    for (std::size_t i = 0; i < features.size(); ++i) {
      const json& feature = *features[i];
      const std::size_t line = lineOfFeature (text, i);
      const Where where{path, line, "feature " + std::to_string (i) + ": "};
      if (!feature.is_object() || feature.value ("type", json()) != "Feature")
        where.fail ("not a GeoJSON Feature object");
      if (!feature.contains ("geometry") || feature["geometry"].is_null())
        continue;
      Footprint f;
      f.line = line;
      if (feature.contains ("id") && !feature["id"].is_null())
        f.id = idText (feature["id"]);
      else if (feature.contains ("properties") && feature["properties"].is_object() &&
               (feature["properties"].contains ("id") ||
                feature["properties"].contains ("identificatie"))) {
        const json& p = feature["properties"];
        f.id = idText (p.contains ("id") ? p["id"] : p["identificatie"]);
      }
      else
        f.id = std::to_string (i);
      geometryFromJson (feature["geometry"], f, where);
      result.push_back (std::move (f));
    }
  }
  catch (const json::exception& e) // type errors in unexpected structures
  {
    throw ReadError (
        path, 0, std::string ("unexpected GeoJSON structure: ") + e.what());
  }
  if (result.empty())
    throw ReadError (path, 0, "no polygons");
  footprints = std::move (result);
}

void
loadTextFootprints (const std::string& path, std::vector<Footprint>& footprints)
{
  detail::TextLines lines (path);
  std::vector<Footprint> result;
  std::string_view line;
  std::vector<std::string_view> tokens;
  while (lines.nextData (line, false)) {
    detail::splitBlanks (line, tokens);
    const Where where{path, lines.lineNumber(), ""};
    if (tokens.size() < 2)
      where.fail ("expected 'id n x1 y1 ... xn yn', found " + detail::quote (line));
    std::uint32_t n = 0;
    if (!detail::parseLabel (tokens[1], n))
      where.fail ("vertex count " + detail::quote (tokens[1]) +
                  " is not a non-negative integer");
    if (tokens.size() != 2 + 2 * static_cast<std::size_t> (n))
      where.fail ("expected " + std::to_string (2 * static_cast<std::size_t> (n)) +
                  " coordinates for " + std::to_string (n) + " vertices, found " +
                  std::to_string (tokens.size() - 2) + " (truncated line?)");
    std::vector<Eigen::Vector2d> ring (n);
    for (std::size_t v = 0; v < n; ++v)
      for (int c = 0; c < 2; ++c) {
        const auto& t = tokens[2 + 2 * v + c];
        if (!detail::parseDouble (t, ring[v][c]))
          where.fail ("vertex " + std::to_string (v + 1) + (c ? " y " : " x ") +
                      detail::quote (t) + " is not a number");
      }
    Footprint f;
    f.id = std::string (tokens[0]);
    f.line = lines.lineNumber();
    f.polygons.push_back (makePolygon ({ring}, "polygon", where));
    result.push_back (std::move (f));
  }
  if (result.empty())
    throw ReadError (
        path, 0, lines.lineNumber() == 0 ? "empty file, no polygons" : "no polygons");
  footprints = std::move (result);
}

void
loadFootprints (const std::string& path, std::vector<Footprint>& footprints)
{
  const auto dot = path.find_last_of ('.');
  const auto slash = path.find_last_of ('/');
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    ext = upper (path.substr (dot + 1));
  if (ext == "WKT")
    return loadWktFootprints (path, footprints);
  if (ext == "GEOJSON" || ext == "JSON")
    return loadGeoJsonFootprints (path, footprints);
  if (ext == "CSV")
    return loadCsvFootprints (path, footprints);
  if (ext == "TXT")
    return loadTextFootprints (path, footprints);
  detail::TextLines lines (path);
  std::string_view first;
  if (!lines.nextData (first, false))
    throw ReadError (path, 0, "empty file, no polygons");
  if (first.front() == '{')
    return loadGeoJsonFootprints (path, footprints);
  if (findWktKeyword (first) != std::string::npos)
    return loadWktFootprints (path, footprints);
  return loadTextFootprints (path, footprints);
}

void
translateFootprints (std::vector<Footprint>& footprints, const Eigen::Vector2d& offset)
{
  for (auto& f : footprints)
    for (auto& polygon : f.polygons) {
      for (auto& p : polygon.outer)
        p += offset;
      for (auto& hole : polygon.holes)
        for (auto& p : hole)
          p += offset;
    }
}
} // namespace io
} // namespace pcl_ext
