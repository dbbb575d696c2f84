// Capabilities, probed once at start-up into booleans; every path
// decision branches on this struct, never on version strings.
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "gl/cap_names.h"  // split_caps, the --caps names

namespace dsr {

struct Caps {
    std::string vendor, renderer, version, glsl_version;
    int gl_major = 0, gl_minor = 0, glsl_major = 0, glsl_minor = 0;
    // OpenGL ES 2.0 (docs/gles2.md): every flag below is read from ES 2.0 and its extensions, each
    // mapped onto the desktop capability whose path it stands in for; the shaders are the
    // glsl120/ sources through the GLSL ES 1.00 prelude (gl/glsl_dialect.h).
    bool es = false;
    // ES only: the extension the G-buffer's targets come from (GL_EXT_draw_buffers or
    // GL_NV_draw_buffers; empty: one target), and gl_FragDepth (EXT_frag_depth; desktop GLSL has it).
    std::string es_draw_buffers;
    bool frag_depth = true;
    bool glsl120 = false;            // GLSL 1.20 (OpenGL 2.1): every shader is #version 120
    // GLSL 1.30 (OpenGL 3.0): flat varyings and roundEven, for the tiles' vertex fetch
    // (light_tiles_flat.vert/.frag, Paths::tile_fetch_vertex); every other shader stays 1.20.
    bool glsl130 = false;
    int max_varying_components = 0;  // GL_MAX_VARYING_COMPONENTS (GL_MAX_VARYING_FLOATS before 3.0)
    bool draw_buffers = false;       // ARB_draw_buffers (core in 2.0): MRT, §3.2
    int max_draw_buffers = 1;        // GL_MAX_DRAW_BUFFERS
    bool depth_texture = false;      // ARB_depth_texture: the depth-texture path, §3.3.2
    bool shadow = false;             // ARB_shadow: depth textures compared in the lookup (shadow2D)
    bool fbo = false;                // EXT_framebuffer_object: render to texture
    bool fbo_mixed_formats = false;  // ARB_framebuffer_object (core in 3.0): colour attachments of one
                                     // framebuffer in different formats (EXT wants one format)
    bool npot = false;               // ARB_texture_non_power_of_two
    bool texture_float = false;      // ARB_texture_float
    bool half_float = false;         // ARB_half_float_pixel
    // Additive blending into RGBA16F / RGBA32F targets without clamping, measured (gl/float_blend_probe.h):
    // NV40-class GPUs blended half floats but not 32-bit ones.
    bool half_float_blend = false;
    bool float_blend = false;
    bool texture_srgb = false;       // EXT_texture_sRGB (core in 2.1): colour maps decoded when sampled
    bool occlusion_query = false;    // ARB_occlusion_query (core in 1.5): light_fragments
    bool pipeline_statistics = false;  // ARB_pipeline_statistics_query (core in 4.6): light_invocations
    bool timer_query = false;        // ARB_timer_query / EXT_timer_query
    // Light geometries (docs/light_geometry.md): stencil light volumes and depth bounds.
    bool stencil = false;            // an 8-bit stencil buffer in the main frame buffer (GL_STENCIL_BITS)
    bool packed_depth_stencil = false;  // EXT_packed_depth_stencil (core in 3.0): depth-stencil FBO attachment
    bool stencil_separate = false;   // glStencilOpSeparate (GL 2.0): both faces in one stencil pass
    bool stencil_two_side_ext = false;  // EXT_stencil_two_side: the same before GL 2.0
    bool depth_bounds = false;       // EXT_depth_bounds_test (NVIDIA; not llvmpipe)
    bool framebuffer_blit = false;   // EXT_framebuffer_blit (core in 3.0): the depth hand-off by blit (docs/forward.md)
    bool pbuffer_surfaces = false;   // the context offers pbuffer surfaces (gl/surfaces.h: EGL)
    // A CPU rasteriser (Mesa's llvmpipe, softpipe or swrast, by GL_RENDERER): the tiles geometry's
    // defaults (options.h) and forward.frag's view vector form (forward_renderer.cpp) differ there.
    bool software_rasterizer = false;
    // GL_ALIASED_POINT_SIZE_RANGE's upper end (core in 1.2): the largest square a point rasterises
    // to, which the tiles geometry may draw a tile as (Paths::tile_points).
    float max_point_size = 1;
    std::vector<std::string> forced_off;  // names hidden by --caps / DSR_CAPS
};

// Reads the current context. `force_off` lists capabilities to report missing, by the names of
// cap_names.h; an unknown name throws dsr::Error (check_cap_names' line).
Caps probe_caps(const std::vector<std::string>& force_off = {});

// Whether --caps (or $DSR_CAPS) hid capability `name` (cap_names.h).
inline bool is_forced_off(const Caps& caps, const char* name) {
    return std::find(caps.forced_off.begin(), caps.forced_off.end(), name) != caps.forced_off.end();
}

// The end of a refusal for a missing capability `name`: `otherwise` ("which this GL lacks") where
// the GL has none, "which --caps or $DSR_CAPS hides (forced off: NAME)" where they hid it, so a
// refusal never blames a GL that has it. Inline: the fuzz targets link the paths without the probe.
inline std::string which_missing(const Caps& caps, const char* name, const std::string& otherwise = "which this GL lacks") {
    return is_forced_off(caps, name) ? std::string("which --caps or $DSR_CAPS hides (forced off: ") + name + ")" : otherwise;
}

// One line per capability with the extension it comes from, for `dsr info`.
std::string describe(const Caps& caps);

bool has_extension(const char* name);

}  // namespace dsr
