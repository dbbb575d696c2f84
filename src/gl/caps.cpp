#include "gl/caps.h"

#include "gl/surfaces.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>

#include "dsr_error.h"
#include "gl/float_blend_probe.h"
#include "gl/gl.h"

namespace dsr {

bool has_extension(const char* name) {
    // glGetString(GL_EXTENSIONS) is valid in compatibility contexts (the only kind dsr asks for).
    const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    if (!ext) return false;
    size_t n = std::strlen(name);
    for (const char* p = ext; (p = std::strstr(p, name)); p += n)
        if ((p == ext || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

static std::string gl_string(GLenum e) {
    const char* s = reinterpret_cast<const char*>(glGetString(e));
    return s ? s : "";
}

namespace {

// OpenGL ES 2.0's capabilities, each mapped onto the desktop flag whose path it stands in for
// (docs/gles2.md has the table). Only ES 2.0 and extensions count, never a newer ES version's
// core: Mesa gives ES 3.2 for an ES 2.0 request.
void probe_es_caps(Caps& c, const std::function<bool(const char*)>& off) {
    c.es = true;
    // "OpenGL ES 2.0 Mesa ..." and "OpenGL ES GLSL ES 1.0.16".
    std::sscanf(c.version.c_str(), "OpenGL ES %d.%d", &c.gl_major, &c.gl_minor);
    std::sscanf(c.glsl_version.c_str(), "OpenGL ES GLSL ES %d.%d", &c.glsl_major, &c.glsl_minor);
    // GLSL ES 1.00 runs the glsl120/ sources through its prelude; nothing of 1.30 (flat varyings).
    c.glsl120 = c.gl_major >= 2 && !off("no-glsl");
    c.glsl130 = false;
    GLint varyings = 0;
    glGetIntegerv(GL_MAX_VARYING_VECTORS, &varyings);
    c.max_varying_components = varyings * 4;
    // EXT_draw_buffers, or NVIDIA's NV_draw_buffers (its attachments beyond the first need
    // NV_fbo_color_attachments); the same GL_MAX_DRAW_BUFFERS enum.
    if (has_extension("GL_EXT_draw_buffers")) c.es_draw_buffers = "GL_EXT_draw_buffers";
    else if (has_extension("GL_NV_draw_buffers") && has_extension("GL_NV_fbo_color_attachments"))
        c.es_draw_buffers = "GL_NV_draw_buffers";
    c.draw_buffers = !c.es_draw_buffers.empty() && gl_entry.DrawBuffersARB && !off("no-mrt");
    GLint mdb = 1;
    if (c.draw_buffers) glGetIntegerv(GL_MAX_DRAW_BUFFERS_ARB, &mdb);
    c.max_draw_buffers = c.draw_buffers ? mdb : 1;
    if (c.max_draw_buffers < 2) c.draw_buffers = false;
    c.depth_texture = (has_extension("GL_OES_depth_texture") || has_extension("GL_ANGLE_depth_texture")) &&
                      !off("no-depth-texture");
    // EXT_shadow_samplers would give shadow2DEXT; without it the maps are packed and compared in
    // the shader, as without ARB_shadow.
    c.shadow = c.depth_texture && has_extension("GL_EXT_shadow_samplers") && !off("no-shadow");
    c.fbo = !off("no-fbo");  // framebuffer objects are core in ES 2.0
    c.fbo_mixed_formats = c.fbo && !off("no-arb-fbo");  // ES 2.0 asks no one format of a framebuffer's targets
    // ES 2.0 core samples non-power-of-two textures only without mipmaps and with clamping; the
    // material maps need both, so npot is OES_texture_npot's.
    c.npot = has_extension("GL_OES_texture_npot") && !off("no-npot");
    // Float targets: ES 2.0 renders into none. OES_texture_float / OES_texture_half_float with
    // EXT_color_buffer_half_float give half-float targets of unsized formats, which dsr's float
    // paths (sized RGBA16F/RGBA32F) do not take yet: both stay off, and those paths refuse.
    c.texture_float = false;
    c.half_float = false;
    c.texture_srgb = has_extension("GL_EXT_sRGB") && !off("no-srgb-texture");
    c.occlusion_query = false;  // EXT_occlusion_query_boolean: any sample passed, not how many
    c.pipeline_statistics = false;
    c.timer_query = false;  // EXT_disjoint_timer_query is not loaded: wall-clock timing
    GLint stencil_bits = 0;
    glGetIntegerv(GL_STENCIL_BITS, &stencil_bits);
    c.stencil = stencil_bits >= 8 && !off("no-stencil");
    c.packed_depth_stencil = has_extension("GL_OES_packed_depth_stencil") && !off("no-packed-depth-stencil");
    c.stencil_separate = !off("no-stencil-separate") && !off("no-stencil-two-side");  // core in ES 2.0
    c.stencil_two_side_ext = false;
    c.depth_bounds = false;
    c.framebuffer_blit = c.fbo && gl_entry.BlitFramebufferEXT && !off("no-framebuffer-blit");  // NV_/ANGLE_framebuffer_blit
    c.frag_depth = has_extension("GL_EXT_frag_depth");
    c.pbuffer_surfaces = false;
}

}  // namespace

Caps probe_caps(const std::vector<std::string>& force_off) {
    const std::string unknown = check_cap_names(force_off);
    if (!unknown.empty()) throw Error(unknown);
    auto off = [&](const char* k) {
        if (!is_cap_name(k)) throw Error(std::string("probe_caps: '") + k + "' is not in cap_names()");  // a slip here, not the user's
        return std::find(force_off.begin(), force_off.end(), k) != force_off.end();
    };

    Caps c;
    c.vendor = gl_string(GL_VENDOR);
    c.renderer = gl_string(GL_RENDERER);
    for (const char* sw : {"llvmpipe", "softpipe", "swrast"})
        c.software_rasterizer = c.software_rasterizer || c.renderer.find(sw) != std::string::npos;
    GLfloat point_range[2] = {1, 1};
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, point_range);
    c.max_point_size = point_range[1];
    c.version = gl_string(GL_VERSION);
    c.glsl_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
    if (current_gl_is_es()) {
        probe_es_caps(c, off);
        c.forced_off = force_off;
        while (glGetError() != GL_NO_ERROR) {}
        return c;
    }
    std::sscanf(c.version.c_str(), "%d.%d", &c.gl_major, &c.gl_minor);
    std::sscanf(c.glsl_version.c_str(), "%d.%d", &c.glsl_major, &c.glsl_minor);
    auto at_least = [](int ma, int mi, int wa, int wi) { return ma > wa || (ma == wa && mi >= wi); };
    bool gl20 = at_least(c.gl_major, c.gl_minor, 2, 0);
    c.glsl120 = at_least(c.glsl_major, c.glsl_minor, 1, 20) &&
                (gl20 || has_extension("GL_ARB_shading_language_100")) && !off("no-glsl");
    c.glsl130 = c.glsl120 && at_least(c.glsl_major, c.glsl_minor, 1, 30) && !off("no-glsl130");
    GLint varyings = 0;
    glGetIntegerv(GL_MAX_VARYING_FLOATS, &varyings);  // the same enum as GL_MAX_VARYING_COMPONENTS
    c.max_varying_components = varyings;
    c.draw_buffers = (gl20 || has_extension("GL_ARB_draw_buffers")) && !off("no-mrt");
    GLint mdb = 1;
    if (c.draw_buffers) glGetIntegerv(GL_MAX_DRAW_BUFFERS_ARB, &mdb);
    c.max_draw_buffers = c.draw_buffers ? mdb : 1;
    if (c.max_draw_buffers < 2) c.draw_buffers = false;
    c.depth_texture = (at_least(c.gl_major, c.gl_minor, 1, 4) || has_extension("GL_ARB_depth_texture")) &&
                      !off("no-depth-texture");
    // ARB_shadow (core in 1.4): the shadow maps' comparison in the lookup; without depth textures
    // there is nothing to compare, and the maps are packed (shadow_stage.h).
    c.shadow = c.depth_texture && (at_least(c.gl_major, c.gl_minor, 1, 4) || has_extension("GL_ARB_shadow")) &&
               !off("no-shadow");
    c.fbo = has_extension("GL_EXT_framebuffer_object") && !off("no-fbo");
    // no-arb-fbo leaves EXT_framebuffer_object's one-format rule (what a 2005 driver enforced).
    c.fbo_mixed_formats = c.fbo && (at_least(c.gl_major, c.gl_minor, 3, 0) || has_extension("GL_ARB_framebuffer_object")) &&
                          !off("no-arb-fbo");
    c.npot = (gl20 || has_extension("GL_ARB_texture_non_power_of_two")) && !off("no-npot");
    c.texture_float = (at_least(c.gl_major, c.gl_minor, 3, 0) || has_extension("GL_ARB_texture_float")) &&
                      !off("no-float");
    c.half_float = (at_least(c.gl_major, c.gl_minor, 3, 0) || has_extension("GL_ARB_half_float_pixel")) &&
                   !off("no-float");
    // Measured, not read off a version: blending into float targets (float_blend_probe.h).
    if (c.fbo && c.texture_float && !off("no-float-blend")) {
        c.float_blend = probe_float_blend(GL_RGBA32F_ARB);
        c.half_float_blend = c.half_float && probe_float_blend(GL_RGBA16F_ARB);
    }
    c.texture_srgb = (at_least(c.gl_major, c.gl_minor, 2, 1) || has_extension("GL_EXT_texture_sRGB")) && !off("no-srgb-texture");
    c.occlusion_query = (at_least(c.gl_major, c.gl_minor, 1, 5) || has_extension("GL_ARB_occlusion_query")) &&
                        !off("no-occlusion-query");
    // GL_FRAGMENT_SHADER_INVOCATIONS_ARB through the GL 1.5 query calls: no entry point of its own.
    c.pipeline_statistics = (at_least(c.gl_major, c.gl_minor, 4, 6) ||
                             has_extension("GL_ARB_pipeline_statistics_query")) &&
                            !off("no-pipeline-stats");
    c.timer_query = has_extension("GL_ARB_timer_query") || has_extension("GL_EXT_timer_query");
    GLint stencil_bits = 0;  // of the main frame buffer: create_context asks for 8 on every backend
    glGetIntegerv(GL_STENCIL_BITS, &stencil_bits);
    c.stencil = stencil_bits >= 8 && !off("no-stencil");
    c.packed_depth_stencil = (at_least(c.gl_major, c.gl_minor, 3, 0) || has_extension("GL_EXT_packed_depth_stencil")) &&
                             !off("no-packed-depth-stencil");
    // no-stencil-two-side hides both ways of setting the two faces apart; no-stencil-separate only GL 2.0's.
    c.stencil_separate = gl20 && !off("no-stencil-separate") && !off("no-stencil-two-side");
    c.stencil_two_side_ext = has_extension("GL_EXT_stencil_two_side") && gl_entry.ActiveStencilFaceEXT &&
                             !off("no-stencil-two-side");
    c.depth_bounds = has_extension("GL_EXT_depth_bounds_test") && gl_entry.DepthBoundsEXT && !off("no-depth-bounds");
    c.framebuffer_blit = c.fbo && (at_least(c.gl_major, c.gl_minor, 3, 0) || has_extension("GL_EXT_framebuffer_blit")) &&
                         gl_entry.BlitFramebufferEXT && !off("no-framebuffer-blit");
    c.pbuffer_surfaces = offscreen_surfaces() != nullptr;
    c.forced_off = force_off;
    while (glGetError() != GL_NO_ERROR) {}
    return c;
}

namespace {

// describe() on OpenGL ES 2.0: each capability with the ES extension it is read from and the
// desktop path it maps onto.
std::string describe_es(const Caps& c) {
    std::ostringstream o;
    auto yn = [](bool b) { return b ? "yes" : "no "; };
    auto ext = [](const char* e) { return has_extension(e) ? std::string(e + 3) : std::string("no ") + (e + 3); };
    o << "GL_VENDOR      " << c.vendor << "\n"
      << "GL_RENDERER    " << c.renderer << "\n"
      << "GL_VERSION     " << c.version << " (read as OpenGL ES 2.0 and its extensions)\n"
      << "GLSL           " << c.glsl_version << "\n"
      << "capabilities on OpenGL ES 2.0 (the ES extension -> the desktop path it takes):\n"
      << "  " << yn(c.glsl120) << " GLSL ES 1.00             (the glsl120/ sources through the ES prelude), "
      << c.max_varying_components << " varying components\n"
      << "  " << yn(c.draw_buffers) << " multiple render targets  ("
      << (c.es_draw_buffers.empty() ? "no EXT_draw_buffers, no NV_draw_buffers" : c.es_draw_buffers.substr(3))
      << " -> mrt), max " << c.max_draw_buffers << "\n"
      << "  " << yn(c.depth_texture) << " depth textures           (" << ext("GL_OES_depth_texture") << " -> --depth texture)\n"
      << "  " << yn(c.shadow) << " depth comparison         (" << ext("GL_EXT_shadow_samplers") << " -> shadow2D; else packed maps)\n"
      << "  " << yn(c.fbo) << " render to texture        (framebuffer objects, core in ES 2.0 -> fbo)\n"
      << "  " << yn(c.npot) << " non-power-of-two         (" << ext("GL_OES_texture_npot") << " -> npot; else pow2)\n"
      << "  " << yn(c.texture_float) << " float targets            (" << ext("GL_OES_texture_float") << ", "
      << ext("GL_OES_texture_half_float") << ", " << ext("GL_EXT_color_buffer_half_float")
      << ": unsized half-float targets, not taken: float paths refuse)\n"
      << "  " << yn(c.texture_srgb) << " sRGB textures            (" << ext("GL_EXT_sRGB") << ")\n"
      << "  " << yn(c.occlusion_query) << " occlusion queries        (" << ext("GL_EXT_occlusion_query_boolean")
      << ": yes/no only, light_fragments not counted)\n"
      << "  " << yn(c.timer_query) << " timer queries            (wall clock)\n"
      << "  " << yn(c.stencil) << " stencil buffer           (8 bits in the main frame buffer)\n"
      << "  " << yn(c.packed_depth_stencil) << " depth-stencil targets    (" << ext("GL_OES_packed_depth_stencil") << ")\n"
      << "  " << yn(c.stencil_separate) << " two-sided stencil        (glStencilOpSeparate, core in ES 2.0)\n"
      << "  " << yn(c.framebuffer_blit) << " framebuffer blit         (" << ext("GL_NV_framebuffer_blit") << ", "
      << ext("GL_ANGLE_framebuffer_blit") << ")\n"
      << "  " << yn(c.frag_depth) << " gl_FragDepth             (" << ext("GL_EXT_frag_depth") << ")\n"
      << "  " << yn(c.software_rasterizer) << " CPU rasteriser           (llvmpipe, softpipe or swrast)\n";
    if (!c.forced_off.empty()) {
        o << "forced off:";
        for (auto& f : c.forced_off) o << " " << f;
        o << "\n";
    }
    return o.str();
}

}  // namespace

std::string describe(const Caps& c) {
    if (c.es) return describe_es(c);
    std::ostringstream o;
    auto yn = [](bool b) { return b ? "yes" : "no "; };
    o << "GL_VENDOR      " << c.vendor << "\n"
      << "GL_RENDERER    " << c.renderer << "\n"
      << "GL_VERSION     " << c.version << "\n"
      << "GLSL           " << c.glsl_version << "\n"
      << "capabilities (source extension):\n"
      << "  " << yn(c.glsl120) << " GLSL 1.20                (OpenGL 2.1)\n"
      << "  " << yn(c.glsl130) << " GLSL 1.30                (OpenGL 3.0: flat varyings), " << c.max_varying_components
      << " varying components\n"
      << "  " << yn(c.draw_buffers) << " multiple render targets  (ARB_draw_buffers), max "
      << c.max_draw_buffers << "\n"
      << "  " << yn(c.depth_texture) << " depth textures           (ARB_depth_texture)\n"
      << "  " << yn(c.shadow) << " depth comparison         (ARB_shadow)\n"
      << "  " << yn(c.fbo) << " render to texture        (EXT_framebuffer_object)\n"
      << "  " << yn(c.fbo_mixed_formats) << " mixed target formats     (ARB_framebuffer_object)\n"
      << "  " << yn(c.npot) << " non-power-of-two         (ARB_texture_non_power_of_two)\n"
      << "  " << yn(c.texture_float) << " float targets            (ARB_texture_float)\n"
      << "  " << yn(c.half_float) << " half-float targets       (ARB_half_float_pixel)\n"
      << "  " << yn(c.half_float_blend) << " half-float blending      (measured: 0.75 + 0.75 read back as 1.5)\n"
      << "  " << yn(c.float_blend) << " float blending           (measured, RGBA32F)\n"
      << "  " << yn(c.texture_srgb) << " sRGB textures            (EXT_texture_sRGB)\n"
      << "  " << yn(c.occlusion_query) << " occlusion queries        (ARB_occlusion_query)\n"
      << "  " << yn(c.pipeline_statistics) << " pipeline statistics      (ARB_pipeline_statistics_query)\n"
      << "  " << yn(c.timer_query) << " timer queries            (ARB_timer_query)\n"
      << "  " << yn(c.stencil) << " stencil buffer           (8 bits in the main frame buffer)\n"
      << "  " << yn(c.packed_depth_stencil) << " depth-stencil targets    (EXT_packed_depth_stencil)\n"
      << "  " << yn(c.stencil_separate) << " two-sided stencil        (glStencilOpSeparate, OpenGL 2.0)\n"
      << "  " << yn(c.stencil_two_side_ext) << " two-sided stencil        (EXT_stencil_two_side)\n"
      << "  " << yn(c.depth_bounds) << " depth bounds test        (EXT_depth_bounds_test)\n"
      << "  " << yn(c.framebuffer_blit) << " framebuffer blit         (EXT_framebuffer_blit)\n"
      << "  " << yn(c.pbuffer_surfaces) << " pbuffer surfaces         (EGL pbuffers for --render-target pbuffer)\n"
      << "  " << yn(c.software_rasterizer) << " CPU rasteriser           (llvmpipe, softpipe or swrast: the tiles defaults, forward's view vector)\n";
    if (!c.forced_off.empty()) {
        o << "forced off:";
        for (auto& f : c.forced_off) o << " " << f;
        o << "\n";
    }
    return o.str();
}

}  // namespace dsr
