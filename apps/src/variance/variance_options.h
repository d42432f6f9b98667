/*
 * pcl_ext: the Belton & Lichti classification options that pcl_ext_classify_variance
 * and pcl_ext_segment_variance share: their switches, checks and hand-over, written
 * once.
 */
#pragma once

#include <pcl_ext/apps/command_line.h>

#include <cmath>
#include <iostream>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief Options of the local variance classification (eqs. 4-6 and pcl_ext's
 * additions), with the defaults of LocalVarianceClassification. */
struct VarianceClassificationOptions {
  double curvature_threshold = 0.0;
  double curvature_factor = 0.0;
  double variance_threshold = 1e-4;
  double confidence = 0.95;
  double noise_sigma = 0.0;
  double crease_angle = 0.0; ///< degrees
  bool boundary_band = false;
  double boundary_band_fraction = 1.0;
  std::string preset;   ///< "paper" or "derived" (setPaperSettings, setDerivedSettings)
  bool verbose = false; ///< print the values estimated from the cloud and used
  bool noise_given = false;
  bool given_factor = false;

  void
  addTo (apps::CommandLine& cl)
  {
    cl.addOption (
        "preset",
        preset,
        "'paper': the paper's settings (when segmenting, no re-integration); "
        "'derived': the noise estimated from the cloud and removed and the "
        "curvature threshold at the median curvature; the other options still "
        "override them");
    cl.addSwitch ("v",
                  verbose,
                  "print the noise and spacing estimated from the cloud and the "
                  "thresholds used");
    cl.addOption ("curvature_threshold",
                  curvature_threshold,
                  "curvature (eq. 4) threshold; 0: factor * median curvature");
    cl.addOption ("curvature_factor",
                  curvature_factor,
                  "multiple of the median curvature when the threshold is 0 (0: "
                  "from the cloud: 1 where the noise exceeds 0.2 point spacings, a "
                  "range camera's, else 3; -preset paper 3, -preset derived 1)");
    cl.addOption ("variance_threshold",
                  variance_threshold,
                  "variance of curvature tolerance (eq. 5)");
    cl.addOption ("confidence",
                  confidence,
                  "confidence of the chi-squared boundary test (eq. 6)");
    cl.addOption (
        "noise_sigma",
        noise_sigma,
        "the noise sigma about the surfaces, removed from eq. 4-6 (0: the paper's; "
        "-preset derived estimates it from the cloud)");
    cl.addSwitch ("boundary_band",
                  boundary_band,
                  "also label boundary the surface points next to one eq. 6 finds");
    cl.addOption (
        "boundary_band_fraction",
        boundary_band_fraction,
        "share of each neighbourhood, nearest first, the band reaches through (0-1]");
    cl.addOption (
        "crease_angle",
        crease_angle,
        "an edge of eq. 5 must bend the normals by more than this (degrees; 0: off)");
  }

  /** \brief The checks the classes cannot make for the app (units of the command line);
   * prints the error. The classes check the rest. */
  bool
  valid (const apps::CommandLine& cl)
  {
    noise_given = cl.given ("noise_sigma");
    given_factor = cl.given ("curvature_factor");
    if (!preset.empty() && preset != "paper" && preset != "derived") {
      std::cerr << "Error: -preset must be 'paper' or 'derived'.\n";
      return false;
    }
    if (!(crease_angle >= 0.0 && crease_angle <= 90.0)) {
      std::cerr << "Error: -crease_angle must lie between 0 and 90 degrees.\n";
      return false;
    }
    if (!(noise_sigma >= 0.0) || !std::isfinite (noise_sigma)) {
      std::cerr << "Error: -noise_sigma must be finite and >= 0.\n";
      return false;
    }
    return true;
  }

  /** \brief Hands the options to a LocalVarianceClassification. */
  template <typename Classifier>
  void
  applyTo (Classifier& classifier) const
  {
    if (preset == "paper")
      classifier.setPaperSettings();
    else if (preset == "derived")
      classifier.setDerivedSettings();
    classifier.setCurvatureThreshold (curvature_threshold);
    if (given_factor)
      classifier.setCurvatureThresholdFactor (curvature_factor);
    classifier.setVarianceThreshold (variance_threshold);
    classifier.setConfidence (confidence);
    if (noise_given)
      classifier.setNoiseStandardDeviation (noise_sigma);
    classifier.setBoundaryBand (boundary_band);
    classifier.setBoundaryBandFraction (boundary_band_fraction);
    classifier.setCreaseAngle (crease_angle * M_PI / 180.0);
  }

  /** \brief With -v: what the last classify() estimated from the cloud and used. */
  template <typename Classifier>
  void
  report (const Classifier& classifier) const
  {
    if (!verbose)
      return;
    const auto precision = std::cout.precision (4);
    const auto& e = classifier.getNoiseEstimate();
    if (e.valid)
      std::cout << "Estimated from the cloud: noise sigma " << e.sigma
                << ", point spacing " << e.spacing << " (from " << e.used
                << " of the flattest neighbourhoods, median curvature "
                << e.flat_curvature << ")"
                << (classifier.getNoiseEstimation() &&
                            classifier.getNoiseStandardDeviationUsed() == 0.0 &&
                            e.sigma > 0.0
                        ? "; noise above 0.2 spacings: not removed"
                        : "")
                << "\n";
    else if (classifier.getNoiseEstimation())
      std::cout << "The noise could not be estimated (" << e.reason
                << "): none removed, the paper's eq. 4-6\n";
    std::cout << "Used: noise sigma " << classifier.getNoiseStandardDeviationUsed()
              << (noise_given ? " (given)" : "") << ", curvature threshold "
              << classifier.getCurvatureThresholdUsed();
    if (classifier.getCurvatureThresholdFactorUsed() > 0.0)
      std::cout << " (" << classifier.getCurvatureThresholdFactorUsed()
                << " x the median curvature)";
    std::cout << ", variance threshold " << classifier.getVarianceThreshold()
              << ", confidence " << classifier.getConfidence() << "\n";
    std::cout.precision (precision);
  }
};
} // namespace apps
} // namespace pcl_ext
