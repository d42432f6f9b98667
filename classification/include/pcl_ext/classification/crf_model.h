/*
 * pcl_ext: Lim & Suter's multi-scale CRF over adaptive super-voxels, without the point
 * type.
 */
#pragma once

#include <pcl_ext/features/saliency_features.h>
#include <pcl_ext/segmentation/supervoxel_set.h>

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
/** \brief The three models of Lim & Suter's comparison (section 5). */
enum class CrfMode {
  NodeOnly, ///< node potentials only: multinomial logistic regression per super-voxel
  LocalCrf, ///< plus local edges to m member points (P_l of eq. 5; the paper's "CRF")
  MultiscaleCrf ///< plus regional edges to l super-voxels (eq. 5: P_r * P_l; "mCRF")
};

/** \brief "node", "crf", "mcrf". */
const char*
crfModeName (CrfMode mode);

/** \brief Parses "node", "crf", "mcrf"; false for anything else. */
bool
parseCrfMode (const std::string& text, CrfMode& mode);

/** \brief The inputs of the node potentials' multinomial logistic regression (eq. 8).
 *
 * The regression stays the paper's (one weight vector per class, the Gaussian prior of
 * eq. 9 on every weight); what changes is the fixed map from the standardised features
 * z to its inputs (pcl_ext addition). The edge potentials (eq. 6-7) always use z
 * itself. With Spline, each class's log node potential is a piecewise-linear function
 * of each feature (an additive model) instead of a linear one: a linear score cannot
 * single out the middle of a feature's range (wires and facades between the ground and
 * the tree tops in height, say). The knots are fitted on the training features and
 * saved with the model. */
enum class CrfNodeExpansion {
  Linear, ///< z itself: the paper's linear model
  Spline, ///< z and the hinges max(0, z_d - t_dk) at K training quantiles t_dk of each
          ///< feature: a piecewise-linear function of each feature per class
  SplineProducts ///< Spline plus the products z_a z_b of every pair of features
};

/** \brief "linear", "spline", "spline_products". */
const char*
crfNodeExpansionName (CrfNodeExpansion expansion);

/** \brief Parses "linear", "spline", "spline_products"; false for anything else. */
bool
parseCrfNodeExpansion (const std::string& text, CrfNodeExpansion& expansion);

/** \brief The classifier of the node potentials (pcl_ext addition).
 *
 * Logistic is the paper's multinomial logistic regression (eq. 8) over the node
 * expansion of the features. BoostedTrees are gradient-boosted decision trees (XGBoost,
 * softmax objective) over the standardised features: the node potential is the log of
 * their class probabilities. Trees separate what a linear score cannot (wires from
 * facade edges, poles from trunks, the middle of a feature's range). */
enum class CrfNodeModel {
  Logistic,    ///< the paper's multinomial logistic regression (eq. 8)
  BoostedTrees ///< gradient-boosted trees (XGBoost), log class probabilities
};

/** \brief "logistic", "boosted_trees". */
const char*
crfNodeModelName (CrfNodeModel model);

/** \brief Parses "logistic", "boosted_trees"; false for anything else. */
bool
parseCrfNodeModel (const std::string& text, CrfNodeModel& model);

/** \brief How the weights are trained (see MultiscaleCrfModel, "Training").
 *
 * Staged (pcl_ext's, the default): the node weights alone, then the edge weights by a
 * stacked pseudo-likelihood with the node weights held and the neighbours' stage-1
 * class probabilities as context, then the edges' weight at inference (stage 3).
 * PseudoLikelihood (the paper's eq. 9): every weight at once, maximising the penalised
 * pseudo-likelihood with the neighbours' true labels as context, and the model that
 * inference runs is that one (edge weight 1 at inference, no stage 3). */
enum class CrfTraining {
  Staged,          ///< pcl_ext's three stages
  PseudoLikelihood ///< the paper's eq. 9, all weights jointly
};

/** \brief "staged", "pseudo_likelihood". */
const char*
crfTrainingName (CrfTraining training);

/** \brief Parses "staged", "pseudo_likelihood"; false for anything else. */
bool
parseCrfTraining (const std::string& text, CrfTraining& training);

/** \brief A cloud as the CRF sees it: xyz (non-finite points are skipped), normalised
 * RGB and intensity per point (each empty when absent). */
struct CrfInput {
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr xyz;
  std::vector<Eigen::Vector3f> colours;
  std::vector<float> intensity;
};

/** \brief The CRF's super-voxel parameters: section 3.1's, with a lower bound of 0.5 m
 * on the radius (AdaptiveRadiusParameters::min_radius; pcl_ext's default for the CRF, 0
 * in the paper and in AdaptiveSupervoxelSegmentation).
 *
 * Why: the k threshold that stops the radius growing (max_k points) counts points, so
 * where a scan is dense the super-voxels are small. On facades scanned along closely
 * spaced horizontal lines (Oakland's part3_aj and part3_al) the radius fell below 0.2
 * m, each super-voxel held one scan line, and its eq. 12 features described a line, not
 * a plane: most of those facade points were misclassified, as vegetation or as trunks
 * and poles. The bound was chosen by cross-validation between Oakland's part3_am and
 * part3_an and then checked once on the other part3 chunks (docs/lim_suter.md has the
 * figures). Lengths are in metres: set 0 for the paper's super-voxels or for clouds in
 * other units. */
inline SupervoxelParameters
defaultCrfSupervoxelParameters ()
{
  SupervoxelParameters p;
  p.radius.min_radius = 0.5;
  return p;
}

/** \brief Everything the model needs besides its weights; saved with them. */
struct CrfSettings {
  CrfMode mode = CrfMode::MultiscaleCrf;
  /** section 3.1 (l is supervoxels.adjacency); radius.min_radius 0.5 m by default (see
   * defaultCrfSupervoxelParameters; 0: the paper's). */
  SupervoxelParameters supervoxels = defaultCrfSupervoxelParameters();
  int local_edges = 4; ///< m, local edges per super-voxel (paper: 4); >= 0
  /** Over-segmentations averaged at classification (pcl_ext addition): the super-voxels
   * are drawn with seeds seed, seed + 1, ..., each draw is classified (its graph,
   * belief propagation, eq. 11) and each point takes the class of highest mean
   * probability over the draws. Training uses the draw of seed. A single draw's labels
   * depend on where its mid-points fell; averaging draws removes most of that
   * (docs/lim_suter.md has the cross-validation). [1, 64]; a model file without it
   * has 1. */
  int draws = 3;
  /** Colour / intensity are decided at training. features.scales: empty (the default)
   * is the paper's single-scale set; defaultFeatureScales() adds the multi-scale
   * features (pcl_ext addition, at a much higher feature cost; not the default, as its
   * gain in cross-validation did not carry over to Oakland's validation chunks).
   * features.ground_estimate: LowestInBlock (the default) or Opening, which puts the
   * ground points much closer to their estimated ground but did not change the mCRF's
   * cross-validation macro F1 on Oakland (docs/lim_suter.md has the figures of both).
   */
  SaliencyFeatureOptions features;
  double sigma = 1.0; ///< sigma_C of the Gaussian prior, eq. 9; > 0
  /** The node classifier (see CrfNodeModel): Logistic, the paper's, by default.
   * BoostedTrees gave the better node-only model but the worse mCRF in cross-validation
   * between Oakland chunks (docs/lim_suter.md has the figures of both). */
  CrfNodeModel node_model = CrfNodeModel::Logistic;
  /** How the weights are trained (a training setting, not stored in the model file);
   * PseudoLikelihood needs the logistic node model. */
  CrfTraining training = CrfTraining::Staged;
  int boost_rounds = 200; ///< boosting rounds (BoostedTrees); [1, 10000]
  int boost_depth = 6;    ///< maximum tree depth (BoostedTrees); [1, 32]
  double boost_eta = 0.1; ///< learning rate (BoostedTrees); (0, 1]
  /** Inputs of the logistic node model: Linear (the paper's, the default) or a spline
   * expansion (refused with BoostedTrees). */
  CrfNodeExpansion node_expansion = CrfNodeExpansion::Linear;
  int spline_knots = 2; ///< K, hinges per feature of the spline expansions; [1, 64]
  bool balance_classes = true; ///< weight training nodes by 1 / sqrt(class frequency)
  int max_training_iterations = 200; ///< L-BFGS iterations; >= 1
  double edge_scale =
      0.0; ///< beta, the factor on the log edge potentials at inference
           ///< (pcl_ext addition); 0: fitted at training (stage 3); >= 0
  double bp_damping = 0.5;    ///< message damping of loopy BP; [0, 1)
  int bp_iterations = 100;    ///< at most this many BP sweeps; >= 1
  double bp_tolerance = 1e-4; ///< converged when no message moves more; > 0
  unsigned int threads = 0;   ///< 0 = all cores; results do not depend on it
};

/** \brief Checks the settings; PCL_ERROR naming \a caller and false when one is
 * invalid. */
bool
checkCrfSettings (const CrfSettings& settings, const char* caller);

/** \brief Timings (ms) and sizes of the last train() or classify(). */
struct CrfStatistics {
  double supervoxels_ms = 0, features_ms = 0, training_ms = 0, inference_ms = 0;
  std::size_t points = 0, supervoxels = 0, local_points = 0;
  std::size_t local_edges = 0, regional_edges = 0;
  int iterations = 0;     ///< L-BFGS iterations (train) or BP sweeps (classify)
  bool converged = false; ///< BP converged (classify) or the optimiser did (train)
  double objective =
      0.0; ///< final penalised negative pseudo-log-likelihood per node (train)
};

/** \brief The multi-scale CRF of Lim & Suter ("Multi-scale conditional random fields
 * for over-segmented irregular 3D point clouds classification", CVPR workshops 2008,
 * section 3.2).
 *
 * Graph. Each super-voxel (section 3.1) is a node described by features s at its
 * mid-point with its radius; m random member points are nodes described by features x
 * at their own adaptive radius (section 3.1, last paragraph), joined to the super-voxel
 * node by local edges; each super-voxel is joined to its l nearest super-voxels by
 * regional edges (figure 3). The super-voxel's label is shared by P_l and P_r, so P(c |
 * s, x) = P_r(c | s) P_l(c | x) (eq. 5) is one pairwise model over that graph, up to
 * normalisation.
 *
 * Features: those of computeSaliencyFeatures, the paper's single-scale set by default,
 * the multi-scale features at fixed radii (e.g. 0.5, 1 and 2 m) added on request
 * (CrfSettings::features; see there); with the multi-scale features, the means of the
 * shape, angle, height and dimension features over each super-voxel and its regional
 * neighbours are added (pcl_ext addition, after CGAL's Cluster_mean_of_feature). The
 * model file stores the feature set, and a model of another set is refused.
 *
 * Draws (CrfSettings::draws, pcl_ext addition): classify() averages the per-point
 * probabilities of several draws of the super-voxels (seeds seed, seed + 1, ...), each
 * classified on its own; train() uses the draw of seed.
 *
 * Node model (CrfSettings::node_model, pcl_ext addition): the paper's logistic
 * regression by default, or gradient-boosted trees (XGBoost), one booster for the
 * super-voxel nodes and one for the local points,
 * over the standardised features, whose log class probabilities are the log node
 * potentials: log psi_i(c) = log P_boost(c | s_i). Logistic is the paper's eq. 8 below.
 * The edges, the training of the edges (stages 2 and 3 below) and inference are the
 * same for both.
 *
 * Potentials (as eq. 6-8): node psi_i(c) = exp(lambda_i^c . [1, phi(s_i)]) for
 * super-voxels and exp(lambda_x^c . [1, phi(x_j)]) for local points (multinomial
 * logistic regression), phi the node expansion of the standardised features
 * (CrfNodeExpansion: the paper's phi(s) = s by default; Spline adds K hinges per
 * feature at its training quantiles); edges psi_ij(c_i, c_j) = exp([c_i = c_j]
 * softplus(lambda_e^c . [1, z_i (.) z_j])) with (.) the element-wise product of the
 * standardised features, clamped to [-3, 3] (eq. 6 local, eq. 7 regional, each with its
 * own weights). Departures: the constant 1 (a per-class bias), the clamp and the
 * softplus, which keeps every edge associative: the text's linear form let edges turn
 * repulsive on feature combinations unseen in training, and loopy BP then collapsed
 * whole classes on real data.
 *
 * Training (CrfSettings::training): CrfTraining::PseudoLikelihood is the paper's eq. 9
 * as printed (every weight at once, each node given its neighbours' true labels, edge
 * weight 1 at inference); it collapses on Oakland in cross-validation
 * (docs/lim_suter.md), so the default is pcl_ext's staged fit, described here.
 *
 * Training (eq. 9) maximises a pseudo-likelihood, not the likelihood, whose partition
 * function over a loopy graph is intractable, minus |lambda|^2 / (2 sigma^2), by L-BFGS
 * (a quasi-Newton method; the paper used scaled conjugate gradients), in three stages.
 * Stage 1 fits the node potentials alone (exactly penalised logistic regression; all of
 * NodeOnly; with boosted trees, the boosters, trained by XGBoost's histogram method
 * on one thread with a fixed seed and no subsampling, so that the model does not
 * depend on the thread count;
 * with several training clouds, the node potentials that stages 2 and 3 see on each
 * cloud come from boosters trained on the other clouds, as confident as on unseen
 * scans; the boosters kept are trained on all clouds). Stage 2 fits the edge weights
 * with the node weights held at stage 1: each node is scored with, from each neighbour,
 * the message a first (undamped) BP sweep sends given that neighbour's stage-1 class
 * probabilities q, log(1 + q(c) (e^d - 1)) (a stacked pseudo-likelihood). The node
 * weights stay fixed and the neighbours enter through their probabilities, not their
 * labels: otherwise the edges explain the labels alone, the node potentials lose their
 * meaning, and rare classes get edge potentials so large that a small belief in a
 * neighbour already triggers them in BP (docs/lim_suter.md describes both variants).
 * Stage 3 fits the weight beta of the edges against the nodes at inference (log edge
 * potentials times beta), which the pseudo-likelihood cannot: it sees each neighbour
 * once, while loopy BP hears the same evidence again around the graph's short cycles.
 * beta is the value on the grid 0.1, 0.2,
 * .., 1.5 that minimises the weighted negative log-likelihood of the labelled
 * super-voxels under their BP marginals on the training graph (CrfSettings::edge_scale
 * fixes it instead); each grid point's BP starts from the previous one's messages. A
 * super-voxel's training label is the majority label of its members; unlabelled nodes
 * are not scored. With balance_classes, each node is weighted by 1/sqrt(frequency of
 * its class) (pcl_ext addition: rare classes such as wires would otherwise be given
 * up).
 *
 * Inference: sum-product loopy belief propagation with damped, synchronous message
 * updates (so the result does not depend on the thread count), stopped when no message
 * changes by more than the tolerance. Each point takes the label maximising the product
 * of the marginals of the super-voxels that hold it (eq. 11).
 *
 * Errors never throw: PCL_ERROR and false (or empty output).
 */
class MultiscaleCrfModel {
public:
  MultiscaleCrfModel();
  ~MultiscaleCrfModel();
  MultiscaleCrfModel (const MultiscaleCrfModel&);
  MultiscaleCrfModel&
  operator= (const MultiscaleCrfModel&);

  /** \brief The options of training (see CrfSettings). Default: CrfSettings' defaults;
   * a loaded model brings its own. */
  void
  setSettings (const CrfSettings& settings)
  {
    settings_ = settings;
  }

  const CrfSettings&
  getSettings () const
  {
    return settings_;
  }

  /** \brief Class ids (> 0) and names. When set before train(), every named class must
   * have training points; otherwise the classes are the non-zero labels found. */
  void
  setClassNames (const std::map<std::uint32_t, std::string>& names)
  {
    names_ = names;
  }

  /** \brief Train on labelled clouds: \a labels[c][i] is point i's class id (0 =
   * unlabelled). Uses colour / intensity when every input has them. \return false
   * (model unchanged) on bad input: no cloud, sizes that differ, fewer than two
   *         classes, a named class without points, no labelled super-voxel */
  bool
  train (const std::vector<CrfInput>& inputs,
         const std::vector<std::vector<std::uint32_t>>& labels);

  /** \brief Classify one cloud.
   * \param[out] labels class id per point (0 for non-finite points)
   * \param[out] probabilities per point and class (rows: points, columns:
   * getClassLabels()); rows of non-finite points are 0 \return false (outputs empty)
   * with an untrained model or bad input */
  bool
  classify (const CrfInput& input,
            std::vector<std::uint32_t>& labels,
            Eigen::MatrixXf& probabilities);

  bool
  isTrained () const
  {
    return trained_;
  }

  /** \brief Class ids in column order of the probabilities. */
  const std::vector<std::uint32_t>&
  getClassLabels () const
  {
    return class_ids_;
  }

  /** \brief Class names by id. */
  const std::map<std::uint32_t, std::string>&
  getClassNames () const
  {
    return names_;
  }

  /** \brief Feature names of the trained model (saliencyFeatureNames, then with the
   * multi-scale features the neighbourhood means, "neighbours_" and the name). */
  std::vector<std::string>
  getFeatureNames () const;

  /** \brief The super-voxels of the last train() (its last input) or classify() (its
   * first draw). */
  const SupervoxelSet&
  getSupervoxels () const
  {
    return last_supervoxels_;
  }

  /** \brief The super-voxels of every draw of the last classify() (CrfSettings::draws).
   */
  const std::vector<SupervoxelSet>&
  getDrawSupervoxels () const
  {
    return last_draws_;
  }

  /** \brief Super-voxel marginals of the last classify()'s first draw (rows: its
   * super-voxels). */
  const Eigen::MatrixXf&
  getSupervoxelProbabilities () const
  {
    return last_marginals_;
  }

  const CrfStatistics&
  getStatistics () const
  {
    return statistics_;
  }

  /** \brief Write the model as versioned text (format "pcl_ext_crf_model 5": settings
   * with the ground estimate, the feature scales, the node expansion and the node
   * model, classes, feature names and scaling, the knots of a spline expansion, the
   * node weights or the two boosters (XGBoost's UBJ model, base64), the edge weights,
   * the edge scale), atomically. Other versions are refused. \return false with an
   * untrained model or when the file cannot be written */
  bool
  saveModel (const std::string& path) const;

  /** \brief Read a model; the current one is kept when the file is missing, malformed,
   * of another version or inconsistent (PCL_ERROR names the file, line and problem). */
  bool
  loadModel (const std::string& path);

  /** \brief Same, from text (\a source names it in errors). */
  bool
  parseModel (const std::string& text, const std::string& source);

  /** \brief The model as text (what saveModel writes). */
  std::string
  toText () const;

  /** \brief The weights and feature scaling (opaque outside the implementation). */
  struct Weights;

private:
  CrfSettings settings_;
  std::map<std::uint32_t, std::string> names_;
  std::vector<std::uint32_t> class_ids_;
  std::unique_ptr<Weights> weights_;
  bool trained_ = false;
  SupervoxelSet last_supervoxels_;
  std::vector<SupervoxelSet> last_draws_;
  Eigen::MatrixXf last_marginals_;
  CrfStatistics statistics_;
};
} // namespace pcl_ext
