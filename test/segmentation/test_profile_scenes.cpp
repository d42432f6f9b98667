/*
 * Quality of pcl_ext::ProfileSegmentation on the generated scenes of Sithole & Mapurisa's
 * section 5 (simulated TLS scans with exact ground truth).
 */
#include <pcl_ext/evaluation/segmentation_metrics.h>
#include <pcl_ext/segmentation/profile_segmentation.h>
#include <pcl_ext/simulation/scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;

namespace
{
/** Scan \a name at its defaults; the truth is the object id or the surface id (the
  * \c segment: one connected visible piece of a surface). */
void
loadScene (const std::string& name, bool surfaces, pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
           std::vector<std::uint32_t>& truth, std::vector<std::uint32_t>* labels = nullptr)
{
  pcl_ext::simulation::SyntheticScene scene;
  ASSERT_TRUE (pcl_ext::simulation::generateScene (name, {}, scene));
  cloud.reset (new pcl::PointCloud<pcl::PointXYZ>);
  truth.clear ();
  if (labels)
    labels->clear ();
  for (const auto& p : scene.cloud)
  {
    cloud->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    truth.push_back (surfaces ? p.segment : p.object);
    if (labels)
      labels->push_back (p.label);
  }
}

/** Curve fitting for noisy scans: the width gives each side of a point enough points for the
  * fits, AICc and the significance test keep the noise from ending curves (see
  * ProfileSegmentation::setTurnSignificance). */
constexpr double kCurveWidthFactor = 2.5;

pcl_ext::SegmentationMetrics
segment (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud, const std::vector<std::uint32_t>& truth,
         Segmentation::ProfileMethod method = Segmentation::ProfileMethod::Proximity,
         double width_factor = 1.5, bool for_noise = false)
{
  Segmentation seg;
  seg.setInputCloud (cloud);
  seg.setProfileSegmentation (method);
  seg.setProfileWidthFactor (width_factor);
  if (for_noise)
  {
    seg.setCorrectedAic (true);
    seg.setTurnSignificance (3.0);
  }
  std::vector<pcl::PointIndices> clusters;
  seg.extract (clusters);
  pcl_ext::SegmentationMetrics metrics;
  EXPECT_TRUE (pcl_ext::evaluateSegmentation (clusters, truth, metrics));
  return metrics;
}
}  // namespace

TEST (ProfileSegmentationScenes, CubesAreOneSegmentEach)
{
  // Figure 10: 41,500 points, eight disjoint cubes.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("cubes", false, cloud, truth);
  const auto m = segment (cloud, truth);
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
  EXPECT_GE (m.mean_best_iou, 0.95);
  EXPECT_EQ (m.correct, m.num_truth_segments);
}

TEST (ProfileSegmentationScenes, CurveFittingSeparatesTheCoaxialSurfaces)
{
  // Figure 13: a pipe inside a coaxial pipe closed by an annular step, a flange on the pipe,
  // and a vertical reducer; 159,000 points at 7.7 mm spacing with 5 mm range noise. The truth
  // is the surface level (a segment per connected visible piece of a surface): the goal is
  // that touching surfaces separate.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("coaxial", true, cloud, truth);
  // Proximity links across the creases: the horizontal assembly is one segment (measured:
  // mean best IoU 0.55, 5 of its surfaces under-segmented).
  const auto proximity = segment (cloud, truth);
  EXPECT_GE (proximity.under_segmented, 4u);
  EXPECT_LT (proximity.mean_best_iou, 0.6);
  // Curve fitting for noisy scans ends the curves at the creases (measured: 0.913, 8 of 9
  // surfaces correct; the one missed is a flange face, a ring 10 cm wide between two creases).
  // With the paper's defaults the noise ends curves everywhere: 0.52; width 2.5x alone 0.68,
  // AICc and the significance test alone 0.55.
  const auto curve = segment (cloud, truth, Segmentation::ProfileMethod::CurveFitting,
                              kCurveWidthFactor, true);
  EXPECT_GE (curve.mean_best_iou, 0.90);
  EXPECT_GE (curve.correct, 8u);
  EXPECT_EQ (curve.under_segmented, 0u);
}

namespace
{
/** The truth segment holding most points of \a label below \a z_max. */
std::uint32_t
dominantSegment (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                 const std::vector<std::uint32_t>& truth, const std::vector<std::uint32_t>& labels,
                 std::uint32_t label, float z_max)
{
  std::map<std::uint32_t, std::size_t> count;
  for (std::size_t i = 0; i < cloud.size (); ++i)
    if (labels[i] == label && cloud[i].z < z_max)
      ++count[truth[i]];
  return std::max_element (count.begin (), count.end (),
                           [] (const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

const pcl_ext::SegmentMatch&
matchOf (const pcl_ext::SegmentationMetrics& m, std::uint32_t truth_label)
{
  return *std::find_if (m.segments.begin (), m.segments.end (),
                        [&] (const pcl_ext::SegmentMatch& s) { return s.truth_label == truth_label; });
}
}  // namespace

TEST (ProfileSegmentationScenes, TreeTrunkIsSeparatedFromTheGroundByCurveFitting)
{
  // Figure 14: a tree on flat ground, 275,000 points. The trunk is the surface of most trunk
  // points below the first branch (which starts above 3.7 m).
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth, labels;
  loadScene ("tree", true, cloud, truth, &labels);
  const auto trunk = dominantSegment (*cloud, truth, labels,
                                      static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Trunk), 3.0f);
  const auto ground = dominantSegment (*cloud, truth, labels,
                                       static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Terrain), 1.0f);
  // Proximity: the trunk touches the ground, and trunk and ground are one segment.
  const auto proximity = segment (cloud, truth);
  EXPECT_EQ (matchOf (proximity, trunk).best_predicted, matchOf (proximity, ground).best_predicted);
  EXPECT_LT (matchOf (proximity, trunk).iou, 0.1);
  // Curve fitting (the paper's defaults) cuts the crease where the trunk meets the ground: the
  // ground is its own segment (measured IoU 1.000) and the trunk's best segment lies within
  // the trunk (measured: all its 1756 points).
  const auto curve = segment (cloud, truth, Segmentation::ProfileMethod::CurveFitting);
  const auto& t = matchOf (curve, trunk);
  EXPECT_GE (matchOf (curve, ground).iou, 0.99);
  EXPECT_NE (t.best_predicted, matchOf (curve, ground).best_predicted);
  EXPECT_GE (static_cast<double> (t.overlap), 0.95 * t.predicted_size);
}

TEST (ProfileSegmentationScenes, DISABLED_TreeTrunkIsOneSegment)
{
  // Goal (figure 14: "the trunk and larger branches are successfully detected"). Not met:
  // curve fitting separates the trunk from the ground but splits it: best IoU 0.35 with the
  // settings for noisy scans, 0.27 with the paper's defaults; proximity merges it with the
  // ground and the whole tree (0.02).
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth, labels;
  loadScene ("tree", true, cloud, truth, &labels);
  const auto trunk = dominantSegment (*cloud, truth, labels,
                                      static_cast<std::uint32_t> (pcl_ext::simulation::OutdoorLabel::Trunk), 3.0f);
  const auto curve = segment (cloud, truth, Segmentation::ProfileMethod::CurveFitting,
                              kCurveWidthFactor, true);
  EXPECT_GE (matchOf (curve, trunk).iou, 0.9);
}

TEST (ProfileSegmentationScenes, PipesGroundIsOneSegment)
{
  // Figure 12: seven pipes resting on three portal frames over the ground, 578,000 points.
  // What holds at the object level: the ground is one segment (measured IoU 0.911).
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("pipes", false, cloud, truth);
  const auto m = segment (cloud, truth);
  ASSERT_EQ (m.num_truth_segments, 11u);
  EXPECT_GE (m.segments[0].iou, 0.9);  // object 1 is the ground
}

TEST (ProfileSegmentationScenes, DISABLED_PipesAreOneSegmentEach)
{
  // Goal: each pipe its own segment (object-level mean best IoU >= 0.85). Not met: 0.13 with
  // proximity, 0.18 with curve fitting and the settings for noisy scans at width 1.5x, 0.34 at
  // width 2.5x (and 50 s). The
  // pipes lie 3.3 m up and 7 m or more from the scanners: at the 0.3 degree step they are
  // sampled at 4 cm or more, while the ground near the scanners sets the one automatic
  // spacing (0.025 m, threshold 0.075 m). Their profiles break into short chains (each pipe
  // split into pieces of a few hundred points), and with proximity a pipe resting on a beam
  // is linked to the frame and through it to the ground. Needs a spacing that follows the
  // local density.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  std::vector<std::uint32_t> truth;
  loadScene ("pipes", false, cloud, truth);
  const auto m = segment (cloud, truth, Segmentation::ProfileMethod::CurveFitting,
                          kCurveWidthFactor, true);
  EXPECT_GE (m.mean_best_iou, 0.85);
}
