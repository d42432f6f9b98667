/*
 * The rows of the bad-input matrix for the neighbourhoods and the features.
 */
#include "bad_input.h"

#include <pcl_ext/features/chi_squared_boundary.h>
#include <pcl_ext/features/covariance_features.h>
#include <pcl_ext/features/curvature_variance.h>
#include <pcl_ext/features/projected_normal_curvatures.h>
#include <pcl_ext/features/saliency_feature_estimation.h>
#include <pcl_ext/search/neighbourhoods.h>

#include <Eigen/Core>

namespace pcl_ext {
namespace test {
namespace bad_input {
void
addFeatureSubjects (std::vector<Subject>& s)
{
  const auto k_based = with (kCloudInputs, {Bad::KLargerThanCloud});
  const auto with_normals =
      with (k_based, {Bad::MissingNormals, Bad::WrongSizeNormals});

  s.push_back ({"Neighbourhoods",
                k_based,
                {{Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
                  Neighbourhoods<Point> nb;
                  nb.setInputCloud (in.cloud);
                  if (in.indices)
                    nb.setIndices (in.indices);
                  nb.setNumberOfThreads (2);
                  if (in.nan_param)
                    nb.setRadiusSearch (std::numeric_limits<double>::quiet_NaN());
                  else
                    nb.setKSearch (in.param ? static_cast<int> (*in.param) : in.k);
                  Outcome o;
                  o.produced = nb.compute() && nb.size() > 0;
                  if (o.produced) {
                    o.size = nb.size();
                    for (std::size_t r = 0; r < nb.size(); ++r)
                      o.no_result.push_back (nb[r].empty() ? 1 : 0);
                  }
                  return o;
                }});

  s.push_back ({"CovarianceFeatureEstimation", k_based, {}, [] (const Input& in) {
                  CovarianceFeatureEstimation<Point> est;
                  setCommon (est, in);
                  setNeighbourhood (est, in);
                  pcl::PointCloud<CovarianceFeatures> out;
                  est.compute (out);
                  return perPoint (out, [] (const CovarianceFeatures& f) {
                    return isNaN (f.surface_variance);
                  });
                }});

  s.push_back ({"CurvatureVarianceEstimation", with_normals, {}, [] (const Input& in) {
                  CurvatureVarianceEstimation<Point, pcl::Normal> est;
                  setCommon (est, in);
                  setNeighbourhood (est, in);
                  if (in.normals)
                    est.setInputNormals (in.normals);
                  pcl::PointCloud<CurvatureVariance> out;
                  est.compute (out);
                  return perPoint (out, [] (const CurvatureVariance& f) {
                    return isNaN (f.curvature_variance);
                  });
                }});

  // Boundaries: non-finite and degenerate points are documented as "not a boundary"
  // (0), so "no result" is 0 and a result is any point found to be a boundary.
  s.push_back (
      {"ChiSquaredBoundaryEstimation",
       k_based,
       {{Bad::Coplanar, Expect::Computed}, {Bad::DuplicatePoints, Expect::Computed}},
       [] (const Input& in) {
         ChiSquaredBoundaryEstimation<Point> est;
         setCommon (est, in);
         setNeighbourhood (est, in);
         pcl::PointCloud<pcl::Boundary> out;
         est.compute (out);
         return perPoint (
             out, [] (const pcl::Boundary& b) { return b.boundary_point == 0; });
       }});

  s.push_back (
      {"ProjectedNormalCurvaturesEstimation", with_normals, {}, [] (const Input& in) {
         ProjectedNormalCurvaturesEstimation<Point, pcl::Normal> est;
         setCommon (est, in);
         setNeighbourhood (est, in);
         if (in.normals)
           est.setInputNormals (in.normals);
         pcl::PointCloud<pcl::PrincipalCurvatures> out;
         est.compute (out);
         return perPoint (
             out, [] (const pcl::PrincipalCurvatures& c) { return isNaN (c.pc1); });
       }});

  // Radius-based; a non-finite indexed point is an error (documented).
  s.push_back ({"SaliencyFeatureEstimation",
                kCloudInputs,
                {{Bad::SomeNaNDense, Expect::Refused},
                 {Bad::SomeNaNNotDense, Expect::Refused},
                 {Bad::OnePoint, Expect::Computed},
                 {Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
                  SaliencyFeatureEstimation<Point> est;
                  est.setInputCloud (in.cloud);
                  if (in.indices)
                    est.setIndices (in.indices);
                  est.setNumberOfThreads (2);
                  float r = static_cast<float> (
                      0.3 * in.scale); // about 4 spacings of the cube
                  if (in.param)
                    r = static_cast<float> (*in.param);
                  if (in.nan_param)
                    r = kNaN;
                  est.setRadius (r);
                  Eigen::MatrixXf f;
                  est.compute (f);
                  Outcome o;
                  o.produced = f.rows() > 0;
                  o.size = static_cast<std::size_t> (f.rows());
                  for (Eigen::Index i = 0; i < f.rows(); ++i)
                    o.no_result.push_back (f.row (i).allFinite() ? 0 : 1);
                  return o;
                }});
}
} // namespace bad_input
} // namespace test
} // namespace pcl_ext
