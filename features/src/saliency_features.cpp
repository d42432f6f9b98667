/*
 * pcl_ext: Lim & Suter's saliency features (eq. 12) and section 4.1's other features.
 */
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/common/parallel.h>
#include <pcl_ext/features/saliency_features.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

namespace pcl_ext {
namespace {
constexpr double kTiny = 1e-12;
constexpr std::size_t kMinRegion = 5;
const char* const kScaleFeatures[] = {"clutterness",
                                      "surfaceness",
                                      "curveness",
                                      "linearity",
                                      "planarity",
                                      "scattering",
                                      "normal_angle",
                                      "tangent_angle",
                                      "log_density",
                                      "top_above",
                                      "bottom_below"};
constexpr std::size_t kNumScaleFeatures =
    sizeof (kScaleFeatures) / sizeof (kScaleFeatures[0]);

/** The eigen-decomposition of the points \a nn and their eq. 12 saliencies over radius
 * \a r (clutterness, surfaceness, curveness) into out(0 .. 2). */
template <typename Row>
EigenDecomposition
saliencies (const pcl::PointCloud<pcl::PointXYZ>& cloud,
            const pcl::Indices& nn,
            double r,
            Row& out)
{
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  Eigen::Vector3d centroid;
  EigenDecomposition eig;
  computeLocalCovariance (cloud, nn, cov, centroid);
  computeEigenDecomposition (cov, eig);
  const Eigen::Vector3d& l = eig.values;
  out (0) = static_cast<float> (std::log (std::max (l (0), kTiny)));
  out (1) = static_cast<float> (std::log (std::max (l (1) / r - l (0), kTiny)));
  out (2) = static_cast<float> (std::log (std::max (l (2) / r - l (1) / r, kTiny)));
  return eig;
}

/** Eq. 12, the dimensionality features and the angles of the eigen-decomposition of the
 * points \a nn over radius \a r, into out(0 .. 7). */
template <typename Row>
void
eigenFeatures (const pcl::PointCloud<pcl::PointXYZ>& cloud,
               const pcl::Indices& nn,
               double r,
               const Eigen::Vector3d& up,
               Row&& out)
{
  const EigenDecomposition eig = saliencies (cloud, nn, r, out);
  const Eigen::Vector3d& l = eig.values;
  const double l3 = std::max (l (2), kTiny);
  out (3) = static_cast<float> (std::max (0.0, l (2) - l (1)) / l3);
  out (4) = static_cast<float> (std::max (0.0, l (1) - l (0)) / l3);
  out (5) = static_cast<float> (std::max (0.0, l (0)) / l3);
  out (6) = static_cast<float> (
      std::acos (std::min (1.0, std::abs (eig.vectors.col (0).dot (up)))));
  out (7) = static_cast<float> (
      std::acos (std::min (1.0, std::abs (eig.vectors.col (2).dot (up)))));
}
} // namespace

std::vector<float>
defaultFeatureScales ()
{
  return {0.5f, 1.f, 2.f};
}

std::string
featureScaleSuffix (float radius)
{
  char buf[32];
  std::snprintf (buf, sizeof (buf), "@%g", static_cast<double> (radius));
  return buf;
}

bool
validFeatureScales (const std::vector<float>& scales)
{
  for (std::size_t k = 0; k < scales.size(); ++k)
    if (!(scales[k] > 0.f) || !std::isfinite (scales[k]) ||
        (k > 0 && !(scales[k] > scales[k - 1])))
      return false;
  return true;
}

namespace {
/** The map key of cell (x, y). */
std::uint64_t
cellKey (int x, int y)
{
  return (static_cast<std::uint64_t> (static_cast<std::uint32_t> (x)) << 32) |
         static_cast<std::uint32_t> (y);
}

int
cellX (std::uint64_t key)
{
  return static_cast<int> (static_cast<std::uint32_t> (key >> 32));
}

int
cellY (std::uint64_t key)
{
  return static_cast<int> (static_cast<std::uint32_t> (key & 0xffffffffu));
}

/** Block minimum (\a take_min) or maximum of the cells \a in over the (2 reach + 1)^2
 * cells around each cell, separably (rows, then columns), scattered from the cells that
 * have a value to the cells within reach of them: only cells with a value are stored.
 */
LocalGround::CellMap
blockExtremum (const LocalGround::CellMap& in, int reach, bool take_min)
{
  auto scatter = [&] (const LocalGround::CellMap& from, bool along_x) {
    LocalGround::CellMap to;
    to.reserve (from.size() * static_cast<std::size_t> (2 * reach + 1));
    for (const auto& [key, value] : from) {
      const int x = cellX (key), y = cellY (key);
      const int c = along_x ? x : y;
      for (int k = c - reach; k <= c + reach; ++k) {
        const auto [it, inserted] =
            to.emplace (along_x ? cellKey (k, y) : cellKey (x, k), value);
        if (!inserted)
          it->second =
              take_min ? std::min (it->second, value) : std::max (it->second, value);
      }
    }
    return to;
  };
  return scatter (scatter (in, true), false);
}

/** Largest cell index magnitude kept (the cell's indices must fit an int). */
constexpr float kMaxCellIndex = 1073741824.f; // 2^30
} // namespace

const char*
groundEstimateName (GroundEstimate estimate)
{
  return estimate == GroundEstimate::Opening ? "opening" : "lowest_in_block";
}

bool
parseGroundEstimate (const std::string& text, GroundEstimate& estimate)
{
  if (text == "lowest_in_block")
    estimate = GroundEstimate::LowestInBlock;
  else if (text == "opening")
    estimate = GroundEstimate::Opening;
  else
    return false;
  return true;
}

bool
LocalGround::cellOf (const Eigen::Vector3f& p, Eigen::Vector2i& cell) const
{
  const float x = std::floor (p.dot (u_) / cell_);
  const float y = std::floor (p.dot (v_) / cell_);
  if (!(std::abs (x) <= kMaxCellIndex && std::abs (y) <= kMaxCellIndex))
    return false;
  cell = Eigen::Vector2i (static_cast<int> (x), static_cast<int> (y));
  return true;
}

void
LocalGround::build (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                    const Eigen::Vector3f& up,
                    float cell,
                    int reach,
                    GroundEstimate estimate)
{
  up_ = up.normalized();
  u_ = up_.unitOrthogonal();
  v_ = up_.cross (u_);
  cell_ = cell > 0.f ? cell : 1.f;
  reach_ = std::max (0, reach);
  ground_.clear();
  // The lowest point per occupied cell.
  CellMap lowest;
  for (const auto& p : cloud) {
    Eigen::Vector2i c;
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z) ||
        !cellOf (p.getVector3fMap(), c))
      continue;
    const float h = p.getVector3fMap().dot (up_);
    const auto [it, inserted] = lowest.emplace (cellKey (c.x(), c.y()), h);
    if (!inserted)
      it->second = std::min (it->second, h);
  }
  if (lowest.empty())
    return;
  ground_ = blockExtremum (lowest, reach_, true);
  if (estimate == GroundEstimate::Opening)
    ground_ = blockExtremum (ground_, reach_, false);
}

float
LocalGround::heightAbove (const Eigen::Vector3f& p) const
{
  Eigen::Vector2i c;
  if (ground_.empty() || !cellOf (p, c))
    return 0.f;
  const auto it = ground_.find (cellKey (c.x(), c.y()));
  return it == ground_.end() ? 0.f : p.dot (up_) - it->second;
}

std::vector<std::string>
saliencyFeatureNames (const SaliencyFeatureOptions& options)
{
  std::vector<std::string> names{"clutterness",
                                 "surfaceness",
                                 "curveness",
                                 "normal_angle",
                                 "tangent_angle",
                                 "height",
                                 "log_radius"};
  if (options.colour)
    names.insert (names.end(), {"red", "green", "blue"});
  if (options.intensity)
    names.emplace_back ("intensity");
  for (const float r : options.scales)
    for (const char* name : kScaleFeatures)
      names.push_back (name + featureScaleSuffix (r));
  for (std::size_t k = 1; k < options.scales.size(); ++k)
    names.push_back ("dimension" + featureScaleSuffix (options.scales[k]));
  return names;
}

bool
computeSaliencyFeatures (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                         const search::KdTree3f& tree,
                         const std::vector<Eigen::Vector3f>& colours,
                         const std::vector<float>& intensity,
                         const LocalGround& ground,
                         const std::vector<pcl::index_t>& centres,
                         const std::vector<float>& radii,
                         const SaliencyFeatureOptions& options,
                         Eigen::MatrixXf& features,
                         unsigned int threads)
{
  features.resize (0, 0);
  const char* bad = nullptr;
  if (centres.size() != radii.size())
    bad = "one radius per centre is needed";
  else if (options.colour && colours.size() != cloud.size())
    bad = "colour features need one colour per point";
  else if (options.intensity && intensity.size() != cloud.size())
    bad = "intensity features need one intensity per point";
  else if (tree.size() == 0)
    bad = "the search tree is empty";
  else if (!validFeatureScales (options.scales))
    bad = "feature scales must be positive, finite and ascending";
  if (bad) {
    PCL_ERROR ("[pcl_ext::computeSaliencyFeatures] %s.\n", bad);
    return false;
  }
  const Eigen::Vector3f up = options.up.normalized();
  const std::size_t dims = saliencyFeatureNames (options).size();
  features.resize (static_cast<Eigen::Index> (centres.size()),
                   static_cast<Eigen::Index> (dims));
  const int nthreads = static_cast<int> (resolveThreadCount (threads));
#pragma omp parallel num_threads(nthreads)
  {
    pcl::Indices nn, wide, at;
    std::vector<float> d2, wide_d2;
#pragma omp for schedule(dynamic, 64)
    for (std::ptrdiff_t row = 0; row < static_cast<std::ptrdiff_t> (centres.size());
         ++row) {
      const auto& p = cloud[static_cast<std::size_t> (centres[row])];
      const double r = std::max (static_cast<double> (radii[row]), 1e-6);
      tree.radiusSearch (p.data, r, nn, d2);
      if (nn.size() < kMinRegion) {
        const std::size_t k = std::min (kMinRegion, tree.size());
        nn.resize (k);
        d2.resize (k);
        nn.resize (tree.nearestKSearch (p.data, k, nn.data(), d2.data()));
      }
      auto out = features.row (row);
      const EigenDecomposition eig = saliencies (cloud, nn, r, out);
      const double cn =
          std::min (1.0, std::abs (eig.vectors.col (0).dot (up.cast<double>())));
      const double ct =
          std::min (1.0, std::abs (eig.vectors.col (2).dot (up.cast<double>())));
      out (3) = static_cast<float> (std::acos (cn));
      out (4) = static_cast<float> (std::acos (ct));
      out (5) = ground.heightAbove (p.getVector3fMap());
      out (6) = static_cast<float> (std::log (r));
      Eigen::Index col = 7;
      if (options.colour) {
        Eigen::Vector3f sum = Eigen::Vector3f::Zero();
        for (const auto i : nn)
          sum += colours[static_cast<std::size_t> (i)];
        out.segment<3> (col) =
            sum / static_cast<float> (std::max<std::size_t> (1, nn.size()));
        col += 3;
      }
      if (options.intensity) {
        double sum = 0.0;
        for (const auto i : nn)
          sum += intensity[static_cast<std::size_t> (i)];
        out (col) = static_cast<float> (sum / std::max<std::size_t> (1, nn.size()));
        ++col;
      }
      if (options.scales.empty())
        continue;
      // One search at the largest radius; the smaller ones are its subsets.
      const Eigen::Vector3f pv = p.getVector3fMap();
      tree.radiusSearch (p.data, options.scales.back(), wide, wide_d2);
      const Eigen::Index first_scale = col;
      for (const float R : options.scales) {
        at.clear();
        const float R2 = R * R;
        for (std::size_t k = 0; k < wide.size(); ++k)
          if (wide_d2[k] <= R2)
            at.push_back (wide[k]);
        const double density = static_cast<double> (at.size());
        if (at.size() < kMinRegion) {
          const std::size_t k = std::min (kMinRegion, tree.size());
          at.resize (k);
          std::vector<float> kd2 (k);
          at.resize (tree.nearestKSearch (p.data, k, at.data(), kd2.data()));
        }
        eigenFeatures (cloud, at, R, up.cast<double>(), out.segment<8> (col));
        float top = 0.f, bottom = 0.f;
        const float h = pv.dot (up);
        for (const auto i : at) {
          const float hi =
              cloud[static_cast<std::size_t> (i)].getVector3fMap().dot (up);
          top = std::max (top, hi - h);
          bottom = std::max (bottom, h - hi);
        }
        out (col + 8) = static_cast<float> (std::log (std::max (density, 1.0)));
        out (col + 9) = top;
        out (col + 10) = bottom;
        col += static_cast<Eigen::Index> (kNumScaleFeatures);
      }
      // The dimension between consecutive radii: how the number of neighbours grows
      // with the radius (1 along a wire or a pole, 2 on a plane, 3 in a crown).
      for (std::size_t k = 1; k < options.scales.size(); ++k) {
        const Eigen::Index at_k =
            first_scale + static_cast<Eigen::Index> (k * kNumScaleFeatures + 8);
        const Eigen::Index at_prev =
            at_k - static_cast<Eigen::Index> (kNumScaleFeatures);
        out (col++) =
            (out (at_k) - out (at_prev)) /
            static_cast<float> (std::log (options.scales[k] / options.scales[k - 1]));
      }
    }
  }
  return true;
}
} // namespace pcl_ext
