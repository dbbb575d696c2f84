// The frame's seams: RenderTargets::resize (no shader rebuilt, same image as a renderer made
// at that size), the FrameTimer's source chosen by measurement, and GL errors named per stage
// only in debug mode.
#include <gtest/gtest.h>

#include "dsr_error.h"
#include "gl/check.h"
#include "gl/frame_timer.h"
#include "render_fixture.h"

namespace dsr {
namespace {

ShaderOptions with_post() {
    ShaderOptions o;
    o.post.bloom = o.post.aa = true;
    return o;
}

Image render_fresh(const Scene& scene, int w, int h, const ShaderOptions& o, const std::vector<std::string>& off) {
    Caps caps = probe_caps(off);
    DeferredShader ds(caps, w, h, o, resource_dir("glsl120"));
    ds.set_scene(scene);
    ds.render(scene, w, h);
    return read_pixels(w, h);
}

TEST(Resize, SameImageAsAFreshRendererAndNoShaderRebuilt) {
    const Scene scene = test::default_scene();
    for (const std::vector<std::string>& off : {std::vector<std::string>{}, {"no-fbo"}, {"no-npot"}}) {
        const std::string label = off.empty() ? "full" : off[0];
        auto ctx = create_context(ContextDesc{"osmesa", 160, 120});
        Caps caps = probe_caps(off);
        DeferredShader ds(caps, 96, 64, with_post(), resource_dir("glsl120"));
        ds.set_scene(scene);
        ds.render(scene, 96, 64);
        // 512² -> 800x600 -> 300x200 in the viewer's test, here scaled to the context.
        for (auto [w, h] : {std::pair{160, 120}, std::pair{75, 50}, std::pair{1, 1}, std::pair{128, 96}}) {
            const long long built = Program::built();
            ds.resize(w, h);
            EXPECT_EQ(Program::built(), built) << label << ": resize rebuilt a shader";
            EXPECT_EQ(ds.width(), w);
            EXPECT_EQ(ds.pbuffer_width(P_ACCUM), w);
            EXPECT_EQ(ds.pbuffer_height(P_BLOOM_V), std::max(1, h / 2));
            ds.render(scene, w, h);
            Image resized = read_pixels(w, h);
            Image fresh = render_fresh(scene, w, h, with_post(), off);
            ImageDiff d = compare_images(resized, fresh, 0.5 / 255.0);
            EXPECT_EQ(d.failing, 0) << label << " at " << w << "x" << h << ": " << d.failing << " pixels differ (max "
                                    << d.max_lsb() << " LSB)";
        }
    }
}

TEST(FrameTimer, LlvmpipeTimerQueriesAreFoundNotToMeasureRasterisation) {
    auto ctx = create_context(ContextDesc{"osmesa", 512, 512});
    Caps caps = probe_caps();
    if (caps.renderer.find("llvmpipe") == std::string::npos) GTEST_SKIP() << "renderer is " << caps.renderer;
    if (!caps.timer_query) GTEST_SKIP() << "no ARB_timer_query";
    const TimingCheck& t = choose_timing(caps, 512, 512);
    std::printf("[ timing   ] %s: %.3f ms by query, %.3f ms by wall clock (%s)\n", timing_name(t.source), t.query_ms,
                t.wall_ms, t.reason.c_str());
    EXPECT_EQ(t.source, TimingSource::wall);
    EXPECT_GT(t.wall_ms, 0);
    // How far the query falls short of the wall clock is printed, not asserted: a timing depends
    // on the load (the suite's shards share the cores), and the choice above rests on the
    // software rasteriser, not on that ratio.
}

TEST(FrameTimer, BothSourcesTimeEveryStageOfAFrame) {
    const Scene scene = test::default_scene();
    auto ctx = create_context(ContextDesc{"osmesa", 96, 64});
    Caps caps = probe_caps();
    for (TimingSource src : {TimingSource::wall, TimingSource::gpu_timer}) {
        if (src == TimingSource::gpu_timer && !caps.timer_query) continue;
        FrameTimer timer(src);
        timer.begin_frame(3);
        timer.begin(0);
        DeferredShader ds(caps, 96, 64, with_post(), resource_dir("glsl120"));
        ds.set_scene(scene);
        timer.end();
        timer.begin(2);
        ds.render(scene, 96, 64);
        timer.end();
        std::vector<double> ms;
        const double frame = timer.end_frame(ms);
        ASSERT_EQ(ms.size(), 3u);
        EXPECT_GT(ms[0], 0) << timing_name(src);
        EXPECT_EQ(ms[1], 0) << timing_name(src) << ": an untimed slot";
        EXPECT_GT(ms[2], 0) << timing_name(src);
        // The wall clock bounds both stages; timer queries may read less (llvmpipe), never more
        // than the wall time by more than clock granularity.
        EXPECT_GE(frame + 0.5, ms[0] + ms[2]) << timing_name(src);
    }
}

TEST(FrameTimer, RenderReportsItsSource) {
    test::RenderResult r = test::render_scene(test::default_scene(), 64, 64, ShaderOptions{});
    auto ctx = create_context(ContextDesc{"osmesa", 512, 512});
    EXPECT_EQ(r.stats.timing, choose_timing(probe_caps(), 512, 512).source);
    EXPECT_GT(r.stats.ms.frame, 0);
    EXPECT_GT(r.stats.ms.geometry, 0);
    EXPECT_GT(r.stats.ms.lights, 0);
}

TEST(DebugGl, StageErrorsNamedOnlyInDebugModeAndAlwaysCaughtByTheFrame) {
    const Scene scene = test::default_scene();
    auto ctx = create_context(ContextDesc{"osmesa", 64, 64});
    Caps caps = probe_caps();
    DeferredShader ds(caps, 64, 64, ShaderOptions{}, resource_dir("glsl120"));
    ds.set_scene(scene);
    for (bool debug : {true, false}) {
        set_debug_gl(debug);
        glEnable(0xdead);  // GL_INVALID_ENUM, pending when the geometry stage starts
        std::string what;
        try {
            ds.render(scene, 64, 64);
        } catch (const Error& e) {
            what = e.what();
        }
        if (debug)
            EXPECT_NE(what.find("GL error in geometry stage"), std::string::npos) << what;
        else
            EXPECT_NE(what.find("GL error in frame"), std::string::npos) << what;
        EXPECT_NE(what.find("GL_INVALID_ENUM"), std::string::npos) << what;
    }
    set_debug_gl(false);
    EXPECT_NO_THROW(ds.render(scene, 64, 64));
}

}  // namespace
}  // namespace dsr
