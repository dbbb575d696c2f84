// What models from real files bring (scene.h): two-sided objects, per-vertex colours, cut-out
// materials and texture sampling, through every light geometry, both depth paths, a stored-position
// path, the no-MRT fallback, the shadow maps and the forward references. Each is checked pixel by
// pixel against the same scene drawn another way that needs none of the feature: a plane turned
// around, a material of the vertices' colour, the scene without the cut part or with it solid.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "deferred/gpu_scene.h"
#include "deferred/render_targets.h"
#include "forward_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {

constexpr int kSize = 64;
constexpr double kLsb = 1.0 / 255.0;
const LightGeometry kGeometries[] = {LightGeometry::quad,  LightGeometry::volume, LightGeometry::stencil,
                                     LightGeometry::tiles, LightGeometry::screen, LightGeometry::automatic};

// One configuration of the deferred renderer: options and the capabilities forced off (--caps).
struct Config {
    std::string name;
    ShaderOptions opts;
    std::vector<std::string> off;
};

Config config(const std::string& name, DepthPath d, LightGeometry g, std::vector<std::string> off = {}) {
    ShaderOptions o;
    o.depth = d;
    o.light_geometry = g;
    return {name, o, std::move(off)};
}

// Every light geometry on both depth paths, a stored-position path, and the no-MRT fallback (one
// pass per G-buffer target) on both depth paths.
std::vector<Config> every_path() {
    std::vector<Config> c;
    for (DepthPath d : {DepthPath::texture, DepthPath::packed})
        for (LightGeometry g : kGeometries)
            c.push_back(config(std::string(depth_path_name(d)) + "/" + light_geometry_name(g), d, g));
    c.push_back(config("position16/quad", DepthPath::position16, LightGeometry::quad));
    c.push_back(config("no-mrt/texture", DepthPath::texture, LightGeometry::quad, {"no-mrt"}));
    c.push_back(config("no-mrt/packed", DepthPath::packed, LightGeometry::automatic, {"no-mrt"}));
    return c;
}

struct Rendered {
    Image image, diffuse;  // the output, the G-buffer's diffuse target
};

// Each scene through one DeferredShader (programs compiled once), read back after its frame.
std::vector<Rendered> render_deferred(const std::vector<Scene>& scenes, const Config& c, int size = kSize) {
    auto ctx = create_context(ContextDesc{"osmesa", size, size});
    const Caps caps = probe_caps(c.off);
    DeferredShader ds(caps, size, size, c.opts, resource_dir("glsl120"));
    std::vector<Rendered> out;
    for (const Scene& s : scenes) {
        ds.set_scene(s);
        ds.render(s, size, size);
        Rendered f;
        f.image = read_pixels(size, size);
        f.diffuse = ds.read_gbuffer(G_DIFFUSE);
        out.push_back(std::move(f));
    }
    return out;
}

std::vector<Image> render_forward_all(const std::vector<Scene>& scenes, const ForwardOptions& o,
                                      const std::vector<std::string>& off = {}) {
    std::vector<Image> out;
    for (const Scene& s : scenes) out.push_back(render_forward(s, kSize, kSize, o, false, off).image);
    return out;
}

// The largest difference over pixels where `mask` (x, y) holds, in 8-bit steps, and how many.
struct MaskedDiff {
    double max_lsb = 0;
    int pixels = 0;
};
MaskedDiff masked_diff(const Image& a, const Image& b, const std::function<bool(int, int)>& mask) {
    MaskedDiff d;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!mask(x, y)) continue;
            ++d.pixels;
            for (int c = 0; c < 3; ++c)
                d.max_lsb = std::max(d.max_lsb, std::fabs(double(a.at(x, y)[c]) - double(b.at(x, y)[c])) * 255.0);
        }
    return d;
}

// Where pixel (x, y)'s ray from the scene's camera meets the plane y = h (a square image).
glm::vec3 ray_hits(const Scene& s, int x, int y, float h, int size = kSize) {
    const glm::mat4 view = s.camera.view(), proj = s.camera.projection(1.0f);
    const glm::vec4 vp(0, 0, size, size);
    const glm::vec3 a = glm::unProject(glm::vec3(x + 0.5f, y + 0.5f, 0.0f), view, proj, vp);
    const glm::vec3 b = glm::unProject(glm::vec3(x + 0.5f, y + 0.5f, 1.0f), view, proj, vp);
    const float t = (h - a.y) / (b.y - a.y);
    return a + t * (b - a);
}

// The pixel world point p shows (a square image).
glm::ivec2 pixel_of(const Scene& s, glm::vec3 p, int size = kSize) {
    const glm::vec4 c = s.camera.projection(1.0f) * s.camera.view() * glm::vec4(p, 1);
    return {int((c.x / c.w * 0.5f + 0.5f) * float(size)), int((c.y / c.w * 0.5f + 0.5f) * float(size))};
}

Material material(const std::string& name, glm::vec3 diffuse, glm::vec3 specular = glm::vec3(0.3f)) {
    Material m;
    m.name = name;
    m.diffuse = diffuse;
    m.specular = specular;
    m.shininess = 20;
    return m;
}

Image solid_texture(int w, int h, const std::function<glm::vec4(int, int)>& texel) {
    Image t;
    t.width = w, t.height = h;
    t.rgba.resize(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec4 v = texel(x, y);
            for (int c = 0; c < 4; ++c) t.at(x, y)[c] = v[c];
        }
    return t;
}

// ---- two-sided ---------------------------------------------------------------------------------

// The plane turned around: the same triangles wound the other way, its tangent frame negated, so
// its front is the original's back with the normal (and a normal map's) flipped.
Mesh turned_around(Mesh m) {
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) std::swap(m.indices[i + 1], m.indices[i + 2]);
    for (Vertex& v : m.vertices) v.normal = -v.normal, v.tangent = -v.tangent, v.binormal = -v.binormal;
    return m;
}

// Three planes facing up (+Y) seen from below, lit from below: left one-sided, middle two-sided,
// right two-sided with a normal map whose normals lean every way. `reference`: the left plane left
// out, the other two turned around and one-sided: what the two-sided planes must show.
Scene planes_from_below(bool reference) {
    Scene s;
    s.camera.pos = {0, -4, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.1f);
    s.background = {0.25f, 0.5f, 0.75f};
    s.materials = {material("grey", glm::vec3(0.7f)), material("bumpy", glm::vec3(0.6f, 0.7f, 0.5f))};
    s.textures.push_back(solid_texture(4, 4, [](int x, int y) {
        const glm::vec3 n = glm::normalize(glm::vec3(0.5f * float(x - 1.5f), 0.4f * float(1.5f - y), 1.0f));
        return glm::vec4(n * 0.5f + 0.5f, 1.0f);
    }));
    s.texture_paths.push_back("bumps");
    s.materials[1].normal_map = 0;
    const float xs[3] = {-1.6f, 0, 1.6f};
    const int mats[3] = {0, 0, 1};
    for (int i = 0; i < 3; ++i) {
        if (reference && i == 0) continue;
        Mesh m = make_plane(1.4f, mats[i]);
        if (reference && i > 0) m = turned_around(m);
        const size_t o = s.add(m, glm::translate(glm::dmat4(1), glm::dvec3(xs[i], 0, 0)));
        s.objects[o].material = mats[i];
        s.objects[o].two_sided = !reference && i > 0;
    }
    s.lights.push_back({{0, -1.5f, 0.3f}, {1, 1, 1}, 6.0f});
    return s;
}

// The planes' pixels must differ from the background where lit (so the comparisons say something).
void expect_lit(const Scene& s, const Image& reference, const std::string& label) {
    for (float x : {0.0f, 1.6f}) {
        const glm::ivec2 p = pixel_of(s, {x, 0, 0});
        float d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::fabs(reference.at(p.x, p.y)[c] - s.background[c]) * 255);
        EXPECT_GT(d, 20) << label << " at x " << x;
    }
}

}  // namespace

// A one-sided plane seen from behind is background; a two-sided one is lit as the same plane turned
// around (its normal, the normal map's included, flipped to face the camera), in every light
// geometry, both depth paths, a stored-position path and without MRT.
TEST(ModelSurfaces, TwoSidedPlanesOnEveryPath) {
    const Scene two = planes_from_below(false), ref = planes_from_below(true);
    const std::vector<Config> configs = every_path();
    for (size_t i = 0; i < configs.size(); ++i) {
        const Config& c = configs[i];
        const std::vector<Rendered> f = render_deferred({two, ref}, c);
        expect_lit(ref, f[1].image, c.name);
        const ImageDiff d = compare_logged("two-sided vs turned around, " + c.name, f[0].image, f[1].image, kLsb);
        if (d.max_lsb() > 1) write_failure_images("two_sided_" + std::to_string(i), f[0].image, f[1].image);
        EXPECT_LE(d.max_lsb(), 1.0) << c.name;
    }
}

// The forward references draw them the same way, and agree with the deferred image.
TEST(ModelSurfaces, TwoSidedPlanesInTheForwardReferences) {
    const Scene two = planes_from_below(false), ref = planes_from_below(true);
    const Image deferred = render_deferred({two}, config("texture/quad", DepthPath::texture, LightGeometry::quad))[0].image;
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
        const std::vector<Image> f = render_forward_all({two, ref}, forward_mode(m));
        expect_lit(ref, f[1], "forward");
        const ImageDiff d = compare_logged("forward: two-sided vs turned around", f[0], f[1], kLsb);
        EXPECT_LE(d.max_lsb(), 1.0) << int(m);
        // The deferred image's 8-bit G-buffer against the forward float math (Forward.MatchesDeferredOnDefaultScene).
        const ImageDiff fd = compare_logged("forward vs deferred, two-sided planes", f[0], deferred, 2 * kLsb);
        EXPECT_LE(fd.max_lsb(), 4.0) << int(m);
        EXPECT_LE(fd.failing_fraction(), 0.01) << int(m);
    }
}

namespace {

// ---- vertex colours ----------------------------------------------------------------------------

// Two planes seen from above under a white light: with `colors`, white-ish materials times
// per-vertex colours; without, materials of the product's colour. One more plane without colours
// beside them, the same in both, and a transparent one of each kind.
Scene coloured_planes(bool colors) {
    Scene s;
    s.camera.pos = {0, 5, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.15f);
    s.background = {0.1f, 0.1f, 0.1f};
    const glm::vec4 vc[3] = {{1, 0, 0, 1}, {0.2f, 0.6f, 1.0f, 1}, {0, 1, 0, 1}};
    const glm::vec3 base[3] = {glm::vec3(1), glm::vec3(0.5f), glm::vec3(0.8f)};
    const glm::vec3 at[4] = {{-1.3f, 0, -1.3f}, {1.3f, 0, -1.3f}, {-1.3f, 0, 1.3f}, {1.3f, 0, 1.3f}};
    for (int i = 0; i < 3; ++i) {
        s.materials.push_back(material("m" + std::to_string(i), colors ? base[i] : base[i] * glm::vec3(vc[i])));
        if (i == 2) s.materials.back().opacity = 0.6f;  // the transparent pass
        Mesh m = make_plane(2.2f, i);
        if (colors) m.colors.assign(m.vertices.size(), vc[i]);
        s.add(m, glm::translate(glm::dmat4(1), glm::dvec3(at[i])));
    }
    s.materials.push_back(material("plain", glm::vec3(0.9f, 0.8f, 0.7f)));
    s.add(make_plane(2.2f, 3), glm::translate(glm::dmat4(1), glm::dvec3(at[3])));
    s.lights.push_back({{0, 2, 0}, {1, 1, 1}, 8.0f});
    return s;
}

}  // namespace

// A red-vertex plane under white light is the red-material plane, within 1 LSB, on both depth
// paths and without MRT, through the transparent pass and in the forward references.
TEST(ModelSurfaces, VertexColoursMultiplyDiffuse) {
    const Scene col = coloured_planes(true), mat = coloured_planes(false);
    std::vector<Config> configs = {config("texture", DepthPath::texture, LightGeometry::automatic),
                                   config("packed", DepthPath::packed, LightGeometry::quad),
                                   config("no-mrt", DepthPath::texture, LightGeometry::quad, {"no-mrt"})};
    for (const Config& c : configs) {
        const std::vector<Rendered> f = render_deferred({col, mat}, c);
        const glm::ivec2 red = pixel_of(col, {-1.3f, 0, -1.3f});
        EXPECT_GT(f[1].image.at(red.x, red.y)[0] * 255, 100) << c.name;
        EXPECT_LT(f[0].image.at(red.x, red.y)[1] * 255, f[0].image.at(red.x, red.y)[0] * 255 - 60) << c.name;
        const ImageDiff d = compare_logged("vertex colours vs material colours, " + c.name, f[0].image, f[1].image, kLsb);
        EXPECT_LE(d.max_lsb(), 1.0) << c.name;
        const ImageDiff g = compare_images(f[0].diffuse, f[1].diffuse, kLsb);
        EXPECT_LE(g.max_lsb(), 1.0) << c.name << ": the diffuse target";
    }
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
        const std::vector<Image> f = render_forward_all({col, mat}, forward_mode(m));
        const ImageDiff d = compare_logged("forward: vertex colours vs material colours", f[0], f[1], kLsb);
        EXPECT_LE(d.max_lsb(), 1.0) << int(m);
    }
}

namespace {

// ---- cut-outs ----------------------------------------------------------------------------------

// The cut-out map: left half (u < 0.5) coverage 0, right half 1, white.
Image half_cut_texture() {
    return solid_texture(64, 64, [](int x, int) { return glm::vec4(1, 1, 1, x < 32 ? 0.0f : 1.0f); });
}

enum class Front { cut_out, none, solid };

// A back plane (y = 0) and in front of it, seen from above, a plane (y = 1) with the cut-out map:
// `none` leaves it out, `solid` draws it without the cut-out (its map's alpha ignored).
Scene cut_scene(Front front) {
    Scene s;
    s.camera.pos = {0, 5, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.1f);
    s.background = {0.3f, 0.3f, 0.3f};
    s.materials = {material("back", {0.2f, 0.3f, 0.9f}), material("leaf", {0.9f, 0.7f, 0.2f})};
    s.textures.push_back(half_cut_texture());
    s.texture_paths.push_back("cut");
    s.materials[1].diffuse_map = 0;
    s.materials[1].alpha_cutoff = front == Front::cut_out ? 0.5f : 0.0f;
    add_plane(s, 4, {0, 0, 0}, 0);
    if (front != Front::none) add_plane(s, 2.4f, {0, 1, 0}, 1);
    s.lights.push_back({{0.3f, 3, 0.2f}, {1, 1, 1}, 8.0f});
    return s;
}

// Pixels whose ray meets the front plane's left (cut) or right (kept) half, a margin from the cut
// and the plane's edges (the map's filtering there).
bool on_half(const Scene& s, int x, int y, bool left) {
    const glm::vec3 p = ray_hits(s, x, y, 1.0f);
    const float m = 0.15f, h = 1.2f - m;
    if (std::fabs(p.z) > h || std::fabs(p.x) > h) return false;
    return left ? p.x < -m : p.x > m;
}

// Left half: the scene without the front plane; right half: with it solid; elsewhere either.
void expect_cut(const Scene& s, const Image& cut, const Image& none, const Image& solid, const std::string& label,
                double tol = 1.0) {
    const MaskedDiff l = masked_diff(cut, none, [&](int x, int y) { return on_half(s, x, y, true); });
    const MaskedDiff r = masked_diff(cut, solid, [&](int x, int y) { return on_half(s, x, y, false); });
    const MaskedDiff out = masked_diff(cut, none, [&](int x, int y) {
        const glm::vec3 p = ray_hits(s, x, y, 1.0f);
        return std::fabs(p.x) > 1.35f || std::fabs(p.z) > 1.35f;
    });
    std::printf("[ cut-out  ] %s: cut half vs no plane max %.1f LSB (%d px), kept half vs solid max %.1f LSB (%d px)\n",
                label.c_str(), l.max_lsb, l.pixels, r.max_lsb, r.pixels);
    EXPECT_GT(l.pixels, 200) << label;
    EXPECT_GT(r.pixels, 200) << label;
    EXPECT_LE(l.max_lsb, tol) << label << ": the cut half shows what lies behind";
    EXPECT_LE(r.max_lsb, tol) << label << ": the kept half is the solid plane";
    EXPECT_LE(out.max_lsb, tol) << label << ": around the plane";
    // The two expectations differ on the cut half, so the check says something.
    EXPECT_GT(masked_diff(none, solid, [&](int x, int y) { return on_half(s, x, y, true); }).max_lsb, 20) << label;
}

}  // namespace

// A cut-out plane in front of another shows the back plane through its cut half, in the G-buffer and
// the lit image, on every path (the depth pre-pass must not lay its depth down there).
TEST(ModelSurfaces, CutOutShowsWhatLiesBehindOnEveryPath) {
    const Scene cut = cut_scene(Front::cut_out), none = cut_scene(Front::none), solid = cut_scene(Front::solid);
    for (Config c : every_path()) {
        for (bool prepass : {true, false}) {
            if (!prepass && c.name != "texture/quad" && c.name != "no-mrt/packed") continue;
            c.opts.skip.depth_prepass = !prepass;  // the skip leaves the pre-pass out where it measures it pays
            const std::string label = c.name + (prepass ? "" : " (pre-pass skip on)");
            const std::vector<Rendered> f = render_deferred({cut, none, solid}, c);
            expect_cut(cut, f[0].diffuse, f[1].diffuse, f[2].diffuse, label + ", G-buffer diffuse");
            expect_cut(cut, f[0].image, f[1].image, f[2].image, label);
        }
    }
}

TEST(ModelSurfaces, CutOutInTheForwardReferences) {
    const std::vector<Scene> s = {cut_scene(Front::cut_out), cut_scene(Front::none), cut_scene(Front::solid)};
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
        const std::vector<Image> f = render_forward_all(s, forward_mode(m));
        expect_cut(s[0], f[0], f[1], f[2], m == ForwardMode::single ? "forward single" : "forward multi");
    }
}

// A transparent cut-out plane: its cut half is not blended over what lies behind.
TEST(ModelSurfaces, TransparentCutOut) {
    Scene cut = cut_scene(Front::cut_out), none = cut_scene(Front::none), solid = cut_scene(Front::solid);
    cut.materials[1].opacity = solid.materials[1].opacity = 0.5f;
    const std::vector<Rendered> f = render_deferred({cut, none, solid}, config("texture", DepthPath::texture, LightGeometry::quad));
    expect_cut(cut, f[0].image, f[1].image, f[2].image, "transparent, deferred");
    const std::vector<Image> fw = render_forward_all({cut, none, solid}, forward_mode(ForwardMode::single));
    expect_cut(cut, fw[0], fw[1], fw[2], "transparent, forward");
}

namespace {

// A floor under a cut-out caster (y = 1), a directional light leaning +z with a shadow: the caster's
// shadow falls on the floor at z in [0, 2], clear of where the camera sees the caster itself.
Scene shadow_scene(Front front) {
    Scene s;
    s.camera.pos = {0, 6, 6};
    s.camera.target = {0, 0, 0};
    s.camera.near_plane = 0.1f;
    s.camera.far_plane = 60;
    s.ambient = glm::vec3(0.1f);
    s.materials = {material("floor", glm::vec3(0.8f), glm::vec3(0)), material("leaf", {0.9f, 0.7f, 0.2f})};
    s.textures.push_back(half_cut_texture());
    s.texture_paths.push_back("cut");
    s.materials[1].diffuse_map = 0;
    s.materials[1].alpha_cutoff = front == Front::cut_out ? 0.5f : 0.0f;
    add_plane(s, 8, {0, 0, 0}, 0);
    if (front != Front::none) add_plane(s, 2, {0, 1, 0}, 1);
    Light l;
    l.type = Light::Type::directional;
    l.dir = glm::normalize(glm::vec3(0, -1, 1));
    l.color = glm::vec3(0.9f);
    l.shadow.on = true;
    s.lights.push_back(l);
    return s;
}

// Floor pixels under the caster's cut (left) or kept (right) half's shadow, a margin from its edges.
bool in_shadow_half(const Scene& s, int x, int y, bool left) {
    const glm::vec3 p = ray_hits(s, x, y, 0.0f);
    const float m = 0.2f;
    if (p.z < m || p.z > 2 - m || std::fabs(p.x) > 1 - m) return false;
    return left ? p.x < -m : p.x > m;
}

void expect_shadow_hole(const Scene& s, const Image& cut, const Image& none, const Image& solid, const std::string& label) {
    const auto left = [&](int x, int y) { return in_shadow_half(s, x, y, true); };
    const auto right = [&](int x, int y) { return in_shadow_half(s, x, y, false); };
    const MaskedDiff l = masked_diff(cut, none, left), r = masked_diff(cut, solid, right);
    std::printf("[ shadow   ] %s: under the cut half vs no caster max %.1f LSB (%d px), under the kept half vs a solid "
                "caster max %.1f LSB (%d px)\n",
                label.c_str(), l.max_lsb, l.pixels, r.max_lsb, r.pixels);
    EXPECT_GT(l.pixels, 30) << label;
    EXPECT_GT(r.pixels, 30) << label;
    EXPECT_LE(l.max_lsb, 1.0) << label << ": light passes through the cut";
    EXPECT_LE(r.max_lsb, 1.0) << label << ": the kept half casts";
    EXPECT_GT(masked_diff(none, solid, left).max_lsb, 40) << label << ": a solid caster shadows there";
}

}  // namespace

// The shadow of a cut-out caster has the cut in it: depth-texture maps and packed maps, the
// deferred renderer and the forward reference.
TEST(ModelSurfaces, CutOutCastsOnlyWhereItIsDrawn) {
    const std::vector<Scene> s = {shadow_scene(Front::cut_out), shadow_scene(Front::none), shadow_scene(Front::solid)};
    for (bool packed : {false, true}) {
        Config c = packed ? config("packed maps", DepthPath::packed, LightGeometry::quad, {"no-depth-texture"})
                          : config("depth-texture maps", DepthPath::texture, LightGeometry::automatic);
        c.opts.shadow_lights = true;
        const std::vector<Rendered> f = render_deferred(s, c);
        expect_shadow_hole(s[0], f[0].image, f[1].image, f[2].image, c.name);
        ForwardOptions fo = forward_mode(ForwardMode::single);
        const std::vector<Image> fw = render_forward_all(s, fo, c.off);
        expect_shadow_hole(s[0], fw[0], fw[1], fw[2], "forward, " + c.name);
    }
}

namespace {

// ---- texture sampling --------------------------------------------------------------------------

// A plane (side 4) from above with a diffuse map and material tile `tile`; its G-buffer diffuse.
Scene textured_plane(Image map, float tile, std::optional<TextureSampling> ts) {
    Scene s;
    s.camera.pos = {0, 5, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.materials = {material("mapped", glm::vec3(1))};
    s.materials[0].diffuse_map = 0;
    s.materials[0].tile = tile;
    s.textures.push_back(std::move(map));
    s.texture_paths.push_back("map");
    if (ts) s.texture_sampling.push_back(*ts);
    add_plane(s, 4, {0, 0, 0}, 0);
    s.lights.push_back({{0, 2, 0}, {1, 1, 1}, 8.0f});
    return s;
}

// The plane's point at texture coordinate u (v = 0.5): u along +x from x = -2.
glm::vec3 at_u(float u) { return {-2 + 4 * u, 0, 0}; }

glm::vec3 diffuse_at(const Scene& s, const Image& diffuse, float u) {
    const glm::ivec2 p = pixel_of(s, at_u(u));
    return glm::vec3(diffuse.at(p.x, p.y)[0], diffuse.at(p.x, p.y)[1], diffuse.at(p.x, p.y)[2]) * 255.0f;
}

}  // namespace

// Wrap modes: the map (left half red, right half green) tiled twice across the plane. At u = 1.25
// repeat reads 0.25 (red), clamp the edge (green), mirror 0.75 (green); at 1.75: green, green, red.
TEST(ModelSurfaces, WrapModes) {
    const Image map = solid_texture(4, 4, [](int x, int) { return x < 2 ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 1, 0, 1); });
    struct Case {
        TextureSampling::Wrap wrap;
        bool red_at_1_25, red_at_1_75;
    } cases[] = {{TextureSampling::Wrap::repeat, true, false},
                 {TextureSampling::Wrap::clamp, false, false},
                 {TextureSampling::Wrap::mirror, false, true}};
    std::vector<Scene> scenes;
    for (const Case& c : cases) {
        TextureSampling ts;
        ts.wrap_s = ts.wrap_t = c.wrap;
        scenes.push_back(textured_plane(map, 2, ts));
    }
    scenes.push_back(textured_plane(map, 2, std::nullopt));  // no sampling given: repeat
    for (const Config& cfg : {config("npot", DepthPath::texture, LightGeometry::quad),
                              config("no-npot, no-mrt", DepthPath::packed, LightGeometry::quad, {"no-npot", "no-mrt"})}) {
        const std::vector<Rendered> f = render_deferred(scenes, cfg);
        for (size_t i = 0; i < scenes.size(); ++i) {
            const Case& c = i < 3 ? cases[i] : cases[0];  // the last: no sampling given, repeat
            for (float u : {1.25f, 1.75f}) {
                const glm::vec3 d = diffuse_at(scenes[i], f[i].diffuse, u / 2);
                const bool red = u == 1.25f ? c.red_at_1_25 : c.red_at_1_75;
                EXPECT_NEAR(d.r, red ? 255 : 0, 1.0) << cfg.name << " case " << i << " u " << u;
                EXPECT_NEAR(d.g, red ? 0 : 255, 1.0) << cfg.name << " case " << i << " u " << u;
            }
        }
    }
}

// Filters: a 2 x 1 map (red, green) magnified over the plane: at u = 0.4 nearest reads the red texel
// alone, linear blends 0.3 of the green one in.
TEST(ModelSurfaces, MagnificationFilter) {
    const Image map = solid_texture(2, 1, [](int x, int) { return x == 0 ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 1, 0, 1); });
    TextureSampling nearest;
    nearest.nearest_mag = nearest.nearest_min = true;
    nearest.mipmaps = false;
    TextureSampling linear;
    linear.mipmaps = false;
    const Scene n = textured_plane(map, 1, nearest), l = textured_plane(map, 1, linear);
    const std::vector<Rendered> f = render_deferred({n, l}, config("texture", DepthPath::texture, LightGeometry::quad));
    const glm::vec3 dn = diffuse_at(n, f[0].diffuse, 0.4f), dl = diffuse_at(l, f[1].diffuse, 0.4f);
    EXPECT_NEAR(dn.r, 255, 0.5);
    EXPECT_NEAR(dn.g, 0, 0.5);
    EXPECT_NEAR(dl.g, 0.3 * 255, 8);  // the pixel's centre is within a few hundredths of u = 0.4
    EXPECT_NEAR(dl.r + dl.g, 255, 1.5);
}

// An sRGB map is decoded to linear when sampled: a 0.5-coded texel reads 0.214, whatever --textures
// says (decoded on upload, or by the GL with --textures srgb); the same map unmarked reads 0.5.
TEST(ModelSurfaces, SrgbMapIsDecoded) {
    const Image grey = solid_texture(4, 4, [](int, int) { return glm::vec4(0.5f, 0.5f, 0.5f, 1); });
    TextureSampling srgb;
    srgb.srgb = true;
    const Scene coded = textured_plane(grey, 1, srgb), stored = textured_plane(grey, 1, std::nullopt);
    for (bool textures_srgb : {false, true}) {
        Config c = config("texture", DepthPath::texture, LightGeometry::quad);
        c.opts.hdr.textures_srgb = textures_srgb;
        const std::vector<Rendered> f = render_deferred({coded, stored}, c);
        const glm::vec3 d = diffuse_at(coded, f[0].diffuse, 0.5f), s = diffuse_at(stored, f[1].diffuse, 0.5f);
        EXPECT_NEAR(d.r, 0.214 * 255, 1.0) << "--textures srgb " << textures_srgb;
        EXPECT_NEAR(d.g, 0.214 * 255, 1.0);
        // The unmarked map: as stored, or decoded as every diffuse map with --textures srgb.
        EXPECT_NEAR(s.r, (textures_srgb ? 0.214 : 0.5) * 255, 1.0) << "--textures srgb " << textures_srgb;
    }
    // The forward reference decodes it too: its lit image is the deferred one's.
    const Image def = render_deferred({coded}, config("texture", DepthPath::texture, LightGeometry::quad))[0].image;
    const Image fwd = render_forward(coded, kSize, kSize, forward_mode(ForwardMode::single)).image;
    const ImageDiff d = compare_logged("forward vs deferred, sRGB map", fwd, def, 2 * kLsb);
    EXPECT_LE(d.max_lsb(), 3.0);
}
