/*
 * Tests of the initiate-and-extend plane matching (Khoshelham & Gorte 2009,
 * section 3.3) on analytic plane sets of the H-shaped building.
 */
#include "plane_fixtures.h"

#include <pcl_ext/evaluation/registration_metrics.h>
#include <pcl_ext/registration/plane_matching.h>
#include <pcl_ext/registration/plane_matching_registration.h>

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <limits>

using namespace pcl_ext;

namespace {
const double kPi = 3.14159265358979323846;

// Every pair is right when the truth maps the scan plane onto its map plane.
int
wrongPairs (const std::vector<Plane>& scan,
            const std::vector<Plane>& map,
            const std::vector<PlanePair>& matches,
            const Eigen::Matrix4d& truth)
{
  int wrong = 0;
  for (const auto& pair : matches) {
    const Plane moved = transformPlane (scan[pair.scan], truth);
    const double cosine = pair.sign * moved.normal.dot (map[pair.map].normal);
    if (cosine < std::cos (2.0 * kPi / 180.0) ||
        std::abs (pair.sign * moved.d - map[pair.map].d) > 0.5)
      ++wrong;
  }
  return wrong;
}

// The symmetry of the symmetric H (test::hShape): a half turn about its centre (20,
// 15).
Eigen::Matrix4d
halfTurnOfTheH ()
{
  Eigen::Matrix4d half_turn = Eigen::Matrix4d::Identity();
  half_turn.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd (kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  half_turn.topRightCorner<3, 1>() = Eigen::Vector3d (40, 30, 0);
  return half_turn;
}

// The asymmetric plan: a rotation maps it onto itself only as the identity.
std::vector<MapPlane>
hMapPlanes ()
{
  std::vector<MapPlane> map;
  EXPECT_TRUE (computeMapPlanes (test::asymmetricH(), MapPlaneParameters(), map));
  return map;
}
} // namespace

TEST (PlaneMatching, InitialCombinationCountsAreEquation13)
{
  // Table 3, k = 3, "without constraints", m = n = 7..12.
  const std::uint64_t table3[] = {7350, 18816, 42336, 86400, 163350, 290400};
  for (int m = 7; m <= 12; ++m)
    EXPECT_EQ (countInitialCombinations (m, m, 3), table3[m - 7]);
  EXPECT_EQ (countInitialCombinations (10, 10, 4),
             210u * 5040u); // "in the order of 10^6"
  EXPECT_EQ (countInitialCombinations (3, 10, 4), 0u);

  // With every constraint off the search enumerates exactly that many combinations.
  const auto map = hMapPlanes();
  std::mt19937 rng (4);
  const auto scan = test::scanPlanes (map, test::randomPose (rng), rng, 0.0, 0.0);
  PlaneMatchingParameters p;
  p.k = 3;
  p.scan_initial = p.map_initial = 6;
  p.vertical_constraint = p.orientation_constraint = p.residual_constraint = false;
  PlaneMatchingResult r;
  ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, r));
  EXPECT_EQ (r.statistics.unconstrained, countInitialCombinations (6, 6, 3));
  EXPECT_EQ (r.statistics.orientation, r.statistics.unconstrained);
  EXPECT_EQ (r.statistics.degenerate + r.statistics.residual, r.statistics.orientation);
}

TEST (PlaneMatching, ExactPlanesGiveTheTruth)
{
  const auto map = hMapPlanes();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    const auto scan = test::scanPlanes (map, truth, rng, 0.0, 0.0);
    for (const bool oriented : {false, true}) {
      PlaneMatchingParameters p;
      p.oriented_normals = oriented;
      PlaneMatchingResult r;
      ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, r));
      EXPECT_EQ (r.matches.size(), scan.size()); // 9 distinct planes, all matched
      EXPECT_EQ (wrongPairs (scan, test::slice (map), r.matches, truth), 0);
      const auto error = computeTransformationError (r.estimate.transformation, truth);
      EXPECT_LT (error.rotation_deg, 1e-6);
      EXPECT_LT (error.translation, 1e-6);
    }
  }
}

// The robustness anchor on analytic planes: 100 random poses (yaw any, tilt <= 3 deg,
// shift <= 100 m), 30 % superfluous and 20 % missing planes, plane noise of a 20 cm
// scan.
TEST (PlaneMatching, RightMatchOverRandomPosesWithOutliersAndMissingPlanes)
{
  const auto map = hMapPlanes();
  double worst_rotation = 0.0, worst_translation = 0.0;
  std::size_t fewest = 100;
  for (unsigned seed = 1; seed <= 100; ++seed) {
    std::mt19937 rng (1000 + seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    // 9 distinct planes: 2 missing walls (20 %), 3 superfluous (30 % of 10).
    const auto scan = test::scanPlanes (map, truth, rng, 0.2 * kPi / 180.0, 0.05, 2, 3);
    PlaneMatchingParameters p;
    PlaneMatchingResult r;
    ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, r)) << "seed " << seed;
    EXPECT_EQ (wrongPairs (scan, test::slice (map), r.matches, truth), 0)
        << "seed " << seed;
    // Translation error at the building's centre, in scan coordinates.
    const Eigen::Vector3d centre =
        (truth.inverse() * Eigen::Vector4d (20, 15, 5, 1)).head<3>();
    const auto error =
        computeTransformationError (r.estimate.transformation, truth, centre);
    worst_rotation = std::max (worst_rotation, error.rotation_deg);
    worst_translation = std::max (worst_translation, error.translation);
    fewest = std::min (fewest, r.matches.size());
  }
  EXPECT_LE (worst_rotation, 0.5);
  EXPECT_LE (worst_translation, 0.2);
  EXPECT_GE (fewest, 7u); // every present building plane
  std::printf ("100 poses: worst rotation %.3f deg, worst translation %.3f m, fewest "
               "matches %zu\n",
               worst_rotation,
               worst_translation,
               fewest);
}

TEST (PlaneMatching, ConstraintsCutCombinationsByOrdersOfMagnitude)
{
  const auto map = hMapPlanes();
  std::mt19937 rng (17);
  const Eigen::Matrix4d truth = test::randomPose (rng);
  const auto scan = test::scanPlanes (map, truth, rng, 0.2 * kPi / 180.0, 0.05, 0, 3);
  PlaneMatchingParameters p;
  p.scan_initial = p.map_initial = 12;
  PlaneMatchingResult r;
  ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, r));
  const auto& s = r.statistics;
  EXPECT_EQ (s.unconstrained, countInitialCombinations (12, 12, 4));
  EXPECT_LE (s.vertical, s.unconstrained);
  EXPECT_LE (s.orientation, s.vertical);
  EXPECT_LT (s.orientation, s.unconstrained / 10);
  EXPECT_LT (s.residual, s.unconstrained / 1000);
  EXPECT_GT (s.residual, 0u);
  // The screens of constraint 3 leave fewer estimates than there are combinations to
  // estimate.
  EXPECT_LT (s.estimations, s.orientation - s.degenerate);
  std::printf (
      "m = n = 12, k = 4: %llu unconstrained, %llu vertical, %llu orientation (%llu "
      "degenerate), %llu residual, %llu estimates, %.4f s\n",
      (unsigned long long)s.unconstrained,
      (unsigned long long)s.vertical,
      (unsigned long long)s.orientation,
      (unsigned long long)s.degenerate,
      (unsigned long long)s.residual,
      (unsigned long long)s.estimations,
      s.seconds);
}

TEST (PlaneMatching, DeterministicForAnyThreadCountAndNormalSigns)
{
  const auto map = hMapPlanes();
  std::mt19937 rng (23);
  const Eigen::Matrix4d truth = test::randomPose (rng);
  auto scan = test::scanPlanes (map, truth, rng, 0.2 * kPi / 180.0, 0.05, 1, 3);
  PlaneMatchingParameters p;
  PlaneMatchingResult one, two;
  p.threads = 1;
  ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, one));
  p.threads = 2;
  ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, two));
  ASSERT_EQ (one.matches.size(), two.matches.size());
  for (std::size_t i = 0; i < one.matches.size(); ++i)
    EXPECT_TRUE (one.matches[i].scan == two.matches[i].scan &&
                 one.matches[i].map == two.matches[i].map);
  EXPECT_EQ (one.estimate.transformation, two.estimate.transformation);

  // Flip every other scan plane: without oriented normals the match is the same.
  for (std::size_t i = 0; i < scan.size(); i += 2) {
    scan[i].normal = -scan[i].normal;
    scan[i].d = -scan[i].d;
  }
  PlaneMatchingResult flipped;
  ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, flipped));
  EXPECT_EQ (flipped.matches.size(), one.matches.size());
  EXPECT_EQ (wrongPairs (scan, test::slice (map), flipped.matches, truth), 0);
  EXPECT_LT ((flipped.estimate.transformation - one.estimate.transformation)
                 .cwiseAbs()
                 .maxCoeff(),
             1e-9);
}

TEST (PlaneMatching, BadInputDoesNotConverge)
{
  const auto map = hMapPlanes();
  std::mt19937 rng (5);
  const Eigen::Matrix4d truth = test::randomPose (rng);
  const auto scan = test::scanPlanes (map, truth, rng, 0.0, 0.0);
  PlaneMatchingParameters p;
  PlaneMatchingResult r;
  // Fewer than k planes, or none.
  EXPECT_FALSE (matchPlanes (
      std::vector<Plane> (scan.begin(), scan.begin() + 2), test::slice (map), p, r));
  EXPECT_FALSE (r.converged);
  EXPECT_FALSE (matchPlanes ({}, test::slice (map), p, r));
  EXPECT_FALSE (matchPlanes (scan, {}, p, r));
  // All walls parallel: the floor and walls facing +-y only.
  std::vector<Plane> parallel_map, parallel_scan;
  for (const auto& plane : test::slice (map))
    if (std::abs (plane.normal.x()) < 0.5)
      parallel_map.push_back (plane);
  for (const auto& plane : scan)
    if (std::abs (transformPlane (plane, truth).normal.x()) < 0.5)
      parallel_scan.push_back (plane);
  EXPECT_FALSE (matchPlanes (parallel_scan, parallel_map, p, r));
  EXPECT_FALSE (r.converged);
  EXPECT_GT (r.statistics.degenerate, 0u);
  // Non-finite planes.
  auto nan_scan = scan;
  nan_scan[3].normal.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE (matchPlanes (nan_scan, test::slice (map), p, r));
  // Nonsense parameters.
  for (int which = 0; which < 6; ++which) {
    PlaneMatchingParameters bad;
    switch (which) {
    case 0:
      bad.k = 2;
      break;
    case 1:
      bad.scan_initial = 3;
      break;
    case 2:
      bad.map_initial = 1000;
      break;
    case 3:
      bad.distance_tolerance = -1.0;
      break;
    case 4:
      bad.angle_tolerance_deg = std::numeric_limits<double>::quiet_NaN();
      break;
    default:
      bad.vertical_tolerance_deg = 90.0;
      break;
    }
    EXPECT_FALSE (matchPlanes (scan, test::slice (map), bad, r)) << which;
    EXPECT_FALSE (r.converged);
  }
}

// The building scene's default H is symmetric under a half turn about its centre (20,
// 15): the map cannot tell the true pose from the turned one, and both fit every plane
// equally well.
TEST (PlaneMatching, SymmetricPlanIsMatchedUpToItsHalfTurn)
{
  std::vector<MapPlane> map;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), map));
  const Eigen::Matrix4d half_turn = halfTurnOfTheH();
  int turned = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    const auto scan = test::scanPlanes (map, truth, rng, 0.2 * kPi / 180.0, 0.05, 2, 3);
    PlaneMatchingResult r;
    ASSERT_TRUE (matchPlanes (scan, test::slice (map), PlaneMatchingParameters(), r));
    const Eigen::Vector3d centre =
        (truth.inverse() * Eigen::Vector4d (20, 15, 5, 1)).head<3>();
    const auto direct =
        computeTransformationError (r.estimate.transformation, truth, centre);
    const auto mirrored = computeTransformationError (
        r.estimate.transformation, half_turn * truth, centre);
    const bool is_turned = mirrored.rotation_deg < direct.rotation_deg;
    turned += is_turned;
    const auto& error = is_turned ? mirrored : direct;
    EXPECT_LT (error.rotation_deg, 0.5) << "seed " << seed;
    EXPECT_LT (error.translation, 0.2) << "seed " << seed;
    EXPECT_EQ (
        wrongPairs (
            scan, test::slice (map), r.matches, is_turned ? half_turn * truth : truth),
        0);
  }
  std::printf ("symmetric H: %d of 20 poses matched the half-turned way\n", turned);
}

// The symmetric H fits the scan in two poses, and both are reported. A ceiling 3 m
// above the floor, with a fifth of the floor's points, pairs with the map's floor as
// well as the floor does (as many pairs, the pose 3 m lower): not a pose the map cannot
// tell apart, since it holds a fraction of the support (ambiguity_support).
TEST (PlaneMatching, CandidatesAreTheSymmetricPosesNotAStandInFloor)
{
  std::vector<MapPlane> map;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), map));
  const Eigen::Matrix4d half_turn = halfTurnOfTheH();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    auto scan = test::scanPlanes (map, truth, rng, 0.1 * kPi / 180.0, 0.02);
    Plane ceiling = map[0]; // the floor, 3 m up
    ASSERT_TRUE (map[0].isFloor());
    ceiling.centroid.z() += 3.0;
    ceiling.d = -ceiling.normal.dot (ceiling.centroid);
    ceiling.extent.translate (Eigen::Vector3d (0, 0, 3));
    ceiling.size = 4000; // the floor's: 20000
    scan.push_back (transformPlane (ceiling, truth.inverse()));
    PlaneMatchingResult r;
    ASSERT_TRUE (matchPlanes (scan, test::slice (map), PlaneMatchingParameters(), r));
    EXPECT_EQ (r.candidates.size(), 2u) << "seed " << seed;
    const Eigen::Vector3d centre =
        (truth.inverse() * Eigen::Vector4d (20, 15, 5, 1)).head<3>();
    int direct = 0, turned = 0;
    for (const auto& candidate : r.candidates) {
      const auto e =
          computeTransformationError (candidate.estimate.transformation, truth, centre);
      const auto m = computeTransformationError (
          candidate.estimate.transformation, half_turn * truth, centre);
      direct += e.rotation_deg < 0.5 && e.translation < 0.2;
      turned += m.rotation_deg < 0.5 && m.translation < 0.2;
    }
    EXPECT_EQ (direct, 1) << "seed " << seed;
    EXPECT_EQ (turned, 1) << "seed " << seed;
  }
}

// A pose score decides between the poses the planes cannot tell apart (the symmetric
// H's true pose and its half turn pair the same planes): a score that favours one by
// more than coverage_margin makes it the result and the only candidate, whichever the
// search ranked first; scores within the margin leave both, in the search's order.
TEST (PlaneMatching, PoseScoreChoosesAmongThePosesThePlanesCannotTellApart)
{
  std::vector<MapPlane> map;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), map));
  const Eigen::Matrix4d half_turn = halfTurnOfTheH();
  const PlaneMatchingParameters parameters;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    const auto scan = test::scanPlanes (map, truth, rng, 0.1 * kPi / 180.0, 0.02);
    const Eigen::Vector3d centre =
        (truth.inverse() * Eigen::Vector4d (20, 15, 5, 1)).head<3>();
    auto near = [&] (const Eigen::Matrix4d& pose, const Eigen::Matrix4d& target) {
      const auto e = computeTransformationError (pose, target, centre);
      return e.rotation_deg < 0.5 && e.translation < 0.2;
    };
    PlaneMatchingResult unscored;
    ASSERT_TRUE (matchPlanes (scan, test::slice (map), parameters, unscored));
    ASSERT_EQ (unscored.candidates.size(), 2u) << "seed " << seed;
    for (const Eigen::Matrix4d& favoured :
         {truth, Eigen::Matrix4d (half_turn * truth)}) {
      PlaneMatchingResult r;
      ASSERT_TRUE (matchPlanes (scan,
                                test::slice (map),
                                parameters,
                                r,
                                Eigen::Matrix4d::Identity(),
                                [&] (const Eigen::Matrix4d& pose) {
                                  return near (pose, favoured) ? 0.8 : 0.6;
                                }));
      EXPECT_TRUE (near (r.estimate.transformation, favoured)) << "seed " << seed;
      ASSERT_EQ (r.candidates.size(), 1u) << "seed " << seed;
      EXPECT_TRUE (near (r.candidates[0].estimate.transformation, favoured));
    }
    // Within the margin (0.1): the search's order, both poses.
    PlaneMatchingResult r;
    const Eigen::Matrix4d second = unscored.candidates[1].estimate.transformation;
    ASSERT_TRUE (matchPlanes (scan,
                              test::slice (map),
                              parameters,
                              r,
                              Eigen::Matrix4d::Identity(),
                              [&] (const Eigen::Matrix4d& pose) {
                                return near (pose, second) ? 0.8 : 0.75;
                              }));
    EXPECT_TRUE (r.estimate.transformation == unscored.estimate.transformation);
    EXPECT_EQ (r.candidates.size(), 2u) << "seed " << seed;
  }
}

// The pose score's settings are checked like the others.
TEST (PlaneMatching, PoseScoreSettingsOutOfRangeAreRefused)
{
  std::vector<MapPlane> map;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), map));
  std::mt19937 rng (1);
  const auto scan = test::scanPlanes (map, test::randomPose (rng), rng, 0.001, 0.02);
  for (int which = 0; which < 3; ++which) {
    PlaneMatchingParameters bad;
    if (which == 0)
      bad.coverage_pairs = -1;
    else if (which == 1)
      bad.coverage_margin = 1.5;
    else
      bad.coverage_margin = std::numeric_limits<double>::quiet_NaN();
    PlaneMatchingResult r;
    testing::internal::CaptureStderr();
    EXPECT_FALSE (matchPlanes (scan, test::slice (map), bad, r)) << which;
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE (log.find ("pose score"), std::string::npos) << log;
    EXPECT_FALSE (r.converged);
  }
}

namespace {
// \a pose turned by \a yaw_deg about the vertical through \a centre (map frame) and
// shifted by \a shift: a rough guess of it.
Eigen::Matrix4d
roughGuess (const Eigen::Matrix4d& pose,
            double yaw_deg,
            const Eigen::Vector3d& shift,
            const Eigen::Vector3d& centre)
{
  Eigen::Affine3d turn =
      Eigen::Translation3d (centre + shift) *
      Eigen::AngleAxisd (yaw_deg * kPi / 180.0, Eigen::Vector3d::UnitZ()) *
      Eigen::Translation3d (-centre);
  return turn.matrix() * pose;
}
} // namespace

// The symmetric H has two exact solutions; bounds around a rough guess of either pick
// that one, every time, and a guess near neither gives none.
TEST (PlaneMatchingBounds, GuessPicksTheSolutionWithinTheBounds)
{
  std::vector<MapPlane> map;
  ASSERT_TRUE (computeMapPlanes (test::hShape(), MapPlaneParameters(), map));
  const Eigen::Matrix4d half_turn = halfTurnOfTheH();
  const Eigen::Vector3d centre (20, 15, 5);
  for (unsigned seed = 1; seed <= 10; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    const auto scan = test::scanPlanes (map, truth, rng, 0.2 * kPi / 180.0, 0.05, 2, 3);
    const Eigen::Vector3d scan_centre =
        (truth.inverse() * centre.homogeneous()).head<3>();
    PlaneMatchingParameters p;
    p.max_rotation_from_guess_deg = 10.0;
    p.max_translation_from_guess = 10.0;
    for (const bool turned : {false, true}) {
      const Eigen::Matrix4d solution =
          turned ? Eigen::Matrix4d (half_turn * truth) : truth;
      PlaneMatchingResult r;
      ASSERT_TRUE (matchPlanes (
          scan,
          test::slice (map),
          p,
          r,
          roughGuess (solution, 5.0, Eigen::Vector3d (3.0, -2.0, 0.5), centre)))
          << "seed " << seed;
      const auto error =
          computeTransformationError (r.estimate.transformation, solution, scan_centre);
      EXPECT_LT (error.rotation_deg, 0.5)
          << "seed " << seed << (turned ? " turned" : "");
      EXPECT_LT (error.translation, 0.2)
          << "seed " << seed << (turned ? " turned" : "");
      EXPECT_EQ (wrongPairs (scan, test::slice (map), r.matches, solution), 0);
    }
    // A quarter turn away from both: at most a partial match of x walls to y walls,
    // within 10 degrees of that guess.
    PlaneMatchingResult none;
    const Eigen::Matrix4d quarter =
        roughGuess (truth, 90.0, Eigen::Vector3d::Zero(), centre);
    if (matchPlanes (scan, test::slice (map), p, none, quarter))
      EXPECT_LE (computeTransformationError (
                     none.estimate.transformation, quarter, scan_centre)
                     .rotation_deg,
                 10.0);
    // Far off the building: nothing within 10 m.
    EXPECT_FALSE (
        matchPlanes (scan,
                     test::slice (map),
                     p,
                     none,
                     roughGuess (truth, 0.0, Eigen::Vector3d (200, 0, 0), centre)));
  }
}

// Bounds that hold the global search's answer give that answer (their pruning rejects
// nothing the bounds accept), with fewer combinations; infinite bounds are the global
// search.
TEST (PlaneMatchingBounds, BoundsHoldingTheAnswerChangeNothingButTheWork)
{
  const auto map = hMapPlanes();
  for (unsigned seed = 1; seed <= 10; ++seed) {
    std::mt19937 rng (seed);
    const Eigen::Matrix4d truth = test::randomPose (rng);
    const auto scan = test::scanPlanes (map, truth, rng, 0.2 * kPi / 180.0, 0.05, 2, 3);
    PlaneMatchingParameters p;
    p.threads = 1;
    PlaneMatchingResult global, infinite, bounded;
    ASSERT_TRUE (matchPlanes (scan, test::slice (map), p, global));
    ASSERT_TRUE (
        matchPlanes (scan,
                     test::slice (map),
                     p,
                     infinite,
                     roughGuess (truth, 45.0, Eigen::Vector3d (50, 0, 0), {})));
    p.max_rotation_from_guess_deg = 8.0;
    p.max_translation_from_guess = 10.0;
    ASSERT_TRUE (matchPlanes (scan,
                              test::slice (map),
                              p,
                              bounded,
                              roughGuess (truth,
                                          -5.0,
                                          Eigen::Vector3d (2.0, 2.0, 0.0),
                                          Eigen::Vector3d (20, 15, 5))));
    for (const auto* r : {&infinite, &bounded}) {
      ASSERT_EQ (r->matches.size(), global.matches.size()) << "seed " << seed;
      for (std::size_t i = 0; i < global.matches.size(); ++i) {
        EXPECT_EQ (r->matches[i].scan, global.matches[i].scan);
        EXPECT_EQ (r->matches[i].map, global.matches[i].map);
      }
      EXPECT_TRUE (
          r->estimate.transformation.isApprox (global.estimate.transformation, 1e-12));
    }
    EXPECT_EQ (infinite.statistics.orientation, global.statistics.orientation);
    EXPECT_LT (bounded.statistics.orientation, global.statistics.orientation / 4);
    EXPECT_LE (bounded.statistics.residual, global.statistics.residual);
  }
}

// Bad bounds (negative, zero, NaN) and a non-finite guess: a PCL_ERROR and no
// convergence, from matchPlanes and from the registration class.
TEST (PlaneMatchingBounds, BadBoundsAndGuessAreRefused)
{
  const auto map = hMapPlanes();
  std::mt19937 rng (3);
  const Eigen::Matrix4d truth = test::randomPose (rng);
  const auto scan = test::scanPlanes (map, truth, rng, 0.0, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double bad : {-1.0, 0.0, nan})
    for (const bool rotation : {true, false}) {
      PlaneMatchingParameters p;
      (rotation ? p.max_rotation_from_guess_deg : p.max_translation_from_guess) = bad;
      PlaneMatchingResult r;
      EXPECT_FALSE (matchPlanes (scan, test::slice (map), p, r, truth))
          << bad << " " << rotation;
      EXPECT_FALSE (r.converged);

      PlaneMatchingRegistration<pcl::PointXYZ, pcl::PointXYZ> reg;
      reg.setMapPlanes (map);
      std::vector<ScanPlane> planes (scan.size());
      for (std::size_t i = 0; i < scan.size(); ++i)
        static_cast<Plane&> (planes[i]) = scan[i];
      reg.setSourcePlanes (planes);
      pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
      cloud->emplace_back (0.f, 0.f, 0.f);
      reg.setInputSource (cloud);
      if (rotation)
        reg.setMaxRotationFromGuess (bad);
      else
        reg.setMaxTranslationFromGuess (bad);
      pcl::PointCloud<pcl::PointXYZ> aligned;
      reg.align (aligned, truth.cast<float>());
      EXPECT_FALSE (reg.hasConverged()) << bad << " " << rotation;
      // Good bounds around the same guess converge.
      reg.setMaxRotationFromGuess (5.0);
      reg.setMaxTranslationFromGuess (5.0);
      reg.align (aligned, truth.cast<float>());
      EXPECT_TRUE (reg.hasConverged());
      EXPECT_DOUBLE_EQ (reg.getMaxRotationFromGuess(), 5.0);
      EXPECT_DOUBLE_EQ (reg.getMaxTranslationFromGuess(), 5.0);
    }
  Eigen::Matrix4d guess = truth;
  guess (0, 3) = std::numeric_limits<double>::infinity();
  PlaneMatchingParameters p;
  p.max_translation_from_guess = 5.0;
  PlaneMatchingResult r;
  EXPECT_FALSE (matchPlanes (scan, test::slice (map), p, r, guess));
}
