/*
 * pcl_ext: Belton & Lichti's classification and region growing in one call.
 */
#pragma once

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/segmentation/variance_region_growing.h>

#include <pcl/PointIndices.h>

#include <vector>

namespace pcl_ext {
/** \brief Belton & Lichti's segmentation workflow (2006, sections 2 and 3) in one call:
 * the points of \a growing's cloud (and indices) are classified surface, edge or
 * boundary by \a classifier, then \a growing grows its segments over those classes,
 * both on one neighbourhood search.
 *
 * The neighbourhoods are \a growing's shared ones (setNeighbourhoods) when computed for
 * its cloud and indices, else one search with its k or radius, maximum radius, search
 * method and thread count; \a classifier takes them too, so its own neighbourhood
 * settings are not used. Every other option is each object's own: the classification's
 * thresholds on \a classifier, the distance limits, sizes and plane fits on \a growing.
 * Afterwards \a growing holds the classes (getInputClasses) and the shared
 * neighbourhoods (getNeighbourhoods).
 *
 * \code
 * pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
 * pcl_ext::VarianceRegionGrowing<pcl::PointXYZ> growing;
 * growing.setInputCloud (cloud);
 * growing.setMinClusterSize (50);
 * std::vector<pcl::PointIndices> segments;
 * pcl_ext::segmentByLocalVariance (classifier, growing, segments);
 * \endcode
 *
 * \param[in,out] classifier the classification's options; its input is set here
 * \param[in,out] growing the region growing, with its input cloud (and indices) set
 * \param[out] clusters the segments, largest first; empty after a PCL_ERROR (no cloud,
 * a failed search or classification, or what VarianceRegionGrowing::extract reports)
 */
template <typename PointT>
void
segmentByLocalVariance (LocalVarianceClassification<PointT>& classifier,
                        VarianceRegionGrowing<PointT>& growing,
                        std::vector<pcl::PointIndices>& clusters);
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/classification/impl/variance_segmentation.hpp>
#endif
