/*
 * pcl_ext_tiles: what Belton & Lichti's classification and segmentation share tile by
 * tile: the curvature threshold of the whole cloud, and the classifier on a tile.
 */
#pragma once

#include "../variance/variance_options.h"
#include "tile_method.h"

#include <pcl_ext/classification/local_variance_classification.h>

namespace pcl_ext {
namespace apps {
/** \brief A method on Belton & Lichti's classification: when the curvature threshold is
 * derived (factor x the median curvature kappa, eq. 4, of the noise sample) or the
 * noise is estimated from the cloud, every tile saves the neighbourhoods of its points
 * of the whole cloud's noise sample (estimate(); the plan knows the sample's cut, so
 * those are the only neighbourhoods searched), and reduce() estimates from them the
 * noise and the threshold every tile then uses (applyEstimates()), as the untiled
 * classifier does (pcl_ext::estimateNoiseFromSample, pcl_ext::sampleCurvatureMedian).
 */
class VarianceTileMethod : public TileMethod {
public:
  NeighbourhoodReach
  getEstimateReach () const override;

  bool
  needsEstimate () const override
  {
    return getClassificationOptions().curvature_threshold == 0.0 || estimate_noise_;
  }

  PointSelection
  getEstimateSelection (
      const std::map<std::string, std::string>& settings) const override;

  bool
  estimate (const TileCloud& tile,
            std::map<std::string, std::vector<float>>& values) override;

  bool
  reduce (const std::string& folder,
          std::size_t tiles,
          std::map<std::string, std::string>& settings) override;

protected:
  /** \brief The classification's options of the method. */
  virtual const VarianceClassificationOptions&
  getClassificationOptions () const = 0;

  /** \brief Keep what the options ask the classifier to estimate from the cloud (the
   * curvature factor, the noise). \return true */
  bool
  checkClassification ();

  /** \brief The neighbourhood steps a class reaches through: eq. 5 reads the
   * neighbours' curvatures, the boundary band the neighbours' labels. */
  int
  getClassificationHops () const
  {
    return getClassificationOptions().boundary_band ? 3 : 2;
  }

  /** \brief \a classifier on the points and neighbourhoods of \a tile with the
   * method's options and threads. */
  void
  configure (LocalVarianceClassification<pcl::PointXYZ>& classifier,
             const TileCloud& tile) const;

  /** \brief The whole cloud's curvature threshold and noise (from the plan's \a
   * settings) on \a classifier where they are estimated from the cloud. \return false
   * (message printed) when the plan lacks one */
  bool
  applyEstimates (LocalVarianceClassification<pcl::PointXYZ>& classifier,
                  const std::map<std::string, std::string>& settings) const;

private:
  double curvature_factor_ =
      0.0; ///< the classifier's after the options (0: from the cloud)
  bool estimate_noise_ =
      false; ///< the noise estimated from the cloud (-preset derived)
  double given_noise_sigma_ = 0.0; ///< the noise sigma given (-noise_sigma) or 0
};

/** \brief The adapters of pcl_ext_classify_variance and pcl_ext_segment_variance. */
std::unique_ptr<TileMethod>
makeClassifyVarianceTiles ();
std::unique_ptr<TileMethod>
makeSegmentVarianceTiles ();
} // namespace apps
} // namespace pcl_ext
