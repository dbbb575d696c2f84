// What a DeferredShader is asked to do: depth path, encodings, skips, post-processing. Pure
// data, no GL: choose_paths (paths.h) turns it and the probed capabilities into the paths
// that run.
#pragma once
#include <array>
#include <optional>
#include <string>

#include "deferred/depth_codec.h"

namespace dsr {

// automatic: the depth texture where ARB_depth_texture exists, else packed (choose_paths); it
// never picks a position path.
//  texture     the G-buffer's depth texture, eye position rebuilt from depth (§3.4.3)
//  packed      depth packed into an RGB8 target (Listings 11, 18), rebuilt the same way
//  position16  eye-space position xyz stored in an RGBA16F target (LearnOpenGL's G-buffer)
//  position32  the same in RGBA32F (the lecture's "GL_RGBA32F texture", Vasilovici's targets)
enum class DepthPath { texture, packed, position16, position32, automatic };

// "texture", "packed", "position16", "position32", "auto"; from_name throws dsr::Error otherwise.
const char* depth_path_name(DepthPath d);
DepthPath depth_path_from_name(const std::string& name);
// The paths that store position instead of rebuilding it from depth.
inline bool is_position_path(DepthPath d) { return d == DepthPath::position16 || d == DepthPath::position32; }

// A G-buffer colour target's format (pure: render_targets.cpp maps it to the GL enum).
enum class TargetFormat { rgba8, rgba16f, rgba32f };
int target_format_bytes(TargetFormat f);   // 4, 8, 16
const char* target_format_name(TargetFormat f);  // "RGBA8", "RGBA16F", "RGBA32F"

// How each light reaches its pixels (docs/light_geometry.md; docs/benchmarks.md has one section per geometry):
//  quad     the tutorial's scissored screen-aligned quad per light (§3.4.2, Listing 16)
//  volume   the back faces of the light's volume mesh, depth test GL_GREATER against the scene
//  stencil  per light a two-sided stencil pass over the volume, then the light pass where it marks
//  tiles    screen tiles; up to `tile_lights` lights per pass in one shader (§3.4.3's closing remark)
//  screen   every light at every pixel, in full-screen passes with no culling (LearnOpenGL's
//           deferred demo's lighting pass): the peer's algorithm, measured beside dsr's
//  automatic  each light by the cheapest of quad, volume and tiles (light_cost.h choose_light_paths)
enum class LightGeometry { quad, volume, stencil, tiles, screen, automatic };

// Where the G-buffer and P-buffers are rendered (§3.2's pPBuffer): automatic picks fbo where
// EXT_framebuffer_object exists, else copy; pbuffer needs a context with pbuffer surfaces (EGL).
enum class RenderTarget { automatic, fbo, copy, pbuffer };

// The tiles geometry's plan (tile_plan.h): exact per-tile light lists, or groups of lights drawn
// over the union of their tiles.
enum class TileGrouping { lists, groups };
// How the tiles geometry draws a tile: as a point of the tile's size (one square primitive) where
// the GL's points are as large as a tile, else as a quad (two triangles) (Paths::tile_points).
enum class TileShape { points, quads };
// Where the tiles geometry reads a tile's lights out of the batch's uniform arrays
// (Paths::tile_fetch_vertex): once a tile, in the vertex shader, handed on as flat varyings
// (light_tiles_flat.vert, GLSL 1.30), or at every pixel, in the fragment shader (light_tiles.frag);
// automatic: vertex where the GL can (GLSL 1.30), else fragment.
enum class TileFetch { automatic, vertex, fragment };

// How the G-buffer's depth reaches P-buffer 0's depth buffer (depth_handoff.cpp): automatic picks
// blit where EXT_framebuffer_blit and framebuffer objects exist, else pass (a full-screen pass
// writing gl_FragDepth from the G-buffer's depth, decoding the packed target on the packed path).
enum class DepthHandoff { automatic, blit, pass };

// High dynamic range (docs/hdr.md). P-buffer 0's format: the tutorial's RGBA8, whose sums clip at
// 1.0, or RGBA16F / RGBA32F (ARB_texture_float, ARB_half_float_pixel, float blending), where light
// sums above 1 survive to the final stage's tone mapping.
enum class AccumFormat { rgba8, half, float32 };
const char* accum_format_name(AccumFormat a);  // "rgba8", "half", "float"
// The final stage's operator on the exposed linear colour: none (clamped, the tutorial's
// fixed-function final pass when nothing else is asked), Reinhard et al. 2002's global operator
// on luminance, or Narkowicz's fit of the ACES filmic curve per channel.
enum class ToneMap { none, reinhard, aces };
const char* tone_map_name(ToneMap t);  // "none", "reinhard", "aces"

struct HdrOptions {
    AccumFormat accum = AccumFormat::rgba8;
    ToneMap tonemap = ToneMap::none;
    float exposure = 0;          // stops: the colour is scaled by 2^exposure before the operator
    bool exposure_auto = false;  // the scale from the frame's mean log luminance (key 0.18) instead
    bool output_srgb = false;    // the final pass encodes to sRGB (IEC 61966-2-1); default linear
    bool textures_srgb = false;  // colour maps decoded from sRGB to linear when sampled
    bool float_accum() const { return accum != AccumFormat::rgba8; }
    // The final pass is a program (tonemap.frag), not the tutorial's fixed-function copy.
    bool final_program() const { return tonemap != ToneMap::none || output_srgb || exposure_auto || exposure != 0; }
};

enum class AaSource { normal, depth, both };
enum class AaKernel { text, listing };

// Post-processing (§3.5). Defaults are the tutorial's: a 7-tap separable blur at half size.
struct PostOptions {
    bool bloom = false;
    int bloom_scale = 2;           // P-buffers 2 and 3 at 1/2 or 1/4 of the frame (§3.5.2)
    int bloom_taps = 7;            // NUMPOINTS of Listing 22 (odd, 3..15)
    float bloom_strength = 1.0f;   // weight of the fixed-function add into P-buffer 0
    bool bloom_listing = false;    // Listing 22's grey dot(t,t) in both passes; default keeps colour
    float bloom_threshold = 1.0f;  // float accumulation: the bright pass keeps what lies above this luminance
    bool aa = false;
    AaSource aa_source = AaSource::normal;  // Eq. 7 over the normal target, depth, or both
    AaKernel aa_kernel = AaKernel::text;    // text: all 8 neighbours; listing: Listing 21's table
    float aa_weight = 1.0f;        // Listing 21's `weight`: largest offset, in pixels
    float aa_depth_scale = 4.0f;   // relative eye-z step that counts as an edge: ((dz/z)*scale)^2
};

// Work a scene does not need, skipped (each on by default; bench measures each).
struct SkipOptions {
    bool material_variants = true;  // no normal map: no tangent-space work; no specular: no specular map read
    bool empty_lights = true;       // lights with zero colour or an empty scissor rectangle are not drawn
    bool light_depth_test = true;   // per light, pixels whose surface lies in front of or behind the
                                    // light's sphere (or is background) are rejected before shading
    bool light_sphere_test = true;  // then pixels whose surface point is outside the sphere (att = 0):
                                    // rejected after one depth fetch, before the G-buffer reads
    bool depth_prepass = true;      // the depth pre-pass (§3.3.1) left out where the frame's depth
                                    // complexity makes it pure cost
    bool ambient_target = true;     // the ambient pass (Listing 15) written by the material pass into
                                    // P-buffer 0, a render target beside the G-buffer's (paths.h)
    bool ambient_pass = true;       // else the ambient pass folded into a full-screen light pass
    bool final_pass = true;         // no final pass (§3.6) when the output is P-buffer 0 read back at its size
    bool gbuffer_clears = true;     // the G-buffer's colour clears that no later pass reads: the
                                    // specular target's, and the diffuse target's where the ambient
                                    // term's writer tells a surface by the normal target (render_targets.h GbufferClears)
};

// Screen-space ambient occlusion (Vasilovici §5, docs/ssao.md): its own pass from the G-buffer's
// depth and normals, then a depth-aware blur; it scales the ambient pass (Listing 15, Eq. 6)
// only. Off by default: the ambient pass is then exactly the tutorial's.
struct SsaoOptions {
    bool on = false;
    int scale = 1;          // the AO buffer at 1/1 or 1/2 of the frame
    float radius = 0.5f;    // hemisphere radius, eye-space units
    float strength = 1.0f;  // ao = 1 - strength * occluded fraction, clamped to [0, 1]
    int samples = 16;       // kernel size (ssao_kernel.h), 4..64
};

// Shadow maps (shadow_stage.h, docs/shadows.md). `filter` is what one lookup averages:
//  hard  one comparison with the nearest texel
//  pcf2  2x2 comparisons weighted bilinearly: ARB_shadow's GL_LINEAR compare where the GL filters
//        compares (one shadow2D), the same four in the shader on the packed map
//  pcf3, pcf5  3x3, 5x5 texels, each a 2x2-filtered comparison, averaged
enum class ShadowFilter { hard, pcf2, pcf3, pcf5 };
const char* shadow_filter_name(ShadowFilter f);  // "hard", "pcf2", "pcf3", "pcf5"
struct ShadowOptions {
    bool on = true;  // --shadows on honours the scene's `shadow` lights; off ignores them
    ShadowFilter filter = ShadowFilter::pcf2;
    // A light's map kept from an earlier frame while neither the light nor anything in its views
    // moved (the viewer's still frames); off draws every map every frame (timing the stage).
    bool reuse = true;
};

struct ShaderOptions {
    DepthPath depth = DepthPath::texture;
    DepthEncoding encoding = DepthEncoding::corrected;  // what the packed target holds
    bool listing2_literal = false;  // Listing 2's v and h exactly; default: Equations 1-5
    bool scissor = true;            // §3.4.2 light scissor rectangles
    PostOptions post;
    SkipOptions skip;
    HdrOptions hdr;                 // P-buffer 0's format, tone mapping, output and texture encodings
    // G-buffer target precision: the tutorial's RGBA8 everywhere (Figure 3), or half-float
    // targets (ARB_texture_float + ARB_half_float_pixel) where 8-bit normals are the largest
    // error of the deferred image.
    bool gbuffer_half = false;
    // auto: each light by its cheapest path (light_cost.h); quad is the tutorial's (§3.4.2).
    LightGeometry light_geometry = LightGeometry::automatic;
    // auto: each path's starting cost scale (quad, volume, tiles; light_cost.h LightCostCalibration),
    // given instead of guessed: a large one keeps a path out (--light-cost-scale).
    std::optional<std::array<double, 3>> light_cost_scale;
    bool depth_bounds = false;      // EXT_depth_bounds_test on the quad passes (refused where missing)
    // tiles: pixels per side and lights per pass (the shader's constant loop bound); 0 is auto,
    // resolved by choose_paths (Paths::tile_size, tile_lights) from the GL: on a CPU rasteriser 16
    // and 32 (smaller tiles gain nothing there, larger ones let more tile-light pairs through the
    // depth culling), else 32 and 8, each the faster where measured (docs/tiles.md, "Settings").
    // With the tiles' vertex fetch (Paths::tile_fetch_vertex) the lights a pass are as many as its
    // flat varyings hold, 16 at most.
    int tile_size = 0;
    int tile_lights = 0;
    RenderTarget render_target = RenderTarget::automatic;
    TileGrouping tile_plan = TileGrouping::lists;
    TileShape tile_shape = TileShape::points;
    TileFetch tile_fetch = TileFetch::automatic;
    bool tile_depth = true;         // tiles: leave out a tile's lights that miss its surfaces' depth span (tile_depth.h)
    SsaoOptions ssao;
    // The forward stage after the light passes (forward_stage.h, docs/forward.md).
    bool show_lights = false;       // --show-lights: an emissive marker at each point and spot light
    // Set by DeferredShader::set_scene when the scene has transparent materials (opacity < 1): the
    // forward stage draws them, so P-buffer 0 needs the scene's depth. Not a user option.
    bool forward_surfaces = false;
    DepthHandoff depth_handoff = DepthHandoff::automatic;
    ShadowOptions shadows;
    // Set by RenderOptions::resolved when the scene has lights with `shadow` and shadows are on:
    // the shadow stage and the light programs' shadowed forms are built. Not a user option.
    bool shadow_lights = false;
    // Set by RenderOptions::resolved (and DeferredShader::set_scene) when the scene has a
    // metallic-roughness material: the light programs take the material model from the G-buffer
    // (lighting.glsl METAL_ROUGH). Phong-only scenes keep the programs they always had. Not a user option.
    bool metal_rough = false;
};

// "auto", "blit", "pass"; from_name throws dsr::Error listing them otherwise.
const char* depth_handoff_name(DepthHandoff h);
DepthHandoff depth_handoff_from_name(const std::string& name);

// "quad", "volume", "stencil", "tiles", "screen", "auto"; from_name throws dsr::Error listing them otherwise.
const char* light_geometry_name(LightGeometry g);
LightGeometry light_geometry_from_name(const std::string& name);

}  // namespace dsr
