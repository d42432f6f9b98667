/*
 * LocalSurfaceIntersection on the generated `indoor` scene, with its ground-truth
 * segments: distance of the intersection points to the true crease lines, and
 * re-integration of the edge points into their true segments.
 *
 * Inputs as a segmenter would leave them: surface points carry their true segment, edge
 * and boundary points none. Classes come from the Belton classifier (k = 50, the
 * paper's settings) or, for comparison, from the scene's truth (edge within one scan
 * spacing of a crease).
 */
#include <pcl_ext/classification/local_variance_classification.h>
#include <pcl_ext/segmentation/local_surface_intersection.h>
#include <pcl_ext/simulation/scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>

namespace {
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using LabelCloud = pcl::PointCloud<pcl::Label>;
using Intersection = pcl_ext::LocalSurfaceIntersection<pcl::PointXYZ>;
using pcl_ext::PointClass;

constexpr int kK = 50;
constexpr std::uint32_t kWallLabel = 1; // the indoor scene's "wall"

struct Indoor {
  pcl_ext::simulation::SyntheticScene scene;
  Cloud::Ptr cloud{new Cloud};
  pcl_ext::Neighbourhoods<pcl::PointXYZ>::Ptr nb{
      new pcl_ext::Neighbourhoods<pcl::PointXYZ>};
  LabelCloud::Ptr belton{new LabelCloud}; ///< classifier's classes
  LabelCloud::Ptr truth{new LabelCloud};  ///< the scene's classes
};

const Indoor&
indoor ()
{
  static std::unique_ptr<Indoor> s;
  if (s)
    return *s;
  s.reset (new Indoor);
  pcl_ext::simulation::SceneParameters parameters;
  parameters.points = 300000;
  EXPECT_TRUE (pcl_ext::simulation::generateScene ("indoor", parameters, s->scene));
  for (const auto& p : s->scene.cloud) {
    s->cloud->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    pcl::Label c;
    c.label = p.point_class;
    s->truth->push_back (c);
  }
  s->cloud->is_dense = s->scene.cloud.is_dense;
  s->nb->setInputCloud (s->cloud);
  s->nb->setKSearch (kK);
  EXPECT_TRUE (s->nb->compute());
  pcl_ext::LocalVarianceClassification<pcl::PointXYZ> classifier;
  classifier.setInputCloud (s->cloud);
  classifier.setNeighbourhoods (s->nb);
  classifier.classify (*s->belton);
  return *s;
}

/** True segments on surface points, 0 elsewhere. */
LabelCloud::Ptr
segmentsOfSurfacePoints (const Indoor& s, const LabelCloud& classes)
{
  LabelCloud::Ptr segments (new LabelCloud);
  segments->resize (s.cloud->size());
  for (std::size_t i = 0; i < s.cloud->size(); ++i)
    (*segments)[i].label =
        classes[i].label == static_cast<std::uint32_t> (PointClass::Surface)
            ? s.scene.cloud[i].segment
            : 0u;
  return segments;
}

struct Outcome {
  pcl::PointCloud<pcl_ext::SurfaceIntersectionPoint> intersections;
  LabelCloud labels;
  Intersection::Report report;
  LabelCloud::Ptr segments;
};

Outcome
run (const Indoor& s, const LabelCloud::Ptr& classes, unsigned threads = 0)
{
  Outcome r;
  r.segments = segmentsOfSurfacePoints (s, *classes);
  Intersection lsi;
  lsi.setInputCloud (s.cloud);
  lsi.setNeighbourhoods (s.nb);
  lsi.setSegmentLabels (r.segments);
  lsi.setPointClasses (classes);
  lsi.setNumberOfThreads (threads);
  EXPECT_TRUE (lsi.compute (r.intersections, r.labels));
  r.report = lsi.getReport();
  return r;
}

/** Distances of intersection points to the true crease between their two segments
 * (infinity when the scene has none between them), for the pairs that involve a wall.
 */
std::vector<double>
wallCreaseDistances (const Indoor& s, const Outcome& r)
{
  const auto& geometry = s.scene.description->geometry;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> creases;
  const auto& curves = geometry.curves();
  for (std::size_t c = 0; c < curves.size(); ++c)
    if (curves[c].kind == pcl_ext::simulation::GroundTruthCurve::Kind::Crease) {
      const auto a = std::min (curves[c].segment_a, curves[c].segment_b);
      const auto b = std::max (curves[c].segment_a, curves[c].segment_b);
      creases[{a, b}].push_back (c);
    }
  std::map<std::uint32_t, std::uint32_t> label_of_segment;
  for (const auto& p : s.scene.cloud)
    label_of_segment[p.segment] = p.label;
  const Eigen::Isometry3d scene_from_cloud = s.scene.cloud_from_scene.inverse();
  std::vector<double> d;
  for (const auto& p : r.intersections) {
    if (label_of_segment[p.segment_a] != kWallLabel &&
        label_of_segment[p.segment_b] != kWallLabel)
      continue;
    const Eigen::Vector3d x = scene_from_cloud * Eigen::Vector3d (p.x, p.y, p.z);
    double best = std::numeric_limits<double>::infinity();
    // Intersections name the segments (connected pieces); the curves, their surfaces.
    const std::uint32_t a = s.scene.surface_of_segment[p.segment_a],
                        b = s.scene.surface_of_segment[p.segment_b];
    const auto it = creases.find ({std::min (a, b), std::max (a, b)});
    if (it != creases.end())
      for (const auto c : it->second)
        best = std::min (best, curves[c].distance (x));
    d.push_back (best);
  }
  return d;
}

double
median (std::vector<double> v)
{
  if (v.empty())
    return std::numeric_limits<double>::infinity();
  auto mid = v.begin() + v.size() / 2;
  std::nth_element (v.begin(), mid, v.end());
  return *mid;
}

/** Fraction of the edge points (by \a classes) whose output label is their true
 * segment. */
double
edgesRightlyReintegrated (const Indoor& s, const LabelCloud& classes, const Outcome& r)
{
  std::size_t edges = 0, right = 0;
  for (std::size_t i = 0; i < classes.size(); ++i)
    if (classes[i].label == static_cast<std::uint32_t> (PointClass::Edge)) {
      ++edges;
      right += r.labels[i].label == s.scene.cloud[i].segment;
    }
  return edges ? double (right) / double (edges) : 0.0;
}

void
print (const std::string& name,
       const Indoor& s,
       const LabelCloud& classes,
       const Outcome& r,
       const std::vector<double>& d)
{
  const double sigma = s.scene.noise;
  std::size_t within = 0, no_crease = 0;
  for (const double x : d) {
    within += x <= 3.0 * sigma;
    no_crease += !std::isfinite (x);
  }
  const auto& q = r.report;
  std::cout << std::setprecision (4) << "[ indoor, " << name << " classes ] "
            << s.cloud->size() << " points, k = " << kK << ", noise sigma " << sigma
            << "\n"
            << "  pairs " << q.pairs << ": " << q.intersections << " intersections, "
            << q.parallel << " parallel, " << q.beyond_tolerance << " too far, "
            << q.no_plane << " without a plane\n"
            << "  wall intersections " << d.size()
            << ": median distance to the true crease " << median (d) << " ("
            << median (d) / sigma << " sigma), within 3 sigma "
            << (d.empty() ? 0.0 : double (within) / d.size())
            << ", pairs with no crease " << no_crease << "\n"
            << "  edge/boundary points " << q.examined << ": re-integrated "
            << q.reintegrated << ", ambiguous " << q.ambiguous << ", left " << q.left
            << "; edge points in their true segment "
            << edgesRightlyReintegrated (s, classes, r) << "\n";
}
} // namespace

TEST (LocalSurfaceIntersectionIndoor, WallIntersectionsLieOnTheTrueCreases)
{
  const Indoor& s = indoor();
  ASSERT_GT (s.cloud->size(), 100000u);
  const Outcome r = run (s, s.belton);
  const auto d = wallCreaseDistances (s, r);
  print ("Belton", s, *s.belton, r, d);
  const Outcome t = run (s, s.truth);
  print ("true", s, *s.truth, t, wallCreaseDistances (s, t));
  ASSERT_GT (d.size(), 1000u);
  EXPECT_LE (median (d), 3.0 * s.scene.noise);
}

TEST (LocalSurfaceIntersectionIndoor, EdgePointsGoBackToTheirSegment)
{
  const Indoor& s = indoor();
  const Outcome r = run (s, s.belton);
  EXPECT_GE (edgesRightlyReintegrated (s, *s.belton, r), 0.70);
}

TEST (LocalSurfaceIntersectionIndoor, DeterministicForOneAndTwoThreads)
{
  const Indoor& s = indoor();
  const Outcome one = run (s, s.belton, 1), two = run (s, s.belton, 2);
  ASSERT_EQ (one.intersections.size(), two.intersections.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < one.intersections.size(); ++i) {
    const auto& a = one.intersections[i];
    const auto& b = two.intersections[i];
    differing += a.x != b.x || a.y != b.y || a.z != b.z || a.index_a != b.index_a ||
                 a.index_b != b.index_b;
  }
  EXPECT_EQ (differing, 0u);
  ASSERT_EQ (one.labels.size(), two.labels.size());
  std::size_t labels_differing = 0;
  for (std::size_t i = 0; i < one.labels.size(); ++i)
    labels_differing += one.labels[i].label != two.labels[i].label;
  EXPECT_EQ (labels_differing, 0u);
}
