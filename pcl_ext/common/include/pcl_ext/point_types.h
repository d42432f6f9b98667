/*
 * pcl_ext: point types and class labels shared by every module.
 */
#pragma once

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>

namespace pcl_ext {
/** \brief Point classes used across pcl_ext (Belton & Lichti 2006, section 2).
 *
 * Stored in a pcl::Label's \c label field. \c Unknown is 0 so that it doubles as the
 * "ignore" label of the evaluation metrics.
 */
enum class PointClass : std::uint32_t {
  Unknown = 0, ///< no valid neighbourhood, or not classified
  Surface = 1, ///< on a smooth surface
  Edge = 2,    ///< near a crease between two surfaces
  Boundary = 3 ///< near an open border (a hole or a free edge)
};

/** \brief Number of PointClass values, Unknown included. */
constexpr std::size_t kNumPointClasses = 4;

/** \brief Lower-case name of a class ("unknown", "surface", "edge", "boundary"). */
inline const char*
pointClassName (PointClass c)
{
  switch (c) {
  case PointClass::Surface:
    return "surface";
  case PointClass::Edge:
    return "edge";
  case PointClass::Boundary:
    return "boundary";
  default:
    return "unknown";
  }
}

/** \brief Ascending eigenvalues, normal and eigen features of a local neighbourhood.
 *
 * Written by the covariance feature estimators. Fields follow pcl::Normal's layout for
 * the normal, so pcl::copyPointCloud to a normal cloud works field by field.
 */
struct EIGEN_ALIGN16 CovarianceFeatures {
  PCL_ADD_NORMAL4D;       // normal_x, normal_y, normal_z: eigenvector of the smallest
                          // eigenvalue
  float lambda0;          ///< smallest eigenvalue
  float lambda1;          ///< middle eigenvalue
  float lambda2;          ///< largest eigenvalue
  float surface_variance; ///< l0 / (l0 + l1 + l2), Belton & Lichti eq. 4
  float linearity;        ///< (l2 - l1) / l2
  float planarity;        ///< (l1 - l0) / l2
  float scattering;       ///< l0 / l2
  float omnivariance;     ///< cbrt(e0 e1 e2), e_i = l_i / sum
  float anisotropy;       ///< (l2 - l0) / l2
  float eigenentropy;     ///< -sum e_i ln e_i
  float verticality;      ///< 1 - |n_z|
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Variance of curvature of a neighbourhood (Belton & Lichti 2006, eq. 5).
 *
 * Written by pcl_ext::CurvatureVarianceEstimation. NaN when the point has no valid
 * neighbourhood.
 */
struct CurvatureVariance {
  float curvature_variance =
      0.f; ///< var(kappa) over the k neighbours, kappa from eq. 4
};
} // namespace pcl_ext

POINT_CLOUD_REGISTER_POINT_STRUCT (
    pcl_ext::CovarianceFeatures,
    (float, normal_x, normal_x) (float, normal_y, normal_y) (
        float, normal_z, normal_z) (float, lambda0, lambda0) (float, lambda1, lambda1) (
        float, lambda2, lambda2) (float, surface_variance, surface_variance) (
        float, linearity, linearity) (float, planarity, planarity) (
        float, scattering, scattering) (float, omnivariance, omnivariance) (
        float, anisotropy, anisotropy) (float,
                                        eigenentropy,
                                        eigenentropy) (float, verticality, verticality))

POINT_CLOUD_REGISTER_POINT_STRUCT (pcl_ext::CurvatureVariance,
                                   (float, curvature_variance, curvature_variance))
