/*
 * The harness of the bad-input matrix (test_bad_input.cpp): the inputs (Bad, Input),
 * what a class under test did (Outcome), the classes under test (Subject) and the
 * helpers their entries share. The entries of each module append to the table with
 * add<Module>Subjects.
 */
#pragma once

#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/PointIndices.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pcl_ext {
namespace test {
namespace bad_input {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Normals = pcl::PointCloud<pcl::Normal>;
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

/** The columns of the matrix. */
enum class Bad {
  EmptyCloud,
  AllNaN,
  SomeNaNDense,    ///< NaN and Inf points in a cloud that claims is_dense
  SomeNaNNotDense, ///< the same with is_dense false
  OnePoint,
  KLargerThanCloud, ///< 6 points, k = 10
  DuplicatePoints,  ///< every point three times
  Collinear,
  Coplanar,
  Utm,  ///< x ~ 500,000 m, y ~ 6,000,000 m
  Tiny, ///< the whole cloud within a few 1e-6 m
  IndicesOutOfRange,
  NegativeParameter,
  ZeroParameter,
  NaNParameter,
  MissingNormals,
  WrongSizeNormals
};

/** The name of each column (the cases follow its order). */
extern const std::map<Bad, const char*> kBadNames;

enum class Expect { Refused, Computed, Degenerate, NoneFound, Ran };

/** What a subject is given. */
struct Input {
  Cloud::Ptr cloud;
  pcl::IndicesPtr indices;     ///< null: all points
  std::optional<double> param; ///< the subject's checked parameter, when set
  bool nan_param =
      false;            ///< param is NaN (kept apart so optional<double> stays simple)
  Normals::Ptr normals; ///< one per point unless the input is about normals
  int k = 10;           ///< k for the k-based subjects
  double scale = 1.0;   ///< size of the cloud's features relative to the 1 m cube
};

/** What a subject did, in the same terms for every class. */
struct Outcome {
  bool produced = false; ///< any output (a converged registration)
  std::size_t size = 0;  ///< outputs (rows, labels), or indices covered by segments
  std::vector<char> no_result;  ///< per index: the documented "no result"
  bool finite_transform = true; ///< registration only
};

/** A class under test: one row of the matrix. */
struct Subject {
  std::string name;
  std::set<Bad> applies;              ///< the inputs that make sense for it
  std::map<Bad, Expect> expectations; ///< outcomes other than defaultExpectation()
  std::function<Outcome (const Input&)> run;
  std::function<void()> prepare; ///< when set, run before stderr is captured
};

/** The inputs of every class that takes a cloud. */
extern const std::set<Bad> kCloudInputs;

std::set<Bad>
with (std::set<Bad> set, std::initializer_list<Bad> more);

std::set<Bad>
without (std::set<Bad> set, std::initializer_list<Bad> less);

/** The expected outcome of \a bad unless a subject says otherwise. */
Expect
defaultExpectation (Bad bad);

/** The cloud, normals, indices and parameter for the column \a bad. */
Input
inputFor (Bad bad);

/** The indices a subject's outputs correspond to. */
std::vector<pcl::index_t>
indicesOf (const Input& in);

/** Per-index outcome of a feature cloud: "no result" where \a invalid says so. */
template <typename PointOutT, typename Invalid>
Outcome
perPoint (const pcl::PointCloud<PointOutT>& out, Invalid&& invalid)
{
  Outcome o;
  o.produced = !out.empty();
  o.size = out.size();
  for (const auto& p : out)
    o.no_result.push_back (invalid (p) ? 1 : 0);
  return o;
}

/** Outcome of a segmentation: index r has "no result" when no segment holds it. */
Outcome
segments (const Input& in, const std::vector<pcl::PointIndices>& clusters);

/** k, or (the NaN parameter) a NaN radius, for PCL-style features. */
template <typename Estimator>
void
setNeighbourhood (Estimator& est, const Input& in)
{
  if (in.nan_param) {
    est.setKSearch (0);
    est.setRadiusSearch (std::numeric_limits<double>::quiet_NaN());
  }
  else
    est.setKSearch (in.param ? static_cast<int> (*in.param) : in.k);
}

template <typename Estimator>
void
setCommon (Estimator& est, const Input& in)
{
  est.setInputCloud (in.cloud);
  if (in.indices)
    est.setIndices (in.indices);
  est.setNumberOfThreads (2);
}

inline bool
isNaN (float v)
{
  return std::isnan (v);
}

/** The rows of each module, appended to \a s in the order of the cases. */
void
addFeatureSubjects (std::vector<Subject>& s);
void
addClassificationSubjects (std::vector<Subject>& s);
void
addSegmentationSubjects (std::vector<Subject>& s);
void
addCrfSubjects (std::vector<Subject>& s);
void
addRegistrationSubjects (std::vector<Subject>& s);
} // namespace bad_input
} // namespace test
} // namespace pcl_ext
