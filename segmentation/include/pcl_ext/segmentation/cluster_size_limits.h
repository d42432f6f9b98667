/*
 * pcl_ext: the smallest and largest segment a segmenter keeps.
 */
#pragma once

#include <pcl/types.h>

#include <cstddef>
#include <limits>

namespace pcl_ext {
/** \brief The size limits of the segments a segmenter keeps, set as on
 * pcl::RegionGrowing: one set/get pair each for the smallest and the largest.
 *
 * A mixin of pcl_ext::ProfileSegmentation and pcl_ext::VarianceRegionGrowing, derived
 * from next to pcl::PCLBase.
 */
class ClusterSizeLimits {
public:
  /** \brief Smallest segment kept. Default 1, as pcl::RegionGrowing; valid: >= 1. */
  void
  setMinClusterSize (pcl::uindex_t size)
  {
    min_size_ = size;
  }

  pcl::uindex_t
  getMinClusterSize () const
  {
    return min_size_;
  }

  /** \brief Largest segment kept. Default: no limit; valid: >= the minimum. */
  void
  setMaxClusterSize (pcl::uindex_t size)
  {
    max_size_ = size;
  }

  pcl::uindex_t
  getMaxClusterSize () const
  {
    return max_size_;
  }

protected:
  /** \brief 1 <= minimum <= maximum. */
  bool
  validClusterSizes () const
  {
    return min_size_ >= 1 && max_size_ >= min_size_;
  }

  /** \brief Whether a segment of \a size points is kept. */
  bool
  keepsClusterSize (std::size_t size) const
  {
    return size >= min_size_ && size <= max_size_;
  }

  pcl::uindex_t min_size_ = 1;
  pcl::uindex_t max_size_ = std::numeric_limits<pcl::uindex_t>::max();
};
} // namespace pcl_ext
