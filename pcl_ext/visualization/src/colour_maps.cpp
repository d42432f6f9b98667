/*
 * pcl_ext: colour maps.
 */
#include <pcl_ext/visualization/colour_maps.h>
#include <pcl_ext/common/segment_colours.h>
#include <pcl_ext/point_types.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace pcl_ext {
namespace visualization {
namespace {
// Viridis at 9 stops (matplotlib's, rounded); linear in between.
constexpr std::array<std::array<float, 3>, 9> kViridis{{{0.267f, 0.005f, 0.329f},
                                                        {0.279f, 0.175f, 0.483f},
                                                        {0.230f, 0.322f, 0.546f},
                                                        {0.173f, 0.449f, 0.558f},
                                                        {0.128f, 0.567f, 0.551f},
                                                        {0.153f, 0.680f, 0.504f},
                                                        {0.361f, 0.785f, 0.388f},
                                                        {0.667f, 0.862f, 0.196f},
                                                        {0.993f, 0.906f, 0.144f}}};
} // namespace

Colour
mapColour (float t, ColourMap map)
{
  if (!std::isfinite (t))
    return {70, 70, 70};
  t = std::clamp (t, 0.0f, 1.0f);
  const auto byte = [] (float f) {
    return static_cast<std::uint8_t> (
        std::lround (std::clamp (f, 0.0f, 1.0f) * 255.0f));
  };
  switch (map) {
  case ColourMap::Grey:
    return {byte (t), byte (t), byte (t)};
  case ColourMap::Jet:
    return {byte (1.5f - std::abs (4.0f * t - 3.0f)),
            byte (1.5f - std::abs (4.0f * t - 2.0f)),
            byte (1.5f - std::abs (4.0f * t - 1.0f))};
  case ColourMap::Viridis:
  default: {
    const float s = t * (kViridis.size() - 1);
    const std::size_t i =
        std::min<std::size_t> (static_cast<std::size_t> (s), kViridis.size() - 2);
    const float f = s - static_cast<float> (i);
    return {byte (kViridis[i][0] * (1 - f) + kViridis[i + 1][0] * f),
            byte (kViridis[i][1] * (1 - f) + kViridis[i + 1][1] * f),
            byte (kViridis[i][2] * (1 - f) + kViridis[i + 1][2] * f)};
  }
  }
}

std::vector<Colour>
colourByLabel (const std::vector<std::uint32_t>& labels)
{
  std::vector<Colour> out (labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == 0) {
      out[i] = {170, 170, 170};
      continue;
    }
    // Label L is segment L - 1 of a segmenter's getColoredCloud
    // (pcl_ext::colourBySegment): the same palette everywhere.
    std::uint8_t rgb[3];
    segmentColour (labels[i] - 1, rgb);
    out[i] = {rgb[0], rgb[1], rgb[2]};
  }
  return out;
}

std::vector<Colour>
colourByClass (const std::vector<std::uint32_t>& classes)
{
  std::vector<Colour> out (classes.size());
  for (std::size_t i = 0; i < classes.size(); ++i)
    switch (static_cast<PointClass> (classes[i])) {
    case PointClass::Surface:
      out[i] = {60, 110, 230};
      break;
    case PointClass::Edge:
      out[i] = {225, 30, 30};
      break;
    case PointClass::Boundary:
      out[i] = {30, 175, 60};
      break;
    default:
      out[i] = {120, 120, 120};
      break;
    }
  return out;
}

std::vector<LegendEntry>
classLegend ()
{
  std::vector<LegendEntry> legend;
  const char* names[] = {"surface", "edge", "boundary", "unknown"};
  const std::vector<std::uint32_t> classes = {
      static_cast<std::uint32_t> (PointClass::Surface),
      static_cast<std::uint32_t> (PointClass::Edge),
      static_cast<std::uint32_t> (PointClass::Boundary),
      0u};
  const std::vector<Colour> colours = colourByClass (classes);
  for (std::size_t i = 0; i < classes.size(); ++i)
    legend.push_back ({names[i], colours[i]});
  return legend;
}

std::vector<Colour>
colourByScalar (const std::vector<float>& values, ColourMap map, float min, float max)
{
  if (!(min < max)) {
    std::vector<float> finite;
    finite.reserve (values.size());
    for (const float v : values)
      if (std::isfinite (v))
        finite.push_back (v);
    min = 0.0f;
    max = 1.0f;
    if (!finite.empty()) {
      const auto at = [&finite] (double q) {
        const std::size_t k = static_cast<std::size_t> (q * (finite.size() - 1));
        std::nth_element (finite.begin(), finite.begin() + k, finite.end());
        return finite[k];
      };
      min = at (0.02);
      max = at (0.98);
      if (!(min < max))
        max = min + 1.0f;
    }
  }
  std::vector<Colour> out (values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    out[i] = mapColour ((values[i] - min) / (max - min), map);
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite (values[i]))
      out[i] = {70, 70, 70};
  return out;
}
} // namespace visualization
} // namespace pcl_ext
