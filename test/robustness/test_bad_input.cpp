/*
 * The bad-input matrix of the cloud-processing classes (test/README.md): every class against
 * every kind of bad cloud, bad indices, bad parameter and bad normals that applies to it.
 *
 * Each run is one test named BadInput/Matrix.Run/<Class>_<Input>. The expected outcomes:
 * - Refused: empty output and a PCL_ERROR from pcl_ext (or PCL's own, naming the class);
 *   nothing thrown;
 * - Computed: one output per index, the documented "no result" (NaN, label 0, an empty
 *   neighbourhood, no segment) for every non-finite point, and a result for some finite one;
 * - Degenerate: as Computed, but every point may get "no result" (collinear points have no
 *   tangent plane);
 * - Ran: registration only: align() returns, converged or not, with a finite transformation.
 */
#include "analytic_clouds.h"
#include "plane_fixtures.h"

#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/classification/multiscale_crf_classification.h>
#include <pcl_ext/search/neighbourhoods.h>
#include <pcl_ext/features/chi_squared_boundary.h>
#include <pcl_ext/features/covariance_features.h>
#include <pcl_ext/features/curvature_variance.h>
#include <pcl_ext/features/projected_normal_curvatures.h>
#include <pcl_ext/features/saliency_feature_estimation.h>
#include <pcl_ext/registration/map_planes.h>
#include <pcl_ext/registration/plane_extraction.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/registration/roof_outline_plane_extraction.h>
#include <pcl_ext/segmentation/adaptive_supervoxel_segmentation.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/classification/variance_segmentation.h>
#include <pcl_ext/segmentation/variance_region_growing.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/common/io.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>

using namespace pcl_ext;

namespace
{
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Normals = pcl::PointCloud<pcl::Normal>;
const float kNaN = std::numeric_limits<float>::quiet_NaN ();
const float kInf = std::numeric_limits<float>::infinity ();

/** The columns of the matrix. */
enum class Bad
{
  EmptyCloud,
  AllNaN,
  SomeNaNDense,      ///< NaN and Inf points in a cloud that claims is_dense
  SomeNaNNotDense,   ///< the same with is_dense false
  OnePoint,
  KLargerThanCloud,  ///< 6 points, k = 10
  DuplicatePoints,   ///< every point three times
  Collinear,
  Coplanar,
  Utm,               ///< x ~ 500,000 m, y ~ 6,000,000 m
  Tiny,              ///< the whole cloud within a few 1e-6 m
  IndicesOutOfRange,
  NegativeParameter,
  ZeroParameter,
  NaNParameter,
  MissingNormals,
  WrongSizeNormals
};

const std::map<Bad, const char*> kBadNames = {
    {Bad::EmptyCloud, "EmptyCloud"},
    {Bad::AllNaN, "AllNaN"},
    {Bad::SomeNaNDense, "SomeNaNClaimingDense"},
    {Bad::SomeNaNNotDense, "SomeNaNNotDense"},
    {Bad::OnePoint, "OnePoint"},
    {Bad::KLargerThanCloud, "KLargerThanCloud"},
    {Bad::DuplicatePoints, "DuplicatePoints"},
    {Bad::Collinear, "Collinear"},
    {Bad::Coplanar, "Coplanar"},
    {Bad::Utm, "UtmCoordinates"},
    {Bad::Tiny, "MicrometreCoordinates"},
    {Bad::IndicesOutOfRange, "IndicesOutOfRange"},
    {Bad::NegativeParameter, "NegativeParameter"},
    {Bad::ZeroParameter, "ZeroParameter"},
    {Bad::NaNParameter, "NaNParameter"},
    {Bad::MissingNormals, "MissingNormals"},
    {Bad::WrongSizeNormals, "WrongSizeNormals"}};

enum class Expect { Refused, Computed, Degenerate, Ran };

/** What a subject is given. */
struct Input
{
  Cloud::Ptr cloud;
  pcl::IndicesPtr indices;       ///< null: all points
  std::optional<double> param;   ///< the subject's checked parameter, when set
  bool nan_param = false;        ///< param is NaN (kept apart so optional<double> stays simple)
  Normals::Ptr normals;          ///< one per point unless the input is about normals
  int k = 10;                    ///< k for the k-based subjects
  double scale = 1.0;            ///< size of the cloud's features relative to the 1 m cube
};

/** What a subject did, in the same terms for every class. */
struct Outcome
{
  bool produced = false;            ///< any output (a converged registration)
  std::size_t size = 0;             ///< outputs (rows, labels), or indices covered by segments
  std::vector<char> no_result;      ///< per index: the documented "no result"
  bool finite_transform = true;     ///< registration only
};

/** A box open at the top (so that it has borders as well as creases) with noise, about 900
  * points. */
Cloud::Ptr
baseCloud (double scale = 1.0, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero ())
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.08, 0.002, 11);
  Cloud::Ptr cloud (new Cloud);
  for (const auto& p : *cube.cloud)
  {
    if (p.z > 0.99f)
      continue;
    const Eigen::Vector3d q = p.getVector3fMap ().cast<double> () * scale + offset;
    cloud->push_back (Point (static_cast<float> (q.x ()), static_cast<float> (q.y ()),
                             static_cast<float> (q.z ())));
  }
  return cloud;
}

Cloud::Ptr
cloudFor (Bad bad)
{
  Cloud::Ptr cloud (new Cloud);
  switch (bad)
  {
    case Bad::EmptyCloud:
      break;
    case Bad::AllNaN:
      cloud->resize (200, Point (kNaN, kNaN, kNaN));
      cloud->is_dense = false;
      break;
    case Bad::SomeNaNDense:
    case Bad::SomeNaNNotDense:
      cloud = baseCloud ();
      for (std::size_t i = 0; i < cloud->size (); i += 17)
        (*cloud)[i].y = kNaN;
      for (std::size_t i = 5; i < cloud->size (); i += 29)
        (*cloud)[i].z = kInf;
      cloud->is_dense = bad == Bad::SomeNaNDense;
      break;
    case Bad::OnePoint:
      cloud->push_back (Point (1.f, 2.f, 3.f));
      break;
    case Bad::KLargerThanCloud:
      for (int i = 0; i < 6; ++i)
        cloud->push_back (Point (0.1f * i, 0.05f * (i % 2), 0.f));
      break;
    case Bad::DuplicatePoints:
    {
      const Cloud::Ptr base = baseCloud ();
      for (const auto& p : *base)
        for (int c = 0; c < 3; ++c)
          cloud->push_back (p);
      break;
    }
    case Bad::Collinear:
      for (int i = 0; i < 400; ++i)
        cloud->push_back (Point (0.01f * i, 0.02f * i, -0.005f * i));
      break;
    case Bad::Coplanar:
      for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j)
          cloud->push_back (Point (0.05f * i, 0.05f * j, 0.f));
      break;
    case Bad::Utm:
      // 50 m cube: float keeps 0.5 m at 6,000,000 m, so the geometry survives, coarsely.
      cloud = baseCloud (50.0, Eigen::Vector3d (500000.0, 6000000.0, 100.0));
      break;
    case Bad::Tiny:
      cloud = baseCloud (4e-6);
      break;
    default:
      cloud = baseCloud ();
      break;
  }
  return cloud;
}

/** Normals (0, 0, 1) with a small varying curvature; NaN at non-finite points. */
Normals::Ptr
normalsFor (const Cloud& cloud)
{
  Normals::Ptr normals (new Normals);
  for (std::size_t i = 0; i < cloud.size (); ++i)
    normals->push_back (pcl::isFinite (cloud[i]) ? pcl::Normal (0.f, 0.f, 1.f, 0.001f * (i % 7))
                                                 : pcl::Normal (kNaN, kNaN, kNaN, kNaN));
  return normals;
}

Input
inputFor (Bad bad)
{
  Input in;
  in.cloud = cloudFor (bad);
  in.normals = normalsFor (*in.cloud);
  in.scale = bad == Bad::Utm ? 50.0 : bad == Bad::Tiny ? 4e-6 : 1.0;
  switch (bad)
  {
    case Bad::IndicesOutOfRange:
      in.indices.reset (new pcl::Indices{0, 1, static_cast<pcl::index_t> (in.cloud->size () + 5)});
      break;
    case Bad::NegativeParameter: in.param = -1.0; break;
    case Bad::ZeroParameter: in.param = 0.0; break;
    case Bad::NaNParameter: in.nan_param = true; break;
    case Bad::MissingNormals: in.normals.reset (); break;
    case Bad::WrongSizeNormals: in.normals->resize (in.normals->size () / 2); break;
    default: break;
  }
  return in;
}

/** The indices a subject's outputs correspond to. */
std::vector<pcl::index_t>
indicesOf (const Input& in)
{
  if (in.indices)
    return *in.indices;
  std::vector<pcl::index_t> all (in.cloud->size ());
  for (std::size_t i = 0; i < all.size (); ++i)
    all[i] = static_cast<pcl::index_t> (i);
  return all;
}

/** Per-index outcome of a feature cloud: "no result" where \a invalid says so. */
template <typename PointOutT, typename Invalid> Outcome
perPoint (const pcl::PointCloud<PointOutT>& out, Invalid&& invalid)
{
  Outcome o;
  o.produced = !out.empty ();
  o.size = out.size ();
  for (const auto& p : out)
    o.no_result.push_back (invalid (p) ? 1 : 0);
  return o;
}

/** Outcome of a segmentation: index r has "no result" when no segment holds it. */
Outcome
segments (const Input& in, const std::vector<pcl::PointIndices>& clusters)
{
  Outcome o;
  o.produced = !clusters.empty ();
  if (!o.produced)
    return o;
  std::set<pcl::index_t> covered;
  for (const auto& c : clusters)
    covered.insert (c.indices.begin (), c.indices.end ());
  const auto indices = indicesOf (in);
  o.size = indices.size ();
  for (const auto i : indices)
    o.no_result.push_back (covered.count (i) ? 0 : 1);
  return o;
}

/** k, or (the NaN parameter) a NaN radius, for PCL-style features. */
template <typename Estimator> void
setNeighbourhood (Estimator& est, const Input& in)
{
  if (in.nan_param)
  {
    est.setKSearch (0);
    est.setRadiusSearch (std::numeric_limits<double>::quiet_NaN ());
  }
  else
    est.setKSearch (in.param ? static_cast<int> (*in.param) : in.k);
}

template <typename Estimator> void
setCommon (Estimator& est, const Input& in)
{
  est.setInputCloud (in.cloud);
  if (in.indices)
    est.setIndices (in.indices);
  est.setNumberOfThreads (2);
}

bool
isNaN (float v)
{
  return std::isnan (v);
}

/** Segment labels for LocalSurfaceIntersection: the nearest face of the bounding box (bottom
  * or one of the four sides), 0 for non-finite points; and every finite point a surface. */
void
faceLabels (const Cloud& cloud, pcl::PointCloud<pcl::Label>& segments,
            pcl::PointCloud<pcl::Label>& classes)
{
  Eigen::Vector3f lo = Eigen::Vector3f::Constant (std::numeric_limits<float>::max ());
  Eigen::Vector3f hi = -lo;
  for (const auto& p : cloud)
    if (pcl::isFinite (p))
    {
      lo = lo.cwiseMin (p.getVector3fMap ());
      hi = hi.cwiseMax (p.getVector3fMap ());
    }
  segments.clear ();
  classes.clear ();
  for (const auto& p : cloud)
  {
    pcl::Label s, c;
    s.label = c.label = 0;
    if (pcl::isFinite (p))
    {
      const Eigen::Vector3f q = p.getVector3fMap ();
      const float d[5] = {q.z () - lo.z (), q.x () - lo.x (), hi.x () - q.x (), q.y () - lo.y (),
                          hi.y () - q.y ()};
      s.label = static_cast<std::uint32_t> (std::min_element (d, d + 5) - d) + 1;
      c.label = 1;  // PointClass::Surface
    }
    segments.push_back (s);
    classes.push_back (c);
  }
}

/** A trained CRF model for the classification subject (a small generated street). */
const MultiscaleCrfClassification<Point>&
trainedCrf ()
{
  static const auto crf = [] {
    simulation::SceneParameters p;
    p.seed = 3;
    p.points = 6000;
    p.threads = 1;
    simulation::SyntheticScene scene;
    EXPECT_TRUE (simulation::generateScene ("street", p, scene));
    Cloud::Ptr cloud (new Cloud);
    std::vector<std::uint32_t> labels;
    for (const auto& q : scene.cloud)
    {
      cloud->push_back (Point (q.x, q.y, q.z));
      labels.push_back (q.label);
    }
    auto c = std::make_unique<MultiscaleCrfClassification<Point>> ();
    c->setNumberOfThreads (2);
    // The subject is classification's input handling, not the model's quality: a few
    // optimiser steps and a fixed edge scale (no search over BP runs) give a valid model in a
    // fraction of the time, paid by every case (ctest runs each case in its own process).
    c->getModel ().settings ().max_training_iterations = 10;
    c->setEdgeScale (1.0);
    EXPECT_TRUE (c->train ({cloud}, {labels}));
    return c;
  }();
  return *crf;
}

struct Subject
{
  std::string name;
  std::set<Bad> applies;              ///< the inputs that make sense for it
  std::map<Bad, Expect> expectations; ///< outcomes other than the defaults below
  std::function<Outcome (const Input&)> run;
};

const std::set<Bad> kCloudInputs = {
    Bad::EmptyCloud, Bad::AllNaN, Bad::SomeNaNDense, Bad::SomeNaNNotDense, Bad::OnePoint,
    Bad::DuplicatePoints, Bad::Collinear, Bad::Coplanar, Bad::Utm, Bad::Tiny,
    Bad::IndicesOutOfRange, Bad::NegativeParameter, Bad::ZeroParameter, Bad::NaNParameter};

std::set<Bad>
with (std::set<Bad> set, std::initializer_list<Bad> more)
{
  set.insert (more);
  return set;
}

std::set<Bad>
without (std::set<Bad> set, std::initializer_list<Bad> less)
{
  for (const Bad b : less)
    set.erase (b);
  return set;
}

Expect
defaultExpectation (Bad bad)
{
  switch (bad)
  {
    case Bad::SomeNaNDense:
    case Bad::SomeNaNNotDense:
    case Bad::DuplicatePoints:
    case Bad::Coplanar:
    case Bad::Utm:
    case Bad::Tiny:
      return Expect::Computed;
    case Bad::Collinear:
      return Expect::Degenerate;
    default:
      return Expect::Refused;
  }
}

std::vector<Subject>
subjects ()
{
  std::vector<Subject> s;
  const auto k_based = with (kCloudInputs, {Bad::KLargerThanCloud});
  const auto with_normals = with (k_based, {Bad::MissingNormals, Bad::WrongSizeNormals});

  s.push_back ({"Neighbourhoods", k_based, {{Bad::Collinear, Expect::Computed}}, [] (const Input& in) {
    Neighbourhoods<Point> nb;
    nb.setInputCloud (in.cloud);
    if (in.indices)
      nb.setIndices (in.indices);
    nb.setNumberOfThreads (2);
    if (in.nan_param)
      nb.setRadiusSearch (std::numeric_limits<double>::quiet_NaN ());
    else
      nb.setKSearch (in.param ? static_cast<int> (*in.param) : in.k);
    Outcome o;
    o.produced = nb.compute () && nb.size () > 0;
    if (o.produced)
    {
      o.size = nb.size ();
      for (std::size_t r = 0; r < nb.size (); ++r)
        o.no_result.push_back (nb[r].empty () ? 1 : 0);
    }
    return o;
  }});

  s.push_back ({"CovarianceFeatureEstimation", k_based, {}, [] (const Input& in) {
    CovarianceFeatureEstimation<Point> est;
    setCommon (est, in);
    setNeighbourhood (est, in);
    pcl::PointCloud<CovarianceFeatures> out;
    est.compute (out);
    return perPoint (out, [] (const CovarianceFeatures& f) { return isNaN (f.surface_variance); });
  }});

  s.push_back ({"CurvatureVarianceEstimation", with_normals, {}, [] (const Input& in) {
    CurvatureVarianceEstimation<Point, pcl::Normal> est;
    setCommon (est, in);
    setNeighbourhood (est, in);
    if (in.normals)
      est.setInputNormals (in.normals);
    pcl::PointCloud<CurvatureVariance> out;
    est.compute (out);
    return perPoint (out, [] (const CurvatureVariance& f) { return isNaN (f.curvature_variance); });
  }});

  // Boundaries: non-finite and degenerate points are documented as "not a boundary" (0), so
  // "no result" is 0 and a result is any point found to be a boundary.
  s.push_back ({"ChiSquaredBoundaryEstimation", k_based,
                {{Bad::Coplanar, Expect::Computed}, {Bad::DuplicatePoints, Expect::Computed}},
                [] (const Input& in) {
    ChiSquaredBoundaryEstimation<Point> est;
    setCommon (est, in);
    setNeighbourhood (est, in);
    pcl::PointCloud<pcl::Boundary> out;
    est.compute (out);
    return perPoint (out, [] (const pcl::Boundary& b) { return b.boundary_point == 0; });
  }});

  s.push_back ({"ProjectedNormalCurvaturesEstimation", with_normals, {}, [] (const Input& in) {
    ProjectedNormalCurvaturesEstimation<Point, pcl::Normal> est;
    setCommon (est, in);
    setNeighbourhood (est, in);
    if (in.normals)
      est.setInputNormals (in.normals);
    pcl::PointCloud<pcl::PrincipalCurvatures> out;
    est.compute (out);
    return perPoint (out, [] (const pcl::PrincipalCurvatures& c) { return isNaN (c.pc1); });
  }});

  // Radius-based; a non-finite indexed point is an error (documented).
  s.push_back ({"SaliencyFeatureEstimation", kCloudInputs,
                {{Bad::SomeNaNDense, Expect::Refused}, {Bad::SomeNaNNotDense, Expect::Refused},
                 {Bad::OnePoint, Expect::Computed}, {Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
    SaliencyFeatureEstimation<Point> est;
    est.setInputCloud (in.cloud);
    if (in.indices)
      est.setIndices (in.indices);
    est.setNumberOfThreads (2);
    float r = static_cast<float> (0.3 * in.scale);  // about 4 spacings of the cube
    if (in.param)
      r = static_cast<float> (*in.param);
    if (in.nan_param)
      r = kNaN;
    est.setRadius (r);
    Eigen::MatrixXf f;
    est.compute (f);
    Outcome o;
    o.produced = f.rows () > 0;
    o.size = static_cast<std::size_t> (f.rows ());
    for (Eigen::Index i = 0; i < f.rows (); ++i)
      o.no_result.push_back (f.row (i).allFinite () ? 0 : 1);
    return o;
  }});

  s.push_back ({"LocalVarianceClassification", with (kCloudInputs, {Bad::KLargerThanCloud}), {},
                [] (const Input& in) {
    LocalVarianceClassification<Point> c;
    c.setInputCloud (in.cloud);
    if (in.indices)
      c.setIndices (in.indices);
    c.setNumberOfThreads (2);
    if (in.nan_param)
      c.setRadiusSearch (std::numeric_limits<double>::quiet_NaN ());
    else
      c.setKSearch (in.param ? static_cast<int> (*in.param) : in.k);
    pcl::PointCloud<pcl::Label> labels;
    c.classify (labels);
    return perPoint (labels, [] (const pcl::Label& l) { return l.label == 0; });
  }});

  // Parameter: the width factor (> 0).
  s.push_back ({"ProfileSegmentation", kCloudInputs, {{Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
    ProfileSegmentation<Point> seg;
    seg.setInputCloud (in.cloud);
    if (in.indices)
      seg.setIndices (in.indices);
    seg.setNumberOfThreads (2);
    if (in.param)
      seg.setProfileWidthFactor (*in.param);
    if (in.nan_param)
      seg.setProfileWidthFactor (std::numeric_limits<double>::quiet_NaN ());
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    return segments (in, clusters);
  }});

  // The same with the options not in the paper: curve fitting in side frames, local
  // thresholds. Parameter: the maximum threshold factor (>= 1).
  s.push_back ({"ProfileSegmentationLocalThresholdsSideFrames", kCloudInputs,
                {{Bad::Collinear, Expect::Computed}}, [] (const Input& in) {
    ProfileSegmentation<Point> seg;
    seg.setInputCloud (in.cloud);
    if (in.indices)
      seg.setIndices (in.indices);
    seg.setNumberOfThreads (2);
    seg.setProfileSegmentation (ProfileSegmentation<Point>::ProfileMethod::CurveFitting);
    seg.setLocalThreshold (true);
    seg.setSideFrames (true);
    if (in.param)
      seg.setMaxThresholdFactor (*in.param);
    if (in.nan_param)
      seg.setMaxThresholdFactor (std::numeric_limits<double>::quiet_NaN ());
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    return segments (in, clusters);
  }});

  // Classified, then grown (segmentByLocalVariance). Parameter: the confidence of the
  // classification's boundary test, in (0, 1). A line has no surface point to grow from:
  // refused with a message.
  s.push_back ({"VarianceRegionGrowing", with (kCloudInputs, {Bad::KLargerThanCloud}),
                {{Bad::Collinear, Expect::Refused}}, [] (const Input& in) {
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
      classifier.setConfidence (std::numeric_limits<double>::quiet_NaN ());
    std::vector<pcl::PointIndices> clusters;
    segmentByLocalVariance (classifier, rg, clusters);
    return segments (in, clusters);
  }});

  // Segments: the faces of the box. Normals are optional (missing is fine, the wrong size is
  // not). Parameter: the reach factor (> 0). Labels come out for every point of the cloud.
  s.push_back ({"LocalSurfaceIntersection", with_normals,
                {{Bad::MissingNormals, Expect::Computed}, {Bad::Collinear, Expect::Computed}},
                [] (const Input& in) {
    LocalSurfaceIntersection<Point> lsi;
    lsi.setInputCloud (in.cloud);
    if (in.indices)
      lsi.setIndices (in.indices);
    lsi.setNumberOfThreads (2);
    lsi.setKSearch (in.k);
    auto segments_in = pcl::make_shared<pcl::PointCloud<pcl::Label>> ();
    auto classes = pcl::make_shared<pcl::PointCloud<pcl::Label>> ();
    faceLabels (*in.cloud, *segments_in, *classes);
    lsi.setSegmentLabels (segments_in);
    lsi.setPointClasses (classes);
    if (in.normals && in.normals->size () != in.cloud->size ())
      lsi.setInputNormals (in.normals);  // only the wrong size: the right normals are optional
    if (in.param)
      lsi.setReachFactor (*in.param);
    if (in.nan_param)
      lsi.setReachFactor (std::numeric_limits<double>::quiet_NaN ());
    pcl::PointCloud<SurfaceIntersectionPoint> intersections;
    pcl::PointCloud<pcl::Label> labels;
    Outcome o;
    o.produced = lsi.compute (intersections, labels);
    if (o.produced)
    {
      o.size = labels.size ();
      for (const auto& l : labels)
        o.no_result.push_back (l.label == 0 ? 1 : 0);
    }
    return o;
  }});

  // Parameter: the damping of eq. 3, in (0, 1].
  s.push_back ({"AdaptiveSupervoxelSegmentation", with (kCloudInputs, {Bad::KLargerThanCloud}),
                {{Bad::Collinear, Expect::Computed}}, [] (const Input& in) {
    AdaptiveSupervoxelSegmentation<Point> seg;
    seg.setInputCloud (in.cloud);
    if (in.indices)
      seg.setIndices (in.indices);
    seg.setNumberOfThreads (2);
    if (in.param)
      seg.setDamping (*in.param);
    if (in.nan_param)
      seg.setDamping (std::numeric_limits<double>::quiet_NaN ());
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    return segments (in, clusters);
  }});

  // The parameters come from the trained model: no parameter inputs.
  s.push_back ({"MultiscaleCrfClassification",
                without (kCloudInputs, {Bad::NegativeParameter, Bad::ZeroParameter, Bad::NaNParameter}),
                {{Bad::Collinear, Expect::Computed}}, [] (const Input& in) {
    MultiscaleCrfClassification<Point> crf = trainedCrf ();
    crf.setInputCloud (in.cloud);
    if (in.indices)
      crf.setIndices (in.indices);
    pcl::PointCloud<pcl::Label> labels;
    crf.classify (labels);
    return perPoint (labels, [] (const pcl::Label& l) { return l.label == 0; });
  }});

  // Parameter: the inlier distance (> 0). Too few points for a plane, or none on a plane, is
  // no plane (extract() succeeds with none). At the micrometre scale PCL's plane model
  // rejects every sample (its collinearity test has a fixed absolute threshold), so no plane
  // is found there either.
  s.push_back ({"SACPlaneExtraction", kCloudInputs,
                {{Bad::OnePoint, Expect::Degenerate}, {Bad::Tiny, Expect::Degenerate}},
                [] (const Input& in) {
    SACPlaneExtraction<Point> sac;
    sac.setInputCloud (in.cloud);
    if (in.indices)
      sac.setIndices (in.indices);
    sac.setDistanceThreshold (in.param ? *in.param : 0.02 * in.scale);
    if (in.nan_param)
      sac.setDistanceThreshold (std::numeric_limits<double>::quiet_NaN ());
    sac.setMinInliers (20);
    std::vector<pcl::PointIndices> planes;
    const bool ok = sac.extract (planes);
    Outcome o = segments (in, planes);
    o.produced = ok;
    if (ok && planes.empty ())
    {
      o.size = indicesOf (in).size ();
      o.no_result.assign (o.size, 1);
    }
    return o;
  }});

  // The box as a classified airborne cloud: its floor is ground, the rest building (label by
  // height above the lowest point); parameter: the outline band (> 0). A horizontal plane, or
  // one point, is all floor: no building point, which is refused. At the micrometre scale the
  // plane models reject every sample (as for SACPlaneExtraction).
  s.push_back ({"RoofOutlinePlaneExtraction", kCloudInputs,
                {{Bad::Coplanar, Expect::Refused}, {Bad::Tiny, Expect::Degenerate}},
                [] (const Input& in) {
    float floor = std::numeric_limits<float>::infinity ();
    for (const auto& p : *in.cloud)
      if (pcl::isFinite (p))
        floor = std::min (floor, p.z);
    pcl::PointCloud<pcl::Label>::Ptr labels (new pcl::PointCloud<pcl::Label>);
    for (const auto& p : *in.cloud)
      labels->push_back (pcl::Label {p.z < floor + 0.02 * in.scale ? 2u : 6u});
    RoofOutlinePlaneExtraction<Point> walls;
    walls.setInputCloud (in.cloud);
    walls.setInputLabels (labels);
    if (in.indices)
      walls.setIndices (in.indices);
    walls.setGroundDistanceThreshold (0.02 * in.scale);
    walls.setBuildingTolerance (0.2 * in.scale);
    walls.setMinBuildingPoints (20);
    walls.setOpenSideDistance (0.2 * in.scale);
    walls.setMaxGap (0.3 * in.scale);
    walls.setOutlineBand (in.param ? *in.param : 0.02 * in.scale);
    if (in.nan_param)
      walls.setOutlineBand (std::numeric_limits<double>::quiet_NaN ());
    std::vector<pcl::PointIndices> planes;
    const bool ok = walls.extract (planes);
    Outcome o = segments (in, planes);
    o.produced = ok;
    if (ok && planes.empty ())
    {
      o.size = indicesOf (in).size ();
      o.no_result.assign (o.size, 1);
    }
    return o;
  }});

  // Registration of the cloud to an H-shaped footprint; parameter: the angle tolerance.
  s.push_back ({"PlaneMatchingRegistration", kCloudInputs,
                {{Bad::SomeNaNDense, Expect::Ran}, {Bad::SomeNaNNotDense, Expect::Ran},
                 {Bad::DuplicatePoints, Expect::Ran}, {Bad::Collinear, Expect::Ran},
                 {Bad::Coplanar, Expect::Ran}, {Bad::Utm, Expect::Ran}, {Bad::Tiny, Expect::Ran}},
                [] (const Input& in) {
    PlaneMatchingRegistration<Point, Point> reg;
    io::Footprint footprint;
    footprint.polygons.resize (1);
    footprint.polygons[0].outer = pcl_ext::test::asymmetricH ();
    EXPECT_TRUE (reg.setFootprints ({footprint}));
    reg.setInputSource (in.cloud);
    if (in.indices)
      reg.setIndices (in.indices);
    reg.setNumberOfThreads (2);
    if (in.param)
      reg.setTolerances (*in.param, 0.5);
    if (in.nan_param)
      reg.setTolerances (std::numeric_limits<double>::quiet_NaN (), 0.5);
    Cloud aligned;
    reg.align (aligned);
    Outcome o;
    o.produced = reg.hasConverged ();
    o.finite_transform = reg.getFinalTransformation ().allFinite ();
    return o;
  }});
  return s;
}

const std::vector<Subject>&
allSubjects ()
{
  static const std::vector<Subject> s = subjects ();
  return s;
}

struct Case
{
  std::size_t subject;
  Bad bad;
};

std::vector<Case>
allCases ()
{
  std::vector<Case> cases;
  const auto& s = allSubjects ();
  for (std::size_t i = 0; i < s.size (); ++i)
    for (const auto& entry : kBadNames)
      if (s[i].applies.count (entry.first))
        cases.push_back ({i, entry.first});
  return cases;
}

class Matrix : public ::testing::TestWithParam<Case>
{};

TEST_P (Matrix, Run)
{
  const Subject& subject = allSubjects ()[GetParam ().subject];
  const Bad bad = GetParam ().bad;
  const auto it = subject.expectations.find (bad);
  const Expect expect = it != subject.expectations.end () ? it->second : defaultExpectation (bad);
  const Input in = inputFor (bad);
  if (subject.name == "MultiscaleCrfClassification")
    trainedCrf ();  // train before capturing: its messages are not the subject's

  ::testing::internal::CaptureStderr ();
  const Outcome o = subject.run (in);
  const std::string log = ::testing::internal::GetCapturedStderr ();

  switch (expect)
  {
    case Expect::Refused:
      EXPECT_FALSE (o.produced) << "bad input accepted";
      EXPECT_EQ (o.size, 0u);
      EXPECT_TRUE (log.find ("[pcl_ext::") != std::string::npos ||
                   log.find (subject.name) != std::string::npos)
          << "no PCL_ERROR from pcl_ext or naming the class; stderr: " << log;
      break;
    case Expect::Computed:
    case Expect::Degenerate:
    {
      ASSERT_TRUE (o.produced) << "stderr: " << log;
      const auto indices = indicesOf (in);
      ASSERT_EQ (o.size, indices.size ());
      ASSERT_EQ (o.no_result.size (), indices.size ());
      std::size_t results = 0;
      for (std::size_t r = 0; r < indices.size (); ++r)
      {
        if (!pcl::isFinite ((*in.cloud)[indices[r]]))
          EXPECT_TRUE (o.no_result[r]) << "non-finite point " << indices[r] << " got a result";
        results += o.no_result[r] ? 0 : 1;
      }
      if (expect == Expect::Computed)
        EXPECT_GT (results, 0u) << "no point got a result";
      break;
    }
    case Expect::Ran:
      EXPECT_TRUE (o.finite_transform);
      break;
  }
}

/** Names a case in gtest's messages (otherwise printed as the struct's bytes). */
void
PrintTo (const Case& c, std::ostream* os)
{
  *os << allSubjects ()[c.subject].name << " on " << kBadNames.at (c.bad);
}

std::string
caseName (const ::testing::TestParamInfo<Case>& info)
{
  return allSubjects ()[info.param.subject].name + "_" + kBadNames.at (info.param.bad);
}

INSTANTIATE_TEST_SUITE_P (BadInput, Matrix, ::testing::ValuesIn (allCases ()), caseName);
}  // namespace

TEST (ModelFile, FolderAndMissingFileAreRefused)
{
  char pattern[] = "/tmp/pcl_ext_model_folder_XXXXXX";
  ASSERT_NE (::mkdtemp (pattern), nullptr);
  const std::string folder = pattern;
  MultiscaleCrfModel model;
  ::testing::internal::CaptureStderr ();
  EXPECT_FALSE (model.loadModel (folder));
  EXPECT_FALSE (model.loadModel (folder + "/missing.txt"));
  const std::string log = ::testing::internal::GetCapturedStderr ();
  EXPECT_NE (log.find ("not a regular file"), std::string::npos) << log;
  EXPECT_NE (log.find ("missing.txt is missing"), std::string::npos) << log;
  EXPECT_FALSE (model.isTrained ());
  ::rmdir (folder.c_str ());
}
