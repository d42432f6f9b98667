/*
 * pcl_ext: edge points narrowed to the crease they lie on.
 */
#pragma once

#include <pcl_ext/search/neighbourhood_options.h>

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstddef>

namespace pcl_ext {
/** \brief Keeps as edges only the edge points within a point spacing of the crease
 * their neighbourhood spans; the others become surface points.
 *
 * Belton & Lichti (2006, section 2.2, eq. 4-5) call a point an edge when its
 * neighbourhood reaches across a crease: with k = 50 that is a band about two
 * neighbourhood radii wide, eight or more point spacings, along every crease. A user
 * comparing the classes with creases (or with a truth that marks the points within a
 * spacing of one) sees most of those edges as false. This step goes beyond the paper,
 * in the spirit of its section 4 (eq. 9-17, local planes intersected): for each edge
 * point it fits the two faces of the crease in its neighbourhood and measures its
 * distance to their line of intersection.
 *
 * - The faces: each neighbour's normal is fitted to its nearest few points only
 *   (setNormalK), so that away from the crease it is the normal of its own face. The
 *   two normals of the neighbourhood furthest apart give two planes through their
 *   points (if they are less than setMinCreaseAngle apart there is no crease); every
 *   point of the neighbourhood is given to the nearer plane and the planes refitted,
 *   up to three times.
 * - A crease: the planes make at least the minimum angle, each fits its points
 *   within setMaxResidual times the neighbourhood's nearest-neighbour spacing or
 *   setNoiseFactor times the local noise (the median RMS residual of the neighbours'
 *   patches), whichever is larger, and the neighbourhood's cross-section has a kink at
 *   their line: the section's height over the distance across the line fits two lines
 *   meeting there (c0 + c1 x + c2 |x|) better than a smooth bend (c0 + c1 x + c2 x^2),
 *   with c2 beyond setKinkSignificance standard errors. The curved side of a narrow
 *   pipe, whose normals turn by more than the minimum angle within a neighbourhood,
 *   fits two planes too; its section is a bend, not a kink. Where the noise is as large
 *   as the spacing (a scanner's near field), faces fit their planes only within the
 *   noise, and the kink's significance keeps the noise from making creases.
 * - On it: the point lies within setBandWidth times the point spacing of the line of
 *   intersection, the spacing sqrt(pi r^2 / k) of the point's neighbourhood of k
 *   points within radius r.
 *
 * An edge point on a crease stays an edge; one too far from the crease its
 * neighbourhood spans becomes a surface point. Without a crease, it becomes a surface
 * point where the patches around it are flat (a smooth curved surface, which eq. 5 can
 * still call an edge where the curvature changes) and stays an edge among scattered
 * points (vegetation, clutter: setMaxPatchCurvature), as the paper calls them. Surface,
 * boundary and unknown points are kept as they are. The rows of the neighbourhoods must
 * be sorted, closest first (the default search); shared ones (setNeighbourhoods) are
 * the classifier's. Deterministic, whatever the number of threads.
 *
 * \code
 * pcl_ext::EdgeLocalisation<pcl::PointXYZ> edges;
 * edges.setInputCloud (cloud);
 * edges.setNeighbourhoods (nb);          // those LocalVarianceClassification used
 * edges.setPointClasses (classes);       // its classify() output
 * pcl::PointCloud<pcl::Label> narrowed;
 * edges.localise (narrowed);
 * \endcode
 */
template <typename PointT>
class EdgeLocalisation : public pcl::PCLBase<PointT>,
                         public NeighbourhoodOptions<PointT> {
public:
  using Ptr = pcl::shared_ptr<EdgeLocalisation<PointT>>;
  using ConstPtr = pcl::shared_ptr<const EdgeLocalisation<PointT>>;
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = LabelCloud::ConstPtr;

  /** \brief What localise() did. */
  struct Report {
    std::size_t examined = 0;  ///< indexed edge points with a neighbourhood
    std::size_t kept = 0;      ///< edges on a crease
    std::size_t scattered = 0; ///< edges among scattered points, kept
    std::size_t surface = 0;   ///< edges that became surface points
  };

  EdgeLocalisation() = default;

  /** \brief The class of every point of the input cloud (pcl_ext::PointClass values,
   * as LocalVarianceClassification::classify gives them). */
  void
  setPointClasses (const LabelCloudConstPtr& classes)
  {
    classes_ = classes;
  }

  LabelCloudConstPtr
  getPointClasses () const
  {
    return classes_;
  }

  /** \brief Neighbours (the point included) each normal is fitted to (default 12; at
   * least 3, fewer where a row is shorter). */
  void
  setNormalK (int k)
  {
    normal_k_ = k;
  }

  int
  getNormalK () const
  {
    return normal_k_;
  }

  /** \brief Largest median surface variance (eq. 4) of the neighbours' normal patches
   * for an edge point without a crease to become a surface point (default 0.15): a
   * smooth surface has flat patches at the scale of a few spacings, scattered points
   * (vegetation, clutter) have not, and stay edges. */
  void
  setMaxPatchCurvature (double curvature)
  {
    max_patch_curvature_ = curvature;
  }

  double
  getMaxPatchCurvature () const
  {
    return max_patch_curvature_;
  }

  /** \brief Smallest angle between the two faces of a crease, in radians (default 30
   * degrees). */
  void
  setMinCreaseAngle (double radians)
  {
    min_angle_ = radians;
  }

  double
  getMinCreaseAngle () const
  {
    return min_angle_;
  }

  /** \brief Largest root mean square distance of a face's points from its plane, as a
   * multiple of the median distance from the neighbourhood's points to their nearest
   * neighbour (default 0.4). */
  void
  setMaxResidual (double ratio)
  {
    max_residual_ = ratio;
  }

  double
  getMaxResidual () const
  {
    return max_residual_;
  }

  /** \brief Faces may fit their planes within this multiple of the local noise
   * (the median RMS residual of the neighbours' normal patches) where that exceeds the
   * spacing-based limit (setMaxResidual); default 3, 0: the spacing-based limit alone.
   */
  void
  setNoiseFactor (double factor)
  {
    noise_factor_ = factor;
  }

  double
  getNoiseFactor () const
  {
    return noise_factor_;
  }

  /** \brief Standard errors by which the kink of a crease's cross-section must exceed
   * zero (default 3; 0: the kink need only fit better than a smooth bend). */
  void
  setKinkSignificance (double standard_errors)
  {
    kink_significance_ = standard_errors;
  }

  double
  getKinkSignificance () const
  {
    return kink_significance_;
  }

  /** \brief Half-width of the band kept along a crease, as a multiple of the point
   * spacing (default 1). */
  void
  setBandWidth (double spacings)
  {
    band_width_ = spacings;
  }

  double
  getBandWidth () const
  {
    return band_width_;
  }

  /** \brief Narrow the edges. \a output gets one label per input point: its class, or
   * surface for an edge point off its crease. On bad input: PCL_ERROR, empty output,
   * false. */
  bool
  localise (LabelCloud& output);

  const Report&
  getReport () const
  {
    return report_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  bool
  checkInputs (const char* name) const;

  LabelCloudConstPtr classes_;
  int normal_k_ = 12;
  double max_patch_curvature_ = 0.15;
  double min_angle_ = 30.0 * M_PI / 180.0;
  double max_residual_ = 0.4;
  double noise_factor_ = 3.0;
  double kink_significance_ = 3.0;
  double band_width_ = 1.0;
  Report report_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/classification/impl/edge_localisation.hpp>
#endif
