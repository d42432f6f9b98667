/*
 * pcl_ext_tiles crf_classify: Lim & Suter's multi-scale CRF tile by tile, with the
 * model and result of pcl_ext_crf_classify.
 */
#include "../crf/crf_inputs.h"
#include "tile_keys.h"
#include "tile_method.h"

#include <pcl_ext/segmentation/adaptive_radius.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
constexpr const char* kCrfNoiseSetting = "crf_noise";
// The noise sample of a tile (AdaptiveRadiusEstimator::estimateNoise): its key in three
// parts of at most 22 bits (exact in a float), then what the neighbourhood showed
// (flatness NaN: no plane).
constexpr const char* kCrfKeyParts[3] = {
    "noise_key_high", "noise_key_mid", "noise_key_low"};
constexpr const char* kFlatness = "noise_flatness";
constexpr const char* kRms = "noise_rms";
constexpr const char* kSpacing = "noise_spacing";

/** A tile's result is the whole cloud's where everything it is computed from is:
 *
 * - the super-voxels' mid-points are drawn in the order of a hash of each point's
 *   position and the local points by a hash of their mid-point's
 *   (computeAdaptiveSupervoxels), so a tile draws the whole cloud's super-voxels away
 *   from its edge;
 * - the noise constant of the radii is estimated once from the sample of the whole
 *   cloud (the points of smallest noiseSampleKey over all tiles, estimate(), reduce()),
 *   exactly as the untiled tool estimates it;
 * - the local ground is a grid anchored at the coordinates' origin, the same in a tile;
 * - belief propagation runs over the tile's graph: the messages from beyond the halo
 *   are missing, and the tile's sweeps stop when its own messages settle. This, and the
 *   draws near the halo's edge, are why a few points differ from the untiled result
 *   (the halo bounds the reach as getReach() says, not exactly). */
class CrfClassifyTiles : public TileMethod {
public:
  void
  addOptions (CommandLine& cl) override
  {
    cl.addOption (
        "model", model_path_, "the model written by pcl_ext_crf_train (required)");
    cl.addOption ("probability_field",
                  probability_field_,
                  "also write each point's probability of its class (float, 0 for "
                  "non-finite points) into this field; empty: not written");
  }

  std::string
  getExtraFieldName () const override
  {
    return probability_field_;
  }

  const std::vector<float>*
  getExtraValues () const override
  {
    return &probabilities_;
  }

  bool
  checkOptions (const CommandLine&, bool) override
  {
    if (model_path_.empty()) {
      std::cerr << "Error: pcl_ext_tiles crf_classify needs -model model.txt (written "
                   "by pcl_ext_crf_train).\n";
      return false;
    }
    if (!model_.loadModel (model_path_)) {
      std::cerr << "Error: cannot load the model " << model_path_ << ".\n";
      return false;
    }
    return true;
  }

  std::size_t
  getAttributeCount () const override
  {
    const CrfSettings& s = model_.getSettings();
    return (s.features.colour ? 3 : 0) + (s.features.intensity ? 1 : 0);
  }

  /** The model's colour (3 values), then intensity, as pcl_ext_crf_classify reads them
   * (readCrfAttributes). */
  bool
  readAttributes (const pcl::PCLPointCloud2& chunk,
                  const std::string& input,
                  std::vector<float>& values) const override
  {
    const CrfSettings& s = model_.getSettings();
    std::vector<Eigen::Vector3f> colours;
    std::vector<float> intensity;
    readCrfAttributes (chunk,
                       s.features.colour ? &colours : nullptr,
                       s.features.intensity ? &intensity : nullptr);
    const std::size_t n = static_cast<std::size_t> (chunk.width) * chunk.height;
    if ((s.features.colour && colours.size() != n) ||
        (s.features.intensity && intensity.size() != n)) {
      std::cerr << "\nError: the model uses "
                << (s.features.colour && colours.size() != n ? "colour (rgb)"
                                                             : "intensity")
                << ", which " << input << " does not have.\n";
      return false;
    }
    values.clear();
    values.reserve (n * getAttributeCount());
    for (std::size_t i = 0; i < n; ++i) {
      if (s.features.colour)
        values.insert (values.end(), colours[i].data(), colours[i].data() + 3);
      if (s.features.intensity)
        values.push_back (intensity[i]);
    }
    return true;
  }

  ResultField
  makeResultField () const override
  {
    return crfClassField();
  }

  tiling::MergedResults::Kind
  getKind () const override
  {
    return tiling::MergedResults::Kind::PerPoint;
  }

  /** The codes by the model's class names (crfAsprsCodes, printed the first time). */
  bool
  toAsprs (std::vector<std::uint32_t>& values) override
  {
    if (asprs_.empty())
      asprs_ = crfAsprsCodes (model_.getClassNames());
    for (auto& v : values) {
      const auto it = asprs_.find (v);
      v = it != asprs_.end() ? it->second : 1u;
    }
    return true;
  }

  NeighbourhoodReach
  getReach () const override
  {
    const CrfSettings& s = model_.getSettings();
    NeighbourhoodReach reach;
    reach.search = false;
    // A super-voxel stops growing at max_k points: a core point's super-voxel reaches
    // two such radii beyond the core, then the local ground and the feature radii.
    reach.k = s.supervoxels.radius.max_k;
    reach.hops = 2;
    reach.radius = groundAndFeatureReach();
    return reach;
  }

  bool
  needsEstimate () const override
  {
    return model_.getSettings().supervoxels.radius.noise == 0.0;
  }

  bool
  estimate (const TileCloud& tile,
            std::map<std::string, std::vector<float>>& values) override
  {
    for (const char* name :
         {kCrfKeyParts[0], kCrfKeyParts[1], kCrfKeyParts[2], kFlatness, kRms, kSpacing})
      values[name].clear();
    if (tile.core_points == 0)
      return true;
    AdaptiveRadiusParameters parameters = model_.getSettings().supervoxels.radius;
    parameters.noise = 1.0; // given: initialize() must not estimate this tile's own
    AdaptiveRadiusEstimator estimator;
    if (!estimator.initialize (tile.cloud, {}, parameters)) {
      std::cerr << "Error: the noise sample of tile " << tile.tile << " failed.\n";
      return false;
    }
    needed_margin_ = 0.0;
    const std::vector<char> core (tile.core.begin(), tile.core.end());
    for (const auto i : estimator.selectNoiseSamplePoints (&core)) {
      const std::uint64_t key =
          noiseSampleKey ((*tile.cloud)[static_cast<std::size_t> (i)]);
      appendKey (values, kCrfKeyParts, key);
      NoiseSample s;
      const bool plane = estimator.measureNoiseSample (i, s);
      values[kFlatness].push_back (plane ? s.flatness : NAN);
      values[kRms].push_back (s.rms);
      values[kSpacing].push_back (s.spacing);
      // A core point's neighbourhood within the margin is the whole cloud's.
      needed_margin_ = std::max (needed_margin_, static_cast<double> (s.spacing));
    }
    return true;
  }

  bool
  reduce (const std::string& folder,
          std::size_t tiles,
          std::map<std::string, std::string>& settings) override
  {
    // Every tile's samples, ordered by key (a tile's in its order, the global order,
    // for coincident points): the first kNoiseSamples are the whole cloud's sample.
    struct Keyed {
      std::uint64_t key;
      std::size_t tile, rank;
      NoiseSample sample;
      bool plane;
    };
    std::vector<Keyed> all;
    for (std::size_t t = 0; t < tiles; ++t) {
      std::vector<float> parts[3], flatness, rms, spacing;
      bool read = true;
      for (int p = 0; p < 3; ++p)
        read = read && tiling::loadTileValues (folder, t, kCrfKeyParts[p], parts[p]);
      if (!read || !tiling::loadTileValues (folder, t, kFlatness, flatness) ||
          !tiling::loadTileValues (folder, t, kRms, rms) ||
          !tiling::loadTileValues (folder, t, kSpacing, spacing))
        return false;
      const std::size_t n = flatness.size();
      if (parts[0].size() != n || parts[1].size() != n || parts[2].size() != n ||
          rms.size() != n || spacing.size() != n) {
        std::cerr << "Error: the noise sample of tile " << t << " in " << folder
                  << " is broken.\n";
        return false;
      }
      for (std::size_t i = 0; i < n; ++i) {
        Keyed k;
        k.key = keyAt (parts, i);
        k.tile = t;
        k.rank = i;
        k.plane = std::isfinite (flatness[i]);
        k.sample = {flatness[i], rms[i], spacing[i]};
        all.push_back (k);
      }
    }
    const std::size_t n = std::min (kNoiseSamples, all.size());
    std::partial_sort (
        all.begin(), all.begin() + n, all.end(), [] (const Keyed& a, const Keyed& b) {
          return a.key != b.key
                     ? a.key < b.key
                     : (a.tile != b.tile ? a.tile < b.tile : a.rank < b.rank);
        });
    std::vector<NoiseSample> samples;
    for (std::size_t i = 0; i < n; ++i)
      if (all[i].plane)
        samples.push_back (all[i].sample);
    std::ostringstream text;
    text.precision (17);
    text << noiseFromSamples (std::move (samples));
    settings[kCrfNoiseSetting] = text.str();
    return true;
  }

  bool
  run (const TileCloud& tile,
       const std::map<std::string, std::string>& settings,
       std::vector<std::uint32_t>& labels) override
  {
    labels.assign (tile.cloud ? tile.cloud->size() : 0, 0);
    probabilities_.assign (labels.size(), 0.0f);
    needed_margin_ = 0.0;
    if (tile.core_points == 0)
      return true;
    CrfSettings s = model_.getSettings();
    s.threads = threads_;
    if (needsEstimate()) {
      const auto found = settings.find (kCrfNoiseSetting);
      if (found == settings.end()) {
        std::cerr << "Error: the plan has no noise estimate (run the estimate step on "
                     "every tile first).\n";
        return false;
      }
      // 0: nothing planar in the whole cloud's sample; a tile would estimate its own.
      s.supervoxels.radius.noise = std::stod (found->second);
    }
    MultiscaleCrfModel model = model_;
    model.setSettings (s);
    CrfInput input;
    input.xyz = tile.cloud;
    const std::size_t count = tile.attribute_count, n = tile.cloud->size();
    if (count != getAttributeCount() || tile.attributes.size() != n * count) {
      std::cerr << "Error: tile " << tile.tile
                << " does not carry the colour and intensity the model uses (plan "
                   "again).\n";
      return false;
    }
    if (s.features.colour)
      for (std::size_t i = 0; i < n; ++i)
        input.colours.emplace_back (tile.attributes[i * count],
                                    tile.attributes[i * count + 1],
                                    tile.attributes[i * count + 2]);
    if (s.features.intensity)
      for (std::size_t i = 0; i < n; ++i)
        input.intensity.push_back (tile.attributes[i * count + count - 1]);
    Eigen::MatrixXf probabilities;
    if (!model.classify (input, labels, probabilities)) {
      std::cerr << "Error: the classification of tile " << tile.tile << " failed.\n";
      return false;
    }
    // The winning class's probability, as pcl_ext_crf_classify writes it.
    if (!probability_field_.empty())
      for (std::size_t i = 0; i < labels.size(); ++i)
        if (labels[i] != 0)
          probabilities_[i] =
              probabilities.row (static_cast<Eigen::Index> (i)).maxCoeff();
    for (const auto& draw : model.getDrawSupervoxels())
      needed_margin_ = std::max (needed_margin_, neededMargin (tile, draw));
    return true;
  }

  double
  getNeededMargin () const override
  {
    return needed_margin_;
  }

private:
  /** How far from a super-voxel's mid-point beyond its radius its features read: the
   * cells of the local ground around it, the largest multi-scale radius. */
  double
  groundAndFeatureReach () const
  {
    const SaliencyFeatureOptions& f = model_.getSettings().features;
    return (f.ground_reach + 1) * static_cast<double> (f.ground_cell) *
               (f.ground_estimate == GroundEstimate::Opening ? 2.0 : 1.0) +
           (f.scales.empty() ? 0.0 : static_cast<double> (f.scales.back()));
  }

  /** The margin a core point's label needed: a super-voxel holding a core point reads
   * the points within its radius of its mid-point and the local ground (cells) around
   * it; through the regional edges, its neighbours do the same (belief propagation
   * carries it further, weakened at every step). Each must lie within the data loaded;
   * where one does not, the margin it lacked is added. */
  double
  neededMargin (const TileCloud& tile, const SupervoxelSet& svs) const
  {
    const double ground = groundAndFeatureReach();
    std::vector<char> read (svs.size(), 0); // 1: holds a core point, 2: its neighbour
    for (std::size_t i = 0; i < tile.core.size(); ++i)
      if (tile.core[i] && i + 1 < svs.membership_offsets.size())
        for (std::size_t k = svs.membership_offsets[i];
             k < svs.membership_offsets[i + 1];
             ++k)
          read[svs.membership[k]] = 1;
    if (model_.getSettings().mode == CrfMode::MultiscaleCrf)
      for (std::size_t v = 0; v < svs.size(); ++v)
        if (read[v] == 1)
          for (const auto w : svs.adjacency[v])
            read[w] = std::max<char> (read[w], 2);
    double needed = 0.0;
    for (std::size_t v = 0; v < svs.size(); ++v) {
      if (!read[v])
        continue;
      const Supervoxel& sv = svs.supervoxels[v];
      const auto& m = (*tile.cloud)[static_cast<std::size_t> (sv.seed)];
      const double space = tile.getReach (m.x, m.y);
      const double lacking = sv.radius + ground - space;
      if (std::isfinite (space) && lacking > 0.0)
        needed = std::max (needed, tile.margin + lacking);
    }
    return needed;
  }

  std::string model_path_;
  MultiscaleCrfModel model_;
  std::string probability_field_;
  std::vector<float> probabilities_; ///< of the last run()
  double needed_margin_ = 0.0;
  std::map<std::uint32_t, std::uint32_t> asprs_;
};
} // namespace

std::unique_ptr<TileMethod>
makeCrfClassifyTiles ()
{
  return std::make_unique<CrfClassifyTiles>();
}
} // namespace apps
} // namespace pcl_ext
