#include "gl/rounding_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "gl/blit.h"
#include "gl/caps.h"
#include "gl/pbuffer.h"
#include "gl/state.h"

namespace dsr {

namespace {

// The threshold sweeps' grid of f (Unorm8Rounding::threshold).
constexpr float kSweepF0 = 0.35f, kSweepDf = 0.0005f;
constexpr int kSweepSteps = 601;

// Fills the bound 4x4 target with colour (v, v, v, 1) / 255 by a fixed-function quad; returns
// the red bytes.
void fill(float v) {
    glColor4f(v / 255.0f, v / 255.0f, v / 255.0f, 1.0f);
    draw_clip_square();
}

void read_red(unsigned char out[16]) {
    unsigned char px[64];
    glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < 16; ++i) out[i] = px[4 * i];
}

}  // namespace

Unorm8Rounding probe_unorm8_rounding() {
    Unorm8Rounding r;
    if (!has_extension("GL_EXT_framebuffer_object")) return r;
    PBufferDesc d;
    d.width = d.height = 4;
    d.color_formats = {GL_RGBA8};
    PBuffer target("rounding probe", d);
    target.bind_render();
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    RenderState s;  // fixed function, no blending, dither off
    gl_state().reset();
    gl_state().apply(s);
    unsigned char px[16];
    const float values[4] = {0.4f, 0.6f, 1.5f, 2.5f};
    for (int i = 0; i < 4; ++i) {
        fill(values[i]);
        read_red(px);
        r.plain[i] = px[0];
    }
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    RenderState add = s;
    add.blend = true;
    add.blend_src = add.blend_dst = GL_ONE;
    gl_state().apply(add);
    for (int k = 0; k < 10; ++k) fill(0.6f);
    read_red(px);
    r.added_ten = px[0];
    // The sweeps: one point per value, a column per step of f, a row per k (then per (j, k) for the
    // additive one), in a target of their own.
    {
        constexpr int kSteps = kSweepSteps, kRows = 255 + 15;
        constexpr float kF0 = kSweepF0, kDf = kSweepDf;
        PBufferDesc sd;
        sd.width = kSteps;
        sd.height = kRows;
        sd.color_formats = {GL_RGBA8};
        PBuffer sweep("rounding sweep", sd);
        target.unbind_render();
        sweep.bind_render();
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, kSteps, 0, kRows, -1, 1);
        gl_state().apply(s);
        // Client-side arrays, not glBegin/glColor per point: the same float colours, drawn in a
        // tenth of the time (the probe runs when a tiles shader is built).
        std::vector<float> xy, rgba;
        auto points = [&](int row0, int rows, const std::function<float(int, int)>& value) {
            xy.clear(), rgba.clear();
            for (int row = 0; row < rows; ++row)
                for (int i = 0; i < kSteps; ++i) {
                    const float v = value(row, i) / 255.0f;
                    rgba.insert(rgba.end(), {v, v, v, 1.0f});
                    xy.insert(xy.end(), {float(i) + 0.5f, float(row0 + row) + 0.5f});
                }
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_COLOR_ARRAY);
            glVertexPointer(2, GL_FLOAT, 0, xy.data());
            glColorPointer(4, GL_FLOAT, 0, rgba.data());
            glDrawArrays(GL_POINTS, 0, GLsizei(xy.size() / 2));
            glDisableClientState(GL_COLOR_ARRAY);
            glDisableClientState(GL_VERTEX_ARRAY);
        };
        points(0, 255, [&](int k, int i) { return float(k) + kF0 + kDf * float(i); });
        // The additive rows: j/255 laid down, then (k + f)/255 added.
        points(255, 15, [&](int row, int) { return float(Unorm8Rounding::kAddJ[row / 3]); });
        RenderState add = s;
        add.blend = true;
        add.blend_src = add.blend_dst = GL_ONE;
        gl_state().apply(add);
        points(255, 15, [&](int row, int i) { return float(Unorm8Rounding::kAddK[row % 3]) + kF0 + kDf * float(i); });
        gl_state().apply(s);
        std::vector<unsigned char> px(size_t(kSteps) * kRows * 4);
        glReadPixels(0, 0, kSteps, kRows, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
        auto first_up = [&](int row, int want) {
            for (int i = 0; i < kSteps; ++i)
                if (px[size_t(4 * (row * kSteps + i))] == want) return kF0 + kDf * float(i);
            return -1.0f;
        };
        for (int k = 0; k < 255; ++k) r.threshold[k] = first_up(k, k + 1);
        for (int row = 0; row < 15; ++row) {
            const int j = Unorm8Rounding::kAddJ[row / 3], k = Unorm8Rounding::kAddK[row % 3];
            r.added[row / 3][row % 3] = first_up(255 + row, j + k + 1);
        }
        sweep.unbind_render();
        target.bind_render();
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
    }
    RenderState dither = s;
    dither.dither = true;
    gl_state().apply(dither);
    fill(1.5f);
    read_red(px);
    r.dither_min = *std::min_element(px, px + 16);
    r.dither_max = *std::max_element(px, px + 16);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glColor4f(1, 1, 1, 1);
    target.unbind_render();
    gl_state().reset();
    r.measured = true;
    return r;
}

const Unorm8Rounding& unorm8_rounding() {
    static const Unorm8Rounding r = probe_unorm8_rounding();
    return r;
}

float unorm8_round_offset(const Unorm8Rounding& r) {
    if (!r.measured) return 0.5f;
    std::vector<float> t;
    for (float v : r.threshold)
        if (v >= 0) t.push_back(v);
    if (t.empty()) return 0.5f;
    std::sort(t.begin(), t.end());
    const float median = t[t.size() / 2];
    return std::fabs(median - 0.5f) <= 0.0011f ? 0.5f : 1.0f - median;
}

float predicted_threshold(int bits, int k) {
    for (int i = 0; i < kSweepSteps; ++i) {
        const float f = kSweepF0 + kSweepDf * float(i);
        float t = (float(k) + f) / 255.0f;  // as the probe's glColor4f got it
        if (bits > 0) t = std::floor(t * std::ldexp(1.0f, bits)) / std::ldexp(1.0f, bits);
        const double x = double(t) * 255.0;
        // Round to nearest; an exact tie to even without truncation (llvmpipe), down after it (at
        // 12 bits, k 127, where floor(t x 4096) / 4096 x 255 is 127.5 exactly, turns up a grid step
        // later; docs/gpu.md, "Images on a GPU").
        const double frac = x - std::floor(x);
        const bool up = frac > 0.5 || (frac == 0.5 && bits == 0 && std::fmod(std::floor(x), 2.0) == 1.0);
        if (std::floor(x) + (up ? 1 : 0) >= double(k + 1)) return f;
    }
    return -1.0f;
}

int unorm8_model_misfits(const Unorm8Rounding& r, int bits, std::string* which) {
    int misfits = 0;
    for (int k = 0; k < 255; ++k) {
        const float p = predicted_threshold(bits, k);
        if (r.threshold[k] < 0 && p < 0) continue;  // neither turns up within the sweep
        if (r.threshold[k] < 0 || p < 0 || std::fabs(r.threshold[k] - p) > kSweepDf * 1.5f) {
            if (which && misfits < 8) {
                char e[64];
                std::snprintf(e, sizeof e, " k %d: %.4f not %.4f", k, r.threshold[k], p);
                *which += e;
            }
            ++misfits;
        }
    }
    return misfits;
}

int unorm8_truncate_bits(const Unorm8Rounding& r) {
    if (!r.measured) return -1;
    // The model with the fewest thresholds off by more than a step, if that is at most 8 of 255:
    // a k whose threshold lies within float rounding of a grid point may land a step either side.
    int best = -1, best_misfits = 9;
    for (int bits : {0, 8, 9, 10, 11, 12, 13, 14, 15, 16}) {
        const int m = unorm8_model_misfits(r, bits, nullptr);
        if (m < best_misfits) best = bits, best_misfits = m;
    }
    return best;
}

std::string describe(const Unorm8Rounding& r) {
    if (!r.measured) return "  RGBA8 rounding  not measured (no framebuffer objects)\n";
    std::vector<float> t(r.threshold, r.threshold + 255);
    const int missing = int(std::count(t.begin(), t.end(), -1.0f));
    int off_half = 0;
    for (float v : t) off_half += v >= 0 && std::fabs(v - 0.5f) > 0.0011f;
    std::sort(t.begin(), t.end());
    char b[640];
    std::snprintf(b, sizeof b,
                  "  RGBA8 rounding  v/255 written: 0.4 -> %d, 0.6 -> %d, 1.5 -> %d, 2.5 -> %d; 10 x 0.6/255 added -> %d; "
                  "1.5/255 with GL_DITHER on over 4x4: %d..%d\n"
                  "                  (k+f)/255 turns to k+1 from f = %.4f (k 0), %.4f (1), %.4f (100), %.4f (200); over "
                  "k 0..254: min %.4f, median %.4f, max %.4f, %d more than a step from 0.5, %d not in [0.35, 0.65]\n",
                  r.plain[0], r.plain[1], r.plain[2], r.plain[3], r.added_ten, r.dither_min, r.dither_max, r.threshold[0],
                  r.threshold[1], r.threshold[100], r.threshold[200], t[size_t(missing)], t[size_t(missing + (255 - missing) / 2)],
                  t.back(), off_half, missing);
    std::string add = "                  (k+f)/255 added onto j/255 turns to j+k+1 from f =";
    for (int a = 0; a < 5; ++a)
        for (int c = 0; c < 3; ++c) {
            char e[64];
            std::snprintf(e, sizeof e, " %.4f (j %d k %d)", r.added[a][c], Unorm8Rounding::kAddJ[a], Unorm8Rounding::kAddK[c]);
            add += e;
        }
    const int bits = unorm8_truncate_bits(r);
    const std::string model = bits == 0  ? "round(t x 255)"
                              : bits > 0 ? "round(floor(t x 2^" + std::to_string(bits) + ") / 2^" + std::to_string(bits) +
                                               " x 255): t truncated to " + std::to_string(bits) + " bits first"
                                         : "no model fits; the tiles geometry's emulation adds " +
                                               std::to_string(unorm8_round_offset(r)) + " before floor()";
    std::string misfit;
    const int n = bits >= 0 ? unorm8_model_misfits(r, bits, &misfit) : unorm8_model_misfits(r, 12, &misfit);
    return std::string(b) + add + "\n                  model: " + model + "; " + std::to_string(n) + " of 255 thresholds off it" +
           (bits >= 0 ? "" : " (against n = 12)") + (misfit.empty() ? "" : ":" + misfit) + "\n";
}

}  // namespace dsr
