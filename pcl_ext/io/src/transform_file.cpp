/*
 * pcl_ext: rigid / similarity transforms stored as text.
 */
#include <pcl_ext/io/transform_file.h>

#include "text_lines.h"

#include <cmath>
#include <vector>

void
pcl_ext::io::loadTransform (const std::string& path, Eigen::Matrix4d& transform)
{
  detail::TextLines lines (path);
  std::vector<double> numbers;
  std::vector<std::string_view> values;
  std::string_view line;
  while (lines.nextData (line, false)) {
    detail::splitValues (line, values);
    for (const auto& v : values) {
      double x = 0.0;
      if (!detail::parseDouble (v, x) || !std::isfinite (x))
        lines.fail (detail::quote (v) + " is not a finite number");
      numbers.push_back (x);
    }
  }
  if (numbers.empty())
    throw ReadError (path, 0, "empty file, no transform");
  if (numbers.size() != 16 && numbers.size() != 12)
    throw ReadError (path,
                     0,
                     "expected 16 numbers (4 x 4, row by row) or 12 (3 x 4), found " +
                         std::to_string (numbers.size()));
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (std::size_t i = 0; i < numbers.size(); ++i)
    m (static_cast<int> (i / 4), static_cast<int> (i % 4)) = numbers[i];
  if ((m.row (3) - Eigen::RowVector4d (0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9)
    throw ReadError (path, lines.lineNumber(), "the bottom row must be 0 0 0 1");
  transform = m;
}
