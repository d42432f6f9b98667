/*
 * pcl_ext_crf_train: train Lim & Suter's multi-scale CRF on labelled clouds.
 */
#include "crf/crf_inputs.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/apps/input.h>
#include <pcl_ext/io/file_output.h>

#include <pcl/console/print.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

int
main (int argc, char** argv)
{
  std::string output, classes_file,
      mode_text = "mcrf", scales_text = "none", expansion_text = "linear",
      node_model_text = "logistic", ground_text = "lowest_in_block",
      training_text = "staged";
  double sigma = 1.0, noise = 0.0, min_radius = 0.5;
  int ground_reach = 3;
  int max_k = 60, local_edges = 4, regional_edges = 4, iterations = 200, knots = 2;
  int rounds = 200, depth = 6, draws = pcl_ext::CrfSettings().draws;
  double eta = 0.1;
  unsigned int threads = 0, seed = 1;
  bool no_balance = false;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_crf_train",
      std::string ("Trains the multi-scale CRF over adaptive super-voxels (Lim & Suter "
                   "2008) on labelled clouds and writes the model (text) to -o.\n"
                   "Inputs: ") +
          pcl_ext::apps::kInputFormats +
          " with a 'label' field (class ids), or Oakland .xyz_label_conf files with "
          "-classes.\n"
          "Usage: pcl_ext_crf_train -o model.txt [options] train1 [train2 ...]");
  cl.addOption ("o", output, "the model file to write (required)");
  cl.addOption (
      "classes", classes_file, "class file: 'id name : source labels' per line");
  cl.addOption (
      "mode", mode_text, "node | crf | mcrf (node-only, local CRF, multi-scale CRF)");
  cl.addOption (
      "scales",
      scales_text,
      "radii (m) of the multi-scale features, ascending, "
      "comma-separated, e.g. 0.5,1,2; 'none': the paper's single-scale features");
  cl.addOption ("node_model",
                node_model_text,
                "classifier of the node potentials: logistic (the paper's "
                "multinomial logistic regression) or boosted_trees (XGBoost)");
  cl.addOption ("training",
                training_text,
                "staged (node weights, then edge weights on the node fit's "
                "probabilities, then the edges' weight at inference) or "
                "pseudo_likelihood (the paper's eq. 9: all weights at once given the "
                "neighbours' true labels)");
  cl.addOption ("rounds", rounds, "boosting rounds (boosted_trees)");
  cl.addOption ("depth", depth, "maximum tree depth (boosted_trees)");
  cl.addOption ("eta", eta, "learning rate of the boosting (boosted_trees)");
  cl.addOption (
      "expansion",
      expansion_text,
      "inputs of the logistic node model: linear "
      "(the paper's), spline (piecewise-linear in each feature) or spline_products "
      "(spline and the products of feature pairs)");
  cl.addOption (
      "ground",
      ground_text,
      "local ground under the height feature: "
      "lowest_in_block (lowest point of the cells around) or opening (morphological "
      "opening of the cells' lowest points)");
  cl.addOption ("ground_reach",
                ground_reach,
                "cells (1 m) on each side of the local ground block");
  cl.addOption ("knots", knots, "hinges per feature of the spline expansions");
  cl.addOption ("sigma", sigma, "sigma of the Gaussian prior on the weights (eq. 9)");
  cl.addOption (
      "noise", noise, "noise constant sigma of eq. 3 in metres (0: estimate)");
  cl.addOption (
      "min_radius",
      min_radius,
      "lower bound on the super-voxel radius in metres "
      "(0: none, the paper's; 0.5 was chosen by cross-validation on Oakland)");
  cl.addOption (
      "max_k", max_k, "k threshold that stops the super-voxel radius growing");
  cl.addOption ("m", local_edges, "local edges per super-voxel");
  cl.addOption ("l", regional_edges, "regional edges per super-voxel");
  cl.addOption ("iterations", iterations, "maximum L-BFGS iterations");
  cl.addOption ("seed", seed, "seed of the super-voxel mid-points and local points");
  cl.addOption ("draws",
                draws,
                "over-segmentations the model averages at classification (seeds seed, "
                "seed + 1, ...); training uses the first");
  cl.addOption ("threads", threads, "threads (0: all cores)");
  cl.addSwitch (
      "no_balance", no_balance, "do not weight training nodes by class frequency");
  // Inputs are every argument that is not an option: take them out before parsing.
  std::vector<std::string> inputs;
  std::vector<const char*> args{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (!a.empty() && a[0] == '-') {
      args.push_back (argv[i]);
      const bool is_switch =
          a == "-no_balance" || a == "-h" || a == "-help" || a == "--help";
      if (!is_switch && i + 1 < argc)
        args.push_back (argv[++i]);
    }
    else
      inputs.push_back (a);
  }
  if (const int code = cl.parse (static_cast<int> (args.size()), args.data());
      code >= 0)
    return code;
  pcl_ext::CrfMode mode;
  pcl_ext::CrfNodeExpansion expansion;
  pcl_ext::CrfNodeModel node_model;
  pcl_ext::GroundEstimate ground;
  pcl_ext::CrfTraining training;
  if (output.empty() || inputs.empty() || !pcl_ext::parseCrfMode (mode_text, mode) ||
      !pcl_ext::parseCrfNodeModel (node_model_text, node_model) ||
      !pcl_ext::parseCrfNodeExpansion (expansion_text, expansion) ||
      !pcl_ext::parseGroundEstimate (ground_text, ground) ||
      !pcl_ext::parseCrfTraining (training_text, training)) {
    std::cerr
        << "pcl_ext_crf_train: need -o model.txt, at least one training cloud, a mode "
           "among node, crf, mcrf, a node model among boosted_trees, logistic, an "
           "expansion among linear, spline, spline_products, a ground among "
           "lowest_in_block, opening and a training among staged, pseudo_likelihood "
           "(see -h)\n";
    return 1;
  }
  if (!pcl_ext::io::checkWritable (output))
    return 1;
  pcl_ext::io::ClassMapping mapping;
  if (!classes_file.empty()) {
    try {
      mapping.load (classes_file);
    }
    catch (const std::exception& e) {
      std::cerr << "pcl_ext_crf_train: " << e.what() << '\n';
      return 1;
    }
  }
  std::vector<pcl_ext::CrfInput> clouds;
  std::vector<std::vector<std::uint32_t>> labels;
  for (const auto& path : inputs) {
    pcl_ext::apps::StageTimer timer ("Loading " + path);
    pcl_ext::apps::CrfCloud c;
    std::string error;
    if (!pcl_ext::apps::loadCrfCloud (path, &mapping, c, error)) {
      std::cerr << "\npcl_ext_crf_train: " << error << '\n';
      return 1;
    }
    if (c.labels.empty()) {
      std::cerr << "\npcl_ext_crf_train: " << path << " has no labels to train on\n";
      return 1;
    }
    timer.done (c.input.xyz->size());
    clouds.push_back (c.input);
    labels.push_back (c.labels);
  }
  pcl_ext::MultiscaleCrfModel model;
  pcl_ext::CrfSettings s = model.getSettings();
  s.mode = mode;
  s.sigma = sigma;
  s.node_expansion = expansion;
  s.node_model = node_model;
  s.training = training;
  s.boost_rounds = rounds;
  s.boost_depth = depth;
  s.boost_eta = eta;
  s.spline_knots = knots;
  s.features.ground_estimate = ground;
  s.features.ground_reach = ground_reach;
  s.features.scales.clear();
  if (scales_text != "none") {
    std::istringstream in (scales_text);
    for (std::string item; std::getline (in, item, ',');) {
      char* end = nullptr;
      const float r = std::strtof (item.c_str(), &end);
      if (item.empty() || *end != '\0') {
        std::cerr
            << "pcl_ext_crf_train: -scales takes radii separated by commas, or none\n";
        return 1;
      }
      s.features.scales.push_back (r);
    }
  }
  s.supervoxels.radius.noise = noise;
  s.supervoxels.radius.max_k = max_k;
  s.supervoxels.radius.min_radius = min_radius;
  s.supervoxels.adjacency = regional_edges;
  s.supervoxels.seed = seed;
  s.draws = draws;
  s.local_edges = local_edges;
  s.max_training_iterations = iterations;
  s.threads = threads;
  s.balance_classes = !no_balance;
  model.setSettings (s);
  if (!mapping.empty())
    model.setClassNames (mapping.names());
  pcl_ext::apps::StageTimer timer (
      "Training the " + std::string (pcl_ext::crfModeName (mode)) + " model");
  if (!model.train (clouds, labels)) {
    std::cerr << "\npcl_ext_crf_train: training failed (see above)\n";
    return 1;
  }
  const auto& st = model.getStatistics();
  timer.done (st.points);
  std::printf (
      "  super-voxels %.0f ms, features %.0f ms, optimisation %.0f ms (%d L-BFGS "
      "iterations%s); %zu super-voxels, %zu local points, %zu local and %zu regional "
      "edges\n",
      st.supervoxels_ms,
      st.features_ms,
      st.training_ms,
      st.iterations,
      st.converged ? ", converged" : "",
      st.supervoxels,
      st.local_points,
      st.local_edges,
      st.regional_edges);
  if (!model.saveModel (output))
    return 1;
  std::printf ("Model written to %s\n", output.c_str());
  return 0;
}
