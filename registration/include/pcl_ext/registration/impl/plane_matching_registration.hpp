/*
 * pcl_ext: registration by plane matching (Khoshelham & Gorte 2009).
 */
#pragma once

#include <pcl_ext/common/indices.h>
#include <pcl_ext/registration/impl/plane_extraction.hpp>
#include <pcl_ext/registration/plane_matching_registration.h>

#include <pcl/common/io.h>
#include <pcl/common/transforms.h>
#include <pcl/console/print.h>

namespace pcl_ext
{
template <typename PointSource, typename PointTarget>
PlaneMatchingRegistration<PointSource, PointTarget>::PlaneMatchingRegistration ()
{
  reg_name_ = "PlaneMatchingRegistration";
  source_extractor_ = SACPlaneExtraction<PointSource> ().asExtractor ();
  target_extractor_ = SACPlaneExtraction<PointTarget> ().asExtractor ();
}

template <typename PointSource, typename PointTarget> void
PlaneMatchingRegistration<PointSource, PointTarget>::align (PointCloudSource& output, const Matrix4& guess)
{
  if (input_ && indices_ && !indicesInRange (*indices_, input_->size (), "[pcl_ext::PlaneMatchingRegistration::align]"))
  {
    converged_ = false;
    result_ = PlaneMatchingResult ();
    distances_ = PlaneDistanceMetrics ();
    final_transformation_.setIdentity ();
    final_double_.setIdentity ();
    output.clear ();
    return;
  }
  Base::align (output, guess);
}

template <typename PointSource, typename PointTarget> bool
PlaneMatchingRegistration<PointSource, PointTarget>::setFootprints (
    const std::vector<io::Footprint>& footprints, const MapPlaneParameters& parameters, bool choose_origin)
{
  clearMap ();
  MapPlaneParameters p = parameters;
  if (choose_origin && p.origin.isZero () && !chooseLocalOrigin (footprints, p.origin))
  {
    PCL_ERROR ("[pcl_ext::%s::setFootprints] No footprint vertex.\n", reg_name_.c_str ());
    return false;
  }
  std::vector<MapPlane> planes;
  if (!computeMapPlanes (footprints, p, planes))
    return false;
  setMapPlanes (planes, p.origin);
  return true;
}

template <typename PointSource, typename PointTarget> void
PlaneMatchingRegistration<PointSource, PointTarget>::setMapPlanes (const std::vector<MapPlane>& planes,
                                                                    const Eigen::Vector3d& origin)
{
  map_planes_ = planes;
  origin_ = origin;
  has_map_ = true;
  setCornerTarget ();
}

template <typename PointSource, typename PointTarget> void
PlaneMatchingRegistration<PointSource, PointTarget>::clearMap ()
{
  map_planes_.clear ();
  has_map_ = false;
  origin_.setZero ();
}

template <typename PointSource, typename PointTarget> void
PlaneMatchingRegistration<PointSource, PointTarget>::setCornerTarget ()
{
  // pcl::Registration insists on a target cloud: the map's wall corners serve (a plot of them
  // is also the natural overlay of the registered scan).
  typename PointCloudTarget::Ptr corners (new PointCloudTarget);
  for (const auto& plane : map_planes_)
    if (!plane.isFloor ())
      for (const auto& c : {plane.extent.min (), plane.extent.max ()})
      {
        PointTarget p;
        p.x = static_cast<float> (c.x ());
        p.y = static_cast<float> (c.y ());
        p.z = static_cast<float> (c.z ());
        corners->push_back (p);
      }
  if (corners->empty ())
  {
    PointTarget p;
    p.x = p.y = p.z = 0.f;
    corners->push_back (p);
  }
  Base::setInputTarget (corners);
}

template <typename PointSource, typename PointTarget> bool
PlaneMatchingRegistration<PointSource, PointTarget>::extractSourcePlaneSets (std::vector<pcl::PointIndices>& sets) const
{
  // setIndices: the extractor takes its planes among the indexed points; its sets index the
  // input, which the viewpoints and the plane fits use. An extractor that answers with an index
  // outside the cloud is refused.
  if (!source_extractor_ (input_, fake_indices_ ? pcl::IndicesConstPtr () : indices_, sets))
    return false;
  for (const auto& set : sets)
    if (!indicesInRange (set.indices, input_->size (), "[pcl_ext::PlaneMatchingRegistration::align] plane extractor:"))
      return false;
  return true;
}

template <typename PointSource, typename PointTarget> void
PlaneMatchingRegistration<PointSource, PointTarget>::computeTransformation (PointCloudSource& output,
                                                                             const Matrix4& guess)
{
  converged_ = false;
  result_ = PlaneMatchingResult ();
  distances_ = PlaneDistanceMetrics ();
  final_double_.setIdentity ();
  target_planes_.clear ();
  if (input_->empty ())
  {
    PCL_ERROR ("[pcl_ext::%s::align] The source cloud is empty.\n", reg_name_.c_str ());
    return;
  }

  // Scan planes of the source (and scan to scan, of the target).
  if (!source_planes_given_)
  {
    std::vector<pcl::PointIndices> sets;
    if (!source_extractor_ || !extractSourcePlaneSets (sets) ||
        !fitScanPlanes (*input_, sets, source_viewpoints_, source_planes_))
    {
      PCL_ERROR ("[pcl_ext::%s::align] Plane extraction failed on the source.\n", reg_name_.c_str ());
      source_planes_.clear ();
      return;
    }
  }
  if (has_map_)
    target_planes_.assign (map_planes_.begin (), map_planes_.end ());
  else
  {
    std::vector<pcl::PointIndices> sets;
    if (!target_extractor_ || !target_extractor_ (target_, pcl::IndicesConstPtr (), sets) ||
        !fitScanPlanes (*target_, sets, target_viewpoints_, target_scan_planes_))
    {
      PCL_ERROR ("[pcl_ext::%s::align] Plane extraction failed on the target.\n", reg_name_.c_str ());
      return;
    }
    target_planes_.assign (target_scan_planes_.begin (), target_scan_planes_.end ());
  }
  if (source_planes_.empty () || target_planes_.empty ())
  {
    PCL_ERROR ("[pcl_ext::%s::align] No planes in the %s.\n", reg_name_.c_str (),
               source_planes_.empty () ? "source" : "target");
    return;
  }

  const std::vector<RegistrationPlane> scan (source_planes_.begin (), source_planes_.end ());
  if (!matchPlanes (scan, target_planes_, parameters_, result_, guess.template cast<double> ()))
    return;

  // Tables 1-2: mean and maximum distance of the matched scan inliers to their map planes.
  std::vector<pcl::PointIndices> inliers;
  for (const auto& plane : source_planes_)
    inliers.push_back (plane.inliers);
  std::vector<Eigen::Vector4d> coefficients;
  for (const auto& plane : target_planes_)
    coefficients.push_back (plane.coefficients ());
  pcl::Correspondences matches;
  for (const auto& pair : result_.matches)
    matches.emplace_back (pair.scan, pair.map, 0.f);
  final_double_ = result_.estimate.transformation;
  computePlaneDistances (*input_, inliers, coefficients, matches, final_double_, distances_);

  final_transformation_ = transformation_ = final_double_.cast<float> ();
  // pcl::Registration::align filled output with the indexed points.
  pcl::transformPointCloud (output, output, final_transformation_);
  converged_ = true;
}
}  // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_PlaneMatchingRegistration(T) \
  template class pcl_ext::PlaneMatchingRegistration<T, T>;
