// The one path chooser (STYLE "a pure choose_paths"): probed capabilities and asked-for options
// in, the path taken at each decision out. No GL inside, so every capability combination is
// unit-tested; DeferredShader, `dsr info`, `render --depth auto` and the tests all ask it.
#pragma once
#include <string>

#include "deferred/options.h"
#include "gl/caps.h"

namespace dsr {

struct Paths {
    DepthPath depth_path = DepthPath::texture;  // never automatic
    bool mrt = true;             // one material pass into every G-buffer target (ARB_draw_buffers)
    bool fbo = true;             // render to texture (EXT_framebuffer_object); else copy
    bool pow2 = false;           // targets padded, material maps rescaled to powers of two
    bool count_fragments = true; // occlusion queries around the light passes
    int gbuffer_targets = 3;     // normal, diffuse, specular (+ packed depth)
    // The same decisions by name (info, --stats, the tests).
    std::string depth;           // "texture" | "packed"
    std::string gbuffer;         // "mrt" | "per-target"
    std::string render_target;   // "fbo" | "copy"
    std::string textures;        // "npot" | "pow2"
    // Non-empty: this GL cannot run these options, and why, in one line.
    std::string refused;
};

Paths choose_paths(const Caps& caps, const ShaderOptions& opts);

// One line per decision with its reason, for `dsr info`.
std::string describe(const Paths& paths);

}  // namespace dsr
