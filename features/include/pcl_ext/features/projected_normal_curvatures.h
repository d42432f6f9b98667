/*
 * pcl_ext: principal curvature directions from projected normals (Belton & Lichti 2006,
 * section 5).
 */
#pragma once

#include <pcl_ext/features/neighbourhood_feature.h>

#include <pcl/features/feature.h>
#include <pcl/point_types.h>

namespace pcl_ext {
/** \brief Principal directions of curvature from the normals of each point's
 * neighbourhood and their negative images (Belton & Lichti 2006, section 5).
 *
 * Every neighbour normal n_j and its negative -n_j are projected onto the tangent plane
 * of the index point (the plane normal to its own normal); the eigenvectors of the 2D
 * covariance of the projections, mapped back to 3D, are the directions of most and
 * least change of the normal, and the eigenvalues the amount of change. Output
 * compatible with pcl::PrincipalCurvaturesEstimation: pcl::PrincipalCurvatures with
 * principal_curvature_x/y/z the direction of MOST change (unit, in the tangent plane),
 * pc1 the larger and pc2 the smaller eigenvalue. The direction of least change (a
 * pipe's axis, an edge's direction) is normal x principal_curvature, which
 * pcl::PrincipalCurvatures has no field for.
 *
 * How it differs from pcl::PrincipalCurvaturesEstimation: PCL centres the projected
 * normals on their mean before the covariance. Here each projection comes with its
 * negative image, so the mean is zero by construction and the covariance is the
 * uncentred second moment (1/m) sum p_j p_j^T. This is what the paper needs for normals
 * from covariance analysis, whose signs are arbitrary: flipping any neighbour's normal
 * changes nothing, whereas PCL's result depends on the normals being consistently
 * oriented (on a cylinder whose normals are oriented outwards, PCL's centring also
 * removes the mean tilt, and its pc1, pc2 are variances about that mean rather than the
 * amount of change). Normals are normalised before projection.
 *
 * Inputs: the points, and normals (setInputNormals, one per point, any type with
 * normal_x/y/z, e.g. pcl::Normal or pcl_ext::CovarianceFeatures). Neighbourhoods:
 * setKSearch, setRadiusSearch or shared (setNeighbourhoods). Points whose own normal is
 * not finite, or with fewer than 3 finite neighbour normals, get NaN and make the
 * output not dense.
 */
template <typename PointInT,
          typename PointNT,
          typename PointOutT = pcl::PrincipalCurvatures>
class ProjectedNormalCurvaturesEstimation
: public NeighbourhoodFeatureFromNormals<PointInT, PointNT, PointOutT> {
  using Base = NeighbourhoodFeatureFromNormals<PointInT, PointNT, PointOutT>;

public:
  using Ptr = pcl::shared_ptr<
      ProjectedNormalCurvaturesEstimation<PointInT, PointNT, PointOutT>>;
  using ConstPtr = pcl::shared_ptr<
      const ProjectedNormalCurvaturesEstimation<PointInT, PointNT, PointOutT>>;
  using PointCloudOut = pcl::PointCloud<PointOutT>;

  ProjectedNormalCurvaturesEstimation()
  {
    this->feature_name_ = "ProjectedNormalCurvaturesEstimation";
  }

protected:
  using Base::indices_;
  using Base::input_;
  using Base::nb_;
  using Base::normals_;

  void
  computeFeature (PointCloudOut& output) override;

  /** \brief One point; false (NaN written) without enough finite normals. */
  bool
  computePoint (std::size_t row, PointOutT& out) const;

  static void
  setInvalid (PointOutT& out);
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/features/impl/projected_normal_curvatures.hpp>
#endif
