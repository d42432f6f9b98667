/*
 * pcl_ext: synthetic TLS scenes reproducing the test data of the papers pcl_ext
 * implements.
 */
#pragma once

#include <pcl_ext/simulation/scene_geometry.h>
#include <pcl_ext/simulation/simulated_point.h>

#include <pcl/point_cloud.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace simulation {
/** \brief Labels of the outdoor scenes (\c tree, \c street): Lim & Suter's five classes
 * (section 5: vegetation, trunk, man-made objects, pathway, terrain/grass). Poles and
 * wires are man-made objects, as signboards are in the paper. */
enum class OutdoorLabel : std::uint32_t {
  Vegetation = 1,
  Trunk = 2,
  ManMade = 3,
  Pathway = 4,
  Terrain = 5
};

/** \brief Parameters shared by every scene; 0 (or empty) means "the scene's default".
 */
struct SceneParameters {
  /// Noise and porosity draws, and the layout of the tree, street, cubes and spheres
  /// scenes (indoor, pipes, coaxial and building have one layout each; the building's
  /// frame pose is drawn from it too).
  std::uint64_t seed = 1;
  std::size_t points = 0; ///< target point count (chooses the angular step), <= 1e8
  double angular_step_deg =
      0.0;              ///< angular step in [0.001, 10] degrees; overrides \a points
  double noise = 0.005; ///< range noise sigma at zero range (m), >= 0
  double noise_per_metre = 0.0; ///< added range noise sigma per metre of range, >= 0
  double edge_distance = 0.0;   ///< class distance (m); 0 = local scan spacing
  /** \brief Also label Boundary where the scanned part of a surface ends in the merged
   * scans (shadows, silhouettes, the blind cone, the maximum incidence), see
   * TlsScanSimulation::setCoverageBoundaries. */
  bool coverage_boundaries = true;
  /** \brief One \c segment id per connected visible piece of a surface (true) or per
   * surface (false), see TlsScanSimulation::setConnectedSegments. */
  bool connected_segments = true;
  int num_scanners = 0; ///< number of scan positions (scene default when 0)
  std::vector<Eigen::Vector3d> scan_positions; ///< explicit positions (scene frame)
  double max_range = 0.0;                      ///< maximum range (m)
  /** \brief Added to the coordinates (building: to the map frame, i.e. the footprint
   * and the transform). Points are stored as floats, so a large offset costs precision
   * (3 cm steps at 445 km), as in georeferenced scans loaded without a local origin:
   * that is the point. */
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  unsigned int threads = 0; ///< 0 = all cores

  // building only (Khoshelham & Gorte section 4)
  /** \brief Map polygon (m, either orientation); empty = the H-shaped 40 x 30 m plan
   * with courtyards 10 and 8 m deep (no rotational symmetry, so registration is
   * unambiguous). */
  std::vector<Eigen::Vector2d> footprint;
  double building_height = 10.0; ///< wall height (m)
  int superfluous_planes =
      0; ///< neighbouring buildings and interior walls seen through windows
  int missing_walls = 0; ///< walls hidden behind a row of dense vegetation
  /** \brief Scan frame in a random pose drawn from the seed: yaw uniform in [0, 360)
   * deg, pitch and roll uniform in [-10, 10] deg, translation uniform in [-100, 100] m
   * horizontally and [-10, 10] m vertically; otherwise the scan frame is the map frame.
   */
  bool random_pose = true;
  bool has_pose = false; ///< use \a pose instead of a random one
  /** \brief Scan-from-map pose: scan = pose * map; the saved transform is its inverse.
   */
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

/** \brief The true geometry of a scene and how to scan it, before scanning. */
struct SceneDescription {
  std::string name;
  SceneGeometry geometry; ///< built, in the scene (map) frame
  std::vector<Eigen::Vector3d> scan_positions;
  double angular_step_deg = 0.1;  ///< default step
  std::size_t default_points = 0; ///< when > 0, the default is this many points
  double max_range = 150.0;
  bool has_rgb = false;
  bool has_intensity = false;
  bool has_label = false;
  std::vector<std::string> label_names;   ///< index = label value
  std::vector<Eigen::Vector2d> footprint; ///< building footprint (scene frame)
};

/** \brief A scanned scene: the cloud with ground truth and what is needed to check it.
 */
struct SyntheticScene {
  std::string name;
  pcl::PointCloud<SimulatedPoint> cloud;
  std::vector<std::uint16_t> scanner_of_point; ///< index into scan_positions per point
  /** \brief Indexed by \c segment id: the scene surface (SurfaceInfo::segment, the id
   * the geometry's curves and primitives use) that the segment is a connected piece of;
   * the identity when SceneParameters::connected_segments is off. */
  std::vector<std::uint32_t> surface_of_segment;
  std::vector<Eigen::Vector3d> scan_positions; ///< scene frame
  double angular_step_deg = 0.0;               ///< step used
  double noise = 0.0;                          ///< range noise sigma used
  double noise_per_metre = 0.0;
  double edge_distance = 0.0; ///< 0: the local spacing range * step
  bool has_rgb = false;
  bool has_intensity = false;
  bool has_label = false;
  std::vector<std::string> label_names;
  /** \brief Cloud frame from scene frame: offset, or the building's scan pose. */
  Eigen::Isometry3d cloud_from_scene = Eigen::Isometry3d::Identity();
  /** \brief building: footprint in map coordinates (offset included). */
  std::vector<Eigen::Vector2d> footprint;
  /** \brief building: the true transform from scan (cloud) to map coordinates. */
  Eigen::Matrix4d scan_to_map = Eigen::Matrix4d::Identity();
  /** \brief The true geometry (scene frame). */
  std::shared_ptr<const SceneDescription> description;
};

/** \brief Names of the scenes: indoor, cubes, spheres, coaxial, pipes, tree, building,
 * street. */
std::vector<std::string>
sceneNames ();

/** \brief Build the geometry and scan positions of scene \a name.
 * \return false with a PCL_ERROR for an unknown name or invalid parameters */
bool
describeScene (const std::string& name,
               const SceneParameters& parameters,
               SceneDescription& description);

/** \brief Build and scan scene \a name (describeScene + TlsScanSimulation).
 * \return false with a PCL_ERROR (and an empty scene) for an unknown name or invalid
 *         parameters */
bool
generateScene (const std::string& name,
               const SceneParameters& parameters,
               SyntheticScene& scene);

/** \brief Scan a described scene with \a parameters (step, noise, seed, offset, pose).
 */
bool
scanScene (const std::shared_ptr<const SceneDescription>& description,
           const SceneParameters& parameters,
           SyntheticScene& scene);

/** \brief Whether \a parameters are valid (finite, non-negative noise, ...); PCL_ERROR
 * if not. */
bool
checkSceneParameters (const SceneParameters& parameters);

/** \name Scene builders (each fills \a description; see describeScene)
 * \{ */

/** \brief Two rooms with windows and a door in a thick wall, floor, ceiling, boxes,
 * columns and pipes with an elbow, scanned from inside (Belton & Lichti 2006, figures
 * 2-6: walls, recessed doorways and windows, industrial piping). Labels: 1 wall, 2
 * floor, 3 ceiling, 4 box, 5 column, 6 pipe. Default 2 positions (one per room, 3 adds
 * a second in the large room), step 0.5 deg. */
void
describeIndoorScene (const SceneParameters& parameters, SceneDescription& description);

/** \brief Eight disjoint floating cubes of different sizes and orientations (Sithole &
 * Mapurisa, figure 10), about 41,500 points by default (2 positions); no labels. */
void
describeCubesScene (const SceneParameters& parameters, SceneDescription& description);

/** \brief Spheres nested in spheres (Sithole & Mapurisa, figure 11): outer spheres are
 * cut open towards the scanners so that the inner ones are seen through the opening
 * (whose rim is a border). About 155,000 points by default (2 positions); no labels. */
void
describeSpheresScene (const SceneParameters& parameters, SceneDescription& description);

/** \brief Coaxial pipes whose surfaces touch (Sithole & Mapurisa, figures 9 and 13): a
 * pipe sticking out of a wider open pipe, an annular step joining them, and a flange;
 * every junction is a crease. No labels. Default 2 positions, step 0.1 deg. */
void
describeCoaxialScene (const SceneParameters& parameters, SceneDescription& description);

/** \brief A pipe rack (Sithole & Mapurisa, figure 12): portal frames, pipes of several
 * radii resting on the beams, elbows turning down to the ground or sideways, on a
 * ground plane. Pipes touch the beams tangentially, which is not a crease; elbows join
 * their straight parts tangentially (separate segments, no crease). Labels: 1 ground, 2
 * support, 3 pipe. Default 3 positions, step 0.3 deg. */
void
describePipesScene (const SceneParameters& parameters, SceneDescription& description);

/** \brief A tree (Sithole & Mapurisa, figure 14): a tapering trunk, branches leaving it
 * (their intersection curves are creases) and porous leaf clusters, on flat ground.
 * Labels are OutdoorLabel (vegetation, trunk, terrain). */
void
describeTreeScene (const SceneParameters& parameters, SceneDescription& description);

/** \brief The exterior of a polyhedral building (Khoshelham & Gorte 2009, section 4 and
 * figure 3): walls with windows on the footprint (an H-shaped plan by default), a flat
 * roof and the ground, scanned from positions around it; options add superfluous planes
 * and hide walls behind vegetation. Labels: 1 wall, 2 ground, 3 roof, 4 superfluous, 5
 * vegetation. Positions 12 m out from the middle of every wall that has that much free
 * space in front (the courtyard mouths included, so every wall is seen), in
 * farthest-first order; all of them by default (8 on the H plan), the first
 * num_scanners when given. Step 0.4 deg; the scan frame is posed arbitrarily
 * (SceneParameters::random_pose). */
void
describeBuildingScene (const SceneParameters& parameters,
                       SceneDescription& description);

/** \brief A street (Lim & Suter 2008, figures 6-8): undulating grass terrain, a paved
 * road and walkways, building facades with windows, trees (trunks and porous crowns),
 * shrubs, poles and sagging wires, with colour and intensity per class. Labels are
 * OutdoorLabel. The road, walkways and grass are regions of one terrain surface
 * (separate segments, no crease between them); shrubs and wires carry no crease where
 * they touch the ground or a pole. Default 3 positions along the road, step 0.3 deg. */
void
describeStreetScene (const SceneParameters& parameters, SceneDescription& description);
/** \} */
} // namespace simulation
} // namespace pcl_ext
