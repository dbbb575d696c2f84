// The --caps table (cap_names.h). The effects are the fallbacks choose_paths (deferred/paths.h)
// takes; docs/legacy.md measures them.
#include "gl/cap_names.h"
#include "scene/user_file.h"

namespace dsr {

const std::vector<CapName>& cap_names() {
    static const std::vector<CapName> t = {
        {"no-mrt", "ARB_draw_buffers", "one G-buffer target per pass (§3.2 without multiple render targets)"},
        {"no-depth-texture", "ARB_depth_texture", "--depth auto takes the packed path (Listings 11, 18)"},
        {"no-shadow", "ARB_shadow", "shadow maps are packed into RGB8 and compared in the shader, as without depth textures"},
        {"no-fbo", "EXT_framebuffer_object", "buffers and shadow maps drawn in the main frame buffer and copied to textures"},
        {"no-arb-fbo", "ARB_framebuffer_object", "EXT_framebuffer_object's one format for every target of a framebuffer"},
        {"no-npot", "ARB_texture_non_power_of_two", "targets padded to powers of two"},
        {"no-float", "ARB_texture_float and ARB_half_float_pixel", "--gbuffer half, the position paths and --accum half/float are refused"},
        {"no-float-blend", "blending into float targets", "--accum half and float are refused"},
        {"no-srgb-texture", "EXT_texture_sRGB", "--textures srgb decodes colour maps on upload into RGBA16"},
        {"no-glsl", "GLSL 1.20", "dsr refuses to render, in one line"},
        {"no-glsl130", "GLSL 1.30", "the tiles read their lights at every pixel (--tile-fetch fragment)"},
        {"no-occlusion-query", "ARB_occlusion_query", "light_fragments is not counted (null in --stats)"},
        {"no-pipeline-stats", "ARB_pipeline_statistics_query",
         "light_invocations and light_evaluations are not counted (null in --stats)"},
        {"no-stencil", "the main frame buffer's 8-bit stencil", "--light-geometry stencil falls back to volume"},
        {"no-packed-depth-stencil", "EXT_packed_depth_stencil", "with framebuffer objects, --light-geometry stencil falls back to volume"},
        {"no-stencil-separate", "glStencilOpSeparate (OpenGL 2.0)", "--light-geometry stencil sets its two faces with EXT_stencil_two_side, else in two passes"},
        {"no-stencil-two-side", "glStencilOpSeparate and EXT_stencil_two_side", "--light-geometry stencil marks its two faces in two one-sided passes"},
        {"no-depth-bounds", "EXT_depth_bounds_test", "--depth-bounds on is refused"},
        {"no-framebuffer-blit", "EXT_framebuffer_blit", "the depth hand-off by a gl_FragDepth pass"},
    };
    return t;
}

bool is_cap_name(const std::string& name) {
    for (const CapName& c : cap_names())
        if (name == c.name) return true;
    return false;
}

std::string check_cap_names(const std::vector<std::string>& names) {
    for (const std::string& n : names) {
        if (is_cap_name(n)) continue;
        const std::vector<CapName>& t = cap_names();
        std::string list;
        for (size_t i = 0; i < t.size(); ++i) list += (i == 0 ? "" : i + 1 == t.size() ? " or " : ", ") + std::string(t[i].name);
        return "unknown capability " + quote(n) + " (expected " + list + ")";
    }
    return "";
}

std::vector<std::string> split_caps(const std::string& list) {
    std::vector<std::string> out;
    size_t a = 0;
    while (a <= list.size()) {
        size_t b = list.find(',', a);
        if (b == std::string::npos) b = list.size();
        if (b > a) out.push_back(list.substr(a, b - a));
        a = b + 1;
    }
    return out;
}

}  // namespace dsr
