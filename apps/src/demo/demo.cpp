/*
 * pcl_ext_demo: every pcl_ext method on generated scenes, as PNG images and a text
 * summary.
 */
#include "demo_context.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/file_output.h>

#include <sys/stat.h>

#include <chrono>
#include <ctime>
#include <functional>
#include <iostream>

int
main (int argc, char** argv)
{
  pcl_ext::demo::DemoContext context;
  int points = 0;
  unsigned int seed = 1;
  std::string only;
  pcl_ext::apps::CommandLine cl ("pcl_ext_demo",
                                 "Runs pcl_ext's methods on generated TLS scenes "
                                 "(nothing is downloaded) and writes PNG "
                                 "images and a text summary (summary.txt: timings, "
                                 "metrics) to the output folder.");
  cl.addPositional (
      "out_dir", context.out_dir, "output folder (created if missing)", false);
  cl.addOption (
      "points", points, "target points per generated scene (0: each scene's default)");
  cl.addOption ("seed", seed, "random seed of the scenes");
  cl.addOption ("k", context.k, "neighbours per point");
  cl.addOption ("threads", context.threads, "threads (0: all cores)");
  cl.addOption ("step",
                only,
                "run only this step (scenes, neighbourhoods, classification, "
                "variance_segmentation, profiles, registration, crf)");
  cl.addOption ("data",
                context.shared_data_dir,
                "folder of real scans used by optional steps when present");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (points < 0 || context.k < 1) {
    std::cerr << "Error: -points must be >= 0 and -k >= 1.\n";
    return 1;
  }
  context.points = static_cast<std::size_t> (points);
  context.seed = seed;
  if (context.out_dir.empty())
    context.out_dir = "out";
  ::mkdir (context.out_dir.c_str(), 0755);
  if (!pcl_ext::io::checkWritable (context.out_dir + "/summary.txt"))
    return 1;

  const std::vector<
      std::pair<std::string, std::function<bool (pcl_ext::demo::DemoContext&)>>>
      steps = {{"scenes", pcl_ext::demo::runScenesStep},
               {"neighbourhoods", pcl_ext::demo::runNeighbourhoodsStep},
               {"classification", pcl_ext::demo::runClassificationStep},
               {"variance_segmentation", pcl_ext::demo::runVarianceSegmentationStep},
               {"profiles", pcl_ext::demo::runProfilesStep},
               {"registration", pcl_ext::demo::runRegistrationStep},
               {"crf", pcl_ext::demo::runCrfStep}};

  const auto now =
      std::chrono::system_clock::to_time_t (std::chrono::system_clock::now());
  char date[32];
  std::strftime (date, sizeof (date), "%Y-%m-%d %H:%M UTC", std::gmtime (&now));
  context.summary << "pcl_ext demo, " << date << ", seed " << seed << ", k "
                  << context.k << "\n";
  bool ok = true;
  bool ran = false;
  for (const auto& step : steps) {
    if (!only.empty() && only != step.first)
      continue;
    ran = true;
    std::cout << "== " << step.first << "\n";
    context.summary << "\n[" << step.first << "]\n";
    if (!step.second (context)) {
      std::cerr << "Error: demo step '" << step.first << "' failed.\n";
      context.summary << "  FAILED\n";
      ok = false;
    }
  }
  if (!ran) {
    std::cerr << "Error: no demo step named '" << only << "'.\n";
    return 1;
  }
  if (!pcl_ext::io::writeTextFile (context.path ("summary.txt"), context.summary.str()))
    return 1;
  std::cout << "Wrote " << context.images << " images and summary.txt to "
            << context.out_dir << "\n";
  return ok ? 0 : 1;
}
