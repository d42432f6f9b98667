/*
 * pcl_ext: legends and colour bars drawn at the right of a panel.
 */
#include "legend.h"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cstdio>

namespace pcl_ext {
namespace visualization {
namespace {
/** Steps of the colour bar, and its height in legend lines. */
constexpr int kBarSteps = 64;
constexpr int kBarLines = 8;

std::string
formatValue (float value)
{
  char text[32];
  std::snprintf (text, sizeof text, "%.3g", double (value));
  return text;
}

/** Filled rectangles (x, y, width, height in viewport pixels), one colour each. */
void
addRectangles (vtkRenderer& renderer,
               const std::vector<std::array<double, 4>>& rectangles,
               const std::vector<Colour>& colours)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto polygons = vtkSmartPointer<vtkCellArray>::New();
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetNumberOfComponents (3);
  for (std::size_t i = 0; i < rectangles.size(); ++i) {
    const auto& r = rectangles[i];
    const vtkIdType first = points->GetNumberOfPoints();
    points->InsertNextPoint (r[0], r[1], 0.0);
    points->InsertNextPoint (r[0] + r[2], r[1], 0.0);
    points->InsertNextPoint (r[0] + r[2], r[1] + r[3], 0.0);
    points->InsertNextPoint (r[0], r[1] + r[3], 0.0);
    const vtkIdType corners[4] = {first, first + 1, first + 2, first + 3};
    polygons->InsertNextCell (4, corners);
    const unsigned char c[3] = {colours[i].r, colours[i].g, colours[i].b};
    rgb->InsertNextTypedTuple (c);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints (points);
  data->SetPolys (polygons);
  data->GetCellData()->SetScalars (rgb);
  auto coordinate = vtkSmartPointer<vtkCoordinate>::New();
  coordinate->SetCoordinateSystemToViewport();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData (data);
  mapper->SetTransformCoordinate (coordinate);
  mapper->ScalarVisibilityOn();
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper (mapper);
  renderer.AddActor2D (actor);
}

void
addText (vtkRenderer& renderer,
         const std::string& line,
         double x,
         double y,
         int font,
         double grey)
{
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput (line.c_str());
  actor->GetTextProperty()->SetFontSize (font);
  actor->GetTextProperty()->SetColor (grey, grey, grey);
  actor->SetPosition (x, y);
  renderer.AddActor2D (actor);
}
} // namespace

int
legendWidth (const View& view, int panel_width, int free_height, int& font)
{
  const bool bar = !view.colour_bar.name.empty();
  font = 0;
  if (view.legend.empty() && !bar)
    return 0;
  const int lines = static_cast<int> (view.legend.size()) + (bar ? kBarLines + 2 : 0);
  font = std::clamp (static_cast<int> ((free_height - 16) / (1.5 * lines)), 8, 15);
  // Characters: a swatch line is the swatch and the name; the bar's lines are its name,
  // and the bar with a value beside it.
  double chars = 0.0;
  for (const auto& entry : view.legend)
    chars = std::max (chars, 1.7 + double (entry.name.size()));
  if (bar) {
    chars = std::max (chars, double (view.colour_bar.name.size()));
    for (const float v : {view.colour_bar.min, view.colour_bar.max})
      chars = std::max (chars, 2.2 + double (formatValue (v).size()));
  }
  const int most = std::max (40, panel_width * 2 / 5);
  int width = static_cast<int> (24 + chars * 0.62 * font);
  if (width > most) {
    font = std::max (8, static_cast<int> (font * double (most - 24) / (width - 24)));
    width = most;
  }
  return width;
}

void
drawLegend (vtkRenderer& renderer,
            const View& view,
            int x,
            int top,
            int width,
            int font,
            double text)
{
  if (width <= 0 || font <= 0)
    return;
  (void)width;
  const int line = font * 3 / 2;
  double y = top - 8;
  std::vector<std::array<double, 4>> rectangles;
  std::vector<Colour> colours;
  for (const auto& entry : view.legend) {
    y -= line;
    // A dark rim first, so that a white or pale swatch shows on a white background.
    rectangles.push_back ({x + 7.0, y - 1.0, font + 2.0, font + 2.0});
    colours.push_back ({90, 90, 90});
    rectangles.push_back ({x + 8.0, y, double (font), double (font)});
    colours.push_back (entry.colour);
    addText (renderer, entry.name, x + 8.0 + font * 1.4, y, font, text);
  }
  const ColourBar& bar = view.colour_bar;
  if (!bar.name.empty()) {
    y -= 1.5 * line;
    addText (renderer, bar.name, x + 8.0, y, font, text);
    const double height = kBarLines * line, step = height / kBarSteps;
    const double bottom = y - 6.0 - height;
    for (int s = 0; s < kBarSteps; ++s) {
      rectangles.push_back ({x + 8.0, bottom + s * step, font * 1.2, step + 0.5});
      colours.push_back (mapColour ((s + 0.5f) / kBarSteps, bar.map));
    }
    addText (renderer,
             formatValue (bar.max),
             x + 12.0 + font * 1.2,
             bottom + height - font,
             font,
             text);
    addText (
        renderer, formatValue (bar.min), x + 12.0 + font * 1.2, bottom, font, text);
  }
  if (!rectangles.empty())
    addRectangles (renderer, rectangles, colours);
}
} // namespace visualization
} // namespace pcl_ext
