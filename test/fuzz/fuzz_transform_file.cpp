/*
 * Fuzz target: pcl_ext::io::loadTransform (12 or 16 numbers, row by row).
 */
#include <pcl_ext/io/transform_file.h>

#include "fuzz_input_file.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  const Eigen::Matrix4d previous = Eigen::Matrix4d::Constant (42.0);
  Eigen::Matrix4d transform = previous;
  try {
    pcl_ext::io::loadTransform (file.write (data, size), transform);
  }
  catch (const pcl_ext::io::ReadError&) {
    pcl_ext_fuzz::check (transform == previous,
                         "the transform is untouched after a ReadError");
    return 0;
  }
  pcl_ext_fuzz::check (transform.allFinite(), "the transform is finite");
  pcl_ext_fuzz::check (
      (transform.row (3) - Eigen::RowVector4d (0, 0, 0, 1)).cwiseAbs().maxCoeff() <=
          1e-9,
      "the bottom row is 0 0 0 1");
  return 0;
}
