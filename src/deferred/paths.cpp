#include "deferred/paths.h"

#include <algorithm>
#include <sstream>

#include "dsr_error.h"

namespace dsr {

namespace {

// " (forced off: no-float)" when --caps hid it, so a refusal says it was asked for.
std::string forced_note(const Caps& caps, const char* name) {
    const auto& f = caps.forced_off;
    return std::find(f.begin(), f.end(), name) != f.end() ? std::string(" (forced off: ") + name + ")" : "";
}

// The targets' formats (Paths::gbuffer_formats) and the bytes a pixel of them holds.
void choose_gbuffer_formats(const Caps& caps, const ShaderOptions& opts, Paths& p) {
    const TargetFormat base = opts.gbuffer_half ? TargetFormat::rgba16f : TargetFormat::rgba8;
    p.gbuffer_formats.assign(size_t(p.gbuffer_targets), base);
    if (p.depth_path == DepthPath::position16) p.gbuffer_formats[3] = TargetFormat::rgba16f;
    if (p.depth_path == DepthPath::position32) p.gbuffer_formats[3] = TargetFormat::rgba32f;
    const TargetFormat widest = *std::max_element(p.gbuffer_formats.begin(), p.gbuffer_formats.end(),
                                                  [](TargetFormat a, TargetFormat b) {
                                                      return target_format_bytes(a) < target_format_bytes(b);
                                                  });
    if (!caps.fbo_mixed_formats &&
        std::any_of(p.gbuffer_formats.begin(), p.gbuffer_formats.end(), [&](TargetFormat f) { return f != widest; })) {
        p.gbuffer_formats.assign(p.gbuffer_formats.size(), widest);
        p.gbuffer_formats_note = std::string("every target ") + target_format_name(widest) +
                                 ": EXT_framebuffer_object without ARB_framebuffer_object wants one format per framebuffer";
    }
    p.gbuffer_depth_texture = p.depth_path == DepthPath::texture;
    p.gbuffer_bytes_per_pixel = 4;  // 24-bit depth, stored as D24X8
    for (TargetFormat f : p.gbuffer_formats) p.gbuffer_bytes_per_pixel += target_format_bytes(f);
}

// Paths::ambient_target: whether the material pass can write the ambient term, or why not.
void choose_ambient_target(const Caps& caps, const ShaderOptions& opts, Paths& p) {
    if (!opts.skip.ambient_target) return;
    const bool handoff_instead = p.ambient_in_handoff && !caps.software_rasterizer;
    const bool rgba8 = std::all_of(p.gbuffer_formats.begin(), p.gbuffer_formats.end(),
                                   [](TargetFormat f) { return f == TargetFormat::rgba8; });
    const char* why = opts.ssao.on                                    ? "SSAO scales the ambient pass alone"
                      : draws_own_ambient(p.light_geometry)           ? "the screen geometry writes the ambient itself"
                      : handoff_instead ? "on a GPU the depth hand-off's pass writes it where a frame hands off"
                      : !p.mrt                                        ? "it needs the material pass's multiple render targets"
                      : caps.max_draw_buffers <= p.gbuffer_targets    ? "the GL has no draw buffer beyond the G-buffer's"
                      : p.gbuffer_formats[1] != TargetFormat::rgba8   ? "the diffuse target is not RGBA8"
                      : !caps.fbo_mixed_formats && !(rgba8 && opts.hdr.accum == AccumFormat::rgba8)
                          ? "EXT_framebuffer_object without ARB_framebuffer_object wants one format per framebuffer"
                          : nullptr;
    p.ambient_target = why == nullptr;
    if (why) p.ambient_target_note = why;
}

}  // namespace

std::string accum_format_missing(const Caps& caps, bool fbo, AccumFormat a) {
    if (a == AccumFormat::rgba8) return "";
    const bool half = a == AccumFormat::half;
    if (!fbo) return "needs render to texture (EXT_framebuffer_object): without it P-buffer 0 is copied from the 8-bit main frame buffer" +
                     forced_note(caps, "no-fbo");
    if (!caps.texture_float || (half && !caps.half_float))
        return std::string("needs float targets (ARB_texture_float") + (half ? " and ARB_half_float_pixel" : "") +
               "), " + which_missing(caps, "no-float");
    if (half ? !caps.half_float_blend : !caps.float_blend)
        return std::string("needs additive blending into ") + (half ? "RGBA16F" : "RGBA32F") + " targets, " +
               which_missing(caps, "no-float-blend", "which this GL does not do (measured)");
    return "";
}

bool accum_format_ok(const Caps& caps, bool fbo, AccumFormat a) { return accum_format_missing(caps, fbo, a).empty(); }

Paths choose_paths(const Caps& caps, const ShaderOptions& opts) {
    Paths p;
    if (opts.depth == DepthPath::automatic)
        p.depth_path = caps.depth_texture ? DepthPath::texture : DepthPath::packed;
    else
        p.depth_path = opts.depth;
    // Figure 3: normal, diffuse, specular+shininess, and packed depth only when that path runs;
    // the position paths' eye-space position in the same fourth slot.
    const bool position = is_position_path(p.depth_path);
    p.gbuffer_targets = p.depth_path == DepthPath::packed || position ? 4 : 3;
    choose_gbuffer_formats(caps, opts, p);
    // MRT needs render-to-texture too: without framebuffer objects the main buffer has one
    // colour buffer (§3.2, one pass per target).
    // --render-target: fbo where asked or automatic and present; copy or pbuffer otherwise.
    p.fbo = caps.fbo && (opts.render_target == RenderTarget::automatic || opts.render_target == RenderTarget::fbo);
    p.pbuffer = opts.render_target == RenderTarget::pbuffer && caps.pbuffer_surfaces;
    p.mrt = p.fbo && caps.draw_buffers && caps.max_draw_buffers >= p.gbuffer_targets;
    p.pow2 = !caps.npot;
    p.count_fragments = caps.occlusion_query;
    p.depth = depth_path_name(p.depth_path);
    p.gbuffer = p.mrt ? "mrt" : "per-target";
    p.render_target = p.fbo ? "fbo" : p.pbuffer ? "pbuffer" : "copy";
    p.textures = p.pow2 ? "pow2" : "npot";

    // Light geometry (docs/light_geometry.md). Stencil needs a stencil buffer where P-buffer 0 is drawn: with
    // framebuffer objects a packed depth-stencil attachment, without them the main buffer's.
    p.light_geometry = opts.light_geometry;
    p.tile_size = opts.tile_size ? opts.tile_size : caps.software_rasterizer ? 16 : 32;
    // A CPU rasteriser runs the fragment shader on lanes of 8 pixels and reads an array at an
    // index it takes from a varying lane by lane, element by element: in the tiles' light shader
    // that read, its loop and the loop's masked last terms are a large share of the light stage
    // (docs/light_loop_cpu.md). Read once a tile by the vertex shader and handed on flat,
    // the lights cost the fragment shader a constant read, and each count of lights gets a program
    // of its own with the lights' terms in a row (light_geometry_tiles.cpp). A GPU gains too
    // (docs/tiles.md; docs/gpu_frame.md, "The tiles' light stage: shading").
    p.tile_vertex_lights = caps.glsl130 ? std::min(16, caps.max_varying_components / 8) : 0;
    const bool vertex_fetch = p.tile_vertex_lights > 0 && opts.tile_plan == TileGrouping::lists;
    p.tile_fetch_vertex = opts.tile_fetch == TileFetch::vertex ||
                          (opts.tile_fetch == TileFetch::automatic && vertex_fetch &&
                           (opts.tile_lights == 0 || opts.tile_lights <= p.tile_vertex_lights));
    p.tile_lights = opts.tile_lights                                  ? opts.tile_lights
                    : p.tile_fetch_vertex && p.tile_vertex_lights > 0 ? p.tile_vertex_lights
                    : caps.software_rasterizer                        ? 32
                                                                      : 8;
    // llvmpipe shades a 4x4 pixel block once for each triangle that covers part of it, so a tile's
    // quad pays for the blocks along its diagonal twice; a point is one square primitive (llvmpipe
    // rasterises points itself, as squares). Points are the faster on llvmpipe and on a GPU alike
    // (docs/tiles.md, "Tiles as points").
    p.tile_points = opts.tile_shape != TileShape::quads && float(p.tile_size) <= caps.max_point_size;
    if (opts.light_geometry == LightGeometry::stencil) {
        const char* missing = !caps.stencil ? "a stencil buffer"
                              : p.fbo && !caps.packed_depth_stencil ? "EXT_packed_depth_stencil"
                                                                       : nullptr;
        if (missing) {
            p.light_geometry = LightGeometry::volume;
            p.light_geometry_note = std::string("stencil falls back to volume: ") + missing + " is missing";
        } else {
            p.stencil_faces = caps.stencil_separate       ? Paths::StencilFaces::separate
                              : caps.stencil_two_side_ext ? Paths::StencilFaces::two_side_ext
                                                          : Paths::StencilFaces::one_sided;
        }
    }
    p.depth_bounds = opts.depth_bounds && p.light_geometry == LightGeometry::quad;
    p.accum_stencil = p.light_geometry == LightGeometry::stencil;
    p.forward_stage = opts.show_lights || opts.forward_surfaces;
    // auto: the hand-off runs in the frames where it draws some lights as volumes.
    p.accum_depth = p.light_geometry == LightGeometry::volume || p.light_geometry == LightGeometry::stencil ||
                    p.light_geometry == LightGeometry::automatic ||
                    p.depth_bounds || p.forward_stage;
    // The blit copies between two framebuffer objects (the copy and pbuffer targets have none),
    // and only between depth buffers of one format: EXT_framebuffer_blit makes a depth blit between
    // DEPTH_COMPONENT24 (the G-buffer's) and the stencil geometry's DEPTH24_STENCIL8 an
    // INVALID_OPERATION. Mesa lets it pass; dsr follows the spec and takes the pass there.
    p.depth_handoff = p.fbo && caps.framebuffer_blit && !p.accum_stencil && opts.depth_handoff != DepthHandoff::pass
                          ? DepthHandoff::blit
                          : DepthHandoff::pass;
    // On a CPU rasteriser a blit costs next to nothing and the pass more than the ambient pass it
    // replaces would (paths.h): there only a hand-off that is a pass anyway takes the ambient term.
    p.ambient_in_handoff = p.accum_depth && opts.skip.ambient_pass && !opts.ssao.on &&
                           !draws_own_ambient(p.light_geometry) &&
                           (!caps.software_rasterizer || p.depth_handoff == DepthHandoff::pass);
    choose_ambient_target(caps, opts, p);

    if (!caps.glsl120)
        p.refused = "GLSL 1.20 is required" +
                    (is_forced_off(caps, "no-glsl") ? ", " + which_missing(caps, "no-glsl")
                                                 : " and this GL offers " +
                                                       (caps.glsl_version.empty() ? std::string("none") : caps.glsl_version) +
                                                       " (GL " + caps.version + ")");
    else if (position && !caps.fbo)
        p.refused = std::string("--depth ") + p.depth +
                    " needs render to texture (EXT_framebuffer_object): without it the G-buffer is copied from the "
                    "8-bit main frame buffer" + forced_note(caps, "no-fbo");
    else if (position && !(caps.texture_float && (p.depth_path == DepthPath::position32 || caps.half_float)))
        p.refused = std::string("--depth ") + p.depth + " needs a float G-buffer target (ARB_texture_float" +
                    (p.depth_path == DepthPath::position16 ? " and ARB_half_float_pixel" : "") + "), " +
                    which_missing(caps, "no-float") + " (use --depth texture or packed)";
    else if (p.depth_path == DepthPath::texture && !caps.depth_texture)
        p.refused = "--depth texture needs ARB_depth_texture, " + which_missing(caps, "no-depth-texture", "which is missing") +
                    " (use --depth packed)";
    else if (opts.hdr.float_accum() && !accum_format_ok(caps, p.fbo, opts.hdr.accum))
        p.refused = "--accum " + std::string(accum_format_name(opts.hdr.accum)) + " " + accum_format_missing(caps, p.fbo, opts.hdr.accum);
    else if (opts.hdr.exposure_auto && !(caps.texture_float && p.fbo))
        p.refused = "--exposure auto reduces P-buffer 0's log luminance into a float target: it needs ARB_texture_float and "
                    "EXT_framebuffer_object" + forced_note(caps, "no-float") + forced_note(caps, "no-fbo");
    else if (opts.gbuffer_half && !(caps.half_float && caps.texture_float))
        p.refused = "half-float G-buffer targets need ARB_texture_float and ARB_half_float_pixel, " + which_missing(caps, "no-float");
    else if (opts.depth_bounds && !caps.depth_bounds)
        p.refused = "--depth-bounds on needs EXT_depth_bounds_test, " +
                    which_missing(caps, "no-depth-bounds", "which this GL lacks (llvmpipe has none)");
    else if (opts.render_target == RenderTarget::fbo && !caps.fbo)
        p.refused = "--render-target fbo needs EXT_framebuffer_object, " + which_missing(caps, "no-fbo");
    else if (opts.render_target == RenderTarget::pbuffer && !caps.pbuffer_surfaces)
        p.refused = "--render-target pbuffer needs pbuffer surfaces: run with --context egl (OSMesa has none)";
    else if (opts.depth_bounds && opts.light_geometry != LightGeometry::quad)
        p.refused = "--depth-bounds on applies to --light-geometry quad only";
    else if (opts.depth_handoff == DepthHandoff::blit && !(p.fbo && caps.framebuffer_blit))
        p.refused = std::string("--depth-handoff blit needs EXT_framebuffer_blit between framebuffer objects, ") +
                    (p.fbo ? which_missing(caps, "no-framebuffer-blit")
                           : "which the " + p.render_target + " render target has not") + " (use --depth-handoff pass)";
    else if (opts.depth_handoff == DepthHandoff::blit && p.accum_stencil)
        p.refused = "--depth-handoff blit: the stencil geometry's depth-stencil buffer and the G-buffer's depth differ in "
                    "format, and a depth blit between them is INVALID_OPERATION (use --depth-handoff pass or auto)";
    else if (draws_tiles(opts.light_geometry) &&
             (p.tile_size < 8 || p.tile_size > 512 || p.tile_lights < 1 || p.tile_lights > 32))
        p.refused = "tiles: tile size must be 8..512 and lights per pass 1..32";
    else if (draws_tiles(opts.light_geometry) && p.tile_fetch_vertex && !caps.glsl130)
        p.refused = "--tile-fetch vertex needs GLSL 1.30 (flat varyings), " + which_missing(caps, "no-glsl130");
    else if (draws_tiles(opts.light_geometry) && p.tile_fetch_vertex && opts.tile_plan != TileGrouping::lists)
        p.refused = "--tile-fetch vertex applies to --tile-plan lists (groups read their lights with a uniform count)";
    else if (draws_tiles(opts.light_geometry) && p.tile_fetch_vertex && p.tile_lights > p.tile_vertex_lights)
        p.refused = "--tile-fetch vertex holds at most " + std::to_string(p.tile_vertex_lights) +
                    " lights a pass on this GL (8 varying components a light, and 16), not " + std::to_string(p.tile_lights);
    return p;
}

std::string describe(const Paths& p) {
    std::ostringstream o;
    const char* depth = p.depth_path == DepthPath::texture  ? "texture (ARB_depth_texture)"
                        : p.depth_path == DepthPath::packed ? "packed (float_to_color into an RGB8 target, §3.3.2)"
                        : p.depth_path == DepthPath::position16
                            ? "position16 (eye-space position in an RGBA16F target, ARB_half_float_pixel)"
                            : "position32 (eye-space position in an RGBA32F target, ARB_texture_float)";
    std::string formats;
    for (TargetFormat f : p.gbuffer_formats) formats += std::string(formats.empty() ? "" : " ") + target_format_name(f);
    o << "  depth          " << depth << "\n  G-buffer       "
      << (p.mrt ? "mrt: one material pass into all " + std::to_string(p.gbuffer_targets) + " targets (ARB_draw_buffers)"
                : "per-target: one material pass per G-buffer target (§3.2)")
      << "\n  G-buffer bytes " << p.gbuffer_bytes_per_pixel << " per pixel (" << formats << " + 24-bit depth)";
    if (!p.gbuffer_formats_note.empty()) o << "; " << p.gbuffer_formats_note;
    o
      << "\n  render target  "
      << (p.fbo       ? "fbo: render to texture (EXT_framebuffer_object)"
          : p.pbuffer ? "pbuffer: one EGL pbuffer surface per buffer + glCopyTexSubImage2D"
                      : "copy: main buffer region + glCopyTexSubImage2D")
      << "\n  textures       "
      << (p.pow2 ? "pow2: targets padded, material maps rescaled to powers of two" : "npot: any size")
      << "\n  light counting " << (p.count_fragments ? "occlusion queries" : "off (no occlusion queries)")
      << "\n  light geometry " << light_geometry_name(p.light_geometry);
    if (p.light_geometry == LightGeometry::stencil) o << " (" << stencil_faces_name(p.stencil_faces) << " faces)";
    if (!p.light_geometry_note.empty()) o << " (" << p.light_geometry_note << ")";
    o << "\n  ambient        "
      << (p.ambient_target ? "written by the material pass into P-buffer 0 (render target " +
                                 std::to_string(p.gbuffer_targets) + "): no ambient pass"
                           : std::string(p.ambient_in_handoff ? "written by the depth hand-off's pass in frames that hand off, "
                                                                "else the ambient pass (Listing 15)"
                                                              : "ambient pass (Listing 15)") +
                                 (p.ambient_target_note.empty() ? std::string() : " (" + p.ambient_target_note + ")"));
    o << "\n  depth hand-off "
      << (!p.accum_depth ? "none (nothing tests against the scene's depth in P-buffer 0)"
          : p.depth_handoff == DepthHandoff::blit
              ? std::string("blit (EXT_framebuffer_blit of the G-buffer's depth buffer)") +
                    (p.ambient_in_handoff && !p.ambient_target ? "; a pass where it writes the ambient term" : "")
              : std::string("pass (a full-screen pass writing gl_FragDepth from the G-buffer's depth)"))
      << "\n";
    return o.str();
}

const char* stencil_faces_name(Paths::StencilFaces f) {
    switch (f) {
        case Paths::StencilFaces::separate: return "separate";
        case Paths::StencilFaces::two_side_ext: return "two-side-ext";
        case Paths::StencilFaces::one_sided: return "one-sided";
    }
    return "?";
}

const char* light_geometry_name(LightGeometry g) {
    switch (g) {
        case LightGeometry::quad: return "quad";
        case LightGeometry::volume: return "volume";
        case LightGeometry::stencil: return "stencil";
        case LightGeometry::tiles: return "tiles";
        case LightGeometry::screen: return "screen";
        case LightGeometry::automatic: return "auto";
    }
    return "?";
}

const char* depth_path_name(DepthPath d) {
    switch (d) {
        case DepthPath::texture: return "texture";
        case DepthPath::packed: return "packed";
        case DepthPath::position16: return "position16";
        case DepthPath::position32: return "position32";
        case DepthPath::automatic: return "auto";
    }
    return "?";
}

DepthPath depth_path_from_name(const std::string& n) {
    for (DepthPath d : {DepthPath::texture, DepthPath::packed, DepthPath::position16, DepthPath::position32,
                        DepthPath::automatic})
        if (n == depth_path_name(d)) return d;
    throw Error("depth path '" + n + "': expected auto, texture, packed, position16 or position32");
}

int target_format_bytes(TargetFormat f) {
    return f == TargetFormat::rgba8 ? 4 : f == TargetFormat::rgba16f ? 8 : 16;
}

const char* target_format_name(TargetFormat f) {
    return f == TargetFormat::rgba8 ? "RGBA8" : f == TargetFormat::rgba16f ? "RGBA16F" : "RGBA32F";
}

const char* accum_format_name(AccumFormat a) {
    return a == AccumFormat::rgba8 ? "rgba8" : a == AccumFormat::half ? "half" : "float";
}

const char* tone_map_name(ToneMap t) { return t == ToneMap::none ? "none" : t == ToneMap::reinhard ? "reinhard" : "aces"; }

const char* depth_handoff_name(DepthHandoff h) {
    switch (h) {
        case DepthHandoff::automatic: return "auto";
        case DepthHandoff::blit: return "blit";
        case DepthHandoff::pass: return "pass";
    }
    return "?";
}

DepthHandoff depth_handoff_from_name(const std::string& n) {
    for (DepthHandoff h : {DepthHandoff::automatic, DepthHandoff::blit, DepthHandoff::pass})
        if (n == depth_handoff_name(h)) return h;
    throw Error("depth hand-off '" + n + "': expected auto, blit or pass");
}

LightGeometry light_geometry_from_name(const std::string& n) {
    for (LightGeometry g : {LightGeometry::quad, LightGeometry::volume, LightGeometry::stencil, LightGeometry::tiles,
                            LightGeometry::screen, LightGeometry::automatic})
        if (n == light_geometry_name(g)) return g;
    throw Error("light geometry '" + n + "': expected quad, volume, stencil, tiles, screen or auto");
}

}  // namespace dsr
