/*
 * pcl_ext_convert: any point file the tools read to LAS, PCD or PLY, with class labels
 * in `label`.
 *
 *   pcl_ext_convert input output.(las|pcd|ply) [-columns SPEC] [-classes FILE]
 *                   [-label_field NAME] [-origin auto|none|X,Y,Z] [-ascii]
 */
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/io/point_file.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/file_output.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {
/** How the input is read: text files through the point table (their columns, labels
 * and origin are the tool's options), every other format through io::loadPointFile. */
enum class InputKind { Ascii, Oakland, PointFile };

InputKind
inputKind (const std::string& path)
{
  // The Oakland 3-D format is plain ASCII to the content check: its extension tells it.
  if (pcl_ext::io::fileExtension (path) == "xyz_label_conf")
    return InputKind::Oakland;
  // A missing or unreadable file goes to loadPointFile, whose error names it.
  if (pcl_ext::io::detectPointFileFormat (path) == pcl_ext::io::PointFileFormat::ASCII)
    return InputKind::Ascii;
  return InputKind::PointFile;
}

/** "X,Y,Z" to a vector; false on anything else. */
bool
parseOrigin (const std::string& text, Eigen::Vector3d& origin)
{
  double v[3];
  char tail;
  if (std::sscanf (text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3)
    return false;
  origin = Eigen::Vector3d (v[0], v[1], v[2]);
  return origin.allFinite();
}

bool
samePath (const std::string& a, const std::string& b)
{
  char ra[PATH_MAX], rb[PATH_MAX];
  if (::realpath (a.c_str(), ra) && ::realpath (b.c_str(), rb))
    return std::string (ra) == rb;
  return a == b;
}

std::string
originText (const Eigen::Vector3d& o)
{
  char buffer[128];
  std::snprintf (buffer, sizeof (buffer), "%.3f, %.3f, %.3f", o.x(), o.y(), o.z());
  return buffer;
}

/** Map the labels of \a field with \a mapping into the
 * uint32 field 'label' of \a cloud and print the classes' counts. */
bool
mapLabels (const pcl_ext::io::ClassMapping& mapping,
           const std::string& classes_path,
           const std::string& input,
           const std::string& field,
           pcl::PCLPointCloud2& cloud)
{
  std::vector<std::uint32_t> labels;
  std::string error;
  if (!pcl_ext::io::getLabelField (cloud, field, labels, &error)) {
    std::cerr << "Error: " << input << ": " << error << ".\n";
    return false;
  }
  mapping.apply (labels);
  pcl_ext::io::setLabelField (cloud, "label", labels);
  std::size_t ignored = 0;
  for (const auto l : labels)
    ignored += l == 0;
  std::cout << "Mapped labels with " << classes_path << ": " << ignored << " of "
            << labels.size() << " points ignored (class 0).\n";
  for (const auto& [id, name] : mapping.names()) {
    std::size_t n = 0;
    for (const auto l : labels)
      n += l == id;
    std::cout << "  " << id << " " << name << ": " << n << "\n";
  }
  return true;
}
} // namespace

int
main (int argc, char** argv)
{
  std::string input, output, columns, classes_path, origin_text = "auto",
                                                    label_field = "label";
  bool ascii = false;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_convert",
      "Converts a point file to LAS, PCD or PLY, every field kept, class labels mapped "
      "with\n"
      "-classes into the uint32 field 'label'.\n"
      "Inputs: LAS, LAZ (COPC too), E57, PTX, PTS, PCD, PLY (told by content), ASCII "
      "points\n"
      "(x y z plus optional intensity, colour and label columns, blank- or "
      "comma-separated) and\n"
      "the Oakland 3-D format (.xyz_label_conf: x y z label confidence).\n"
      "Outputs by extension: .las (the input's header when it is LAS / LAZ, else LAS "
      "1.4 at 1 mm\n"
      "with the local origin as offset), .pcd, .ply. Coordinates are kept in double "
      "precision:\n"
      "a georeferenced LAS / LAZ / E57 / PTX / PTS / PCD / PLY input gives FLOAT64 x y "
      "z in PCD\n"
      "and PLY; for text input a local origin is subtracted before storing floats and "
      "printed,\n"
      "so that it can be added back (a LAS output stores it as its offset). The output "
      "is\n"
      "written atomically; the input is never modified.");
  cl.addPositional ("input", input, "the point file to read");
  cl.addPositional ("output.(las|pcd|ply)", output, "the file to write");
  cl.addOption (
      "columns",
      columns,
      "column spec of a text input, e.g. x,y,z,i,r,g,b,label (names: x y z i r g b "
      "label skip); none: guessed from 3, 4, 6, 7 or 8 columns");
  cl.addOption ("classes",
                classes_path,
                "class mapping file ('<id> <name> : <source labels>' lines): maps the "
                "labels read "
                "to class ids, unlisted labels to 0 (ignore)");
  cl.addOption ("label_field",
                label_field,
                "field holding the labels to map, for input other than text (e.g. "
                "classification of LAS)");
  cl.addOption (
      "origin",
      origin_text,
      "for text input: 'auto' (per axis, the minimum rounded down to 100 m when some "
      "|coordinate| exceeds 8192 m, else 0), 'none', or X,Y,Z");
  cl.addSwitch (
      "ascii", ascii, "write ASCII PCD / PLY instead of binary (compressed PCD)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;

  // Everything that can be refused is refused before the input is read.
  std::string reason;
  if (!pcl_ext::io::canWritePointFile (output, &reason)) {
    std::cerr << "pcl_ext_convert: error: " << reason << ".\n";
    return 1;
  }
  const bool las_output = pcl_ext::io::fileExtension (output) == "las";
  if (las_output && ascii) {
    std::cerr << "pcl_ext_convert: error: -ascii applies to PCD / PLY output only.\n";
    return 1;
  }
  const InputKind kind = inputKind (input);
  const bool text = kind != InputKind::PointFile;
  if (!text && (cl.given ("columns") || cl.given ("origin"))) {
    std::cerr
        << "pcl_ext_convert: error: -columns and -origin apply to text input only.\n";
    return 1;
  }
  if (kind == InputKind::Oakland && cl.given ("columns")) {
    std::cerr << "pcl_ext_convert: error: the Oakland format has fixed columns; "
                 "-columns does not apply.\n";
    return 1;
  }
  if (text && cl.given ("label_field")) {
    std::cerr << "pcl_ext_convert: error: -label_field applies to input other than "
                 "text only (text labels are the 'label' column).\n";
    return 1;
  }
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  const bool auto_origin = origin_text == "auto";
  if (!auto_origin && origin_text != "none" && !parseOrigin (origin_text, origin)) {
    std::cerr << "pcl_ext_convert: error: invalid -origin '" << origin_text
              << "' (expected auto, none or X,Y,Z).\n";
    return 1;
  }
  if (!columns.empty()) {
    try {
      pcl_ext::io::parseColumnSpec (columns);
    }
    catch (const std::invalid_argument& e) {
      std::cerr << "pcl_ext_convert: error: " << e.what() << ".\n";
      return 1;
    }
  }
  if (samePath (input, output)) {
    std::cerr << "pcl_ext_convert: error: the output would overwrite the input "
              << input << ".\n";
    return 1;
  }
  if (!pcl_ext::io::checkWritable (output))
    return 1;

  pcl_ext::io::ClassMapping mapping;
  try {
    if (!classes_path.empty())
      mapping.load (classes_path);
  }
  catch (const pcl_ext::io::ReadError& e) {
    std::cerr << "Error: " << e.what() << "\n";
    return 1;
  }

  // The input: its cloud (coordinates relative to the origin) and, read through
  // loadPointFile, the file's header and frame for the output.
  pcl_ext::io::PointFile file;
  {
    pcl_ext::apps::StageTimer timer ("Loading " + input + " ...");
    try {
      if (!text)
        pcl_ext::io::loadPointFile (input, file);
      else {
        pcl_ext::io::PointTable table;
        if (kind == InputKind::Oakland)
          pcl_ext::io::loadOaklandFile (input, table);
        else
          pcl_ext::io::loadAsciiPoints (input, table, columns);
        if (!mapping.empty() && table.label.empty()) {
          std::cout << std::endl;
          std::cerr << "Error: " << input << " has no label column to map with -classes"
                    << " (give one with -columns, e.g. x,y,z,label).\n";
          return 1;
        }
        if (auto_origin)
          origin = pcl_ext::io::computeLocalOrigin (table);
        pcl_ext::io::toPCLPointCloud2 (table, origin, file.cloud);
        file.origin = origin;
      }
    }
    catch (const pcl_ext::io::ReadError& e) {
      std::cout << std::endl;
      std::cerr << "Error: " << e.what() << "\n";
      return 1;
    }
    timer.done (static_cast<std::size_t> (file.cloud.width) * file.cloud.height);
  }
  if (!text)
    std::cout << "  " << pcl_ext::io::formatName (file.format)
              << (file.origin.isZero() ? std::string()
                                       : ", local origin " + originText (file.origin) +
                                             " (kept in the output's coordinates)")
              << "\n";
  else if (!file.origin.isZero())
    std::cout << (las_output ? "Local origin (" : "Subtracted local origin (")
              << originText (file.origin)
              << (las_output ? "): the LAS offset.\n"
                             : "): add it back to get the file's coordinates.\n");

  if (!mapping.empty() &&
      !mapLabels (
          mapping, classes_path, input, text ? "label" : label_field, file.cloud))
    return 1;

  pcl_ext::apps::StageTimer timer ("Writing " + output + " ...");
  bool written;
  if (text && !las_output) // local floats, as the -origin help says
    written = pcl_ext::io::saveCloud (output, file.cloud, ascii);
  else
    written = pcl_ext::io::savePointFile (
        output, file.cloud, file.origin, text ? nullptr : &file, ascii);
  if (!written)
    return 1;
  timer.done (static_cast<std::size_t> (file.cloud.width) * file.cloud.height);
  return 0;
}
