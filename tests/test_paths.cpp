// choose_paths (deferred/paths.h): the one path chooser, pure, for every capability
// combination the old-GL matrix forces and for a GL without GLSL 1.20.
#include <gtest/gtest.h>

#include "deferred/paths.h"

namespace dsr {
namespace {

// A GL 2.1 with everything, then the four fallbacks' capabilities taken away by mask bits:
// 1 no-mrt, 2 no-depth-texture, 4 no-fbo, 8 no-npot (tests/test_fallbacks.cpp's order).
Caps caps_for(int mask) {
    Caps c;
    c.version = "2.1";
    c.glsl_version = "1.20";
    c.gl_major = 2, c.gl_minor = 1, c.glsl_major = 1, c.glsl_minor = 20;
    c.glsl120 = true;
    c.draw_buffers = !(mask & 1);
    c.max_draw_buffers = (mask & 1) ? 1 : 8;
    c.depth_texture = !(mask & 2);
    c.fbo = !(mask & 4);
    c.npot = !(mask & 8);
    c.texture_float = c.half_float = true;
    c.half_float_blend = c.float_blend = true;
    c.occlusion_query = true;
    return c;
}

TEST(Paths, EverySixteenCombinationsWithDepthAuto) {
    for (int mask = 0; mask < 16; ++mask) {
        ShaderOptions o;
        o.depth = DepthPath::automatic;
        Paths p = choose_paths(caps_for(mask), o);
        SCOPED_TRACE("mask " + std::to_string(mask));
        EXPECT_TRUE(p.refused.empty()) << p.refused;
        const bool packed = mask & 2;
        EXPECT_EQ(p.depth_path, packed ? DepthPath::packed : DepthPath::texture);
        EXPECT_EQ(p.depth, packed ? "packed" : "texture");
        EXPECT_EQ(p.gbuffer_targets, packed ? 4 : 3);
        // MRT needs draw buffers and render to texture (one colour buffer otherwise, §3.2).
        EXPECT_EQ(p.mrt, !(mask & 1) && !(mask & 4));
        EXPECT_EQ(p.gbuffer, p.mrt ? "mrt" : "per-target");
        EXPECT_EQ(p.fbo, !(mask & 4));
        EXPECT_EQ(p.render_target, (mask & 4) ? "copy" : "fbo");
        EXPECT_EQ(p.pow2, bool(mask & 8));
        EXPECT_EQ(p.textures, (mask & 8) ? "pow2" : "npot");
    }
}

TEST(Paths, ExplicitDepthPathIsKeptOrRefused) {
    ShaderOptions o;
    o.depth = DepthPath::packed;
    EXPECT_EQ(choose_paths(caps_for(0), o).depth_path, DepthPath::packed);  // asked for, though textures exist
    o.depth = DepthPath::texture;
    Paths p = choose_paths(caps_for(2), o);
    EXPECT_NE(p.refused.find("ARB_depth_texture"), std::string::npos) << p.refused;
}

TEST(Paths, MrtNeedsEnoughDrawBuffersForTheTargets) {
    Caps c = caps_for(0);
    c.max_draw_buffers = 3;  // enough for normal, diffuse, specular; not for the packed depth too
    ShaderOptions o;
    o.depth = DepthPath::texture;
    EXPECT_TRUE(choose_paths(c, o).mrt);
    o.depth = DepthPath::packed;
    EXPECT_FALSE(choose_paths(c, o).mrt);
}

TEST(Paths, NoGlslIsRefusedInOneLine) {
    Caps c = caps_for(0);
    c.glsl120 = false;
    c.glsl_version = "1.10";
    for (int mask : {0, 15}) {
        Caps m = caps_for(mask);
        m.glsl120 = false;
        m.glsl_version = "";
        Paths p = choose_paths(m, ShaderOptions{});
        EXPECT_NE(p.refused.find("GLSL 1.20 is required"), std::string::npos) << p.refused;
        EXPECT_EQ(p.refused.find('\n'), std::string::npos);
    }
    Paths p = choose_paths(c, ShaderOptions{});
    EXPECT_NE(p.refused.find("offers 1.10"), std::string::npos) << p.refused;
}

TEST(Paths, FloatOptionsNeedFloatTargets) {
    Caps c = caps_for(0);
    c.texture_float = c.half_float = false;
    ShaderOptions o;
    o.gbuffer_half = true;
    EXPECT_NE(choose_paths(c, o).refused.find("half-float"), std::string::npos);
    o.gbuffer_half = false;
    o.hdr.accum = AccumFormat::float32;
    EXPECT_NE(choose_paths(c, o).refused.find("--accum float"), std::string::npos);
    EXPECT_TRUE(choose_paths(caps_for(0), o).refused.empty());
}

// --accum half/float: refused in one line naming what is missing (targets, blending, render to
// texture), and the stress runner's float accumulation where all are present.
TEST(Paths, AccumFormatsNeedFloatTargetsAndBlending) {
    ShaderOptions o;
    EXPECT_TRUE(accum_format_ok(caps_for(0), true, AccumFormat::rgba8));
    for (AccumFormat a : {AccumFormat::half, AccumFormat::float32}) {
        o.hdr.accum = a;
        SCOPED_TRACE(accum_format_name(a));
        EXPECT_TRUE(choose_paths(caps_for(0), o).refused.empty());
        Caps no_blend = caps_for(0);
        (a == AccumFormat::half ? no_blend.half_float_blend : no_blend.float_blend) = false;
        const std::string r = choose_paths(no_blend, o).refused;
        EXPECT_NE(r.find("blending"), std::string::npos) << r;
        EXPECT_EQ(r.find('\n'), std::string::npos) << "one line";
        EXPECT_NE(choose_paths(caps_for(4), o).refused.find("EXT_framebuffer_object"), std::string::npos);
    }
    Caps half_only = caps_for(0);
    half_only.float_blend = false;  // an NV40: half floats blend, 32-bit ones do not
    o.hdr.accum = AccumFormat::half;
    EXPECT_TRUE(choose_paths(half_only, o).refused.empty());
    o.hdr.accum = AccumFormat::float32;
    EXPECT_FALSE(choose_paths(half_only, o).refused.empty());
}

TEST(Paths, DescribeNamesEveryDecision) {
    const std::string d = describe(choose_paths(caps_for(1 | 8), ShaderOptions{}));
    for (const char* s : {"depth", "texture", "G-buffer", "per-target", "render target", "fbo", "textures", "pow2",
                          "light counting"})
        EXPECT_NE(d.find(s), std::string::npos) << s << " missing from:\n" << d;
}


// The position paths (docs/depth_precision.md). `auto` never picks them; with ARB_framebuffer_object the other
// targets stay RGBA8, with EXT_framebuffer_object alone every target takes the float format.
TEST(Paths, AutoNeverPicksAPositionPath) {
    for (int mask = 0; mask < 16; ++mask) {
        ShaderOptions o;
        o.depth = DepthPath::automatic;
        EXPECT_FALSE(is_position_path(choose_paths(caps_for(mask), o).depth_path)) << mask;
    }
}

TEST(Paths, PositionPathsFormatsAndBytesPerPixel) {
    Caps arb = caps_for(0);
    arb.fbo_mixed_formats = true;
    Caps ext = caps_for(0);  // EXT_framebuffer_object only: one format per framebuffer
    ShaderOptions o;
    const std::pair<DepthPath, int> expect_arb[] = {{DepthPath::texture, 16}, {DepthPath::packed, 20},
                                                    {DepthPath::position16, 24}, {DepthPath::position32, 32}};
    for (auto [d, bytes] : expect_arb) {
        o.depth = d;
        const Paths p = choose_paths(arb, o);
        SCOPED_TRACE(depth_path_name(d));
        EXPECT_TRUE(p.refused.empty()) << p.refused;
        EXPECT_EQ(p.gbuffer_bytes_per_pixel, bytes);
        EXPECT_EQ(p.gbuffer_depth_texture, d == DepthPath::texture);
        EXPECT_EQ(int(p.gbuffer_formats.size()), p.gbuffer_targets);
    }
    o.depth = DepthPath::position16;
    Paths p = choose_paths(arb, o);
    EXPECT_EQ(p.depth, "position16");
    EXPECT_EQ(p.gbuffer_targets, 4);
    EXPECT_EQ(p.gbuffer_formats[0], TargetFormat::rgba8);
    EXPECT_EQ(p.gbuffer_formats[3], TargetFormat::rgba16f);
    EXPECT_TRUE(p.gbuffer_formats_note.empty());
    p = choose_paths(ext, o);
    EXPECT_EQ(p.gbuffer_formats, std::vector<TargetFormat>(4, TargetFormat::rgba16f));
    EXPECT_EQ(p.gbuffer_bytes_per_pixel, 4 * 8 + 4);
    EXPECT_NE(p.gbuffer_formats_note.find("one format"), std::string::npos);
    o.depth = DepthPath::position32;
    p = choose_paths(ext, o);
    EXPECT_EQ(p.gbuffer_formats, std::vector<TargetFormat>(4, TargetFormat::rgba32f));
    EXPECT_EQ(p.gbuffer_bytes_per_pixel, 4 * 16 + 4);
    // The depth paths keep RGBA8 on EXT alone: nothing to unify.
    o.depth = DepthPath::packed;
    EXPECT_EQ(choose_paths(ext, o).gbuffer_bytes_per_pixel, 20);
    EXPECT_NE(describe(choose_paths(arb, ShaderOptions{})).find("16 per pixel"), std::string::npos);
}

TEST(Paths, PositionPathsNeedFloatTargetsAndRenderToTexture) {
    Caps c = caps_for(0);
    c.texture_float = c.half_float = false;
    c.forced_off = {"no-float"};
    ShaderOptions o;
    for (DepthPath d : {DepthPath::position16, DepthPath::position32}) {
        o.depth = d;
        const std::string r = choose_paths(c, o).refused;
        SCOPED_TRACE(depth_path_name(d));
        EXPECT_NE(r.find("needs a float G-buffer target"), std::string::npos) << r;
        EXPECT_NE(r.find("forced off: no-float"), std::string::npos) << r;
        EXPECT_EQ(r.find('\n'), std::string::npos) << "one line";
        EXPECT_NE(choose_paths(caps_for(4), o).refused.find("EXT_framebuffer_object"), std::string::npos);
        EXPECT_TRUE(choose_paths(caps_for(1 | 2 | 8), o).refused.empty());  // no MRT: one pass per target
    }
    // Half floats missing alone: position32 runs, position16 is refused.
    c = caps_for(0);
    c.half_float = false;
    o.depth = DepthPath::position32;
    EXPECT_TRUE(choose_paths(c, o).refused.empty());
    o.depth = DepthPath::position16;
    EXPECT_NE(choose_paths(c, o).refused.find("ARB_half_float_pixel"), std::string::npos);
}

TEST(Paths, DepthPathNamesRoundTrip) {
    for (DepthPath d : {DepthPath::texture, DepthPath::packed, DepthPath::position16, DepthPath::position32,
                        DepthPath::automatic})
        EXPECT_EQ(depth_path_from_name(depth_path_name(d)), d);
    EXPECT_THROW(depth_path_from_name("position"), std::exception);
}

}  // namespace
TEST(Paths, RenderTargetAskedForIsKeptOrRefused) {
    Caps c = caps_for(0);  // every capability
    ShaderOptions o;
    Paths p = choose_paths(c, o);
    EXPECT_EQ(p.render_target, "fbo");
    o.render_target = RenderTarget::copy;  // asked for, though framebuffer objects exist
    p = choose_paths(c, o);
    EXPECT_EQ(p.render_target, "copy");
    EXPECT_FALSE(p.fbo);
    EXPECT_FALSE(p.mrt);  // one colour buffer: one pass per target
    o.render_target = RenderTarget::pbuffer;
    p = choose_paths(c, o);
    EXPECT_NE(p.refused.find("--context egl"), std::string::npos) << p.refused;  // no surfaces
    c.pbuffer_surfaces = true;
    p = choose_paths(c, o);
    EXPECT_TRUE(p.refused.empty()) << p.refused;
    EXPECT_EQ(p.render_target, "pbuffer");
    EXPECT_TRUE(p.pbuffer);
    EXPECT_FALSE(p.fbo);
    o.render_target = RenderTarget::fbo;
    c.fbo = false;
    EXPECT_NE(choose_paths(c, o).refused.find("EXT_framebuffer_object"), std::string::npos);
    o.render_target = RenderTarget::automatic;
    EXPECT_EQ(choose_paths(c, o).render_target, "copy");
}

}  // namespace dsr

namespace dsr {

// --tile-size / --tile-lights auto (0): 16 pixels and 32 lights a pass on a CPU rasteriser (the
// llvmpipe measurements), 32 and 8 on a GPU (the H200's); explicit values are kept, and the range
// is checked on what is resolved.
TEST(Paths, TileDefaultsFollowTheRasteriser) {
    ShaderOptions o;
    o.light_geometry = LightGeometry::tiles;
    Caps c = caps_for(0);
    for (bool sw : {true, false}) {
        c.software_rasterizer = sw;
        const Paths p = choose_paths(c, o);
        EXPECT_TRUE(p.refused.empty()) << p.refused;
        EXPECT_EQ(p.tile_size, sw ? 16 : 32);
        EXPECT_EQ(p.tile_lights, sw ? 32 : 8);
    }
    o.tile_size = 24, o.tile_lights = 5;
    const Paths p = choose_paths(c, o);
    EXPECT_EQ(p.tile_size, 24);
    EXPECT_EQ(p.tile_lights, 5);
    o.tile_size = 4;
    EXPECT_NE(choose_paths(c, o).refused.find("tile size must be 8..512"), std::string::npos);
}

// Tiles as points by default, on a CPU rasteriser or a GPU, only where the GL's points are as
// large as a tile; else, or where asked, quads.
TEST(Paths, TilesArePointsWherePointsAreLargeEnough) {
    ShaderOptions o;
    o.light_geometry = LightGeometry::tiles;
    Caps c = caps_for(0);
    c.max_point_size = 64;
    for (bool sw : {true, false}) {
        c.software_rasterizer = sw;
        o.tile_shape = TileShape::points;
        EXPECT_TRUE(choose_paths(c, o).tile_points) << sw;
        o.tile_shape = TileShape::quads;
        EXPECT_FALSE(choose_paths(c, o).tile_points) << sw;
    }
    o.tile_shape = TileShape::points;
    o.tile_size = 64;
    EXPECT_TRUE(choose_paths(c, o).tile_points);
    o.tile_size = 65;
    EXPECT_FALSE(choose_paths(c, o).tile_points);  // a point that small would leave the tile's edge unlit
}

// The tiles' vertex fetch: auto takes it where the GL has GLSL 1.30, at as many lights a pass as
// the varyings hold (8 components a light, at most 16), and the fragment fetch elsewhere: without
// GLSL 1.30, with the groups plan, or where more lights a pass are asked for.
// Asked for where it cannot run, it is refused in one line.
TEST(Paths, TilesFetchTheirLightsInTheVertexShaderWhereTheyCan) {
    ShaderOptions o;
    o.light_geometry = LightGeometry::tiles;
    Caps c = caps_for(0);
    c.glsl130 = true;
    c.max_varying_components = 128;
    c.software_rasterizer = true;
    Paths p = choose_paths(c, o);
    EXPECT_TRUE(p.tile_fetch_vertex);
    EXPECT_EQ(p.tile_vertex_lights, 16);
    EXPECT_EQ(p.tile_lights, 16);
    c.max_varying_components = 64;  // OpenGL 3.0's least
    p = choose_paths(c, o);
    EXPECT_EQ(p.tile_lights, 8);
    EXPECT_TRUE(p.tile_fetch_vertex);
    o.tile_lights = 12;  // more than the varyings hold: the fragment fetch
    EXPECT_FALSE(choose_paths(c, o).tile_fetch_vertex);
    o.tile_fetch = TileFetch::vertex;
    EXPECT_NE(choose_paths(c, o).refused.find("at most 8 lights"), std::string::npos) << choose_paths(c, o).refused;
    o.tile_lights = 0;
    o.tile_fetch = TileFetch::automatic;
    c.max_varying_components = 128;
    o.tile_plan = TileGrouping::groups;
    EXPECT_FALSE(choose_paths(c, o).tile_fetch_vertex);
    o.tile_fetch = TileFetch::vertex;
    EXPECT_FALSE(choose_paths(c, o).refused.empty());
    o.tile_plan = TileGrouping::lists;
    o.tile_fetch = TileFetch::automatic;
    c.software_rasterizer = false;  // a GPU: the same
    c.max_varying_components = 124;
    p = choose_paths(c, o);
    EXPECT_TRUE(p.tile_fetch_vertex && p.refused.empty()) << p.refused;
    EXPECT_EQ(p.tile_lights, 15);
    o.tile_fetch = TileFetch::fragment;
    EXPECT_EQ(choose_paths(c, o).tile_lights, 8);  // a GPU's default without it
    o.tile_fetch = TileFetch::vertex;
    c.glsl130 = false;
    EXPECT_NE(choose_paths(c, o).refused.find("GLSL 1.30"), std::string::npos);
    o.tile_fetch = TileFetch::automatic;
    for (bool sw : {true, false}) {
        c.software_rasterizer = sw;
        p = choose_paths(c, o);
        EXPECT_FALSE(p.tile_fetch_vertex);
        EXPECT_EQ(p.tile_lights, sw ? 32 : 8);
    }
}

// Where a frame may hand the depth off (the geometries that test against the scene's depth, or the
// forward stage), the hand-off's pass can write the ambient term; on a GPU it then takes the ambient
// target's place, on a CPU rasteriser the target stays and only a hand-off that is a pass anyway
// (stencil's, or without the blit) takes it. Not with SSAO, nor with the skip off, nor where nothing
// hands off.
TEST(Paths, AmbientInTheHandoffOnAGpu) {
    Caps c = caps_for(0);
    c.framebuffer_blit = true;
    c.stencil = c.packed_depth_stencil = c.stencil_separate = true;
    for (bool sw : {true, false}) {
        c.software_rasterizer = sw;
        for (LightGeometry g : {LightGeometry::automatic, LightGeometry::volume, LightGeometry::stencil}) {
            ShaderOptions o;
            o.light_geometry = g;
            const Paths p = choose_paths(c, o);
            const std::string name = std::string(light_geometry_name(g)) + (sw ? ", CPU rasteriser" : ", GPU");
            EXPECT_EQ(p.depth_handoff, g == LightGeometry::stencil ? DepthHandoff::pass : DepthHandoff::blit) << name;
            EXPECT_EQ(p.ambient_in_handoff, !sw || g == LightGeometry::stencil) << name;
            EXPECT_EQ(p.ambient_target, sw) << name;
            o.depth_handoff = DepthHandoff::pass;
            EXPECT_TRUE(choose_paths(c, o).ambient_in_handoff) << name;
            o.depth_handoff = DepthHandoff::automatic;
            if (!sw) {
                EXPECT_EQ(p.ambient_target_note, "on a GPU the depth hand-off's pass writes it where a frame hands off") << name;
                EXPECT_NE(describe(p).find("written by the depth hand-off's pass in frames that hand off"), std::string::npos);
            }
            o.skip.ambient_pass = false;
            EXPECT_FALSE(choose_paths(c, o).ambient_in_handoff) << name;
            EXPECT_TRUE(choose_paths(c, o).ambient_target) << name;
            o.skip.ambient_pass = true;
            o.ssao.on = true;
            EXPECT_FALSE(choose_paths(c, o).ambient_in_handoff) << name;
        }
        ShaderOptions o;
        o.light_geometry = LightGeometry::quad;  // nothing tests against the scene's depth
        EXPECT_FALSE(choose_paths(c, o).ambient_in_handoff);
        EXPECT_TRUE(choose_paths(c, o).ambient_target);
        o.show_lights = true;  // the forward stage does, every frame
        EXPECT_EQ(choose_paths(c, o).ambient_in_handoff, !sw);
        EXPECT_EQ(choose_paths(c, o).ambient_target, sw);
        o.light_geometry = LightGeometry::screen;  // its first batch writes the ambient itself
        EXPECT_FALSE(choose_paths(c, o).ambient_in_handoff);
    }
}

// The material pass writes the ambient term into P-buffer 0 where a draw buffer is left after the
// G-buffer's, the framebuffer takes P-buffer 0's format beside them, the diffuse target is RGBA8 and
// nothing else writes the ambient; each refusal says why, and the skip turned off says nothing.
TEST(Paths, AmbientTargetNeedsADrawBufferToSpareAndOneFormat) {
    const auto with = [](Caps c, ShaderOptions o) { return choose_paths(c, o); };
    ShaderOptions o;
    o.depth = DepthPath::texture;
    Caps c = caps_for(0);
    c.software_rasterizer = true;  // on a GPU the hand-off's pass takes it where it can (below)
    c.max_draw_buffers = 4;
    Paths p = with(c, o);
    EXPECT_TRUE(p.ambient_target);
    EXPECT_TRUE(p.ambient_target_note.empty());
    EXPECT_NE(describe(p).find("written by the material pass into P-buffer 0 (render target 3)"), std::string::npos);
    c.max_draw_buffers = 3;  // the three targets' MRT, none to spare
    p = with(c, o);
    EXPECT_TRUE(p.mrt);
    EXPECT_FALSE(p.ambient_target);
    EXPECT_EQ(p.ambient_target_note, "the GL has no draw buffer beyond the G-buffer's");
    c.max_draw_buffers = 4;
    o.depth = DepthPath::packed;  // four targets
    EXPECT_FALSE(with(c, o).ambient_target);
    c.max_draw_buffers = 5;
    EXPECT_TRUE(with(c, o).ambient_target);
    EXPECT_FALSE(choose_paths(caps_for(1), o).ambient_target) << "no MRT";
    EXPECT_FALSE(choose_paths(caps_for(4), o).ambient_target) << "no framebuffer objects";
    o.depth = DepthPath::texture;
    // One format per framebuffer without ARB_framebuffer_object: a half-float P-buffer 0 only with it.
    o.hdr.accum = AccumFormat::half;
    c.fbo_mixed_formats = false;
    EXPECT_FALSE(with(c, o).ambient_target);
    c.fbo_mixed_formats = true;
    EXPECT_TRUE(with(c, o).ambient_target);
    o.hdr.accum = AccumFormat::rgba8;
    o.depth = DepthPath::position32;  // RGBA8 diffuse beside the float position, with mixed formats
    EXPECT_TRUE(with(c, o).ambient_target);
    c.fbo_mixed_formats = false;  // every target float then
    EXPECT_EQ(with(c, o).ambient_target_note, "the diffuse target is not RGBA8");
    o.depth = DepthPath::texture;
    o.gbuffer_half = true;
    EXPECT_EQ(with(c, o).ambient_target_note, "the diffuse target is not RGBA8");
    o.gbuffer_half = false;
    o.ssao.on = true;
    EXPECT_EQ(with(c, o).ambient_target_note, "SSAO scales the ambient pass alone");
    o.ssao.on = false;
    o.light_geometry = LightGeometry::screen;
    EXPECT_EQ(with(c, o).ambient_target_note, "the screen geometry writes the ambient itself");
    o.light_geometry = LightGeometry::quad;
    o.skip.ambient_target = false;
    p = with(c, o);
    EXPECT_FALSE(p.ambient_target);
    EXPECT_TRUE(p.ambient_target_note.empty());
    EXPECT_NE(describe(p).find("ambient pass (Listing 15)\n"), std::string::npos);
}

}  // namespace dsr
