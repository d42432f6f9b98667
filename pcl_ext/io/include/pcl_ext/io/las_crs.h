/*
 * pcl_ext: the coordinate reference system a LAS file declares, to compare files.
 */
#pragma once

#include <pcl_ext/io/las_header.h>

#include <string>

namespace pcl_ext {
namespace io {
/** \brief The coordinate reference system (CRS) a LAS / LAZ file declares in its
 * LASF_Projection records (LAS 1.4 R15, section 2.5.1: OGC WKT, record 2112, or the
 * GeoTIFF keys, records 34735-34737), reduced to what two files can be compared by.
 *
 * The CRS's EPSG code where the file gives one: the authority of the WKT's outermost
 * CRS (WKT 1 `AUTHORITY["EPSG","28992"]` or WKT 2 `ID["EPSG",28992]`), or the GeoTIFF
 * ProjectedCSTypeGeoKey (3072), else its GeographicTypeGeoKey (2048). Otherwise the
 * name of the WKT's outermost CRS (programs spell the rest of one CRS differently:
 * "GRS 1980" or "GRS_1980", 298.257222101 or 298.2572221010002), or the GeoTIFF
 * records' bytes. See matchCoordinateSystems. */
struct LasCoordinateSystem {
  enum class Kind { None, Epsg, Wkt, GeoTiff, Text };
  Kind kind = Kind::None;
  std::string value; ///< the EPSG code, the WKT's CRS name, the records' bytes or the
                     ///< text

  /** \brief Whether the file declares a CRS. */
  bool
  declared () const
  {
    return kind != Kind::None;
  }

  bool
  operator== (const LasCoordinateSystem& other) const
  {
    return kind == other.kind && value == other.value;
  }

  bool
  operator!= (const LasCoordinateSystem& other) const
  {
    return !(*this == other);
  }

  /** \brief For messages: "EPSG:28992", "the CRS named "Amersfoort / RD New"", "a
   * user-defined GeoTIFF CRS", "the CRS described as "..."" or "no CRS". */
  std::string
  describe () const;
};

/** \brief What two declared CRSs tell of each other. */
enum class CrsMatch {
  Same,      ///< one EPSG code, one WKT name or the same GeoTIFF records
  Different, ///< two EPSG codes, or two WKT CRSs of two names
  Unknown    ///< either declares none, or they cannot be compared (an EPSG code and a
             ///< WKT without one, GeoTIFF definitions or free texts written
             ///< differently)
};

/** \brief Whether \a a and \b b are one CRS, as far as the files tell. */
CrsMatch
matchCoordinateSystems (const LasCoordinateSystem& a, const LasCoordinateSystem& b);

/** \brief The CRS a text declares, such as an E57 file's coordinateMetadata (ASTM
 * E2807 section 8.4.1: "information describing the coordinate reference system", OGC
 * WKT by common use): "EPSG:n" or "urn:ogc:def:crs:EPSG::n" give the code; WKT 1 or 2
 * is read as a LAS file's record 2112 is; any other text is Kind Text (the same text is
 * the same CRS, another cannot be told apart). Kind None for an empty text. */
LasCoordinateSystem
textCoordinateSystem (const std::string& text);

/** \brief The CRS \a info declares (in its VLRs or EVLRs; the WKT first when a file has
 * both). Kind None when it declares none or its records are too short to read. */
LasCoordinateSystem
lasCoordinateSystem (const LasFileInfo& info);
} // namespace io
} // namespace pcl_ext
