/*
 * pcl_ext: the sample of neighbourhoods the noise and spacing of a cloud are estimated
 * from, chosen by the points' positions so that the parts of a cloud (tiles) give the
 * whole cloud's sample when merged.
 */
#pragma once

#include <pcl_ext/common/noise_estimation.h>

#include <cstddef>
#include <cstdint>
#include <queue>
#include <vector>

namespace pcl_ext {
/** \brief Neighbourhoods in the noise sample of a cloud (before ties at the cut). */
constexpr std::size_t kNoiseSampleSize = 20000;

/** \brief The sampling key of a point: a seeded hash of its float coordinates (see
 * pcl_ext::hashPosition), independent of the point's index and of the other points. */
std::uint64_t
noiseSampleKeyOf (float x, float y, float z);

/** \brief The largest key of the noise sample among the keys added: the
 * kNoiseSampleSize-th smallest (the largest when fewer were added). The sample is every
 * point whose key is at most the cut, so ties at the cut are all in it, and the cut of
 * a cloud is the cut of its parts' cuts. */
class NoiseSampleCut {
public:
  void
  add (std::uint64_t key)
  {
    if (largest_.size() < kNoiseSampleSize)
      largest_.push (key);
    else if (key < largest_.top()) {
      largest_.pop();
      largest_.push (key);
    }
  }

  /** \brief Whether any key was added. */
  bool
  empty () const
  {
    return largest_.empty();
  }

  /** \brief The cut (meaningless when empty()). */
  std::uint64_t
  get () const
  {
    return largest_.empty() ? 0 : largest_.top();
  }

private:
  std::priority_queue<std::uint64_t> largest_;
};

/** \brief A neighbourhood of the noise sample and its point's key. */
struct KeyedSpread {
  std::uint64_t key = 0;
  NeighbourhoodSpread spread;
};

/** \brief estimateNoiseAndSpacing over the noise sample in \a candidates (any set of
 * keyed neighbourhoods that holds every point of the sample, e.g. the samples of the
 * tiles of a cloud): the neighbourhoods whose key is at most the cut of all the keys,
 * in the order of their keys and values, their eigenvalues rounded to float (as the
 * tiles store them), so that the result does not depend on the order or the parts. */
NoiseEstimate
estimateNoiseFromSample (std::vector<KeyedSpread> candidates);

/** \brief The median surface variation (kappa, eq. 4 of Belton & Lichti 2006) over the
 * noise sample in \a candidates, chosen and rounded as estimateNoiseFromSample does,
 * with \a noise_variance taken off the smallest eigenvalue (at least 0), as
 * LocalVarianceClassification computes kappa: the median its curvature threshold is
 * derived from. The sample's twenty thousand points chosen by position fix the median
 * of a cloud of any size, and the tiles of a cloud give the same one. The upper median
 * for an even count; NaN when no neighbourhood of the sample has a covariance. */
double
sampleCurvatureMedian (std::vector<KeyedSpread> candidates, double noise_variance);
} // namespace pcl_ext
