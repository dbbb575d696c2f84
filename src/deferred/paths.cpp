#include "deferred/paths.h"

#include <sstream>

namespace dsr {

Paths choose_paths(const Caps& caps, const ShaderOptions& opts) {
    Paths p;
    if (opts.depth == DepthPath::automatic)
        p.depth_path = caps.depth_texture ? DepthPath::texture : DepthPath::packed;
    else
        p.depth_path = opts.depth;
    // Figure 3: normal, diffuse, specular+shininess, and packed depth only when that path runs.
    p.gbuffer_targets = p.depth_path == DepthPath::packed ? 4 : 3;
    // MRT needs render-to-texture too: without framebuffer objects the main buffer has one
    // colour buffer (§3.2, one pass per target).
    p.mrt = caps.fbo && caps.draw_buffers && caps.max_draw_buffers >= p.gbuffer_targets;
    p.fbo = caps.fbo;
    p.pow2 = !caps.npot;
    p.count_fragments = caps.occlusion_query;
    p.depth = p.depth_path == DepthPath::texture ? "texture" : "packed";
    p.gbuffer = p.mrt ? "mrt" : "per-target";
    p.render_target = p.fbo ? "fbo" : "copy";
    p.textures = p.pow2 ? "pow2" : "npot";

    if (!caps.glsl120)
        p.refused = "GLSL 1.20 is required and this GL offers " +
                    (caps.glsl_version.empty() ? std::string("none") : caps.glsl_version) + " (GL " + caps.version + ")";
    else if (p.depth_path == DepthPath::texture && !caps.depth_texture)
        p.refused = "--depth texture needs ARB_depth_texture, which is missing (use --depth packed)";
    else if (opts.float_accum && !(caps.texture_float && caps.fbo))
        p.refused = "float accumulation needs ARB_texture_float and EXT_framebuffer_object";
    else if (opts.gbuffer_half && !(caps.half_float && caps.texture_float))
        p.refused = "half-float G-buffer targets need ARB_texture_float and ARB_half_float_pixel";
    return p;
}

std::string describe(const Paths& p) {
    std::ostringstream o;
    o << "  depth          "
      << (p.depth_path == DepthPath::texture ? "texture (ARB_depth_texture)"
                                              : "packed (float_to_color into an RGB8 target, §3.3.2)")
      << "\n  G-buffer       "
      << (p.mrt ? "mrt: one material pass into all " + std::to_string(p.gbuffer_targets) + " targets (ARB_draw_buffers)"
                : "per-target: one material pass per G-buffer target (§3.2)")
      << "\n  render target  "
      << (p.fbo ? "fbo: render to texture (EXT_framebuffer_object)" : "copy: main buffer region + glCopyTexSubImage2D")
      << "\n  textures       "
      << (p.pow2 ? "pow2: targets padded, material maps rescaled to powers of two" : "npot: any size")
      << "\n  light counting " << (p.count_fragments ? "occlusion queries" : "off (no occlusion queries)") << "\n";
    return o.str();
}

}  // namespace dsr
