/*
 * pcl_ext_convert: real-data point files to PCD or PLY, with class labels in `label`.
 *
 *   pcl_ext_convert input.(xyz|txt|csv|asc|xyz_label_conf|ply|pcd) output.(pcd|ply)
 *                   [-columns SPEC] [-classes FILE] [-origin auto|none|X,Y,Z]
 */
#include <pcl_ext/io/ascii_reader.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/point_table.h>
#include <pcl_ext/io/cloud_io.h>
#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/file_output.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {
/** The input's kind, from its name ("scan.xyz_label_conf" is Oakland 3-D). */
enum class InputKind { Ascii, Oakland, Cloud, Unknown };

InputKind
inputKind (const std::string& path)
{
  const std::string ext = pcl_ext::io::fileExtension (path);
  if (ext == "xyz_label_conf")
    return InputKind::Oakland;
  if (ext == "xyz" || ext == "txt" || ext == "csv" || ext == "asc" || ext == "pts")
    return InputKind::Ascii;
  if (ext == "pcd" || ext == "ply")
    return InputKind::Cloud;
  return InputKind::Unknown;
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
} // namespace

int
main (int argc, char** argv)
{
  std::string input, output, columns, classes_path, origin_text = "auto",
                                                    label_field = "label";
  bool ascii = false;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_convert",
      "Converts a point file to PCD or PLY, writing class labels into the uint32 field "
      "'label'.\n"
      "Inputs: ASCII points (.xyz .txt .csv .asc .pts: x y z plus optional intensity, "
      "colour and\n"
      "label columns, blank- or comma-separated), the Oakland 3-D format "
      "(.xyz_label_conf:\n"
      "x y z label confidence), PCD and PLY. Coordinates are read in double precision; "
      "for text\n"
      "input a local origin is subtracted before storing floats and printed, so that "
      "it can be\n"
      "added back. The output is written atomically; the input is never modified.");
  cl.addPositional ("input", input, "the point file to read");
  cl.addPositional ("output.(pcd|ply)", output, "the cloud to write");
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
  cl.addOption (
      "label_field", label_field, "field holding the labels to map, for PCD/PLY input");
  cl.addOption (
      "origin",
      origin_text,
      "for text input: 'auto' (per axis, the minimum rounded down to 100 m when some "
      "|coordinate| exceeds 8192 m, else 0), 'none', or X,Y,Z");
  cl.addSwitch (
      "ascii", ascii, "write ASCII PCD / PLY instead of binary (compressed PCD)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;

  const InputKind kind = inputKind (input);
  if (kind == InputKind::Unknown) {
    std::cerr << "pcl_ext_convert: error: cannot tell the format of " << input
              << " (expected .xyz .txt .csv .asc .pts .xyz_label_conf .ply or .pcd).\n";
    return 1;
  }
  const std::string out_ext = pcl_ext::io::fileExtension (output);
  if (out_ext != "pcd" && out_ext != "ply") {
    std::cerr << "pcl_ext_convert: error: output " << output
              << " must end in .pcd or .ply.\n";
    return 1;
  }
  if (kind == InputKind::Cloud && (cl.given ("columns") || cl.given ("origin"))) {
    std::cerr
        << "pcl_ext_convert: error: -columns and -origin apply to text input only.\n";
    return 1;
  }
  if (kind == InputKind::Oakland && cl.given ("columns")) {
    std::cerr << "pcl_ext_convert: error: the Oakland format has fixed columns; "
                 "-columns does not apply.\n";
    return 1;
  }
  if (kind != InputKind::Cloud && cl.given ("label_field")) {
    std::cerr
        << "pcl_ext_convert: error: -label_field applies to PCD/PLY input only.\n";
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

  pcl::PCLPointCloud2 cloud;
  if (kind == InputKind::Cloud) {
    pcl_ext::apps::StageTimer timer ("Loading " + input + " ...");
    if (!pcl_ext::io::loadCloud (input, cloud))
      return 1;
    timer.done (static_cast<std::size_t> (cloud.width) * cloud.height);
    if (!mapping.empty()) {
      std::vector<std::uint32_t> labels;
      std::string error;
      if (!pcl_ext::io::getLabelField (cloud, label_field, labels, &error)) {
        std::cerr << "Error: " << input << ": " << error << ".\n";
        return 1;
      }
      mapping.apply (labels);
      pcl_ext::io::setLabelField (cloud, "label", labels);
    }
  }
  else {
    pcl_ext::io::PointTable table;
    pcl_ext::apps::StageTimer timer ("Loading " + input + " ...");
    try {
      if (kind == InputKind::Oakland)
        pcl_ext::io::loadOaklandFile (input, table);
      else
        pcl_ext::io::loadAsciiPoints (input, table, columns);
    }
    catch (const pcl_ext::io::ReadError& e) {
      std::cout << std::endl;
      std::cerr << "Error: " << e.what() << "\n";
      return 1;
    }
    timer.done (table.size());
    if (!mapping.empty()) {
      if (table.label.empty()) {
        std::cerr << "Error: " << input << " has no label column to map with -classes"
                  << " (give one with -columns, e.g. x,y,z,label).\n";
        return 1;
      }
      mapping.apply (table.label);
    }
    if (auto_origin)
      origin = pcl_ext::io::computeLocalOrigin (table);
    if (!origin.isZero())
      std::cout << "Subtracted local origin (" << originText (origin)
                << "): add it back to get the file's coordinates.\n";
    pcl_ext::io::toPCLPointCloud2 (table, origin, cloud);
  }

  if (!mapping.empty()) {
    std::vector<std::uint32_t> labels;
    pcl_ext::io::getLabelField (cloud, "label", labels);
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
  }

  pcl_ext::apps::StageTimer timer ("Writing " + output + " ...");
  if (!pcl_ext::io::saveCloud (output, cloud, ascii))
    return 1;
  timer.done (static_cast<std::size_t> (cloud.width) * cloud.height);
  return 0;
}
