/*
 * pcl_ext: the noise and the point spacing of a whole cloud, from the neighbourhoods of
 * its noise sample.
 */
#pragma once

#include <pcl_ext/common/noise_estimation.h>

#include <pcl/point_cloud.h>

namespace pcl_ext {
/** \brief The noise about the surfaces and the point spacing of \a cloud
 * (pcl_ext::estimateNoiseFromSample): the k nearest neighbours of the points of its
 * noise sample (about twenty thousand, chosen by position, pcl_ext::noiseSampleKeyOf),
 * their eigenvalues, and the estimate from the flattest half. For a tool that needs
 * the noise of a cloud without searching every point's neighbours; the same sample as
 * LocalVarianceClassification estimates from.
 *
 * \code
 * const pcl_ext::NoiseEstimate noise = pcl_ext::estimateCloudNoise (*cloud);
 * if (noise.valid)
 *   threshold = 3.0 * noise.sigma;
 * \endcode
 * \param[in] cloud the cloud; non-finite points are left out
 * \param[in] k neighbours per sample point, at least 4
 * \param[in] threads threads of the searches (0: all cores)
 * \return not valid (reason given) for fewer than k finite points, or as
 * estimateNoiseAndSpacing says */
template <typename PointT>
NoiseEstimate
estimateCloudNoise (const pcl::PointCloud<PointT>& cloud,
                    int k = 50,
                    unsigned int threads = 1);
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/search/impl/cloud_noise.hpp>
#endif
