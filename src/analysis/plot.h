// Scatter plots drawn by our own code into a dsr::Image (write it with write_image as PNG):
// log-log axes with decade ticks and labels, a built-in 5x7 upper-case bitmap font, a legend.
// Used by `dsr bench` for run time against error; no plotting library, no GL.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/image.h"

namespace dsr {

struct PlotPoint {
    double x = 0, y = 0;
    int radius = 3;  // marker radius in pixels
    std::string label;  // drawn beside the marker (the font's characters); empty: none
};

struct PlotSeries {
    std::string label;  // shown in the legend (upper-cased; letters, digits, space, . - ( ) / :)
    glm::vec3 color{0};
    std::vector<PlotPoint> points;
};

// One panel: log10 axes spanning whole decades around the positive data. A point with y below
// y_floor (or y <= 0: an exact match) is drawn as a ring on the bottom axis, which then sits at
// y_floor's decade; one with x <= 0 is left out.
struct PlotPanel {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    double y_floor = 0;  // 0: no floor
};

// Panels side by side, each panel_w x panel_h pixels, white background. Row 0 = bottom, like
// every dsr::Image.
Image scatter_plot(const std::vector<PlotPanel>& panels, int panel_w, int panel_h);

// Draws `text` with the 5x7 font, `scale` pixels per font pixel, top-left at (x, y) in
// top-down pixel coordinates. Characters the font lacks are drawn as a box. Returns the width.
int draw_text(Image& img, int x, int y, const std::string& text, glm::vec3 color, int scale = 1);

}  // namespace dsr
