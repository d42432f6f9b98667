/*
 * pcl_ext: an app's result written next to the input's fields, in the input's frame.
 */
#include <pcl_ext/apps/input.h>
#include <pcl_ext/apps/output.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/file_output.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <cctype>
#include <iostream>

namespace pcl_ext {
namespace apps {
ResultField::ResultField (std::string default_name,
                          std::string what,
                          std::string asprs_note,
                          std::string refusal)
: name_ (std::move (default_name))
, what_ (std::move (what))
, asprs_note_ (std::move (asprs_note))
, refusal_ (std::move (refusal))
{}

void
ResultField::addTo (CommandLine& cl)
{
  cl.addOption ("output_field",
                name_,
                "field receiving the " + what_ +
                    " (LAS: an extra-bytes dimension); an input field of this name "
                    "is replaced only when named here");
  cl.addSwitch ("asprs",
                asprs_,
                asprs_note_.empty() ? "refused: " + refusal_
                                    : asprs_note_ + " (LAS output only)");
  cl_ = &cl;
}

void
ResultField::addTo (CommandLine& cl, std::string& input, std::string& output)
{
  cl.addPositional ("input", input, kInputFormats);
  cl.addPositional ("output", output, kOutputFormats);
  addTo (cl);
}

bool
ResultField::checkOutput (const std::string& output,
                          std::initializer_list<std::string> optional) const
{
  std::string reason;
  if (!io::canWritePointFile (output, &reason)) {
    std::cerr << "Error: " << reason << ".\n";
    return false;
  }
  if (asprs_ && asprs_note_.empty()) {
    std::cerr << "Error: -asprs: " << refusal_ << ".\n";
    return false;
  }
  if (asprs_ && io::fileExtension (output) != "las") {
    std::cerr << "Error: -asprs writes the LAS Classification; " << output
              << " is not a .las file.\n";
    return false;
  }
  if (name_.empty() || name_ == "x" || name_ == "y" || name_ == "z") {
    std::cerr << "Error: -output_field must name a field other than x, y, z.\n";
    return false;
  }
  return io::checkOutputsWritable (output, optional);
}

bool
ResultField::checkInput (const io::PointFile& input, const std::string& input_path)
{
  if (pcl::getFieldIndex (input.cloud, name_) < 0 ||
      (cl_ && cl_->given ("output_field")))
    return true;
  // Never over an input field the user did not name (a truth, a LAS dimension): the
  // result takes the first free name after it.
  std::string free_name;
  for (int suffix = 2; free_name.empty(); ++suffix) {
    const std::string candidate = name_ + "_" + std::to_string (suffix);
    if (pcl::getFieldIndex (input.cloud, candidate) < 0)
      free_name = candidate;
  }
  std::cout << "  " << input_path << " already has a field '" << name_
            << "' (kept): the " << what_ << " goes to '" << free_name
            << "' (-output_field names another, or this one to replace it)\n";
  name_ = free_name;
  return true;
}

bool
ResultField::attach (pcl::PCLPointCloud2& cloud,
                     const std::vector<std::uint32_t>& values) const
{
  if (!io::setLabelField (cloud, name_, values)) {
    std::cerr << "Error: " << values.size() << " results for "
              << std::size_t (cloud.width) * cloud.height << " points.\n";
    return false;
  }
  return true;
}

bool
ResultField::save (const std::string& path,
                   const io::PointFile& input,
                   const std::vector<std::uint32_t>& values) const
{
  pcl::PCLPointCloud2 output = input.cloud;
  return attach (output, values) && saveOutput (path, output, input);
}

bool
saveOutput (const std::string& path,
            const pcl::PCLPointCloud2& cloud,
            const io::PointFile& input)
{
  StageTimer timer ("Saving " + path);
  if (!io::savePointFile (path, cloud, input.origin, &input))
    return false;
  timer.done (std::size_t (cloud.width) * cloud.height);
  return true;
}

int
asprsClass (const std::string& name)
{
  std::string n = name;
  for (char& c : n)
    c = std::isalnum (static_cast<unsigned char> (c))
            ? static_cast<char> (std::tolower (static_cast<unsigned char> (c)))
            : ' ';
  const auto has = [&n] (const char* word) {
    return (" " + n + " ").find (std::string (" ") + word + " ") != std::string::npos;
  };
  if (has ("low") && has ("vegetation"))
    return 3;
  if (has ("medium") && has ("vegetation"))
    return 4;
  if (has ("vegetation") || has ("tree") || has ("trees"))
    return 5;
  if (has ("tower"))
    return 15;
  if (has ("wire") || has ("wires"))
    return 14;
  if (has ("building") || has ("facade") || has ("roof") || has ("wall"))
    return 6;
  if (has ("ground") || has ("terrain"))
    return 2;
  if (has ("noise"))
    return 7;
  if (has ("water"))
    return 9;
  if (has ("rail"))
    return 10;
  if (has ("road"))
    return 11;
  if (has ("bridge"))
    return 17;
  return -1;
}
ResultField
segmentIdField ()
{
  return ResultField ("segment",
                      "segment id",
                      "",
                      "segment ids are not classes; they go to the -output_field field "
                      "(LAS: an extra-bytes dimension)");
}
} // namespace apps
} // namespace pcl_ext
