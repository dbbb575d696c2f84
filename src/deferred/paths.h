// The one path chooser: probed capabilities and asked-for options
// in, the path taken at each decision out. No GL inside, so every capability combination is
// unit-tested; DeferredShader, `dsr info`, `render --depth auto` and the tests all ask it.
#pragma once
#include <string>
#include <vector>

#include "deferred/options.h"
#include "gl/caps.h"

namespace dsr {

struct Paths {
    DepthPath depth_path = DepthPath::texture;  // never automatic
    bool mrt = true;             // one material pass into every G-buffer target (ARB_draw_buffers)
    bool fbo = true;             // render to texture (EXT_framebuffer_object); else copy
    bool pbuffer = false;        // copy from pbuffer surfaces of their own (--render-target pbuffer)
    bool pow2 = false;           // targets padded, material maps rescaled to powers of two
    bool count_fragments = true; // occlusion queries around the light passes
    int gbuffer_targets = 3;     // normal, diffuse, specular (+ packed depth or position)
    // Each G-buffer colour target's format, in target order: what RenderTargets allocates. Where
    // only EXT_framebuffer_object is present (no ARB_framebuffer_object / GL 3.0) every colour
    // attachment of one framebuffer takes one format ("incomplete: formats" otherwise), so a
    // float position target makes every target float; `gbuffer_formats_note` then says so.
    std::vector<TargetFormat> gbuffer_formats;
    std::string gbuffer_formats_note;
    // The G-buffer's depth: a depth texture on the texture path, a renderbuffer (depth testing
    // only) on the packed and position paths.
    bool gbuffer_depth_texture = true;
    // Bytes a pixel of the G-buffer holds: its colour targets plus the 24-bit depth (counted as
    // the 4 bytes it is stored in, D24X8).
    int gbuffer_bytes_per_pixel = 0;
    // The same decisions by name (info, --stats, the tests).
    std::string depth;           // "texture" | "packed" | "position16" | "position32"
    std::string gbuffer;         // "mrt" | "per-target"
    std::string render_target;   // "fbo" | "copy" | "pbuffer"
    std::string textures;        // "npot" | "pow2"
    // The light geometry as run (a missing capability turns stencil into volume) and why not the
    // one asked for (empty when it is); stencil's way of setting the two faces apart.
    LightGeometry light_geometry = LightGeometry::quad;
    std::string light_geometry_note;
    int tile_size = 16, tile_lights = 32;  // tiles: as asked, or the GL's defaults for 0 (auto)
    // tiles: whole tiles drawn as points of the tile's size, not quads (ShaderOptions::tile_shape;
    // a partial tile at the frame's edge stays a quad: a point whose centre lies outside the
    // viewport is clipped whole).
    bool tile_points = false;
    // tiles: a tile's lights read once, by the vertex shader, into flat varyings (TileFetch::vertex;
    // light_tiles_flat.vert), at most tile_vertex_lights a pass (GL_MAX_VARYING_COMPONENTS over the
    // 8 a light takes, and 16); else read at every pixel (light_tiles.frag).
    bool tile_fetch_vertex = false;
    int tile_vertex_lights = 0;
    enum class StencilFaces { separate, two_side_ext, one_sided };  // GL 2.0 | EXT_stencil_two_side | two passes
    StencilFaces stencil_faces = StencilFaces::separate;
    // P-buffers 0 and 1 get a depth attachment the G-buffer's depth is handed to (the volume,
    // stencil and depth-bounds passes test against it); with stencil, a packed depth-stencil one.
    bool accum_depth = false;
    bool accum_stencil = false;
    // The forward stage after the lights runs (--show-lights, or transparent surfaces), and how the
    // G-buffer's depth reaches P-buffer 0 when accum_depth: a blit (EXT_framebuffer_blit, any depth
    // path: it copies the G-buffer's depth buffer itself) or the gl_FragDepth pass.
    bool forward_stage = false;
    DepthHandoff depth_handoff = DepthHandoff::pass;  // never automatic; meaningful with accum_depth
    bool depth_bounds = false;
    // The material pass writes Listing 15's ambient term into P-buffer 0, attached as one more
    // render target (its index: gbuffer_targets), so no ambient pass is drawn
    // (SkipOptions::ambient_target): where the GL has a draw buffer to spare and takes P-buffer 0's
    // format beside the G-buffer's, the diffuse target is RGBA8 (the shader rounds it as the target
    // stores it, then multiplies as the fixed-function pass does), and nothing else writes the
    // ambient: not with SSAO (it scales the ambient pass alone) nor the screen geometry (its first
    // batch writes it, as LearnOpenGL's lighting pass does).
    bool ambient_target = false;
    std::string ambient_target_note;  // why not, where the skip is on and it is not taken
    // A frame that hands the depth off and whose ambient term nothing else wrote (no ambient target,
    // no fold into a light's pass) writes it in the hand-off's pass (depth_copy.frag AMBIENT), in
    // place of the ambient pass and of the blit (SkipOptions::ambient_pass; not with SSAO, which
    // scales the ambient pass alone). On a GPU this takes the ambient target's place: there a
    // full-screen pass costs what the fourth target adds to the material pass, and the pass
    // replaces the blit too (docs/gpu_frame.md, "The fixed passes"). On a CPU rasteriser the target
    // costs less than a pass, and the hand-off takes the ambient term only where it is a pass
    // anyway (docs/light_geometry.md).
    bool ambient_in_handoff = false;
    // Non-empty: this GL cannot run these options, and why, in one line.
    std::string refused;
};

Paths choose_paths(const Caps& caps, const ShaderOptions& opts);

// Whether the geometry draws lights through the tiles: tiles, and auto, which sends some there.
inline bool draws_tiles(LightGeometry g) { return g == LightGeometry::tiles || g == LightGeometry::automatic; }

// Whether the geometry's first pass covers every pixel and writes, blending off, what the clear and
// Listing 15's ambient pass would have left there (screen: LearnOpenGL's lighting pass adds its
// ambient term itself; LightGeometryPass::draw_with_ambient), so that neither the ambient pass nor
// the material pass's ambient target is needed.
inline bool draws_own_ambient(LightGeometry g) { return g == LightGeometry::screen; }

// --accum: what this GL lacks for accumulation format `a` in one phrase ("needs float targets
// (ARB_texture_float), which this GL lacks"), "" when it can (rgba8 always); `fbo`: the paths
// render to texture. `dsr info` and choose_paths' refusal say it.
std::string accum_format_missing(const Caps& caps, bool fbo, AccumFormat a);
bool accum_format_ok(const Caps& caps, bool fbo, AccumFormat a);

// One line per decision with its reason, for `dsr info`.
std::string describe(const Paths& paths);
const char* stencil_faces_name(Paths::StencilFaces f);  // "separate" | "two-side-ext" | "one-sided"

}  // namespace dsr
