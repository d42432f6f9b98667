/*
 * The row of the bad-input matrix for the local variance classification.
 */
#include "bad_input.h"

#include <pcl_ext/classification/local_variance_classification.h>

namespace pcl_ext {
namespace test {
namespace bad_input {
void
addClassificationSubjects (std::vector<Subject>& s)
{
  s.push_back ({"LocalVarianceClassification",
                with (kCloudInputs, {Bad::KLargerThanCloud}),
                {},
                [] (const Input& in) {
                  LocalVarianceClassification<Point> c;
                  c.setInputCloud (in.cloud);
                  if (in.indices)
                    c.setIndices (in.indices);
                  c.setNumberOfThreads (2);
                  if (in.nan_param)
                    c.setRadiusSearch (std::numeric_limits<double>::quiet_NaN());
                  else
                    c.setKSearch (in.param ? static_cast<int> (*in.param) : in.k);
                  pcl::PointCloud<pcl::Label> labels;
                  c.classify (labels);
                  return perPoint (labels,
                                   [] (const pcl::Label& l) { return l.label == 0; });
                }});
}
} // namespace bad_input
} // namespace test
} // namespace pcl_ext
