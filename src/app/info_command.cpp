#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "analysis/terminal_text.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "deferred/light_cost.h"
#include "deferred/paths.h"
#include "deferred/shader_table.h"
#include "gl/caps.h"
#include "gl/rounding_probe.h"
#include "gl/surfaces.h"
#include "gl/frame_timer.h"
#include "gl/gpu_stamps.h"
#include "platform/context.h"
#include "platform/resources.h"

namespace dsr {

namespace {

// printf into `out`: info gathers its lines and prints them fitted to the terminal's width.
void appendf(std::string& out, const char* format, ...) {
    va_list ap, copy;
    va_start(ap, format);
    va_copy(copy, ap);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string line(size_t(n > 0 ? n : 0) + 1, '\0');
    std::vsnprintf(line.data(), line.size(), format, ap);
    va_end(ap);
    line.pop_back();
    out += line;
}

}  // namespace

int cmd_info(const std::vector<std::string>& argv) {
    InfoSettings flags;  // the info command's table (app/command_table.h)
    parse_command_line(info_command(flags), argv);
    auto ctx = create_context(context_desc(flags.context, 512, 512));  // big enough to time a pass (timing line)
    Caps caps = probe_caps(split_caps(caps_with_environment(flags.caps)));
    std::string out;
    appendf(out, "context        %s\n", ctx->description().c_str());
    // Which shader folder this binary compiles (resources.h): a binary moved away from its tree
    // reads the tree it was built from, which may since hold other sources.
    const std::string shaders = resource_dir("glsl120");
    appendf(out, "shaders        %s\n%s", shaders.c_str(), describe(caps).c_str());
    // The renderer's own chooser with `render`'s defaults (depth auto), so info cannot drift.
    ShaderOptions defaults;
    defaults.depth = DepthPath::automatic;
    const Paths paths = choose_paths(caps, defaults);
    appendf(out, "paths chosen (render's defaults, --depth auto):\n");
    if (!paths.refused.empty()) {
        appendf(out, "  none: %s; dsr cannot render here\n", paths.refused.c_str());
        std::fputs(wrap_lines(out).c_str(), stdout);
        return 0;
    }
    out += describe(paths);
    // What `--light-geometry stencil` and `--depth-bounds on` would get here.
    ShaderOptions stencil = defaults;
    stencil.light_geometry = LightGeometry::stencil;
    const Paths sp = choose_paths(caps, stencil);
    appendf(out, "  --light-geometry stencil: %s\n",
                sp.light_geometry == LightGeometry::stencil
                    ? (std::string("stencil, ") + stencil_faces_name(sp.stencil_faces) +
                       (sp.stencil_faces == Paths::StencilFaces::separate       ? " faces (glStencilOpSeparate)"
                        : sp.stencil_faces == Paths::StencilFaces::two_side_ext ? " faces (EXT_stencil_two_side)"
                                                                                : " faces (two passes, no two-sided stencil)"))
                          .c_str()
                    : sp.light_geometry_note.c_str());
    ShaderOptions tiles = defaults;
    tiles.light_geometry = LightGeometry::tiles;
    const Paths tp = choose_paths(caps, tiles);
    appendf(out, "  --light-geometry tiles: %d-pixel tiles, %d lights a pass (auto: %s), drawn as %s (points up to %g pixels),\n"
                "    their lights read %s\n",
                tp.tile_size, tp.tile_lights, caps.software_rasterizer ? "a CPU rasteriser's" : "a GPU's",
                tp.tile_points ? "points" : "quads", double(caps.max_point_size),
                tp.tile_fetch_vertex ? "once a tile by the vertex shader (GLSL 1.30 flat varyings)"
                                     : "at every pixel by the fragment shader");
    appendf(out, "  --light-geometry auto: each light by the cheapest path; the cost model's constants (%s),\n"
                "  each path's scaled by what its passes took in the frames before%s:\n%s",
                caps.software_rasterizer ? "a CPU rasteriser's" : "a GPU's",
                caps.software_rasterizer ? " (timed by glFinish and the wall clock)"
                : gpu_timestamps(caps)   ? " (timed by timestamp queries read a frame later)"
                                         : " (not here: no timestamp queries, the constants as they are)",
                describe(default_light_costs(caps.software_rasterizer)).c_str());
    appendf(out, "  --depth-bounds on: %s\n", caps.depth_bounds ? "EXT_depth_bounds_test" : "refused (no EXT_depth_bounds_test)");
    appendf(out, "  --render-target pbuffer: %s\n",
                offscreen_surfaces() ? ("EGL pbuffer surfaces; " + offscreen_surfaces()->bind_tex_image_note()).c_str()
                                     : "refused (this context has no pbuffer surfaces: --context egl)");
    for (AccumFormat a : {AccumFormat::half, AccumFormat::float32}) {  // docs/hdr.md
        const std::string missing = accum_format_missing(caps, paths.fbo, a);
        appendf(out, "  --accum %-5s   %s\n", accum_format_name(a),
                    missing.empty() ? (a == AccumFormat::half ? "RGBA16F P-buffer 0, additive blending measured unclamped"
                                                              : "RGBA32F P-buffer 0, additive blending measured unclamped")
                                    : ("refused: " + missing).c_str());
    }
    appendf(out, "  --textures srgb %s\n", caps.texture_srgb ? "EXT_texture_sRGB: colour maps decoded when sampled"
                                                           : "no EXT_texture_sRGB: colour maps decoded on upload into RGBA16");
    if (caps.es) {
        // The probes and the programs below draw with what this dialect has not been given yet.
        appendf(out, "  OpenGL ES 2.0: the rounding probe, the timing check and the programs are not built here yet (docs/gles2.md)\n");
        std::fputs(wrap_lines(out).c_str(), stdout);
        return 0;
    }
    if (caps.fbo) out += describe(probe_unorm8_rounding());
    const TimingCheck& t = choose_timing(caps, ctx->width(), ctx->height());
    appendf(out, "  timing         %s (%s", timing_name(t.source), t.reason.c_str());
    if (t.query_ms >= 0) appendf(out, "; same passes: %.3f ms by timer query, %.3f ms by wall clock", t.query_ms, t.wall_ms);
    appendf(out, ")\n");
    // The shader table's programs for those defaults, built here as the renderer builds them.
    const ShaderConfig programs = shader_config(caps, defaults);
    const ProgramSet built(shaders, programs);
    appendf(out, "programs (render's defaults, %zu compiled and linked):\n%s", built.size(),
                describe_programs(programs).c_str());
    std::fputs(wrap_lines(out).c_str(), stdout);
    return 0;
}

}  // namespace dsr
