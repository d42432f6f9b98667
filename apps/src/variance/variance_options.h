/*
 * pcl_ext: the Belton & Lichti classification options that pcl_ext_classify_variance
 * and pcl_ext_segment_variance share: their switches, checks and hand-over, written
 * once.
 */
#pragma once

#include <pcl_ext/apps/command_line.h>

#include <cmath>
#include <iostream>
#include <set>
#include <string>

namespace pcl_ext {
namespace apps {
/** \brief Options of the local variance classification (eqs. 4-6 and pcl_ext's
 * additions), with the defaults of LocalVarianceClassification (setDerivedSettings).
 * Only the options given on the command line are handed over, after the preset. */
struct VarianceClassificationOptions {
  double curvature_threshold = 0.0;
  double curvature_factor = 1.0;
  double variance_threshold = 1e-4;
  double relative_variance = 0.5;
  double confidence = 0.95;
  double noise_sigma = 0.0;
  double crease_angle = 0.0; ///< degrees
  bool boundary_band = false;
  double boundary_band_fraction = 1.0;
  std::string preset;   ///< "paper" or "derived" (setPaperSettings, setDerivedSettings)
  bool verbose = false; ///< print the values estimated from the cloud and used
  bool noise_given = false;
  std::set<std::string> given; ///< the options given on the command line

  void
  addTo (apps::CommandLine& cl)
  {
    cl.addOption (
        "preset",
        preset,
        "'derived' (the defaults): the noise estimated from the cloud and removed, "
        "the curvature threshold at the median curvature, eq. 5's tolerance also "
        "relative to the curvature, eq. 6 allowing for the sampling and, when "
        "segmenting, section 4's re-integration; 'paper': the paper's settings; "
        "the other options still override them");
    cl.addSwitch ("v",
                  verbose,
                  "print the noise and spacing estimated from the cloud and the "
                  "thresholds used");
    cl.addOption ("curvature_threshold",
                  curvature_threshold,
                  "curvature (eq. 4) threshold; 0: factor * median curvature");
    cl.addOption ("curvature_factor",
                  curvature_factor,
                  "multiple of the median curvature when the threshold is 0 (-preset "
                  "paper: 3)");
    cl.addOption ("variance_threshold",
                  variance_threshold,
                  "variance of curvature tolerance (eq. 5)");
    cl.addOption ("relative_variance",
                  relative_variance,
                  "an edge's standard deviation of curvature must also exceed this "
                  "share of its mean curvature (0: off; -preset paper: 0)");
    cl.addOption ("confidence",
                  confidence,
                  "confidence of the chi-squared boundary test (eq. 6)");
    cl.addOption (
        "noise_sigma",
        noise_sigma,
        "the noise sigma about the surfaces, removed from eq. 4-6 (not given: "
        "estimated from the cloud; -preset paper: 0)");
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
    for (const char* name : {"curvature_threshold",
                             "curvature_factor",
                             "variance_threshold",
                             "relative_variance",
                             "confidence",
                             "boundary_band",
                             "boundary_band_fraction",
                             "crease_angle"})
      if (cl.given (name))
        given.insert (name);
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

  /** \brief Hands the preset, then the options given, to a
   * LocalVarianceClassification. */
  template <typename Classifier>
  void
  applyTo (Classifier& classifier) const
  {
    if (preset == "paper")
      classifier.setPaperSettings();
    else
      classifier.setDerivedSettings();
    const auto has = [this] (const char* name) { return given.count (name) > 0; };
    if (has ("curvature_threshold"))
      classifier.setCurvatureThreshold (curvature_threshold);
    if (has ("curvature_factor"))
      classifier.setCurvatureThresholdFactor (curvature_factor);
    if (has ("variance_threshold"))
      classifier.setVarianceThreshold (variance_threshold);
    if (has ("relative_variance"))
      classifier.setRelativeVarianceThreshold (relative_variance);
    if (has ("confidence"))
      classifier.setConfidence (confidence);
    if (noise_given)
      classifier.setNoiseStandardDeviation (noise_sigma);
    if (has ("boundary_band"))
      classifier.setBoundaryBand (boundary_band);
    if (has ("boundary_band_fraction"))
      classifier.setBoundaryBandFraction (boundary_band_fraction);
    if (has ("crease_angle"))
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
                << (classifier.getNoiseStandardDeviationUsed() == 0.0 && e.sigma > 0.0
                        ? "; noise above 0.2 spacings: not removed"
                        : "")
                << "\n";
    else if (classifier.getNoiseEstimation())
      std::cout << "The noise could not be estimated (" << e.reason
                << "): none removed, the paper's eq. 4-6\n";
    std::cout << "Used: noise sigma " << classifier.getNoiseStandardDeviationUsed()
              << (noise_given ? " (given)" : "") << ", curvature threshold "
              << classifier.getCurvatureThresholdUsed() << ", variance threshold "
              << classifier.getVarianceThreshold() << " (relative "
              << classifier.getRelativeVarianceThreshold() << "), confidence "
              << classifier.getConfidence() << "\n";
    std::cout.precision (precision);
  }
};
} // namespace apps
} // namespace pcl_ext
