/*
 * pcl_ext: building footprint polygons from WKT, GeoJSON, CSV and plain text files.
 */
#pragma once

#include <pcl_ext/io/read_error.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Largest |coordinate| of a footprint vertex, in metres: far beyond any
 * projected coordinate system, and small enough for Boost.Geometry's validity check,
 * which rescales coordinates to 64-bit integers. */
constexpr double kMaxFootprintCoordinate = 1e9;

/** \brief A polygon ring: vertices in order, in double precision, stored open (the
 * first vertex is not repeated at the end), without consecutive duplicates. */
using Ring2d = std::vector<Eigen::Vector2d>;

/** \brief A polygon with holes. The outer ring runs counter-clockwise and the holes
 * clockwise (seen from +z, x east and y north), whatever the file's orientation was, so
 * that edge i (v_i to v_i+1) of any ring has the polygon's interior on its left. */
struct FootprintPolygon {
  Ring2d outer;
  std::vector<Ring2d> holes;
};

/** \brief One footprint: a POLYGON (one part) or a MULTIPOLYGON (several parts). */
struct Footprint {
  std::string id; ///< the identifier found in the file (see each reader)
  std::vector<FootprintPolygon> polygons; ///< the parts, in file order
  std::size_t line = 0; ///< line of the file where it starts (1-based)
};

/** \brief Parse one WKT POLYGON or MULTIPOLYGON (case-insensitive; a "Z" geometry's
 * heights are dropped) with Boost.Geometry.
 *
 * Every ring must be closed (first vertex = last vertex, as the WKT standard requires),
 * have finite coordinates within kMaxFootprintCoordinate and at least 3 distinct
 * vertices; the polygon must then be valid in Boost.Geometry's sense (no
 * self-intersection, holes inside the outer ring, no spikes). The vertex order is
 * normalised (see FootprintPolygon). \param[in] wkt the text \param[out] footprint its
 * polygons (the id and line are left as they were) \param[in] source name used in error
 * messages, e.g. a file name; default "WKT" \param[in] line line number used in error
 * messages; default 0 (none) \throw ReadError on a syntax error, an unclosed or
 * degenerate ring, a coordinate out of range, or an invalid polygon
 */
void
parseWkt (const std::string& wkt,
          Footprint& footprint,
          const std::string& source = "WKT",
          std::size_t line = 0);

/** \brief Read a WKT file: one geometry per line, optionally preceded by an identifier.
 *
 * A line reads `[id<separator>]POLYGON(...)` or `[id<separator>]MULTIPOLYGON(...)`; the
 * id is the text before the geometry keyword with separators (blanks, ',', ';', '|')
 * trimmed, or the line number when there is none. Blank lines and lines starting with
 * '#' are skipped. \throw ReadError naming the file and line (see parseWkt), or when
 * the file is missing or holds no polygon; \a footprints is untouched then
 */
void
loadWktFootprints (const std::string& path, std::vector<Footprint>& footprints);

/** \brief Read GeoJSON: a FeatureCollection, a Feature, or a bare Polygon /
 * MultiPolygon.
 *
 * Coordinates [x, y] or [x, y, z] (z dropped), rings closed as RFC 7946 requires,
 * checked as parseWkt does. The id is the feature's "id", else its properties' "id" or
 * "identificatie", else the feature's 0-based index. Features whose geometry is null
 * are skipped; any other geometry type is an error (a footprint file should hold
 * footprints only). Syntax errors name the line; structural errors name the feature
 * index. \throw ReadError as loadWktFootprints
 */
void
loadGeoJsonFootprints (const std::string& path, std::vector<Footprint>& footprints);

/** \brief Read the plain text footprint format: one polygon per line,
 * `id n x1 y1 x2 y2 ... xn yn`, a closed ring of n vertices (x_n = x_1, y_n = y_1)
 * without holes; '#' comment lines. The id is the first token as it is. \throw
 * ReadError as loadWktFootprints, also when the line does not hold exactly 2n numbers
 */
void
loadTextFootprints (const std::string& path, std::vector<Footprint>& footprints);

/** \brief Read a CSV table of footprints, as GIS tools and open-data portals export
 * them: a header row, then one footprint per row.
 *
 * Fields follow RFC 4180 (a field in double quotes may hold the delimiter, line breaks
 * and doubled quotes); the delimiter is the one of ',', ';' and tab found most often in
 * the header; a UTF-8 byte order mark is skipped. The geometry is the column named
 * (in any case) wkt, geometry, geom, the_geom, polygon or shape, holding either WKT (a
 * POLYGON or MULTIPOLYGON as parseWkt reads it; an EWKT "SRID=n;" prefix is dropped) or
 * JSON coordinates: one closed ring [[x, y], ...], a polygon's rings [[[x, y], ...],
 * ...] (outer ring first), or a list of such polygons. The id is the column id, fid,
 * identificatie, gml_id or objectid when there is one and it is not empty, else the
 * row's line number. Rows with an empty geometry are skipped. \throw ReadError naming
 * the file and line: no geometry column, a row whose field count differs from the
 * header's, an unclosed quote, a geometry parseWkt refuses; or when the file is missing
 * or holds no polygon; \a footprints is untouched then
 */
void
loadCsvFootprints (const std::string& path, std::vector<Footprint>& footprints);

/** \brief Read a footprint file choosing the reader by extension (.wkt; .geojson or
 * .json; .csv; .txt), or for other extensions by content (a '{' first means GeoJSON, a
 * POLYGON keyword in the first data line WKT, otherwise the text format). \throw
 * ReadError as the readers
 */
void
loadFootprints (const std::string& path, std::vector<Footprint>& footprints);

/** \brief Add \a offset to every vertex (pass minus a local origin to move
 * georeferenced footprints to the frame of a cloud converted with that origin). */
void
translateFootprints (std::vector<Footprint>& footprints, const Eigen::Vector2d& offset);

/** \brief Signed area of a ring by the shoelace formula (positive counter-clockwise).
 */
double
signedArea (const Ring2d& ring);
} // namespace io
} // namespace pcl_ext
