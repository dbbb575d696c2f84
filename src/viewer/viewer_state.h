// What the viewer's loop (viewer_app.cpp) and its panel (viewer_panel.cpp) share.
#pragma once
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deferred/deferred_shader.h"
#include "deferred/option_table.h"
#include "gl/caps.h"
#include "scene/scene.h"
#include "viewer/fly_camera.h"

namespace dsr {

// One frame's figures for the panel's plot.
struct FrameSample {
    double t;          // seconds since start
    double frame_ms;   // the renderer's frame (FrameStats::ms.frame)
    double lights_ms;  // its light passes
};

struct ViewerState {
    Caps caps;
    RenderOptions options;      // as the panel and `set` last changed them
    std::string option_error;   // the last refused change, shown in the panel
    // Changes the panel asked for this frame, applied after it (a change may build a new
    // DeferredShader, which the panel must not see replaced while it draws).
    std::vector<std::pair<const RenderOption*, std::string>> pending;
    bool panel = true, overlay = false, animate = false;
    FlyCamera fly;
    FrameStats last;            // the last frame's stats
    double loop_ms = 0;         // the last frame's whole loop: render, panel, swap
    std::optional<long long> ideal;  // ideal light fragments of a recent frame (depth-texture path)
    std::deque<FrameSample> history;  // the last few seconds
    // P-buffer 0's luminance (docs/hdr.md): blocks of the final stage's reduced copy by their mean
    // log2 L, in bins over [kHistogramLo, kHistogramHi]; the share of blocks whose largest L is above
    // 1 (what RGBA8 would clip); the exposure scale of the last final pass.
    static constexpr float kHistogramLo = -8, kHistogramHi = 4;
    std::vector<float> luminance_histogram;
    double luminance_above_one = 0;
    float exposure_scale = 1;
    int builds = 0;             // DeferredShaders built (option changes), not resizes
    int resizes = 0;
    std::string renderer;       // GL_RENDERER
};

class DeferredShader;

// Draws the panel (ImGui, between NewFrame and Render) and the scissor overlay.
void draw_panel(ViewerState& st, const DeferredShader& ds, const Scene& frame_scene, int w, int h);
void draw_scissor_overlay(const ViewerState& st, const DeferredShader& ds, const Scene& frame_scene, int w, int h);

}  // namespace dsr
