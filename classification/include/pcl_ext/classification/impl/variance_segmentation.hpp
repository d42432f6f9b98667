/*
 * pcl_ext: segmentByLocalVariance implementation.
 */
#pragma once

#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/search/neighbourhoods.h>

#include <pcl/console/print.h>

template <typename PointT>
void
pcl_ext::segmentByLocalVariance (LocalVarianceClassification<PointT>& classifier,
                                 VarianceRegionGrowing<PointT>& growing,
                                 std::vector<pcl::PointIndices>& clusters)
{
  clusters.clear();
  const auto cloud = growing.getInputCloud();
  if (!cloud || cloud->empty()) {
    PCL_ERROR (
        "[pcl_ext::segmentByLocalVariance] No input cloud, or an empty one: set it on "
        "the region growing.\n");
    return;
  }
  const pcl::IndicesConstPtr indices = growing.getIndices();
  auto nb = growing.getNeighbourhoods();
  if (!nb || !nb->isComputedFor (cloud, indices)) {
    auto own = pcl::make_shared<Neighbourhoods<PointT>>();
    own->setInputCloud (cloud);
    if (indices)
      own->setIndices (indices);
    if (growing.getKSearch() != 0) {
      own->setKSearch (growing.getKSearch());
      own->setMaxRadius (growing.getMaxRadius());
    }
    else
      own->setRadiusSearch (growing.getRadiusSearch());
    if (growing.getSearchMethod())
      own->setSearchMethod (growing.getSearchMethod());
    own->setNumberOfThreads (growing.getNumberOfThreads());
    // As the methods' own searches: neither step needs the distances stored, and the
    // rows take half the memory without them.
    own->setStoreSquaredDistances (false);
    if (!own->compute()) {
      PCL_ERROR (
          "[pcl_ext::segmentByLocalVariance] The neighbourhood search failed.\n");
      return;
    }
    nb = own;
  }
  classifier.setInputCloud (cloud);
  if (indices)
    classifier.setIndices (indices);
  classifier.setNeighbourhoods (nb);
  auto classes = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
  classifier.classify (*classes);
  if (classes->empty()) {
    PCL_ERROR ("[pcl_ext::segmentByLocalVariance] The classification failed.\n");
    return;
  }
  growing.setNeighbourhoods (nb);
  growing.setInputClasses (classes);
  growing.extract (clusters);
}

#define PCL_EXT_INSTANTIATE_segmentByLocalVariance(T)                                  \
  template void pcl_ext::segmentByLocalVariance<T> (                                   \
      pcl_ext::LocalVarianceClassification<T>&,                                        \
      pcl_ext::VarianceRegionGrowing<T>&,                                              \
      std::vector<pcl::PointIndices>&);
