/*
 * pcl_ext: a generated scene as the input of the multi-scale CRF, for the tools and the
 * tests.
 */
#pragma once

#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/simulation/scenes.h>

#include <cstdint>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The points of a generated \a scene as MultiscaleCrfModel takes them, in the
 * scene's point order: x y z, the colour normalised to (r, g, b) / (r + g + b) (1/3
 * each for black) and the intensity; the scene label of each point (its class, for
 * training or for scoring a classification) in \a labels. */
CrfInput
makeCrfInput (const simulation::SyntheticScene& scene,
              std::vector<std::uint32_t>& labels);
} // namespace apps
} // namespace pcl_ext
