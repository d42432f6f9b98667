/*
 * The rows of the bad-input matrix for the segmentations.
 */
#include "bad_input.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/segmentation/adaptive_supervoxel_segmentation.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>

#include <pcl/common/point_tests.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>

namespace pcl_ext {
namespace test {
namespace bad_input {
namespace {
/** Segment labels for LocalSurfaceIntersection: the nearest face of the bounding box
 * (bottom or one of the four sides), 0 for non-finite points; and every finite point a
 * surface. */
void
faceLabels (const Cloud& cloud,
            pcl::PointCloud<pcl::Label>& segments,
            pcl::PointCloud<pcl::Label>& classes)
{
  Eigen::Vector3f lo = Eigen::Vector3f::Constant (std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo;
  for (const auto& p : cloud)
    if (pcl::isFinite (p)) {
      lo = lo.cwiseMin (p.getVector3fMap());
      hi = hi.cwiseMax (p.getVector3fMap());
    }
  segments.clear();
  classes.clear();
  for (const auto& p : cloud) {
    pcl::Label s, c;
    s.label = c.label = 0;
    if (pcl::isFinite (p)) {
      const Eigen::Vector3f q = p.getVector3fMap();
      const float d[5] = {q.z() - lo.z(),
                          q.x() - lo.x(),
                          hi.x() - q.x(),
                          q.y() - lo.y(),
                          hi.y() - q.y()};
      s.label = static_cast<std::uint32_t> (std::min_element (d, d + 5) - d) + 1;
      c.label = 1; // PointClass::Surface
    }
    segments.push_back (s);
    classes.push_back (c);
  }
}
} // namespace

void
addSegmentationSubjects (std::vector<Subject>& s)
{
  const auto k_based = with (kCloudInputs, {Bad::KLargerThanCloud});
  const auto with_normals =
      with (k_based, {Bad::MissingNormals, Bad::WrongSizeNormals});

  // Parameter: the width factor (> 0).
  s.push_back ({"ProfileSegmentation",
                kCloudInputs,
                {{Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
                  ProfileSegmentation<Point> seg;
                  seg.setInputCloud (in.cloud);
                  if (in.indices)
                    seg.setIndices (in.indices);
                  seg.setNumberOfThreads (2);
                  if (in.param)
                    seg.setProfileWidthFactor (*in.param);
                  if (in.nan_param)
                    seg.setProfileWidthFactor (
                        std::numeric_limits<double>::quiet_NaN());
                  std::vector<pcl::PointIndices> clusters;
                  seg.extract (clusters);
                  return segments (in, clusters);
                }});

  // The same with the options not in the paper: curve fitting in side frames, local
  // thresholds. Parameter: the maximum threshold factor (>= 1).
  s.push_back ({"ProfileSegmentationLocalThresholdsSideFrames",
                kCloudInputs,
                {{Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
                  ProfileSegmentation<Point> seg;
                  seg.setInputCloud (in.cloud);
                  if (in.indices)
                    seg.setIndices (in.indices);
                  seg.setNumberOfThreads (2);
                  seg.setProfileSegmentation (
                      ProfileSegmentation<Point>::ProfileMethod::CurveFitting);
                  seg.setLocalThreshold (true);
                  seg.setSideFrames (true);
                  if (in.param)
                    seg.setMaxThresholdFactor (*in.param);
                  if (in.nan_param)
                    seg.setMaxThresholdFactor (
                        std::numeric_limits<double>::quiet_NaN());
                  std::vector<pcl::PointIndices> clusters;
                  seg.extract (clusters);
                  return segments (in, clusters);
                }});

  // Classified, then grown (segmentByLocalVariance). Parameter: the confidence of the
  // classification's boundary test, in (0, 1). A line has no surface point to grow
  // from: refused with a message.
  s.push_back ({"VarianceRegionGrowing",
                with (kCloudInputs, {Bad::KLargerThanCloud}),
                {{Bad::Collinear, Expect::Refused}},
                [] (const Input& in) {
                  VarianceRegionGrowing<Point> rg;
                  rg.setInputCloud (in.cloud);
                  if (in.indices)
                    rg.setIndices (in.indices);
                  rg.setNumberOfThreads (2);
                  rg.setKSearch (in.k);
                  LocalVarianceClassification<Point> classifier;
                  classifier.setNumberOfThreads (2);
                  if (in.param)
                    classifier.setConfidence (*in.param);
                  if (in.nan_param)
                    classifier.setConfidence (std::numeric_limits<double>::quiet_NaN());
                  std::vector<pcl::PointIndices> clusters;
                  segmentByLocalVariance (classifier, rg, clusters);
                  return segments (in, clusters);
                }});

  // Segments: the faces of the box. Normals are optional (missing is fine, the wrong
  // size is not). Parameter: the reach factor (> 0). Labels come out for every point of
  // the cloud.
  s.push_back (
      {"LocalSurfaceIntersection",
       with_normals,
       {{Bad::MissingNormals, Expect::Computed}, {Bad::Collinear, Expect::Computed}},
       [] (const Input& in) {
         LocalSurfaceIntersection<Point> lsi;
         lsi.setInputCloud (in.cloud);
         if (in.indices)
           lsi.setIndices (in.indices);
         lsi.setNumberOfThreads (2);
         lsi.setKSearch (in.k);
         auto segments_in = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
         auto classes = pcl::make_shared<pcl::PointCloud<pcl::Label>>();
         faceLabels (*in.cloud, *segments_in, *classes);
         lsi.setSegmentLabels (segments_in);
         lsi.setPointClasses (classes);
         if (in.normals && in.normals->size() != in.cloud->size())
           lsi.setInputNormals (
               in.normals); // only the wrong size: the right normals are optional
         if (in.param)
           lsi.setReachFactor (*in.param);
         if (in.nan_param)
           lsi.setReachFactor (std::numeric_limits<double>::quiet_NaN());
         pcl::PointCloud<SurfaceIntersectionPoint> intersections;
         pcl::PointCloud<pcl::Label> labels;
         Outcome o;
         o.produced = lsi.compute (intersections, labels);
         if (o.produced) {
           o.size = labels.size();
           for (const auto& l : labels)
             o.no_result.push_back (l.label == 0 ? 1 : 0);
         }
         return o;
       }});

  // Parameter: the damping of eq. 3, in (0, 1].
  s.push_back ({"AdaptiveSupervoxelSegmentation",
                with (kCloudInputs, {Bad::KLargerThanCloud}),
                {{Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
                  AdaptiveSupervoxelSegmentation<Point> seg;
                  seg.setInputCloud (in.cloud);
                  if (in.indices)
                    seg.setIndices (in.indices);
                  seg.setNumberOfThreads (2);
                  if (in.param)
                    seg.setDamping (*in.param);
                  if (in.nan_param)
                    seg.setDamping (std::numeric_limits<double>::quiet_NaN());
                  std::vector<pcl::PointIndices> clusters;
                  seg.extract (clusters);
                  return segments (in, clusters);
                }});
}
} // namespace bad_input
} // namespace test
} // namespace pcl_ext
