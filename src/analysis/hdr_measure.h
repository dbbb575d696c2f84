// Light beyond 1.0, measured (`dsr hdr`, docs/hdr.md): for scenes whose lights sum past 1, the
// share of pixels that clip with the tutorial's RGBA8 P-buffer 0 against float accumulation with
// each tone-mapping operator, and what each accumulation format costs a frame.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "deferred/options.h"
#include "gl/caps.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr::hdr {

// One white sphere on a grey floor under one point light of colour (4, 4, 4): under RGBA8 a flat
// white disc. Pure.
Scene bright_sphere_scene();
// Every light's colour times k. Pure.
Scene with_lights_scaled(Scene s, float k);
// The share of pixels (0..1) with any of r, g, b above `limit`. Pure.
double share_above(const Image& img, float limit);

struct Case {
    std::string name;
    Scene scene;
};
// The measured scenes: the bright sphere; data/default.scene's lights x4; 256 lights (the bench's
// spread) x4. Reads data/default.scene.
std::vector<Case> default_cases();

struct Result {
    std::string scene;
    AccumFormat accum = AccumFormat::rgba8;
    ToneMap tonemap = ToneMap::none;
    // rgba8: pixels of P-buffer 0 at 255 in a channel (the sum clipped); half/float with none:
    // pixels of P-buffer 0 above 1 (what 8 bits clip, and the clamped output with them); with an
    // operator: output pixels at 255 in a channel.
    double clipped = 0;
    double ms_median = 0;  // whole frame, wall clock around glFinish on llvmpipe (FrameTimer)
    double exposure_scale = 1;
    double accum_max = 0;  // the largest channel of P-buffer 0: 1 at most in RGBA8
};

// Renders every case at size x size in rgba8, half and float (none) and in half with reinhard and
// aces, `frames` timed frames each after one warm-up, interleaved across the configurations of a
// scene; formats the GL refuses are left out and said through `say`. Needs a current context of at least size x size.
std::vector<Result> measure(const Caps& caps, const std::string& shader_dir, const std::vector<Case>& cases, int size,
                            int frames, const std::function<void(const std::string&)>& say);

// The results as a Markdown table.
std::string table(const std::vector<Result>& results);

}  // namespace dsr::hdr
