/*
 * CentroidOffsetTestOptions: the confidence level and size scaling of Belton & Lichti's
 * chi-squared centroid test (eq. 6), the threshold it gives, and the two classes that
 * share it.
 */
#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/features/centroid_offset_test_options.h>
#include <pcl_ext/features/chi_squared_boundary.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

namespace {
/** A class running the test: it reads the threshold. */
class Options : public pcl_ext::CentroidOffsetTestOptions {
public:
  using CentroidOffsetTestOptions::confidenceQuantile;
};

TEST (CentroidOffsetTestOptions, DefaultsAreNinetyFivePercentScaledBySize)
{
  const Options options;
  EXPECT_EQ (options.getConfidence(), 0.95);
  EXPECT_TRUE (options.getScaleByNeighbourhoodSize());
  // chi2 with 2 degrees of freedom: the quantile of p is -2 ln (1 - p).
  EXPECT_NEAR (options.confidenceQuantile(), 5.991, 1e-3);
}

TEST (CentroidOffsetTestOptions, QuantileFollowsTheConfidence)
{
  Options options;
  for (const double p : {0.5, 0.9, 0.99, 0.999}) {
    options.setConfidence (p);
    EXPECT_EQ (options.getConfidence(), p);
    EXPECT_NEAR (options.confidenceQuantile(), -2.0 * std::log (1.0 - p), 1e-9);
  }
  options.setScaleByNeighbourhoodSize (false);
  EXPECT_FALSE (options.getScaleByNeighbourhoodSize());
}

TEST (CentroidOffsetTestOptions, ConfidenceOutsideZeroToOneHasNoQuantile)
{
  Options options;
  for (const double p : {0.0, 1.0, -0.5, 2.0, std::nan ("")}) {
    options.setConfidence (p);
    EXPECT_TRUE (std::isnan (options.confidenceQuantile())) << p;
  }
}

TEST (CentroidOffsetTestOptions, BothClassesAreSetTheSameWay)
{
  pcl_ext::ChiSquaredBoundaryEstimation<pcl::PointXYZ, pcl::Boundary> boundary;
  pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classification;
  for (pcl_ext::CentroidOffsetTestOptions* options :
       {static_cast<pcl_ext::CentroidOffsetTestOptions*> (&boundary),
        static_cast<pcl_ext::CentroidOffsetTestOptions*> (&classification)}) {
    options->setConfidence (0.99);
    options->setScaleByNeighbourhoodSize (false);
  }
  EXPECT_EQ (boundary.getConfidence(), 0.99);
  EXPECT_EQ (classification.getConfidence(), 0.99);
  EXPECT_FALSE (boundary.getScaleByNeighbourhoodSize());
  EXPECT_FALSE (classification.getScaleByNeighbourhoodSize());
}
} // namespace
