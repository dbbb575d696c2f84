// The forward stage after the lights (docs/forward.md): the depth hand-off (blit or gl_FragDepth pass),
// light markers (--show-lights) and transparent surfaces, on both depth paths, through the
// position path and without framebuffer objects (--caps no-fbo). The pure parts first: the
// back-to-front order, the marker's size against glm's projection, the path choice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "cli_fixture.h"
#include "deferred/light_marker.h"
#include "dsr_error.h"
#include "deferred/paths.h"
#include "deferred/transparent_order.h"
#include "forward_fixture.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

TEST(TransparentOrder, FarthestFirstTiesInSceneOrderAgainstBruteForce) {
    std::vector<ObjectBounds> b = {{{0, 0, -1}, 1}, {{0, 0, -5}, 1}, {{3, 0, 0}, 1}, {{0, 0, 3}, 1}, {{0, 4, 0}, 2},
                                   {{0, 0, 1}, 1}};
    const glm::dvec3 eye(0, 0, 2);
    // Distances: 3, 7, sqrt(13), 1, sqrt(20), 1.
    const std::vector<size_t> all = {0, 1, 2, 3, 4, 5};
    EXPECT_EQ(transparent_order(all, b, eye), (std::vector<size_t>{1, 4, 2, 0, 3, 5}));
    EXPECT_EQ(transparent_order({5, 3}, b, eye), (std::vector<size_t>{5, 3})) << "equal distances keep their order";
    EXPECT_TRUE(transparent_order({}, b, eye).empty());
    // Brute force on a grid of objects seen from a far, off-axis eye: every pair in order.
    std::vector<ObjectBounds> g;
    std::vector<size_t> idx;
    for (int i = 0; i < 64; ++i) {
        g.push_back({{float(i % 4) * 1.3f, float(i / 16) * 0.7f, -float((i / 4) % 4) * 2.1f}, 0.5f});
        idx.push_back(size_t(i));
    }
    const glm::dvec3 far_eye(1e4, -3e3, 2e4);
    const std::vector<size_t> o = transparent_order(idx, g, far_eye);
    ASSERT_EQ(o.size(), idx.size());
    for (size_t k = 1; k < o.size(); ++k)
        EXPECT_GE(glm::length(glm::dvec3(g[o[k - 1]].centre) - far_eye), glm::length(glm::dvec3(g[o[k]].centre) - far_eye));
}

TEST(LightMarker, RadiusProjectsToTheAskedShareOfTheViewport) {
    for (float fov : {30.0f, 60.0f, 90.0f})
        for (float d : {0.5f, 3.0f, 250.0f}) {
            const glm::mat4 p = glm::perspective(glm::radians(fov), 1.5f, 0.1f, 1000.0f);
            const float r = marker_radius(d, p[1][1], 0.01f);
            const glm::vec4 top = p * glm::vec4(0, r, -d, 1), centre = p * glm::vec4(0, 0, -d, 1);
            const float share = (top.y / top.w - centre.y / centre.w) / 2;  // NDC spans 2 viewport heights
            EXPECT_NEAR(share, 0.01f, 1e-5f) << fov << " deg, " << d;
        }
    EXPECT_EQ(marker_radius(0, 1.7f), 0.0f);
    EXPECT_EQ(marker_radius(-1, 1.7f), 0.0f);
}

TEST(PathsForward, TheForwardStageGetsTheSceneDepthByBlitOrPass) {
    Caps c;
    c.glsl120 = c.fbo = c.draw_buffers = c.depth_texture = true;
    c.max_draw_buffers = 4;
    ShaderOptions o;
    o.light_geometry = LightGeometry::quad;  // auto may draw volumes: it has the hand-off, run where it does
    EXPECT_FALSE(choose_paths(c, o).accum_depth) << "no forward stage, no hand-off";
    o.show_lights = true;
    Paths p = choose_paths(c, o);
    EXPECT_TRUE(p.forward_stage && p.accum_depth);
    EXPECT_EQ(p.depth_handoff, DepthHandoff::pass) << "no EXT_framebuffer_blit";
    c.framebuffer_blit = true;
    EXPECT_EQ(choose_paths(c, o).depth_handoff, DepthHandoff::blit);
    o.depth_handoff = DepthHandoff::pass;
    EXPECT_EQ(choose_paths(c, o).depth_handoff, DepthHandoff::pass);
    o.show_lights = false;
    o.forward_surfaces = true;
    o.depth_handoff = DepthHandoff::blit;
    p = choose_paths(c, o);
    EXPECT_TRUE(p.refused.empty()) << p.refused;
    EXPECT_EQ(p.depth_handoff, DepthHandoff::blit);
    EXPECT_TRUE(p.accum_depth);
    c.framebuffer_blit = false;
    EXPECT_NE(choose_paths(c, o).refused.find("--depth-handoff blit needs EXT_framebuffer_blit"), std::string::npos);
    c.framebuffer_blit = true;
    c.fbo = false;  // the copy path has no framebuffer objects to blit between
    EXPECT_NE(choose_paths(c, o).refused.find("the copy render target"), std::string::npos);
    o.depth_handoff = DepthHandoff::automatic;
    EXPECT_EQ(choose_paths(c, o).depth_handoff, DepthHandoff::pass);
    // The stencil geometry's DEPTH24_STENCIL8 cannot be blitted into from the G-buffer's depth.
    c.fbo = c.stencil = c.packed_depth_stencil = c.stencil_separate = true;
    o.light_geometry = LightGeometry::stencil;
    p = choose_paths(c, o);
    EXPECT_EQ(p.light_geometry, LightGeometry::stencil);
    EXPECT_EQ(p.depth_handoff, DepthHandoff::pass);
    o.depth_handoff = DepthHandoff::blit;
    EXPECT_NE(choose_paths(c, o).refused.find("differ in format"), std::string::npos);
    o.light_geometry = LightGeometry::volume;
    EXPECT_EQ(choose_paths(c, o).depth_handoff, DepthHandoff::blit);
}

namespace {
constexpr int kN = 192;

int lsb(const Image& im, int x, int y, int c) { return int(std::lround(im.rgba[size_t(4 * (y * im.width + x) + c)] * 255.0f)); }

// The window pixel of a world point (row 0 at the bottom, as read_pixels gives).
glm::ivec2 pixel_of(const Scene& s, glm::vec3 world) {
    const glm::vec4 c = s.camera.projection(1.0f) * s.camera.view() * glm::vec4(world, 1);
    return {int((c.x / c.w * 0.5f + 0.5f) * kN), int((c.y / c.w * 0.5f + 0.5f) * kN)};
}

Material matte(const std::string& name, glm::vec3 diffuse, float opacity = 1) {
    Material m;
    m.name = name;
    m.diffuse = diffuse;
    m.specular = glm::vec3(0);
    m.opacity = opacity;
    return m;
}

// A grey wall facing the camera, an opaque box in front of it to the right, one white light.
// Materials: 0 wall, 1 box, then whatever the test adds.
Scene wall_scene() {
    Scene s;
    s.camera.pos = {0, 0, 4};
    s.camera.target = {0, 0, 0};
    s.camera.near_plane = 0.1f;
    s.camera.far_plane = 30.0f;
    s.background = {0.1f, 0.1f, 0.3f};
    s.ambient = {0.2f, 0.2f, 0.2f};
    s.materials.push_back(matte("wall", {0.8f, 0.8f, 0.8f}));
    s.materials.push_back(matte("box", {0.9f, 0.6f, 0.2f}));
    add_box(s, {8, 8, 0.2f}, {0, 0, -1.1f}, 0);
    add_box(s, {0.5f, 0.5f, 0.5f}, {0.55f, 0.45f, 1.3f}, 1);
    s.lights.push_back({{0.3f, 0.4f, 2.0f}, {1, 1, 1}, 8.0f});
    return s;
}

// Adds a thin pane (box) of `material` centred at `at`; returns the scene.
Scene with_pane(Scene s, int material, glm::vec3 at, glm::vec2 size) {
    add_box(s, {size.x, size.y, 0.02f}, at, material);
    return s;
}

struct Case {
    const char* name;
    DepthPath depth;
    DepthHandoff handoff;
    std::vector<std::string> caps;
    DepthHandoff expect;  // as run
};

ShaderOptions options_of(const Case& c) {
    ShaderOptions o;
    o.depth = c.depth;
    o.depth_handoff = c.handoff;
    return o;
}

class Forward : public ::testing::TestWithParam<Case> {};

// Pixels that differ between two images, grown by one pixel (the edges of what differs).
std::vector<char> differs_grown(const Image& a, const Image& b) {
    std::vector<char> m(size_t(kN * kN), 0);
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x)
            for (int c = 0; c < 3; ++c)
                if (lsb(a, x, y, c) != lsb(b, x, y, c)) m[size_t(y * kN + x)] = 1;
    std::vector<char> g = m;
    for (int y = 1; y < kN - 1; ++y)
        for (int x = 1; x < kN - 1; ++x)
            if (m[size_t(y * kN + x)])
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) g[size_t((y + dy) * kN + x + dx)] = 1;
    return g;
}
}  // namespace

// A transparent pane over the lit wall is the blend its opacity says, of the wall alone and the
// pane's own colour (the pane drawn opaque, through the G-buffer: another code path); everywhere
// else the image is exactly the wall's, including where the opaque box in front hides the pane.
TEST_P(Forward, TransparentPaneBlendsAsItsOpacitySaysAndOpaqueSurfacesHideIt) {
    const Case& c = GetParam();
    const float a = 0.4f;
    Scene base = wall_scene();
    base.materials.push_back(matte("pane_opaque", {0.2f, 0.5f, 0.9f}));
    base.materials.push_back(matte("pane_glass", {0.2f, 0.5f, 0.9f}, a));
    const glm::vec3 at(0.2f, 0.2f, 0.6f);
    const Scene opaque = with_pane(base, 2, at, {1.6f, 1.4f}), glass = with_pane(base, 3, at, {1.6f, 1.4f});
    const ShaderOptions o = options_of(c);
    const RenderResult w = render_scene(base, kN, kN, o, c.caps);
    const RenderResult q = render_scene(opaque, kN, kN, o, c.caps);
    const RenderResult t = render_scene(glass, kN, kN, o, c.caps);
    EXPECT_FALSE(w.paths.forward_stage);
    EXPECT_FALSE(q.paths.forward_stage) << "an opaque pane needs no forward stage";
    ASSERT_TRUE(t.paths.forward_stage);
    EXPECT_EQ(t.paths.depth_handoff, c.expect);
    EXPECT_EQ(t.stats.forward.transparent_objects, 1);
    EXPECT_GT(t.stats.ms.forward, 0.0);
    const std::vector<char> pane = differs_grown(q.image, w.image);
    long long inside = 0, outside_off = 0, blend_off = 0;
    int worst = 0;
    for (int y = 1; y < kN - 1; ++y)
        for (int x = 1; x < kN - 1; ++x) {
            if (!pane[size_t(y * kN + x)]) {
                for (int ch = 0; ch < 3; ++ch) outside_off += lsb(t.image, x, y, ch) != lsb(w.image, x, y, ch);
                continue;
            }
            bool interior = true;  // the pane's edges may be rasterised a pixel apart by the two paths
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) interior = interior && pane[size_t((y + dy) * kN + x + dx)];
            if (!interior) continue;
            ++inside;
            for (int ch = 0; ch < 3; ++ch) {
                const double want = a * lsb(q.image, x, y, ch) + (1 - a) * lsb(w.image, x, y, ch);
                const int off = int(std::lround(std::fabs(lsb(t.image, x, y, ch) - want)));
                worst = std::max(worst, off);
                blend_off += off > 2;
            }
        }
    EXPECT_GT(inside, 1500) << "the pane covers too little to judge";
    EXPECT_EQ(outside_off, 0) << "channels changed outside the pane";
    EXPECT_EQ(blend_off, 0) << "channels off the blend by more than 2 LSB (worst " << worst << ")";
    // The box hides the pane's lower right corner: its centre is the box's colour, untouched.
    const glm::ivec2 box = pixel_of(base, {0.55f, 0.45f, 1.55f});
    for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(lsb(t.image, box.x, box.y, ch), lsb(w.image, box.x, box.y, ch));
    if (::testing::Test::HasFailure()) write_failure_images(std::string("forward_pane_") + c.name, t.image, w.image);
}

// Two overlapping panes listed near-first: drawn back to front, the overlap is the far pane
// blended over the wall, then the near one over that.
TEST_P(Forward, OverlappingPanesBlendBackToFront) {
    const Case& c = GetParam();
    const float a_far = 0.6f, a_near = 0.35f;
    Scene base = wall_scene();
    base.materials.push_back(matte("far_opaque", {0.9f, 0.2f, 0.1f}));
    base.materials.push_back(matte("near_opaque", {0.1f, 0.8f, 0.3f}));
    base.materials.push_back(matte("far_glass", {0.9f, 0.2f, 0.1f}, a_far));
    base.materials.push_back(matte("near_glass", {0.1f, 0.8f, 0.3f}, a_near));
    const glm::vec3 far_at(-0.4f, 0.0f, -0.2f), near_at(-0.1f, -0.2f, 0.9f);
    const Scene far_only = with_pane(base, 2, far_at, {1.4f, 1.4f});
    const Scene near_only = with_pane(base, 3, near_at, {1.0f, 1.0f});
    const Scene both = with_pane(with_pane(base, 5, near_at, {1.0f, 1.0f}), 4, far_at, {1.4f, 1.4f});
    const ShaderOptions o = options_of(c);
    const RenderResult w = render_scene(base, kN, kN, o, c.caps);
    const RenderResult f = render_scene(far_only, kN, kN, o, c.caps);
    const RenderResult n = render_scene(near_only, kN, kN, o, c.caps);
    const RenderResult t = render_scene(both, kN, kN, o, c.caps);
    EXPECT_EQ(t.stats.forward.transparent_objects, 2);
    // A point inside both panes' interiors: the near pane's centre lies over the far pane.
    const glm::ivec2 p = pixel_of(base, near_at);
    for (int ch = 0; ch < 3; ++ch) {
        const double under = a_far * lsb(f.image, p.x, p.y, ch) + (1 - a_far) * lsb(w.image, p.x, p.y, ch);
        const double want = a_near * lsb(n.image, p.x, p.y, ch) + (1 - a_near) * under;
        const double wrong = a_far * lsb(f.image, p.x, p.y, ch) +
                             (1 - a_far) * (a_near * lsb(n.image, p.x, p.y, ch) + (1 - a_near) * lsb(w.image, p.x, p.y, ch));
        EXPECT_NEAR(lsb(t.image, p.x, p.y, ch), want, 2.5) << "channel " << ch << " (front to back would give " << wrong << ")";
    }
}

// Markers: the one in front of the wall shows the light's colour at the light's pixel; the one
// behind the opaque box is hidden by it; nothing else changes but a few pixels around the first.
TEST_P(Forward, LightMarkersShowInFrontOfSurfacesAndHideBehindThem) {
    const Case& c = GetParam();
    Scene s = wall_scene();
    s.lights.clear();
    const glm::vec3 shown(-1.2f, 0.6f, 0.5f);
    // On the ray from the eye through the box's centre, behind the box.
    const glm::vec3 box(0.55f, 0.45f, 1.3f), eye = s.camera.pos;
    const glm::vec3 hidden = eye + 1.6f * (box - eye);
    s.lights.push_back({shown, {1.0f, 0.25f, 0.1f}, 3.0f});
    s.lights.push_back({hidden, {0.1f, 1.0f, 0.25f}, 3.0f});
    ShaderOptions off = options_of(c), on = off;
    on.show_lights = true;
    const RenderResult a = render_scene(s, kN, kN, off, c.caps);
    const RenderResult b = render_scene(s, kN, kN, on, c.caps);
    EXPECT_TRUE(b.paths.forward_stage);
    EXPECT_EQ(b.stats.forward.light_markers, 2);
    const glm::ivec2 ps = pixel_of(s, shown), ph = pixel_of(s, hidden);
    const int want[3] = {255, 64, 26};  // the light's colour, 8-bit
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(lsb(b.image, ps.x, ps.y, ch), want[ch], 1) << "shown marker, channel " << ch;
        EXPECT_EQ(lsb(b.image, ph.x, ph.y, ch), lsb(a.image, ph.x, ph.y, ch)) << "hidden marker, channel " << ch;
    }
    long long changed = 0;
    int far_changes = 0;
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x) {
            bool d = false;
            for (int ch = 0; ch < 3; ++ch) d = d || lsb(a.image, x, y, ch) != lsb(b.image, x, y, ch);
            changed += d;
            if (d && std::hypot(x - ps.x, y - ps.y) > 4) ++far_changes;
        }
    EXPECT_GT(changed, 4);
    EXPECT_EQ(far_changes, 0) << "pixels changed away from the visible marker";
    if (::testing::Test::HasFailure()) write_failure_images(std::string("forward_markers_") + c.name, b.image, a.image);
}

// `markers box H`: a world-sized cube in the light's colour. At the light's pixel the colour, and
// the changed pixels a square about as wide as the cube's projection (not the sphere's 4 pixels).
TEST_P(Forward, BoxMarkersAreCubesOfTheirWorldSize) {
    const Case& c = GetParam();
    Scene s = wall_scene();
    s.lights.clear();
    const glm::vec3 shown(-1.2f, 0.6f, 0.5f);
    s.lights.push_back({shown, {1.0f, 0.25f, 0.1f}, 3.0f});
    s.marker_shape = Scene::MarkerShape::box;
    s.marker_size = 0.1f;
    ShaderOptions off = options_of(c), on = off;
    on.show_lights = true;
    const RenderResult a = render_scene(s, kN, kN, off, c.caps);
    const RenderResult b = render_scene(s, kN, kN, on, c.caps);
    EXPECT_EQ(b.stats.forward.light_markers, 1);
    const glm::ivec2 ps = pixel_of(s, shown);
    const int want[3] = {255, 64, 26};
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(lsb(b.image, ps.x, ps.y, ch), want[ch], 1) << "channel " << ch;
    // The cube's half-width on screen at its distance (corners and perspective add up to ~1.7x).
    const float half_px = 0.1f / glm::length(shown - s.camera.pos) *
                          (kN / 2.0f) / std::tan(glm::radians(s.camera.fov_deg) / 2.0f);
    int x0 = kN, x1 = -1;
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x) {
            bool d = false;
            for (int ch = 0; ch < 3; ++ch) d = d || lsb(a.image, x, y, ch) != lsb(b.image, x, y, ch);
            if (d) x0 = std::min(x0, x), x1 = std::max(x1, x);
        }
    const float width = float(x1 - x0 + 1);
    EXPECT_GT(width, 1.8f * half_px) << "cube " << width << " px wide, its face " << 2 * half_px;
    EXPECT_LT(width, 3.6f * half_px + 2) << "cube " << width << " px wide, its face " << 2 * half_px;
    if (::testing::Test::HasFailure()) write_failure_images(std::string("forward_box_markers_") + c.name, b.image, a.image);
}

// With nothing to draw, the forward stage and its depth hand-off change no pixel: opacity 1 is the
// opaque path, and a frame that runs the stage (a directional light has no marker) is the same.
TEST_P(Forward, NothingToDrawChangesNothing) {
    const Case& c = GetParam();
    Scene s = wall_scene();
    s.lights.push_back(Light{});
    s.lights.back().type = Light::Type::directional;
    s.lights.back().dir = glm::normalize(glm::vec3(0.3f, -0.5f, -1));
    s.lights.back().color = {0.3f, 0.3f, 0.3f};
    ShaderOptions off = options_of(c), on = off;
    on.forward_surfaces = true;
    const RenderResult a = render_scene(s, kN, kN, off, c.caps);
    const RenderResult b = render_scene(s, kN, kN, on, c.caps);
    EXPECT_TRUE(b.paths.accum_depth);
    EXPECT_EQ(a.image.rgba, b.image.rgba) << "the forward stage with nothing to draw changed the image";
}

INSTANTIATE_TEST_SUITE_P(
    Paths, Forward,
    ::testing::Values(Case{"texture_blit", DepthPath::texture, DepthHandoff::automatic, {}, DepthHandoff::blit},
                      Case{"texture_pass", DepthPath::texture, DepthHandoff::pass, {}, DepthHandoff::pass},
                      Case{"packed_blit", DepthPath::packed, DepthHandoff::blit, {}, DepthHandoff::blit},
                      Case{"packed_pass", DepthPath::packed, DepthHandoff::pass, {}, DepthHandoff::pass},
                      Case{"position32_pass", DepthPath::position32, DepthHandoff::pass, {}, DepthHandoff::pass},
                      Case{"no_fbo", DepthPath::texture, DepthHandoff::automatic, {"no-fbo"}, DepthHandoff::pass},
                      Case{"no_fbo_packed", DepthPath::packed, DepthHandoff::automatic, {"no-fbo"}, DepthHandoff::pass}),
    [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

// The forward stage behind every light geometry: the same pane over the same lights as with quad,
// within the 1 LSB the geometries keep between themselves; stencil's depth-stencil buffer gets
// the pass, the others the blit.
TEST(ForwardScene, EveryLightGeometryHandsOffAndBlendsTheSame) {
    Scene s = wall_scene();
    s.materials.push_back(matte("glass", {0.2f, 0.5f, 0.9f}, 0.4f));
    s = with_pane(s, 2, {0.2f, 0.2f, 0.6f}, {1.6f, 1.4f});
    ShaderOptions o;
    o.show_lights = true;
    const RenderResult q = render_scene(s, kN, kN, o);
    for (LightGeometry g : {LightGeometry::volume, LightGeometry::stencil, LightGeometry::tiles}) {
        ShaderOptions og = o;
        og.light_geometry = g;
        const RenderResult r = render_scene(s, kN, kN, og);
        EXPECT_EQ(r.paths.light_geometry, g);
        EXPECT_EQ(r.paths.depth_handoff, g == LightGeometry::stencil ? DepthHandoff::pass : DepthHandoff::blit);
        EXPECT_EQ(r.stats.forward.transparent_objects, 1);
        const ImageDiff d = compare_logged(std::string("forward_behind_") + light_geometry_name(g), r.image, q.image, 1.0 / 255);
        EXPECT_LE(d.max_lsb(), 1.0) << light_geometry_name(g);
    }
}

// Opacity 1 in a scene file is the opaque path: the same image as no opacity at all.
TEST(ForwardScene, OpacityOneIsTheOpaquePathAndBadOpacityIsOneError) {
    const std::string head =
        "camera pos 0 0 4 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 30\nmaterial m diffuse 0.5 0.6 0.7 specular 0.2 0.2 0.2 shininess 16";
    const std::string tail = "\nbox size 1 1 1 at 0 0 0 material m\nlight point pos 1 1 2 color 1 1 1 radius 6\n";
    const Scene plain = parse_scene("plain.scene", head + tail), one = parse_scene("one.scene", head + " opacity 1" + tail);
    const Scene half = parse_scene("half.scene", head + " opacity 0.5" + tail);
    EXPECT_FALSE(one.materials[0].transparent());
    EXPECT_TRUE(half.materials[0].transparent());
    const RenderResult a = render_scene(plain, 96, 96, ShaderOptions{});
    const RenderResult b = render_scene(one, 96, 96, ShaderOptions{});
    EXPECT_EQ(a.image.rgba, b.image.rgba);
    EXPECT_FALSE(b.paths.forward_stage);
    for (const char* bad : {" opacity 0", " opacity 1.5", " opacity -0.2", " opacity x", " opacity"}) {
        try {
            parse_scene("bad.scene", head + bad + tail);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("bad.scene:2:"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("opacity"), std::string::npos) << e.what();
        }
    }
}

// The forward reference renderers draw transparent objects the same way (the same pass after
// their opaque surfaces): within a few LSB of the deferred image, whose opaque part they already
// match that closely.
TEST(ForwardScene, ForwardRenderersBlendTheSamePane) {
    Scene s = wall_scene();
    s.materials.push_back(matte("glass", {0.2f, 0.5f, 0.9f}, 0.4f));
    s = with_pane(s, 2, {0.2f, 0.2f, 0.6f}, {1.6f, 1.4f});
    const RenderResult d = render_scene(s, kN, kN, ShaderOptions{});
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
        const ForwardResult f = render_forward(s, kN, kN, forward_mode(m));
        const ImageDiff diff = compare_logged(m == ForwardMode::single ? "forward_single_pane" : "forward_multi_pane",
                                              d.image, f.image, 3.0 / 255);
        EXPECT_LE(diff.max_lsb(), 3.0);
        const glm::ivec2 p = pixel_of(s, {0.2f, 0.2f, 0.6f});
        EXPECT_NEAR(lsb(f.image, p.x, p.y, 2), lsb(d.image, p.x, p.y, 2), 2);
    }
}

TEST(ForwardCli, HandoffAndMarkersFromTheCommandLine) {
    const std::string dir = test_output_dir();
    RunResult r = run("render --size 64x64 --show-lights --depth-handoff blit --caps no-framebuffer-blit -o " + dir +
                      "/fwd_bad.png");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--depth-handoff blit needs EXT_framebuffer_blit"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    r = run("render --size 64x64 --depth-handoff sideways -o " + dir + "/fwd_bad.png");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--depth-handoff: expected auto|blit|pass, got 'sideways'"), std::string::npos) << r.output;
    const std::string stats = dir + "/fwd_stats.json";
    r = run("render " + resource_dir("data") + "/transparency.scene --size 96x96 --show-lights --depth-handoff pass --stats " + stats + " -o " +
            dir + "/fwd_ok.png");
    ASSERT_EQ(r.status, 0) << r.output;
    FILE* f = std::fopen(stats.c_str(), "r");
    ASSERT_NE(f, nullptr);
    std::string text(1 << 16, '\0');
    text.resize(std::fread(&text[0], 1, text.size(), f));
    std::fclose(f);
    EXPECT_NE(text.find("\"depth_handoff\": \"pass\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"transparent_objects\": 3"), std::string::npos);
    EXPECT_NE(text.find("\"light_markers\": 4"), std::string::npos);
    EXPECT_NE(text.find("\"forward\":"), std::string::npos);
}
