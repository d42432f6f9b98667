/*
 * pcl_ext_tiles: the output of a run, every input point with its merged result.
 */
#include "merge_output.h"
#include "input_fields.h"
#include "second_pass_steps.h"
#include "tile_outputs.h"
#include "tile_steps.h"

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/cloud_fields.h>
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/io/las_writer.h>
#include <pcl_ext/tiling/point_file_chunks.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <cstring>
#include <iostream>

namespace pcl_ext {
namespace apps {
namespace {

/** The method's float per point (TileMethod::getExtraValues) of the \a chunk's points,
 * the first of them at global index \a first, into its field \a name (0 for a point no
 * tile holds: not finite). */
bool
attachExtraValues (const std::string& workdir,
                   std::uint64_t first,
                   const std::string& name,
                   pcl::PCLPointCloud2& chunk)
{
  std::vector<std::uint32_t> bits;
  const std::size_t n = static_cast<std::size_t> (chunk.width) * chunk.height;
  if (!tiling::TileResults::read (workdir, first, n, bits, kExtraValues))
    return false;
  std::vector<float> values (n, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
    if (bits[i] != tiling::TileResults::kNoResult)
      std::memcpy (&values[i], &bits[i], sizeof (float));
  if (!io::setFloatField (chunk, name, values)) {
    std::cerr << "\nError: cannot write the field '" << name << "'.\n";
    return false;
  }
  return true;
}

} // namespace

bool
writeMergedOutput (const tiling::TilePlan& plan,
                   ResultField& field,
                   const std::string& workdir,
                   const std::string& output,
                   const MergeReading& reading)
{
  StageTimer timer ("Merging into " + output);
  const bool segments = reading.segments;
  const bool las = io::fileExtension (output) == "las";
  const bool per_tile = TileOutputs::isPattern (output);
  if (per_tile && !las) {
    std::cerr << "\nError: one file per tile ('#' in " << output
              << ") is written as LAS: name it .las.\n";
    return false;
  }
  try {
    tiling::PointFileChunks first;
    first.open (plan.inputs.front());
    io::PointFile like = first.getDescription();
    like.origin = plan.origin;
    // Inputs with different fields: every field in the output.
    pcl::PCLPointCloud2 layout, conformed;
    if (!unionOfInputFields (plan.inputs, layout))
      return false;
    like.cloud.fields = layout.fields;
    if (!field.checkInput (like, plan.inputs.front()))
      return false;
    const std::uint64_t min_size = reading.min_size;
    const std::string& extra_field = reading.extra_field;
    const tiling::TileGrid grid = plan.getGrid();
    const io::LasFileInfo* like_las = like.las ? &*like.las : nullptr;
    TileOutputs tile_outputs (output, grid, plan.origin, like_las);
    io::LasWriter writer;
    pcl::PCLPointCloud2 chunk, whole;
    std::vector<std::uint32_t> values, codes;
    std::uint64_t points = 0;
    // One file per tile: a pass over the inputs for as many tiles as files may be
    // open at once (all of them, mostly).
    const std::size_t tiles_per_pass = per_tile
                                           ? TileOutputs::openFilesAllowed()
                                           : std::max<std::size_t> (grid.size(), 1);
    for (std::size_t pass_first = 0;
         pass_first < std::max<std::size_t> (grid.size(), 1);
         pass_first += tiles_per_pass) {
      tiling::MergedResults merged;
      if (reading.kind == tiling::MergedResults::Kind::Segments && min_size > 0)
        merged.setSegmentsBySize (min_size);
      merged.setResultsName (reading.results_name);
      if (reading.grown)
        merged.setGrownSegments (tiling::SegmentPassFiles::named (kGrown),
                                 reading.grown_min_size,
                                 reading.grown_first_id);
      if (!merged.open (plan, workdir, reading.kind))
        return false;
      if (reading.kind == tiling::MergedResults::Kind::Segments && min_size > 0 &&
          merged.getNumberOfSegments() == 0) {
        std::cerr << "\nError: no segment of at least " << min_size << " points.\n";
        return false;
      }
      std::size_t input = 0;
      bool opened = false;
      while (merged.read (kChunkPoints, chunk, input, values) > 0) {
        for (auto& v : values)
          v = v == tiling::TileResults::kNoResult ? 0u : (segments ? v + 1 : v);
        if (!hasLayout (chunk, layout)) {
          io::conformToFields (chunk, layout, conformed);
          chunk = std::move (conformed);
        }
        if (!field.attach (chunk, values) ||
            (!extra_field.empty() &&
             !attachExtraValues (
                 workdir, merged.getNextIndex() - values.size(), extra_field, chunk)))
          return false;
        if (field.asprs()) {
          codes = values;
          if (!reading.to_asprs || !reading.to_asprs (codes) ||
              !io::setLabelField (chunk, "classification", codes))
            return false;
        }
        if (per_tile) {
          if (!tile_outputs.write (chunk, pass_first, pass_first + tiles_per_pass))
            return false;
        }
        else if (las) {
          if (!opened && !writer.open (output, chunk, plan.origin, like_las))
            return false;
          opened = true;
          if (!writer.write (chunk))
            return false;
        }
        else if (whole.data.empty())
          whole = chunk;
        else if (!pcl::PCLPointCloud2::concatenate (whole, chunk)) {
          std::cerr << "\nError: the chunks of " << plan.inputs[input]
                    << " cannot be joined to the output.\n";
          return false;
        }
        if (pass_first == 0)
          points += values.size();
      }
      if (merged.failed() || (per_tile && !tile_outputs.finishPass()))
        return false;
    }
    if (per_tile ? !tile_outputs.close()
        : las    ? !writer.close()
                 : !io::savePointFile (output, whole, plan.origin, &like))
      return false;
    timer.done (points);
    if (per_tile) {
      std::cout << "  " << tile_outputs.getNumberOfFiles() << " files, index "
                << TileOutputs::indexPathOf (output);
      if (tile_outputs.getPointsInNoTile() > 0)
        std::cout << "; " << tile_outputs.getPointsInNoTile()
                  << " points without finite coordinates are in no tile's file";
      std::cout << "\n";
    }
  }
  catch (const std::exception& e) {
    std::cerr << "\nError: " << e.what() << "\n";
    return false;
  }
  return true;
}
} // namespace apps
} // namespace pcl_ext
