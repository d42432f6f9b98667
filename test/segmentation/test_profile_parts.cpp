/*
 * ProfilePartSegmentation: a cloud segmented part by part, each part holding whole
 * profiles of one stack, with what depends on more (the frame, the mean gaps, the
 * curve ends) handed in from all the parts, gives the whole cloud's segments.
 */
#include "profile_test_clouds.h"

#include <pcl_ext/segmentation/profile_graph.h>
#include <pcl_ext/segmentation/profile_part_segmentation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace {
using Segmentation = pcl_ext::ProfileSegmentation<pcl::PointXYZ>;
using PartSegmentation = pcl_ext::ProfilePartSegmentation<pcl::PointXYZ>;
using pcl_ext::profiles::CurveScores;

/** The whole cloud's segments of a part-by-part curve fitting of \a cloud, each
 * stack's profiles cut into \a parts runs, with the whole run's \a spacing and \a
 * width. */
std::vector<std::uint32_t>
segmentByParts (const profile_test::Cloud::Ptr& cloud,
                double spacing,
                double width,
                bool local_threshold,
                int parts)
{
  const std::size_t n = cloud->size();
  const auto normals = pcl_ext::profiles::makeStackNormals (
      4, pcl_ext::profiles::StackDistribution::Hemisphere);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : *cloud)
    centre += p.getVector3fMap().cast<double>();
  centre /= static_cast<double> (n);
  // Each stack's origin and each point's part.
  std::vector<double> origins (normals.size());
  std::vector<std::vector<int>> part_of (normals.size(), std::vector<int> (n));
  for (std::size_t s = 0; s < normals.size(); ++s) {
    const Eigen::Vector3d d =
        pcl_ext::profiles::stackDirection (normals[s].normalized());
    std::vector<double> t (n);
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3f c =
          ((*cloud)[i].getVector3fMap().cast<double>() - centre).cast<float>();
      t[i] = d.dot (c.cast<double>());
      lo = std::min (lo, t[i]);
      hi = std::max (hi, t[i]);
    }
    origins[s] = lo;
    const double profiles = std::floor ((hi - lo) / width) + 1;
    for (std::size_t i = 0; i < n; ++i) {
      const double profile = std::floor ((t[i] - lo) / width);
      part_of[s][i] = static_cast<int> (profile * parts / profiles);
    }
  }
  const auto makePart = [&] (std::size_t s, int part, std::vector<int>& index) {
    auto points = pcl::make_shared<profile_test::Cloud>();
    index.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (part_of[s][i] == part) {
        points->push_back ((*cloud)[i]);
        index.push_back (static_cast<int> (i));
      }
    PartSegmentation seg;
    seg.setInputCloud (points);
    seg.setStackNormals ({normals[s]});
    seg.setPointSpacing (spacing);
    seg.setCloudFrame (centre, {origins[s]});
    seg.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
    seg.setLocalThreshold (local_threshold);
    seg.setNumberOfThreads (1);
    return seg;
  };

  // Local thresholds: each stack's mean gap over every part, in the points' order.
  std::vector<double> mean_gaps;
  if (local_threshold)
    for (std::size_t s = 0; s < normals.size(); ++s) {
      std::vector<float> gap (n, NAN);
      double longest = 0.0;
      for (int part = 0; part < parts; ++part) {
        std::vector<int> index;
        PartSegmentation seg = makePart (s, part, index);
        std::vector<std::vector<float>> gaps;
        EXPECT_TRUE (seg.computeLocalGaps (gaps));
        for (std::size_t k = 0; k < index.size(); ++k)
          gap[index[k]] = gaps[0][k];
        longest = seg.getUsedMaxThreshold();
      }
      double sum = 0.0;
      std::size_t count = 0;
      for (const float g : gap)
        if (g < static_cast<float> (longest)) {
          sum += g;
          ++count;
        }
      mean_gaps.push_back (count ? sum / static_cast<double> (count) : 0.0);
    }

  // First run: the scores and chains of every part.
  std::vector<CurveScores> scores (normals.size());
  std::vector<std::vector<pcl_ext::profiles::GraphEdge>> edges (normals.size());
  pcl_ext::profiles::CurveEndRule rules[4];
  for (std::size_t s = 0; s < normals.size(); ++s) {
    auto& all = scores[s];
    all.evaluated.assign (n, 0);
    all.turn.assign (n, 0.f);
    all.rms.assign (n, 0.f);
    all.noise.assign (n, 0.f);
    all.turn_sigma.assign (n, 0.f);
    std::vector<float> rms, noise;
    for (int part = 0; part < parts; ++part) {
      std::vector<int> index;
      PartSegmentation seg = makePart (s, part, index);
      if (local_threshold)
        seg.setStackMeanGaps ({mean_gaps[s]});
      std::vector<CurveScores> part_scores;
      std::vector<std::vector<Segmentation::Edge>> chains;
      EXPECT_TRUE (seg.computeCurveScores (part_scores, chains));
      for (std::size_t k = 0; k < index.size(); ++k) {
        const auto& p = part_scores[0];
        all.evaluated[index[k]] = p.evaluated[k];
        all.turn[index[k]] = p.turn[k];
        all.rms[index[k]] = p.rms[k];
        all.noise[index[k]] = p.noise[k];
        all.turn_sigma[index[k]] = p.turn_sigma[k];
        if (p.evaluated[k]) {
          rms.push_back (p.rms[k]);
          noise.push_back (p.noise[k]);
        }
      }
      // The medians: each stack's over every part.
      if (part == parts - 1)
        rules[s] = seg.getCurveEndRule (pcl_ext::profiles::upperMedian (rms),
                                        pcl_ext::profiles::upperMedian (noise));
    }
  }
  // Each point's own curve ends, and a breakpoint where any stack ends a curve.
  std::vector<std::vector<std::uint8_t>> own (normals.size(),
                                              std::vector<std::uint8_t> (n, 0));
  std::vector<std::uint8_t> breakpoints (n, 0);
  for (std::size_t s = 0; s < normals.size(); ++s)
    for (std::size_t i = 0; i < n; ++i)
      if (pcl_ext::profiles::isCurveEnd (scores[s], i, rules[s], M_PI / 6.0))
        own[s][i] = breakpoints[i] = 1;
  // Last run: the chains and the joins across junctions of every part.
  std::vector<std::uint8_t> absorbed (n, 0);
  for (std::size_t s = 0; s < normals.size(); ++s)
    for (int part = 0; part < parts; ++part) {
      std::vector<int> index;
      PartSegmentation seg = makePart (s, part, index);
      if (local_threshold)
        seg.setStackMeanGaps ({mean_gaps[s]});
      std::vector<std::uint8_t> part_own (index.size()), part_breaks (index.size());
      for (std::size_t k = 0; k < index.size(); ++k) {
        part_own[k] = own[s][index[k]];
        part_breaks[k] = breakpoints[index[k]];
      }
      std::vector<std::vector<Segmentation::Edge>> part_edges;
      std::vector<std::uint8_t> part_out;
      EXPECT_TRUE (seg.computeCurveJoins ({part_own},
                                          part_breaks,
                                          {rules[s].junction_tolerance},
                                          part_edges,
                                          part_out));
      for (const auto& e : part_edges[0])
        edges[s].push_back ({static_cast<std::uint32_t> (index[e.source]),
                             static_cast<std::uint32_t> (index[e.target])});
      for (std::size_t k = 0; k < index.size(); ++k)
        absorbed[index[k]] = absorbed[index[k]] || part_out[k];
    }
  for (std::size_t i = 0; i < n; ++i)
    breakpoints[i] = breakpoints[i] || absorbed[i];
  std::vector<std::uint32_t> labels;
  pcl_ext::profiles::labelSegments (n, edges, breakpoints, labels);
  return labels;
}

/** Whether two labellings are one partition. */
bool
samePartition (const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b)
{
  if (a.size() != b.size())
    return false;
  std::map<std::uint32_t, std::uint32_t> ab, ba;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto x = ab.emplace (a[i], b[i]).first->second;
    const auto y = ba.emplace (b[i], a[i]).first->second;
    if (x != b[i] || y != a[i])
      return false;
  }
  return true;
}

/** Two plates crossing along a line (curves crossing in the profiles: junctions) and
 * the coaxial pipes beside them. */
profile_test::LabelledCloud
crossingPlates ()
{
  auto scene = profile_test::coarseCoaxialPipes();
  std::mt19937 rng (3);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  profile_test::addRectangle (scene, {0, 1.5, 0}, x, y, 1.5, 1.5, 0.03, 4, rng);
  profile_test::addRectangle (scene, {0.75, 1.5, -0.6}, y, z, 1.5, 1.2, 0.03, 5, rng);
  return scene;
}

void
expectPartsGiveTheWhole (bool local_threshold)
{
  const auto scene = crossingPlates();
  Segmentation whole;
  whole.setInputCloud (scene.cloud);
  whole.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
  whole.setLocalThreshold (local_threshold);
  whole.setNumberOfThreads (1);
  std::vector<pcl::PointIndices> clusters;
  whole.extract (clusters);
  ASSERT_GT (clusters.size(), 1u);
  ASSERT_FALSE (whole.getBreakpoints().empty());
  EXPECT_GT (whole.getJunctionJoins(), 0u); // curves followed across junctions
  std::vector<std::uint32_t> expected (scene.cloud->size(), 0);
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (const auto i : clusters[c].indices)
      expected[i] = static_cast<std::uint32_t> (c);
  for (const int parts : {1, 3}) {
    const auto labels = segmentByParts (scene.cloud,
                                        whole.getUsedPointSpacing(),
                                        whole.getUsedProfileWidth(),
                                        local_threshold,
                                        parts);
    EXPECT_TRUE (samePartition (labels, expected)) << parts << " parts";
  }
}
} // namespace

TEST (ProfilePartSegmentation, CurveFittingByPartsGivesTheWholeCloudsSegments)
{
  expectPartsGiveTheWhole (false);
}

TEST (ProfilePartSegmentation, WithLocalThresholdsToo)
{
  expectPartsGiveTheWhole (true);
}

TEST (ProfilePartSegmentation, StagesRefuseWhatTheyCannotRun)
{
  const auto scene = profile_test::coarseCoaxialPipes();
  PartSegmentation seg;
  seg.setInputCloud (scene.cloud);
  std::vector<CurveScores> scores;
  std::vector<std::vector<Segmentation::Edge>> chains;
  EXPECT_FALSE (seg.computeCurveScores (scores, chains)); // proximity: no scores
  std::vector<std::vector<float>> gaps;
  EXPECT_FALSE (seg.computeLocalGaps (gaps)); // local thresholds off
  seg.setProfileSegmentation (Segmentation::ProfileMethod::CurveFitting);
  std::vector<std::uint8_t> out;
  // Flags not one per point.
  EXPECT_FALSE (seg.computeCurveJoins ({std::vector<std::uint8_t> (3, 0)},
                                       std::vector<std::uint8_t> (3, 0),
                                       {0.01},
                                       chains,
                                       out));
  EXPECT_TRUE (chains.empty());
}
