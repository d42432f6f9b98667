/*
 * pcl_ext: registration by plane matching (Khoshelham & Gorte 2009).
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/registration/impl/plane_distances.hpp>
#include <pcl_ext/registration/impl/plane_extraction.hpp>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/registration/scan_levelling.h>

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/transforms.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

namespace pcl_ext {
template <typename PointSource, typename PointTarget>
PlaneMatchingRegistration<PointSource, PointTarget>::PlaneMatchingRegistration()
{
  reg_name_ = "PlaneMatchingRegistration";
  source_extractor_ = SACPlaneExtraction<PointSource>().asExtractor();
  target_extractor_ = SACPlaneExtraction<PointTarget>().asExtractor();
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setInputSource (
    const PointCloudSourceConstPtr& cloud)
{
  if (cloud && cloud->empty()) {
    PCL_ERROR ("[pcl_ext::%s::setInputSource] The source cloud is empty.\n",
               reg_name_.c_str());
    source_cloud_updated_ = true;
    pcl::PCLBase<PointSource>::setInputCloud (cloud);
  }
  else
    Base::setInputSource (cloud);
  holdBackIndicesOutOfRange ("setInputSource");
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setIndices (
    const pcl::IndicesPtr& indices)
{
  setCheckedIndices (indices);
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setIndices (
    const pcl::IndicesConstPtr& indices)
{
  setCheckedIndices (indices);
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setIndices (
    const pcl::PointIndicesConstPtr& indices)
{
  setCheckedIndices (indices);
}

template <typename PointSource, typename PointTarget>
template <typename IndicesT>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setCheckedIndices (
    const IndicesT& indices)
{
  held_back_indices_.reset();
  Base::setIndices (indices);
  holdBackIndicesOutOfRange ("setIndices");
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::holdBackIndicesOutOfRange (
    const char* method)
{
  // pcl::Registration::align reads the indexed points before computeTransformation
  // runs: an index outside the cloud must not reach it. Held-back indices get another
  // chance with a new cloud.
  if (held_back_indices_) {
    indices_ = held_back_indices_;
    held_back_indices_.reset();
  }
  if (!input_ || !indices_ || fake_indices_)
    return;
  const std::string caller = "[pcl_ext::" + reg_name_ + "::" + method + "]";
  if (indicesInRange (*indices_, input_->size(), caller.c_str()))
    return;
  held_back_indices_ = indices_;
  indices_.reset (new pcl::Indices);
}

template <typename PointSource, typename PointTarget>
double
PlaneMatchingRegistration<PointSource, PointTarget>::getFitnessScore (double max_range)
{
  if (!converged_ || !input_)
    return std::numeric_limits<double>::max();
  const Eigen::Matrix3d block = final_double_.topLeftCorner<3, 3>();
  const Eigen::Vector3d translation = final_double_.topRightCorner<3, 1>();
  double sum = 0.0;
  std::size_t planes = 0;
  for (const auto& pair : result_.matches) {
    // Scan planes given by setSourcePlanes() after align() may no longer be those
    // matched.
    if (static_cast<std::size_t> (pair.scan) >= source_planes_.size())
      continue;
    const Plane& map = target_planes_[pair.map];
    double squares = 0.0;
    std::size_t points = 0;
    for (const auto i : source_planes_[pair.scan].inliers.indices) {
      if (i < 0 || static_cast<std::size_t> (i) >= input_->size() ||
          !pcl::isXYZFinite ((*input_)[i]))
        continue;
      const Eigen::Vector3d x =
          block * (*input_)[i].getVector3fMap().template cast<double>() + translation;
      const double distance = std::abs (map.signedDistance (x));
      if (distance > max_range)
        continue;
      squares += distance * distance;
      ++points;
    }
    if (points > 0) {
      sum += std::sqrt (squares / static_cast<double> (points));
      ++planes;
    }
  }
  return planes > 0 ? sum / static_cast<double> (planes)
                    : std::numeric_limits<double>::max();
}

template <typename PointSource, typename PointTarget>
bool
PlaneMatchingRegistration<PointSource, PointTarget>::getPlaneDistances (
    PlaneDistanceMetrics& metrics) const
{
  if (!input_) {
    PCL_ERROR ("[pcl_ext::%s::getPlaneDistances] No source cloud.\n",
               reg_name_.c_str());
    metrics = PlaneDistanceMetrics();
    return false;
  }
  return computePlaneDistances (
      *input_, source_planes_, target_planes_, result_.matches, final_double_, metrics);
}

template <typename PointSource, typename PointTarget>
bool
PlaneMatchingRegistration<PointSource, PointTarget>::setFootprints (
    const std::vector<io::Footprint>& footprints,
    const MapPlaneParameters& parameters,
    bool choose_origin)
{
  clearMap();
  MapPlaneParameters p = parameters;
  if (choose_origin && p.origin.isZero() && !chooseLocalOrigin (footprints, p.origin)) {
    PCL_ERROR ("[pcl_ext::%s::setFootprints] No footprint vertex.\n",
               reg_name_.c_str());
    return false;
  }
  std::vector<MapPlane> planes;
  if (!computeMapPlanes (footprints, p, planes))
    return false;
  setMapPlanes (planes, p.origin);
  coverage_ = std::make_shared<const FootprintCoverage> (footprints, p.origin);
  return true;
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setMapPlanes (
    const std::vector<MapPlane>& planes, const Eigen::Vector3d& origin)
{
  map_planes_ = planes;
  origin_ = origin;
  has_map_ = true;
  coverage_.reset();
  setCornerTarget();
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::clearMap()
{
  map_planes_.clear();
  has_map_ = false;
  coverage_.reset();
  origin_.setZero();
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::setCornerTarget()
{
  // pcl::Registration insists on a target cloud: the map's wall corners serve (a plot
  // of them is also the natural overlay of the registered scan).
  typename PointCloudTarget::Ptr corners (new PointCloudTarget);
  for (const auto& plane : map_planes_)
    if (!plane.isFloor())
      for (const auto& c : {plane.extent.min(), plane.extent.max()}) {
        PointTarget p;
        p.x = static_cast<float> (c.x());
        p.y = static_cast<float> (c.y());
        p.z = static_cast<float> (c.z());
        corners->push_back (p);
      }
  if (corners->empty()) {
    PointTarget p;
    p.x = p.y = p.z = 0.f;
    corners->push_back (p);
  }
  Base::setInputTarget (corners);
}

template <typename PointSource, typename PointTarget>
bool
PlaneMatchingRegistration<PointSource, PointTarget>::extractSourcePlaneSets (
    std::vector<pcl::PointIndices>& sets) const
{
  // setIndices: the extractor takes its planes among the indexed points; its sets index
  // the input, which the viewpoints and the plane fits use. An extractor that answers
  // with an index outside the cloud is refused.
  source_extractor_ (input_, fake_indices_ ? pcl::IndicesConstPtr() : indices_, sets);
  for (const auto& set : sets)
    if (!indicesInRange (
            set.indices,
            input_->size(),
            "[pcl_ext::PlaneMatchingRegistration::align] plane extractor:"))
      return false;
  return true;
}

template <typename PointSource, typename PointTarget>
void
PlaneMatchingRegistration<PointSource, PointTarget>::computeTransformation (
    PointCloudSource& output, const Matrix4& guess)
{
  converged_ = false;
  result_ = PlaneMatchingResult();
  final_double_.setIdentity();
  target_planes_.clear();
  // pcl::Registration::align has copied the indexed points into output: held-back
  // indices gave none (see setIndices), and indices changed through their pointer since
  // are refused.
  if (held_back_indices_ ||
      (!fake_indices_ &&
       !indicesInRange (
           *indices_, input_->size(), "[pcl_ext::PlaneMatchingRegistration::align]"))) {
    PCL_ERROR ("[pcl_ext::%s::align] The indices do not fit the source cloud.\n",
               reg_name_.c_str());
    output.clear();
    return;
  }
  if (input_->empty()) {
    PCL_ERROR ("[pcl_ext::%s::align] The source cloud is empty.\n", reg_name_.c_str());
    return;
  }

  // Scan planes of the source (and scan to scan, of the target).
  if (!source_planes_given_) {
    std::vector<pcl::PointIndices> sets;
    if (!source_extractor_ || !extractSourcePlaneSets (sets) ||
        !fitScanPlanes (*input_, sets, source_viewpoints_, source_planes_)) {
      PCL_ERROR ("[pcl_ext::%s::align] Plane extraction failed on the source.\n",
                 reg_name_.c_str());
      source_planes_.clear();
      return;
    }
  }
  if (has_map_)
    target_planes_.assign (map_planes_.begin(), map_planes_.end());
  else {
    std::vector<pcl::PointIndices> sets;
    if (target_extractor_)
      target_extractor_ (target_, pcl::IndicesConstPtr(), sets);
    if (!target_extractor_ ||
        !fitScanPlanes (*target_, sets, target_viewpoints_, target_scan_planes_)) {
      PCL_ERROR ("[pcl_ext::%s::align] Plane extraction failed on the target.\n",
                 reg_name_.c_str());
      return;
    }
    target_planes_.assign (target_scan_planes_.begin(), target_scan_planes_.end());
  }
  if (source_planes_.empty() || target_planes_.empty()) {
    PCL_ERROR ("[pcl_ext::%s::align] No planes in the %s.\n",
               reg_name_.c_str(),
               source_planes_.empty() ? "source" : "target");
    return;
  }

  // A scan that is not levelled is levelled from its planes (map only: the map is).
  source_up_ = Eigen::Vector3d::UnitZ();
  std::vector<Plane> scan (source_planes_.begin(), source_planes_.end());
  // The levelling takes a nearly level plane's normal from its flat patches (see
  // estimateFlatPatchNormal: a town's ground is level pieces joined by steps).
  std::vector<Plane> levelling = scan;
  if (has_map_ && estimate_vertical_)
    for (std::size_t i = 0; i < levelling.size(); ++i) {
      const Eigen::Vector3d fitted = levelling[i].normal;
      if (!(std::abs (fitted.z()) >= std::cos (kMaxLevellingTiltDeg * M_PI / 180.0)))
        continue;
      // At most kMaxPatchPoints of them, evenly spread: a few hundred a cell.
      constexpr std::size_t kMaxPatchPoints = std::size_t (1) << 18;
      const auto& ids = source_planes_[i].inliers.indices;
      const std::size_t step = (ids.size() + kMaxPatchPoints - 1) / kMaxPatchPoints;
      std::vector<Eigen::Vector3d> points;
      points.reserve (std::min (ids.size(), kMaxPatchPoints));
      for (std::size_t j = 0; j < ids.size(); j += std::max<std::size_t> (step, 1))
        if (ids[j] >= 0 && static_cast<std::size_t> (ids[j]) < input_->size() &&
            pcl::isXYZFinite ((*input_)[ids[j]]))
          points.push_back ((*input_)[ids[j]].getVector3fMap().template cast<double>());
      estimateFlatPatchNormal (points, fitted, levelling[i].normal);
    }
  const bool levelled =
      has_map_ && estimate_vertical_ &&
      estimateUpDirection (levelling, source_up_, kMaxLevellingTiltDeg);
  const Eigen::Matrix4d level = levellingTransform (source_up_);
  for (auto& plane : scan)
    plane = transformPlane (plane, level);
  const Eigen::Matrix4d level_inverse = level.inverse();
  // The points a pose must put over the footprints, in the scan frame.
  std::vector<Eigen::Vector3d> covered;
  if (coverage_ && !coverage_->empty() && coverage_indices_) {
    constexpr std::size_t kMaxCoveragePoints = 4096;
    const auto& ids = *coverage_indices_;
    const std::size_t step = std::max<std::size_t> (1, ids.size() / kMaxCoveragePoints);
    for (std::size_t i = 0; i < ids.size(); i += step)
      if (ids[i] >= 0 && static_cast<std::size_t> (ids[i]) < input_->size() &&
          pcl::isXYZFinite ((*input_)[ids[i]]))
        covered.push_back ((*input_)[ids[i]].getVector3fMap().template cast<double>());
  }
  std::function<double (const Eigen::Matrix4d&)> coverage;
  if (!covered.empty())
    coverage = [&] (const Eigen::Matrix4d& levelled) {
      return coverage_->share (covered, levelled * level);
    };
  if (!matchPlanes (scan,
                    target_planes_,
                    parameters_,
                    result_,
                    guess.template cast<double>() * level_inverse,
                    coverage))
    return;

  // The tilt of the levelling, from every plane, not that of the matched few.
  if (levelled) {
    refineAboutVertical (scan, target_planes_, result_.matches, result_.estimate);
    for (auto& candidate : result_.candidates)
      refineAboutVertical (scan, target_planes_, candidate.matches, candidate.estimate);
  }
  result_.estimate.transformation = result_.estimate.transformation * level;
  for (auto& candidate : result_.candidates)
    candidate.estimate.transformation = candidate.estimate.transformation * level;
  final_double_ = result_.estimate.transformation;
  final_transformation_ = transformation_ = final_double_.cast<float>();
  // pcl::Registration::align filled output with the indexed points.
  pcl::transformPointCloud (output, output, final_transformation_);
  converged_ = true;
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_PlaneMatchingRegistration(T)                               \
  template class pcl_ext::PlaneMatchingRegistration<T, T>;
