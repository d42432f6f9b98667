/*
 * Khoshelham & Gorte (2009) on the simulated building over many random poses: each
 * trial scans the building (asymmetric H, yaw any angle, tilt up to 3 degrees,
 * translation up to 100 m) with superfluous planes and walls hidden behind hedges,
 * registers the scan to the footprint and checks the match set and the errors against
 * the true transform. Prints one line per failed trial and a summary; exits non-zero
 * when a trial misses the goals.
 */
#include "../registration/building_fixture.h"

#include <pcl_ext/apps/command_line.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

int
main (int argc, char** argv)
{
  int trials = 100, superfluous = 4, missing = 2;
  double noise = 0.2, max_rotation = 0.5, max_translation = 0.2, max_mean = 0.27;
  unsigned int first_seed = 1;
  pcl_ext::apps::CommandLine cl (
      "pcl_ext_benchmark_building_trials",
      "Registers scans of the simulated building in random poses to its footprint "
      "(plane "
      "matching) and counts the trials that meet the goals.");
  cl.addOption ("trials", trials, "number of random poses");
  cl.addOption ("seed", first_seed, "seed of the first trial (then +1 per trial)");
  cl.addOption ("noise", noise, "range noise sigma (m)");
  cl.addOption ("superfluous", superfluous, "superfluous planes (4 of 13 = 30 %)");
  cl.addOption ("missing", missing, "walls hidden behind hedges (2 of 12)");
  cl.addOption ("max_rotation", max_rotation, "goal: rotation error (deg)");
  cl.addOption ("max_translation", max_translation, "goal: translation error (m)");
  cl.addOption ("max_mean", max_mean, "goal: mean distance between matched planes (m)");
  if (const int code = cl.parse (argc, argv); code >= 0)
    return code;
  if (trials < 1 || !(noise >= 0.0) || superfluous < 0 || missing < 0) {
    std::fprintf (stderr,
                  "Error: need trials >= 1, noise >= 0, non-negative plane counts.\n");
    return 1;
  }
  int good = 0;
  double worst_rotation = 0.0, worst_translation = 0.0, worst_mean = 0.0, seconds = 0.0;
  for (int t = 0; t < trials; ++t) {
    const unsigned int seed = first_seed + static_cast<unsigned int> (t);
    const pcl_ext::test::Building b =
        pcl_ext::test::scanBuilding (seed, noise, superfluous, missing);
    const auto t0 = std::chrono::steady_clock::now();
    const pcl_ext::test::Outcome o = pcl_ext::test::registerToMap (b);
    seconds +=
        std::chrono::duration<double> (std::chrono::steady_clock::now() - t0).count();
    const bool ok =
        o.converged && o.wrong == 0 && o.error.rotation_deg <= max_rotation &&
        o.error.translation <= max_translation && o.distances.mean <= max_mean;
    good += ok;
    if (o.converged) {
      worst_rotation = std::max (worst_rotation, o.error.rotation_deg);
      worst_translation = std::max (worst_translation, o.error.translation);
      worst_mean = std::max (worst_mean, o.distances.mean);
    }
    if (!ok)
      std::printf (
          "trial %u: converged %d, %zu scan planes, %zu matched, %d wrong, rotation "
          "%.3f deg, translation %.3f m, mean plane distance %.3f m\n",
          seed,
          int (o.converged),
          o.scan_planes,
          o.matches,
          o.wrong,
          o.error.rotation_deg,
          o.error.translation,
          o.distances.mean);
  }
  std::printf (
      "%d of %d trials met the goals (noise %.2f m, %d superfluous planes, %d hidden "
      "walls); worst rotation %.3f deg, translation %.3f m, mean plane distance %.3f "
      "m; "
      "registration %.3f s per trial (plane extraction included)\n",
      good,
      trials,
      noise,
      superfluous,
      missing,
      worst_rotation,
      worst_translation,
      worst_mean,
      seconds / trials);
  return good == trials ? 0 : 2;
}
