/*
 * pcl_ext: LocalVarianceClassification implementation.
 */
#pragma once

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/common/indices.h>
#include <pcl_ext/common/noise_sample.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/features/local_variance.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>

template <typename PointT>
bool
pcl_ext::LocalVarianceClassification<PointT>::checkParameters() const
{
  const char* const name = "[pcl_ext::LocalVarianceClassification::classify]";
  if ((tests_ & ALL_TESTS) == 0 ||
      (tests_ & ~static_cast<unsigned int> (ALL_TESTS)) != 0) {
    PCL_ERROR (
        "%s tests = %u; give a non-empty combination of CURVATURE_TEST, VARIANCE_TEST "
        "and BOUNDARY_TEST.\n",
        name,
        tests_);
    return false;
  }
  if (!(curvature_threshold_ >= 0.0) || !std::isfinite (curvature_threshold_)) {
    PCL_ERROR (
        "%s curvature threshold = %g; it must be finite and >= 0 (0: derived).\n",
        name,
        curvature_threshold_);
    return false;
  }
  if (!(curvature_factor_ >= 0.0) || !std::isfinite (curvature_factor_)) {
    PCL_ERROR ("%s curvature threshold factor = %g; it must be finite and >= 0 (0: "
               "chosen from the cloud).\n",
               name,
               curvature_factor_);
    return false;
  }
  if (!(variance_threshold_ >= 0.0) || !std::isfinite (variance_threshold_)) {
    PCL_ERROR ("%s variance threshold = %g; it must be finite and >= 0.\n",
               name,
               variance_threshold_);
    return false;
  }
  if (!(noise_sigma_ >= 0.0) || !std::isfinite (noise_sigma_)) {
    PCL_ERROR ("%s noise standard deviation = %g; it must be finite and >= 0.\n",
               name,
               noise_sigma_);
    return false;
  }
  if (!(boundary_band_fraction_ > 0.0 && boundary_band_fraction_ <= 1.0)) {
    PCL_ERROR ("%s boundary band fraction = %g; it must lie in (0, 1].\n",
               name,
               boundary_band_fraction_);
    return false;
  }
  if (!(crease_angle_ >= 0.0 && crease_angle_ <= 0.5 * M_PI)) {
    PCL_ERROR ("%s crease angle = %g; it must lie between 0 and pi/2 (0: off).\n",
               name,
               crease_angle_);
    return false;
  }
  if ((tests_ & BOUNDARY_TEST) && !std::isfinite (confidenceQuantile())) {
    PCL_ERROR ("%s confidence = %g; it must lie strictly between 0 and 1.\n",
               name,
               confidence_);
    return false;
  }
  return this->checkNeighbourhoodOptions (name, static_cast<int> (kMinNeighbours));
}

template <typename PointT>
template <bool dense>
void
pcl_ext::LocalVarianceClassification<PointT>::computeCovariances (
    const Neighbourhoods<PointT>& nb)
{
  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size());
  const bool boundary = (tests_ & BOUNDARY_TEST) != 0;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const double noise_variance = noise_sigma_used_ * noise_sigma_used_;
#pragma omp parallel for num_threads(resolveThreadCount(threads_))                     \
    schedule(dynamic, 256) default(none)                                               \
        shared(nb, rows, boundary, nan, noise_variance)
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    const pcl::index_t idx = (*indices_)[r];
    const PointT& p = (*input_)[idx];
    // The dense loop skips this check: a non-finite point has an empty row anyway.
    if (!dense && !pcl::isFinite (p)) {
      statistic_[r] = nan;
      continue;
    }
    const auto nn = nb[static_cast<std::size_t> (r)];
    LocalCovariance local;
    if (!computeNeighbourhoodCovariance (*input_, nn.begin(), nn.end(), local)) {
      statistic_[r] = nan;
      continue;
    }
    // The noise floor of l0 (setNoiseStandardDeviation); 0 leaves eq. 4 as printed.
    Eigen::Vector3d values = local.eigen.values;
    values[0] = std::max (values[0] - noise_variance, 0.0);
    kappa_[idx] = static_cast<float> (surfaceVariance (values));
    if (!normals_.empty())
      normals_[idx] = local.eigen.vectors.col (0).template cast<float>();
    statistic_[r] = boundary ? static_cast<float> (centroidOffsetStatistic (
                                   Eigen::Vector3d (p.x, p.y, p.z),
                                   local,
                                   scale_by_size_,
                                   noise_variance))
                             : 0.f;
  }
}

template <typename PointT>
template <bool dense>
void
pcl_ext::LocalVarianceClassification<PointT>::sampleNeighbourhoods (
    const Neighbourhoods<PointT>& nb)
{
  // The rows of the points of smallest position key (a few thousand neighbourhoods
  // fix the medians well; the covariances are computed again in pass 1): the sample
  // does not depend on the order of the points, and the tiles of a cloud give it.
  const std::size_t rows = indices_->size();
  const auto keyOf = [this] (std::size_t r, std::uint64_t& key) {
    const PointT& p = (*input_)[(*indices_)[r]];
    if (!dense && !pcl::isFinite (p))
      return false;
    key = noiseSampleKeyOf (p.x, p.y, p.z);
    return true;
  };
  NoiseSampleCut cut;
  std::uint64_t key = 0;
  for (std::size_t r = 0; r < rows; ++r)
    if (keyOf (r, key))
      cut.add (key);
  std::vector<KeyedSpread> sample;
  std::vector<std::size_t> sample_rows;
  for (std::size_t r = 0; r < rows && !cut.empty(); ++r)
    if (keyOf (r, key) && key <= cut.get()) {
      sample.emplace_back();
      sample.back().key = key;
      sample_rows.push_back (r);
    }
  const std::ptrdiff_t samples = static_cast<std::ptrdiff_t> (sample.size());
#pragma omp parallel for num_threads(resolveThreadCount(threads_))                     \
    schedule(dynamic, 256) default(none) shared(nb, samples, sample, sample_rows)
  for (std::ptrdiff_t i = 0; i < samples; ++i) {
    const auto nn = nb[sample_rows[static_cast<std::size_t> (i)]];
    LocalCovariance local;
    if (!computeNeighbourhoodCovariance (*input_, nn.begin(), nn.end(), local))
      continue; // unusable: zero eigenvalues and size, still counted in the cut
    auto& spread = sample[static_cast<std::size_t> (i)].spread;
    spread.values = local.eigen.values;
    spread.size = local.size;
  }
  noise_sample_ = std::move (sample);
}

template <typename PointT>
void
pcl_ext::LocalVarianceClassification<PointT>::removeEstimatedNoise()
{
  noise_sigma_used_ = noiseSigmaRemovedFor (noise_estimate_);
  if (!noise_estimate_.valid)
    PCL_WARN ("[pcl_ext::LocalVarianceClassification::classify] The noise cannot be "
              "estimated: %s; none is removed (the paper's eq. 4-6).\n",
              noise_estimate_.reason.c_str());
  else if (noise_sigma_used_ == 0.0)
    // Noise near the spacing (a range camera, not a scanner): the few-centimetre
    // neighbourhoods that see a crease see it through the noise, and removing the noise
    // from l0 removes the crease with it.
    PCL_DEBUG ("[pcl_ext::LocalVarianceClassification::classify] Estimated noise sigma "
               "%g is above %g point spacings (%g): none removed.\n",
               noise_estimate_.sigma,
               kMaxNoiseToSpacing,
               noise_estimate_.spacing);
  else
    PCL_DEBUG ("[pcl_ext::LocalVarianceClassification::classify] Estimated noise sigma "
               "%g, point spacing %g (from %zu neighbourhoods).\n",
               noise_estimate_.sigma,
               noise_estimate_.spacing,
               noise_estimate_.used);
}

template <typename PointT>
double
pcl_ext::LocalVarianceClassification<PointT>::deriveCurvatureThreshold() const
{
  const double median =
      sampleCurvatureMedian (noise_sample_, noise_sigma_used_ * noise_sigma_used_);
  return std::isfinite (median) ? curvature_factor_used_ * median : 0.0;
}

template <typename PointT>
template <typename Row>
float
pcl_ext::LocalVarianceClassification<PointT>::widestNormalCosine (
    const Row& nn, const Eigen::Vector3f& own) const
{
  // Normals are unoriented: |cos|. First the neighbour normal farthest from the point's
  // own, then the one farthest from that: the two ends of the spread (exact for normals
  // along one arc, as across a crease or around a pipe).
  float farthest = 1.f;
  Eigen::Vector3f end = own;
  for (const auto j : nn)
    if (std::isfinite (kappa_[j])) {
      const float c = std::abs (own.dot (normals_[j]));
      if (c < farthest) {
        farthest = c;
        end = normals_[j];
      }
    }
  float widest = farthest;
  for (const auto j : nn)
    if (std::isfinite (kappa_[j]))
      widest = std::min (widest, std::abs (end.dot (normals_[j])));
  return widest;
}

template <typename PointT>
void
pcl_ext::LocalVarianceClassification<PointT>::label (
    const Neighbourhoods<PointT>& nb, pcl::PointCloud<pcl::Label>& labels) const
{
  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (indices_->size());
  const bool curvature = (tests_ & CURVATURE_TEST) != 0;
  const bool variance = (tests_ & VARIANCE_TEST) != 0;
  const bool boundary = (tests_ & BOUNDARY_TEST) != 0;
  const double threshold = curvature_threshold_used_;
  const double quantile = boundary ? confidenceQuantile() : 0.0;
  const float* const kappa = kappa_.data();
  const float min_cosine = static_cast<float> (std::cos (crease_angle_));
#pragma omp parallel for num_threads(resolveThreadCount(threads_))                     \
    schedule(dynamic, 1024) default(none) shared(nb,                                   \
                                                 labels,                               \
                                                 rows,                                 \
                                                 curvature,                            \
                                                 variance,                             \
                                                 boundary,                             \
                                                 threshold,                            \
                                                 quantile,                             \
                                                 kappa,                                \
                                                 min_cosine)
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    auto& out = labels[r].label;
    const float k = kappa[(*indices_)[r]];
    if (!std::isfinite (k)) {
      out = static_cast<std::uint32_t> (PointClass::Unknown);
      continue;
    }
    bool edge = false;
    const bool curved = k > threshold;
    if (curvature && !variance)
      edge = curved;
    else if (variance && (!curvature || curved)) {
      // Section 2.2: only points the curvature test calls edges are re-checked by
      // eq. 5.
      const auto nn = nb[static_cast<std::size_t> (r)];
      std::size_t count = 0;
      const double var = curvatureVariance (
          nn.begin(), nn.end(), [kappa] (pcl::index_t j) { return kappa[j]; }, count);
      if (!std::isfinite (var)) {
        out = static_cast<std::uint32_t> (PointClass::Unknown);
        continue;
      }
      edge = var > variance_threshold_;
      // setCreaseAngle: an edge must bend the normals across its neighbourhood. The
      // widest angle between two of its normals, found from the normal farthest from
      // the point's own (on a crease the point's own normal is a blend of the two
      // faces', so the angle to it can be half the crease's).
      if (edge && !normals_.empty())
        edge = widestNormalCosine (nn, normals_[(*indices_)[r]]) < min_cosine;
    }
    if (edge)
      out = static_cast<std::uint32_t> (PointClass::Edge);
    else if (boundary && statistic_[r] > quantile)
      out = static_cast<std::uint32_t> (PointClass::Boundary);
    else
      out = static_cast<std::uint32_t> (PointClass::Surface);
  }
}

template <typename PointT>
void
pcl_ext::LocalVarianceClassification<PointT>::widenBoundaries (
    const Neighbourhoods<PointT>& nb, pcl::PointCloud<pcl::Label>& labels) const
{
  const auto boundary = static_cast<std::uint32_t> (PointClass::Boundary);
  const auto surface = static_cast<std::uint32_t> (PointClass::Surface);
  // The labels of pass 2 by cloud index (neighbours outside the indices have none),
  // read-only below, so the result does not depend on the order the rows are visited
  // in.
  std::vector<std::uint8_t> seed (input_->size(), 0);
  for (std::size_t r = 0; r < labels.size(); ++r)
    seed[(*indices_)[r]] = labels[r].label == boundary;
  const std::ptrdiff_t rows = static_cast<std::ptrdiff_t> (labels.size());
  const double fraction = boundary_band_fraction_;
#pragma omp parallel for num_threads(resolveThreadCount(threads_))                     \
    schedule(dynamic, 1024) default(none)                                              \
        shared(nb, labels, rows, seed, boundary, surface, fraction)
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    if (labels[r].label != surface)
      continue;
    const auto nn = nb[static_cast<std::size_t> (r)];
    // Rows are closest first: the band reaches through the nearest share of each.
    const auto reach = static_cast<std::size_t> (std::ceil (fraction * nn.size()));
    for (std::size_t n = 0; n < reach; ++n)
      if (seed[nn.begin()[n]]) {
        labels[r].label = boundary;
        break;
      }
  }
}

template <typename PointT>
void
pcl_ext::LocalVarianceClassification<PointT>::classify (
    pcl::PointCloud<pcl::Label>& labels)
{
  labels.clear();
  labels.width = labels.height = 0;
  if (!initCompute()) {
    PCL_ERROR ("[pcl_ext::LocalVarianceClassification::classify] No input cloud.\n");
    return;
  }
  if (input_->empty()) {
    PCL_ERROR (
        "[pcl_ext::LocalVarianceClassification::classify] The input cloud is empty.\n");
    deinitCompute();
    return;
  }
  if (!checkParameters()) {
    deinitCompute();
    return;
  }
  const Neighbourhoods<PointT>* nb =
      this->prepareNeighbourhoods ("LocalVarianceClassification::classify",
                                   input_,
                                   fake_indices_ ? pcl::IndicesConstPtr() : indices_);
  if (!nb) {
    deinitCompute();
    return;
  }

  kappa_.assign (input_->size(), std::numeric_limits<float>::quiet_NaN());
  statistic_.resize (indices_->size());
  // Normals only where the crease check needs them (every point whose kappa is
  // computed).
  if (crease_angle_ > 0.0 && (tests_ & VARIANCE_TEST))
    normals_.assign (input_->size(), Eigen::Vector3f::Zero());
  else
    normals_.clear();
  noise_estimate_ = NoiseEstimate();
  noise_sigma_used_ = noise_sigma_;
  const bool threshold_derived =
      (tests_ & CURVATURE_TEST) && curvature_threshold_ == 0.0;
  noise_sample_.clear();
  if (estimate_noise_ || threshold_derived) {
    if (input_->is_dense)
      sampleNeighbourhoods<true> (*nb);
    else
      sampleNeighbourhoods<false> (*nb);
  }
  if (estimate_noise_ || (threshold_derived && curvature_factor_ == 0.0))
    noise_estimate_ = estimateNoiseFromSample (noise_sample_);
  if (estimate_noise_)
    removeEstimatedNoise();
  curvature_factor_used_ = !threshold_derived ? 0.0
                           : curvature_factor_ > 0.0
                               ? curvature_factor_
                               : curvatureFactorFor (noise_estimate_);
  if (input_->is_dense)
    computeCovariances<true> (*nb);
  else
    computeCovariances<false> (*nb);
  curvature_threshold_used_ = curvature_threshold_;
  if ((tests_ & CURVATURE_TEST) && curvature_threshold_ == 0.0)
    curvature_threshold_used_ = deriveCurvatureThreshold();

  labels.resize (indices_->size());
  if (fake_indices_ && input_->height > 1 &&
      input_->width * input_->height == labels.size()) {
    labels.width = input_->width;
    labels.height = input_->height;
  }
  noise_sample_.clear();
  noise_sample_.shrink_to_fit();
  label (*nb, labels);
  normals_.clear();
  normals_.shrink_to_fit();
  if (boundary_band_ && (tests_ & BOUNDARY_TEST))
    widenBoundaries (*nb, labels);
  labels.header = input_->header;
  labels.is_dense = true;
  this->releaseNeighbourhoods();
  deinitCompute();
}

template <typename PointT>
void
pcl_ext::LocalVarianceClassification<PointT>::extract (
    std::vector<pcl::PointIndices>& clusters)
{
  clusters.clear();
  pcl::PointCloud<pcl::Label> labels;
  classify (labels);
  if (labels.empty())
    return;
  // classify() released the indices; the labels are in the order of getIndices().
  const auto indices = this->getIndices();
  groupByClass (
      labels,
      indices.get(),
      kNumPointClasses,
      [] (std::uint32_t label) {
        return std::min<std::size_t> (label, kNumPointClasses - 1);
      },
      input_->header,
      clusters);
}

#define PCL_EXT_INSTANTIATE_LocalVarianceClassification(T)                             \
  template class pcl_ext::LocalVarianceClassification<T>;
