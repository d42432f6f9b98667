/*
 * CoplanarSegmentMerging and mergeInterleavedCoplanarSegments: interleaved pieces of
 * one plane merged, pieces of two planes and coplanar pieces that only touch kept
 * apart, a small piece between two surfaces not chaining them, the same merges from a
 * cloud's parts summed, and bad input.
 */
#include <pcl_ext/common/random.h>
#include <pcl_ext/segmentation/coplanar_segment_merging.h>
#include <pcl_ext/segmentation/segment_contacts.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <vector>

namespace {
using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Labels = pcl::PointCloud<pcl::Label>;

/** A 2 x 1 m plane z = 0 sampled in scan lines along x, 2 cm apart in y with 5 mm
 * between points along a line and 1 mm noise, the lines labelled 1 and 2 in turn (one
 * plane's points split as two stations' or alternate lines); a 1 m-high wall x = 2
 * sampled at 1 cm, labelled 3; and a second patch of the plane z = 0, 2 m away
 * (x 4 .. 5), sampled as the first but every line labelled 4, touching nothing. */
struct InterleavedScene {
  Cloud::Ptr cloud = pcl::make_shared<Cloud>();
  Labels::Ptr labels = pcl::make_shared<Labels>();
};

InterleavedScene
makeInterleavedScene (double line_offset_z = 0.0)
{
  InterleavedScene s;
  pcl_ext::RandomStream random (77);
  const auto add = [&s] (double x, double y, double z, std::uint32_t label) {
    s.cloud->push_back (
        Point (static_cast<float> (x), static_cast<float> (y), static_cast<float> (z)));
    pcl::Label l;
    l.label = label;
    s.labels->push_back (l);
  };
  for (int line = 0; line < 50; ++line) {
    const std::uint32_t label = line % 2 == 0 ? 1u : 2u;
    const double z = label == 2u ? line_offset_z : 0.0;
    for (int i = 0; i < 400; ++i)
      add (0.005 * i, 0.02 * line, z + 0.001 * random.gaussian(), label);
  }
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      add (2.0 + 0.001 * random.gaussian(), 0.01 * i, 0.01 * j + 0.01, 3u);
  for (int line = 0; line < 50; ++line)
    for (int i = 0; i < 200; ++i)
      add (4.0 + 0.005 * i, 0.02 * line, 0.001 * random.gaussian(), 4u);
  return s;
}

std::vector<std::uint32_t>
mergedLabels (const InterleavedScene& s, unsigned int threads = 2)
{
  pcl_ext::CoplanarSegmentMerging<Point> merging;
  merging.setInputCloud (s.cloud);
  merging.setSegmentLabels (s.labels);
  merging.setKSearch (50);
  merging.setNumberOfThreads (threads);
  Labels out;
  EXPECT_TRUE (merging.compute (out));
  std::vector<std::uint32_t> ids;
  for (const auto& l : out)
    ids.push_back (l.label);
  return ids;
}

/** The output label of the first point of each input label. */
std::vector<std::uint32_t>
labelOfEach (const InterleavedScene& s, const std::vector<std::uint32_t>& ids)
{
  std::vector<std::uint32_t> of (5, 0);
  for (std::size_t i = ids.size(); i-- > 0;)
    of[(*s.labels)[i].label] = ids[i];
  return of;
}
} // namespace

TEST (CoplanarSegmentMerging, InterleavedLinesOfOnePlaneAreMergedOthersKeptApart)
{
  const InterleavedScene s = makeInterleavedScene();
  const std::vector<std::uint32_t> ids = mergedLabels (s);
  ASSERT_EQ (ids.size(), s.cloud->size());
  const auto of = labelOfEach (s, ids);
  // The alternate lines are one segment; the wall they meet and the distant patch of
  // the same plane are others; labels renumbered 1, 2, 3.
  EXPECT_EQ (of[1], 1u);
  EXPECT_EQ (of[2], 1u);
  EXPECT_EQ (of[3], 2u);
  EXPECT_EQ (of[4], 3u);
  for (std::size_t i = 0; i < ids.size(); ++i)
    ASSERT_EQ (ids[i], of[(*s.labels)[i].label]) << i;
}

TEST (CoplanarSegmentMerging, ParallelPiecesApartByManyResidualsStaySeparate)
{
  // Every other line 2 cm above the plane (20 times the noise): interleaved, but two
  // surfaces.
  const InterleavedScene s = makeInterleavedScene (0.02);
  const auto of = labelOfEach (s, mergedLabels (s));
  EXPECT_NE (of[1], of[2]);
}

TEST (CoplanarSegmentMerging, AnyThreadCountAndPartsSummedGiveTheSameMerges)
{
  const InterleavedScene s = makeInterleavedScene();
  EXPECT_EQ (mergedLabels (s, 1), mergedLabels (s, 2));
  // The sums of two halves of the points, added, decide the same merges.
  pcl_ext::CoplanarSegmentMerging<Point> merging;
  merging.setInputCloud (s.cloud);
  merging.setSegmentLabels (s.labels);
  merging.setNumberOfThreads (2);
  auto first = pcl::make_shared<pcl::Indices>(),
       second = pcl::make_shared<pcl::Indices>();
  for (std::size_t i = 0; i < s.cloud->size(); ++i)
    (i % 3 == 0 ? first : second)->push_back (static_cast<pcl::index_t> (i));
  pcl_ext::SegmentContacts whole, part_a, part_b;
  ASSERT_TRUE (merging.accumulate (whole));
  ASSERT_TRUE (merging.accumulate (part_a, first));
  ASSERT_TRUE (merging.accumulate (part_b, second));
  part_a.add (part_b);
  EXPECT_EQ (part_a.contacts(), whole.contacts());
  ASSERT_EQ (part_a.planes().size(), whole.planes().size());
  for (const auto& [label, sums] : whole.planes())
    EXPECT_EQ (part_a.planes().at (label).size(), sums.size());
  std::size_t merges_whole = 0, merges_parts = 0;
  EXPECT_EQ (pcl_ext::mergeInterleavedCoplanarSegments (
                 whole, pcl_ext::CoplanarMergeCriteria(), &merges_whole),
             pcl_ext::mergeInterleavedCoplanarSegments (
                 part_a, pcl_ext::CoplanarMergeCriteria(), &merges_parts));
  EXPECT_EQ (merges_whole, 1u);
  EXPECT_EQ (merges_parts, 1u);
}

namespace {
/** The new label of \a label in the result of mergeInterleavedCoplanarSegments (0:
 * none). */
std::uint32_t
newLabel (const std::vector<std::pair<std::uint32_t, std::uint32_t>>& map,
          std::uint32_t label)
{
  for (const auto& [old_label, new_label] : map)
    if (old_label == label)
      return new_label;
  return 0;
}

/** The plane sums of \a n points spread over a square of side \a size centred at
 * (\a x, 0) in the plane z = \a z, 1 mm noise. */
pcl_ext::SegmentContacts::PlaneSums
patch (int n, double x, double size, double z, pcl_ext::RandomStream& random)
{
  pcl_ext::SegmentContacts::PlaneSums s;
  for (int i = 0; i < n; ++i)
    s.add (Eigen::Vector3d (x + size * (random.uniform() - 0.5),
                            size * (random.uniform() - 0.5),
                            z + 0.001 * random.gaussian()));
  return s;
}
} // namespace

TEST (MergeInterleavedCoplanarSegments, APieceBetweenTwoSurfacesJoinsOneOfThem)
{
  // Two patches of one plane (1 and 2, not in contact) and a small piece (3) lying
  // among the points of both: 50 % of its points touch 1, 40 % touch 2. It joins 1,
  // the one it is most a part of; 1 and 2 then share too small a part of their points
  // to merge, so they are not chained together through it.
  pcl_ext::RandomStream random (5);
  pcl_ext::SegmentContacts contacts;
  contacts.addPoints (1, patch (1000, 0.0, 1.0, 0.0, random));
  contacts.addPoints (2, patch (900, 1.2, 1.0, 0.0, random));
  contacts.addPoints (3, patch (100, 0.6, 0.3, 0.0, random));
  contacts.addContacts (3, 1, 50);
  contacts.addContacts (1, 3, 60);
  contacts.addContacts (3, 2, 40);
  contacts.addContacts (2, 3, 45);
  std::size_t merges = 0;
  const auto map = pcl_ext::mergeInterleavedCoplanarSegments (
      contacts, pcl_ext::CoplanarMergeCriteria(), &merges);
  ASSERT_EQ (map.size(), 3u);
  EXPECT_EQ (merges, 1u);
  EXPECT_EQ (newLabel (map, 1), 1u);
  EXPECT_EQ (newLabel (map, 3), 1u);
  EXPECT_EQ (newLabel (map, 2), 2u);
}

TEST (MergeInterleavedCoplanarSegments, SumsFarFromTheOriginKeepTheirResiduals)
{
  // A plane 6,000 km from the frame's origin: the residuals (1 mm) survive the sums
  // around each segment's reference, and two pieces 2 cm apart are not merged.
  pcl_ext::RandomStream random (9);
  const Eigen::Vector3d far (6.0e6, 6.0e6, 100.0);
  pcl_ext::SegmentContacts contacts;
  for (std::uint32_t label = 1; label <= 2; ++label) {
    pcl_ext::SegmentContacts::PlaneSums part_a, part_b;
    for (int i = 0; i < 400; ++i) {
      const Eigen::Vector3d p =
          far + Eigen::Vector3d (random.uniform(),
                                 random.uniform(),
                                 (label == 2 ? 0.02 : 0.0) + 0.001 * random.gaussian());
      (i % 2 == 0 ? part_a : part_b).add (p);
    }
    part_a.add (part_b);
    contacts.addPoints (label, part_a);
    Eigen::Vector3d centroid;
    Eigen::Matrix3d covariance;
    ASSERT_EQ (part_a.finish (covariance, centroid), 400u);
    EXPECT_NEAR (covariance (2, 2), 1e-6, 3e-7);
  }
  contacts.addContacts (1, 2, 300);
  contacts.addContacts (2, 1, 300);
  std::size_t merges = 1;
  const auto map = pcl_ext::mergeInterleavedCoplanarSegments (
      contacts, pcl_ext::CoplanarMergeCriteria(), &merges);
  EXPECT_EQ (merges, 0u);
  EXPECT_NE (newLabel (map, 1), newLabel (map, 2));
}

TEST (MergeInterleavedCoplanarSegments, AnyLabelsHoweverLarge)
{
  // Labels near the largest 32-bit value: only those in use are stored; the result is
  // that of small labels in the same order.
  pcl_ext::RandomStream random (12);
  pcl_ext::SegmentContacts large, small;
  const std::uint32_t big = 4294967290u;
  const auto a = patch (500, 0.0, 1.0, 0.0, random),
             b = patch (400, 0.2, 1.0, 0.0, random);
  large.addPoints (big, a);
  large.addPoints (big + 3, b);
  large.addContacts (big + 3, big, 300);
  small.addPoints (1, a);
  small.addPoints (2, b);
  small.addContacts (2, 1, 300);
  std::size_t merges = 0;
  const auto map = pcl_ext::mergeInterleavedCoplanarSegments (
      large, pcl_ext::CoplanarMergeCriteria(), &merges);
  EXPECT_EQ (merges, 1u);
  ASSERT_EQ (map.size(), 2u);
  EXPECT_EQ (newLabel (map, big), 1u);
  EXPECT_EQ (newLabel (map, big + 3), 1u);
  const auto reference = pcl_ext::mergeInterleavedCoplanarSegments (
      small, pcl_ext::CoplanarMergeCriteria());
  EXPECT_EQ (newLabel (reference, 1), 1u);
  EXPECT_EQ (newLabel (reference, 2), 1u);
}

TEST (CoplanarSegmentMerging, BadInputGivesAnErrorAndNoOutput)
{
  const InterleavedScene s = makeInterleavedScene();
  pcl_ext::CoplanarSegmentMerging<Point> merging;
  Labels out;
  out.resize (3);
  EXPECT_FALSE (merging.compute (out)); // no cloud
  EXPECT_TRUE (out.empty());
  merging.setInputCloud (pcl::make_shared<Cloud>());
  EXPECT_FALSE (merging.compute (out)); // empty cloud
  merging.setInputCloud (s.cloud);
  EXPECT_FALSE (merging.compute (out)); // no labels
  auto wrong = pcl::make_shared<Labels>();
  wrong->resize (5);
  merging.setSegmentLabels (wrong);
  EXPECT_FALSE (merging.compute (out)); // labels of the wrong size
  merging.setSegmentLabels (s.labels);
  merging.setContactK (0);
  EXPECT_FALSE (merging.compute (out));
  merging.setContactK (20);
  pcl_ext::CoplanarMergeCriteria bad;
  bad.min_contact_fraction = 0.0;
  merging.setCriteria (bad);
  EXPECT_FALSE (merging.compute (out));
  bad = pcl_ext::CoplanarMergeCriteria();
  bad.distance_factor = std::nan ("");
  merging.setCriteria (bad);
  EXPECT_FALSE (merging.compute (out));
  EXPECT_TRUE (out.empty());
  // A point without coordinates takes no part (its segment's label is mapped as the
  // others'); the rest merge as before.
  {
    auto cloud = pcl::make_shared<Cloud> (*s.cloud);
    (*cloud)[0].x = std::numeric_limits<float>::quiet_NaN();
    merging.setCriteria (pcl_ext::CoplanarMergeCriteria());
    merging.setInputCloud (cloud);
    ASSERT_TRUE (merging.compute (out));
    ASSERT_EQ (out.size(), cloud->size());
    EXPECT_EQ (out[1].label, 1u);
    merging.setInputCloud (s.cloud);
  }
  // Fewer points than the neighbourhood's k: the search refuses, no output.
  {
    auto tiny = pcl::make_shared<Cloud>();
    auto labels = pcl::make_shared<Labels>();
    for (int i = 0; i < 4; ++i) {
      tiny->push_back (Point (0.1f * i, 0.0f, 0.0f));
      pcl::Label l;
      l.label = 1 + i % 2;
      labels->push_back (l);
    }
    pcl_ext::CoplanarSegmentMerging<Point> small;
    small.setInputCloud (tiny);
    small.setSegmentLabels (labels);
    EXPECT_FALSE (small.compute (out));
    EXPECT_TRUE (out.empty());
  }
  // No segment at all: nothing to merge, the labels as they were.
  auto none = pcl::make_shared<Labels>();
  none->resize (s.cloud->size());
  merging.setCriteria (pcl_ext::CoplanarMergeCriteria());
  merging.setSegmentLabels (none);
  ASSERT_TRUE (merging.compute (out));
  ASSERT_EQ (out.size(), s.cloud->size());
  for (const auto& l : out)
    ASSERT_EQ (l.label, 0u);
}
