/*
 * pcl_ext: Lim & Suter's saliency features (eq. 12) and the other per-region features
 * of their section 4.1, without the point type.
 */
#pragma once

#include <pcl_ext/search/kdtree_3f.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace pcl_ext {
/** \brief How LocalGround finds the ground under a position (pcl_ext's estimates; Lim &
 * Suter list "height" without saying how). */
enum class GroundEstimate {
  /** The lowest point of the (2 reach + 1)^2 cells around the position's cell (a block
   * minimum). Biased low wherever the ground slopes or is noisy: the ground points
   * themselves sit above it (docs/lim_suter.md has the figure on Oakland). */
  LowestInBlock,
  /** The morphological opening of the surface of the cells' lowest points (a block
   * minimum, then a block maximum of that over the same block): what is narrower than
   * the block (a pole, a trunk, a car) is removed, while a plane, sloping or not, is
   * kept as it is, so the ground points sit close above it. Cells without points within
   * the block take the opening of their neighbours (interpolation over small gaps). */
  Opening
};

/** \brief "lowest_in_block", "opening". */
const char*
groundEstimateName (GroundEstimate estimate);

/** \brief Parses "lowest_in_block", "opening"; false for anything else. */
bool
parseGroundEstimate (const std::string& text, GroundEstimate& estimate);

/** \brief Height of the local ground under any position, from a horizontal grid of the
 * lowest point per cell (pcl_ext's estimate; Lim & Suter list "height" without saying
 * how).
 *
 * The plane perpendicular to the up axis is cut into square cells; the ground under a
 * position is found from the lowest points of the (2 reach + 1)^2 cells around its cell
 * as GroundEstimate says. Where no point lies near (an isolated roof, say) the position
 * is its own ground (height 0).
 *
 * Only the cells that hold a ground height are stored (a hash map keyed by the cell),
 * not a grid over the bounding box: memory grows with the number of occupied cells
 * times (2 reach + 1)^2 (twice the reach with Opening), however far apart the points
 * are, so one distant outlier adds a few cells instead of a grid up to it. The heights
 * are those of a grid without bounds: the same as the former bounding-box grid with
 * LowestInBlock; with Opening they differ within 2 reach cells of the bounding box's
 * edge, which cut the block short there (and made the ground at the edge depend on
 * how far the farthest point was). Points more than 2^30 cells from the origin along
 * the plane are left out (their cell index would not fit an int).
 */
class LocalGround {
public:
  /** \param[in] up the up axis (normalised inside), the scanner's vertical
   * \param[in] cell cell size (m), > 0; \param[in] reach cells searched on each side,
   * >= 0 \param[in] estimate how the ground is found from the cells' lowest points */
  void
  build (const pcl::PointCloud<pcl::PointXYZ>& cloud,
         const Eigen::Vector3f& up,
         float cell,
         int reach,
         GroundEstimate estimate = GroundEstimate::LowestInBlock);

  /** \brief Height of \a p above the local ground (>= 0 up to the noise with
   * LowestInBlock; may be slightly negative with Opening). */
  float
  heightAbove (const Eigen::Vector3f& p) const;

  /** \brief Number of cells holding a ground height, what the memory grows with. */
  std::size_t
  getCellCount () const
  {
    return ground_.size();
  }

  /** \brief Cells keyed by their two indices. */
  using CellMap = std::unordered_map<std::uint64_t, float>;

private:
  /** The cell of \a p; false when its index would not fit an int. */
  bool
  cellOf (const Eigen::Vector3f& p, Eigen::Vector2i& cell) const;

  Eigen::Vector3f u_, v_, up_;
  float cell_ = 1.f;
  int reach_ = 0;
  CellMap ground_; // ground height per cell that has one
};

/** \brief What goes into a feature vector (Lim & Suter 2008, section 4.1). */
struct SaliencyFeatureOptions {
  Eigen::Vector3f up = Eigen::Vector3f::UnitZ(); ///< the scanner's up axis
  bool colour = false;                           ///< normalised RGB (needs rgb)
  bool intensity = false;                        ///< intensity (needs intensity)
  float ground_cell = 1.f;                       ///< LocalGround cell (m)
  int ground_reach = 3;                          ///< LocalGround cells on each side
  /** How LocalGround finds the ground (see GroundEstimate). */
  GroundEstimate ground_estimate = GroundEstimate::LowestInBlock;
  /** Fixed neighbourhood radii (m) of the multi-scale features, ascending, each > 0;
   * empty: the single-scale set (the paper's features at the region's own radius only).
   */
  std::vector<float> scales;
};

/** \brief Feature radii (m) of the multi-scale set (pcl_ext addition): 0.5, 1 and 2 m,
 * about a pole's or a wire's width, a trunk's crown and a facade bay on street scans.
 */
std::vector<float>
defaultFeatureScales ();

/** \brief The name suffix of the features at one fixed radius: "@" and the radius
 * ("%g"). */
std::string
featureScaleSuffix (float radius);

/** \brief Checks that \a scales are positive, finite and strictly ascending. */
bool
validFeatureScales (const std::vector<float>& scales);

/** \brief Column names of the feature vectors for \a options, in order:
 * clutterness, surfaceness, curveness (eq. 12), normal_angle (eq. 10), tangent_angle,
 * height, log_radius, then red green blue and intensity when asked for, then for each
 * fixed radius R of options.scales the eleven multi-scale features named with the
 * suffix "@R": clutterness, surfaceness, curveness, linearity, planarity, scattering,
 * normal_angle, tangent_angle, log_density, top_above, bottom_below; then for each
 * radius but the first, "dimension@R". */
std::vector<std::string>
saliencyFeatureNames (const SaliencyFeatureOptions& options);

/** \brief Feature vectors of points, each over the sphere of its own radius.
 *
 * With ascending eigenvalues l1 <= l2 <= l3 of the covariance of the points within r
 * (eq. 12): clutterness = log(l1), surfaceness = log(l2 / r - l1), curveness = log(l3 /
 * r - l2 / r); arguments are clamped to 1e-12 (they are negative when r > 1 m and the
 * region is isotropic). normal_angle = acos |n . up| with n the eigenvector of l1 (the
 * text's "largest" is a slip: a plane's normal is its direction of least spread; the
 * absolute value because a normal has no sign); tangent_angle = acos |e3 . up| with e3
 * the eigenvector of l3 (pcl_ext addition: tells poles from wires); height above
 * LocalGround; log_radius = log r (pcl_ext addition: the super-voxel size is itself
 * telling, large on flat ground); colour and intensity are neighbourhood means. Regions
 * of fewer than 5 points use the 5 nearest points instead.
 *
 * Multi-scale features (pcl_ext addition, after the multi-scale eigen features of
 * Weinmann et al. and CGAL's Classification): for each fixed radius R, over the points
 * within R of the centre: eq. 12 with r = R; the dimensionality features linearity =
 * (l3 - l2) / l3, planarity = (l2 - l1) / l3, scattering = l1 / l3, which do not depend
 * on the point density as the logs of eq. 12 do; the normal and tangent angles at R;
 * log_density = log of the number of points within R; top_above and bottom_below, the
 * height of the highest neighbour above the centre and of the centre above the lowest
 * (a wire has nothing under it within R, a pole has its own points above and below);
 * for each radius R_k but the first, dimension = (log n(R_k) - log n(R_k-1)) / log(R_k
 * / R_k-1), how the number of neighbours n grows with the radius (1 along a line, 2 on
 * a plane, 3 in a volume: the density ratio between scales, normalised). A single
 * region radius cannot see a pole's length or a wire's isolation: the super-voxels of
 * thin structures are small.
 *
 * \param[in] tree a KdTree3f over the finite points of \a cloud (point indices as
 * given) \param[in] colours normalised RGB per point (empty unless options.colour)
 * \param[in] intensity per point (empty unless options.intensity)
 * \param[in] centres finite point indices; \param[in] radii one radius per centre, > 0
 * \param[out] features one row per centre, saliencyFeatureNames(options).size ()
 * columns \return false with a PCL_ERROR when sizes disagree or something asked for is
 * missing
 */
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
                         unsigned int threads = 0);
} // namespace pcl_ext
