// The option table (option_table.h). Each entry reads and writes one field of RenderOptions;
// the values and their spelling are exactly those `dsr render` has always taken.
#include "deferred/option_table.h"
#include "scene/user_file.h"

#include "dsr_text.h"
#include "scene/scene.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace dsr {

namespace {

std::string on_off(bool b) { return b ? "on" : "off"; }

std::vector<std::string> split_commas(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream ss(list);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

std::string format_number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

RenderOption choice(std::string name, std::vector<std::string> values, std::function<std::string(const RenderOptions&)> get,
                    std::function<void(RenderOptions&, const std::string&)> put) {
    return RenderOption{std::move(name), OptionKind::choice, std::move(values), 0, 0, true, std::move(get), std::move(put)};
}

// A float field of one ShaderOptions group (post, ssao): --NAME X in [lo, hi]; `arg` names X in help.
template <class Group>
RenderOption number(std::string name, std::string arg, float lo, float hi, Group ShaderOptions::*group, float Group::*field) {
    RenderOption o{std::move(name), OptionKind::number, {}, lo, hi, true,
                   [group, field](const RenderOptions& r) { return format_number(r.shader.*group.*field); },
                   [group, field](RenderOptions& r, const std::string& v) {
                       r.shader.*group.*field = std::strtof(v.c_str(), nullptr);
                   }};
    o.arg = std::move(arg);
    return o;
}

// A switch written --NAME / --no-NAME on a command line.
RenderOption toggle(std::string name, std::function<bool(const RenderOptions&)> get, std::function<void(RenderOptions&, bool)> put) {
    return RenderOption{std::move(name), OptionKind::toggle, {"on", "off"}, 0, 0, true,
                        [get](const RenderOptions& r) { return on_off(get(r)); },
                        [put](RenderOptions& r, const std::string& v) { put(r, v == "on"); }};
}

RenderOption with_help(RenderOption o, std::string help) {
    o.help = std::move(help);
    return o;
}

}  // namespace

const std::vector<SkipName>& skip_names() {
    static const std::vector<SkipName> names = {
        {"variants", "material_variants", &SkipOptions::material_variants},
        {"empty-lights", "empty_lights", &SkipOptions::empty_lights},
        {"light-depth-test", "light_depth_test", &SkipOptions::light_depth_test},
        {"light-sphere-test", "light_sphere_test", &SkipOptions::light_sphere_test},
        {"depth-prepass", "depth_prepass", &SkipOptions::depth_prepass},
        {"ambient-target", "ambient_target", &SkipOptions::ambient_target},
        {"ambient", "ambient_pass", &SkipOptions::ambient_pass},
        {"final", "final_pass", &SkipOptions::final_pass},
        {"gbuffer-clears", "gbuffer_clears", &SkipOptions::gbuffer_clears},
    };
    return names;
}

std::vector<std::string> skip_names_off(const SkipOptions& skip, const char* SkipName::*name) {
    std::vector<std::string> out;
    for (const SkipName& s : skip_names())
        if (!(skip.*s.on)) out.push_back(s.*name);
    return out;
}

namespace {

std::vector<RenderOption> make_table() {
    std::vector<RenderOption> t;
    auto add = [&t](RenderOption o, std::string help) { t.push_back(with_help(std::move(o), std::move(help))); };
    add(choice(
            "depth", {"auto", "texture", "packed", "position16", "position32"},
            [](const RenderOptions& r) { return std::string(depth_path_name(r.shader.depth)); },
            [](RenderOptions& r, const std::string& v) { r.shader.depth = depth_path_from_name(v); }),
        "depth path: texture (the G-buffer's depth texture, §3.3.2) or packed (depth packed into an RGB8 "
        "target, Listings 11 and 18), both rebuilding eye position from depth; position16 and position32 "
        "store eye-space position in an RGBA16F or RGBA32F target instead; auto: texture where the GL has "
        "ARB_depth_texture, else packed (never a position path)");
    add(choice(
            "depth-encoding", {"corrected", "literal", "linear", "log"},
            [](const RenderOptions& r) { return std::string(encoding_name(r.shader.encoding)); },
            [](RenderOptions& r, const std::string& v) { r.shader.encoding = encoding_from_name(v); }),
        "what the packed depth target holds: window depth packed so every 24-bit code survives the 8-bit "
        "target (corrected), window depth as Listings 11 and 18 pack it (literal, docs/errata.md), or "
        "linear or logarithmic eye depth (docs/accuracy.md)");
    add(choice(
            "gbuffer", {"rgba8", "half"}, [](const RenderOptions& r) { return r.shader.gbuffer_half ? "half" : "rgba8"; },
            [](RenderOptions& r, const std::string& v) { r.shader.gbuffer_half = v == "half"; }),
        "G-buffer target precision: RGBA8 as the tutorial (Figure 3), or half-float targets");
    add(switch_option("scissor", &ShaderOptions::scissor), "light scissor rectangles (§3.4.2, Listing 16)");
    add(choice(
            "light-geometry", {"auto", "quad", "volume", "stencil", "tiles", "screen"},
            [](const RenderOptions& r) { return std::string(light_geometry_name(r.shader.light_geometry)); },
            [](RenderOptions& r, const std::string& v) { r.shader.light_geometry = light_geometry_from_name(v); }),
        "how each light reaches its pixels: each by the cheapest of quad, volume and tiles as a cost model "
        "prices it (auto), the tutorial's scissored screen quad, the back faces of the "
        "light's volume mesh, a stencil-masked volume, or screen tiles with several lights a pass "
        "(docs/light_geometry.md); screen is LearnOpenGL's deferred demo's lighting pass, every light at every "
        "pixel in full-screen passes with no culling (the peer's algorithm, for comparison)");
    add(switch_option("depth-bounds", &ShaderOptions::depth_bounds),
        "quad: EXT_depth_bounds_test on each light's depth span (refused where the GL lacks it, as llvmpipe does)");
    add(choice(
            "render-target", {"auto", "fbo", "copy", "pbuffer"},
            [](const RenderOptions& r) {
                static const char* names[] = {"auto", "fbo", "copy", "pbuffer"};
                return std::string(names[int(r.shader.render_target)]);
            },
            [](RenderOptions& r, const std::string& v) {
                r.shader.render_target = v == "fbo" ? RenderTarget::fbo : v == "copy" ? RenderTarget::copy
                                         : v == "pbuffer" ? RenderTarget::pbuffer : RenderTarget::automatic;
            }),
        "where the G-buffer and P-buffers are drawn (§3.2's pPBuffer): framebuffer objects, the main "
        "buffer copied to textures, or EGL pbuffer surfaces copied to textures (needs --context egl); "
        "auto: fbo, else copy");
    add(integer_option("tile-size", 8, 512, &ShaderOptions::tile_size, true),
        "tiles: pixels per tile side; auto: 16 on a CPU rasteriser such as llvmpipe, else 32 (`dsr info` says which)");
    add(integer_option("tile-lights", 1, 32, &ShaderOptions::tile_lights, true),
        "tiles: lights per pass; auto: with --tile-fetch vertex as many as the varyings hold (16 on llvmpipe, 15 "
        "on an H100), else 32 on a CPU rasteriser, else 8");
    add(choice(
            "tile-plan", {"lists", "groups"},
            [](const RenderOptions& r) { return std::string(r.shader.tile_plan == TileGrouping::groups ? "groups" : "lists"); },
            [](RenderOptions& r, const std::string& v) { r.shader.tile_plan = v == "groups" ? TileGrouping::groups : TileGrouping::lists; }),
        "tiles: each tile its exact light list, or lights in screen-order groups drawn over the union of their tiles");
    add(choice(
            "tile-shape", {"points", "quads"},
            [](const RenderOptions& r) { return std::string(r.shader.tile_shape == TileShape::quads ? "quads" : "points"); },
            [](RenderOptions& r, const std::string& v) { r.shader.tile_shape = v == "quads" ? TileShape::quads : TileShape::points; }),
        "tiles: each whole tile drawn as a point of the tile's size, one square primitive (where the GL's points "
        "are as large as a tile, else a quad), or as a quad, two triangles, whose diagonal a rasteriser shades "
        "partly twice (the same image either way)");
    add(choice(
            "tile-fetch", {"auto", "vertex", "fragment"},
            [](const RenderOptions& r) {
                static const char* names[] = {"auto", "vertex", "fragment"};
                return std::string(names[int(r.shader.tile_fetch)]);
            },
            [](RenderOptions& r, const std::string& v) {
                r.shader.tile_fetch = v == "vertex" ? TileFetch::vertex : v == "fragment" ? TileFetch::fragment : TileFetch::automatic;
            }),
        "tiles: where a tile's lights are read from the batch's arrays: once a tile, by the vertex shader, into flat "
        "varyings (GLSL 1.30; up to 16 lights a pass, a program for each count; batches of point lights of the "
        "linear law or of one attenuation), or at every pixel, by the fragment shader; auto: vertex where the GL "
        "has GLSL 1.30, else fragment (the same image either way)");
    add(switch_option("tile-depth", &ShaderOptions::tile_depth),
        "tiles: leave out each tile's lights whose sphere misses the depth span of its surfaces (needs float targets)");
    add(choice(
            "lighting", {"equations", "listing"},
            [](const RenderOptions& r) { return r.shader.listing2_literal ? "listing" : "equations"; },
            [](RenderOptions& r, const std::string& v) { r.shader.listing2_literal = v == "listing"; }),
        "Listing 2 as Equations 1-5 say, or with its view and half vectors as printed");
    std::vector<std::string> skips;
    for (const SkipName& s : skip_names()) skips.push_back(s.flag);
    add(RenderOption{"no-skip", OptionKind::subset, skips, 0, 0, true,
                     [](const RenderOptions& r) {
                         const std::vector<std::string> off = skip_names_off(r.shader.skip, &SkipName::flag);
                         return off.empty() ? std::string("none") : joined(off, ",");
                     },
                     [](RenderOptions& r, const std::string& v) {
                         const std::vector<std::string> off = split_commas(v);
                         for (const SkipName& s : skip_names()) {
                             bool listed = false;
                             for (const std::string& k : off) listed |= k == s.flag;
                             r.shader.skip.*s.on = !listed;
                         }
                     }},
        "work the renderer skips where a scene does not need it, turned off: the tangent-space work and map "
        "reads a material lacks (variants), lights of zero colour or an empty scissor rectangle "
        "(empty-lights), pixels whose surface lies in front of or behind a light's sphere "
        "(light-depth-test) or outside it (light-sphere-test), the depth pre-pass where the last frame's "
        "depth complexity makes it pure cost (depth-prepass: the material pass writes depth itself), the "
        "ambient pass, its colours written by the material pass into P-buffer 0 as one more render target "
        "(ambient-target: where the GL has a draw buffer to spare, the diffuse target is RGBA8, not with "
        "--ssao nor the screen geometry, nor on a GPU where the depth hand-off can write it; `dsr info` "
        "says whether), else folded into the pass of a light drawn over the whole screen by a pass of "
        "its own (ambient: a directional light, or any with --scissor off; not where the light goes into "
        "a batch of the tiles; the screen geometry's first pass writes it; not with --ssao), or into the "
        "depth hand-off's pass in frames that hand off (ambient too; on a CPU rasteriser only where the "
        "hand-off is a pass anyway), the final pass where the image is read back at the buffers' size "
        "(final: P-buffer 0 read directly), the G-buffer's colour clears whose background value no later pass "
        "reads (gbuffer-clears: the specular target's, and the diffuse target's where the ambient term is written by "
        "the material pass or certainly by the depth hand-off, which tell a surface by the normal target; the "
        "G-buffer views draw the G-buffer again with every clear)");
    RenderOption view = choice(
        "view", view_names(), [](const RenderOptions& r) { return std::string(view_name(r.view)); },
        [](RenderOptions& r, const std::string& v) { r.view = view_from_name(v); });
    view.rebuild = false;  // every view reads buffers the frame already has (the bloom view: see resolved)
    add(view, "the buffer written instead of the final image: a G-buffer target (Figure 4), the anti-alias "
              "blur factor (Figure 8), the bloom blur (Figure 10c) or the AO buffer");
    RenderOption bloom = toggle("bloom", [](const RenderOptions& r) { return r.bloom == 1; },
                                [](RenderOptions& r, bool on) { r.bloom = on; });
    bloom.default_text = "the scene's post line";
    add(bloom, "bloom (§3.5.2): intense colours blurred at a lower resolution and added to the image");
    add(choice(
            "bloom-scale", {"2", "4"}, [](const RenderOptions& r) { return std::to_string(r.shader.post.bloom_scale); },
            [](RenderOptions& r, const std::string& v) { r.shader.post.bloom_scale = std::atoi(v.c_str()); }),
        "bloom buffers at 1/2 or 1/4 of the frame");
    add(choice(
            "bloom-taps", {"3", "5", "7", "9", "11", "13", "15"},
            [](const RenderOptions& r) { return std::to_string(r.shader.post.bloom_taps); },
            [](RenderOptions& r, const std::string& v) { r.shader.post.bloom_taps = std::atoi(v.c_str()); }),
        "blur taps (Listing 22's NUMPOINTS)");
    add(number("bloom-strength", "S", 0.0f, 16.0f, &ShaderOptions::post, &PostOptions::bloom_strength),
        "weight of the bloom added to the image (above 1 it adds what 1 adds: GL clamps the colour it scales)");
    add(choice(
            "bloom-mode", {"color", "listing"}, [](const RenderOptions& r) { return r.shader.post.bloom_listing ? "listing" : "color"; },
            [](RenderOptions& r, const std::string& v) { r.shader.post.bloom_listing = v == "listing"; }),
        "blur intense colours, or Listing 22 as printed (a grey dot(t,t) in both passes)");
    RenderOption aa = toggle("aa", [](const RenderOptions& r) { return r.aa == 1; }, [](RenderOptions& r, bool on) { r.aa = on; });
    aa.default_text = "the scene's post line";
    add(aa, "anti-alias (§3.5.1): a blur by Equation 7's edge factor");
    add(choice(
            "aa-source", {"normal", "depth", "both"},
            [](const RenderOptions& r) {
                const AaSource s = r.shader.post.aa_source;
                return s == AaSource::normal ? "normal" : s == AaSource::depth ? "depth" : "both";
            },
            [](RenderOptions& r, const std::string& v) {
                r.shader.post.aa_source = v == "normal" ? AaSource::normal : v == "depth" ? AaSource::depth : AaSource::both;
            }),
        "what the edge factor of Equation 7 measures: the normal target, depth, or both");
    add(choice(
            "aa-kernel", {"text", "listing"},
            [](const RenderOptions& r) { return r.shader.post.aa_kernel == AaKernel::listing ? "listing" : "text"; },
            [](RenderOptions& r, const std::string& v) {
                r.shader.post.aa_kernel = v == "listing" ? AaKernel::listing : AaKernel::text;
            }),
        "all 8 neighbours as the text says, or Listing 21's table of 4");
    add(number("aa-weight", "W", 0.0f, 8.0f, &ShaderOptions::post, &PostOptions::aa_weight),
        "largest anti-alias offset in pixels (Listing 21's weight)");
    // Screen-space ambient occlusion (docs/ssao.md): --ssao / --no-ssao, then its four parameters.
    add(toggle("ssao", [](const RenderOptions& r) { return r.shader.ssao.on; }, [](RenderOptions& r, bool on) { r.shader.ssao.on = on; }),
        "screen-space ambient occlusion scaling the ambient pass only (docs/ssao.md)");
    add(choice(
            "ssao-scale", {"1", "2"}, [](const RenderOptions& r) { return std::to_string(r.shader.ssao.scale); },
            [](RenderOptions& r, const std::string& v) { r.shader.ssao.scale = std::atoi(v.c_str()); }),
        "AO buffer at full (1) or half (2) resolution");
    add(number("ssao-radius", "R", 0.01f, 100.0f, &ShaderOptions::ssao, &SsaoOptions::radius),
        "hemisphere radius in eye-space units");
    add(number("ssao-strength", "S", 0.0f, 4.0f, &ShaderOptions::ssao, &SsaoOptions::strength),
        "ao = 1 - S x the occluded fraction");
    RenderOption samples{"ssao-samples", OptionKind::integer, {}, 4, 64, true,
                         [](const RenderOptions& r) { return std::to_string(r.shader.ssao.samples); },
                         [](RenderOptions& r, const std::string& v) { r.shader.ssao.samples = std::atoi(v.c_str()); }};
    add(samples, "hemisphere samples per pixel");
    // The forward stage after the lights (docs/forward.md).
    add(toggle("show-lights", [](const RenderOptions& r) { return r.shader.show_lights; },
               [](RenderOptions& r, bool on) { r.shader.show_lights = on; }),
        "an emissive marker at each point and spot light, drawn forward into P-buffer 0 after the lights, "
        "so bloom makes it glow");
    add(choice(
            "depth-handoff", {"auto", "blit", "pass"},
            [](const RenderOptions& r) { return std::string(depth_handoff_name(r.shader.depth_handoff)); },
            [](RenderOptions& r, const std::string& v) { r.shader.depth_handoff = depth_handoff_from_name(v); }),
        "how the G-buffer's depth reaches P-buffer 0 for the passes that test against it: "
        "EXT_framebuffer_blit or a gl_FragDepth pass; auto: blit where present (docs/forward.md)");
    // Shadow maps (docs/shadows.md): the scene's `shadow` lights, and what one lookup averages.
    RenderOption shadows{"shadows", OptionKind::on_off, {"on", "off"}, 0, 0, true,
                         [](const RenderOptions& r) { return on_off(r.shader.shadows.on); },
                         [](RenderOptions& r, const std::string& v) { r.shader.shadows.on = v == "on"; }};
    add(shadows, "shadow maps for the scene's lights that say `shadow` (on), or none whatever the scene says (off)");
    add(choice(
            "shadow-filter", {"hard", "pcf2", "pcf3", "pcf5"},
            [](const RenderOptions& r) { return std::string(shadow_filter_name(r.shader.shadows.filter)); },
            [](RenderOptions& r, const std::string& v) {
                r.shader.shadows.filter = v == "hard" ? ShadowFilter::hard : v == "pcf3" ? ShadowFilter::pcf3
                                          : v == "pcf5" ? ShadowFilter::pcf5 : ShadowFilter::pcf2;
            }),
        "what a shadow lookup averages: one comparison with the nearest texel (hard), 2x2 comparisons "
        "weighted bilinearly (pcf2: ARB_shadow's filtered compare where the GL has it), or 3x3 or 5x5 "
        "texels of those, averaged (pcf3, pcf5)");
    RenderOption reuse{"shadow-reuse", OptionKind::on_off, {"on", "off"}, 0, 0, true,
                       [](const RenderOptions& r) { return on_off(r.shader.shadows.reuse); },
                       [](RenderOptions& r, const std::string& v) { r.shader.shadows.reuse = v == "on"; }};
    add(reuse, "keep a light's shadow map from the last frame while neither the light nor anything in its "
               "views moved (on), or draw every map every frame (off: what the shadow stage costs)");
    // High dynamic range (docs/hdr.md): P-buffer 0's format, the final stage's tone mapping and
    // encodings, the colour maps' decoding.
    add(choice(
            "accum", {"rgba8", "half", "float"}, [](const RenderOptions& r) { return std::string(accum_format_name(r.shader.hdr.accum)); },
            [](RenderOptions& r, const std::string& v) {
                r.shader.hdr.accum = v == "half" ? AccumFormat::half : v == "float" ? AccumFormat::float32 : AccumFormat::rgba8;
            }),
        "P-buffer 0's format (and the post buffers that read it): RGBA8 as the tutorial, where light sums clip "
        "at 1, or RGBA16F / RGBA32F, where they add without clamping (needs float targets and float blending)");
    add(choice(
            "tonemap", {"none", "reinhard", "aces"}, [](const RenderOptions& r) { return std::string(tone_map_name(r.shader.hdr.tonemap)); },
            [](RenderOptions& r, const std::string& v) {
                r.shader.hdr.tonemap = v == "reinhard" ? ToneMap::reinhard : v == "aces" ? ToneMap::aces : ToneMap::none;
            }),
        "the final stage's operator: none (clamp; with the other defaults the tutorial's fixed-function final "
        "pass), Reinhard et al. 2002's L/(1+L) on luminance, or Narkowicz's fit of the ACES filmic curve");
    RenderOption exposure{"exposure", OptionKind::number, {"auto"}, -16.0f, 16.0f, true,
                          [](const RenderOptions& r) {
                              return r.shader.hdr.exposure_auto ? std::string("auto") : format_number(r.shader.hdr.exposure);
                          },
                          [](RenderOptions& r, const std::string& v) {
                              r.shader.hdr.exposure_auto = v == "auto";
                              r.shader.hdr.exposure = v == "auto" ? 0.0f : std::strtof(v.c_str(), nullptr);
                          }};
    exposure.arg = "E";
    add(exposure, "stops the linear colour is scaled by (2^E) before the operator; auto: the frame's mean log "
                  "luminance, from a reduced copy of P-buffer 0, brought to 0.18 (needs float targets)");
    add(choice(
            "output-encoding", {"linear", "srgb"}, [](const RenderOptions& r) { return r.shader.hdr.output_srgb ? "srgb" : "linear"; },
            [](RenderOptions& r, const std::string& v) { r.shader.hdr.output_srgb = v == "srgb"; }),
        "the image's encoding: linear values written as they are (the tutorial's), or sRGB-encoded in the final pass");
    add(choice(
            "textures", {"linear", "srgb"}, [](const RenderOptions& r) { return r.shader.hdr.textures_srgb ? "srgb" : "linear"; },
            [](RenderOptions& r, const std::string& v) { r.shader.hdr.textures_srgb = v == "srgb"; }),
        "colour maps as stored (linear, the tutorial's) or decoded from sRGB when sampled (EXT_texture_sRGB, else "
        "converted on upload into 16-bit targets); normal and specular maps are never decoded");
    add(number("bloom-threshold", "T", 0.0f, 64.0f, &ShaderOptions::post, &PostOptions::bloom_threshold),
        "with float accumulation, bloom's bright pass keeps the part of each colour whose luminance is above T "
        "(the RGBA8 path keeps Listing 22's selection)");
    return t;
}

}  // namespace

const char* shadow_filter_name(ShadowFilter f) {
    static const char* names[] = {"hard", "pcf2", "pcf3", "pcf5"};
    return names[int(f)];
}

RenderOption switch_option(std::string name, bool ShaderOptions::*field) {
    return RenderOption{std::move(name), OptionKind::on_off, {"on", "off"}, 0, 0, true,
                        [field](const RenderOptions& r) { return on_off(r.shader.*field); },
                        [field](RenderOptions& r, const std::string& v) { r.shader.*field = v == "on"; }};
}

RenderOption integer_option(std::string name, int lo, int hi, int ShaderOptions::*field, bool with_auto) {
    std::vector<std::string> words;
    if (with_auto) words.push_back("auto");  // stored as 0: the GL's default (choose_paths)
    return RenderOption{std::move(name), OptionKind::integer, words, float(lo), float(hi), true,
                        [field](const RenderOptions& r) {
                            return r.shader.*field == 0 ? std::string("auto") : std::to_string(r.shader.*field);
                        },
                        [field](RenderOptions& r, const std::string& v) {
                            r.shader.*field = v == "auto" ? 0 : std::atoi(v.c_str());
                        }};
}

ShaderOptions RenderOptions::resolved(const Scene& scene) const {
    ShaderOptions s = shader;
    s.post.bloom = bloom < 0 ? scene.post_bloom : bloom == 1;
    s.post.aa = aa < 0 ? scene.post_aa : aa == 1;
    if (view == View::bloom) s.post.bloom = true;  // the view shows the bloom blur
    if (view == View::ssao) s.ssao.on = true;      // the view shows the AO buffer
    for (const Material& m : scene.materials) s.forward_surfaces = s.forward_surfaces || m.transparent();
    for (const Light& l : scene.lights) s.shadow_lights = s.shadow_lights || (s.shadows.on && l.shadow.on);
    for (const Material& m : scene.materials) s.metal_rough = s.metal_rough || m.metal_rough();
    return s;
}

const std::vector<RenderOption>& render_options() {
    static const std::vector<RenderOption> t = make_table();
    return t;
}

const RenderOption* find_render_option(const std::string& name) {
    for (const RenderOption& o : render_options())
        if (o.name == name) return &o;
    return nullptr;
}

std::string check_render_option(const RenderOption& o, const std::string& v) {
    switch (o.kind) {
        case OptionKind::choice:
        case OptionKind::on_off:
        case OptionKind::toggle:
            for (const std::string& a : o.values)
                if (v == a) return "";
            return "expected " + joined(o.values, "|") + ", got " + quote(v);
        case OptionKind::number: {
            for (const std::string& a : o.values)  // words it also takes (auto)
                if (v == a) return "";
            char* end = nullptr;
            errno = 0;
            const double d = v.empty() ? 0 : std::strtod(v.c_str(), &end);
            if (v.empty() || errno != 0 || *end != '\0' || !(d >= o.lo && d <= o.hi))
                return "expected " + (o.values.empty() ? std::string() : joined(o.values, "|") + " or ") + "a number in [" + std::to_string(o.lo) + ", " + std::to_string(o.hi) + "], got " + quote(v);
            return "";
        }
        case OptionKind::integer: {
            for (const std::string& a : o.values)  // words it also takes (auto)
                if (v == a) return "";
            char* end = nullptr;
            errno = 0;
            const long n = v.empty() ? 0 : std::strtol(v.c_str(), &end, 10);
            if (v.empty() || errno != 0 || *end != '\0' || n < long(o.lo) || n > long(o.hi))
                return "expected " + (o.values.empty() ? std::string() : joined(o.values, "|") + " or ") +
                       "an integer in [" + std::to_string(long(o.lo)) + ", " + std::to_string(long(o.hi)) +
                       "], got " + quote(v);
            return "";
        }
        case OptionKind::subset: {
            if (v == "none") return "";
            const std::vector<std::string> items = split_commas(v);
            for (const std::string& k : items) {
                bool known = false;
                for (const std::string& a : o.values) known |= k == a;
                if (!known) return "expected " + joined(o.values, ", ") + " (comma-separated) or none, got " + quote(k);
            }
            if (items.empty()) return "expected " + joined(o.values, ", ") + " (comma-separated) or none, got " + quote(v);
            return "";
        }
    }
    return "unknown option kind";
}

std::string set_render_option(RenderOptions& ro, const RenderOption& o, const std::string& value) {
    std::string err = check_render_option(o, value);
    if (err.empty()) o.put(ro, value);
    return err;
}

std::string option_arg(const RenderOption& o) {
    switch (o.kind) {
        case OptionKind::choice:
        case OptionKind::on_off: return joined(o.values, "|");
        case OptionKind::toggle: return "";
        case OptionKind::number: return (o.values.empty() ? "" : joined(o.values, "|") + "|") + (o.arg.empty() ? "X" : o.arg);
        case OptionKind::integer: return (o.values.empty() ? "" : joined(o.values, "|") + "|") + (o.arg.empty() ? "N" : o.arg);
        case OptionKind::subset: return "LIST";
    }
    return "";
}

std::string option_range(const RenderOption& o) {
    switch (o.kind) {
        case OptionKind::number: return format_number(o.lo) + ".." + format_number(o.hi);
        case OptionKind::integer: return std::to_string(long(o.lo)) + ".." + std::to_string(long(o.hi));
        case OptionKind::subset: return joined(o.values, ", ") + " (comma-separated) or none";
        default: return "";
    }
}

std::string option_default(const RenderOption& o) { return o.default_text.empty() ? o.get(RenderOptions{}) : o.default_text; }

std::vector<std::string> render_option_flags() {
    std::vector<std::string> f;
    for (const RenderOption& o : render_options()) {
        f.push_back("--" + o.name);
        if (o.kind == OptionKind::toggle) f.push_back("--no-" + o.name);
    }
    return f;
}

}  // namespace dsr
