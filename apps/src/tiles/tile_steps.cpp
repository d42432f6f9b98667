/*
 * pcl_ext_tiles: the steps of a tiled run (plan, estimate, tile, merge), each usable
 * alone (scheduler array jobs) or one after another.
 */
#include "tile_steps.h"
#include "merge_output.h"
#include "second_pass_steps.h"
#include "input_fields.h"
#include "tile_outputs.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_writer.h>
#include <pcl_ext/io/read_error.h>
#include <pcl_ext/tiling/merged_results.h>
#include <pcl_ext/tiling/point_file_chunks.h>
#include <pcl_ext/tiling/tile_results.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <sys/stat.h>

namespace pcl_ext {
namespace apps {
namespace {
/** At most this many points in the densest tile when no tile size is given: with its
 * halo, its neighbourhoods and the method's arrays, a process stays under 2 GB
 * (docs/tiles.md has the measurements). */
constexpr std::uint64_t kPointsPerTile = 2500000;

/** A halo for \a reach from the first million points of \a input: the 99th percentile
 * of the neighbourhood radii of a sample of them, through every step a result reaches,
 * with a quarter more (and, for a method that searches by itself, its radius added). A
 * run of a file's points holds fewer neighbours than the whole cloud, so the radii are
 * rather too wide than too narrow; where they are too narrow the tiles widen
 * themselves. */
double
estimateHalo (const std::string& input,
              const Eigen::Vector3d& origin,
              const NeighbourhoodReach& reach)
{
  if (!reach.search) {
    // The method's own part, and as far as its k-neighbourhoods reach.
    NeighbourhoodReach k_part = reach;
    k_part.search = true;
    k_part.radius = 0.0;
    return reach.radius + estimateHalo (input, origin, k_part);
  }
  if (reach.radius > 0.0)
    return 1.25 * reach.hops * reach.radius;
  tiling::PointFileChunks file;
  file.open (input);
  file.setOrigin (origin);
  pcl::PCLPointCloud2 chunk;
  file.read (1 << 20, chunk);
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  const std::uint8_t* xyz = chunk.data.data() + tiling::xyzOffset (chunk);
  const std::size_t n = static_cast<std::size_t> (chunk.width) * chunk.height;
  for (std::size_t i = 0; i < n; ++i) {
    float p[3];
    std::memcpy (p, xyz + i * chunk.point_step, sizeof (p));
    if (std::isfinite (p[0]) && std::isfinite (p[1]) && std::isfinite (p[2]))
      cloud->push_back (pcl::PointXYZ (p[0], p[1], p[2]));
  }
  if (cloud->size() <= static_cast<std::size_t> (reach.k))
    return 0.0;
  auto sample = pcl::make_shared<pcl::Indices>();
  const std::size_t step = std::max<std::size_t> (1, cloud->size() / 2000);
  for (std::size_t i = 0; i < cloud->size(); i += step)
    sample->push_back (static_cast<pcl::index_t> (i));
  pcl_ext::Neighbourhoods<pcl::PointXYZ> nb;
  nb.setInputCloud (cloud);
  nb.setIndices (sample);
  nb.setKSearch (reach.k);
  nb.setMaxRadius (reach.max_radius);
  if (!nb.compute() || nb.empty())
    return 0.0;
  std::vector<float> radii;
  for (std::size_t r = 0; r < nb.size(); ++r)
    if (nb[r].size() > 0)
      radii.push_back (std::sqrt (nb.getSquaredDistance (r, nb[r].size() - 1)));
  if (radii.empty())
    return 0.0;
  auto at = radii.begin() + static_cast<std::ptrdiff_t> (0.99 * (radii.size() - 1));
  std::nth_element (radii.begin(), at, radii.end());
  return 1.25 * reach.hops * static_cast<double> (*at);
}

/** Remove what an earlier run left in \a workdir (stopped, or -keep_workdir): its marks
 * would pass for this plan's. Only the names the steps write are touched. */
bool
removeEarlierRun (const std::string& workdir)
{
  std::error_code error;
  std::vector<std::filesystem::path> earlier;
  for (const auto& entry : std::filesystem::directory_iterator (workdir, error)) {
    const std::string name = entry.path().filename().string();
    const std::size_t digits = name.find_first_not_of ("0123456789", 5);
    const bool tile_file = name.rfind ("tile_", 0) == 0 && digits > 5 &&
                           digits < name.size() && name[digits] == '.';
    if (tile_file || name == "plan.txt" || name == "segments.joined" ||
        name == "results.bin" || name == "values.bin" || name == "refined.bin" ||
        name == "grown.bin" || name == "extra.bin")
      earlier.push_back (entry.path());
  }
  for (const auto& path : earlier)
    std::filesystem::remove (path, error);
  if (error) {
    std::cerr << "Error: cannot clear the work folder " << workdir << " of an earlier "
              << "run: " << error.message() << ".\n";
    return false;
  }
  return true;
}

} // namespace

std::string
joinArguments (const std::vector<std::string>& args)
{
  std::string text;
  for (const auto& a : args)
    text += (text.empty() ? "" : "\t") + a;
  return text;
}

std::vector<std::string>
splitArguments (const std::string& text)
{
  std::vector<std::string> args;
  std::istringstream in (text);
  std::string a;
  while (std::getline (in, a, '\t'))
    args.push_back (a);
  return args;
}

std::string
planPath (const std::string& workdir)
{
  return workdir + "/plan.txt";
}

std::vector<tiling::SegmentSize>
segmentSizes (const TileCloud& cloud, const std::vector<std::uint32_t>& labels)
{
  std::vector<tiling::SegmentSize> sizes;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::uint32_t l = labels[i];
    if (!cloud.core[i] || l == tiling::SegmentMerge::kNoSegment)
      continue;
    if (sizes.size() <= l)
      sizes.resize (l + 1);
    auto& s = sizes[l];
    s.first = s.points == 0 ? cloud.indices[i] : std::min (s.first, cloud.indices[i]);
    ++s.points;
  }
  for (std::uint32_t l = 0; l < sizes.size(); ++l)
    sizes[l].label = l;
  sizes.erase (std::remove_if (sizes.begin(),
                               sizes.end(),
                               [] (const auto& s) { return s.points == 0; }),
               sizes.end());
  return sizes;
}

bool
planStep (const std::string& method_name,
          const TileMethod& method,
          const std::vector<std::string>& method_arguments,
          const std::vector<std::string>& inputs,
          double tile_size,
          double halo,
          const std::string& workdir,
          tiling::TilePlan& plan)
{
  ::mkdir (workdir.c_str(), 0755);
  struct stat st;
  if (::stat (workdir.c_str(), &st) != 0 || !S_ISDIR (st.st_mode)) {
    std::cerr << "Error: cannot make the work folder " << workdir << ".\n";
    return false;
  }
  if (!removeEarlierRun (workdir))
    return false;
  StageTimer timer ("Planning");
  try {
    // The grid's size and halo need the box: plan once to get it.
    if (!tiling::planTiles (inputs, 1e9, 0.0, plan))
      return false;
    if (!(tile_size > 0.0))
      tile_size = tiling::fitTileSize (plan, kPointsPerTile);
    if (halo < 0.0)
      halo = std::min (estimateHalo (inputs.front(), plan.origin, method.getReach()),
                       0.5 * tile_size);
    if (!tiling::planTiles (inputs, tile_size, halo, plan))
      return false;
    // Refused now rather than at the merge: inputs whose fields or coordinate
    // reference systems cannot share a file.
    pcl::PCLPointCloud2 layout;
    if (!unionOfInputFields (inputs, layout) || !sameCoordinateSystem (inputs))
      return false;
    const NeighbourhoodReach reach = method.getReach();
    if (!reach.search && plan.halo < reach.radius)
      std::cerr << "\nWarning: the halo (" << plan.halo << " m) is narrower than "
                << method_name << "'s reach (" << reach.radius
                << " m): more points near the tiles' edges will differ from the "
                   "untiled result; give a larger -tile_size or -halo.\n";
    plan.settings["method"] = method_name;
    plan.settings["arguments"] = joinArguments (method_arguments);
    const std::size_t attributes = method.getAttributeCount();
    plan.settings["attributes"] = std::to_string (attributes);
    const tiling::ChunkAttributes read_attributes =
        [&method] (const pcl::PCLPointCloud2& chunk,
                   const std::string& input,
                   std::vector<float>& values) {
          return method.readAttributes (chunk, input, values);
        };
    if (!method.getExtraFieldName().empty() &&
        !tiling::TileResults::create (workdir, plan.getTotalPoints(), kExtraValues))
      return false;
    if (method.needsRefine() &&
        (!tiling::TileResults::create (workdir, plan.getTotalPoints(), kRefineValues) ||
         !tiling::TileResults::create (workdir, plan.getTotalPoints(), kRefined)))
      return false;
    if (method.needsGrow() &&
        !tiling::TileResults::create (workdir, plan.getTotalPoints(), kGrown))
      return false;
    // The whole cloud's noise sample, known from the points as they are sorted, so
    // that the estimates read the neighbourhoods of its points alone.
    NoiseSampleCut sample_cut;
    if (!tiling::TileResults::create (workdir, plan.getTotalPoints()) ||
        !tiling::writeTiles (plan,
                             workdir,
                             attributes,
                             read_attributes,
                             method.needsEstimate() ? &sample_cut : nullptr))
      return false;
    if (!sample_cut.empty())
      plan.settings[kNoiseSampleCutSetting] = std::to_string (sample_cut.get());
    if (!tiling::saveTilePlan (planPath (workdir), plan))
      return false;
  }
  catch (const std::exception& e) {
    std::cerr << "\nError: " << e.what() << "\n";
    return false;
  }
  timer.done (plan.getTotalPoints());
  const tiling::TileGrid grid = plan.getGrid();
  // Six digits whatever a timer left (StageTimer leaves the precision at 0).
  std::cout << std::setprecision (6) << grid.size() << " tiles (" << grid.getColumns()
            << " x " << grid.getRows() << ") of " << plan.tile_size << " m, halo "
            << plan.halo << " m, in " << workdir << "\n";
  return true;
}

bool
loadPlanAndMethod (const std::string& workdir,
                   tiling::TilePlan& plan,
                   std::unique_ptr<TileMethod>& method,
                   CommandLine& cl,
                   ResultField& result_field)
{
  if (!tiling::loadTilePlan (planPath (workdir), plan))
    return false;
  method = makeTileMethod (plan.settings["method"]);
  if (!method) {
    std::cerr << "Error: the plan's method '" << plan.settings["method"]
              << "' is unknown.\n";
    return false;
  }
  method->addOptions (cl);
  result_field = method->makeResultField();
  result_field.addTo (cl);
  std::vector<std::string> args = splitArguments (plan.settings["arguments"]);
  args.insert (args.begin(), "pcl_ext_tiles");
  std::vector<const char*> argv;
  for (const auto& a : args)
    argv.push_back (a.c_str());
  if (cl.parse (static_cast<int> (argv.size()), argv.data()) >= 0 ||
      !method->checkOptions (cl, false)) {
    std::cerr << "Error: the options in " << planPath (workdir) << " are not valid.\n";
    return false;
  }
  return true;
}

bool
estimateStep (const tiling::TilePlan& plan,
              TileMethod& method,
              const std::string& workdir,
              std::size_t tile,
              unsigned int threads)
{
  if (!method.needsEstimate())
    return true;
  TileCloud cloud;
  method.setNumberOfThreads (threads);
  std::map<std::string, std::vector<float>> values;
  const auto estimate = [&method, &values] (const TileCloud& c) {
    return method.estimate (c, values);
  };
  if (!computeOnTile (plan,
                      workdir,
                      tile,
                      method.getEstimateReach(),
                      threads,
                      0.0,
                      method,
                      estimate,
                      cloud,
                      method.getEstimateSelection (plan.settings)))
    return false;
  for (const auto& [name, v] : values)
    if (!tiling::saveTileValues (workdir, tile, name, v))
      return false;
  return true;
}

bool
reduceStep (tiling::TilePlan& plan, TileMethod& method, const std::string& workdir)
{
  if (!method.needsEstimate() || plan.settings.count ("estimated"))
    return true;
  if (!method.reduce (workdir, plan.getGrid().size(), plan.settings))
    return false;
  plan.settings["estimated"] = "1";
  return tiling::saveTilePlan (planPath (workdir), plan);
}

bool
tileStep (const tiling::TilePlan& plan,
          TileMethod& method,
          const std::string& workdir,
          std::size_t tile,
          unsigned int threads)
{
  StageTimer timer ("Tile " + std::to_string (tile));
  if (!tiling::markTileStarted (workdir, tile))
    return false;
  TileCloud cloud;
  method.setNumberOfThreads (threads);
  std::vector<std::uint32_t> labels;
  const auto run = [&method, &plan, &labels] (const TileCloud& c) {
    return method.run (c, plan.settings, labels);
  };
  if (!computeOnTile (
          plan, workdir, tile, method.getReach(), threads, 0.0, method, run, cloud))
    return false;
  std::vector<std::uint64_t> core_indices;
  std::vector<std::uint32_t> core_labels, core_values;
  std::vector<tiling::HaloLabel> halo;
  const std::vector<std::uint32_t>* values =
      method.needsRefine() ? method.getRefineValues() : nullptr;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (cloud.core[i]) {
      core_indices.push_back (cloud.indices[i]);
      core_labels.push_back (labels[i]);
      if (values)
        core_values.push_back (i < values->size() ? (*values)[i]
                                                  : tiling::TileResults::kNoResult);
    }
    else if (labels[i] != tiling::SegmentMerge::kNoSegment)
      halo.push_back ({cloud.indices[i], cloud.owners[i], labels[i]});
  }
  if (!tiling::TileResults::write (workdir, core_indices, core_labels) ||
      (values &&
       (!tiling::TileResults::write (
            workdir, core_indices, core_values, kRefineValues) ||
        !tiling::saveTileValues (workdir,
                                 tile,
                                 kRefineBounds,
                                 {static_cast<float> (method.getRefineRadius()),
                                  static_cast<float> (method.getRefineMargin())}))))
    return false;
  if (const std::vector<float>* extra =
          method.getExtraFieldName().empty() ? nullptr : method.getExtraValues()) {
    std::vector<std::uint32_t> bits;
    for (std::size_t i = 0; i < cloud.core.size(); ++i)
      if (cloud.core[i]) {
        const float v = i < extra->size() ? (*extra)[i] : 0.0f;
        std::uint32_t b;
        std::memcpy (&b, &v, sizeof (b));
        bits.push_back (b);
      }
    if (!tiling::TileResults::write (workdir, core_indices, bits, kExtraValues))
      return false;
  }
  if (method.getKind() == tiling::MergedResults::Kind::Segments &&
      (!tiling::saveHaloLabels (workdir, tile, halo) ||
       !tiling::saveSegmentSizes (workdir, tile, segmentSizes (cloud, labels))))
    return false;
  if (!tiling::markTileDone (workdir, tile))
    return false;
  const double ms = timer.done (cloud.core_points);
  std::cout << "  " << cloud.indices.size() - cloud.core_points << " halo points"
            << (cloud.margin > plan.halo
                    ? ", margin widened to " + std::to_string (cloud.margin) + " m"
                    : "")
            << ", "
            << static_cast<long long> (cloud.core_points / std::max (ms, 1.0) * 1e3)
            << " points/s\n";
  return true;
}

void
reportTilesNotDone (const std::string& workdir,
                    const std::vector<std::size_t>& missing,
                    const std::string& pass)
{
  const std::string step = stepOfPass (pass);
  std::cerr << "Error: " << missing.size() << " tile(s) of " << workdir
            << (pass == kRefined ? " have not run their second pass ('refine') or did "
                                   "not finish it:"
                : pass == kGrown ? " have not grouped their points left out ('grow') "
                                   "or did not finish:"
                                 : " have not run or did not finish:");
  for (std::size_t i = 0; i < missing.size() && i < 20; ++i)
    std::cerr << " " << missing[i];
  std::cerr << (missing.size() > 20 ? " ..." : "") << ".\n";
  std::size_t named = 0;
  for (const std::size_t t : missing) {
    const std::string start = tiling::describeTileStart (workdir, t);
    if (!start.empty() && named++ < 20)
      std::cerr << "  tile " << t << " was started by " << start
                << " and did not finish (the process stopped or died)\n";
  }
  std::cerr << "Run 'pcl_ext_tiles " << step << " I -workdir " << workdir
            << "' for each, then merge again; or 'pcl_ext_tiles resume OUTPUT -workdir "
            << workdir << "' (under mpirun too) runs them all and merges.\n";
}

bool
mergeStep (const tiling::TilePlan& plan,
           TileMethod& method,
           ResultField& field,
           const std::string& workdir,
           const std::string& output)
{
  for (const std::string& p : passesOf (method)) {
    const auto missing = tiling::findTilesNotDone (workdir, plan.getGrid().size(), p);
    if (!missing.empty()) {
      reportTilesNotDone (workdir, missing, p);
      return false;
    }
  }
  // What the second pass made besides the segments first, as the untiled tools write
  // it: a failure there leaves no output.
  const bool refined = method.needsRefine();
  if (refined &&
      !method.mergeRefineOutputs (workdir, plan.getGrid().size(), plan.origin))
    return false;
  const bool segments = method.getKind() == tiling::MergedResults::Kind::Segments;
  // After a second pass the segments are numbered over the whole cloud already.
  const auto kind = refined ? tiling::MergedResults::Kind::PerPoint : method.getKind();
  const std::uint64_t min_size = refined ? 0 : method.getMinSegmentSize();
  MergeReading reading;
  reading.kind = kind;
  reading.segments = segments;
  reading.min_size = segments ? min_size : 0;
  if (refined)
    reading.results_name = kRefined;
  if (method.needsGrow()) {
    // New segments grown among the points left out, numbered after the others.
    std::uint32_t joined = 0;
    if (!loadJoinedSegmentCount (workdir, joined))
      return false;
    reading.grown = true;
    reading.grown_first_id = joined;
    reading.grown_min_size = std::max<std::uint64_t> (method.getMinSegmentSize(), 1);
  }
  reading.extra_field = method.getExtraFieldName();
  reading.to_asprs = [&method] (std::vector<std::uint32_t>& codes) {
    return method.toAsprs (codes);
  };
  return writeMergedOutput (plan, field, workdir, output, reading);
}

} // namespace apps
} // namespace pcl_ext
