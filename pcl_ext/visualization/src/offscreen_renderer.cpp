/*
 * pcl_ext: headless rendering of coloured clouds to PNG.
 */
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/visualization/pcl_visualizer.h>

#include "legend.h"

#include <vtkCamera.h>
#include <vtkPNGWriter.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

namespace pcl_ext {
namespace visualization {
namespace {
/** Font size (pixels) at which every line of \a title fits a panel of the given size:
 * at most 22 and a 22nd of the panel height, smaller for long lines (VTK's default
 * Arial: a character is at most about 0.6 of the font size wide on average), never
 * below 8. */
int
titleFontSize (const std::string& title, int panel_width, int panel_height, int& lines)
{
  std::size_t longest = 0, line = 0;
  lines = 1;
  for (const char c : title)
    if (c == '\n') {
      ++lines;
      line = 0;
    }
    else
      longest = std::max (longest, ++line);
  int font = std::min (22, panel_height / 22);
  if (longest > 0)
    font = std::min (font,
                     static_cast<int> ((panel_width - 16) / (0.6 * double (longest))));
  return std::max (8, font);
}

/** The finite points of every layer of every view no higher than \a max_height along
 * \a up, each layer's cloud replaced by its points kept (when any is left out). */
std::vector<View>
clipViews (const std::vector<View>& views, const Eigen::Vector3d& up, double max_height)
{
  std::vector<View> clipped = views;
  if (!(max_height < std::numeric_limits<double>::infinity()))
    return clipped;
  for (auto& view : clipped)
    for (auto& layer : view.layers) {
      if (!layer.cloud)
        continue;
      pcl::PointCloud<pcl::PointXYZRGB>::Ptr kept (
          new pcl::PointCloud<pcl::PointXYZRGB>);
      for (const auto& p : *layer.cloud)
        if (pcl::isFinite (p) && Eigen::Vector3d (p.x, p.y, p.z).dot (up) <= max_height)
          kept->push_back (p);
      layer.cloud = kept;
    }
  return clipped;
}

/** Up to \a most finite points spread evenly over every layer of every view. */
std::vector<Eigen::Vector3d>
samplePoints (const std::vector<View>& views, std::size_t most)
{
  std::size_t total = 0;
  for (const auto& view : views)
    for (const auto& layer : view.layers)
      if (layer.cloud)
        total += layer.cloud->size();
  const std::size_t stride = std::max<std::size_t> (1, (total + most - 1) / most);
  std::vector<Eigen::Vector3d> points;
  std::size_t i = 0;
  for (const auto& view : views)
    for (const auto& layer : view.layers)
      if (layer.cloud)
        for (const auto& p : *layer.cloud)
          if (i++ % stride == 0 && pcl::isFinite (p))
            points.emplace_back (p.x, p.y, p.z);
  return points;
}

/** Whether \a sensor lies outside the horizontal bounds of \a points (a camera looking
 * at a scene rather than a scanner standing inside it). */
bool
sensorOutside (const std::vector<Eigen::Vector3d>& points,
               const Eigen::Vector3d& sensor,
               const Eigen::Vector3d& up)
{
  if (!sensor.allFinite() || points.empty())
    return false;
  const Eigen::Vector3d u = up.normalized();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant (std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const auto& p : points) {
    const Eigen::Vector3d q = p - p.dot (u) * u;
    lo = lo.cwiseMin (q);
    hi = hi.cwiseMax (q);
  }
  const Eigen::Vector3d s = sensor - sensor.dot (u) * u;
  return (s.array() < lo.array()).any() || (s.array() > hi.array()).any();
}
} // namespace

bool
renderToPng (const std::vector<View>& views,
             const std::string& path,
             const RenderOptions& options)
{
  if (views.empty()) {
    PCL_ERROR ("[pcl_ext::visualization::renderToPng] nothing to render into %s.\n",
               path.c_str());
    return false;
  }
  if (options.width < 16 || options.height < 16 || options.width > 16384 ||
      options.height > 16384) {
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] image size %d x %d is out of range "
        "(16 .. 16384).\n",
        static_cast<int> (options.width),
        static_cast<int> (options.height));
    return false;
  }
  if (!options.view_direction.allFinite() || !(options.up.norm() > 0.0) ||
      !options.up.allFinite() || !(options.margin >= 0.0 && options.margin < 0.45)) {
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] invalid camera settings for %s.\n",
        path.c_str());
    return false;
  }
  const Eigen::Vector3d up = options.up.normalized();
  double max_height = options.max_height;
  if (std::isnan (max_height))
    max_height = estimateCeilingHeight (samplePoints (views, 200000), up);
  const std::vector<View> shown = clipViews (views, up, max_height);
  const std::vector<Eigen::Vector3d> points = samplePoints (shown, 200000);
  if (points.empty()) {
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] no finite point to render into %s.\n",
        path.c_str());
    return false;
  }
  if (!displayAvailable()) {
    const char* display = std::getenv ("DISPLAY");
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] rendering %s needs an X display (VTK "
        "here is built for X only) and none can be opened (DISPLAY=%s); on a headless "
        "machine run under Xvfb, e.g. 'xvfb-run -a <command>'.\n",
        path.c_str(),
        display ? display : "");
    return false;
  }
  if (!io::checkWritable (path))
    return false;

  // A visualizer without an interactor: never spin() and never saveScreenshot() here
  // (both need the interactor); read the frame buffer through vtkWindowToImageFilter
  // instead.
  pcl::visualization::PCLVisualizer viewer ("pcl_ext offscreen", false);
  viewer.getRenderWindow()->SetOffScreenRendering (1);
  viewer.getRenderWindow()->SetSize (options.width, options.height);

  const int n = static_cast<int> (shown.size());
  const int cols = options.columns > 0
                       ? std::min (options.columns, n)
                       : static_cast<int> (std::ceil (std::sqrt (double (n))));
  const int rows = (n + cols - 1) / cols;
  const int panel_height = options.height / rows, panel_width = options.width / cols;

  // The camera: one for every panel, framed in the part of a panel that the title band
  // above and the legend column at the right leave free in every panel.
  ViewKind kind = options.view;
  if (kind == ViewKind::Auto)
    kind = sensorOutside (points, options.sensor, up) ? ViewKind::Sensor
                                                      : ViewKind::Oblique;
  const Eigen::Vector3d direction =
      options.view_direction.norm() > 0.0
          ? Eigen::Vector3d (options.view_direction.normalized())
          : viewDirection (points, kind, up, options.sensor);
  // Seen from straight above, the picture's top is the scene's +y (north).
  const Eigen::Vector3d camera_up =
      std::abs (direction.dot (up)) > 0.999
          ? Eigen::Vector3d (up.cross (Eigen::Vector3d::UnitX()))
          : up;
  std::vector<int> title_band (n, 0), title_font (n, 0), title_lines (n, 1),
      side (n, 0), side_font (n, 0);
  int top = 0, right = 0;
  for (int v = 0; v < n; ++v) {
    if (!shown[v].title.empty()) {
      title_font[v] =
          titleFontSize (shown[v].title, panel_width, panel_height, title_lines[v]);
      title_band[v] = title_lines[v] * (title_font[v] + title_font[v] / 6) + 14;
    }
    side[v] =
        legendWidth (shown[v], panel_width, panel_height - title_band[v], side_font[v]);
    top = std::max (top, title_band[v]);
    right = std::max (right, side[v]);
  }
  const int free_width = std::max (8, panel_width - right),
            free_height = std::max (8, panel_height - top);
  const Framing framing = frameRobustly (
      points, direction, camera_up, double (free_width) / free_height, options.margin);
  const double pixel = 2.0 * framing.half_width / free_width; // world units per pixel
  const Eigen::Vector3d right_axis = framing.direction.cross (framing.up);
  const Eigen::Vector3d focal = framing.centre + right_axis * (0.5 * right * pixel) +
                                framing.up * (0.5 * top * pixel);

  // The eye stands beyond every point (an orthographic camera clips what is behind it).
  double reach = 1.0;
  for (const auto& view : shown)
    for (const auto& layer : view.layers)
      if (layer.cloud)
        for (const auto& p : *layer.cloud)
          if (pcl::isFinite (p))
            reach = std::max (reach,
                              2.0 * (Eigen::Vector3d (p.x, p.y, p.z) - focal).norm());

  const double bg[3] = {options.background[0] / 255.0,
                        options.background[1] / 255.0,
                        options.background[2] / 255.0};
  const double text = (bg[0] + bg[1] + bg[2]) / 3.0 > 0.5 ? 0.0 : 1.0;
  // The window's own renderer shows through where no panel is (the end of an incomplete
  // last row): give it the background colour too.
  viewer.setBackgroundColor (bg[0], bg[1], bg[2]);

  std::map<const void*, double> spacing; // per cloud, estimated once
  for (int v = 0; v < n; ++v) {
    const int col = v % cols, row = v / cols;
    // VTK viewports are in normalised coordinates with y up; panel 0 is top left.
    const double x0 = double (col) / cols, x1 = double (col + 1) / cols;
    const double y1 = 1.0 - double (row) / rows, y0 = 1.0 - double (row + 1) / rows;
    int viewport = 0;
    viewer.createViewPort (x0, y0, x1, y1, viewport);
    viewer.setBackgroundColor (bg[0], bg[1], bg[2], viewport);
    for (std::size_t l = 0; l < shown[v].layers.size(); ++l) {
      const auto& layer = shown[v].layers[l];
      if (!layer.cloud || layer.cloud->empty())
        continue;
      double size = layer.point_size;
      if (!(size > 0.0)) {
        auto found = spacing.find (layer.cloud.get());
        if (found == spacing.end()) {
          std::vector<View> one (1);
          one[0].layers.push_back (layer);
          found = spacing
                      .emplace (layer.cloud.get(),
                                estimateSpacing (samplePoints (one, 1000000)))
                      .first;
        }
        size = std::isfinite (found->second)
                   ? std::clamp (1.5 * found->second / pixel, 2.0, 8.0)
                   : 2.0;
      }
      const std::string id = "v" + std::to_string (v) + "l" + std::to_string (l);
      pcl::visualization::PointCloudColorHandlerRGBField<pcl::PointXYZRGB> rgb (
          layer.cloud);
      viewer.addPointCloud<pcl::PointXYZRGB> (layer.cloud, rgb, id, viewport);
      viewer.setPointCloudRenderingProperties (
          pcl::visualization::PCL_VISUALIZER_POINT_SIZE, size, id, viewport);
    }
    auto* renderer = vtkRenderer::SafeDownCast (
        viewer.getRendererCollection()->GetItemAsObject (viewport));
    if (!shown[v].title.empty()) {
      // Titles are one line or several ('\n'), sized to stay inside their own panel: a
      // long one would otherwise run on under the next panel and be cut there.
      const int font = title_font[v], lines = title_lines[v];
      const int top_line = panel_height - font - 8;
      viewer.addText (shown[v].title,
                      8,
                      top_line - (lines - 1) * (font + font / 6),
                      font,
                      text,
                      text,
                      text,
                      "title" + std::to_string (v),
                      viewport);
    }
    drawLegend (*renderer,
                shown[v],
                panel_width - side[v],
                panel_height - title_band[v],
                side[v],
                side_font[v],
                text);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    const Eigen::Vector3d eye = focal - framing.direction * reach;
    camera->SetFocalPoint (focal.x(), focal.y(), focal.z());
    camera->SetPosition (eye.x(), eye.y(), eye.z());
    camera->SetViewUp (framing.up.x(), framing.up.y(), framing.up.z());
    camera->SetParallelScale (0.5 * panel_height * pixel);
    renderer->ResetCameraClippingRange();
  }
  viewer.getRenderWindow()->Render();

  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput (viewer.getRenderWindow());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  return io::writeFileAtomically (path, [&grab] (const std::string& temporary) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName (temporary.c_str());
    writer->SetInputConnection (grab->GetOutputPort());
    writer->Write();
    return writer->GetErrorCode() == 0;
  });
}
} // namespace visualization
} // namespace pcl_ext
