/*
 * pcl_ext: the part every pcl_ext feature estimator shares: shared neighbourhoods and
 * threads, and for those that read normals, the normals' check.
 */
#pragma once

#include <pcl_ext/common/parallel.h>
#include <pcl_ext/search/neighbourhood_options.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/features/feature.h>

#include <cstddef>
#include <string>

namespace pcl_ext {
/** \brief A pcl::Feature (or pcl::FeatureFromNormals, as \a FeatureBase) whose
 * neighbourhoods come from a pcl_ext::Neighbourhoods: shared through
 * setNeighbourhoods(), or searched once per compute() with the k or radius set as for
 * any PCL feature (default search: pcl_ext::search::NanoflannKdTree; setSearchMethod()
 * replaces it).
 *
 * Departs from pcl::Feature in two ways: no FLANN tree is built when it is not needed,
 * and a search surface other than the input (setSearchSurface) is not supported
 * (PCL_ERROR).
 */
template <typename FeatureBase, typename PointInT>
class NeighbourhoodFeature : public FeatureBase,
                             public SharedNeighbourhoodsOption<PointInT> {
public:
  using NeighbourhoodsConstPtr = typename Neighbourhoods<PointInT>::ConstPtr;

protected:
  using SharedNeighbourhoodsOption<PointInT>::threads_;
  using SharedNeighbourhoodsOption<PointInT>::source_;
  using FeatureBase::fake_indices_;
  using FeatureBase::fake_surface_;
  using FeatureBase::feature_name_;
  using FeatureBase::indices_;
  using FeatureBase::input_;
  using FeatureBase::k_;
  using FeatureBase::search_radius_;
  using FeatureBase::surface_;
  using FeatureBase::tree_;

  /** \brief Checks of the subclass's own inputs (normals, parameters), before any
   * search. */
  virtual bool
  checkInputs ()
  {
    return true;
  }

  bool
  initCompute () override
  {
    nb_ = nullptr;
    if (!pcl::PCLBase<PointInT>::initCompute()) {
      PCL_ERROR ("[pcl_ext::%s::compute] No input cloud.\n", feature_name_.c_str());
      return false;
    }
    if (input_->empty()) {
      PCL_ERROR ("[pcl_ext::%s::compute] The input cloud is empty.\n",
                 feature_name_.c_str());
      pcl::PCLBase<PointInT>::deinitCompute();
      return false;
    }
    if (surface_ && surface_ != input_) {
      PCL_ERROR (
          "[pcl_ext::%s::compute] A search surface other than the input cloud is not "
          "supported.\n",
          feature_name_.c_str());
      pcl::PCLBase<PointInT>::deinitCompute();
      return false;
    }
    if (!surface_) {
      fake_surface_ = true;
      surface_ = input_;
    }
    if (!checkInputs()) {
      deinitCompute();
      return false;
    }
    nb_ = source_.prepare (feature_name_ + "::compute",
                           input_,
                           fake_indices_ ? pcl::IndicesConstPtr() : indices_,
                           k_,
                           search_radius_,
                           tree_,
                           threads_);
    if (!nb_) {
      deinitCompute();
      return false;
    }
    return true;
  }

  bool
  deinitCompute () override
  {
    source_.release();
    return FeatureBase::deinitCompute();
  }

  /** \brief PCL_ERROR unless \a normals holds one normal per input point (the normals
   * of a FeatureFromNormals-style estimator are indexed like the input cloud). */
  template <typename NormalCloudConstPtr>
  bool
  checkNormals (const NormalCloudConstPtr& normals) const
  {
    if (!normals) {
      PCL_ERROR ("[pcl_ext::%s::compute] No normals (setInputNormals).\n",
                 feature_name_.c_str());
      return false;
    }
    if (normals->size() != input_->size()) {
      PCL_ERROR (
          "[pcl_ext::%s::compute] %zu normals for %zu points; one per input point is "
          "needed.\n",
          feature_name_.c_str(),
          normals->size(),
          input_->size());
      return false;
    }
    return true;
  }

  /** \brief The per-point loop of every estimator: \a compute_row (r, output[r]) for
   * each row r of nb_, in parallel (dynamic chunks of \a chunk rows), and \a
   * set_invalid (output[r]) for rows whose index point is not finite. Returns whether
   * every row succeeded, i.e. the output's is_dense. Two loops as in PCL: a dense input
   * skips the finite check (a non-finite point has an empty row and fails compute_row
   * anyway, only later). */
  template <typename PointOutT, typename ComputeRow, typename SetInvalid>
  bool
  computeRows (pcl::PointCloud<PointOutT>& output,
               int chunk,
               const ComputeRow& compute_row,
               const SetInvalid& set_invalid) const
  {
    const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size());
    const int threads = static_cast<int> (threadCount());
    bool dense = true;
    if (input_->is_dense) {
#pragma omp parallel for num_threads(threads) schedule(dynamic, chunk) reduction(&& : dense)
      for (std::ptrdiff_t r = 0; r < rows; ++r)
        dense = compute_row (static_cast<std::size_t> (r), output[r]) && dense;
    }
    else {
#pragma omp parallel for num_threads(threads) schedule(dynamic, chunk) reduction(&& : dense)
      for (std::ptrdiff_t r = 0; r < rows; ++r) {
        if (!pcl::isFinite ((*input_)[(*indices_)[r]])) {
          set_invalid (output[r]);
          dense = false;
          continue;
        }
        dense = compute_row (static_cast<std::size_t> (r), output[r]) && dense;
      }
    }
    return dense;
  }

  /** \brief Threads to use, 0 resolved to all cores. */
  unsigned int
  threadCount () const
  {
    return resolveThreadCount (threads_);
  }

  /** \brief The neighbourhoods of the current compute(); row r belongs to
   * (*indices_)[r]. */
  const Neighbourhoods<PointInT>* nb_ = nullptr;
};

/** \brief A NeighbourhoodFeature on pcl::FeatureFromNormals: the normals given with
 * setInputNormals() are checked (checkNormals: one per input point) before any search.
 *
 * The base of the estimators that read a normal per neighbour, as PCL's estimators
 * derive from pcl::FeatureFromNormals. A subclass with inputs of its own to check
 * overrides checkInputs() and calls this one first.
 */
template <typename PointInT, typename PointNT, typename PointOutT>
class NeighbourhoodFeatureFromNormals
: public NeighbourhoodFeature<pcl::FeatureFromNormals<PointInT, PointNT, PointOutT>,
                              PointInT> {
protected:
  using pcl::FeatureFromNormals<PointInT, PointNT, PointOutT>::normals_;

  bool
  checkInputs () override
  {
    return this->checkNormals (normals_);
  }
};
} // namespace pcl_ext
