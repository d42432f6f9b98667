/*
 * pcl_ext: wall planes from the roof outlines of an airborne cloud, for plane matching
 * (Khoshelham & Gorte 2009, section 3.1, with airborne data).
 */
#pragma once

#include <pcl_ext/registration/plane_extraction.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <vector>

namespace pcl_ext {
/** \brief Ground and wall planes of a classified airborne cloud: a ground plane, and
 * vertical planes through the roof outline of each building.
 *
 * Khoshelham & Gorte (2009) match planes extracted from a terrestrial scan to the walls
 * of a 2D map (section 3.1). An airborne cloud has dense roofs and almost no wall
 * points, so here walls stand in for the facades from where the roofs end. This is
 * pcl_ext's own; the paper extracts planes by a range-image segmentation and does not
 * treat airborne data:
 * - Ground: one RANSAC plane through the points of the ground label.
 * - Buildings: the points of the building label, clustered in 2D (x, y) with the
 * building tolerance, so that no wall is fitted across two buildings.
 * - Outline: a building point whose 2D neighbours lie to one side (their centroid is
 * offset by more than 0.35 of their mean spacing), with a point of another label beyond
 * it on that open side. Where the cloud's edge cuts a roof there is nothing beyond,
 * hence no wall: a plane along the cut would match nothing in the map, or the wrong
 * wall.
 * - Walls: per building, sequential RANSAC planes within the angle tolerance of
 * vertical through the outline points, each kept as its longest unbroken stretch along
 * the wall (points no farther apart than the maximum gap), so that one plane is one
 * stretch of outline and not two collinear ones across a courtyard or a street.
 *
 * Walls are planes in 3D through outline points, so an outline needs some spread in
 * height (roof noise, slopes, eaves of several heights): the edge of a perfectly flat,
 * noiseless roof is a line, through which RANSAC finds no plane. A thin band of outline
 * points leaves a wall's tilt loosely fitted (a few degrees in AHN3); its direction in
 * plan is well fitted.
 *
 * The labels are one per point of the input cloud (setInputLabels; e.g. the ASPRS LAS
 * classes 2 ground and 6 building, the defaults). Non-finite points are ignored. RANSAC
 * draws from a fixed seed (setSeed), so the planes are the same on every run.
 *
 * \code
 * pcl_ext::RoofOutlinePlaneExtraction<pcl::PointXYZ> walls;
 * walls.setInputLabels (labels);             // pcl::PointCloud<pcl::Label>, one per
 * point reg.setPlaneExtractor (walls.asExtractor ()); \endcode
 */
template <typename PointT>
class RoofOutlinePlaneExtraction : public pcl::PCLBase<PointT> {
public:
  using PointCloudConstPtr = typename pcl::PointCloud<PointT>::ConstPtr;
  using LabelCloud = pcl::PointCloud<pcl::Label>;
  using LabelCloudConstPtr = LabelCloud::ConstPtr;

  /** \brief One label per point of the input cloud (required). */
  void
  setInputLabels (const LabelCloudConstPtr& labels)
  {
    labels_ = labels;
  }
  LabelCloudConstPtr
  getInputLabels () const
  {
    return labels_;
  }

  /** \brief Label of ground points; default 2 (ASPRS LAS "ground"). Must differ from
   * the building label. */
  void
  setGroundLabel (std::uint32_t label)
  {
    ground_label_ = label;
  }
  std::uint32_t
  getGroundLabel () const
  {
    return ground_label_;
  }

  /** \brief Label of building (roof) points; default 6 (ASPRS LAS "building"). */
  void
  setBuildingLabel (std::uint32_t label)
  {
    building_label_ = label;
  }
  std::uint32_t
  getBuildingLabel () const
  {
    return building_label_;
  }

  /** \brief Whether a ground plane is extracted (first of the sets); default true. */
  void
  setExtractGround (bool extract)
  {
    extract_ground_ = extract;
  }
  bool
  getExtractGround () const
  {
    return extract_ground_;
  }

  /** \brief Inlier distance of the ground plane (m), > 0; default 0.3. */
  void
  setGroundDistanceThreshold (double distance)
  {
    ground_distance_ = distance;
  }
  double
  getGroundDistanceThreshold () const
  {
    return ground_distance_;
  }

  /** \brief Largest 2D gap between points of one building (m), > 0; default 1.0 (about
   * four times the 0.25 m spacing of AHN3). */
  void
  setBuildingTolerance (double distance)
  {
    building_tolerance_ = distance;
  }
  double
  getBuildingTolerance () const
  {
    return building_tolerance_;
  }

  /** \brief Least points of a building, >= 1; default 100 (smaller clusters: sheds,
   * noise). */
  void
  setMinBuildingPoints (int count)
  {
    min_building_points_ = count;
  }
  int
  getMinBuildingPoints () const
  {
    return min_building_points_;
  }

  /** \brief 2D neighbours that decide whether a building point is on the outline, >= 3;
   * default 12. */
  void
  setOutlineNeighbours (int count)
  {
    outline_neighbours_ = count;
  }
  int
  getOutlineNeighbours () const
  {
    return outline_neighbours_;
  }

  /** \brief How far beyond an outline point, on its open side, a point of another label
   * must be (m), > 0; default 1.0. The probe is placed this far out and searches within
   * this radius, so eaves over a narrow strip of ground still count. */
  void
  setOpenSideDistance (double distance)
  {
    open_side_distance_ = distance;
  }
  double
  getOpenSideDistance () const
  {
    return open_side_distance_;
  }

  /** \brief Outline band: inlier distance of a wall plane (m), > 0; default 0.3. Roof
   * edges are jagged (eaves, gutters, dormers): a narrower band splits a wall, a wider
   * one joins a wall to the next. */
  void
  setOutlineBand (double distance)
  {
    outline_band_ = distance;
  }
  double
  getOutlineBand () const
  {
    return outline_band_;
  }

  /** \brief Largest angle of a wall's normal to the horizontal plane (degrees), in (0,
   * 90); default 5. */
  void
  setAngleTolerance (double degrees)
  {
    angle_tolerance_deg_ = degrees;
  }
  double
  getAngleTolerance () const
  {
    return angle_tolerance_deg_;
  }

  /** \brief Largest gap along a wall between consecutive inliers (m), > 0; default 1.5.
   */
  void
  setMaxGap (double distance)
  {
    max_gap_ = distance;
  }
  double
  getMaxGap () const
  {
    return max_gap_;
  }

  /** \brief Least points of a wall, >= 3; default 15. */
  void
  setMinWallPoints (int count)
  {
    min_wall_points_ = count;
  }
  int
  getMinWallPoints () const
  {
    return min_wall_points_;
  }

  /** \brief Most walls per building, >= 0; default 0: no limit. */
  void
  setMaxWallsPerBuilding (int count)
  {
    max_walls_per_building_ = count;
  }
  int
  getMaxWallsPerBuilding () const
  {
    return max_walls_per_building_;
  }

  /** \brief RANSAC iterations per plane, >= 1; default 500. */
  void
  setMaxIterations (int count)
  {
    max_iterations_ = count;
  }
  int
  getMaxIterations () const
  {
    return max_iterations_;
  }

  /** \brief Seed of the RANSAC draws; default 12345 (the fixed seed of PCL's models, so
   * the planes equal those of pcl::SACSegmentation). */
  void
  setSeed (unsigned int seed)
  {
    seed_ = seed;
  }
  unsigned int
  getSeed () const
  {
    return seed_;
  }

  /** \brief Inlier sets: the ground plane first (when there is one), then the walls,
   * building by building, sorted indices. No wall when no building has an outline
   * (nothing of another label around it, or too few points). No planes, after a
   * PCL_ERROR, on bad parameters, no input, no labels or a label count unlike the point
   * count, an index out of range, no finite point or no finite point of the building
   * label. */
  void
  extract (std::vector<pcl::PointIndices>& planes);

  /** \brief As a PlaneExtractor for PlaneMatchingRegistration. The labels go with it;
   * the cloud it is given must be the one they label (the registration's source). */
  PlaneExtractor<PointT>
  asExtractor () const;

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;

  /** \brief Whether the parameters are in range (PCL_ERROR naming the first that is
   * not). */
  bool
  checkParameters () const;

  LabelCloudConstPtr labels_;
  std::uint32_t ground_label_ = 2;
  std::uint32_t building_label_ = 6;
  bool extract_ground_ = true;
  double ground_distance_ = 0.3;
  double building_tolerance_ = 1.0;
  int min_building_points_ = 100;
  int outline_neighbours_ = 12;
  double open_side_distance_ = 1.0;
  double outline_band_ = 0.3;
  double angle_tolerance_deg_ = 5.0;
  double max_gap_ = 1.5;
  int min_wall_points_ = 15;
  int max_walls_per_building_ = 0;
  int max_iterations_ = 500;
  unsigned int seed_ = 12345u;
};

/** \brief The longest unbroken stretch of \a inliers along the horizontal line of a
 * vertical plane with normal \a normal: the points sorted along the line and split
 * where consecutive ones are more than \a max_gap apart. Sorted indices; ties keep the
 * first stretch.
 */
template <typename PointT>
pcl::Indices
longestWallStretch (const pcl::PointCloud<PointT>& cloud,
                    const pcl::Indices& inliers,
                    const Eigen::Vector3f& normal,
                    float max_gap);
} // namespace pcl_ext

#ifdef PCL_NO_PRECOMPILE
#include <pcl_ext/registration/impl/roof_outline_plane_extraction.hpp>
#endif
