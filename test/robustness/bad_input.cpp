/*
 * The inputs of the bad-input matrix (the bad clouds, normals, indices and parameters)
 * and the helpers the rows share (bad_input.h).
 */
#include "bad_input.h"

#include "analytic_clouds.h"

#include <pcl/common/point_tests.h>

#include <Eigen/Core>

namespace pcl_ext {
namespace test {
namespace bad_input {
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

const std::set<Bad> kCloudInputs = {Bad::EmptyCloud,
                                    Bad::AllNaN,
                                    Bad::SomeNaNDense,
                                    Bad::SomeNaNNotDense,
                                    Bad::OnePoint,
                                    Bad::DuplicatePoints,
                                    Bad::Collinear,
                                    Bad::Coplanar,
                                    Bad::Utm,
                                    Bad::Tiny,
                                    Bad::IndicesOutOfRange,
                                    Bad::NegativeParameter,
                                    Bad::ZeroParameter,
                                    Bad::NaNParameter};

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
  switch (bad) {
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

namespace {
/** A box open at the top (so that it has borders as well as creases) with noise, about
 * 900 points. */
Cloud::Ptr
baseCloud (double scale = 1.0, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero())
{
  const auto cube = pcl_ext::test::makeCube (1.0, 0.08, 0.002, 11);
  Cloud::Ptr cloud (new Cloud);
  for (const auto& p : *cube.cloud) {
    if (p.z > 0.99f)
      continue;
    const Eigen::Vector3d q = p.getVector3fMap().cast<double>() * scale + offset;
    cloud->push_back (Point (static_cast<float> (q.x()),
                             static_cast<float> (q.y()),
                             static_cast<float> (q.z())));
  }
  return cloud;
}

Cloud::Ptr
cloudFor (Bad bad)
{
  Cloud::Ptr cloud (new Cloud);
  switch (bad) {
  case Bad::EmptyCloud:
    break;
  case Bad::AllNaN:
    cloud->resize (200, Point (kNaN, kNaN, kNaN));
    cloud->is_dense = false;
    break;
  case Bad::SomeNaNDense:
  case Bad::SomeNaNNotDense:
    cloud = baseCloud();
    for (std::size_t i = 0; i < cloud->size(); i += 17)
      (*cloud)[i].y = kNaN;
    for (std::size_t i = 5; i < cloud->size(); i += 29)
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
  case Bad::DuplicatePoints: {
    const Cloud::Ptr base = baseCloud();
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
    cloud = baseCloud();
    break;
  }
  return cloud;
}

/** Normals (0, 0, 1) with a small varying curvature; NaN at non-finite points. */
Normals::Ptr
normalsFor (const Cloud& cloud)
{
  Normals::Ptr normals (new Normals);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    normals->push_back (pcl::isFinite (cloud[i])
                            ? pcl::Normal (0.f, 0.f, 1.f, 0.001f * (i % 7))
                            : pcl::Normal (kNaN, kNaN, kNaN, kNaN));
  return normals;
}
} // namespace

Input
inputFor (Bad bad)
{
  Input in;
  in.cloud = cloudFor (bad);
  in.normals = normalsFor (*in.cloud);
  in.scale = bad == Bad::Utm ? 50.0 : bad == Bad::Tiny ? 4e-6 : 1.0;
  switch (bad) {
  case Bad::IndicesOutOfRange:
    in.indices.reset (
        new pcl::Indices{0, 1, static_cast<pcl::index_t> (in.cloud->size() + 5)});
    break;
  case Bad::NegativeParameter:
    in.param = -1.0;
    break;
  case Bad::ZeroParameter:
    in.param = 0.0;
    break;
  case Bad::NaNParameter:
    in.nan_param = true;
    break;
  case Bad::MissingNormals:
    in.normals.reset();
    break;
  case Bad::WrongSizeNormals:
    in.normals->resize (in.normals->size() / 2);
    break;
  default:
    break;
  }
  return in;
}

std::vector<pcl::index_t>
indicesOf (const Input& in)
{
  if (in.indices)
    return *in.indices;
  std::vector<pcl::index_t> all (in.cloud->size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<pcl::index_t> (i);
  return all;
}

Outcome
segments (const Input& in, const std::vector<pcl::PointIndices>& clusters)
{
  Outcome o;
  o.produced = !clusters.empty();
  if (!o.produced)
    return o;
  std::set<pcl::index_t> covered;
  for (const auto& c : clusters)
    covered.insert (c.indices.begin(), c.indices.end());
  const auto indices = indicesOf (in);
  o.size = indices.size();
  for (const auto i : indices)
    o.no_result.push_back (covered.count (i) ? 0 : 1);
  return o;
}
} // namespace bad_input
} // namespace test
} // namespace pcl_ext
