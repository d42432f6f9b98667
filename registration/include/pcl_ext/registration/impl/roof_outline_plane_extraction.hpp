/*
 * pcl_ext: wall planes from the roof outlines of an airborne cloud.
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/registration/roof_outline_plane_extraction.h>

#include <pcl/console/print.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_parallel_plane.h>
#include <pcl/sample_consensus/sac_model_plane.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace pcl_ext {
namespace detail {
// PCL's models draw from a generator seeded 12345 (or the time) at construction, with
// no setter; a model seeded by the caller makes the seed a parameter. The generator is
// drawn from only by computeModel, so seeding after construction equals seeding in it.
template <typename Model>
class SeededModel : public Model {
public:
  SeededModel (const typename Model::PointCloudConstPtr& cloud,
               const pcl::Indices& indices,
               unsigned int seed)
  : Model (cloud, indices, false)
  {
    this->rng_alg_.seed (seed);
  }
};

// What pcl::SACSegmentation::segment does with RANSAC and optimised coefficients, on a
// model we seeded: the consensus set, the least-squares plane of it, and the points
// within the threshold of that plane.
template <typename PointT>
bool
segmentSeeded (const typename pcl::SampleConsensusModel<PointT>::Ptr& model,
               double threshold,
               int max_iterations,
               pcl::Indices& inliers,
               Eigen::VectorXf& coefficients)
{
  inliers.clear();
  pcl::RandomSampleConsensus<PointT> ransac (model, threshold);
  ransac.setMaxIterations (max_iterations);
  if (!ransac.computeModel (0))
    return false;
  ransac.getInliers (inliers);
  Eigen::VectorXf raw;
  ransac.getModelCoefficients (raw);
  model->optimizeModelCoefficients (inliers, raw, coefficients);
  model->selectWithinDistance (coefficients, threshold, inliers);
  return true;
}
} // namespace detail

template <typename PointT>
pcl::Indices
longestWallStretch (const pcl::PointCloud<PointT>& cloud,
                    const pcl::Indices& inliers,
                    const Eigen::Vector3f& normal,
                    float max_gap)
{
  const Eigen::Vector2f along = Eigen::Vector2f (-normal.y(), normal.x()).normalized();
  std::vector<std::pair<float, int>> position;
  position.reserve (inliers.size());
  for (const auto i : inliers)
    position.emplace_back (along.dot (cloud[i].getVector3fMap().template head<2>()),
                           static_cast<int> (i));
  std::sort (position.begin(), position.end());
  std::size_t best_begin = 0, best_end = 0;
  for (std::size_t begin = 0, end = 0; begin < position.size(); begin = end) {
    for (end = begin + 1; end < position.size() &&
                          position[end].first - position[end - 1].first <= max_gap;
         ++end)
      ;
    if (end - begin > best_end - best_begin) {
      best_begin = begin;
      best_end = end;
    }
  }
  pcl::Indices stretch;
  stretch.reserve (best_end - best_begin);
  for (std::size_t q = best_begin; q < best_end; ++q)
    stretch.push_back (position[q].second);
  std::sort (stretch.begin(), stretch.end());
  return stretch;
}

template <typename PointT>
bool
RoofOutlinePlaneExtraction<PointT>::checkParameters() const
{
  const auto positive = [] (double v) { return v > 0.0 && std::isfinite (v); };
  const char* bad = nullptr;
  if (ground_label_ == building_label_)
    bad = "the ground and building labels must differ";
  else if (!positive (ground_distance_))
    bad = "the ground distance threshold must be > 0";
  else if (!positive (building_tolerance_))
    bad = "the building tolerance must be > 0";
  else if (min_building_points_ < 1)
    bad = "the least points of a building must be >= 1";
  else if (outline_neighbours_ < 3)
    bad = "the outline neighbours must be >= 3";
  else if (!positive (open_side_distance_))
    bad = "the open side distance must be > 0";
  else if (!positive (outline_band_))
    bad = "the outline band must be > 0";
  else if (!(angle_tolerance_deg_ > 0.0 && angle_tolerance_deg_ < 90.0))
    bad = "the angle tolerance must be in (0, 90) degrees";
  else if (!positive (max_gap_))
    bad = "the maximum gap must be > 0";
  else if (min_wall_points_ < 3)
    bad = "the least points of a wall must be >= 3";
  else if (max_walls_per_building_ < 0)
    bad = "the most walls per building must be >= 0 (0: no limit)";
  else if (max_iterations_ < 1)
    bad = "the RANSAC iterations must be >= 1";
  if (bad)
    PCL_ERROR (
        "[pcl_ext::RoofOutlinePlaneExtraction::extract] Invalid parameters: %s.\n",
        bad);
  return bad == nullptr;
}

template <typename PointT>
void
RoofOutlinePlaneExtraction<PointT>::extract (std::vector<pcl::PointIndices>& planes)
{
  planes.clear();
  if (!checkParameters())
    return;
  if (!this->initCompute()) {
    PCL_ERROR ("[pcl_ext::RoofOutlinePlaneExtraction::extract] No input cloud.\n");
    return;
  }
  if (!labels_ || labels_->size() != input_->size()) {
    PCL_ERROR ("[pcl_ext::RoofOutlinePlaneExtraction::extract] %zu labels for %zu "
               "points: one label per "
               "point is needed.\n",
               labels_ ? labels_->size() : std::size_t (0),
               input_->size());
    this->deinitCompute();
    return;
  }

  // Sort the points: ground, building (with their 2D positions), and everything else,
  // which is what an outline must have beyond it. Non-finite points are in none.
  pcl::Indices ground, building;
  // 2D positions as pcl::PointXYZ with z = 0, whatever PointT is, so that the searches
  // below measure x and y only.
  pcl::PointCloud<pcl::PointXYZ>::Ptr flat (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::PointXYZ>::Ptr others (new pcl::PointCloud<pcl::PointXYZ>);
  if (!indicesInRange (*indices_,
                       input_->size(),
                       "[pcl_ext::RoofOutlinePlaneExtraction::extract]")) {
    this->deinitCompute();
    return;
  }
  for (const auto i : *indices_) {
    const PointT& p = (*input_)[i];
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      continue;
    const std::uint32_t label = (*labels_)[i].label;
    if (label == ground_label_)
      ground.push_back (i);
    if (label == building_label_) {
      building.push_back (i);
      flat->emplace_back (p.x, p.y, 0.f);
    }
    else
      others->emplace_back (p.x, p.y, 0.f);
  }

  if (building.empty()) {
    if (flat->empty() && others->empty())
      PCL_ERROR ("[pcl_ext::RoofOutlinePlaneExtraction::extract] The input has no "
                 "finite point.\n");
    else
      PCL_ERROR ("[pcl_ext::RoofOutlinePlaneExtraction::extract] No finite point has "
                 "the building label %u.\n",
                 building_label_);
    this->deinitCompute();
    return;
  }

  if (extract_ground_ && ground.size() >= 3) {
    typename pcl::SampleConsensusModel<PointT>::Ptr model (
        new detail::SeededModel<pcl::SampleConsensusModelPlane<PointT>> (
            input_, ground, seed_));
    pcl::PointIndices inliers;
    Eigen::VectorXf coefficients;
    detail::segmentSeeded<PointT> (
        model, ground_distance_, max_iterations_, inliers.indices, coefficients);
    if (!inliers.indices.empty()) {
      inliers.header = input_->header;
      planes.push_back (std::move (inliers));
    }
  }
  if (others->empty()) // all roof: no outline has anything beyond
  {
    this->deinitCompute();
    return;
  }

  // Buildings: connected in 2D.
  std::vector<pcl::PointIndices> buildings;
  pcl::search::KdTree<pcl::PointXYZ>::Ptr flat_search (
      new pcl::search::KdTree<pcl::PointXYZ>);
  flat_search->setInputCloud (flat);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
  clustering.setClusterTolerance (building_tolerance_);
  clustering.setMinClusterSize (min_building_points_);
  clustering.setSearchMethod (flat_search);
  clustering.setInputCloud (flat);
  clustering.extract (buildings);

  pcl::KdTreeFLANN<pcl::PointXYZ> beyond;
  beyond.setInputCloud (others);
  const float open_side = static_cast<float> (open_side_distance_);
  const auto k = static_cast<std::size_t> (outline_neighbours_);
  pcl::Indices nn;
  std::vector<float> d2;
  for (const auto& members : buildings) {
    // Outline points: neighbours to one side, and another label beyond on the open
    // side.
    pcl::PointCloud<pcl::PointXYZ>::Ptr roof (
        new pcl::PointCloud<pcl::PointXYZ> (*flat, members.indices));
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud (roof);
    pcl::Indices outline;
    for (std::size_t j = 0; j < roof->size(); ++j) {
      if (tree.nearestKSearch ((*roof)[j], outline_neighbours_, nn, d2) <
          outline_neighbours_)
        continue;
      const Eigen::Vector2f p = (*roof)[j].getVector3fMap().template head<2>();
      Eigen::Vector2f mean = Eigen::Vector2f::Zero();
      float spacing = 0.f;
      for (std::size_t q = 1; q < k; ++q) // the first neighbour is the point itself
      {
        mean += (*roof)[nn[q]].getVector3fMap().template head<2>();
        spacing += std::sqrt (d2[q]);
      }
      mean /= static_cast<float> (k - 1);
      spacing /= static_cast<float> (k - 1);
      // Inside a roof the neighbours surround the point; 0.35 of the spacing leaves
      // room for the unevenness of a scan pattern, and is far below the half spacing of
      // a straight edge.
      if ((mean - p).norm() <= 0.35f * spacing)
        continue;
      const Eigen::Vector2f out = p + (p - mean).normalized() * open_side;
      if (beyond.radiusSearch (
              pcl::PointXYZ (out.x(), out.y(), 0.f), open_side_distance_, nn, d2, 1) ==
          0)
        continue;
      outline.push_back (building[members.indices[j]]);
    }
    std::sort (outline.begin(), outline.end());

    // Walls: vertical RANSAC planes, each cut to its longest stretch, until too few
    // points.
    int walls = 0;
    while (static_cast<int> (outline.size()) >= min_wall_points_ &&
           (max_walls_per_building_ == 0 || walls < max_walls_per_building_)) {
      auto* parallel =
          new detail::SeededModel<pcl::SampleConsensusModelParallelPlane<PointT>> (
              input_, outline, seed_);
      typename pcl::SampleConsensusModel<PointT>::Ptr model (parallel);
      parallel->setAxis (Eigen::Vector3f::UnitZ());
      parallel->setEpsAngle (angle_tolerance_deg_ * M_PI / 180.0);
      pcl::Indices inliers;
      Eigen::VectorXf coefficients;
      if (!detail::segmentSeeded<PointT> (
              model, outline_band_, max_iterations_, inliers, coefficients) ||
          static_cast<int> (inliers.size()) < min_wall_points_)
        break;
      pcl::PointIndices wall;
      wall.indices = longestWallStretch (*input_,
                                         inliers,
                                         coefficients.template head<3>(),
                                         static_cast<float> (max_gap_));
      if (static_cast<int> (wall.indices.size()) < min_wall_points_)
        break;
      pcl::Indices rest;
      rest.reserve (outline.size() - wall.indices.size());
      std::set_difference (outline.begin(),
                           outline.end(),
                           wall.indices.begin(),
                           wall.indices.end(),
                           std::back_inserter (rest));
      outline.swap (rest);
      wall.header = input_->header;
      planes.push_back (std::move (wall));
      ++walls;
    }
  }
  this->deinitCompute();
}

template <typename PointT>
PlaneExtractor<PointT>
RoofOutlinePlaneExtraction<PointT>::asExtractor() const
{
  return makePlaneExtractor<PointT> (*this);
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_RoofOutlinePlaneExtraction(T)                              \
  template class pcl_ext::RoofOutlinePlaneExtraction<T>;                               \
  template pcl::Indices pcl_ext::longestWallStretch<T> (                               \
      const pcl::PointCloud<T>&, const pcl::Indices&, const Eigen::Vector3f&, float);
