/*
 * pcl_ext: montages of segmentations.
 */
#include <pcl_ext/visualization/montage.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace pcl_ext {
namespace visualization {
RenderOptions
makeMontageOptions (std::size_t tiles, int tile_width, int tile_height, int max_columns)
{
  const int n = static_cast<int> (std::clamp<std::size_t> (tiles, 1, 1024));
  const int columns = std::min (n, std::max (1, max_columns));
  const int rows = (n + columns - 1) / columns;
  RenderOptions options;
  options.columns = columns;
  options.width = std::clamp (tile_width, 16, 16384 / columns) * columns;
  options.height = std::clamp (tile_height, 16, 16384 / rows) * rows;
  return options;
}

std::vector<std::uint32_t>
matchLabelsToReference (const std::vector<std::uint32_t>& labels,
                        const std::vector<std::uint32_t>& reference)
{
  if (labels.size() != reference.size())
    return labels;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> shared;
  std::uint32_t top = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    top = std::max (top, reference[i]);
    if (labels[i] != 0 && reference[i] != 0)
      ++shared[{labels[i], reference[i]}];
  }
  // (count, segment, reference): most shared first; ties by the smaller labels.
  std::vector<std::tuple<std::size_t, std::uint32_t, std::uint32_t>> pairs;
  for (const auto& [key, count] : shared)
    pairs.emplace_back (count, key.first, key.second);
  std::sort (pairs.begin(), pairs.end(), [] (const auto& a, const auto& b) {
    if (std::get<0> (a) != std::get<0> (b))
      return std::get<0> (a) > std::get<0> (b);
    return std::make_pair (std::get<1> (a), std::get<2> (a)) <
           std::make_pair (std::get<1> (b), std::get<2> (b));
  });
  std::map<std::uint32_t, std::uint32_t> to;
  std::map<std::uint32_t, bool> taken;
  for (const auto& [count, segment, ref] : pairs)
    if (!to.count (segment) && !taken[ref]) {
      to[segment] = ref;
      taken[ref] = true;
    }
  std::vector<std::uint32_t> out (labels.size(), 0);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == 0)
      continue;
    auto found = to.find (labels[i]);
    if (found == to.end())
      found = to.emplace (labels[i], ++top).first;
    out[i] = found->second;
  }
  return out;
}
} // namespace visualization
} // namespace pcl_ext
