// Procedural brick, stone-tile and metal-plate maps for the default scene (Figure 6 stand-ins).
// Each family: a periodic height field h(x, y) in [0, 1] (joints low), then
//   diffuse  = colour following the pattern and h,
//   normal   = normalize(-s*dh/dx, -s*dh/dy, 1) * 0.5 + 0.5 with wrapped central differences,
//   specular = grey, 0 in the joints.
// Bit-identical everywhere: noise comes from an integer hash, lattices wrap at the texture
// size, and the float work uses only + - * / sqrt and floor (no libm transcendentals, whose
// last bits differ between C libraries). Results are quantized to k/255 at the end, which
// also absorbs any last-bit differences from FMA contraction.
#include "scene/procedural_textures.h"

#include "scene/hash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

namespace dsr {

namespace {

constexpr int N = kProceduralTextureSize;

// Uniform in [0, 1) from two integers and a seed.
double rand01(int a, int b, uint32_t seed) {
    uint32_t h = hash32(uint32_t(a) * 0x9E3779B1U ^ hash32(uint32_t(b) + seed * 0x85EBCA77U));
    return double(h >> 8) * (1.0 / 16777216.0);
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

double smoothstep(double e0, double e1, double x) {
    double t = std::min(1.0, std::max(0.0, (x - e0) / (e1 - e0)));
    return t * t * (3 - 2 * t);
}

double mix(double a, double b, double t) { return a + (b - a) * t; }

// Value noise on a lattice of cx x cy cells over the whole texture, wrapping, so it tiles.
// x, y are pixel coordinates; result in [0, 1).
double value_noise(double x, double y, int cx, int cy, uint32_t seed) {
    const double fx = x * cx / N, fy = y * cy / N;
    const double x0f = std::floor(fx), y0f = std::floor(fy);
    const int x0 = int(x0f), y0 = int(y0f);
    const double tx = smoothstep(0, 1, fx - x0f), ty = smoothstep(0, 1, fy - y0f);
    auto r = [&](int i, int j) { return rand01(wrap(i, cx), wrap(j, cy), seed); };
    return mix(mix(r(x0, y0), r(x0 + 1, y0), tx), mix(r(x0, y0 + 1), r(x0 + 1, y0 + 1), tx), ty);
}

// Fractal sum of octaves, cells doubling from (cx, cy); result roughly in [0, 1).
double fbm(double x, double y, int cx, int cy, int octaves, uint32_t seed) {
    double sum = 0, amp = 0.5, total = 0;
    for (int o = 0; o < octaves; ++o) {
        sum += amp * value_noise(x, y, cx << o, cy << o, seed + uint32_t(o) * 101U);
        total += amp;
        amp *= 0.5;
    }
    return sum / total;
}

double quantize(double v) { return std::floor(std::min(1.0, std::max(0.0, v)) * 255.0 + 0.5) / 255.0; }

Image blank() {
    Image img;
    img.width = img.height = N;
    img.rgba.assign(size_t(N) * N * 4, 1.0f);
    return img;
}

struct Rgb { double r, g, b; };

// What a family's pattern gives per pixel: height, colour, specular level.
struct Sample {
    double height;
    Rgb colour;
    double specular;
};

// Builds the three maps of one family from a per-pixel sampler (x, y = pixel centre,
// y counted from the bottom row, as in Image).
void build_family(const std::string& name, double strength, const std::function<Sample(double, double)>& f,
                  std::vector<std::pair<std::string, Image>>& out) {
    std::vector<double> h(size_t(N) * N);
    Image diffuse = blank(), normal = blank(), specular = blank();
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            const Sample s = f(x + 0.5, y + 0.5);
            h[size_t(y) * N + x] = s.height;
            float* d = diffuse.at(x, y);
            d[0] = float(quantize(s.colour.r));
            d[1] = float(quantize(s.colour.g));
            d[2] = float(quantize(s.colour.b));
            float* sp = specular.at(x, y);
            sp[0] = sp[1] = sp[2] = float(quantize(s.specular));
        }
    auto H = [&](int x, int y) { return h[size_t(wrap(y, N)) * N + wrap(x, N)]; };
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            // Central differences with wrap-around, so the normal map tiles like the height.
            const double dx = (H(x + 1, y) - H(x - 1, y)) * 0.5;
            const double dy = (H(x, y + 1) - H(x, y - 1)) * 0.5;
            const double nx = -strength * dx, ny = -strength * dy, nz = 1.0;
            const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
            float* n = normal.at(x, y);
            n[0] = float(quantize(nx / len * 0.5 + 0.5));
            n[1] = float(quantize(ny / len * 0.5 + 0.5));
            n[2] = float(quantize(nz / len * 0.5 + 0.5));
        }
    out.emplace_back(name + "_diffuse.png", std::move(diffuse));
    out.emplace_back(name + "_normal.png", std::move(normal));
    out.emplace_back(name + "_specular.png", std::move(specular));
}

// Running bond: 64 x 32 px bricks (4 x 8 per tile), odd rows shifted half a brick, 4 px
// mortar joints sunk below the brick faces, bevelled edges.
Sample brick(double x, double y) {
    const double bw = 64, bh = 32, half_joint = 2.0, bevel = 3.0;
    const int row = int(std::floor(y / bh));
    const double sx = x + (row % 2 ? bw / 2 : 0);
    const int col = wrap(int(std::floor(sx / bw)), N / int(bw));
    const double lx = sx - std::floor(sx / bw) * bw, ly = y - row * bh;
    const double edge = std::min(std::min(lx, bw - lx), std::min(ly, bh - ly));  // to joint centre
    const double edge_noise = (value_noise(x, y, 64, 64, 7) - 0.5) * 1.5;       // chipped edges
    const double face = smoothstep(half_joint, half_joint + bevel, edge + edge_noise);

    const double per_brick = rand01(col, row, 11);
    const double grain = fbm(x, y, 16, 16, 4, 13);
    const double mortar_grain = fbm(x, y, 64, 64, 2, 17);
    const double height = mix(0.1 + 0.15 * mortar_grain, 0.8 + 0.12 * grain + 0.08 * per_brick, face);

    // Reds and browns varying per brick, darkened by the grain; mortar a light grey.
    const double tone = 0.75 + 0.45 * per_brick, dirt = 0.75 + 0.4 * grain;
    const double hue = rand01(col, row, 19);
    const Rgb b{(0.50 + 0.08 * hue) * tone * dirt, (0.20 + 0.06 * hue) * tone * dirt,
                (0.12 + 0.03 * hue) * tone * dirt};
    const double m = 0.55 + 0.2 * mortar_grain;
    const Rgb mortar{m, m * 0.97, m * 0.9};
    const Rgb c{mix(mortar.r, b.r, face), mix(mortar.g, b.g, face), mix(mortar.b, b.b, face)};
    // Bricks dull, mortar not shiny at all.
    return {height, c, face * (0.18 + 0.1 * grain)};
}

// Square flagstones, 64 px (4 x 4 per tile), 3 px joints, each stone with its own shade,
// height offset and tilt; smoother and shinier than brick.
Sample stone(double x, double y) {
    const double size = 64, half_joint = 1.5, bevel = 2.5;
    const int tx = int(std::floor(x / size)), ty = int(std::floor(y / size));
    const double lx = x - tx * size, ly = y - ty * size;
    const double edge = std::min(std::min(lx, size - lx), std::min(ly, size - ly));
    const double face = smoothstep(half_joint, half_joint + bevel, edge);

    const double shade = rand01(tx, ty, 23), lift = rand01(tx, ty, 29);
    const double tilt_x = rand01(tx, ty, 31) - 0.5, tilt_y = rand01(tx, ty, 37) - 0.5;
    const double grain = fbm(x, y, 8, 8, 5, 41);
    const double fine = value_noise(x, y, 128, 128, 43);
    const double slope = (tilt_x * (lx - size / 2) + tilt_y * (ly - size / 2)) / size;
    const double height = mix(0.05 + 0.1 * fine, 0.75 + 0.1 * lift + 0.1 * slope + 0.15 * grain, face);

    // Warm greys with veins from the low octaves.
    const double v = (0.6 + 0.25 * shade) * (0.8 + 0.35 * grain) * (0.95 + 0.1 * fine);
    const Rgb s{v * 1.0, v * 0.95, v * 0.86};
    const Rgb joint{0.18, 0.17, 0.16};
    const Rgb c{mix(joint.r, s.r, face), mix(joint.g, s.g, face), mix(joint.b, s.b, face)};
    return {height, c, face * (0.45 + 0.3 * grain)};
}

// Brushed metal plates, 128 px (2 x 2 per tile), grooved seams and a domed rivet in each
// corner; shiny.
Sample metal(double x, double y) {
    const double size = 128, half_seam = 1.5, bevel = 1.5, inset = 10, rivet_r = 5;
    const double lx = x - std::floor(x / size) * size, ly = y - std::floor(y / size) * size;
    const double edge = std::min(std::min(lx, size - lx), std::min(ly, size - ly));
    const double face = smoothstep(half_seam, half_seam + bevel, edge);
    // Nearest corner rivet: a spherical cap.
    const double rx = std::min(std::abs(lx - inset), std::abs(lx - (size - inset)));
    const double ry = std::min(std::abs(ly - inset), std::abs(ly - (size - inset)));
    const double r2 = (rx * rx + ry * ry) / (rivet_r * rivet_r);
    const double dome = r2 < 1 ? std::sqrt(1 - r2) : 0.0;
    // Brushing: noise stretched along x (4 cells across, 256 down).
    const double brush = fbm(x, y, 4, 256, 2, 53);
    const double height = mix(0.2, 0.6 + 0.03 * brush, face) + 0.3 * dome;
    const double v = (0.5 + 0.15 * brush) * (0.7 + 0.3 * face) + 0.1 * dome;
    const Rgb c{v * 0.95, v * 0.98, v * 1.03};
    return {height, c, (0.02 + 0.88 * face) * (0.85 + 0.15 * brush) + 0.1 * dome};
}

// Vertical boards, 32 px wide (8 per tile), 2 px dark gaps, each board its own tone and
// length offset for its end joint; grain runs along the board (noise stretched along y).
Sample wood(double x, double y) {
    const double bw = 32, half_gap = 1.0, bevel = 2.0;
    const int col = int(std::floor(x / bw));
    const double lx = x - col * bw;
    // One end joint per board per tile, at a height of its own.
    const double joint_y = 32 + 192 * rand01(col, 0, 61);
    const double ly = y - joint_y, dy = std::abs(ly - std::floor(ly / N + 0.5) * N);
    const double edge = std::min(std::min(lx, bw - lx), dy);
    const double face = smoothstep(half_gap, half_gap + bevel, edge);
    const double tone = rand01(col, 1, 67);
    const double grain = fbm(x + 11 * tone * bw, y, 32, 2, 4, 71);
    const double rings = value_noise(x * 4 + 17 * col, y, 64, 8, 73);
    const double height = mix(0.1, 0.75 + 0.1 * grain + 0.05 * tone, face);
    const double v = (0.8 + 0.3 * tone) * (0.75 + 0.35 * grain) * (0.9 + 0.15 * rings);
    const Rgb board{0.46 * v, 0.30 * v, 0.17 * v};
    const Rgb gap{0.08, 0.05, 0.03};
    const Rgb c{mix(gap.r, board.r, face), mix(gap.g, board.g, face), mix(gap.b, board.b, face)};
    return {height, c, face * (0.15 + 0.15 * grain)};
}

// Slate roof shingles: rows 32 px high (8 per tile), each of 32 px tiles offset half a tile from the
// row below, 2 px gaps between tiles; a tile's lower edge stands proud of the row it covers
// and its surface slopes back up under the next row.
Sample shingle(double x, double y) {
    const double th = 32, tw = 32, half_gap = 1.0, bevel = 1.5;
    const int row = int(std::floor(y / th));
    const double sx = x + (row % 2 ? tw / 2 : 0);
    const int col = wrap(int(std::floor(sx / tw)), N / int(tw));
    const double lx = sx - std::floor(sx / tw) * tw, ly = y - row * th;  // ly = 0: the lower edge
    const double side = std::min(lx, tw - lx);
    const double face = smoothstep(half_gap, half_gap + bevel, side);
    const double lip = smoothstep(0, 2.5, ly);  // the exposed lower edge, rounded
    const double per_tile = rand01(col, row, 79);
    const double grain = fbm(x, y, 32, 32, 3, 83);
    const double height = mix(0.05, (0.35 + 0.55 * (1 - ly / th)) * lip + 0.05 * grain, face);
    const double v = (0.7 + 0.4 * per_tile) * (0.8 + 0.3 * grain) * (0.75 + 0.25 * (1 - ly / th));
    const Rgb slate{0.30 * v, 0.32 * v, 0.37 * v};
    const Rgb gap{0.06, 0.04, 0.04};
    const Rgb c{mix(gap.r, slate.r, face * lip), mix(gap.g, slate.g, face * lip), mix(gap.b, slate.b, face * lip)};
    return {height, c, face * lip * (0.3 + 0.3 * per_tile)};
}

}  // namespace

std::vector<std::pair<std::string, Image>> model_textures() {
    std::vector<std::pair<std::string, Image>> out;
    build_family("wood", 3.0, wood, out);
    build_family("shingle", 4.0, shingle, out);
    return out;
}

std::vector<std::pair<std::string, Image>> default_textures() {
    std::vector<std::pair<std::string, Image>> out;
    build_family("brick", 3.0, brick, out);
    build_family("stone", 3.0, stone, out);
    build_family("metal", 3.0, metal, out);
    return out;
}

}  // namespace dsr
