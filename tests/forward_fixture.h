// Shared by tests/test_forward.cpp and tests/test_analytic.cpp: the forward reference renderer
// under OSMesa, read back like render_fixture.h's render_scene.
#pragma once
#include "forward/forward_renderer.h"
#include "render_fixture.h"

namespace dsr::test {

struct ForwardResult {
    Image image;
    ForwardStats stats;
    int lights_per_pass = 0;
};

// as_gpu: the capabilities as probed, but not a CPU rasteriser, so the renderer takes the shader
// forms it picks for GPUs (forward.frag's VIEW_PER_LIGHT). force_off: as render_scene's (--caps).
inline ForwardResult render_forward(const Scene& scene, int w, int h, const ForwardOptions& opts, bool as_gpu = false,
                                    const std::vector<std::string>& force_off = {}) {
    auto ctx = create_context(ContextDesc{"osmesa", w, h});
    Caps caps = probe_caps(force_off);
    if (as_gpu) caps.software_rasterizer = false;
    ForwardRenderer fr(caps, w, h, opts, resource_dir("glsl120"));
    fr.set_scene(scene);
    ForwardResult r;
    r.stats = fr.render(scene);
    r.image = read_pixels(w, h);
    r.lights_per_pass = fr.lights_per_pass();
    return r;
}

inline ForwardOptions forward_mode(ForwardMode m, bool float_target = true) {
    ForwardOptions o;
    o.mode = m;
    o.float_target = float_target;
    return o;
}

}  // namespace dsr::test
