/*
 * pcl_ext: the profile-intersection segmentation on plain coordinates (Sithole &
 * Mapurisa).
 */
#pragma once

#include <pcl_ext/segmentation/profile_graph.h>
#include <pcl_ext/segmentation/profile_segmenters.h>
#include <pcl_ext/segmentation/profile_stacks.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace profiles {
/** \brief The profile segmenters of section 4.1. */
enum class ProfileMethod {
  Proximity,           ///< proximity chaining (4.1.1)
  MinimumSpanningTree, ///< minimum spanning tree cut at the threshold (section 3)
  CurveFitting,        ///< curve fitting with AIC model selection (4.1.2)
  CurveReconstruction  ///< nearest-neighbour crust cut at the threshold (5.2)
};

/** \brief What a run of the pipeline computes: everything, or one stage of a run over
 * parts of a cloud, each part holding whole profiles (see ProfileSegmentation). */
enum class PipelineStage {
  Segments,  ///< everything (the default)
  LocalGaps, ///< the stacks and the local gaps (PipelineResult::local_gaps) only
  /** Curve fitting: the chains (PipelineResult::edges) and every point's scores
   * (PipelineResult::curve_scores); no curve ends, no segments. */
  CurveScores,
  /** Curve fitting with the curve ends given (PipelineParameters::given_ends,
   * given_breakpoints, junction_tolerances): the chains and the curves followed across
   * junctions (PipelineResult::edges) and the breakpoints with the points the joins
   * absorb; no scores, no segments. */
  CurveJoins
};

/** \brief The rule that makes a point a curve end in a stack (curve fitting), from the
 * stack's medians of the evaluated points' residuals and noise. */
struct CurveEndRule {
  double tolerance = 0.0;          ///< a larger residual RMS is not one curve
  double junction_tolerance = 0.0; ///< residual a curve through a junction may have
  double turn_z = 0.0; ///< a sharp turn must exceed this many times its standard error
};

/** \brief Everything the pipeline needs; see ProfileSegmentation for the meaning and
 * defaults. */
struct PipelineParameters {
  std::vector<Eigen::Vector3f> normals; ///< unit stack normals
  /** \brief Where profile 0 of each stack starts (buildStack's origin), one per normal;
   * empty (the default): at the stack's lowest point. With a cloud's origins and width,
   * any part of it that holds its profiles whole gets the cloud's edges among them. */
  std::vector<double> origins;
  double width = 0.0;     ///< profile width (> 0)
  double threshold = 0.0; ///< proximity threshold (>= 0)
  ProfileMethod method = ProfileMethod::Proximity;
  unsigned int proximity_neighbours = 4;
  /** \brief Per-point thresholds: \a threshold times the point's local gap (localGaps)
   * over the stack's mean local gap, at least \a threshold and at most \a
   * max_threshold; the curve window scales with them. */
  bool local_threshold = false;
  double max_threshold = 0.0; ///< >= threshold when local_threshold
  /** \brief With local thresholds: each stack's mean local gap, one per normal, given
   * rather than taken over the points (a run over parts of a cloud gives the whole
   * cloud's); empty (the default): the points' own. */
  std::vector<double> mean_gaps;
  PipelineStage stage = PipelineStage::Segments; ///< what the run computes
  /** \brief Stage CurveJoins: each stack's own curve ends, one flag per point. */
  std::vector<std::vector<std::uint8_t>> given_ends;
  /** \brief Stage CurveJoins: whether each point ends a curve in any stack of the
   * whole cloud. */
  std::vector<std::uint8_t> given_breakpoints;
  /** \brief Stage CurveJoins: each stack's CurveEndRule::junction_tolerance. */
  std::vector<double> junction_tolerances;
  double curve_window = 0.0;      ///< > 0 for CurveFitting
  double tangent_radius = 0.0;    ///< > 0 for CurveFitting
  double max_turn = 0.0;          ///< radians
  double turn_significance = 0.0; ///< turns within this many standard errors are noise
  bool corrected_aic = false;     ///< AICc rather than AIC
  bool side_frames = false;       ///< fit each side along its own principal axis
  double residual_factor = 3.0;
  double min_residual = 0.0; ///< floor of the residual tolerance
  unsigned int threads = 1;
};

/** \brief The data structure of section 2 and the segments it yields. */
struct PipelineResult {
  std::vector<Stack> stacks;                 ///< one per normal
  std::vector<std::vector<GraphEdge>> edges; ///< E_phi: the edges of each stack
  std::vector<std::uint8_t> breakpoints;     ///< curve ends (CurveFitting only)
  /** \brief Edges of \a edges that follow a curve across a junction of curve ends
   * (CurveFitting only; joinCurvesAcrossJunctions), last in their stack's edges. */
  std::size_t junction_joins = 0;
  /** \brief With local thresholds: each point's local gap in each stack (localGaps;
   * at most max_threshold, those at it had no neighbour within reach). */
  std::vector<std::vector<float>> local_gaps;
  /** \brief Stage CurveScores: each stack's scores of every point. */
  std::vector<CurveScores> curve_scores;
  std::vector<std::uint32_t> labels; ///< component of each point
  std::size_t num_segments = 0;
};

/** \brief The value at position size / 2 of \a values sorted (the upper median; 0 when
 * empty): a stack's median residual or noise over its evaluated points. */
double
upperMedian (std::vector<float> values);

/** \brief The curve end rule of a stack of medians \a median_rms and \a median_noise:
 * tolerance max(residual_factor median_rms, min_residual), the junction tolerance that
 * over the residual factor, turn_z turn_significance median_noise. */
CurveEndRule
curveEndRule (double median_rms,
              double median_noise,
              const PipelineParameters& parameters);

/** \brief Whether point \a i of \a scores ends a curve by \a rule: evaluated, and a
 * turn sharper than \a max_turn and than turn_z standard errors, or a residual above
 * the tolerance. */
inline bool
isCurveEnd (const CurveScores& scores,
            std::size_t i,
            const CurveEndRule& rule,
            double max_turn)
{
  return scores.evaluated[i] &&
         ((scores.turn[i] > max_turn &&
           scores.turn[i] > rule.turn_z * scores.turn_sigma[i]) ||
          scores.rms[i] > rule.tolerance);
}

/** \brief Build the stacks, segment every profile (in parallel; the result does not
 * depend on the thread count), and label the connected components of the union of all
 * edges. \param[in] xyz finite coordinates, best centred near the origin \return false
 * when a parameter is invalid or a point lies below its stack's given origin (nothing
 * computed) */
bool
runProfileSegmentation (const std::vector<Eigen::Vector3f>& xyz,
                        const PipelineParameters& parameters,
                        PipelineResult& result);
} // namespace profiles
} // namespace pcl_ext
