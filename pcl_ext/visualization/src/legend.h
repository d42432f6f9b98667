/*
 * pcl_ext: legends and colour bars drawn at the right of a panel (private to the
 * renderer).
 */
#pragma once

#include <pcl_ext/visualization/offscreen_renderer.h>

class vtkRenderer;

namespace pcl_ext {
namespace visualization {
/** Width in pixels of the column at the right of a panel that \a view's legend and
 * colour bar need (0 when it has neither), at most two fifths of \a panel_width; \a
 * font is set to the font size they are written in, small enough for every legend line
 * to fit \a free_height. */
int
legendWidth (const View& view, int panel_width, int free_height, int& font);

/** Draws \a view's legend (a swatch and a name per line) and colour bar (the map from
 * bottom to top, its name above, min and max beside) into \a renderer's viewport, in
 * the column of \a width pixels starting at \a x, from \a top (pixels from the
 * viewport's bottom) down. \a text is the grey level (0 or 1) of the text. */
void
drawLegend (vtkRenderer& renderer,
            const View& view,
            int x,
            int top,
            int width,
            int font,
            double text);
} // namespace visualization
} // namespace pcl_ext
