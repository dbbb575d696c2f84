#include "analysis/plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dsr {

namespace {

// 5x7 glyphs, one string of 35 cells per character, rows top to bottom.
struct Glyph {
    char c;
    const char* rows;
};
const Glyph kFont[] = {
    {'A', ".###.#...##...#######...##...##...#"}, {'B', "####.#...##...#####.#...##...#####."},
    {'C', ".###.#...##....#....#....#...#.###."}, {'D', "####.#...##...##...##...##...#####."},
    {'E', "######....#....####.#....#....#####"}, {'F', "######....#....####.#....#....#...."},
    {'G', ".###.#...##....#.####...##...#.####"}, {'H', "#...##...##...#######...##...##...#"},
    {'I', ".###...#....#....#....#....#...###."}, {'J', "..###...#....#....#....#.#..#..##.."},
    {'K', "#...##..#.#.#..##...#.#..#..#.#...#"}, {'L', "#....#....#....#....#....#....#####"},
    {'M', "#...###.###.#.##.#.##...##...##...#"}, {'N', "#...##...###..##.#.##..###...##...#"},
    {'O', ".###.#...##...##...##...##...#.###."}, {'P', "####.#...##...#####.#....#....#...."},
    {'Q', ".###.#...##...##...##.#.##..#..##.#"}, {'R', "####.#...##...#####.#.#..#..#.#...#"},
    {'S', ".#####....#.....###.....#....#####."}, {'T', "#####..#....#....#....#....#....#.."},
    {'U', "#...##...##...##...##...##...#.###."}, {'V', "#...##...##...##...##...#.#.#...#.."},
    {'W', "#...##...##...##.#.##.#.##.#.#.#.#."}, {'X', "#...##...#.#.#...#...#.#.#...##...#"},
    {'Y', "#...##...#.#.#...#....#....#....#.."}, {'Z', "#####....#...#...#...#...#....#####"},
    {'0', ".###.#...##..###.#.###..##...#.###."}, {'1', "..#...##....#....#....#....#...###."},
    {'2', ".###.#...#....#...#...#...#...#####"}, {'3', "#####...#...#.....#.....##...#.###."},
    {'4', "...#...##..#.#.#..#.#####...#....#."}, {'5', "######....####.....#....##...#.###."},
    {'6', "..##..#...#....####.#...##...#.###."}, {'7', "#####....#...#...#...#....#....#..."},
    {'8', ".###.#...##...#.###.#...##...#.###."}, {'9', ".###.#...##...#.####....#...#..##.."},
    {'.', "..........................##...##.."}, {'-', "...............#####..............."},
    {'(', "...#...#...#....#....#.....#.....#."}, {')', ".#.....#.....#....#....#...#...#..."},
    {'/', ".........#...#...#...#...#........."}, {':', "......##...##.........##...##......"},
    {' ', "..................................."},
};

const char* glyph(char c) {
    c = char(std::toupper(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont)
        if (g.c == c) return g.rows;
    return nullptr;
}

// Top-down pixel writes; the image stores the bottom row first.
void put(Image& img, int x, int y, glm::vec3 c) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    float* p = img.at(x, img.height - 1 - y);
    p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 1.0f;
}

void hline(Image& img, int x0, int x1, int y, glm::vec3 c) {
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) put(img, x, y, c);
}
void vline(Image& img, int x, int y0, int y1, glm::vec3 c) {
    for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y) put(img, x, y, c);
}

void marker(Image& img, int cx, int cy, int r, glm::vec3 c, bool ring) {
    for (int dy = -r - 1; dy <= r + 1; ++dy)
        for (int dx = -r - 1; dx <= r + 1; ++dx) {
            const double d = std::sqrt(double(dx * dx + dy * dy));
            if (d <= r + 0.5 && (!ring || d >= r - 0.7)) put(img, cx + dx, cy + dy, c);
            else if (!ring && d <= r + 1.2) put(img, cx + dx, cy + dy, c * 0.5f);  // dark rim: overlaps stay legible
        }
}

std::string decade_label(int e) {
    if (e >= 0) return "1" + std::string(size_t(e), '0');
    return "0." + std::string(size_t(-e - 1), '0') + "1";
}

int text_width(const std::string& s, int scale) { return int(s.size()) * 6 * scale - scale; }

}  // namespace

int draw_text(Image& img, int x, int y, const std::string& text, glm::vec3 color, int scale) {
    int cx = x;
    for (char ch : text) {
        const char* g = glyph(ch);
        for (int r = 0; r < 7; ++r)
            for (int col = 0; col < 5; ++col) {
                const bool on = g ? g[r * 5 + col] == '#' : (r == 0 || r == 6 || col == 0 || col == 4);
                if (!on) continue;
                for (int sy = 0; sy < scale; ++sy)
                    for (int sx = 0; sx < scale; ++sx) put(img, cx + col * scale + sx, y + r * scale + sy, color);
            }
        cx += 6 * scale;
    }
    return cx - x - scale;
}

Image scatter_plot(const std::vector<PlotPanel>& panels, int panel_w, int panel_h) {
    Image img;
    img.width = panel_w * int(std::max<size_t>(panels.size(), 1));
    img.height = panel_h;
    img.rgba.assign(size_t(img.width) * img.height * 4, 1.0f);
    const glm::vec3 black(0.0f), grey(0.85f), dark(0.35f);
    for (size_t pi = 0; pi < panels.size(); ++pi) {
        const PlotPanel& panel = panels[pi];
        const int ox = int(pi) * panel_w;
        // Plot area inside the panel: room for tick labels left and below, title above.
        // Below the axis: its label, then the legend, a line per series (room for 3 at least).
        const int legend = int(std::max<size_t>(panel.series.size(), 3));
        const int left = ox + 62, right = ox + panel_w - 16, top = 40, bottom = panel_h - 44 - 12 * legend;
        double xmin = std::numeric_limits<double>::infinity(), xmax = 0, ymin = xmin, ymax = 0;
        for (const PlotSeries& s : panel.series)
            for (const PlotPoint& p : s.points) {
                if (p.x > 0) xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
                if (p.x > 0 && p.y > 0 && p.y >= panel.y_floor) ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
            }
        if (!(xmax > 0)) xmin = 1, xmax = 10;
        if (!(ymax > 0)) ymin = 0.1, ymax = 1;
        if (panel.y_floor > 0) ymin = std::min(ymin, panel.y_floor), ymax = std::max(ymax, panel.y_floor);
        const int ex0 = int(std::floor(std::log10(xmin))), ex1 = std::max(ex0 + 1, int(std::ceil(std::log10(xmax))));
        const int ey0 = int(std::floor(std::log10(ymin))), ey1 = std::max(ey0 + 1, int(std::ceil(std::log10(ymax))));
        auto px = [&](double x) { return left + int(std::lround((std::log10(x) - ex0) / (ex1 - ex0) * (right - left))); };
        auto py = [&](double y) { return bottom - int(std::lround((std::log10(y) - ey0) / (ey1 - ey0) * (bottom - top))); };

        // Grid at decades, minor ticks at 2..9.
        for (int e = ex0; e <= ex1; ++e) {
            const int x = px(std::pow(10.0, e));
            if (e > ex0 && e < ex1) vline(img, x, top, bottom, grey);
            vline(img, x, bottom, bottom + 6, black);
            const std::string l = decade_label(e);
            draw_text(img, x - text_width(l, 1) / 2, bottom + 10, l, black);
            if (e < ex1)
                for (int m = 2; m < 10; ++m) vline(img, px(m * std::pow(10.0, e)), bottom, bottom + 3, black);
        }
        for (int e = ey0; e <= ey1; ++e) {
            const int y = py(std::pow(10.0, e));
            if (e > ey0 && e < ey1) hline(img, left, right, y, grey);
            hline(img, left - 6, left, y, black);
            const std::string l = decade_label(e);
            draw_text(img, left - 9 - text_width(l, 1), y - 3, l, black);
            if (e < ey1)
                for (int m = 2; m < 10; ++m) hline(img, left - 3, left, py(m * std::pow(10.0, e)), black);
        }
        vline(img, left, top, bottom, black);
        hline(img, left, right, bottom, black);
        draw_text(img, ox + (panel_w - text_width(panel.title, 1)) / 2, 8, panel.title, black);
        draw_text(img, left, top - 12, panel.y_label, dark);
        draw_text(img, (left + right - text_width(panel.x_label, 1)) / 2, bottom + 22, panel.x_label, dark);

        for (const PlotSeries& s : panel.series)
            for (const PlotPoint& p : s.points) {
                if (!(p.x > 0)) continue;
                const bool ring = !(p.y > 0 && p.y >= panel.y_floor);
                const int x = px(p.x), y = ring ? bottom : py(p.y);
                marker(img, x, y, p.radius, s.color, ring);
                // Above and right of the dot, in the series' colour darkened so thin strokes read.
                if (!p.label.empty()) draw_text(img, x + p.radius + 2, y - p.radius - 8, p.label, s.color * 0.7f);
            }
        // Legend below the axis label: one line per series.
        int ly = bottom + 36;
        for (const PlotSeries& s : panel.series) {
            marker(img, left + 4, ly + 3, 3, s.color, false);
            draw_text(img, left + 14, ly, s.label, black);
            ly += 12;
        }
        if (pi + 1 < panels.size()) vline(img, ox + panel_w - 1, 0, panel_h - 1, grey);
    }
    return img;
}

}  // namespace dsr
