/*
 * Quality of pcl_ext::ProfileSegmentation on the generated scenes of Sithole &
 * Mapurisa's section 5 (simulated TLS scans with exact ground truth). The measured
 * figures behind the bounds below, and what was tried on the way, are in
 * docs/sithole_mapurisa.md.
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/cylinder_segment_join.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/simulation/scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <string>

using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

namespace {
/** Scan \a name at its defaults; the truth is the object id or the surface id (the
 * \c segment: one connected visible piece of a surface). */
void
loadScene (const std::string& name,
           bool surfaces,
           pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
           std::vector<std::uint32_t>& truth,
           std::vector<std::uint32_t>* labels = nullptr)
{
  pcl_ext::simulation::SyntheticScene scene;
  ASSERT_TRUE (pcl_ext::simulation::generateScene (name, {}, scene));
  cloud.reset (new pcl::PointCloud<pcl::PointXYZ>);
  truth.clear();
  if (labels)
    labels->clear();
  for (const auto& p : scene.cloud) {
    cloud->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    truth.push_back (surfaces ? p.segment : p.object);
    if (labels)
      labels->push_back (p.label);
  }
}

/** Prints the figures the bounds below check, for docs/sithole_mapurisa.md. */
void
reportScene (const std::string& name, const pcl_ext::SegmentationMetrics& m)
{
  std::cout << std::fixed << std::setprecision (3) << "  [ " << name
            << " ] mean best IoU " << m.mean_best_iou << ", "
            << m.num_predicted_segments << " segments, " << m.correct << " correct, "
            << m.over_segmented << " over, " << m.under_segmented << " under, "
            << m.missed << " missed\n";
}

/** One ground-truth segment's best match: its IoU and the share of the predicted
 * segment that is this truth. */
void
reportScene (const std::string& name, const pcl_ext::SegmentMatch& s)
{
  std::cout << std::fixed << std::setprecision (3) << "  [ " << name << " ] IoU "
            << s.iou << ", purity "
            << (s.predicted_size ? double (s.overlap) / s.predicted_size : 0.0) << "\n";
}

/** Curve fitting for noisy scans: the width gives each side of a point enough points
 * for the fits, AICc and the significance test keep the noise from ending curves (see
 * ProfileSegmentation::setTurnSignificance). */
constexpr double kCurveWidthFactor = 2.5;

pcl_ext::SegmentationMetrics
segment (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
         const std::vector<std::uint32_t>& truth,
         Segmentation::ProfileMethod method = Segmentation::ProfileMethod::Proximity,
         double width_factor = 1.5,
         bool for_noise = false,
         bool local_threshold = false)
{
  Segmentation seg;
  seg.setInputCloud (cloud);
  seg.setProfileSegmentation (method);
  seg.setProfileWidthFactor (width_factor);
  seg.setLocalThreshold (local_threshold);
  if (for_noise) {
    seg.setCorrectedAic (true);
    seg.setTurnSignificance (3.0);
  }
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  pcl_ext::SegmentationMetrics metrics;
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (clusters, truth, metrics));
  return metrics;
}
} // namespace

TEST (ProfileSegmentationScenes, CubesAreOneSegmentEach)
{
  // Figure 10: 41,500 points, eight disjoint cubes.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("cubes", false, cloud, truth);
  const auto m = segment (cloud, truth);
  reportScene ("cubes, proximity", m);
  EXPECT_EQ (m.num_truth_segments, 8u);
  EXPECT_GE (m.mean_best_iou, 0.98);
  EXPECT_EQ (m.correct, 8u);
}

TEST (ProfileSegmentationScenes, NestedSpheresAreOneSegmentEach)
{
  // Figure 11: 155,000 points, spheres inside spheres.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("spheres", false, cloud, truth);
  const auto m = segment (cloud, truth);
  reportScene ("spheres, proximity", m);
  EXPECT_GE (m.mean_best_iou, 0.95);
  EXPECT_EQ (m.correct, m.num_truth_segments);
}

TEST (ProfileSegmentationScenes, CurveFittingSeparatesTheCoaxialSurfaces)
{
  // Figure 13: a pipe inside a coaxial pipe closed by an annular step, a flange on the
  // pipe, and a vertical reducer; 159,000 points at 7.7 mm spacing with 5 mm range
  // noise. The truth is the surface level (a segment per connected visible piece of a
  // surface): the goal is that touching surfaces separate.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("coaxial", true, cloud, truth);
  // Proximity links across the creases: the horizontal assembly is one segment.
  const auto proximity = segment (cloud, truth);
  reportScene ("coaxial surfaces, proximity", proximity);
  EXPECT_GE (proximity.under_segmented, 4u);
  EXPECT_LT (proximity.mean_best_iou, 0.6);
  // Curve fitting for noisy scans ends the curves at the creases: all but one surface
  // are found (the one missed is a flange face, a ring 10 cm wide between two creases).
  // With the paper's defaults the noise ends curves everywhere.
  const auto curve = segment (
      cloud, truth, Segmentation::ProfileMethod::CurveFitting, kCurveWidthFactor, true);
  reportScene ("coaxial surfaces, curve fitting for noisy scans", curve);
  EXPECT_GE (curve.mean_best_iou, 0.90);
  EXPECT_GE (curve.correct, 8u);
  EXPECT_EQ (curve.under_segmented, 0u);
}

namespace {
/** The truth segment holding most points of \a label below \a z_max. */
std::uint32_t
dominantSegment (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                 const std::vector<std::uint32_t>& truth,
                 const std::vector<std::uint32_t>& labels,
                 std::uint32_t label,
                 float z_max)
{
  std::map<std::uint32_t, std::size_t> count;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (labels[i] == label && cloud[i].z < z_max)
      ++count[truth[i]];
  return std::max_element (
             count.begin(),
             count.end(),
             [] (const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

const pcl_ext::SegmentMatch&
matchOf (const pcl_ext::SegmentationMetrics& m, std::uint32_t truth_label)
{
  return *std::find_if (
      m.segments.begin(), m.segments.end(), [&] (const pcl_ext::SegmentMatch& s) {
        return s.truth_label == truth_label;
      });
}

/** The tree scene of figure 14 (a tree on flat ground, 275,000 points) and two of its
 * truth segments: the trunk, the surface of most trunk points below 3 m (the first
 * branch starts above 3.7 m), and the ground, of most terrain points below 1 m. */
struct TreeScene {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth, labels;
  std::uint32_t trunk = 0, ground = 0;
};

TreeScene
loadTreeScene ()
{
  TreeScene tree;
  loadScene ("tree", true, tree.cloud, tree.truth, &tree.labels);
  tree.trunk = dominantSegment (
      *tree.cloud,
      tree.truth,
      tree.labels,
      static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Trunk),
      3.0f);
  tree.ground = dominantSegment (
      *tree.cloud,
      tree.truth,
      tree.labels,
      static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Terrain),
      1.0f);
  return tree;
}
} // namespace

TEST (ProfileSegmentationScenes, TreeTrunkIsSeparatedFromTheGroundByCurveFitting)
{
  // Figure 14: a tree on flat ground, 275,000 points.
  const auto [cloud, truth, labels, trunk, ground] = loadTreeScene();
  // Proximity: the trunk touches the ground, and trunk and ground are one segment.
  const auto proximity = segment (cloud, truth);
  reportScene ("tree trunk, proximity", matchOf (proximity, trunk));
  EXPECT_EQ (matchOf (proximity, trunk).best_predicted,
             matchOf (proximity, ground).best_predicted);
  EXPECT_LT (matchOf (proximity, trunk).iou, 0.1);
  // Curve fitting (the paper's defaults) cuts the crease where the trunk meets the
  // ground: the ground is its own segment and the trunk's best segment lies within the
  // trunk.
  const auto curve = segment (cloud, truth, Segmentation::ProfileMethod::CurveFitting);
  reportScene ("tree trunk, curve fitting", matchOf (curve, trunk));
  reportScene ("tree ground, curve fitting", matchOf (curve, ground));
  const auto& t = matchOf (curve, trunk);
  EXPECT_GE (matchOf (curve, ground).iou, 0.99);
  EXPECT_NE (t.best_predicted, matchOf (curve, ground).best_predicted);
  EXPECT_GE (static_cast<double> (t.overlap), 0.95 * t.predicted_size);
}

TEST (ProfileSegmentationScenes, SideFramesKeepTheTrunkWhole)
{
  // Why the trunk splits: every stack plane cuts the trunk (radius 0.26 m at the foot,
  // 0.07 m at the top) obliquely, 55 degrees from the horizontal, in an ellipse whose
  // radius of curvature at the ends of its long axis is 0.58 r, about the curve window
  // (0.16 m). There a side of a point turns by tens of degrees, the polynomials in the
  // point's frame cannot follow, and the residual and turn tests mark bands of curve
  // ends along the trunk that cut it into pieces. Fitting each side along its own axis
  // removes the bands where the trunk is thick. Scene: the tree with the ground cut
  // to 1.5 m around the trunk, at the whole scene's spacing (0.027 m), which keeps the
  // trunk-ground crease and the crown in a few seconds.
  const auto [cloud, truth, labels, trunk, ground] = loadTreeScene();
  const auto terrain =
      static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Terrain);
  pcl::IndicesPtr kept (new pcl::Indices);
  std::vector<std::uint32_t> kept_truth (truth.size(), 0);
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const auto& q = (*cloud)[i];
    if (labels[i] != terrain || q.x * q.x + q.y * q.y < 1.5f * 1.5f) {
      kept->push_back (static_cast<pcl::index_t> (i));
      kept_truth[i] = truth[i];
    }
  }
  Segmentation seg;
  seg.setInputCloud (cloud);
  seg.setIndices (kept);
  seg.setPointSpacing (0.027);
  seg.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
  seg.setProfileWidthFactor (kCurveWidthFactor);
  seg.setCorrectedAic (true);
  seg.setTurnSignificance (3.0);
  seg.setSideFrames (true);
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  pcl_ext::SegmentationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (clusters, kept_truth, m));
  reportScene ("cut tree trunk, side frames", matchOf (m, trunk));
  reportScene ("cut tree ground, side frames", matchOf (m, ground));
  // Without side frames the trunk's pieces join the ground.
  EXPECT_GE (matchOf (m, trunk).iou, 0.85);
  EXPECT_GE (matchOf (m, ground).iou, 0.95);
  EXPECT_NE (matchOf (m, trunk).best_predicted, matchOf (m, ground).best_predicted);
}

TEST (ProfileSegmentationScenes, TreeTrunkIsOneSegmentAfterTheCylinderJoin)
{
  // Goal (figure 14: "the trunk and larger branches are successfully detected"): the
  // trunk one segment. Curve fitting for noisy scans with side frames keeps the trunk
  // whole up to 4 m; above, where its radius falls to 0.13-0.07 m and the branches
  // leave it, it splits into short pieces (proximity merges it with the ground and the
  // crown). Those pieces lie on the trunk's cone: CylinderSegmentJoin (cones allowed,
  // radii compared where two pieces face each other) joins them to the lower trunk, and
  // the fragments at the branch junctions that lie on the joined surface follow.
  const auto [cloud, truth, labels, trunk, ground] = loadTreeScene();
  Segmentation seg;
  seg.setInputCloud (cloud);
  seg.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
  seg.setProfileWidthFactor (kCurveWidthFactor);
  seg.setCorrectedAic (true);
  seg.setTurnSignificance (3.0);
  seg.setSideFrames (true);
  std::vector<pcl::PointIndices> segments;
  seg.extract (segments);
  pcl_ext::SegmentationMetrics before;
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (segments, truth, before));
  reportScene ("tree trunk, side frames", matchOf (before, trunk));
  EXPECT_LT (matchOf (before, trunk).iou, 0.8);

  pcl_ext::CylinderSegmentJoin<pcl::PointXYZ> join;
  join.setInputCloud (cloud);
  join.setInputSegments (segments);
  std::vector<pcl::PointIndices> joined;
  join.join (joined);
  pcl_ext::SegmentationMetrics m;
  ASSERT_TRUE (pcl_ext::evaluateSegmentation (joined, truth, m));
  reportScene ("tree trunk, after the join", matchOf (m, trunk));
  reportScene ("tree ground, after the join", matchOf (m, ground));
  const auto& t = matchOf (m, trunk);
  EXPECT_GE (t.iou, 0.9);
  // The trunk's segment is the trunk (the rest is bark of branch stubs), and the ground
  // stays apart and whole.
  EXPECT_GE (static_cast<double> (t.overlap), 0.95 * t.predicted_size);
  EXPECT_NE (t.best_predicted, matchOf (m, ground).best_predicted);
  EXPECT_GE (matchOf (m, ground).iou, 0.99);
}

TEST (ProfileSegmentationScenes, PipesGroundIsOneSegment)
{
  // Figure 12: seven pipes resting on three portal frames over the ground, 578,000
  // points. What holds at the object level: the ground is one segment.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("pipes", false, cloud, truth);
  const auto m = segment (cloud, truth);
  reportScene ("pipes, proximity", m);
  reportScene ("pipes ground, proximity", m.segments[0]);
  ASSERT_EQ (m.num_truth_segments, 11u);
  EXPECT_GE (m.segments[0].iou, 0.9); // object 1 is the ground
}

TEST (ProfileSegmentationScenes, LocalThresholdKeepsTheSparsePipesWhole)
{
  // The pipes lie 3.3 m up and 7 m or more from the scanners, sampled at 0.049 m, while
  // the dense ground near the scanners sets the automatic spacing of the whole cloud
  // (0.025 m). Segmented alone at the whole cloud's spacing (which isolates the effect
  // of density: the pipes do not touch one another), their profiles break into short
  // chains with one global threshold; thresholds that follow the local gaps join most
  // of the chains.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth, labels;
  loadScene ("pipes", false, cloud, truth, &labels);
  std::vector<Eigen::Vector3f> xyz;
  for (const auto& q : *cloud)
    xyz.push_back (q.getVector3fMap());
  const double spacing = pcl_ext::profiles::estimatePointSpacing (xyz);
  EXPECT_NEAR (spacing, 0.025, 0.002);
  constexpr std::uint32_t kPipe = 3; // the scene's pipe label
  pcl::IndicesPtr pipes (new pcl::Indices);
  std::vector<std::uint32_t> pipe_truth (truth.size(), 0);
  for (std::size_t i = 0; i < cloud->size(); ++i)
    if (labels[i] == kPipe) {
      pipes->push_back (static_cast<pcl::index_t> (i));
      pipe_truth[i] = truth[i];
    }
  const auto run = [&] (bool local) {
    Segmentation seg;
    seg.setInputCloud (cloud);
    seg.setIndices (pipes);
    seg.setPointSpacing (spacing);
    seg.setLocalThreshold (local);
    std::vector<pcl::PointIndices> clusters;
    seg.extract (clusters);
    pcl_ext::SegmentationMetrics m;
    EXPECT_TRUE (pcl_ext::evaluateSegmentation (clusters, pipe_truth, m));
    EXPECT_EQ (m.num_truth_segments, 7u);
    return m;
  };
  const auto global = run (false), local = run (true);
  reportScene ("pipes alone, one threshold", global);
  reportScene ("pipes alone, local thresholds", local);
  EXPECT_LT (global.mean_best_iou, 0.5);
  EXPECT_GE (local.mean_best_iou, 0.65);
  EXPECT_LT (local.num_predicted_segments, global.num_predicted_segments / 2);
  EXPECT_EQ (local.under_segmented, 0u);
}

namespace {
constexpr std::uint32_t kFirstPipeObject =
    5; // objects: ground, three frames, seven pipes
constexpr std::uint32_t kLastPipeObject = 11;

/** Figure 12's scene segmented once for the tests below (about 15 s): curve fitting
 * with the settings for noisy scans and local thresholds. */
class PipesByCurves : public ::testing::Test {
protected:
  static void
  SetUpTestSuite ()
  {
    cloud_.reset (new pcl::PointCloud<pcl::PointXYZ>);
    loadScene ("pipes", false, cloud_, truth_);
    Segmentation seg;
    seg.setInputCloud (cloud_);
    seg.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
    seg.setProfileWidthFactor (kCurveWidthFactor);
    seg.setCorrectedAic (true);
    seg.setTurnSignificance (3.0);
    seg.setLocalThreshold (true);
    seg.extract (segments_);
  }

  static void
  TearDownTestSuite ()
  {
    cloud_.reset();
    segments_.clear();
  }

  static pcl_ext::SegmentationMetrics
  evaluate (const std::vector<pcl::PointIndices>& segments)
  {
    pcl_ext::SegmentationMetrics m;
    EXPECT_TRUE (pcl_ext::evaluateSegmentation (segments, truth_, m));
    EXPECT_EQ (m.num_truth_segments, 11u);
    return m;
  }

  /** Mean best IoU over the seven pipes. */
  static double
  meanOverPipes (const pcl_ext::SegmentationMetrics& m)
  {
    double sum = 0.0;
    for (std::uint32_t pipe = kFirstPipeObject; pipe <= kLastPipeObject; ++pipe)
      sum += matchOf (m, pipe).iou;
    return sum / (kLastPipeObject - kFirstPipeObject + 1);
  }

  static pcl::PointCloud<pcl::PointXYZ>::Ptr cloud_;
  static std::vector<std::uint32_t> truth_;
  static std::vector<pcl::PointIndices> segments_;
};

pcl::PointCloud<pcl::PointXYZ>::Ptr PipesByCurves::cloud_;
std::vector<std::uint32_t> PipesByCurves::truth_;
std::vector<pcl::PointIndices> PipesByCurves::segments_;
} // namespace

TEST_F (PipesByCurves, CurveFittingKeepsThePipesOffTheFrames)
{
  // What curve fitting achieves on figure 12's scene: the creases where the pipes rest
  // on the beams and where two pipes meet the ground end the curves, so no pipe shares
  // a segment with a frame or the ground (proximity joins them all), and the ground
  // stays whole.
  const auto m = evaluate (segments_);
  reportScene ("pipes, curve fitting", m);
  std::cout << "  [ pipes, curve fitting ] mean over the pipes " << meanOverPipes (m)
            << "\n";
  EXPECT_GE (m.segments[0].iou, 0.99);
  for (std::uint32_t pipe = kFirstPipeObject; pipe <= kLastPipeObject; ++pipe) {
    const auto& match = matchOf (m, pipe);
    EXPECT_GE (static_cast<double> (match.overlap), 0.8 * match.predicted_size)
        << "pipe " << pipe;
  }
  // But it over-segments them. Five of the seven are cut where they rest on the beams
  // (x = 0, 6, 12 m) into their spans between beams: there a scanner on the ground sees
  // only the pipe's underside next to the beam, all of it within a curve window of the
  // pipe-beam crease, so all of it ends curves (the 0.25 m pipe, whose side shows above
  // the beams, is one piece but for small strips). The frames are split into their
  // faces by the same creases.
  EXPECT_LT (meanOverPipes (m), 0.5);
}

TEST_F (PipesByCurves, PipesAreOneSegmentEachAfterTheCylinderJoin)
{
  // Goal: each pipe its own segment (mean best IoU >= 0.85 over the seven pipes). The
  // spans of a pipe cut at its supports lie on one cylinder, and so do the legs of an
  // elbow: CylinderSegmentJoin finds the cylinders in each segment (two pipes side by
  // side share some) and joins those that continue one another; the ground stays whole.
  // What is left: the leg of the 0.15 m pipe that bends down to the ground stays in the
  // ground's segment.
  pcl_ext::CylinderSegmentJoin<pcl::PointXYZ> join;
  join.setInputCloud (cloud_);
  join.setInputSegments (segments_);
  std::vector<pcl::PointIndices> joined;
  join.join (joined);
  const auto m = evaluate (joined);
  reportScene ("pipes, after the join", m);
  std::cout << "  [ pipes, after the join ] mean over the pipes " << meanOverPipes (m)
            << "\n";
  for (std::uint32_t pipe = kFirstPipeObject; pipe <= kLastPipeObject; ++pipe)
    reportScene ("pipe " + std::to_string (pipe) + ", after the join",
                 matchOf (m, pipe));
  EXPECT_GE (meanOverPipes (m), 0.85);
  EXPECT_GE (m.segments[0].iou, 0.99);
  // No pipe's segment holds a point of another pipe; the rest of it are the bits of the
  // beams next to the pipe that curve fitting had already left with its spans.
  for (std::uint32_t pipe = kFirstPipeObject; pipe <= kLastPipeObject; ++pipe) {
    const auto& match = matchOf (m, pipe);
    ASSERT_GT (match.best_predicted, 0u);
    std::size_t other_pipes = 0;
    for (const auto i : joined[match.best_predicted - 1].indices)
      other_pipes += truth_[i] >= kFirstPipeObject && truth_[i] != pipe;
    EXPECT_EQ (other_pipes, 0u) << "pipe " << pipe;
    EXPECT_GE (static_cast<double> (match.overlap), 0.85 * match.predicted_size)
        << "pipe " << pipe;
  }
  // The cylinders give the pipes' radii (the scene's: 0.25, 0.15, 0.10, 0.08, 0.20,
  // 0.05 and 0.12 m), and all the joined cylinders of a pipe went into one segment.
  const double radius[] = {0.25, 0.15, 0.10, 0.08, 0.20, 0.05, 0.12};
  std::map<std::uint32_t, std::set<int>> segments_of_pipe;
  for (const auto& c : join.getCylinders()) {
    std::map<std::uint32_t, std::size_t> count;
    for (const auto i : c.cylinder.inliers)
      ++count[truth_[i]];
    const auto pipe = std::max_element (count.begin(),
                                        count.end(),
                                        [] (const auto& a, const auto& b) {
                                          return a.second < b.second;
                                        })
                          ->first;
    if (pipe < kFirstPipeObject || c.output_segment < 0)
      continue;
    EXPECT_NEAR (c.cylinder.radius, radius[pipe - kFirstPipeObject], 0.01)
        << "pipe " << pipe;
    segments_of_pipe[pipe].insert (c.output_segment);
  }
  EXPECT_EQ (segments_of_pipe.size(), 7u);
  for (const auto& [pipe, output] : segments_of_pipe)
    EXPECT_EQ (output.size(), 1u) << "pipe " << pipe;
}
