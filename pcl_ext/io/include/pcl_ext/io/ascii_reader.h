/*
 * pcl_ext: ASCII point files (x y z plus optional intensity, colour and label columns).
 */
#pragma once

#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/read_error.h>

#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief What one column of an ASCII point file holds. */
enum class AsciiColumn {
  X,
  Y,
  Z,         ///< coordinates (required, each once)
  Intensity, ///< intensity, any real number
  Red,
  Green,
  Blue,  ///< colour channels, numbers in [0, 255] (rounded)
  Label, ///< label / class id: a non-negative integer (written as 3 or 3.0)
  Skip   ///< a column to ignore (only its presence is checked)
};

/** \brief Parse a column spec: names separated by commas (or spaces), case-insensitive.
 *
 * Names: x, y, z; i or intensity; r or red, g or green, b or blue; label, l, class or
 * classification;
 * skip, _ or - for a column to ignore. Example: "x,y,z,i,r,g,b,label", or
 * "x,y,z,label,_" for the Oakland 3-D files. \throw std::invalid_argument naming the
 * offending entry, when a name is unknown, x, y or z is missing, or a name other than
 * skip occurs twice
 */
std::vector<AsciiColumn>
parseColumnSpec (const std::string& spec);

/** \brief The columns assumed for a file with \a count columns when no spec is given:
 * 3 = x y z; 4 = x y z i; 6 = x y z r g b; 7 = x y z i r g b; 8 = x y z i r g b label.
 * Any other count returns an empty vector (the caller must give a spec). */
std::vector<AsciiColumn>
defaultColumns (std::size_t count);

/** \brief Read an ASCII point file: one point a line, values separated by whitespace or
 * by commas (a line containing a comma is split at commas, surrounding blanks ignored).
 *
 * Empty lines and lines starting with '#' or "//" are skipped. Before the first point,
 * a line none of whose values is a number is a header line and is skipped; when no
 * column spec is given, the first header line naming x, y and z (a plain line such as
 * PDAL's `"X","Y","Z","Intensity"`, or a comment starting with x y z such as
 * CloudCompare's
 * `//X,Y,Z,R,G,B,Intensity`) gives the columns: names in any case, quotes ignored,
 * x y z, r / red, g / green, b / blue, i / intensity, label / class / classification;
 * other names are skipped columns (as are r g b unless all three are named). Without
 * spec or header, defaultColumns chooses from the first point line; 7 columns are x y
 * z r g b i (CloudCompare's default export order) when columns 4-6 of the first 1000
 * points are all integers in [0, 255] and column 7 is not, else x y z i r g b (Leica
 * PTS order). Numbers are read locale-independently ("1.5", "-2e3"); coordinates must
 * be finite. Every data line must have exactly as many values as there are columns.
 * \param[in] path the file \param[out] table the points; untouched when an exception is
 * thrown \param[in] columns the column spec (see parseColumnSpec); empty (default)
 * reads the header or chooses as above
 * \throw ReadError naming the file (and line) when it cannot be opened, has no point,
 * has a line with a wrong number of values or a value that is not a valid number, or
 * when \a columns is invalid
 */
void
loadAsciiPoints (const std::string& path,
                 PointTable& table,
                 const std::string& columns = "");

/** \brief Read the Oakland 3-D format: `x y z label confidence` per line, '#' comments.
 *
 * Munoz et al. (CVPR 2009). The label is the fine Oakland label id (1001 ... 1501,
 * 9999); map it to coarse classes with ClassMapping. The confidence column must be
 * present but is not kept. \throw ReadError as loadAsciiPoints
 */
void
loadOaklandFile (const std::string& path, PointTable& table);
} // namespace io
} // namespace pcl_ext
