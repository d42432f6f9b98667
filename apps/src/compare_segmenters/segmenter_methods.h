/*
 * pcl_ext_compare_segmenters: the segmenters compared, as a table of name -> runner.
 */
#pragma once

#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <functional>
#include <string>
#include <vector>

namespace pcl_ext {
namespace compare {
/** \brief The cloud every method segments: finite points only, loaded once. */
struct SegmenterInput {
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud;
  /** \brief The same points with their colour; null when the file has no rgb / rgba
   * field. */
  pcl::PointCloud<pcl::PointXYZRGBA>::ConstPtr coloured;
  /** \brief Normals (pcl::NormalEstimationOMP, k nearest neighbours), computed once,
   * set for the methods that need them. */
  pcl::PointCloud<pcl::Normal>::ConstPtr normals;
};

/** \brief Parameters shared by the methods. Every length is a multiple of the point
 * spacing s (one rule for all methods); angles are in degrees. */
struct SegmenterSettings {
  double spacing = 0.0;     ///< s, the mean point spacing (m)
  int k = 30;               ///< neighbours of the normals and of pcl::RegionGrowing
  int normal_k = 0;         ///< neighbours of the normals when not k (0: k)
  unsigned int threads = 0; ///< 0: all cores (methods that run in parallel)
  int min_size = 50; ///< smallest segment kept, where a method has this parameter
  double tolerance =
      3.0; ///< connection distance / s (Euclidean, CEC, profiles, plane split)
  double angle = 5.0; ///< normal angle (deg): RegionGrowing smoothness, CEC condition
  double curvature = 1.0;      ///< RegionGrowing curvature threshold
  double plane_distance = 2.0; ///< SAC plane inlier distance / s
  int max_planes = 100;        ///< SAC: most planes extracted
  double voxel = 2.0;          ///< SupervoxelClustering voxel resolution / s
  double seed = 8.0;           ///< SupervoxelClustering seed resolution / s
  double concavity = 10.0;     ///< LCCP concavity tolerance (deg)
  // Profile segmentation options that are not the paper's (all off: the paper).
  bool profile_aicc = false; ///< curve fitting: polynomials chosen by AICc
  double profile_turn_significance =
      0; ///< curve fitting: turns must exceed z standard errors
  bool profile_side_frames =
      false; ///< curve fitting: each side fitted in its own frame
  bool profile_local_threshold = false; ///< thresholds that follow the local density
};

/** \brief One method of the comparison. */
struct SegmenterMethod {
  using Runner = std::function<bool (const SegmenterInput&,
                                     const SegmenterSettings&,
                                     std::vector<pcl::PointIndices>&)>;
  std::string name;    ///< as given to -methods
  std::string library; ///< "pcl_ext", "PCL" or "CGAL"
  bool needs_normals;  ///< uses SegmenterInput::normals (their time is counted in its
                       ///< own)
  std::string description; ///< class and parameters, for -h
  Runner run;              ///< segments; false on failure
};

/** \brief pcl_ext's segmenters (pcl_ext_methods.cpp). */
std::vector<SegmenterMethod>
pclExtMethods ();

/** \brief Stock PCL segmenters (pcl_methods.cpp). */
std::vector<SegmenterMethod>
pclMethods ();

/** \brief CGAL's plane region growing (cgal_methods.cpp, built where CGAL is found:
 * allMethods() lists it then). */
std::vector<SegmenterMethod>
cgalMethods ();

/** \brief Every method, pcl_ext's first, in the order of the table. */
std::vector<SegmenterMethod>
allMethods ();
} // namespace compare
} // namespace pcl_ext
