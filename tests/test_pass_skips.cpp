// The pass skips (SkipOptions: depth_prepass, ambient_target, ambient_pass, final_pass): each leaves
// a pass out, and the image stays what the pass would have made (0 LSB for the pre-pass, the ambient
// target and the final pass, within 1 LSB for the ambient fold, which rounds once instead of twice).
// Each test also checks the skip happened (FrameStats' depth_prepass_ran, final_pass_ran,
// ambient_in_material, ambient_folded).
#include <gtest/gtest.h>

#include "analysis/bench_scenes.h"
#include "deferred/ambient_fold.h"
#include "deferred/depth_prepass.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {

constexpr int kSize = 128;

struct Frames {
    std::vector<FrameStats> stats;
    Image image;  // the last frame's, as a headless render reads it
};

// `frames` frames of `scene` on one DeferredShader, the last read back as `dsr render` reads it
// (read_back: the final pass may be skipped).
// gpu_paths: the paths a GPU gets (Caps::software_rasterizer off), drawn by this GL.
Frames render_frames(const Scene& scene, const ShaderOptions& opts, int frames, bool read_back = true,
                     const std::vector<std::string>& force_off = {}, int out_w = kSize, int out_h = kSize,
                     bool gpu_paths = false) {
    auto ctx = create_context(ContextDesc{"osmesa", std::max(kSize, out_w), std::max(kSize, out_h)});
    Caps caps = probe_caps(force_off);
    if (gpu_paths) caps.software_rasterizer = false;
    DeferredShader ds(caps, kSize, kSize, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    ds.set_read_back(read_back);
    Frames r;
    for (int i = 0; i < frames; ++i) r.stats.push_back(ds.render(scene, out_w, out_h));
    r.image = opaque(ds.read_output(out_w, out_h));
    return r;
}

ShaderOptions no_skip(bool SkipOptions::*field, ShaderOptions o = {}) {
    o.skip.*field = false;
    return o;
}

// The fold's tests: the material pass writes no ambient term, so the fold is what skips the pass.
ShaderOptions no_target(ShaderOptions o = {}) { return no_skip(&SkipOptions::ambient_target, o); }

// Ten discs facing the camera, drawn far to near, each covering the one behind: every pixel of
// the nearest is drawn ten times in draw order, the overdraw the pre-pass is for.
Scene stacked_scene() {
    Scene s = lit_sphere_scene();
    s.objects.clear();
    s.meshes.clear();
    for (int i = 0; i < 10; ++i) add_sphere(s, 1.0f, {0, 0, -2.0f + 0.2f * i}, 0);
    return s;
}

}  // namespace

// The choice: the first frame runs the pre-pass (nothing measured yet); below the threshold the
// next frames leave it out, above it they keep it; a frame without it that measures more shaded
// fragments against the last covered count brings it back; and every kRemeasure frames it runs.
TEST(PassSkips, DepthPrepassChoice) {
    DepthPrepassChoice c(1.5, 4);
    EXPECT_TRUE(c.run_next());
    EXPECT_FALSE(c.complexity());
    c.measured_without(1000);  // nothing to set it against: still measuring
    EXPECT_TRUE(c.run_next());
    c.measured_with_prepass(1200, 1000);
    EXPECT_DOUBLE_EQ(*c.complexity(), 1.2);
    EXPECT_FALSE(c.run_next());
    c.measured_without(1400);
    EXPECT_FALSE(c.run_next());
    c.measured_without(1600);  // 1.6 per covered pixel
    EXPECT_TRUE(c.run_next());
    c.measured_with_prepass(3000, 1000);
    EXPECT_TRUE(c.run_next());
    c.measured_with_prepass(0, 0);  // nothing drawn: nothing to save
    EXPECT_FALSE(c.run_next());
    for (int i = 0; i < 3; ++i) {
        c.measured_without(0);
        EXPECT_FALSE(c.run_next()) << i;
    }
    c.measured_without(0);
    EXPECT_TRUE(c.run_next()) << "the fourth frame without it measures again";
}

// The default scene has little overdraw: from the second frame on the pre-pass is left out, and
// the image is the pre-pass's to the byte, with MRT and with one material pass per target.
TEST(PassSkips, DepthPrepassSkippedSameImage) {
    const Scene s = default_scene();
    for (const bool mrt : {true, false}) {
        const std::vector<std::string> caps = mrt ? std::vector<std::string>{} : std::vector<std::string>{"no-mrt"};
        for (DepthPath p : {DepthPath::texture, DepthPath::packed}) {
            const Frames skip = render_frames(s, with_depth(p), 3, true, caps);
            const Frames full = render_frames(s, no_skip(&SkipOptions::depth_prepass, with_depth(p)), 3, true, caps);
            ASSERT_TRUE(skip.stats[1].passes.depth_complexity);
            std::printf("[ prepass  ] %s %s: depth complexity %.3f\n", mrt ? "mrt" : "no-mrt", depth_path_name(p),
                        *skip.stats[1].passes.depth_complexity);
            EXPECT_TRUE(skip.stats[0].passes.depth_prepass) << "the first frame measures";
            EXPECT_FALSE(skip.stats[1].passes.depth_prepass);
            EXPECT_FALSE(skip.stats[2].passes.depth_prepass);
            EXPECT_TRUE(full.stats[2].passes.depth_prepass);
            EXPECT_FALSE(full.stats[2].passes.depth_complexity) << "not measured with the skip off";
            const ImageDiff d = compare_logged("depth pre-pass skipped vs run", skip.image, full.image, 0);
            EXPECT_EQ(d.max_abs, 0.0);
        }
    }
}

// Heavy overdraw keeps the pre-pass: ten discs, each drawn over the last.
TEST(PassSkips, DepthPrepassKeptUnderOverdraw) {
    const Frames f = render_frames(stacked_scene(), ShaderOptions{}, 3);
    ASSERT_TRUE(f.stats[1].passes.depth_complexity);
    std::printf("[ prepass  ] stacked discs: depth complexity %.3f\n", *f.stats[1].passes.depth_complexity);
    EXPECT_GT(*f.stats[1].passes.depth_complexity, DepthPrepassChoice::kThreshold);
    EXPECT_TRUE(f.stats[1].passes.depth_prepass);
    EXPECT_TRUE(f.stats[2].passes.depth_prepass);
}

// A headless render read back at the buffers' size reads P-buffer 0 directly: the same bytes as
// the final pass's copy, on every render-target path. At another output size the final pass runs.
TEST(PassSkips, FinalPassSkippedSameImage) {
    const Scene s = default_scene();
    for (const char* off : {"", "no-fbo"}) {
        const std::vector<std::string> caps = *off ? std::vector<std::string>{off} : std::vector<std::string>{};
        const Frames skip = render_frames(s, ShaderOptions{}, 1, true, caps);
        const Frames full = render_frames(s, no_skip(&SkipOptions::final_pass), 1, true, caps);
        const Frames window = render_frames(s, ShaderOptions{}, 1, false, caps);  // a viewer: the final pass runs
        EXPECT_FALSE(skip.stats[0].passes.final) << off;
        EXPECT_EQ(skip.stats[0].ms.final, 0.0);
        EXPECT_TRUE(full.stats[0].passes.final) << off;
        EXPECT_TRUE(window.stats[0].passes.final) << off;
        EXPECT_EQ(compare_logged("final pass skipped vs run", skip.image, full.image, 0).max_abs, 0.0) << off;
        EXPECT_EQ(compare_images(window.image, full.image, 0).max_abs, 0.0) << off;
    }
    const Frames scaled = render_frames(s, ShaderOptions{}, 1, true, {}, 160, 120);
    EXPECT_TRUE(scaled.stats[0].passes.final) << "another output size needs the final pass's scaling";
    EXPECT_EQ(scaled.image.width, 160);
}

// With a light over the whole screen the ambient pass folds into its pass, with the scissors on
// (the directional light) and off (every light; the first is folded). The GL's rounding into RGBA8
// is measured and the fold rounds each term as the ambient pass and the light's own pass would: the
// same bytes (the brief allows 1 LSB). Without framebuffer objects nothing measures the rounding and
// the fold, which would round once instead of twice, is not made. Not with SSAO.
TEST(PassSkips, AmbientFoldedSameImage) {
    const Scene s = with_directional(default_scene());
    for (const char* off : {"", "no-fbo"}) {
        const std::vector<std::string> caps = *off ? std::vector<std::string>{off} : std::vector<std::string>{};
        for (const bool scissor : {true, false}) {
            ShaderOptions o = no_target();
            o.scissor = scissor;
            o.light_geometry = LightGeometry::quad;  // a pass per light: the fold's pass replaces its light's
            const Frames fold = render_frames(s, o, 1, true, caps);
            const Frames full = render_frames(s, no_skip(&SkipOptions::ambient_pass, o), 1, true, caps);
            EXPECT_EQ(fold.stats[0].passes.ambient_folded(), !*off) << off;
            EXPECT_FALSE(full.stats[0].passes.ambient_folded());
            EXPECT_EQ(fold.stats[0].lights.passes, full.stats[0].lights.passes);
            const std::string name = std::string("ambient folded vs not") + (scissor ? "" : ", no scissor") + (*off ? ", no-fbo" : "");
            const ImageDiff d = compare_logged(name, fold.image, full.image, 1.0 / 255.0);
            EXPECT_EQ(d.max_abs, 0.0) << name;
        }
    }
    // LearnOpenGL's lights, of the attenuation law, each over the whole screen without the scissors:
    // the first folded through that law's form (light_fold_point_inverse), the same bytes.
    {
        ShaderOptions o = no_target();
        o.scissor = false;
        o.light_geometry = LightGeometry::quad;
        const Scene demo = large_lights_scene(8);
        const Frames fold = render_frames(demo, o, 1);
        const Frames full = render_frames(demo, no_skip(&SkipOptions::ambient_pass, o), 1);
        EXPECT_TRUE(fold.stats[0].passes.ambient_folded());
        EXPECT_EQ(compare_logged("ambient folded vs not, attenuation law", fold.image, full.image, 1.0 / 255.0).max_abs,
                  0.0);
    }
    // Without a full-screen light there is nothing to fold into.
    EXPECT_FALSE(render_frames(default_scene(), no_target(), 1).stats[0].passes.ambient_folded());
    ShaderOptions ssao;
    ssao.ssao.on = true;
    EXPECT_FALSE(render_frames(s, ssao, 1).stats[0].passes.ambient_folded()) << "SSAO scales the ambient pass alone";
    // Into half floats the fold would round once where the passes round twice (1.12 LSB off on
    // data/mesh.scene): it is made into RGBA8 (the rounding emulated) and 32-bit floats only.
    ShaderOptions half = no_target();
    half.light_geometry = LightGeometry::quad;
    half.hdr.accum = AccumFormat::half;
    EXPECT_FALSE(render_frames(s, half, 1).stats[0].passes.ambient_folded());
    half.hdr.accum = AccumFormat::float32;
    EXPECT_TRUE(render_frames(s, half, 1).stats[0].passes.ambient_folded());
}

// The material pass writes Listing 15's ambient term into P-buffer 0, a render target after the
// G-buffer's: no ambient pass, and the bytes of the tutorial's clear and ambient pass, in every
// P-buffer format and with lights of every geometry that takes it (the default scene's diffuse maps
// on a white colour, the coloured spheres; ambient 0.15 x a stored byte lands on rounding ties, where
// x / 255 instead of the sampler's x (1/255) was 1 LSB off on 0.4% of the default scene's pixels).
TEST(PassSkips, AmbientWrittenByTheMaterialPass) {
    for (const Scene& s : {with_directional(default_scene()), lit_sphere_scene()}) {
        for (AccumFormat a : {AccumFormat::rgba8, AccumFormat::half, AccumFormat::float32}) {
            for (LightGeometry g : {LightGeometry::quad, LightGeometry::tiles, LightGeometry::automatic}) {
                ShaderOptions o;
                o.hdr.accum = a;
                o.light_geometry = g;
                ShaderOptions tutorial = no_target(no_skip(&SkipOptions::ambient_pass, o));
                const Frames target = render_frames(s, o, 1);
                const Frames full = render_frames(s, tutorial, 1);
                const std::string name = std::string("ambient target, ") + accum_format_name(a) + ", " +
                                         light_geometry_name(g);
                EXPECT_TRUE(target.stats[0].passes.ambient_in_material()) << name;
                EXPECT_FALSE(target.stats[0].passes.ambient_folded()) << name;
                EXPECT_EQ(target.stats[0].ms.ambient, 0.0) << name;
                EXPECT_FALSE(full.stats[0].passes.ambient_in_material()) << name;
                EXPECT_EQ(compare_logged(name, target.image, full.image, 0).max_abs, 0.0) << name;
            }
        }
    }
    // Where the GL or the options leave no room for it, the ambient pass (or the fold) runs.
    EXPECT_FALSE(render_frames(default_scene(), ShaderOptions{}, 1, true, {"no-mrt"}).stats[0].passes.ambient_in_material());
    ShaderOptions ssao, screen;
    ssao.ssao.on = true;
    screen.light_geometry = LightGeometry::screen;
    EXPECT_FALSE(render_frames(default_scene(), ssao, 1).stats[0].passes.ambient_in_material()) << "SSAO";
    EXPECT_FALSE(render_frames(default_scene(), screen, 1).stats[0].passes.ambient_in_material()) << "screen";
}

// Where the material pass does not write the ambient term and a frame hands the depth off, the
// hand-off's pass writes it (Paths::ambient_in_handoff): no ambient pass, and the bytes of the
// tutorial's clear and ambient pass (the stored diffuse target times the ambient colour, rounded once
// into P-buffer 0 as the pass's modulate is), on both depth paths, into RGBA8, half and float
// P-buffers. The default scene's diffuse maps and 256 lights, drawn as volumes and stencil volumes,
// which hand off every frame, by a pass (on a CPU rasteriser a blit's hand-off does not take it).
TEST(PassSkips, AmbientWrittenByTheHandoff) {
    const Scene s = with_generated_lights(default_scene(), 256);
    struct Case {
        LightGeometry geometry;
        DepthPath depth;
        AccumFormat accum;
        const char* caps;
    };
    const Case cases[] = {
        {LightGeometry::volume, DepthPath::texture, AccumFormat::rgba8, ""},
        {LightGeometry::volume, DepthPath::texture, AccumFormat::float32, ""},
        {LightGeometry::volume, DepthPath::packed, AccumFormat::rgba8, ""},
        {LightGeometry::volume, DepthPath::texture, AccumFormat::rgba8, "no-framebuffer-blit"},
        {LightGeometry::stencil, DepthPath::texture, AccumFormat::half, ""},
        {LightGeometry::volume, DepthPath::texture, AccumFormat::rgba8, "no-fbo"},
    };
    for (const Case& c : cases) {
        ShaderOptions o = no_target();
        o.light_geometry = c.geometry;
        o.depth = c.depth;
        o.hdr.accum = c.accum;
        o.depth_handoff = DepthHandoff::pass;
        const std::vector<std::string> caps = *c.caps ? std::vector<std::string>{c.caps} : std::vector<std::string>{};
        const Frames handoff = render_frames(s, o, 1, true, caps);
        const Frames tutorial = render_frames(s, no_skip(&SkipOptions::ambient_pass, o), 1, true, caps);
        const std::string name = std::string("ambient in the hand-off, ") + light_geometry_name(c.geometry) + ", " +
                                 depth_path_name(c.depth) + ", " + accum_format_name(c.accum) + (*c.caps ? ", " : "") + c.caps;
        EXPECT_TRUE(handoff.stats[0].passes.ambient_in_handoff()) << name;
        EXPECT_FALSE(handoff.stats[0].passes.ambient_in_material()) << name;
        EXPECT_EQ(handoff.stats[0].ms.ambient, 0.0) << name;
        EXPECT_FALSE(tutorial.stats[0].passes.ambient_in_handoff()) << name;
        EXPECT_GT(tutorial.stats[0].ms.ambient, 0.0) << name;
        EXPECT_EQ(compare_logged(name, handoff.image, tutorial.image, 0).max_abs, 0.0) << name;
    }
}

// A GPU's paths, drawn here: no ambient target where a frame may hand off, and the hand-off that
// would be a blit becomes the pass that writes the ambient term. The same bytes as the tutorial's
// clear and ambient pass with the ambient target off (volume hands off every frame; auto's default
// frames as they come).
TEST(PassSkips, AmbientWrittenByTheHandoffOnAGpusPaths) {
    const Scene s = with_generated_lights(default_scene(), 256);
    for (const LightGeometry g : {LightGeometry::volume, LightGeometry::automatic}) {
        for (const DepthPath d : {DepthPath::texture, DepthPath::packed}) {
            ShaderOptions o;
            o.light_geometry = g;
            o.depth = d;
            ShaderOptions tutorial_opts = no_skip(&SkipOptions::ambient_pass, no_target(o));
            const Frames gpu = render_frames(s, o, 2, true, {}, kSize, kSize, true);
            const Frames tutorial = render_frames(s, tutorial_opts, 2, true, {}, kSize, kSize, true);
            const std::string name = std::string("a GPU's paths, ") + light_geometry_name(g) + ", " + depth_path_name(d);
            EXPECT_FALSE(gpu.stats[1].passes.ambient_in_material()) << name;
            if (g == LightGeometry::volume) {
                EXPECT_TRUE(gpu.stats[1].passes.ambient_in_handoff()) << name;
            }
            EXPECT_FALSE(tutorial.stats[1].passes.ambient_in_handoff()) << name;
            EXPECT_FALSE(tutorial.stats[1].passes.ambient_in_material()) << name;
            EXPECT_EQ(compare_logged(name, gpu.image, tutorial.image, 0).max_abs, 0.0) << name;
        }
    }
}

TEST(PassSkips, AmbientInTheHandoffNotWhereItIsNotWanted) {
    const Scene s = with_generated_lights(default_scene(), 256);
    // Not where the material pass writes it (this GL's default), nor with SSAO, nor where no frame
    // hands off (quad draws nothing against the scene's depth); on a CPU rasteriser not into a blit.
    ShaderOptions volume;
    volume.light_geometry = LightGeometry::volume;
    volume.depth_handoff = DepthHandoff::pass;
    EXPECT_FALSE(render_frames(s, volume, 1).stats[0].passes.ambient_in_handoff());
    ShaderOptions blit = no_target(volume);
    blit.depth_handoff = DepthHandoff::automatic;
    const bool software = [] {
        auto ctx = create_context(ContextDesc{"osmesa", kSize, kSize});
        return probe_caps({}).software_rasterizer;
    }();
    EXPECT_EQ(render_frames(s, blit, 1).stats[0].passes.ambient_in_handoff(), !software);
    ShaderOptions ssao = no_target(volume);
    ssao.ssao.on = true;
    EXPECT_FALSE(render_frames(s, ssao, 1).stats[0].passes.ambient_in_handoff()) << "SSAO scales the ambient pass alone";
    ShaderOptions quad = no_target();
    quad.light_geometry = LightGeometry::quad;
    EXPECT_FALSE(render_frames(s, quad, 1).stats[0].passes.ambient_in_handoff());
}

// The fold only where the light geometry would draw the full-screen light by a pass of its own:
// the tiles and screen take it into a batch, where a fold would add a pass. The tiles draw the
// ambient pass instead (their image stays quad's with the skip off); the screen's first batch
// writes the ambient itself, as LearnOpenGL's lighting pass does, with no pass added. Auto folds
// where it sent that light by quad or volume, and then counts it on no path.
TEST(PassSkips, AmbientFoldsOnlyIntoAPassOfItsOwn) {
    const Scene s = with_directional(default_scene());
    ShaderOptions quad = no_target();
    quad.light_geometry = LightGeometry::quad;
    const Frames ref = render_frames(s, no_skip(&SkipOptions::ambient_pass, quad), 1);
    for (LightGeometry g : {LightGeometry::tiles, LightGeometry::screen, LightGeometry::automatic}) {
        ShaderOptions o = no_target();
        o.light_geometry = g;
        const Frames r = render_frames(s, o, 2);
        const std::string name = light_geometry_name(g);
        const FrameStats& st = r.stats[1];
        if (g != LightGeometry::automatic) {
            EXPECT_EQ(st.passes.ambient_folded(), g == LightGeometry::screen) << name;
            EXPECT_EQ(st.lights.passes, render_frames(s, no_skip(&SkipOptions::ambient_pass, o), 2).stats[1].lights.passes) << name;
        } else {
            EXPECT_EQ(st.auto_geometry.lights[at(LightPath::quad)] + st.auto_geometry.lights[at(LightPath::volume)] + st.auto_geometry.lights[at(LightPath::tiles)] + int(st.passes.ambient_folded()), st.lights.drawn);
        }
        const double lsb = g == LightGeometry::screen ? 6.0 / 255.0 : 1.0 / 255.0;
        EXPECT_LE(compare_logged("ambient fold, " + name, r.image, ref.image, lsb).max_abs, lsb) << name;
    }
}

// The fold's pure part: the first full-screen light, and the frame without it.
TEST(PassSkips, FullScreenLight) {
    FrameDef f;
    Light a, b;
    LightDraw la, lb;
    la.light = &a;
    lb.light = &b;
    f.lights = {la, lb};
    EXPECT_FALSE(full_screen_light(f));
    f.lights[1].full = true;
    ASSERT_TRUE(full_screen_light(f));
    EXPECT_EQ(*full_screen_light(f), 1u);
    f.lights_total = 2;
    const FrameDef g = without_light(f, 1);
    ASSERT_EQ(g.lights.size(), 1u);
    EXPECT_EQ(g.lights[0].light, &a);
    EXPECT_EQ(g.lights_total, 2);
}

// The G-buffer's clears (SkipOptions::gbuffer_clears). ambient_pass_possible, over every
// combination of the facts known before the geometry stage: where it says no pass can write the
// ambient term, no value of the facts known later (the lights, the plan) makes decide_ambient
// answer one; where it says one can, some value does.
TEST(PassSkips, AmbientPassPossibleAgreesWithEveryLaterFact) {
    for (int bits = 0; bits < 32; ++bits)
        for (const bool certain : {false, true}) {
            AmbientFacts a;
            a.material_pass = bits & 1;
            a.ssao = bits & 2;
            a.fold_program = bits & 4;
            a.geometry_draws_own = bits & 8;
            a.handoff_program = bits & 16;
            bool some_pass = false;
            for (int later = 0; later < 32; ++later) {
                a.has_lights = later & 1;
                a.full_screen_light = later & 2;
                a.plan_reads_back = later & 4;
                PlanFacts p;
                p.own_pass = later & 8;
                p.hands_off = (later & 16) || certain;
                const AmbientWriter w = decide_ambient(a, p);
                some_pass = some_pass || w == AmbientWriter::pass_before_plan || w == AmbientWriter::pass_after_plan;
            }
            a.has_lights = a.full_screen_light = a.plan_reads_back = false;
            EXPECT_EQ(ambient_pass_possible(a, certain), some_pass) << "facts " << bits << ", hand-off certain " << certain;
        }
}

namespace {

// Two frames on one DeferredShader, the camera moved between them so that the second frame's
// background holds what the first frame's surfaces wrote where its clears are left out; the
// second frame's image and, with `view`, that view of it.
struct TwoFrames {
    FrameStats first, second;
    Image image;
};
TwoFrames two_frames(const Scene& scene, const ShaderOptions& opts, View view, bool gpu_paths,
                     const std::vector<std::string>& force_off = {}) {
    auto ctx = create_context(ContextDesc{"osmesa", kSize, kSize});
    Caps caps = probe_caps(force_off);
    if (gpu_paths) caps.software_rasterizer = false;
    DeferredShader ds(caps, kSize, kSize, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    ds.set_read_back(true);
    TwoFrames r;
    r.first = ds.render(scene, kSize, kSize);
    Scene moved = scene;  // the camera moved sideways: the background takes pixels surfaces had
    const glm::vec3 step = 0.15f * glm::length(scene.camera.pos - scene.camera.target) * glm::vec3(1.0f, 0.6f, 0.0f);
    moved.camera.pos += step;
    moved.camera.target += step;
    r.second = ds.render(moved, kSize, kSize);
    if (view == View::final) {
        r.image = opaque(ds.read_output(kSize, kSize));
    } else {
        ds.draw_view(view, moved.camera, kSize, kSize);
        r.image = opaque(read_pixels(kSize, kSize));
    }
    return r;
}

}  // namespace

// The skip leaves out the specular target's clear always and the diffuse target's where no pass
// reads its alpha; the image, and every G-buffer view, is what every clear gives, on the CPU's
// paths (the material pass writes the ambient term), a GPU's (the hand-off writes it where the
// light markers' forward stage makes every frame hand off; else the ambient pass, with the
// diffuse clear), without MRT, on the packed and position paths, with SSAO and the edge blur.
TEST(PassSkips, GbufferClearsSkippedSameImage) {
    // The default scene with lights enough for the light geometries' paths; a sphere on the
    // background, lit by a directional light too, which reaches the background's pixels.
    const Scene scenes[] = {with_generated_lights(default_scene(), 64), with_directional(lit_sphere_scene())};
    struct Case {
        const char* name;
        DepthPath depth;
        bool gpu_paths, show_lights, ssao, aa, half;
        const char* caps;
        int clears;  // colour clears of the second frame with the skip on
    };
    const Case cases[] = {
        {"cpu paths", DepthPath::texture, false, false, false, false, false, "", 1},
        {"cpu paths, light markers", DepthPath::texture, false, true, false, false, false, "", 1},
        {"gpu paths", DepthPath::texture, true, false, false, false, false, "", 2},
        {"gpu paths, light markers", DepthPath::texture, true, true, false, false, false, "", 1},
        {"gpu paths, light markers, packed", DepthPath::packed, true, true, false, false, false, "", 2},
        {"gpu paths, light markers, position16, half", DepthPath::position16, true, true, false, false, true, "", 2},
        {"no mrt, packed", DepthPath::packed, false, false, false, false, false, "no-mrt", 3},
        {"ssao, aa", DepthPath::texture, false, false, true, true, false, "", 2},
    };
    for (const Case& c : cases) {
        ShaderOptions o = with_depth(c.depth);
        o.show_lights = c.show_lights;
        o.ssao.on = c.ssao;
        o.post.aa = c.aa;
        o.gbuffer_half = c.half;
        const std::vector<std::string> caps = *c.caps ? std::vector<std::string>{c.caps} : std::vector<std::string>{};
        const std::pair<int, View> runs[] = {{0, View::final},   {1, View::final},   {1, View::normal},
                                             {1, View::diffuse}, {1, View::specular}};
        for (const auto& [k, v] : runs) {
            const Scene& s = scenes[k];
            const std::string name = std::string("G-buffer clears skipped, ") + (k == 0 ? "64 lights, " : "sphere, ") +
                                     c.name + ", view " + view_name(v);
            const TwoFrames skip = two_frames(s, o, v, c.gpu_paths, caps);
            const TwoFrames full = two_frames(s, no_skip(&SkipOptions::gbuffer_clears, o), v, c.gpu_paths, caps);
            EXPECT_EQ(skip.first.passes.gbuffer_clears, full.first.passes.gbuffer_clears) << name << ": new targets";
            EXPECT_EQ(skip.second.passes.gbuffer_clears, c.clears) << name;
            EXPECT_EQ(full.second.passes.gbuffer_clears, c.depth == DepthPath::texture ? 3 : 4) << name;
            EXPECT_EQ(compare_logged(name, skip.image, full.image, 0).max_abs, 0.0) << name;
        }
    }
}
