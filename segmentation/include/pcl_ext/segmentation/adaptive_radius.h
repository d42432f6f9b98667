/*
 * pcl_ext: the adaptive neighbourhood radius of Lim & Suter's super-voxels (eq. 1-4).
 */
#pragma once

#include <pcl_ext/search/kdtree_3f.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <vector>

namespace pcl_ext {
/** \brief Parameters of the adaptive radius (Lim & Suter 2008, section 3.1, eq. 1-4).
 *
 * The radius follows Mitra, Nguyen & Guibas' optimal neighbourhood size, shrunk by the
 * colour variance. The printed eq. 1-4 are garbled; this is how pcl_ext reads them:
 * r_new = (1 - damp) r + damp [ (1 / kappa) (c1 sigma / sqrt(eps rho) + c2 sigma^2)
 * ]^(1/3) (1 - w max(var R, var G, var B)), rho = k / (pi r^2), kappa = 2 d / mu^2, k =
 * pi rho r^2.
 *
 * The paper gives no values for c1, c2 and eps. On a noisy plane d is of the order of
 * sigma, so kappa ~ 2 sigma / mu^2 with mu ~ 0.6 r, and eq. 3 settles where k ~ pi
 * (0.18 c1)^2 / eps, whatever sigma: the defaults (c1 = 4, eps = 0.01) put that above
 * the k threshold, so flat regions grow to it (the large super-voxels on building and
 * terrain of figure 6a) while curvature, scatter and colour variance shrink the others.
 */
struct AdaptiveRadiusParameters {
  int initial_k = 15;      ///< k at the first step (paper: 15); >= 3
  double damping = 0.2;    ///< damp (paper: 0.2); in (0, 1]
  int max_iterations = 10; ///< at most this many steps (paper: 10); >= 1
  int max_k = 60; ///< stop when k = pi rho r^2 passes this threshold; > initial_k
  double saturation =
      0.5;            ///< stop when k changes by less than this ("k saturates"); >= 0
  double noise = 0.0; ///< sigma, the noise constant (m); 0 = estimate from the cloud
  double c1 = 4.0;    ///< c1 (Mitra et al.'s constant); > 0
  double c2 = 1.0;    ///< c2 (Mitra et al.'s constant); >= 0
  double epsilon = 0.01; ///< eps, "a very small number"; in (0, 1]
  double colour_weight =
      1.0; ///< w, weight of the colour factor (paper: 1); in [0, 1 / max var]
  double min_radius = 0.0; ///< lower bound on r (m); >= 0
  double max_radius = std::numeric_limits<double>::infinity(); ///< upper bound on r (m)
};

/** \brief Checks the parameters; PCL_ERROR naming \a caller and false when one is
 * invalid. */
bool
checkAdaptiveRadiusParameters (const AdaptiveRadiusParameters& parameters,
                               const char* caller);

/** \brief Mean distance of points to their least-squares plane: Lim & Suter's way of
 * estimating the noise constant sigma from points acquired from a single plane.
 * \return NaN when fewer than 3 finite points are given */
double
estimateNoiseFromPlanarPatch (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                              const std::vector<pcl::index_t>& patch);

/** \brief What one sampled neighbourhood tells of the noise (see
 * AdaptiveRadiusEstimator::estimateNoise). */
struct NoiseSample {
  float flatness = 0.f; ///< lambda_0 / (lambda_0 + lambda_1 + lambda_2)
  float rms = 0.f;      ///< sqrt (lambda_0), the residual off the neighbourhood's plane
  float spacing = 0.f;  ///< distance to the neighbourhood's farthest point
};

/** \brief The number of neighbourhoods AdaptiveRadiusEstimator::estimateNoise samples.
 */
constexpr std::size_t kNoiseSamples = 512;

/** \brief The order in which points are sampled for the noise: the kNoiseSamples
 * finite points of smallest key (ties by index) are the sample. A hash of the position,
 * so that the sample of a cloud cut into parts is the parts' samples merged (the
 * kNoiseSamples smallest keys of all of them). */
std::uint64_t
noiseSampleKey (const pcl::PointXYZ& point);

/** \brief The noise constant from the samples of kNoiseSamples neighbourhoods (those
 * whose neighbourhood had no plane left out): the median residual of the flattest 10 %,
 * or, when that is 0 (a cloud without noise, on which every radius would collapse), 1 %
 * of the median spacing. 0 when \a samples is empty. */
double
noiseFromSamples (std::vector<NoiseSample> samples);

/** \brief The adaptive radius of any point of a cloud, with the k-d tree built once.
 *
 * Not templated on the point type: the classes that use it copy xyz and normalised
 * colour out of their input. estimate() is const and thread-safe.
 */
class AdaptiveRadiusEstimator {
public:
  /** \brief Build the search structure over the finite points of \a cloud.
   * \param[in] colours normalised RGB (r, g, b) / (r + g + b) per point, or empty
   * \return false when there are fewer than initial_k finite points or a parameter is
   * bad */
  bool
  initialize (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
              const std::vector<Eigen::Vector3f>& colours,
              const AdaptiveRadiusParameters& parameters);

  /** \brief The noise constant in use: the given one, or the estimate (see
   * estimateNoise). */
  double
  getNoise () const
  {
    return noise_;
  }

  /** \brief The radius of point \a index (finite), iterating eq. 1-4; \a steps gets the
   * number of iterations done. */
  float
  estimate (pcl::index_t index, int* steps = nullptr) const;

  /** \brief Indices of all points within \a radius of point \a index, closest first. */
  void
  neighbours (pcl::index_t index, float radius, pcl::Indices& result) const;

  /** \brief The k nearest neighbours of an arbitrary position. */
  void
  nearest (const Eigen::Vector3f& position, std::size_t k, pcl::Indices& result) const;

  const search::KdTree3f&
  tree () const
  {
    return tree_;
  }

  const pcl::PointCloud<pcl::PointXYZ>::ConstPtr&
  cloud () const
  {
    return cloud_;
  }

  const std::vector<Eigen::Vector3f>&
  colours () const
  {
    return colours_;
  }

  /** \brief Sigma estimated as the median plane residual of the flattest 10 % of
   * kNoiseSamples sampled initial_k-neighbourhoods: a stand-in for "points acquired
   * from a single plane" when no planar patch is given (pcl_ext addition). The sample:
   * selectNoiseSamplePoints(); then measureNoiseSample() each, and noiseFromSamples().
   * Returns 0 when nothing is planar enough to tell. */
  double
  estimateNoise () const;

  /** \brief The finite points of smallest noiseSampleKey (ties by index), at most
   * kNoiseSamples, in that order; only those with \a eligible[i] != 0 when \a
   * eligible is given (e.g. a tile's own points). */
  std::vector<pcl::index_t>
  selectNoiseSamplePoints (const std::vector<char>* eligible = nullptr) const;

  /** \brief The noise sample of the initial_k-neighbourhood of point \a index.
   * \return false when it has no plane (too few points, no spread) */
  bool
  measureNoiseSample (pcl::index_t index, NoiseSample& sample) const;

private:
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud_;
  std::vector<Eigen::Vector3f> colours_;
  AdaptiveRadiusParameters parameters_;
  search::KdTree3f tree_;
  std::size_t finite_ = 0;
  double noise_ = 0.0;
};
} // namespace pcl_ext
