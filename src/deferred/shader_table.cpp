// The shader table's rows (shader_table.h). A row's `used` and `defines` read only the
// configuration: the option ranges were checked where the options were parsed (option_table.cpp).
#include "deferred/shader_table.h"

#include <algorithm>
#include <sstream>

#include "deferred/gpu_scene.h"
#include "deferred/main_buffer_map.h"
#include "deferred/tile_plan.h"
#include "dsr_error.h"
#include "gl/rounding_probe.h"

namespace dsr {

ShaderConfig shader_config(const Caps& caps, const ShaderOptions& asked) {
    ShaderConfig c;
    c.caps = caps;
    c.paths = choose_paths(caps, asked);
    if (!c.paths.refused.empty()) throw Error(c.paths.refused);
    c.opts = asked;
    c.opts.depth = c.paths.depth_path;
    c.opts.tile_size = c.paths.tile_size, c.opts.tile_lights = c.paths.tile_lights;  // auto resolved
    const LightGeometry g = c.paths.light_geometry;
    const bool tiles = draws_tiles(g);
    const bool fold = c.opts.skip.ambient_pass && !c.opts.ssao.on;  // the light_fold rows
    // The batch the uniform arrays hold (tiles, auto's quads, the volume meshes, screen's lights a
    // draw): five vec4s a light within the fragment stage's uniform budget (GL 2.0 guarantees 64
    // vec4s; llvmpipe and NVIDIA give 1024), a few vec4s kept for the other uniforms, and below
    // tile_plan's empty-slot index 255.
    if (tiles || g == LightGeometry::screen || g == LightGeometry::volume) {
        // OpenGL ES 2.0 counts uniforms in vec4s (its GL_MAX_..._UNIFORM_VECTORS).
        auto components = [&c](GLenum desktop, GLenum es) {
            GLint n = 0;
            glGetIntegerv(c.caps.es ? es : desktop, &n);
            return c.caps.es ? 4 * n : n;
        };
        const GLint comps = components(GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, GL_MAX_FRAGMENT_UNIFORM_VECTORS);
        const bool groups = tiles && c.opts.tile_plan == TileGrouping::groups;
        c.tile_batch = groups ? c.opts.tile_lights : std::clamp((comps / 4 - 8) / 5, 1, 128);
        // The batched volume meshes (auto, volume) place each copy from the batch's positions in the
        // vertex stage too: one vec4 a light there, beside the matrices.
        if (g == LightGeometry::volume || g == LightGeometry::automatic) {
            const GLint vcomps = components(GL_MAX_VERTEX_UNIFORM_COMPONENTS, GL_MAX_VERTEX_UNIFORM_VECTORS);
            c.tile_batch = std::clamp(std::min(c.tile_batch, vcomps / 4 - 32), 1, 128);
        }
        // Shadowed lights in the batches (shadow.glsl SHADOW_SLOTS): a texture unit each after the
        // G-buffer's four, and twelve vec4s each of uniforms beside the batch's arrays (the atlas
        // form's region included).
        if (c.opts.shadow_lights) {
            GLint units = 0;
            glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
            const int room = (comps / 4 - 8 - 5 * c.tile_batch) / 12;
            c.shadow_slots = std::max(0, std::min({kShadowSlots, int(units) - kShadowUnit, room}));
        }
    }
    // P-buffer 0 is RGBA8: several lights summed in one pass are each rounded as their own pass
    // would be, as this GL rounds into RGBA8, measured once (gl/rounding_probe.h): llvmpipe rounds
    // t x 255 to nearest, an exact tie to even; a GPU may truncate t to 12 bits first, which rounds
    // up later than the half, and over the dozens of lights a pixel may get, the difference adds up
    // to many LSB (docs/gpu.md, "Images on a GPU"). The ambient fold likewise rounds the ambient
    // term and the light's as the ambient pass and the light's own pass would.
    // The material pass that writes the ambient term rounds the diffuse colour as the G-buffer's
    // RGBA8 target stores it, whatever P-buffer 0's format.
    if (((!c.opts.hdr.float_accum() && ((tiles && c.opts.tile_lights > 1) || fold)) || c.paths.ambient_target) &&
        c.paths.fbo) {
        const Unorm8Rounding& r = unorm8_rounding();
        c.rounding_measured = true;
        c.rounding_bits = unorm8_truncate_bits(r);
        if (c.rounding_bits < 0) c.tile_round = unorm8_round_offset(r);  // the fallback's quantize_round
    }
    return c;
}

namespace {

// The depth path and packed encoding (glsl120/depth_codec.glsl).
Defines depth_defines(const ShaderConfig& c) {
    const ShaderOptions& o = c.opts;
    if (o.depth == DepthPath::position16) return {"POSITION_TARGET", "POSITION16"};
    if (o.depth == DepthPath::position32) return {"POSITION_TARGET"};
    if (o.depth != DepthPath::packed) return {};
    Defines d = {"PACKED_DEPTH"};
    if (o.encoding == DepthEncoding::literal) d.push_back("ENC_LITERAL");
    if (o.encoding == DepthEncoding::linear) d.push_back("ENC_LINEAR");
    if (o.encoding == DepthEncoding::log) d.push_back("ENC_LOG");
    return d;
}

Defines with(Defines d, std::initializer_list<std::string> more) {
    d.insert(d.end(), more.begin(), more.end());
    return d;
}

// The light pass (light.frag, §3.4.3): Listing 2 as printed or as the equations say, and the
// in-shader rejections of the skips.
Defines light_defines(const ShaderConfig& c, bool rejections = true) {
    Defines d = depth_defines(c);
    if (c.opts.metal_rough) d.push_back("METAL_ROUGH");  // the material model per pixel (lighting.glsl)
    if (c.opts.listing2_literal) d.push_back("LISTING2_LITERAL");
    if (rejections && c.opts.skip.light_depth_test) d.push_back("LIGHT_DEPTH_TEST");
    if (rejections && c.opts.skip.light_sphere_test) d.push_back("LIGHT_SPHERE_TEST");
    return d;
}

// quantize.glsl's model of this GL's rounding into RGBA8, where it was measured.
Defines quantize_defines(const ShaderConfig& c) {
    if (!c.rounding_measured) return {};
    Defines d = {"QUANTIZE_8BIT"};
    if (c.rounding_bits > 0) d.push_back("QUANTIZE_TRUNCATE " + std::to_string(1 << c.rounding_bits) + ".0");
    if (c.rounding_bits == 0) d.push_back("QUANTIZE_TIES_EVEN");
    return d;
}

// The ambient fold's light pass (light.frag AMBIENT_FOLD), each term rounded as its pass would be
// (into RGBA8: a float P-buffer 0 rounds neither).
Defines fold_defines(const ShaderConfig& c) {
    Defines d = light_defines(c);
    d.push_back("AMBIENT_FOLD");
    if (c.opts.hdr.float_accum()) return d;
    const Defines q = quantize_defines(c);
    d.insert(d.end(), q.begin(), q.end());
    return d;
}

// The material pass (material.frag): the depth path's target, and where Paths::ambient_target, the
// ambient term into P-buffer 0 as the render target after the G-buffer's (AMBIENT_TARGET n), the
// diffuse colour rounded as the G-buffer stores it.
Defines material_defines(const ShaderConfig& c, std::initializer_list<std::string> more) {
    Defines d = with(depth_defines(c), more);
    if (!c.paths.ambient_target) return d;
    d.push_back("AMBIENT_TARGET " + std::to_string(c.paths.gbuffer_targets));
    const Defines q = quantize_defines(c);
    d.insert(d.end(), q.begin(), q.end());
    return d;
}

// light_tiles.frag: up to tile_lights lights a pass out of a batch in uniform arrays.
Defines tiles_defines(const ShaderConfig& c) {
    Defines d = light_defines(c);
    d.push_back("MAX_LIGHTS " + std::to_string(c.opts.tile_lights));
    if (c.opts.tile_plan == TileGrouping::lists)  // groups: the light count is a uniform instead
        d.push_back("ID_VECS " + std::to_string(tile_id_vecs(c.opts.tile_lights)));
    d.push_back("BATCH " + std::to_string(c.tile_batch));
    // A float P-buffer 0 clamps no pass (docs/hdr.md): each term is added as it is.
    if (c.opts.hdr.float_accum()) d.push_back("ACCUM_FLOAT");
    // One light a pass needs no emulation: the blend rounds it as quad's does.
    if (!c.opts.hdr.float_accum() && c.opts.tile_lights > 1) {
        d.push_back("QUANTIZE_8BIT");
        if (c.rounding_measured && c.rounding_bits > 0)
            d.push_back("QUANTIZE_TRUNCATE " + std::to_string(1 << c.rounding_bits) + ".0");
        if (c.rounding_measured && c.rounding_bits == 0) d.push_back("QUANTIZE_TIES_EVEN");  // predicted_threshold's model
    }
    return d;
}

// light_screen.frag: a batch of lights in uniform arrays, every one at every pixel.
Defines screen_defines(const ShaderConfig& c) {
    return with(light_defines(c, false), {"BATCH " + std::to_string(c.tile_batch)});
}

Defines blur_defines(const ShaderConfig& c, bool select) {
    const PostOptions& p = c.opts.post;
    Defines d = {"NUMPOINTS " + std::to_string(p.bloom_taps)};
    if (p.bloom_listing) d.push_back("LISTING");
    else if (select && c.opts.hdr.float_accum()) d.push_back("SELECT_THRESHOLD");  // docs/hdr.md
    else if (select) d.push_back("SELECT");
    return d;
}

Defines aa_defines(const ShaderConfig& c) {
    const PostOptions& p = c.opts.post;
    Defines d = depth_defines(c);
    if (p.aa_source != AaSource::depth) d.push_back("SOURCE_NORMAL");
    if (p.aa_source != AaSource::normal) d.push_back("SOURCE_DEPTH");
    if (p.aa_kernel == AaKernel::listing) d.push_back("LISTING_KERNEL");
    return d;
}

// tonemap.frag: the operator and the output encoding.
Defines tonemap_defines(const ShaderConfig& c) {
    Defines d;
    if (c.opts.hdr.tonemap == ToneMap::reinhard) d.push_back("TONEMAP_REINHARD");
    if (c.opts.hdr.tonemap == ToneMap::aces) d.push_back("TONEMAP_ACES");
    if (c.opts.hdr.output_srgb) d.push_back("OUTPUT_SRGB");
    return d;
}

bool always(const ShaderConfig&) { return true; }
bool material_variants(const ShaderConfig& c) { return c.opts.skip.material_variants; }
bool geometry_is(const ShaderConfig& c, LightGeometry g) { return c.paths.light_geometry == g; }
bool is_auto(const ShaderConfig& c) { return geometry_is(c, LightGeometry::automatic); }
// Which geometries draw with which programs: volume and stencil draw the lights their meshes
// cannot serve as quads; auto draws each light as a quad (in batches), a volume or in tiles.
bool uses_quads(const ShaderConfig& c) {
    return geometry_is(c, LightGeometry::quad) || geometry_is(c, LightGeometry::volume) ||
           geometry_is(c, LightGeometry::stencil);
}
bool uses_volume(const ShaderConfig& c) { return geometry_is(c, LightGeometry::volume) || is_auto(c); }
// The auto geometry submits its quads in batches (LightQuadBatch); quad keeps Listing 17's loop.
bool uses_batches(const ShaderConfig& c) { return is_auto(c); }
Defines batch_defines(const ShaderConfig& c) { return with(light_defines(c), {"BATCH " + std::to_string(c.tile_batch)}); }
bool uses_stencil(const ShaderConfig& c) { return geometry_is(c, LightGeometry::stencil); }
bool uses_tiles(const ShaderConfig& c) { return draws_tiles(c.paths.light_geometry); }
// The tiles' vertex fetch (Paths::tile_fetch_vertex): batches of point lights of one law read once
// a tile; the table's programs hold tile_lights lights, light_geometry_tiles.cpp builds one for
// each count it draws.
bool uses_tile_fetch_vertex(const ShaderConfig& c) { return uses_tiles(c) && c.paths.tile_fetch_vertex; }
Defines point_linear(Defines d) { return with(std::move(d), {"LIGHT_POINT_ONLY"}); }
Defines point_inverse(Defines d) { return with(std::move(d), {"LIGHT_POINT_INVERSE"}); }
bool uses_screen(const ShaderConfig& c) { return geometry_is(c, LightGeometry::screen); }
// The ambient fold where it gives the unfolded image's bytes: a 32-bit float P-buffer 0 (the same
// float sums), or this GL's rounding into RGBA8 measured (shader_config) so each term is rounded as its
// own pass would be. Elsewhere it would round once instead of twice: without framebuffer objects (no
// probe) bloom's bright pass made that 1 LSB into 3, and into half floats it was 1.12 LSB off.
bool ambient_fold(const ShaderConfig& c) {
    return c.opts.skip.ambient_pass && !c.opts.ssao.on &&
           (c.opts.hdr.accum == AccumFormat::float32 || (!c.opts.hdr.float_accum() && c.rounding_measured));
}
// The tiles' depth spans need a float target behind a framebuffer object; without them the plan
// runs without depth culling.
bool tile_depth(const ShaderConfig& c) {
    return uses_tiles(c) && c.opts.tile_depth && c.caps.fbo && c.caps.texture_float && c.paths.fbo;
}
bool tile_depth_passes(const ShaderConfig& c) { return tile_depth(c) && !tile_spans_by_readback(c); }

// Shadow maps (shadow_stage.h, glsl120/shadow.glsl): built only for scenes with shadowed lights.
bool shadows(const ShaderConfig& c) { return c.opts.shadow_lights; }
// Depth textures compared by ARB_shadow where the GL has both (and, without framebuffer objects, a
// main frame buffer of 24 depth bits to copy them from), else depth packed in RGB8.
bool shadow_packed(const ShaderConfig& c) { return shadow_maps_packed(c.caps); }
// The batched geometries' shadowed forms, where a batch can hold shadowed lights.
bool tiles_shadow(const ShaderConfig& c) { return shadows(c) && uses_tiles(c) && c.shadow_slots > 0; }
bool screen_shadow(const ShaderConfig& c) { return shadows(c) && uses_screen(c) && c.shadow_slots > 0; }
std::string shadow_slots(const ShaderConfig& c) { return "SHADOW_SLOTS " + std::to_string(c.shadow_slots); }
// Their maps copied into one atlas a batch (shadow_atlas.h): the copies need framebuffer objects.
bool tiles_shadow_atlas(const ShaderConfig& c) { return tiles_shadow(c) && c.caps.fbo; }
bool screen_shadow_atlas(const ShaderConfig& c) { return screen_shadow(c) && c.caps.fbo; }
Defines shadow_defines(Defines d, const ShaderConfig& c) {
    const Defines s = shadow_lookup_defines(shadow_packed(c), c.opts.shadows.filter);
    d.insert(d.end(), s.begin(), s.end());
    return d;
}

std::string tile_size(const ShaderConfig& c) { return "TILE_SIZE " + std::to_string(c.opts.tile_size); }

}  // namespace

bool tile_depth_culling(const ShaderConfig& c) { return tile_depth(c); }

Defines surface_defines(int surface) {
    Defines d;
    if (surface & kSurfaceTwoSided) d.push_back("TWO_SIDED");
    if (surface & kSurfaceColors) d.push_back("VERTEX_COLOR");
    if (surface & kSurfaceCutOut) d.push_back("CUT_OUT");
    if (surface & kMaterialMetalRough) d.push_back("METAL_ROUGH_MATERIAL");
    return d;
}
bool tile_spans_by_readback(const ShaderConfig& c) {
    return tile_depth(c) && c.caps.software_rasterizer && c.paths.depth_path == DepthPath::texture;
}

Defines shadow_lookup_defines(bool packed, ShadowFilter filter) {
    Defines d = {"SHADOW"};
    if (packed) d.push_back("SHADOW_PACKED");
    if (filter == ShadowFilter::hard) d.push_back("SHADOW_HARD");
    if (filter == ShadowFilter::pcf3) d.push_back("SHADOW_TAPS 3");
    if (filter == ShadowFilter::pcf5) d.push_back("SHADOW_TAPS 5");
    return d;
}

const std::vector<ShaderRow>& shader_rows() {
    using C = const ShaderConfig&;
    static const std::vector<ShaderRow> rows = {
        // Geometry stage (§3.3, Listing 9). Without the variants skip every material takes the
        // full shader (normal map and specular map read), as a single-shader renderer would. A
        // two-sided, vertex-coloured or cut-out surface takes its row with surface_defines added,
        // built when a scene first draws one (geometry_stage.cpp).
        {"material", "material.vert", "material.frag", "G-buffer, normal-mapped material (Listing 9)", always,
         [](C c) { return material_defines(c, {"NORMAL_MAP"}); }, true},
        {"material_no_specular", "material.vert", "material.frag", "G-buffer, normal map, no specular",
         material_variants, [](C c) { return material_defines(c, {"NORMAL_MAP", "NO_SPECULAR"}); }, true},
        {"material_flat", "material.vert", "material.frag", "G-buffer, no normal map", material_variants,
         [](C c) { return material_defines(c, {}); }, true},
        {"material_flat_no_specular", "material.vert", "material.frag", "G-buffer, no normal map, no specular",
         material_variants, [](C c) { return material_defines(c, {"NO_SPECULAR"}); }, true},
        // Lighting stage (§3.4): each light program in three forms (LightShader, light_pass.h
        // LightPrograms), so a light pays only for its own type and law: any light (type and law
        // selected per pixel), the tutorial's point lights with Equation 2 (LIGHT_POINT_ONLY), and
        // point lights with the attenuation law (LIGHT_POINT_INVERSE).
        {"light", "light.vert", "light.frag", "light pass, any light (Listing 20)", uses_quads,
         [](C c) { return light_defines(c); }},
        {"light_point", "light.vert", "light.frag", "light pass, the tutorial's point lights", uses_quads,
         [](C c) { return point_linear(light_defines(c)); }},
        {"light_point_inverse", "light.vert", "light.frag", "light pass, point lights, attenuation law", uses_quads,
         [](C c) { return point_inverse(light_defines(c)); }},
        {"light_batch", "light.vert", "light.frag", "light quads in batches, any light", uses_batches,
         [](C c) { return batch_defines(c); }},
        {"light_batch_point", "light.vert", "light.frag", "light quads in batches, the tutorial's point lights",
         uses_batches, [](C c) { return point_linear(batch_defines(c)); }},
        {"light_batch_point_inverse", "light.vert", "light.frag", "light quads in batches, point lights, attenuation law",
         uses_batches, [](C c) { return point_inverse(batch_defines(c)); }},
        // The ambient pass folded into a full-screen light's pass (lighting_stage.cpp): the light
        // pass that also writes the background and Listing 15's ambient term, blending off. Not
        // with SSAO, which scales the ambient pass alone.
        // In the three forms of the light passes (LightPrograms), so a light of the attenuation law
        // is not folded through the general form's selection.
        {"light_fold", "light.vert", "light.frag", "full-screen light pass with the ambient pass folded in",
         ambient_fold, [](C c) { return fold_defines(c); }},
        {"light_fold_point", "light.vert", "light.frag", "the same, the tutorial's point lights", ambient_fold,
         [](C c) { return point_linear(fold_defines(c)); }},
        {"light_fold_point_inverse", "light.vert", "light.frag", "the same, point lights, attenuation law",
         ambient_fold, [](C c) { return point_inverse(fold_defines(c)); }},
        {"light_volume", "light.vert", "light.frag", "light pass over a volume mesh", uses_volume,
         [](C c) { return with(light_defines(c), {"VOLUME"}); }},
        {"light_volume_point", "light.vert", "light.frag", "volume mesh, the tutorial's point lights", uses_volume,
         [](C c) { return point_linear(with(light_defines(c), {"VOLUME"})); }},
        {"light_volume_point_inverse", "light.vert", "light.frag", "volume mesh, point lights, attenuation law",
         uses_volume, [](C c) { return point_inverse(with(light_defines(c), {"VOLUME"})); }},
        // The volume meshes of many point lights in one draw (LightVolumeBatch, light_mesh.h).
        {"light_volume_batch", "light.vert", "light.frag", "volume meshes in batches, any light", uses_volume,
         [](C c) { return with(batch_defines(c), {"VOLUME", "VOLUME_BATCH"}); }},
        {"light_volume_batch_point", "light.vert", "light.frag", "volume meshes in batches, the tutorial's point lights",
         uses_volume, [](C c) { return point_linear(with(batch_defines(c), {"VOLUME", "VOLUME_BATCH"})); }},
        {"light_volume_batch_point_inverse", "light.vert", "light.frag",
         "volume meshes in batches, point lights, attenuation law", uses_volume,
         [](C c) { return point_inverse(with(batch_defines(c), {"VOLUME", "VOLUME_BATCH"})); }},
        // Behind the stencil test the in-shader rejections are redundant (the stencil marks surfaces
        // inside the volume) and harmful: a shader that may discard, in a pass that writes the
        // stencil (zeroing it for the next light), makes the GPU test the stencil after the shader
        // instead of before it, running the shader at pixels the stencil would reject
        // (docs/gpu_frame.md, "Choices these costs decide").
        // Without them a pixel just outside the sphere adds att = 0.
        {"light_stencil", "light.vert", "light.frag", "light pass behind the stencil mask", uses_stencil,
         [](C c) { return with(light_defines(c, false), {"VOLUME"}); }},
        {"light_stencil_point", "light.vert", "light.frag", "stencil mask, the tutorial's point lights", uses_stencil,
         [](C c) { return point_linear(with(light_defines(c, false), {"VOLUME"})); }},
        {"light_stencil_point_inverse", "light.vert", "light.frag", "stencil mask, point lights, attenuation law",
         uses_stencil, [](C c) { return point_inverse(with(light_defines(c, false), {"VOLUME"})); }},
        // Shadowed lights (a scene's `shadow` lights): the light pass with the shadow lookup, any
        // light, drawn as the light's quad by quad (and by auto for those it gives to quads, and
        // by tiles and screen where a batch holds no shadow map); volume, stencil and auto's
        // volumes have a volume form, tiles and screen a batched form with up to shadow_slots maps.
        // Scenes without shadows build none of these.
        {"light_shadow", "light.vert", "light.frag", "light pass with its shadow map, any light", shadows,
         [](C c) { return shadow_defines(light_defines(c), c); }},
        {"light_volume_shadow", "light.vert", "light.frag", "volume mesh with its shadow map",
         [](C c) { return shadows(c) && uses_volume(c); },
         [](C c) { return shadow_defines(with(light_defines(c), {"VOLUME"}), c); }},
        {"light_stencil_shadow", "light.vert", "light.frag", "stencil mask with its shadow map",
         [](C c) { return shadows(c) && uses_stencil(c); },
         [](C c) { return shadow_defines(with(light_defines(c, false), {"VOLUME"}), c); }},
        {"shadow_caster", "shadow_caster.vert", "shadow_caster.frag", "shadow maps: depth from the light", shadows,
         [](C c) { return shadow_packed(c) ? Defines{"SHADOW_PACKED"} : Defines{}; }},
        {"light_tiles", "light.vert", "light_tiles.frag", "tiles: several lights a pass, any type", uses_tiles,
         tiles_defines},
        {"light_tiles_point", "light.vert", "light_tiles.frag", "tiles: the tutorial's point lights", uses_tiles,
         [](C c) { return point_linear(tiles_defines(c)); }},
        {"light_tiles_point_inverse", "light.vert", "light_tiles.frag", "tiles: point lights, attenuation law",
         uses_tiles, [](C c) { return point_inverse(tiles_defines(c)); }},
        {"light_tiles_flat_point", "light_tiles_flat.vert", "light_tiles_flat.frag",
         "tiles, lights read by the vertex shader: the tutorial's point lights", uses_tile_fetch_vertex,
         [](C c) { return point_linear(tiles_defines(c)); }},
        {"light_tiles_flat_point_inverse", "light_tiles_flat.vert", "light_tiles_flat.frag",
         "tiles, lights read by the vertex shader: point lights of one attenuation", uses_tile_fetch_vertex,
         [](C c) { return with(point_inverse(tiles_defines(c)), {"ATT_SHARED"}); }},
        {"light_tiles_shadow", "light.vert", "light_tiles.frag", "tiles: any light, some with shadow maps",
         tiles_shadow, [](C c) { return with(shadow_defines(tiles_defines(c), c), {shadow_slots(c)}); }},
        {"light_tiles_shadow_atlas", "light.vert", "light_tiles.frag", "tiles: the same, the batch's maps in one atlas",
         tiles_shadow_atlas,
         [](C c) { return with(shadow_defines(tiles_defines(c), c), {shadow_slots(c), "SHADOW_ATLAS"}); }},
        // LearnOpenGL's deferred demo's lighting pass (light_geometry_screen.cpp): every light of a
        // batch at every pixel, no in-shader rejections; in the three forms, as the demo's shader
        // is written for its one kind of light.
        {"light_screen", "light.vert", "light_screen.frag", "screen: every light at every pixel, any type", uses_screen,
         screen_defines},
        {"light_screen_point", "light.vert", "light_screen.frag", "screen: the tutorial's point lights", uses_screen,
         [](C c) { return point_linear(screen_defines(c)); }},
        {"light_screen_point_inverse", "light.vert", "light_screen.frag", "screen: point lights, attenuation law",
         uses_screen, [](C c) { return point_inverse(screen_defines(c)); }},
        {"light_screen_shadow", "light.vert", "light_screen.frag", "screen: any light, some with shadow maps",
         screen_shadow, [](C c) { return with(shadow_defines(screen_defines(c), c), {shadow_slots(c)}); }},
        {"light_screen_shadow_atlas", "light.vert", "light_screen.frag", "screen: the same, the batch's maps in one atlas",
         screen_shadow_atlas,
         [](C c) { return with(shadow_defines(screen_defines(c), c), {shadow_slots(c), "SHADOW_ATLAS"}); }},
        {"tile_depth", "post.vert", "tile_depth.frag", "tiles: each tile column's depth span per row", tile_depth_passes,
         [](C c) { return with(depth_defines(c), {tile_size(c)}); }},
        {"tile_depth_reduce", "post.vert", "tile_depth_reduce.frag", "tiles: a tile's rows together", tile_depth_passes,
         [](C c) { return Defines{tile_size(c)}; }},
        // The depth hand-off's pass (depth_handoff.h), where it is not a blit.
        {"depth_copy", "post.vert", "depth_copy.frag", "depth hand-off: gl_FragDepth from the G-buffer",
         [](C c) { return c.paths.accum_depth && c.paths.depth_handoff == DepthHandoff::pass; },
         [](C c) { return depth_defines(c); }},
        // The same pass writing the ambient term too (Paths::ambient_in_handoff: a pass hand-off only).
        {"depth_copy_ambient", "post.vert", "depth_copy.frag", "depth hand-off with the ambient pass folded in",
         [](C c) { return c.paths.ambient_in_handoff && !c.paths.ambient_target; },
         [](C c) { return with(depth_defines(c), {"AMBIENT"}); }},
        // SSAO (docs/ssao.md): occlusion, then its depth-aware blur.
        {"ssao", "light.vert", "ssao.frag", "ambient occlusion", [](C c) { return c.opts.ssao.on; },
         [](C c) { return with(depth_defines(c), {"SAMPLES " + std::to_string(c.opts.ssao.samples)}); }},
        {"ssao_blur", "post.vert", "ssao_blur.frag", "ambient occlusion blur", [](C c) { return c.opts.ssao.on; },
         [](C c) { return depth_defines(c); }},
        // Post-processing (§3.5): Listing 22's blur, plain and with the bright-pass selection of
        // bloom's first pass; Listing 21 / Equation 7's anti-alias, and its factor alone (Figure 8,
        // --view blur-factor, which any configuration may ask for).
        {"bloom_blur", "post.vert", "blur.frag", "bloom blur (Listing 22)", [](C c) { return c.opts.post.bloom; },
         [](C c) { return blur_defines(c, false); }},
        {"bloom_select", "post.vert", "blur.frag", "bloom blur with the bright pass", [](C c) { return c.opts.post.bloom; },
         [](C c) { return blur_defines(c, true); }},
        {"anti_alias", "post.vert", "anti_alias.frag", "anti-alias (Listing 21, Equation 7)", always, aa_defines},
        {"aa_factor", "post.vert", "anti_alias.frag", "anti-alias factor (Figure 8)", always,
         [](C c) { return with(aa_defines(c), {"FACTOR_ONLY"}); }},
        // The final stage with tone mapping or an output encoding (docs/hdr.md); without them the
        // tutorial's fixed-function copy (§3.6). The reduction of P-buffer 0's log luminance for
        // --exposure auto, and with float accumulation for the viewer's histogram.
        {"tonemap", "post.vert", "tonemap.frag", "final pass: exposure, tone mapping, output encoding",
         [](C c) { return c.opts.hdr.final_program(); }, tonemap_defines},
        {"log_luminance", "post.vert", "log_luminance.frag", "P-buffer 0's mean log2 luminance per block",
         [](C c) { return (c.opts.hdr.exposure_auto || c.opts.hdr.float_accum()) && c.caps.fbo && c.caps.texture_float && c.paths.fbo; },
         [](C) { return Defines{"TAPS " + std::to_string(kLogLuminanceTaps)}; }},
        // The light pass's arithmetic written out as eye-space positions (reconstructed_positions).
        {"position", "light.vert", "light.frag", "read-back of the reconstructed positions",
         [](C c) { return c.caps.fbo && c.caps.texture_float; },
         [](C c) { return with(depth_defines(c), {"OUTPUT_POSITION"}); }},
    };
    return rows;
}

std::vector<ProgramSpec> shader_programs(const ShaderConfig& c) {
    std::vector<ProgramSpec> out;
    for (const ShaderRow& r : shader_rows()) {
        if (!r.used(c)) continue;
        const Defines d = r.defines(c);
        if (!r.per_target || c.paths.mrt) {
            out.push_back(ProgramSpec{r.name, r.vert, r.frag, r.role, d});
            continue;
        }
        for (int t = 0; t < c.paths.gbuffer_targets; ++t)
            out.push_back(ProgramSpec{std::string(r.name) + "/" + std::to_string(t), r.vert, r.frag, r.role,
                                      with(d, {"TARGET_" + std::to_string(t)})});
    }
    return out;
}

std::string describe_programs(const ShaderConfig& c) {
    std::ostringstream s;
    for (const ProgramSpec& p : shader_programs(c)) {
        std::string d;
        for (const std::string& x : p.defines) d += (d.empty() ? "" : ", ") + x;
        char line[256];
        std::snprintf(line, sizeof line, "  %-26s %-34s %s\n", p.name.c_str(), (p.vert + " + " + p.frag).c_str(),
                      p.role.c_str());
        s << line;
        if (!d.empty()) s << "  " << std::string(26, ' ') << " " << d << "\n";
    }
    std::string rest;
    for (const ShaderRow& r : shader_rows())
        if (!r.used(c)) rest += (rest.empty() ? "" : ", ") + std::string(r.name);
    if (!rest.empty()) s << "  the table's other rows (other options): " << rest << "\n";
    return s.str();
}

ProgramSet::ProgramSet(const std::string& dir, const ShaderConfig& c, const std::vector<std::string>& only) : dir_(dir) {
    for (ProgramSpec& p : shader_programs(c))
        if (only.empty() || std::find(only.begin(), only.end(), p.name) != only.end()) {
            programs_[p.name] = Program(dir, p.vert, p.frag, p.defines);
            specs_.push_back(std::move(p));
        }
}

ProgramSources ProgramSet::sources(const std::string& prefix) const {
    std::vector<ProgramSpec> out;
    for (const ProgramSpec& p : specs_)
        if (p.name.compare(0, prefix.size(), prefix) == 0) out.push_back(p);
    return ProgramSources(dir_, std::move(out));
}

bool ProgramSources::has(const std::string& name) const {
    return std::any_of(specs_.begin(), specs_.end(), [&](const ProgramSpec& p) { return p.name == name; });
}

Program ProgramSources::build(const std::string& name, const Defines& extra) const {
    for (const ProgramSpec& p : specs_)
        if (p.name == name) {
            Defines d = p.defines;
            d.insert(d.end(), extra.begin(), extra.end());
            return Program(dir_, p.vert, p.frag, d);
        }
    throw Error("shader table: no program '" + name + "' in this configuration");
}

Program ProgramSet::take(const std::string& name) {
    auto it = programs_.find(name);
    if (it == programs_.end()) throw Error("shader table: no program '" + name + "' in this configuration");
    Program p = std::move(it->second);
    programs_.erase(it);
    return p;
}

}  // namespace dsr
