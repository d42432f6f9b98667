/*
 * Determinism: the same input gives bit-identical output over two runs and for 1 and 2
 * threads, for the classes whose own tests do not already check it (see test/README.md
 * for the whole list). Inputs hold NaN points, so the non-dense paths are covered as
 * well.
 */
#include "analytic_clouds.h"
#include "plane_fixtures.h"

#include <pcl_ext/classification/multiscale_crf_classification.h>
#include <pcl_ext/features/chi_squared_boundary.h>
#include <pcl_ext/features/covariance_features.h>
#include <pcl_ext/features/curvature_variance.h>
#include <pcl_ext/features/projected_normal_curvatures.h>
#include <pcl_ext/features/saliency_feature_estimation.h>
#include <pcl_ext/registration/map_planes.h>
#include <pcl_ext/registration/plane_extraction.h>
#include <pcl_ext/registration/plane_matching_registration.h>
#include <pcl_ext/search/nanoflann_kdtree.h>
#include <pcl_ext/segmentation/adaptive_radius.h>
#include <pcl_ext/simulation/scenes.h>

#include <pcl/common/io.h>
#include <pcl/point_traits.h>

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

using namespace pcl_ext;

namespace {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using RgbCloud = pcl::PointCloud<pcl::PointXYZRGB>;
const float kNaN = std::numeric_limits<float>::quiet_NaN();

/** The bytes of every field of every point, without padding, so that clouds compare bit
 * for bit (NaN included). */
template <typename PointT>
std::vector<std::uint8_t>
fieldBytes (const pcl::PointCloud<PointT>& cloud)
{
  std::vector<std::uint8_t> bytes;
  const auto fields = pcl::getFields<PointT>();
  for (const auto& p : cloud)
    for (const auto& f : fields) {
      const auto* begin = reinterpret_cast<const std::uint8_t*> (&p) + f.offset;
      bytes.insert (bytes.end(),
                    begin,
                    begin + pcl::getFieldSize (f.datatype) *
                                std::max<std::uint32_t> (f.count, 1));
    }
  return bytes;
}

std::vector<std::uint8_t>
matrixBytes (const Eigen::MatrixXf& m)
{
  std::vector<std::uint8_t> bytes (static_cast<std::size_t> (m.size()) *
                                   sizeof (float));
  if (!bytes.empty())
    std::memcpy (bytes.data(), m.data(), bytes.size());
  return bytes;
}

/** Runs \a run with 1 thread, then twice with 2 threads (fresh objects each time): all
 * three results must be identical and not empty. */
template <typename Run>
void
expectDeterministic (Run&& run)
{
  const auto one = run (1u);
  const auto two = run (2u);
  const auto again = run (2u);
  ASSERT_FALSE (one.empty());
  EXPECT_TRUE (one == two) << "1 and 2 threads differ";
  EXPECT_TRUE (two == again) << "two runs with 2 threads differ";
}

/** A noisy cube with NaN points sprinkled in (not dense). */
Cloud::Ptr
cubeWithNaN ()
{
  Cloud::Ptr cloud = pcl_ext::test::makeCube (1.0, 0.04, 0.002, 3).cloud;
  for (std::size_t i = 0; i < cloud->size(); i += 97)
    (*cloud)[i].x = kNaN;
  cloud->is_dense = false;
  return cloud;
}

const Cloud::Ptr&
cube ()
{
  static const Cloud::Ptr c = cubeWithNaN();
  return c;
}

pcl::PointCloud<CovarianceFeatures>::Ptr
covarianceOf (const Cloud::ConstPtr& cloud, unsigned int threads)
{
  pcl::PointCloud<CovarianceFeatures>::Ptr out (
      new pcl::PointCloud<CovarianceFeatures>);
  CovarianceFeatureEstimation<pcl::PointXYZ> est;
  est.setInputCloud (cloud);
  est.setKSearch (30);
  est.setNumberOfThreads (threads);
  est.compute (*out);
  return out;
}

/** A small generated street scene with colour (the CRF's classes as labels). */
struct Street {
  RgbCloud::Ptr cloud{new RgbCloud};
  std::vector<std::uint32_t> labels;
};

const Street&
street (std::uint64_t seed)
{
  static std::map<std::uint64_t, Street> cache;
  auto it = cache.find (seed);
  if (it != cache.end())
    return it->second;
  Street s;
  simulation::SceneParameters p;
  p.seed = seed;
  p.points = 8000;
  p.threads = 1;
  simulation::SyntheticScene scene;
  EXPECT_TRUE (simulation::generateScene ("street", p, scene));
  for (const auto& q : scene.cloud) {
    pcl::PointXYZRGB r (q.r, q.g, q.b);
    r.x = q.x;
    r.y = q.y;
    r.z = q.z;
    s.cloud->push_back (r);
    s.labels.push_back (q.label);
  }
  return cache.emplace (seed, std::move (s)).first->second;
}
} // namespace

TEST (Deterministic, CovarianceFeatureEstimation)
{
  expectDeterministic ([] (unsigned int threads) {
    return fieldBytes (*covarianceOf (cube(), threads));
  });
}

TEST (Deterministic, CurvatureVarianceEstimation)
{
  const auto normals = covarianceOf (cube(), 1);
  expectDeterministic ([&] (unsigned int threads) {
    CurvatureVarianceEstimation<pcl::PointXYZ, CovarianceFeatures> est;
    est.setInputCloud (cube());
    est.setInputNormals (normals);
    est.setKSearch (30);
    est.setNumberOfThreads (threads);
    pcl::PointCloud<CurvatureVariance> out;
    est.compute (out);
    return fieldBytes (out);
  });
}

TEST (Deterministic, ChiSquaredBoundaryEstimation)
{
  expectDeterministic ([] (unsigned int threads) {
    ChiSquaredBoundaryEstimation<pcl::PointXYZ> est;
    est.setInputCloud (cube());
    est.setKSearch (30);
    est.setNumberOfThreads (threads);
    pcl::PointCloud<pcl::Boundary> out;
    est.compute (out);
    return fieldBytes (out);
  });
}

TEST (Deterministic, ProjectedNormalCurvaturesEstimation)
{
  const auto normals = covarianceOf (cube(), 1);
  expectDeterministic ([&] (unsigned int threads) {
    ProjectedNormalCurvaturesEstimation<pcl::PointXYZ, CovarianceFeatures> est;
    est.setInputCloud (cube());
    est.setInputNormals (normals);
    est.setKSearch (30);
    est.setNumberOfThreads (threads);
    pcl::PointCloud<pcl::PrincipalCurvatures> out;
    est.compute (out);
    return fieldBytes (out);
  });
}

TEST (Deterministic, SaliencyFeatureEstimation)
{
  const Street& s = street (1);
  expectDeterministic ([&] (unsigned int threads) {
    SaliencyFeatureEstimation<pcl::PointXYZRGB> est;
    est.setInputCloud (s.cloud);
    est.setRadius (0.3f);
    est.setNumberOfThreads (threads);
    Eigen::MatrixXf f;
    est.compute (f);
    return matrixBytes (f);
  });
}

TEST (Deterministic, MultiscaleCrfClassification)
{
  const Street& train = street (1);
  const Street& test = street (2);
  expectDeterministic ([&] (unsigned int threads) {
    MultiscaleCrfClassification<pcl::PointXYZRGB> crf;
    crf.setNumberOfThreads (threads);
    EXPECT_TRUE (crf.train ({train.cloud}, {train.labels}));
    crf.setInputCloud (test.cloud);
    pcl::PointCloud<pcl::Label> labels;
    crf.classify (labels);
    std::vector<std::uint8_t> bytes = fieldBytes (labels);
    const auto p = matrixBytes (crf.getProbabilities());
    bytes.insert (bytes.end(), p.begin(), p.end());
    return bytes;
  });
}

TEST (Deterministic, AdaptiveRadiusEstimator)
{
  Cloud::Ptr cloud (new Cloud);
  pcl::copyPointCloud (*street (1).cloud, *cloud);
  // The estimator has no thread setting: two runs, each estimating every 10th point.
  const auto run = [&] (unsigned int) {
    AdaptiveRadiusEstimator est;
    est.initialize (cloud, {}, AdaptiveRadiusParameters());
    std::vector<float> radii;
    for (std::size_t i = 0; i < cloud->size(); i += 10)
      if (pcl::isFinite ((*cloud)[i]))
        radii.push_back (est.estimate (static_cast<pcl::index_t> (i)));
    radii.push_back (static_cast<float> (est.getNoise()));
    return radii;
  };
  expectDeterministic (run);
}

TEST (Deterministic, NanoflannKdTree)
{
  expectDeterministic ([] (unsigned int) {
    search::NanoflannKdTree<pcl::PointXYZ> tree;
    tree.setInputCloud (cube());
    std::vector<float> out;
    pcl::Indices k_indices;
    std::vector<float> k_distances;
    for (std::size_t i = 0; i < cube()->size(); i += 13) {
      if (!pcl::isFinite ((*cube())[i]))
        continue;
      tree.nearestKSearch ((*cube())[i], 8, k_indices, k_distances);
      for (std::size_t j = 0; j < k_indices.size(); ++j) {
        out.push_back (static_cast<float> (k_indices[j]));
        out.push_back (k_distances[j]);
      }
    }
    return out;
  });
}

TEST (Deterministic, SACPlaneExtraction)
{
  // RANSAC draws from PCL's fixed seed: two runs find the same planes.
  Cloud::Ptr cloud (new Cloud);
  pcl::copyPointCloud (*pcl_ext::test::makeCube (1.0, 0.03, 0.003, 5).cloud, *cloud);
  expectDeterministic ([&] (unsigned int) {
    SACPlaneExtraction<pcl::PointXYZ> sac;
    sac.setInputCloud (cloud);
    sac.setDistanceThreshold (0.01);
    sac.setMaxPlanes (6);
    std::vector<pcl::PointIndices> planes;
    sac.extract (planes);
    std::vector<pcl::index_t> flat;
    for (const auto& p : planes) {
      flat.push_back (-1);
      flat.insert (flat.end(), p.indices.begin(), p.indices.end());
    }
    return flat;
  });
}

TEST (Deterministic, PlaneMatchingRegistration)
{
  // Scan planes of the H-shaped building in a random pose, matched to its footprint.
  std::vector<MapPlane> map;
  ASSERT_TRUE (computeMapPlanes (test::asymmetricH(), MapPlaneParameters(), map));
  std::mt19937 rng (5);
  const Eigen::Matrix4d truth = test::randomPose (rng);
  const auto scan = test::scanPlanes (map, truth, rng, 0.2 * M_PI / 180.0, 0.05, 1, 2);
  std::vector<ScanPlane> source;
  for (const auto& plane : scan) {
    ScanPlane s;
    static_cast<Plane&> (s) = plane;
    source.push_back (s);
  }
  Cloud::Ptr dummy (new Cloud);
  dummy->resize (10, pcl::PointXYZ (0, 0, 0));
  expectDeterministic ([&] (unsigned int threads) {
    PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
    reg.setInputSource (dummy);
    reg.setMapPlanes (map);
    reg.setSourcePlanes (source);
    reg.setNumberOfThreads (threads);
    Cloud aligned;
    reg.align (aligned);
    EXPECT_TRUE (reg.hasConverged());
    std::vector<double> out;
    const Eigen::Matrix4d t = reg.getFinalTransformationDouble();
    out.assign (t.data(), t.data() + 16);
    for (const auto& pair : reg.getMatchingResult().matches) {
      out.push_back (pair.scan);
      out.push_back (pair.map);
    }
    return out;
  });
}
