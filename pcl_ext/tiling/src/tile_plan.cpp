/*
 * pcl_ext: the plan of a tiled run (inputs, origin, tile grid, settings), kept as text
 * in its work folder.
 */
#include <pcl_ext/tiling/point_file_chunks.h>
#include <pcl_ext/tiling/tile_plan.h>
#include <pcl_ext/tiling/tile_points.h>

#include <pcl_ext/io/file_output.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>
#include <unordered_set>
#include <sstream>

#include <unistd.h>

namespace pcl_ext {
namespace tiling {
namespace {
constexpr const char* kPlanHeader = "pcl_ext tile plan 1";
/** How far a point may lie outside the box it was planned in: float rounding of local
 * coordinates and LAS header bounds rounded to the file's scale. */
constexpr double kBoxMargin = 0.01;
constexpr std::size_t kChunkPoints = 1 << 20;
/// Tiles that own points are allowed at least this many, however few the points.
constexpr std::uint64_t kMinTileLimit = 1000;

/** \a path made absolute (a relative one joined to the working folder), so that the
 * steps of a plan find its inputs from any working folder; as given where the working
 * folder cannot be read. */
std::string
absolutePath (const std::string& path)
{
  char cwd[PATH_MAX];
  if (path.empty() || path.front() == '/' || ::getcwd (cwd, sizeof (cwd)) == nullptr)
    return path;
  return std::string (cwd) + "/" + path;
}

std::string
number (double v)
{
  std::ostringstream s;
  s << std::setprecision (17) << v;
  return s.str();
}
} // namespace

std::uint64_t
TilePlan::getTotalPoints() const
{
  std::uint64_t n = 0;
  for (const auto c : counts)
    n += c;
  return n;
}

std::uint64_t
TilePlan::getFirstIndex (std::size_t input) const
{
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < input && i < counts.size(); ++i)
    n += counts[i];
  return n;
}

bool
saveTilePlan (const std::string& path, const TilePlan& plan)
{
  std::ostringstream s;
  s << kPlanHeader << "\n";
  s << "origin " << number (plan.origin.x()) << " " << number (plan.origin.y()) << " "
    << number (plan.origin.z()) << "\n";
  s << "box " << number (plan.min.x()) << " " << number (plan.min.y()) << " "
    << number (plan.max.x()) << " " << number (plan.max.y()) << "\n";
  s << "tile_size " << number (plan.tile_size) << "\n";
  s << "halo " << number (plan.halo) << "\n";
  for (std::size_t i = 0; i < plan.inputs.size(); ++i)
    s << "input " << plan.counts[i] << " " << plan.inputs[i] << "\n";
  for (const auto& [key, value] : plan.settings)
    s << "setting " << key << " " << value << "\n";
  return io::writeTextFile (path, s.str());
}

bool
loadTilePlan (const std::string& path, TilePlan& plan)
{
  plan = TilePlan();
  std::ifstream in (path);
  auto fail = [&path] (std::size_t line, const std::string& what) {
    PCL_ERROR ("[pcl_ext::tiling::loadTilePlan] %s:%zu: %s\n",
               path.c_str(),
               line,
               what.c_str());
    return false;
  };
  if (!in)
    return fail (0, "cannot open the plan (run the plan step first)");
  std::string line;
  std::size_t number_of_line = 1;
  if (!std::getline (in, line) || line != kPlanHeader)
    return fail (1, "not a tile plan");
  bool has_origin = false, has_box = false;
  while (std::getline (in, line)) {
    ++number_of_line;
    std::istringstream words (line);
    std::string key;
    words >> key;
    if (key == "origin")
      has_origin = static_cast<bool> (words >> plan.origin.x() >> plan.origin.y() >>
                                      plan.origin.z());
    else if (key == "box")
      has_box = static_cast<bool> (words >> plan.min.x() >> plan.min.y() >>
                                   plan.max.x() >> plan.max.y());
    else if (key == "tile_size") {
      if (!(words >> plan.tile_size))
        return fail (number_of_line, "bad tile size");
    }
    else if (key == "halo") {
      if (!(words >> plan.halo))
        return fail (number_of_line, "bad halo");
    }
    else if (key == "input") {
      std::uint64_t count;
      std::string name;
      if (!(words >> count) || !std::getline (words >> std::ws, name) || name.empty())
        return fail (number_of_line, "bad input line");
      plan.counts.push_back (count);
      plan.inputs.push_back (name);
    }
    else if (key == "setting") {
      std::string name, value;
      if (!(words >> name))
        return fail (number_of_line, "bad setting line");
      std::getline (words >> std::ws, value);
      plan.settings[name] = value;
    }
    else if (!key.empty())
      return fail (number_of_line, "unknown line '" + key + "'");
  }
  if (!has_origin || !has_box || plan.inputs.empty() || !plan.origin.allFinite() ||
      !plan.getGrid().isValid())
    return fail (number_of_line, "incomplete plan (origin, box, tiles or inputs)");
  return true;
}

bool
planTiles (const std::vector<std::string>& inputs,
           double tile_size,
           double halo,
           TilePlan& plan)
{
  plan = TilePlan();
  Eigen::Vector3d lo =
      Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    PointFileChunks file;
    file.open (inputs[i]);
    if (i == 0)
      plan.origin = file.getOrigin();
    Eigen::Vector3d a, b;
    file.getBounds (a, b);
    if (file.getPointCount() > 0 && (a.array() <= b.array()).all()) {
      lo = lo.cwiseMin (a);
      hi = hi.cwiseMax (b);
    }
    plan.inputs.push_back (absolutePath (inputs[i]));
    plan.counts.push_back (file.getPointCount());
  }
  if (!lo.allFinite() || !hi.allFinite()) {
    PCL_ERROR ("[pcl_ext::tiling::planTiles] the inputs hold no point with finite "
               "coordinates.\n");
    return false;
  }
  if ((hi - lo).maxCoeff() > 1e6 || (plan.origin - lo).cwiseAbs().maxCoeff() > 1e6) {
    PCL_ERROR ("[pcl_ext::tiling::planTiles] the inputs span more than 1000 km: files "
               "of different coordinate systems?\n");
    return false;
  }
  plan.min = lo.head<2>() - Eigen::Vector2d::Constant (kBoxMargin);
  plan.max = hi.head<2>() + Eigen::Vector2d::Constant (kBoxMargin);
  plan.tile_size = tile_size;
  plan.halo = halo;
  if (!plan.getGrid().isValid()) {
    PCL_ERROR ("[pcl_ext::tiling::planTiles] tile size %g and halo %g do not make a "
               "grid (the size must be > 0, the halo >= 0, at most 2^32 tiles).\n",
               tile_size,
               halo);
    return false;
  }
  return true;
}

double
suggestTileSize (const Eigen::Vector2d& min,
                 const Eigen::Vector2d& max,
                 std::uint64_t points,
                 std::uint64_t points_per_tile)
{
  const double area = std::max ((max - min).prod(), 1.0);
  const double tiles = std::max (
      1.0, static_cast<double> (points) / std::max<double> (points_per_tile, 1));
  const double raw = std::sqrt (area / tiles);
  const double decade = std::pow (10.0, std::floor (std::log10 (raw)));
  for (const double step : {1.0, 2.0, 5.0, 10.0})
    if (step * decade >= raw)
      return step * decade;
  return 10.0 * decade;
}

double
fitTileSize (const TilePlan& plan, std::uint64_t max_points_per_tile)
{
  const std::uint64_t points = plan.getTotalPoints();
  const double uniform =
      suggestTileSize (plan.min, plan.max, points, max_points_per_tile);
  // The cell: 1, 2 or 5 times a power of ten, at most a sixteenth of the uniform size.
  const double target = uniform / 16.0;
  double cell = std::pow (10.0, std::floor (std::log10 (target)));
  for (const double step : {2.0, 5.0})
    if (step * std::pow (10.0, std::floor (std::log10 (target))) <= target)
      cell = step * std::pow (10.0, std::floor (std::log10 (target)));
  // At most 2^26 cells (512 MB of counts); beyond, the uniform size.
  const double span = (plan.max - plan.min).maxCoeff();
  if (!(cell > 0.0) || !(span / cell < static_cast<double> (1 << 26)) ||
      !(std::abs (plan.min.x()) / cell < 1e15) ||
      !(std::abs (plan.min.y()) / cell < 1e15))
    return uniform;
  const auto first_x = static_cast<std::int64_t> (std::floor (plan.min.x() / cell));
  const auto first_y = static_cast<std::int64_t> (std::floor (plan.min.y() / cell));
  const auto columns =
      static_cast<std::int64_t> (std::floor (plan.max.x() / cell)) - first_x + 1;
  const auto rows =
      static_cast<std::int64_t> (std::floor (plan.max.y() / cell)) - first_y + 1;
  if (columns <= 0 || rows <= 0 || columns * rows > (1LL << 26))
    return uniform;
  std::vector<std::uint64_t> counts (static_cast<std::size_t> (columns * rows), 0);
  pcl::PCLPointCloud2 chunk;
  for (const auto& input : plan.inputs) {
    PointFileChunks file;
    file.open (input);
    file.setOrigin (plan.origin);
    std::size_t n;
    while ((n = file.read (kChunkPoints, chunk)) > 0) {
      const std::uint8_t* xyz = chunk.data.data() + xyzOffset (chunk);
      for (std::size_t i = 0; i < n; ++i) {
        float p[3];
        std::memcpy (p, xyz + i * chunk.point_step, sizeof (p));
        if (!std::isfinite (p[0]) || !std::isfinite (p[1]) || !std::isfinite (p[2]))
          continue;
        const auto cx = std::clamp<std::int64_t> (
            static_cast<std::int64_t> (std::floor ((plan.origin.x() + p[0]) / cell)) -
                first_x,
            0,
            columns - 1);
        const auto cy = std::clamp<std::int64_t> (
            static_cast<std::int64_t> (std::floor ((plan.origin.y() + p[1]) / cell)) -
                first_y,
            0,
            rows - 1);
        ++counts[static_cast<std::size_t> (cy * columns + cx)];
      }
    }
  }
  // A tile of m cells a side, laid on multiples of m cells (of the size), sums the
  // cells whose absolute index divided by m (rounded down) is the tile's.
  const auto floorDiv = [] (std::int64_t a, std::int64_t b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
  };
  std::int64_t best = 1;
  std::vector<std::uint64_t> tiles;
  for (std::int64_t m = 2; m <= 64; ++m) {
    const std::int64_t tx0 = floorDiv (first_x, m), ty0 = floorDiv (first_y, m);
    const std::int64_t tile_columns = floorDiv (first_x + columns - 1, m) - tx0 + 1;
    const std::int64_t tile_rows = floorDiv (first_y + rows - 1, m) - ty0 + 1;
    tiles.assign (static_cast<std::size_t> (tile_columns * tile_rows), 0);
    for (std::int64_t y = 0; y < rows; ++y)
      for (std::int64_t x = 0; x < columns; ++x)
        tiles[static_cast<std::size_t> ((floorDiv (first_y + y, m) - ty0) *
                                            tile_columns +
                                        floorDiv (first_x + x, m) - tx0)] +=
            counts[static_cast<std::size_t> (y * columns + x)];
    if (*std::max_element (tiles.begin(), tiles.end()) > max_points_per_tile)
      break;
    best = m;
  }
  return static_cast<double> (best) * cell;
}

bool
writeTiles (const TilePlan& plan,
            const std::string& folder,
            std::size_t attribute_count,
            const ChunkAttributes& attributes,
            NoiseSampleCut* sample_cut)
{
  const TileGrid grid = plan.getGrid();
  // A tile size far too small for the data (a cloud in millimetres, a typing error)
  // would write files for millions of tiles of a few points each: stop once the tiles
  // that own points would average fewer than a hundred.
  const std::size_t max_tiles = static_cast<std::size_t> (
      std::max<std::uint64_t> (kMinTileLimit, plan.getTotalPoints() / 100));
  std::unordered_set<std::size_t> owners;
  std::size_t last_owner = TileGrid::kNoTile;
  TilePointWriter writer (folder, grid.size(), 4096, attribute_count);
  std::vector<float> values;
  pcl::PCLPointCloud2 chunk;
  std::vector<std::size_t> near;
  std::uint64_t index = 0;
  for (std::size_t f = 0; f < plan.inputs.size(); ++f) {
    PointFileChunks file;
    file.open (plan.inputs[f]);
    if (file.getPointCount() != plan.counts[f]) {
      PCL_ERROR ("[pcl_ext::tiling::writeTiles] %s has %llu points, the plan %llu: it "
                 "changed since the plan.\n",
                 plan.inputs[f].c_str(),
                 static_cast<unsigned long long> (file.getPointCount()),
                 static_cast<unsigned long long> (plan.counts[f]));
      return false;
    }
    file.setOrigin (plan.origin);
    std::size_t n;
    while ((n = file.read (kChunkPoints, chunk)) > 0) {
      if (attribute_count > 0) {
        if (!attributes || !attributes (chunk, plan.inputs[f], values))
          return false;
        if (values.size() != n * attribute_count) {
          PCL_ERROR ("[pcl_ext::tiling::writeTiles] %s: %zu attribute values for %zu "
                     "points.\n",
                     plan.inputs[f].c_str(),
                     values.size(),
                     n);
          return false;
        }
      }
      const std::uint8_t* xyz = chunk.data.data() + xyzOffset (chunk);
      for (std::size_t i = 0; i < n; ++i, ++index) {
        TilePoint p;
        p.index = index;
        std::memcpy (&p.x, xyz + i * chunk.point_step, 3 * sizeof (float));
        if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
          continue;
        const double x = plan.origin.x() + p.x, y = plan.origin.y() + p.y;
        const std::size_t owner = grid.getTile (x, y);
        if (owner == TileGrid::kNoTile) {
          PCL_ERROR ("[pcl_ext::tiling::writeTiles] %s: point %llu (%.3f %.3f) lies "
                     "outside the box of the plan (a LAS header's bounding box that "
                     "lies, or a file changed since the plan).\n",
                     plan.inputs[f].c_str(),
                     static_cast<unsigned long long> (index - plan.getFirstIndex (f)),
                     x,
                     y);
          return false;
        }
        if (owner != last_owner) {
          last_owner = owner;
          if (owners.insert (owner).second && owners.size() > max_tiles) {
            PCL_ERROR (
                "[pcl_ext::tiling::writeTiles] tile size %g: more than %zu tiles "
                "hold points, fewer than a hundred of the %llu points each; "
                "give a larger tile size (0: fitted to the data).\n",
                plan.tile_size,
                max_tiles,
                static_cast<unsigned long long> (plan.getTotalPoints()));
            return false;
          }
        }
        p.owner = static_cast<std::uint32_t> (owner);
        if (sample_cut)
          sample_cut->add (noiseSampleKeyOf (p.x, p.y, p.z));
        grid.getTilesNear (x, y, near);
        const float* a = attribute_count > 0 ? &values[i * attribute_count] : nullptr;
        for (const std::size_t t : near)
          if (!writer.add (t, p, a))
            return false;
      }
    }
  }
  return writer.finish();
}
} // namespace tiling
} // namespace pcl_ext
