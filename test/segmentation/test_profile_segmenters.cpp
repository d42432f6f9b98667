/*
 * Tests of the profile segmenters (Sithole & Mapurisa, section 4.1): proximity
 * chaining, the minimum spanning tree, local gaps and thresholds, AIC curve fits.
 */
#include <pcl_ext/segmentation/profile_segmenters.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

using namespace pcl_ext::profiles;

TEST (ProfileSegmenters, ProximityAndSpanningTreeCutLongLinks)
{
  // Two collinear chains, spacing 1, separated by a gap of 3; threshold 1.5.
  ProfilePoints profile;
  for (int i = 0; i < 10; ++i)
    profile.uv.emplace_back (static_cast<float> (i), 0.f);
  for (int i = 0; i < 10; ++i)
    profile.uv.emplace_back (12.f + i, 0.f);
  profile.uv.emplace_back (3.f, 0.f); // a duplicate of point 3
  profile.t.assign (profile.uv.size(), 0.f);
  std::vector<LocalEdge> edges;
  for (int method = 0; method < 2; ++method) {
    if (method == 0)
      proximityEdges (profile, 1.5, 2, edges);
    else
      spanningTreeEdges (profile, 1.5, edges);
    std::vector<int> comp (profile.uv.size());
    for (std::size_t i = 0; i < comp.size(); ++i)
      comp[i] = static_cast<int> (i);
    // Tiny label propagation to find components.
    for (int pass = 0; pass < 30; ++pass)
      for (const auto& e : edges) {
        EXPECT_LT (e.a, e.b);
        EXPECT_LE ((profile.uv[e.a] - profile.uv[e.b]).norm(), 1.5f);
        comp[e.a] = comp[e.b] = std::min (comp[e.a], comp[e.b]);
      }
    for (int i = 1; i < 10; ++i)
      EXPECT_EQ (comp[i], comp[0]) << "method " << method;
    for (int i = 11; i < 20; ++i)
      EXPECT_EQ (comp[i], comp[10]) << "method " << method;
    EXPECT_NE (comp[0], comp[10]);
    EXPECT_EQ (comp[20], comp[0]); // the duplicate joins its twin
  }
  // A spanning forest: n - components edges.
  spanningTreeEdges (profile, 1.5, edges);
  EXPECT_EQ (edges.size(), profile.uv.size() - 2);
}

TEST (ProfileSegmenters, LocalGapsAndThresholds)
{
  // A dense chain (gap 0.01) and, 0.3 further on, a sparse one (gap 0.06) whose every
  // fourth gap is 0.09; the global threshold 0.05 suits the dense chain only.
  ProfilePoints profile;
  for (int i = 0; i < 40; ++i)
    profile.uv.emplace_back (0.01f * i, 0.f);
  const std::size_t sparse_begin = profile.uv.size();
  float x = 0.69f;
  for (int i = 0; i < 20; ++i, x += (i % 4 == 0 ? 0.09f : 0.06f))
    profile.uv.emplace_back (x, 0.f);
  profile.uv.push_back (profile.uv[20]); // a duplicate of point 20
  profile.t.assign (profile.uv.size(), 0.f);
  std::vector<float> gaps;
  localGaps (profile, 0.2, 8, gaps);
  ASSERT_EQ (gaps.size(), profile.uv.size());
  // The median over a point and its 8 nearest: the wider gaps (a quarter) do not count.
  for (std::size_t i = 0; i < sparse_begin; ++i)
    EXPECT_NEAR (gaps[i], 0.01f, 1e-5f) << i;
  for (std::size_t i = sparse_begin; i + 1 < profile.uv.size(); ++i)
    EXPECT_NEAR (gaps[i], 0.06f, 1e-5f) << i;
  EXPECT_EQ (gaps.back(), gaps[20]); // duplicates share their twin's
  // Nothing within reach: the maximum.
  localGaps (profile, 0.005, 8, gaps);
  for (std::size_t i = 0; i + 1 < profile.uv.size(); ++i)
    EXPECT_FLOAT_EQ (gaps[i], 0.005f) << i;

  // Thresholds proportional to the local gap (0.05 for the dense chain, 0.3 for the
  // sparse one, capped at 0.15), as the pipeline makes them.
  std::vector<float> thresholds (profile.uv.size());
  for (std::size_t i = 0; i < thresholds.size(); ++i)
    thresholds[i] = i < sparse_begin || i + 1 == thresholds.size() ? 0.05f : 0.15f;
  const auto components = [&] (const std::vector<LocalEdge>& edges) {
    std::vector<int> comp (profile.uv.size());
    for (std::size_t i = 0; i < comp.size(); ++i)
      comp[i] = static_cast<int> (i);
    for (std::size_t pass = 0; pass < comp.size(); ++pass)
      for (const auto& e : edges)
        comp[e.a] = comp[e.b] = std::min (comp[e.a], comp[e.b]);
    return std::set<int> (comp.begin(), comp.end()).size();
  };
  std::vector<LocalEdge> edges;
  for (int method = 0; method < 2; ++method) {
    // The global threshold cuts the sparse chain into single points.
    if (method == 0)
      proximityEdges (profile, 0.05, 4, edges);
    else
      spanningTreeEdges (profile, 0.05, edges);
    EXPECT_EQ (components (edges), 21u) << "method " << method;
    // Local thresholds keep it whole, and every link is within both its ends'
    // thresholds.
    if (method == 0)
      proximityEdges (profile, 0.15, 4, edges, &thresholds);
    else
      spanningTreeEdges (profile, 0.15, edges, &thresholds);
    EXPECT_EQ (components (edges), 2u) << "method " << method;
    for (const auto& e : edges)
      EXPECT_LE ((profile.uv[e.a] - profile.uv[e.b]).norm(),
                 std::min (thresholds[e.a], thresholds[e.b]) + 1e-6f);
  }
  // A sparse point 0.08 from the dense chain's end: its threshold would reach the
  // chain, the chain's does not, so the two stay apart.
  profile.uv.emplace_back (0.47f, 0.f);
  profile.t.push_back (0.f);
  thresholds.push_back (0.15f);
  for (int method = 0; method < 2; ++method) {
    if (method == 0)
      proximityEdges (profile, 0.15, 4, edges, &thresholds);
    else
      spanningTreeEdges (profile, 0.15, edges, &thresholds);
    EXPECT_EQ (components (edges), 3u) << "method " << method;
  }
}

TEST (CurveFit, AicSelectsTheModel)
{
  std::mt19937 rng (5);
  std::normal_distribution<double> noise (0.0, 0.001);
  std::vector<double> x, line, parabola, cubic, t;
  for (int i = 0; i < 40; ++i) {
    const double xi = -1.0 + 2.0 * i / 39.0;
    x.push_back (xi);
    t.push_back (0.0);
    line.push_back (0.3 + 0.5 * xi + noise (rng));
    parabola.push_back (0.1 - 0.2 * xi + 0.8 * xi * xi + noise (rng));
    cubic.push_back (0.1 + 0.3 * xi - 0.5 * xi * xi + 1.2 * xi * xi * xi + noise (rng));
  }
  const PolynomialFit a = fitPolynomialAic (x, line, t, 1.0);
  EXPECT_EQ (a.degree, 1);
  EXPECT_NEAR (a.slope, 0.5, 0.01);
  const PolynomialFit b = fitPolynomialAic (x, parabola, t, 1.0);
  EXPECT_EQ (b.degree, 2);
  EXPECT_NEAR (b.slope, -0.2, 0.01);
  const PolynomialFit c = fitPolynomialAic (x, cubic, t, 1.0);
  EXPECT_EQ (c.degree, 3);
  EXPECT_NEAR (c.slope, 0.3, 0.01);
  // The t term absorbs a slant across the profile: y = 0.5 x + 2 t leaves only the
  // noise.
  std::vector<double> slanted;
  for (std::size_t i = 0; i < x.size(); ++i) {
    t[i] = (i % 3) * 0.01;
    slanted.push_back (0.5 * x[i] + 2.0 * t[i] + noise (rng));
  }
  const PolynomialFit d = fitPolynomialAic (x, slanted, t, 1.0);
  EXPECT_EQ (d.degree, 1);
  EXPECT_LT (d.rss, 2.0 * 40 * 0.001 * 0.001);
  EXPECT_EQ (fitPolynomialAic ({0.0}, {0.0}, {0.0}, 1.0).degree, -1);
  // With 40 points AICc and the paper's AIC agree.
  EXPECT_EQ (fitPolynomialAic (x, line, t, 1.0, true).degree, 1);
  EXPECT_EQ (fitPolynomialAic (x, parabola, t, 1.0, true).degree, 2);
  EXPECT_EQ (fitPolynomialAic (x, cubic, t, 1.0, true).degree, 3);
}

TEST (CurveFit, SlopeStandardErrorOfALine)
{
  // Least squares: var (a1) = sigma^2 / sum (x - mean)^2 for a line; x is symmetric, t
  // = 0 (its column is decoupled). The same in any conditioning scale, and in metres.
  std::vector<double> x, y, t;
  double sxx = 0.0;
  for (int i = 0; i < 21; ++i) {
    x.push_back (-0.1 + 0.01 * i);
    y.push_back (0.2 * x.back() + ((i * 7) % 5 - 2) * 1e-4);
    t.push_back (0.0);
    sxx += x.back() * x.back();
  }
  for (const double scale : {0.1, 1.0}) {
    const PolynomialFit fit = fitPolynomialAic (x, y, t, scale);
    ASSERT_EQ (fit.degree, 1);
    EXPECT_NEAR (fit.unit_covariance (0, 0) * sxx, 1.0, 1e-6) << scale;
    EXPECT_EQ (fit.unit_covariance (1, 1), 0.0);
  }
}

TEST (CurveFit, CornerPointsTurnSharply)
{
  // An L in the profile plane: arm along x, then arm along y; spacing 0.01.
  ProfilePoints profile;
  for (int i = 0; i <= 100; ++i)
    profile.uv.emplace_back (0.01f * i, 0.f);
  for (int i = 1; i <= 100; ++i)
    profile.uv.emplace_back (1.f, 0.01f * i);
  profile.t.assign (profile.uv.size(), 0.f);
  std::vector<LocalEdge> chain;
  spanningTreeEdges (profile, 0.02, chain);
  CurveFitParameters p;
  p.threshold = 0.02;
  p.window = 0.08;
  p.tangent_radius = 0.04;
  CurveScores scores;
  scoreCurveTurns (profile, chain, p, scores);
  // Far from the corner: evaluated, straight, tiny residual.
  for (int i : {30, 50, 150, 170}) {
    EXPECT_TRUE (scores.evaluated[i]) << i;
    EXPECT_LT (scores.turn[i], 0.05f) << i;
    EXPECT_LT (scores.rms[i], 1e-3f) << i;
  }
  // Near the corner (index 100) something flags: a sharp turn or a side that is not one
  // curve.
  int flagged = 0;
  for (int i = 94; i <= 106; ++i)
    if (scores.evaluated[i] && (scores.turn[i] > M_PI / 6 || scores.rms[i] > 3e-3f))
      ++flagged;
  EXPECT_GE (flagged, 3);
}

TEST (CurveFit, AiccRefusesModelsItCannotScore)
{
  // AICc = AIC + 2 k (k + 1) / (n - k - 1), k = fitted terms + 1 (the noise variance):
  // infinite at n = k + 1, undefined below. A line (3 terms with t) is scored from 6
  // points, a parabola from 7, a cubic from 8. Noisy samples, t spread across a profile
  // 2 cm wide.
  std::mt19937 rng (11);
  std::normal_distribution<double> noise (0.0, 0.002);
  std::uniform_real_distribution<double> across (0.0, 0.02);
  const auto samples = [&] (int n, double cubic) {
    std::vector<double> x, y, t;
    for (int i = 0; i < n; ++i) {
      x.push_back (-1.0 + 2.0 * i / (n - 1));
      t.push_back (across (rng));
      y.push_back (0.3 * x.back() + cubic * std::pow (x.back(), 3) + noise (rng));
    }
    return std::make_tuple (x, y, t);
  };
  for (int trial = 0; trial < 20; ++trial) {
    // Six points: only the line can be scored.
    const auto [x6, y6, t6] = samples (6, 0.0);
    EXPECT_EQ (fitPolynomialAic (x6, y6, t6, 1.0, true).degree, 1) << trial;
    // Five: no model can; the line, the simplest, is kept with an infinite AICc.
    const auto [x5, y5, t5] = samples (5, 0.0);
    const PolynomialFit five = fitPolynomialAic (x5, y5, t5, 1.0, true);
    EXPECT_EQ (five.degree, 1) << trial;
    EXPECT_TRUE (std::isinf (five.aic)) << trial;
    // Seven points of a strong cubic: no cubic (it needs eight).
    const auto [x7, y7, t7] = samples (7, 5.0);
    const int degree = fitPolynomialAic (x7, y7, t7, 1.0, true).degree;
    EXPECT_GE (degree, 1) << trial;
    EXPECT_LE (degree, 2) << trial;
    // Eight points of it: the cubic.
    const auto [x8, y8, t8] = samples (8, 5.0);
    EXPECT_EQ (fitPolynomialAic (x8, y8, t8, 1.0, true).degree, 3) << trial;
  }
}

TEST (CurveFit, AicCountsTheNoiseVariance)
{
  // aic = n ln (rss / n) + 2 k (+ 2 k (k + 1) / (n - k - 1) for AICc) with k the fitted
  // terms (degree + 2) and the noise variance; residual_variance = rss / (n - degree -
  // 2).
  std::mt19937 rng (3);
  std::normal_distribution<double> noise (0.0, 0.01);
  std::vector<double> x, y, t;
  for (int i = 0; i < 15; ++i) {
    x.push_back (-1.0 + 2.0 * i / 14.0);
    t.push_back ((i % 4) * 0.05);
    y.push_back (0.2 + 0.5 * x.back() - 0.7 * x.back() * x.back() + noise (rng));
  }
  const double n = 15.0;
  for (const bool corrected : {false, true}) {
    const PolynomialFit fit = fitPolynomialAic (x, y, t, 1.0, corrected);
    ASSERT_GE (fit.degree, 1);
    const double k = fit.degree + 3.0;
    const double expected = n * std::log (fit.rss / n) + 2.0 * k +
                            (corrected ? 2.0 * k * (k + 1.0) / (n - k - 1.0) : 0.0);
    EXPECT_NEAR (fit.aic, expected, 1e-6) << corrected;
    EXPECT_NEAR (fit.residual_variance, fit.rss / (n - fit.degree - 2.0), 1e-15);
  }
}

namespace {
/** The curve fitting's scores of \a profile, straight chains of points 0.01 apart with
 * noise across them: chains of the spanning tree at 0.02, window 0.105, tangent radius
 * 0.04, corrected AIC. */
CurveScores
scoreNoisyChains (const ProfilePoints& profile)
{
  std::vector<LocalEdge> chain;
  spanningTreeEdges (profile, 0.02, chain);
  CurveFitParameters p;
  p.threshold = 0.02;
  p.window = 0.105;
  p.tangent_radius = 0.04;
  p.corrected_aic = true;
  CurveScores scores;
  scoreCurveTurns (profile, chain, p, scores);
  return scores;
}
} // namespace

TEST (CurveFit, ResidualRmsIsTheNoise)
{
  // Many short straight chains, one profile: each is clean to the left of its middle
  // point and has Gaussian noise sigma across it from the middle on. At the middle the
  // larger residual RMS is the noisy side's, eleven points fitted with three terms:
  // rss / (n - p) estimates sigma^2 without bias, rss / n gives 8/11 of it.
  const double sigma = 0.001;
  std::mt19937 rng (7);
  std::normal_distribution<double> noise (0.0, sigma);
  std::uniform_real_distribution<double> across (0.0, 0.02);
  ProfilePoints profile;
  std::vector<std::uint32_t> middles;
  const int chains = 400;
  for (int c = 0; c < chains; ++c)
    for (int i = -15; i <= 15; ++i) {
      if (i == 0)
        middles.push_back (static_cast<std::uint32_t> (profile.uv.size()));
      profile.uv.emplace_back (static_cast<float> (c + 0.01 * i),
                               static_cast<float> (i >= 0 ? noise (rng) : 0.0));
      profile.t.push_back (static_cast<float> (across (rng)));
    }
  const CurveScores scores = scoreNoisyChains (profile);
  double sum = 0.0;
  for (const std::uint32_t i : middles) {
    ASSERT_TRUE (scores.evaluated[i]);
    sum += scores.rms[i] * scores.rms[i];
  }
  // The mean of 400 estimates, each of relative standard deviation 0.5 (8 degrees of
  // freedom): within 0.1 of sigma^2 for an unbiased estimate.
  EXPECT_NEAR (sum / chains / (sigma * sigma), 1.0, 0.1);
}

TEST (CurveFit, NoiseIsTheNoiseSigma)
{
  // Straight chains with Gaussian noise sigma across them: the median over the points
  // of the pooled, median-corrected estimate is sigma; the larger of the two sides'
  // RMS lies above it.
  const double sigma = 0.001;
  std::mt19937 rng (5);
  std::normal_distribution<double> noise (0.0, sigma);
  std::uniform_real_distribution<double> across (0.0, 0.02);
  ProfilePoints profile;
  for (int c = 0; c < 200; ++c)
    for (int i = -15; i <= 15; ++i) {
      profile.uv.emplace_back (static_cast<float> (c + 0.01 * i),
                               static_cast<float> (noise (rng)));
      profile.t.push_back (static_cast<float> (across (rng)));
    }
  const CurveScores scores = scoreNoisyChains (profile);
  std::vector<float> pooled, larger;
  for (std::size_t i = 0; i < profile.uv.size(); ++i)
    if (scores.evaluated[i]) {
      pooled.push_back (scores.noise[i]);
      larger.push_back (scores.rms[i]);
    }
  ASSERT_GE (pooled.size(), 1000u);
  const auto median = [] (std::vector<float> v) {
    std::nth_element (v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  EXPECT_NEAR (median (pooled) / sigma, 1.0, 0.05);
  EXPECT_GT (median (larger), median (pooled));
}
