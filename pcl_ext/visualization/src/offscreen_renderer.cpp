/*
 * pcl_ext: headless rendering of coloured clouds to PNG.
 */
#include <pcl_ext/io/file_output.h>
#include <pcl_ext/visualization/offscreen_renderer.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace pcl_ext {
namespace visualization {
bool
displayAvailable ()
{
  const char* display = std::getenv ("DISPLAY");
  return display && *display;
}

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

/** Centre and radius of the bounding box of every finite point in every view. */
bool
sceneBounds (const std::vector<View>& views, Eigen::Vector3d& centre, double& radius)
{
  Eigen::Vector3d lo =
      Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  bool any = false;
  for (const auto& view : views)
    for (const auto& layer : view.layers)
      if (layer.cloud)
        for (const auto& p : *layer.cloud)
          if (pcl::isFinite (p)) {
            const Eigen::Vector3d q (p.x, p.y, p.z);
            lo = lo.cwiseMin (q);
            hi = hi.cwiseMax (q);
            any = true;
          }
  if (!any)
    return false;
  centre = 0.5 * (lo + hi);
  radius = std::max (0.5 * (hi - lo).norm(), 1e-6);
  return true;
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
  if (!(options.view_direction.norm() > 0.0) || !options.view_direction.allFinite() ||
      !(options.zoom_out > 0.0)) {
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] invalid camera settings for %s.\n",
        path.c_str());
    return false;
  }
  Eigen::Vector3d centre;
  double radius;
  if (!sceneBounds (views, centre, radius)) {
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] no finite point to render into %s.\n",
        path.c_str());
    return false;
  }
  if (!displayAvailable()) {
    PCL_ERROR (
        "[pcl_ext::visualization::renderToPng] rendering %s needs an X display (VTK "
        "here "
        "is built for X only); on a headless machine run under Xvfb, e.g. 'xvfb-run -a "
        "<command>'.\n",
        path.c_str());
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

  const int n = static_cast<int> (views.size());
  const int cols = options.columns > 0
                       ? std::min (options.columns, n)
                       : static_cast<int> (std::ceil (std::sqrt (double (n))));
  const int rows = (n + cols - 1) / cols;
  const Eigen::Vector3d dir = options.view_direction.normalized();
  // Fit the bounding sphere in the panel's smaller field of view.
  const Eigen::Vector3d eye = centre - dir * radius * options.zoom_out;
  const double bg[3] = {options.background[0] / 255.0,
                        options.background[1] / 255.0,
                        options.background[2] / 255.0};
  const double text = (bg[0] + bg[1] + bg[2]) / 3.0 > 0.5 ? 0.0 : 1.0;
  // The window's own renderer shows through where no panel is (the end of an incomplete
  // last row): give it the background colour too.
  viewer.setBackgroundColor (bg[0], bg[1], bg[2]);

  for (int v = 0; v < n; ++v) {
    const int col = v % cols, row = v / cols;
    // VTK viewports are in normalised coordinates with y up; panel 0 is top left.
    const double x0 = double (col) / cols, x1 = double (col + 1) / cols;
    const double y1 = 1.0 - double (row) / rows, y0 = 1.0 - double (row + 1) / rows;
    int viewport = 0;
    viewer.createViewPort (x0, y0, x1, y1, viewport);
    viewer.setBackgroundColor (bg[0], bg[1], bg[2], viewport);
    for (std::size_t l = 0; l < views[v].layers.size(); ++l) {
      const auto& layer = views[v].layers[l];
      if (!layer.cloud || layer.cloud->empty())
        continue;
      const std::string id = "v" + std::to_string (v) + "l" + std::to_string (l);
      pcl::visualization::PointCloudColorHandlerRGBField<pcl::PointXYZRGB> rgb (
          layer.cloud);
      viewer.addPointCloud<pcl::PointXYZRGB> (layer.cloud, rgb, id, viewport);
      viewer.setPointCloudRenderingProperties (
          pcl::visualization::PCL_VISUALIZER_POINT_SIZE,
          layer.point_size,
          id,
          viewport);
    }
    if (!views[v].title.empty()) {
      // Titles are one line or several ('\n'), sized to stay inside their own panel: a
      // long one would otherwise run on under the next panel and be cut there.
      const int panel_height = options.height / rows,
                panel_width = options.width / cols;
      int lines = 1;
      const int font = titleFontSize (views[v].title, panel_width, panel_height, lines);
      const int top_line = panel_height - font - 8;
      viewer.addText (views[v].title,
                      8,
                      top_line - (lines - 1) * (font + font / 6),
                      font,
                      text,
                      text,
                      text,
                      "title" + std::to_string (v),
                      viewport);
    }
    viewer.setCameraPosition (eye.x(),
                              eye.y(),
                              eye.z(),
                              centre.x(),
                              centre.y(),
                              centre.z(),
                              options.up.x(),
                              options.up.y(),
                              options.up.z(),
                              viewport);
    viewer.setCameraClipDistances (
        radius * 0.01, radius * (options.zoom_out + 4.0), viewport);
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
