// GL state through one door (gl/state.h): the cache always says what GL holds, each stage
// states everything it needs (scrambling GL between stages changes no pixel), and the cache
// skips what is unchanged while its off switch sets everything and gives the same image.
#include <gtest/gtest.h>

#include "gl/rounding_probe.h"
#include "gl/state.h"
#include "render_fixture.h"

namespace dsr {
namespace {

std::string describe(const RenderState& s) {
    char b[512];
    std::snprintf(b, sizeof b,
                  "blend %d %#x %#x depth %d %#x w%d stencil %d f(%#x %d %#x %#x %#x %#x %#x) b(%#x %d) cull %d %#x "
                  "scissor %d color %d alpha %d %#x %.2f tex %d %#x program %u dither %d point %.1f",
                  s.blend, s.blend_src, s.blend_dst, s.depth_test, s.depth_func, s.depth_write, s.stencil_test,
                  s.stencil_front.func, s.stencil_front.ref, s.stencil_front.mask, s.stencil_front.fail,
                  s.stencil_front.zfail, s.stencil_front.zpass, s.stencil_front.write_mask, s.stencil_back.func,
                  s.stencil_back.ref, s.cull, s.cull_face, s.scissor, s.color_write, s.alpha_test, s.alpha_func,
                  s.alpha_ref, s.texture_2d, s.tex_env, s.program, s.dither, double(s.point_size));
    return b;
}

// Every RenderState field set away from what any pass uses, straight through GL; then the
// cache is told GL changed behind its back (what a viewer overlay does).
void scramble() {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_NEVER, 1, 0x0f);
    glStencilOpSeparate(GL_FRONT_AND_BACK, GL_ZERO, GL_INVERT, GL_INCR);
    glStencilMaskSeparate(GL_FRONT_AND_BACK, 0x3);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 1, 2, 2);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_NEVER, 1.0f);
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glUseProgram(0);
    glEnable(GL_DITHER);
    glPointSize(7.0f);
    gl_state().reset();
}

ShaderOptions with_post() {
    ShaderOptions o;
    o.post.bloom = o.post.aa = true;
    return o;
}

struct StageRun {
    Image image;
    std::vector<std::string> mismatches;  // stage: cache vs GL
};

// The frame stage by stage; after each, the cache is compared with glGet*, and with
// `scramble_between` GL is scrambled before the next stage.
StageRun run_stages(const Scene& scene, int w, int h, const ShaderOptions& opts,
                    const std::vector<std::string>& caps_off, bool scramble_between) {
    auto ctx = create_context(ContextDesc{"osmesa", w, h});
    Caps caps = probe_caps(caps_off);
    DeferredShader ds(caps, w, h, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    StageRun r;
    auto after = [&](const char* stage) {
        RenderState gl = read_gl_state();
        if (gl != gl_state().current())
            r.mismatches.push_back(std::string(stage) + ": GL " + describe(gl) + "\n   cache " +
                                   describe(gl_state().current()));
        if (scramble_between) scramble();
    };
    if (scramble_between) scramble();
    FrameStats st;
    ds.geometry_stage(scene);
    after("geometry");
    ds.draw_lights(scene, true, st);
    after("lights");
    ds.post_stage(scene.camera);
    after("post");
    ds.final_stage(w, h);
    after("final");
    r.image = read_pixels(w, h);
    return r;
}

struct Config {
    const char* name;
    std::vector<std::string> caps_off;
    DepthPath depth;
    bool shadows = false;  // the first light casts shadows (the shadow stage draws before the lights)
    LightGeometry geometry = LightGeometry::automatic;
};

const Config kConfigs[] = {
    {"full", {}, DepthPath::texture},
    {"packed", {}, DepthPath::packed},
    {"no-mrt", {"no-mrt"}, DepthPath::texture},
    {"no-fbo (copy P-buffers)", {"no-fbo"}, DepthPath::texture},
    {"no-npot", {"no-npot"}, DepthPath::texture},
    {"shadows", {}, DepthPath::texture, true},
    {"no-fbo shadows (maps copied from the main buffer)", {"no-fbo"}, DepthPath::texture, true},
    {"no-fbo packed shadows", {"no-fbo", "no-depth-texture"}, DepthPath::packed, true},
    {"tiles (drawn as points here)", {}, DepthPath::texture, false, LightGeometry::tiles},
};

// The default scene, its first light casting shadows where c asks.
Scene config_scene(const Config& c) {
    Scene s = test::default_scene();
    if (c.shadows) s.lights[0].shadow.on = true, s.lights[0].shadow.size = 256;
    return s;
}

TEST(GlState, CacheMatchesGlAfterEveryStage) {
    for (const Config& c : kConfigs) {
        const Scene scene = config_scene(c);
        ShaderOptions o = with_post();
        o.depth = c.depth;
        o.shadow_lights = c.shadows;
        o.light_geometry = c.geometry;
        StageRun r = run_stages(scene, 96, 64, o, c.caps_off, false);
        for (const auto& m : r.mismatches) ADD_FAILURE() << c.name << ", after " << m;
    }
}

TEST(GlState, NoStageReliesOnWhatThePreviousLeft) {
    for (const Config& c : kConfigs) {
        const Scene scene = config_scene(c);
        ShaderOptions o = with_post();
        o.depth = c.depth;
        o.shadow_lights = c.shadows;
        o.light_geometry = c.geometry;
        StageRun clean = run_stages(scene, 96, 64, o, c.caps_off, false);
        StageRun scrambled = run_stages(scene, 96, 64, o, c.caps_off, true);
        ImageDiff d = compare_images(scrambled.image, clean.image, 0.5 / 255.0);
        EXPECT_EQ(d.failing, 0) << c.name << ": scrambling GL state between stages changed " << d.failing
                                << " pixels (max " << d.max_lsb() << " LSB)";
    }
}

// The matrices go through the same door (GlState::set_camera): each pass states its camera, so
// garbage in both matrices, and GL_PROJECTION left the current mode, between stages change no
// pixel. Light markers and the volume geometry draw with the frame's projection and a modelview
// per draw; the other passes with their pixel camera.
void scramble_matrices() {
    const float garbage[16] = {3, 1, 0, 0, -1, 2, 0, 0, 0, 0, 5, 1, 7, -9, 2, 4};
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(garbage);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(garbage);
}

Image stages_with_matrices(const Scene& scene, int w, int h, const ShaderOptions& opts, bool scramble) {
    auto ctx = create_context(ContextDesc{"osmesa", w, h});
    DeferredShader ds(probe_caps(), w, h, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    FrameStats st;
    if (scramble) scramble_matrices();
    ds.geometry_stage(scene);
    if (scramble) scramble_matrices();
    ds.draw_lights(scene, true, st);
    if (scramble) scramble_matrices();
    ds.post_stage(scene.camera);
    if (scramble) scramble_matrices();
    ds.final_stage(w, h);
    return read_pixels(w, h);
}

TEST(GlState, EveryPassStatesItsCamera) {
    const Scene scene = test::default_scene();
    for (bool ssao : {false, true})  // the lighting stage's first pass: the ambient pass, or SSAO's
        for (LightGeometry g : {LightGeometry::quad, LightGeometry::volume, LightGeometry::tiles}) {
            ShaderOptions o = with_post();
            o.show_lights = true;
            o.ssao.on = ssao;
            o.ssao.scale = 2;  // its camera is moved by half a pixel: not the ambient pass's
            o.light_geometry = g;
            const Image clean = stages_with_matrices(scene, 96, 64, o, false);
            const Image scrambled = stages_with_matrices(scene, 96, 64, o, true);
            ImageDiff d = compare_images(scrambled, clean, 0.5 / 255.0);
            EXPECT_EQ(d.failing, 0) << light_geometry_name(g) << (ssao ? ", ssao" : "")
                                    << ": garbage matrices between stages changed " << d.failing << " pixels (max "
                                    << d.max_lsb() << " LSB)";
        }
}

TEST(GlState, CacheOffSetsEverythingAndChangesNoPixel) {
    const Scene scene = test::default_scene();
    const ShaderOptions o = with_post();
    const long long c0 = gl_state().calls();
    test::RenderResult on = test::render_scene(scene, 96, 64, o);
    const long long with_cache = gl_state().calls() - c0;
    gl_state().set_cache(false);
    const long long c1 = gl_state().calls();
    test::RenderResult off = test::render_scene(scene, 96, 64, o);
    const long long without = gl_state().calls() - c1;
    gl_state().set_cache(true);
    ImageDiff d = compare_images(off.image, on.image, 0.5 / 255.0);
    EXPECT_EQ(d.failing, 0) << "the cache changed " << d.failing << " pixels";
    std::printf("[ state    ] GL state calls per frame and set-up: %lld with the cache, %lld without\n", with_cache,
                without);
    EXPECT_LT(with_cache * 2, without) << "the cache should skip most state calls";
}

TEST(GlState, ApplyChangesOnlyWhatDiffers) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    RenderState s;
    s.blend = true;
    s.blend_src = s.blend_dst = GL_ONE;
    gl_state().apply(s);  // first apply after a context: everything
    const long long c0 = gl_state().calls();
    gl_state().apply(s);
    EXPECT_EQ(gl_state().calls(), c0) << "re-applying the same state made GL calls";
    s.depth_test = true;
    gl_state().apply(s);
    EXPECT_EQ(gl_state().calls(), c0 + 1) << "one field changed, one call expected";
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_EQ(read_gl_state(), gl_state().current());
    // reset(): the next apply sets everything, so GL changed behind the cache is repaired.
    glDisable(GL_DEPTH_TEST);
    gl_state().reset();
    gl_state().apply(s);
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_EQ(read_gl_state(), gl_state().current());
}

TEST(GlState, DefaultsAreGlsOwn) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    // Every field's default is GL's, but GL_DITHER: GL starts with it on, dsr turns it off (state.h).
    RenderState gl_defaults;
    gl_defaults.dither = true;
    EXPECT_EQ(read_gl_state(), gl_defaults) << "GL " << describe(read_gl_state()) << "\n   GL's defaults "
                                            << describe(gl_defaults);
}

// The RGBA8 rounding probe `dsr info` prints: on llvmpipe round to nearest, ties to even, no
// dithering; it leaves the cache reset and dither off for the next pass.
TEST(GlState, Unorm8RoundingProbe) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    const Unorm8Rounding r = probe_unorm8_rounding();
    ASSERT_TRUE(r.measured);
    EXPECT_EQ(r.plain[0], 0);
    EXPECT_EQ(r.plain[1], 1);
    EXPECT_EQ(r.added_ten, 10) << "each additive pass rounds 0.6/255 to one step";
    if (probe_caps().renderer.find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(r.plain[2], 2);
        EXPECT_EQ(r.plain[3], 2) << "llvmpipe rounds ties to even";
        EXPECT_EQ(r.dither_min, r.dither_max) << "llvmpipe does not dither";
    }
    if (probe_caps().renderer.find("llvmpipe") != std::string::npos) {
        for (float t : r.threshold) EXPECT_NEAR(t, 0.5f, 0.00051f) << "llvmpipe rounds to nearest";
        EXPECT_EQ(unorm8_truncate_bits(r), 0) << "round(t x 255) explains every threshold";
    }
    EXPECT_EQ(unorm8_round_offset(r), unorm8_round_offset(unorm8_rounding()));
    gl_state().apply(RenderState{});
    EXPECT_FALSE(glIsEnabled(GL_DITHER));
    EXPECT_NE(describe(r).find("10 x 0.6/255 added -> 10"), std::string::npos) << describe(r);
    std::printf("[ rounding ] %s", describe(r).c_str());
}

// The tiles geometry's rounding offset from the probe: round to nearest (whatever the ties) keeps
// 0.5; a GL that turns up later gets 1 minus the median threshold; nothing measured keeps 0.5.
// The truncation model: thresholds made by a GL that truncates to n bits first are told apart
// from round to nearest and from each other n, and the H200's measured ones are n = 12.
TEST(GlState, Unorm8TruncationModelFitsTheThresholdsItMade) {
    for (int bits : {0, 10, 12, 14}) {
        Unorm8Rounding r;
        r.measured = true;
        for (int k = 0; k < 255; ++k) r.threshold[k] = predicted_threshold(bits, k);
        EXPECT_EQ(unorm8_truncate_bits(r), bits);
    }
    // dsr info on the H200 (docs/gpu.md): 0.5605 (k 0), 0.5565 (1), 0.5435 (100), 0.5265 (200).
    EXPECT_FLOAT_EQ(predicted_threshold(12, 0), 0.5605f);
    EXPECT_FLOAT_EQ(predicted_threshold(12, 1), 0.5565f);
    EXPECT_FLOAT_EQ(predicted_threshold(12, 100), 0.5435f);
    EXPECT_FLOAT_EQ(predicted_threshold(12, 200), 0.5265f);
    EXPECT_FLOAT_EQ(predicted_threshold(12, 127), 0.5625f) << "the H200's tie at 127.5 goes down";
    Unorm8Rounding odd;
    odd.measured = true;
    for (int k = 0; k < 255; ++k) odd.threshold[k] = 0.6f;  // a constant late threshold: no model
    EXPECT_EQ(unorm8_truncate_bits(odd), -1);
    EXPECT_NEAR(unorm8_round_offset(odd), 0.4f, 1e-6f);
}

TEST(GlState, Unorm8RoundOffsetFollowsTheMeasuredThreshold) {
    Unorm8Rounding r;
    EXPECT_EQ(unorm8_round_offset(r), 0.5f) << "not measured";
    r.measured = true;
    for (int k = 0; k < 255; ++k) r.threshold[k] = k % 3 ? 0.5005f : 0.5f;
    EXPECT_EQ(unorm8_round_offset(r), 0.5f);
    for (int k = 0; k < 255; ++k) r.threshold[k] = k < 100 ? 0.52f : k < 254 ? 0.53f : -1.0f;
    EXPECT_NEAR(unorm8_round_offset(r), 0.47f, 1e-6f);
    std::fill(r.threshold, r.threshold + 255, -1.0f);
    EXPECT_EQ(unorm8_round_offset(r), 0.5f);
}

}  // namespace
}  // namespace dsr
