/*
 * pcl_ext: Lim & Suter's multi-scale CRF classifier as a PCL class.
 */
#pragma once

#include <pcl_ext/classification/crf_model.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_types.h>

#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
/** \brief Multi-scale conditional random field classification over adaptive
 * super-voxels (Lim & Suter, "Multi-scale conditional random fields for over-segmented
 * irregular 3D point clouds classification", CVPR workshops 2008, sections 3-4).
 *
 * A thin PCL wrapper over MultiscaleCrfModel (see there for the model, the training
 * approximation and where pcl_ext departs from the text): train() on labelled clouds,
 * or loadModel(); then setInputCloud() (and setIndices()) and classify() or extract().
 * Colour is used when PointT has rgb, intensity when it has an intensity field.
 *
 * \code
 * pcl_ext::MultiscaleCrfClassification<pcl::PointXYZRGB> crf;
 * crf.setMode (pcl_ext::CrfMode::MultiscaleCrf);
 * crf.train ({training_cloud}, {training_labels});
 * crf.setInputCloud (cloud);
 * pcl::PointCloud<pcl::Label> labels;
 * crf.classify (labels);
 * \endcode
 */
template <typename PointT>
class MultiscaleCrfClassification : public pcl::PCLBase<PointT> {
public:
  using Ptr = pcl::shared_ptr<MultiscaleCrfClassification<PointT>>;
  using ConstPtr = pcl::shared_ptr<const MultiscaleCrfClassification<PointT>>;
  using PointCloudConstPtr = typename pcl::PointCloud<PointT>::ConstPtr;

  /** \brief Node-only, local CRF or multi-scale CRF (section 5's comparison). Default
   * MultiscaleCrf. Takes effect at train(); a loaded model brings its own. */
  void
  setMode (CrfMode mode)
  {
    changeSettings ([&] (CrfSettings& s) { s.mode = mode; });
  }

  CrfMode
  getMode () const
  {
    return model_.getSettings().mode;
  }

  /** \brief sigma_C of the Gaussian prior (eq. 9). Default 1; > 0. */
  void
  setSigma (double sigma)
  {
    changeSettings ([&] (CrfSettings& s) { s.sigma = sigma; });
  }

  double
  getSigma () const
  {
    return model_.getSettings().sigma;
  }

  /** \brief The inputs of the node potentials' logistic regression (pcl_ext addition,
   * see CrfNodeExpansion). Default Linear (the paper's). Takes effect at train(); a
   * loaded model brings its own. */
  void
  setNodeExpansion (CrfNodeExpansion expansion)
  {
    changeSettings ([&] (CrfSettings& s) { s.node_expansion = expansion; });
  }

  CrfNodeExpansion
  getNodeExpansion () const
  {
    return model_.getSettings().node_expansion;
  }

  /** \brief K, the hinges per feature of the spline expansions. Default 2; in [1, 64].
   */
  void
  setSplineKnots (int knots)
  {
    changeSettings ([&] (CrfSettings& s) { s.spline_knots = knots; });
  }

  int
  getSplineKnots () const
  {
    return model_.getSettings().spline_knots;
  }

  /** \brief beta, the factor on the log edge potentials in belief propagation (pcl_ext
   * addition, see MultiscaleCrfModel). Default 0: fitted on the training data; else >
   * 0. Takes effect at train(). */
  void
  setEdgeScale (double beta)
  {
    changeSettings ([&] (CrfSettings& s) { s.edge_scale = beta; });
  }

  double
  getEdgeScale () const
  {
    return model_.getSettings().edge_scale;
  }

  /** \brief m, local edges per super-voxel (paper: 4). Default 4; >= 0. */
  void
  setNumberOfLocalEdges (int m)
  {
    changeSettings ([&] (CrfSettings& s) { s.local_edges = m; });
  }

  int
  getNumberOfLocalEdges () const
  {
    return model_.getSettings().local_edges;
  }

  /** \brief l, regional edges per super-voxel (paper: 4). Default 4; >= 0. */
  void
  setNumberOfRegionalEdges (int l)
  {
    changeSettings ([&] (CrfSettings& s) { s.supervoxels.adjacency = l; });
  }

  int
  getNumberOfRegionalEdges () const
  {
    return model_.getSettings().supervoxels.adjacency;
  }

  /** \brief Super-voxel radius parameters (eq. 1-4; see AdaptiveRadiusParameters).
   * Default: defaultCrfSupervoxelParameters ().radius (the paper's, with min_radius 0.5
   * m). */
  void
  setRadiusParameters (const AdaptiveRadiusParameters& p)
  {
    changeSettings ([&] (CrfSettings& s) { s.supervoxels.radius = p; });
  }

  const AdaptiveRadiusParameters&
  getRadiusParameters () const
  {
    return model_.getSettings().supervoxels.radius;
  }

  /** \brief Seed of the super-voxel mid-points and of the local points. Default 1. */
  void
  setSeed (std::uint64_t seed)
  {
    changeSettings ([&] (CrfSettings& s) { s.supervoxels.seed = seed; });
  }

  std::uint64_t
  getSeed () const
  {
    return model_.getSettings().supervoxels.seed;
  }

  /** \brief Fixed radii (m, ascending, > 0) of the multi-scale features (pcl_ext
   * addition, see computeSaliencyFeatures), e.g. defaultFeatureScales(): 0.5, 1 and 2
   * m. Default empty: the paper's single-scale feature set. Takes effect at train(); a
   * loaded model brings its own. */
  void
  setFeatureScales (const std::vector<float>& radii)
  {
    changeSettings ([&] (CrfSettings& s) { s.features.scales = radii; });
  }

  const std::vector<float>&
  getFeatureScales () const
  {
    return model_.getSettings().features.scales;
  }

  /** \brief The scanner's up axis (eq. 10 and height). Default (0, 0, 1). */
  void
  setUpAxis (const Eigen::Vector3f& up)
  {
    changeSettings ([&] (CrfSettings& s) { s.features.up = up; });
  }

  const Eigen::Vector3f&
  getUpAxis () const
  {
    return model_.getSettings().features.up;
  }

  /** \brief Threads (0, the default: all cores); results do not depend on it. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    changeSettings ([&] (CrfSettings& s) { s.threads = threads; });
  }

  unsigned int
  getNumberOfThreads () const
  {
    return model_.getSettings().threads;
  }

  /** \brief Names of the classes by id; each must have training points. Default: the
   * non-zero labels found, named by their id. */
  void
  setClassNames (const std::map<std::uint32_t, std::string>& names)
  {
    model_.setClassNames (names);
  }

  /** \brief Train on labelled clouds (labels[c][i]: class id of point i of cloud c, 0 =
   * unlabelled). \return false (model unchanged) on bad input */
  bool
  train (const std::vector<PointCloudConstPtr>& clouds,
         const std::vector<std::vector<std::uint32_t>>& labels);

  /** \brief One label (class id) per index; empty on error. */
  void
  classify (pcl::PointCloud<pcl::Label>& labels);

  /** \brief One PointIndices per class, in getClassLabels() order. */
  void
  extract (std::vector<pcl::PointIndices>& classes);

  /** \brief Per-index class probabilities of the last classify() (eq. 11), columns in
   * getClassLabels() order. */
  const Eigen::MatrixXf&
  getProbabilities () const
  {
    return probabilities_;
  }

  const std::vector<std::uint32_t>&
  getClassLabels () const
  {
    return model_.getClassLabels();
  }

  bool
  saveModel (const std::string& path) const
  {
    return model_.saveModel (path);
  }

  bool
  loadModel (const std::string& path)
  {
    return model_.loadModel (path);
  }

  MultiscaleCrfModel&
  getModel ()
  {
    return model_;
  }

protected:
  /** \brief Apply \a change to a copy of the model's settings and give them back. */
  template <typename Change>
  void
  changeSettings (const Change& change)
  {
    CrfSettings settings = model_.getSettings();
    change (settings);
    model_.setSettings (settings);
  }

  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** xyz of the indexed points (others NaN), normalised colour and intensity. */
  static CrfInput
  makeInput (const pcl::PointCloud<PointT>& cloud, const pcl::Indices* indices);

  MultiscaleCrfModel model_;
  Eigen::MatrixXf probabilities_;
};
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/classification/impl/multiscale_crf_classification.hpp>
#endif
