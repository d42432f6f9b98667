/*
 * pcl_ext: the profile-intersection segmentation on plain coordinates (Sithole &
 * Mapurisa).
 */
#include <pcl_ext/segmentation/profile_pipeline.h>
#include <pcl_ext/segmentation/profile_segmenters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pcl_ext {
namespace profiles {
namespace {
/** The local gap is the median over a point and this many nearest: four a side of a
 * chain. */
constexpr unsigned int kLocalGapNeighbours = 8;

struct Task {
  std::uint32_t stack;
  std::uint32_t profile;
};

bool
validParameters (const PipelineParameters& p)
{
  if (p.normals.empty() || !(p.width > 0.0) || !std::isfinite (p.width) ||
      !(p.threshold >= 0.0) || !std::isfinite (p.threshold) || p.threads == 0)
    return false;
  for (const auto& n : p.normals)
    if (!n.allFinite() || n.norm() < 1e-6f)
      return false;
  if (!p.origins.empty() && p.origins.size() != p.normals.size())
    return false;
  if (!p.mean_gaps.empty() && p.mean_gaps.size() != p.normals.size())
    return false;
  for (const double g : p.mean_gaps)
    if (!(g >= 0.0) || !std::isfinite (g))
      return false;
  if ((p.stage == PipelineStage::CurveScores || p.stage == PipelineStage::CurveJoins) &&
      p.method != ProfileMethod::CurveFitting)
    return false;
  if (p.stage == PipelineStage::CurveJoins &&
      (p.given_ends.size() != p.normals.size() ||
       p.junction_tolerances.size() != p.normals.size()))
    return false;
  for (const double o : p.origins)
    if (!std::isfinite (o))
      return false;
  if (p.method == ProfileMethod::Proximity && p.proximity_neighbours == 0)
    return false;
  if (p.local_threshold &&
      (!(p.max_threshold >= p.threshold) || !std::isfinite (p.max_threshold)))
    return false;
  if (p.method == ProfileMethod::CurveFitting &&
      (!(p.curve_window > 0.0) || !(p.tangent_radius > 0.0) || !(p.max_turn > 0.0) ||
       !(p.residual_factor > 0.0) || !std::isfinite (p.curve_window) ||
       !(p.turn_significance >= 0.0) || !std::isfinite (p.turn_significance)))
    return false;
  return true;
}

/** The values of the evaluated points. */
std::vector<float>
evaluatedValues (const std::vector<std::uint8_t>& evaluated,
                 const std::vector<float>& values)
{
  std::vector<float> out;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (evaluated[i])
      out.push_back (values[i]);
  return out;
}
} // namespace

double
upperMedian (std::vector<float> values)
{
  if (values.empty())
    return 0.0;
  std::nth_element (values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

CurveEndRule
curveEndRule (double median_rms,
              double median_noise,
              const PipelineParameters& parameters)
{
  CurveEndRule rule;
  rule.tolerance =
      std::max (parameters.residual_factor * median_rms, parameters.min_residual);
  // A curve through a junction joins two arms for good: it must fit as well as a
  // typical stretch of the stack's curves, not merely pass for a curve.
  rule.junction_tolerance = rule.tolerance / parameters.residual_factor;
  rule.turn_z = parameters.turn_significance * median_noise;
  return rule;
}

bool
runProfileSegmentation (const std::vector<Eigen::Vector3f>& xyz,
                        const PipelineParameters& parameters,
                        PipelineResult& result)
{
  result = PipelineResult();
  if (!validParameters (parameters))
    return false;
  const std::size_t n = xyz.size();
  const std::size_t num_stacks = parameters.normals.size();
  if (parameters.stage == PipelineStage::CurveJoins) {
    bool sizes = parameters.given_breakpoints.size() == n;
    for (const auto& ends : parameters.given_ends)
      sizes = sizes && ends.size() == n;
    if (!sizes)
      return false;
  }
  result.stacks.resize (num_stacks);
  result.edges.resize (num_stacks);
  if (n == 0)
    return true;

  const int threads = static_cast<int> (parameters.threads);
  bool below_origin = false;
#pragma omp parallel for num_threads(threads) schedule(static, 1)                      \
    reduction(||                                                                       \
              : below_origin)
  for (std::ptrdiff_t s = 0; s < static_cast<std::ptrdiff_t> (num_stacks); ++s)
    below_origin = !buildStack (xyz,
                                parameters.normals[s],
                                parameters.width,
                                result.stacks[s],
                                parameters.origins.empty()
                                    ? std::numeric_limits<double>::quiet_NaN()
                                    : parameters.origins[s]) ||
                   below_origin;
  if (below_origin) {
    result = PipelineResult();
    return false;
  }

  std::vector<Task> tasks;
  for (std::uint32_t s = 0; s < num_stacks; ++s)
    for (std::uint32_t p = 0; p < result.stacks[s].numProfiles(); ++p)
      tasks.push_back ({s, p});

  const bool curves = parameters.method == ProfileMethod::CurveFitting;
  // With the curve ends given, the scores that made them are not needed.
  const bool scoring = curves && parameters.stage != PipelineStage::CurveJoins;
  std::vector<CurveScores> stack_scores (scoring ? num_stacks : 0);
  for (auto& scores : stack_scores) {
    scores.evaluated.assign (n, 0);
    scores.turn.assign (n, 0.f);
    scores.rms.assign (n, 0.f);
    scores.noise.assign (n, 0.f);
    scores.turn_sigma.assign (n, 0.f);
  }
  CurveFitParameters fit;
  fit.threshold = parameters.threshold;
  fit.window = parameters.curve_window;
  fit.tangent_radius = parameters.tangent_radius;
  fit.corrected_aic = parameters.corrected_aic;
  fit.side_frames = parameters.side_frames;

  const auto load_profile = [&] (const Task& task, ProfilePoints& points) {
    const Stack& stack = result.stacks[task.stack];
    const std::uint32_t begin = stack.offsets[task.profile];
    const std::uint32_t end = stack.offsets[task.profile + 1];
    points.uv.resize (end - begin);
    points.t.resize (end - begin);
    for (std::uint32_t i = begin; i < end; ++i) {
      const Eigen::Vector3f& p = xyz[stack.order[i]];
      points.uv[i - begin] = Eigen::Vector2f (stack.u.dot (p), stack.v.dot (p));
      points.t[i - begin] = static_cast<float> (stack.normal.dot (p) - stack.origin);
    }
    return stack.order.data() + begin;
  };

  // Local thresholds: the local gap of every point in every stack first, then each
  // stack's mean gap, the in-profile counterpart of the average spacing the threshold
  // was set from.
  const bool adaptive = parameters.local_threshold &&
                        parameters.max_threshold > parameters.threshold &&
                        parameters.threshold > 0.0;
  std::vector<std::vector<float>> stack_gaps (adaptive ? num_stacks : 0);
  std::vector<double> mean_gap (num_stacks, 0.0);
  if (adaptive) {
    for (auto& gaps : stack_gaps)
      gaps.assign (n, 0.f);
#pragma omp parallel num_threads(threads)
    {
      ProfilePoints points;
      std::vector<float> gaps;
#pragma omp for schedule(dynamic, 4)
      for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t> (tasks.size()); ++k) {
        const std::uint32_t* members = load_profile (tasks[k], points);
        localGaps (points, parameters.max_threshold, kLocalGapNeighbours, gaps);
        std::vector<float>& out = stack_gaps[tasks[k].stack]; // profiles are disjoint
        for (std::size_t i = 0; i < gaps.size(); ++i)
          out[members[i]] = gaps[i];
      }
    }
    // Points with no neighbour within reach (gap at the maximum) are left out of the
    // mean.
    const float cap = static_cast<float> (parameters.max_threshold);
    for (std::size_t s = 0; s < num_stacks; ++s) {
      if (!parameters.mean_gaps.empty()) {
        mean_gap[s] = parameters.mean_gaps[s];
        continue;
      }
      double sum = 0.0;
      std::size_t count = 0;
      for (const float g : stack_gaps[s])
        if (g < cap) {
          sum += g;
          ++count;
        }
      mean_gap[s] = count ? sum / static_cast<double> (count) : 0.0;
    }
  }
  if (parameters.stage == PipelineStage::LocalGaps) {
    result.local_gaps = std::move (stack_gaps);
    return true;
  }

  // The threshold scaled by how much sparser than the stack's mean the point's stretch
  // of profile is; never below the global threshold, never above the maximum. \return
  // false where the thresholds are global
  const auto local_thresholds = [&] (const Task& task,
                                     const std::uint32_t* members,
                                     std::size_t m,
                                     std::vector<float>& thresholds) {
    if (!adaptive || !(mean_gap[task.stack] > 0.0))
      return false;
    const std::vector<float>& gaps = stack_gaps[task.stack];
    const double ratio = parameters.threshold / mean_gap[task.stack];
    thresholds.resize (m);
    for (std::size_t i = 0; i < m; ++i)
      thresholds[i] = static_cast<float> (std::clamp (
          ratio * gaps[members[i]], parameters.threshold, parameters.max_threshold));
    return true;
  };
  const auto window_scales = [&] (const std::vector<float>& thresholds,
                                  std::vector<float>& scales) {
    scales.resize (thresholds.size());
    for (std::size_t i = 0; i < thresholds.size(); ++i)
      scales[i] = static_cast<float> (thresholds[i] / parameters.threshold);
  };

  // One result slot per profile, concatenated in profile order afterwards:
  // deterministic for any number of threads.
  std::vector<std::vector<GraphEdge>> task_edges (tasks.size());
  // The chains of each profile, kept for following curves across junctions.
  std::vector<std::vector<LocalEdge>> task_chains (curves ? tasks.size() : 0);
#pragma omp parallel num_threads(threads)
  {
    ProfilePoints points;
    std::vector<LocalEdge> local;
    CurveScores scores;
    std::vector<float> thresholds, window_scale;
    CurveFitParameters point_fit = fit;
#pragma omp for schedule(dynamic, 4)
    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t> (tasks.size()); ++k) {
      const std::uint32_t* members = load_profile (tasks[k], points);
      const std::size_t m = points.uv.size();
      const bool local_here = local_thresholds (tasks[k], members, m, thresholds);
      const double link_threshold =
          local_here ? parameters.max_threshold : parameters.threshold;
      const std::vector<float>* link_thresholds = local_here ? &thresholds : nullptr;
      switch (parameters.method) {
      case ProfileMethod::Proximity:
        proximityEdges (points,
                        link_threshold,
                        parameters.proximity_neighbours,
                        local,
                        link_thresholds);
        break;
      case ProfileMethod::CurveReconstruction:
        crustEdges (points, link_threshold, local, link_thresholds);
        break;
      case ProfileMethod::MinimumSpanningTree:
      case ProfileMethod::CurveFitting:
        spanningTreeEdges (points, link_threshold, local, link_thresholds);
        break;
      }
      if (scoring) {
        point_fit.window_scale = nullptr;
        if (local_here) {
          window_scales (thresholds, window_scale);
          point_fit.window_scale = &window_scale;
        }
        scoreCurveTurns (points, local, point_fit, scores);
        CurveScores& out =
            stack_scores[tasks[k].stack]; // profiles of a stack are disjoint
        for (std::size_t i = 0; i < m; ++i) {
          out.evaluated[members[i]] = scores.evaluated[i];
          out.turn[members[i]] = scores.turn[i];
          out.turn_sigma[members[i]] = scores.turn_sigma[i];
          out.rms[members[i]] = scores.rms[i];
          out.noise[members[i]] = scores.noise[i];
        }
      }
      auto& edges = task_edges[k];
      edges.reserve (local.size());
      for (const LocalEdge& e : local)
        edges.push_back ({members[e.a], members[e.b]});
      if (curves)
        task_chains[k] = local;
    }
  }
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    auto& edges = result.edges[tasks[k].stack];
    edges.insert (edges.end(), task_edges[k].begin(), task_edges[k].end());
  }
  task_edges.clear();
  if (parameters.stage == PipelineStage::CurveScores) {
    result.curve_scores = std::move (stack_scores);
    return true;
  }

  // Curves followed across the junctions their ends leave (entangled curves): the joins
  // are edges of their stack, between points that are not curve ends.
  const auto joinAcrossJunctions =
      [&] (const std::vector<double>& tolerances,
           const std::vector<std::vector<std::uint8_t>>& own_ends) {
        std::vector<std::vector<GraphEdge>> task_joins (tasks.size());
        std::vector<std::vector<std::uint32_t>> task_absorbed (tasks.size());
#pragma omp parallel num_threads(threads)
        {
          ProfilePoints points;
          std::vector<std::uint8_t> ends, removed;
          std::vector<float> thresholds, window_scale;
          std::vector<LocalEdge> joins;
          std::vector<std::uint32_t> absorbed;
#pragma omp for schedule(dynamic, 4)
          for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t> (tasks.size());
               ++k) {
            const std::uint32_t* members = load_profile (tasks[k], points);
            const std::size_t m = points.uv.size();
            // The junctions are those of the stack's own curve ends: where another
            // stack ends curves (a crease it crosses sharply, this one at a slant) this
            // one sees no junction. A join never ends at a curve end of any stack.
            const std::vector<std::uint8_t>& own = own_ends[tasks[k].stack];
            ends.resize (m);
            removed.resize (m);
            bool any = false;
            for (std::size_t i = 0; i < m; ++i) {
              ends[i] = own[members[i]];
              removed[i] = result.breakpoints[members[i]];
              any = any || ends[i];
            }
            if (!any)
              continue;
            JunctionParameters junction;
            junction.threshold = parameters.threshold;
            junction.window = parameters.curve_window;
            junction.max_turn = parameters.max_turn;
            junction.tolerance = tolerances[tasks[k].stack];
            junction.corrected_aic = parameters.corrected_aic;
            junction.removed = &removed;
            if (local_thresholds (tasks[k], members, m, thresholds)) {
              window_scales (thresholds, window_scale);
              junction.window_scale = &window_scale;
            }
            joinCurvesAcrossJunctions (
                points, task_chains[k], ends, junction, joins, &absorbed);
            for (const LocalEdge& e : joins)
              task_joins[k].push_back ({members[e.a], members[e.b]});
            for (const std::uint32_t i : absorbed)
              task_absorbed[k].push_back (members[i]);
          }
        }
        std::size_t count = 0;
        for (std::size_t k = 0; k < tasks.size(); ++k) {
          auto& edges = result.edges[tasks[k].stack];
          edges.insert (edges.end(), task_joins[k].begin(), task_joins[k].end());
          count += task_joins[k].size();
          for (const std::uint32_t i : task_absorbed[k])
            result.breakpoints[i] = 1;
        }
        return count;
      };

  if (curves && parameters.stage == PipelineStage::CurveJoins) {
    // The curve ends of the whole cloud, given: the joins, then the caller labels.
    result.breakpoints = parameters.given_breakpoints;
    result.junction_joins =
        joinAcrossJunctions (parameters.junction_tolerances, parameters.given_ends);
    return true;
  }
  if (curves) {
    // A point ends a curve in some stack when the normal turns sharply there, or when
    // its stretch of profile is not one curve (a junction): residual far above the
    // stack's noise. A sharp turn must also be more than turn_significance standard
    // errors: with the noise of a scan and about ten points a side, a 30 degree turn is
    // often the noise alone, and such false ends, dense enough, cut a surface apart.
    // The stack's medians are the noise: a fit's own residual is inflated exactly
    // where a side straddles a crease. A residual is compared with the median of the
    // same statistic (the larger of two sides); the significance test takes the median
    // of the pooled estimates, the noise sigma itself.
    result.breakpoints.assign (n, 0);
    std::vector<double> tolerances;
    std::vector<std::vector<std::uint8_t>> own_ends (num_stacks);
    for (std::size_t s = 0; s < num_stacks; ++s) {
      const CurveScores& scores = stack_scores[s];
      own_ends[s].assign (n, 0);
      const CurveEndRule rule =
          curveEndRule (upperMedian (evaluatedValues (scores.evaluated, scores.rms)),
                        upperMedian (evaluatedValues (scores.evaluated, scores.noise)),
                        parameters);
      tolerances.push_back (rule.junction_tolerance);
      for (std::size_t i = 0; i < n; ++i)
        if (isCurveEnd (scores, i, rule, parameters.max_turn))
          result.breakpoints[i] = own_ends[s][i] = 1;
    }
    stack_scores.clear();
    result.junction_joins = joinAcrossJunctions (tolerances, own_ends);
  }
  result.num_segments =
      labelSegments (n, result.edges, result.breakpoints, result.labels);
  return true;
}
} // namespace profiles
} // namespace pcl_ext
