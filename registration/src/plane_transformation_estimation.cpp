/*
 * pcl_ext: linear plane-to-plane transformation estimate (Khoshelham & Gorte 2009, eqs.
 * 8-12).
 */
#include <pcl_ext/registration/plane_transformation_estimation.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace pcl_ext {
namespace {
// A point of the scan plane where the data is: its centroid projected onto it (d n
// without one).
Eigen::Vector3d
anchor (const Plane& p)
{
  return p.project (p.centroid);
}
} // namespace

bool
estimatePlaneTransformation (const Plane* const* scan,
                             const Plane* const* map,
                             const int* signs,
                             int count,
                             PlaneTransformationModel model,
                             PlaneTransformationResult& result,
                             double min_conditioning,
                             bool per_pair)
{
  result.valid = false;
  result.degenerate = false;
  result.angle_residuals.clear();
  result.distance_residuals.clear();
  result.residual_norm = result.max_angle = result.max_distance = 0.0;
  result.conditioning = 0.0;
  const bool similarity = model == PlaneTransformationModel::Similarity;
  if (count < (similarity ? 4 : 3)) {
    result.degenerate = true;
    return false;
  }

  // Eq. 12 through the factored normal equations: N = sum n_m n_m^T, C = sum b n_m^T.
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 4, 3> c = Eigen::Matrix<double, 4, 3>::Zero();
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d& nm = map[i]->normal;
    const double s = signs[i];
    Eigen::Vector4d b;
    b.head<3>() = s * scan[i]->normal;
    b[3] = s * scan[i]->d - map[i]->d;
    normal_matrix.noalias() += nm * nm.transpose();
    c.noalias() += b * nm.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect (normal_matrix, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d values = eigen.eigenvalues();
  result.conditioning = values[2] > 0.0 ? std::max (0.0, values[0]) / values[2] : 0.0;
  if (!(result.conditioning >= min_conditioning)) {
    result.degenerate = true;
    return false;
  }
  const Eigen::Matrix3d normal_inverse = normal_matrix.inverse();
  result.affine = (c * normal_inverse).transpose();

  // Projection onto a rotation: the nearest orthonormal matrix with determinant +1, U
  // diag(1, 1, det) V^T from the SVD of the block. The inner loop of the search runs
  // this millions of times, so U comes from the eigen decomposition of B^T B = V S^2
  // V^T (U = B V S^-1), which is several times cheaper than a Jacobi SVD; a nearly
  // singular block takes the SVD.
  const Eigen::Matrix3d block = result.affine.leftCols<3>();
  Eigen::Matrix3d rotation;
  eigen.computeDirect (block.transpose() * block);
  const Eigen::Vector3d squared = eigen.eigenvalues(); // ascending
  if (squared[0] > 1e-6 * squared[2]) {
    const Eigen::Matrix3d v = eigen.eigenvectors();
    Eigen::Vector3d inverse_singular = squared.cwiseSqrt().cwiseInverse();
    if (block.determinant() < 0.0)
      inverse_singular[0] = -inverse_singular[0]; // flip the weakest direction
    rotation = block * v * inverse_singular.asDiagonal() * v.transpose();
  }
  else {
    Eigen::JacobiSVD<Eigen::Matrix3d> svd (block,
                                           Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
    fix (2, 2) =
        (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    rotation = svd.matrixU() * fix * svd.matrixV().transpose();
  }

  // Translation (and scale) from the distance rows of eq. 10, written at a point c of
  // each scan plane: n_m . (s R c + t) = d_m. With c = d_s n_s this is eq. 10's fourth
  // row; at the data, an angle error is not multiplied by the distance from the scan
  // origin to the building.
  Eigen::Vector3d t;
  double scale = 1.0;
  if (!similarity) {
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (int i = 0; i < count; ++i)
      rhs += map[i]->normal *
             (-map[i]->d - map[i]->normal.dot (rotation * anchor (*scan[i])));
    t = normal_inverse * rhs;
  }
  else {
    Eigen::Matrix4d n4 = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    for (int i = 0; i < count; ++i) {
      Eigen::Vector4d a;
      a.head<3>() = map[i]->normal;
      a[3] = map[i]->normal.dot (rotation * anchor (*scan[i]));
      n4.noalias() += a * a.transpose();
      rhs -= a * map[i]->d;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen4 (n4, Eigen::EigenvaluesOnly);
    const Eigen::Vector4d v4 = eigen4.eigenvalues();
    // The scale needs offsets that a translation cannot explain (planes not all through
    // one point).
    if (!(v4[3] > 0.0) || !(std::max (0.0, v4[0]) / v4[3] >= min_conditioning * 1e-3)) {
      result.degenerate = true;
      return false;
    }
    const Eigen::Vector4d x = n4.ldlt().solve (rhs);
    t = x.head<3>();
    scale = x[3];
    if (!(scale > 0.0)) {
      result.degenerate = true;
      return false;
    }
  }
  result.scale = scale;
  result.transformation.setIdentity();
  result.transformation.topLeftCorner<3, 3>() = scale * rotation;
  result.transformation.topRightCorner<3, 1>() = t;
  if (!result.transformation.allFinite())
    return false;

  // Residuals of the projected transform, the offsets measured at the same points.
  double sum = 0.0, min_cosine = 1.0;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d ns = signs[i] * scan[i]->normal;
    const Eigen::Vector3d& nm = map[i]->normal;
    const double cosine = std::clamp ((rotation * ns).dot (nm), -1.0, 1.0);
    const double distance =
        std::abs (nm.dot (scale * (rotation * anchor (*scan[i])) + t) + map[i]->d);
    if (per_pair) {
      result.angle_residuals.push_back (std::acos (cosine));
      result.distance_residuals.push_back (distance);
    }
    min_cosine = std::min (min_cosine, cosine);
    result.max_distance = std::max (result.max_distance, distance);
    sum += (ns - rotation.transpose() * nm).squaredNorm() + distance * distance;
  }
  result.max_angle = std::acos (min_cosine);
  result.residual_norm = std::sqrt (sum / count);
  result.valid = true;
  return true;
}

bool
estimatePlaneTransformation (const std::vector<Plane>& scan,
                             const std::vector<Plane>& map,
                             const std::vector<PlanePair>& pairs,
                             PlaneTransformationModel model,
                             PlaneTransformationResult& result,
                             double min_conditioning)
{
  std::vector<const Plane*> s, m;
  std::vector<int> signs;
  for (const auto& pair : pairs) {
    if (pair.scan < 0 || pair.map < 0 || pair.scan >= static_cast<int> (scan.size()) ||
        pair.map >= static_cast<int> (map.size()) ||
        (pair.sign != 1 && pair.sign != -1)) {
      result = PlaneTransformationResult();
      return false;
    }
    s.push_back (&scan[pair.scan]);
    m.push_back (&map[pair.map]);
    signs.push_back (pair.sign);
  }
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!s[i]->normal.allFinite() || !std::isfinite (s[i]->d) ||
        !s[i]->centroid.allFinite() || !m[i]->normal.allFinite() ||
        !std::isfinite (m[i]->d)) {
      result = PlaneTransformationResult();
      return false;
    }
  return estimatePlaneTransformation (s.data(),
                                      m.data(),
                                      signs.data(),
                                      static_cast<int> (s.size()),
                                      model,
                                      result,
                                      min_conditioning);
}
} // namespace pcl_ext
