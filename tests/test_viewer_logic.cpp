// The viewer's pure parts, without a window: the --script parser, the option table that
// `render`, `set` and the panel share, the fly camera, and the scissor overlay against what the
// light pass itself counts.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "deferred/option_table.h"
#include "dsr_error.h"
#include "render_fixture.h"
#include "viewer/fly_camera.h"
#include "viewer/scissor_overlay.h"
#include "viewer/script.h"

using namespace dsr;

namespace {

std::string parse_error(const std::string& text) {
    try {
        parse_script(text, "s.txt");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ViewerScript, EveryCommandParses) {
    const Script s = parse_script(
        "# a comment\n"
        "size 640 480\n"
        "\n"
        "camera pos 0 2 5 target 0 0 0 up 0 1 0   # trailing comment\n"
        "set scissor off\r\n"
        "set view normal\n"
        "set no-skip variants,light-depth-test\n"
        "set overlay on\n"
        "frames 3\n"
        "screenshot out/a.png\n"
        "size 0 0\n"
        "quit\n",
        "s.txt");
    ASSERT_EQ(s.commands.size(), 10u);
    EXPECT_EQ(s.commands[0].kind, ScriptCommand::size);
    EXPECT_EQ(s.commands[0].w, 640);
    EXPECT_EQ(s.commands[0].h, 480);
    EXPECT_EQ(s.commands[0].line, 2);
    EXPECT_EQ(s.commands[1].kind, ScriptCommand::camera);
    EXPECT_EQ(s.commands[1].pos, glm::vec3(0, 2, 5));
    EXPECT_EQ(s.commands[1].up, glm::vec3(0, 1, 0));
    EXPECT_EQ(s.commands[2].name, "scissor");
    EXPECT_EQ(s.commands[2].value, "off");
    EXPECT_EQ(s.commands[3].value, "normal");
    EXPECT_EQ(s.commands[5].name, "overlay");
    EXPECT_EQ(s.commands[6].count, 3);
    EXPECT_EQ(s.commands[7].value, "out/a.png");
    EXPECT_FALSE(s.commands[7].with_panel);
    const Script shot = parse_script("screenshot out/b.png panel\n", "s.txt");
    ASSERT_EQ(shot.commands.size(), 1u);
    EXPECT_EQ(shot.commands[0].kind, ScriptCommand::screenshot);
    EXPECT_EQ(shot.commands[0].value, "out/b.png");
    EXPECT_TRUE(shot.commands[0].with_panel);
    EXPECT_EQ(s.commands[8].w, 0);
    EXPECT_EQ(s.commands[9].kind, ScriptCommand::quit);
    EXPECT_EQ(s.where(s.commands[9]), "s.txt:12: ");
}

// A script ends when it ends (the viewer closes after its last command) unless that command is
// `wait`; comments and blank lines after it do not count.
TEST(ViewerScript, EndsUnlessItsLastCommandIsWait) {
    EXPECT_FALSE(parse_script("frames 2\n", "s.txt").waits());
    EXPECT_FALSE(parse_script("", "s.txt").waits());
    EXPECT_FALSE(parse_script("# only a comment\n", "s.txt").waits());
    EXPECT_FALSE(parse_script("frames 2\nquit\n", "s.txt").waits());
    const Script w = parse_script("size 640 480\nframes 2\nwait   # for a person\n\n# done\n", "s.txt");
    ASSERT_EQ(w.commands.size(), 3u);
    EXPECT_EQ(w.commands[2].kind, ScriptCommand::wait);
    EXPECT_EQ(w.commands[2].line, 3);
    EXPECT_TRUE(w.waits());
    EXPECT_TRUE(parse_script("wait\n", "s.txt").waits());
}

TEST(ViewerScript, BadLineIsOneErrorNamingFileAndLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"frames 2\nfly away\n", "s.txt:2: expected size, camera, set, frames, screenshot, quit or wait, got 'fly'"},
        {"size 640\n", "s.txt:1: expected 'size W H', got 'size 640'"},
        {"size 0 480\n", "s.txt:1: size: expected W H, each in [1, 8192] (or 0 0 to minimise), got '0 480'"},
        {"size 9000 10\n", "s.txt:1: size: expected W H"},
        {"frames -1\n", "s.txt:1: frames: expected an integer in [1, 1000000], got '-1'"},
        {"frames 2x\n", "s.txt:1: frames: expected an integer"},
        {"set scissor maybe\n", "s.txt:1: set scissor: expected on|off, got 'maybe'"},
        {"set view albedo\n", "s.txt:1: set view: expected final|normal|diffuse|specular|depth|blur-factor|bloom|ssao|shadow-map, got 'albedo'"},
        {"set bloom-strength 99\n", "s.txt:1: set bloom-strength: expected a number in [0.000000, 16.000000], got '99'"},
        {"set no-skip fast\n", "s.txt:1: set no-skip: expected variants, empty-lights, light-depth-test, light-sphere-test"},
        {"set frobnicate 1\n", "s.txt:1: set: expected an option name (depth, depth-encoding,"},
        {"set overlay maybe\n", "s.txt:1: set overlay: expected on|off, got 'maybe'"},
        {"set scissor\n", "s.txt:1: expected 'set NAME VALUE', got 'set scissor'"},
        {"camera pos 0 0 5 target 0 0 0 up 0 1\n", "s.txt:1: expected 'camera pos X Y Z target X Y Z up X Y Z'"},
        {"camera pos 0 0 5 look 0 0 0 up 0 1 0\n", "s.txt:1: camera: expected 'target', got 'look'"},
        {"camera pos 0 0 nan target 0 0 0 up 0 1 0\n", "s.txt:1: camera pos: expected a finite number, got 'nan'"},
        {"camera pos 0 0 5 target 0 0 0 up 0 0 1\n", "s.txt:1: camera: expected target apart from pos and up not along"},
        {"screenshot\n", "s.txt:1: expected 'screenshot FILE [panel]', got 'screenshot'"},
        {"screenshot a.png panel now\n", "s.txt:1: expected 'screenshot FILE [panel]', got 'screenshot a.png panel now'"},
        {"screenshot a.png window\n", "s.txt:1: screenshot: expected 'panel' or nothing after FILE, got 'window'"},
        {"screenshot a.bmp\n", "s.txt:1: screenshot: expected a file ending .png, .exr, .tif, .jpg or .ppm, got 'a.bmp'"},
        {"quit now\n", "s.txt:1: expected 'quit', got 'quit now'"},
        {"wait 5\n", "s.txt:1: expected 'wait', got 'wait 5'"},
        {"frames 2\nwait\nframes 3\n", "s.txt:2: wait: expected as the script's last command, got 'frames' on line 3 after it"},
        {"wait\n# a comment\nwait\n", "s.txt:1: wait: expected as the script's last command, got 'wait' on line 3"},
    };
    for (auto [text, want] : cases) {
        const std::string got = parse_error(text);
        EXPECT_EQ(got.rfind(want, 0), 0u) << text << "\ngot: " << got;
        EXPECT_EQ(got.find('\n'), std::string::npos) << got;
    }
    try {
        load_script("/nonexistent/dsr.script");
        ADD_FAILURE() << "no error for a missing script";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "cannot open viewer script /nonexistent/dsr.script: No such file or directory");
    }
}

// Every value an entry lists comes back from get as it was set; a switch's `set` form is on|off.
TEST(OptionTable, EveryValueRoundTripsAndRenderDefaultsHold) {
    const RenderOptions defaults;
    EXPECT_EQ(find_render_option("depth")->get(defaults), "auto");
    EXPECT_EQ(find_render_option("scissor")->get(defaults), "on");
    EXPECT_EQ(find_render_option("no-skip")->get(defaults), "none");
    EXPECT_EQ(find_render_option("bloom-taps")->get(defaults), "7");
    EXPECT_EQ(find_render_option("view")->get(defaults), "final");
    for (const RenderOption& o : render_options()) {
        std::vector<std::string> values = o.values;
        if (o.kind == OptionKind::number) {  // three values inside the entry's range
            values.clear();
            for (const char* v : {"0", "0.5", "2"})
                if (std::atof(v) >= o.lo && std::atof(v) <= o.hi) values.push_back(v);
            EXPECT_GE(values.size(), 2u) << o.name;
        }
        if (o.kind == OptionKind::subset) values = {"none", o.values[0], o.values[1] + "," + o.values[2]};
        for (const std::string& v : values) {
            RenderOptions r;
            EXPECT_EQ(set_render_option(r, o, v), "") << o.name << " " << v;
            EXPECT_EQ(o.get(r), v) << o.name;
        }
        RenderOptions r;
        const std::string before = o.get(r);
        EXPECT_NE(set_render_option(r, o, "bogus"), "") << o.name;
        EXPECT_EQ(o.get(r), before) << o.name << ": a refused value changed it";
    }
    // Toggles resolve against the scene's post line until set.
    Scene s;
    s.post_bloom = true;
    RenderOptions r;
    EXPECT_TRUE(r.resolved(s).post.bloom);
    set_render_option(r, *find_render_option("bloom"), "off");
    EXPECT_FALSE(r.resolved(s).post.bloom);
    set_render_option(r, *find_render_option("view"), "bloom");
    EXPECT_TRUE(r.resolved(s).post.bloom) << "the bloom view needs the bloom pass";
    // The one-line helpers for plain fields.
    const RenderOption sw = switch_option("x", &ShaderOptions::gbuffer_half);
    RenderOption in = sw;  // an integer entry's checks (integer_option makes them for an int field)
    in.kind = OptionKind::integer, in.lo = 8, in.hi = 512, in.values.clear();
    EXPECT_EQ(check_render_option(in, "32"), "");
    EXPECT_EQ(check_render_option(in, "7"), "expected an integer in [8, 512], got '7'");
    EXPECT_EQ(check_render_option(in, "3.5"), "expected an integer in [8, 512], got '3.5'");
    in.values = {"auto"};  // integer_option(..., with_auto): the GL's default, stored as 0
    EXPECT_EQ(check_render_option(in, "auto"), "");
    EXPECT_EQ(check_render_option(in, "7"), "expected auto or an integer in [8, 512], got '7'");
    const RenderOption ts = *find_render_option("tile-size");
    RenderOptions t;
    EXPECT_EQ(ts.get(t), "auto");
    EXPECT_EQ(set_render_option(t, ts, "24"), "");
    EXPECT_EQ(t.shader.tile_size, 24);
    EXPECT_EQ(set_render_option(t, ts, "auto"), "");
    EXPECT_EQ(t.shader.tile_size, 0);
    RenderOptions q;
    EXPECT_EQ(set_render_option(q, sw, "on"), "");
    EXPECT_TRUE(q.shader.gbuffer_half);
    EXPECT_EQ(sw.get(q), "on");
    const std::vector<std::string> flags = render_option_flags();
    for (const char* f : {"--depth", "--bloom", "--no-bloom", "--aa", "--no-aa", "--no-skip", "--view", "--aa-weight"})
        EXPECT_NE(std::find(flags.begin(), flags.end(), f), flags.end()) << f;
}

// The fly camera starts exactly where the scene's camera is (so the viewer's first frame is the
// render's), and its moves and turns do what the keys say.
TEST(FlyCamera, StartsAtTheSceneCameraAndMovesAsTold) {
    Camera c;
    c.pos = {1, 2, 5};
    c.target = {0, 0.5f, -1};
    c.up = {0, 1, 0};
    FlyCamera f = FlyCamera::from(c);
    const glm::mat4 a = c.view(), b = f.apply(c).view();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-5f) << i << "," << j;
    const float d = glm::length(c.target - c.pos);
    EXPECT_NEAR(f.speed, 0.5f * d, 1e-5f);
    const glm::vec3 p0 = f.pos, fw = f.forward;
    f.move({0, 0, 1}, 2.0f, 1.0f);  // forward for 2 s
    EXPECT_NEAR(glm::length(f.pos - (p0 + fw * (2.0f * f.speed))), 0, 1e-5f);
    f.move({0, 1, 0}, 1.0f, 4.0f);  // up, shift
    EXPECT_NEAR(f.pos.y - (p0 + fw * (2.0f * f.speed)).y, 4.0f * f.speed, 1e-4f);
    // Yaw keeps the angle to up; a huge pitch stops 1 degree short of straight up.
    const float up_angle = std::acos(glm::dot(f.forward, f.world_up));
    f.look(0.7f, 0);
    EXPECT_NEAR(std::acos(glm::dot(f.forward, f.world_up)), up_angle, 1e-4f);
    f.look(0, 10.0f);
    EXPECT_NEAR(glm::degrees(std::acos(glm::dot(f.forward, f.world_up))), 1.0f, 1e-2f);
    EXPECT_NEAR(glm::length(f.forward), 1.0f, 1e-5f);
}

// Orbiting keeps the distance to the centre and looks at it; half a turn puts the camera on the
// other side (a model whose front faces -Z is seen from the front).
TEST(FlyCamera, OrbitCirclesTheCentre) {
    Camera c;
    c.pos = {0, 1, 5};
    c.target = {0, 1, 0};
    FlyCamera f = FlyCamera::from(c);
    f.orbit(c.target, 0.5f, 0.2f);
    EXPECT_NEAR(glm::length(f.pos - c.target), 5.0f, 1e-4f);
    EXPECT_NEAR(glm::length(glm::normalize(c.target - f.pos) - f.forward), 0.0f, 1e-5f);
    f = FlyCamera::from(c);
    f.orbit(c.target, glm::pi<float>(), 0);
    EXPECT_NEAR(f.pos.x, 0.0f, 1e-4f);
    EXPECT_NEAR(f.pos.z, -5.0f, 1e-4f);
}

// The overlay draws the rectangles the pass used: as many as lights drawn, their areas summing to
// the pass's scissor_pixels, on and off, for the default scene rendered under OSMesa.
TEST(ScissorOverlay, RectanglesAreThoseTheLightPassDrew) {
    Scene scene = test::default_scene();
    const int w = 96, h = 72;
    for (bool scissors : {true, false}) {
        auto ctx = create_context(ContextDesc{"osmesa", w, h});
        Caps caps = probe_caps();
        ShaderOptions opts;
        opts.scissor = scissors;
        DeferredShader ds(caps, w, h, opts, resource_dir("glsl120"));
        ds.set_scene(scene);
        const FrameStats st = ds.render(scene, w, h);
        const auto rects = light_scissor_rects(scene, scene.camera.view(), ds.proj_matrix(scene.camera), w, h, scissors, true);
        long long area = 0;
        for (const LightRect& r : rects) {
            area += r.rect.area();
            EXPECT_GE(r.rect.x0, 0);
            EXPECT_LE(r.rect.x1, w);
        }
        EXPECT_GT(st.lights.drawn, 0);
        EXPECT_EQ(int(rects.size()), st.lights.drawn) << "scissor " << scissors;
        EXPECT_EQ(area, st.lights.scissor_pixels) << "scissor " << scissors;
    }
}
