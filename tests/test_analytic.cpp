// The analytic reference (src/analysis/analytic_reference.h) checked by hand, then the forward
// and deferred renderers measured against it on tests/data/analytic.scene (planes and spheres,
// constant materials, two lights). Every measured number is printed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "analysis/analytic_reference.h"
#include "dsr_error.h"
#include "forward_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr int kSize = 128;
constexpr double kLsb = 1.0 / 255.0;

double excluded_fraction(const std::vector<uint8_t>& mask) {
    size_t n = 0;
    for (uint8_t m : mask) n += !m;
    return double(n) / double(mask.size());
}

ImageDiff logged_masked(const std::string& name, const Image& a, const Image& b, const std::vector<uint8_t>& mask,
                        double thr) {
    ImageDiff d = compare_images_masked(a, b, mask, thr);
    std::printf("[ image    ] %s: max %.2f LSB, mean %.4f LSB, %lld/%lld interior pixels over %.1f LSB\n",
                name.c_str(), d.max_lsb(), d.mean_lsb(), d.failing, d.pixels, thr * 255);
    return d;
}

// Where the comparison of a triangle renderer with the exact trace measures the renderer and
// not the sphere's tessellation (docs/accuracy.md: the trace now hits exact shapes, and the 48x24
// sphere's facets lie up to 0.43% of r inside the sphere):
// `untessellated`: interior pixels on meshes that are exactly their triangles (planes, boxes,
// meshes without a shape); `same_surface`: pixels where the exact trace and the trace of the
// renderer's triangles see the same mesh (only the sphere silhouettes' coverage differs), less
// the spheres' own silhouette ring (sphere pixels not interior), where the ray meets the sphere
// at grazing incidence and the facet's normal is off by gap / cos(incidence), unbounded.
std::vector<uint8_t> untessellated(const Scene& s, const AnalyticTrace& tr, std::vector<uint8_t> mask) {
    for (size_t p = 0; p < mask.size(); ++p) {
        const int m = tr.mesh[p];
        if (m >= 0 && s.objects[size_t(m)].shape && s.objects[size_t(m)].shape->kind == ShapeDesc::Kind::sphere)
            mask[p] = 0;
    }
    return mask;
}
std::vector<uint8_t> only_spheres(const Scene& s, const AnalyticTrace& tr, std::vector<uint8_t> mask) {
    const std::vector<uint8_t> flat = untessellated(s, tr, mask);
    for (size_t p = 0; p < mask.size(); ++p) mask[p] = mask[p] && !flat[p];
    return mask;
}
std::vector<uint8_t> same_surface(const Scene& s, const AnalyticTrace& exact) {
    AnalyticOptions tri;
    tri.triangles = true;
    const AnalyticTrace t = analytic_trace(s, exact.image.width, exact.image.height, tri);
    std::vector<uint8_t> mask(exact.mesh.size());
    const std::vector<uint8_t> interior = interior_mask(exact, exact.image.width, exact.image.height);
    const std::vector<uint8_t> flat = untessellated(s, exact, std::vector<uint8_t>(mask.size(), 1));
    for (size_t p = 0; p < mask.size(); ++p)
        mask[p] = exact.mesh[p] == t.mesh[p] && (flat[p] || interior[p]);
    return mask;
}

}  // namespace

TEST(Analytic, HandComputedPixels) {
    Scene s = plane_from_above();
    const int n = 65;
    AnalyticTrace t = analytic_trace(s, n, n);
    // Centre: ambient 0.1*0.5 + att (1 - 1/2) * (diffuse 1*0.5 + specular 1^10*0.25) = 0.425.
    EXPECT_NEAR(t.image.at(32, 32)[0], 0.425, 1e-6);
    EXPECT_EQ(t.mesh[32 * n + 32], 0);
    // The plane (4 wide, 5 below a 60-degree camera) does not reach the corners: background.
    EXPECT_EQ(t.mesh[0], -1);
    EXPECT_FLOAT_EQ(t.image.at(0, 0)[2], 0.75f);
    // A pixel whose point is beyond the light's radius sees the ambient term only: 0.05.
    // Pixel i has ray x = ((i + 0.5)/n*2 - 1) * tan(30deg), hitting the plane at 5x from the axis.
    const int i = 53;
    const double x = ((i + 0.5) / n * 2 - 1) * std::tan(3.14159265358979 / 6) * 5;
    ASSERT_LT(x, 2.0);                     // on the plane
    ASSERT_GT(std::sqrt(x * x + 1), 2.0);  // distance to the light > S_radius
    EXPECT_EQ(t.mesh[32 * n + i], 0);
    EXPECT_NEAR(t.image.at(i, 32)[0], 0.05, 1e-6);
    // Back faces are culled, as in GL: seen from below, the plane vanishes.
    Scene below = s;
    below.camera.pos = {0, -5, 0};
    below.camera.up = {0, 0, 1};
    EXPECT_EQ(analytic_trace(below, n, n).mesh[32 * n + 32], -1);
}

TEST(Analytic, RejectsTextureMaps) {
    EXPECT_THROW(analytic_reference(default_scene(), 8, 8), Error);
}

// Transparent materials (docs/forward.md) are blended by the forward stage; the trace has no blending.
TEST(Analytic, RejectsTransparentMaterials) {
    Scene s = lit_sphere_scene();
    EXPECT_NO_THROW(analytic_reference(s, 8, 8));
    s.materials[0].opacity = 0.5f;
    try {
        analytic_reference(s, 8, 8);
        ADD_FAILURE() << "a transparent material was traced as opaque";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is transparent"), std::string::npos) << e.what();
    }
}

// The forward renderer against the trace. On planes (exactly their triangles) with the same
// pixel-centre sampling, the only differences are float against double arithmetic and the 8-bit
// output. Interior pixels (3x3 neighbourhood on one mesh in the trace) of the planes: within the
// output rounding (measured max 0.50 LSB, mean 0.16). All pixels where the exact shapes and the
// renderer's triangles show the same mesh: a pixel or so on a silhouette where GL's float edge
// test and the exact one disagree, bounded at 0.1%.
// Since the trace hits the exact spheres (docs/accuracy.md) these assertions hold only where that
// comparison is valid, so they are restricted to those pixels (`untessellated`, `same_surface`;
// over every interior pixel the forward image is now max 1.46 LSB off, and over all pixels 19 of
// 16384 are over 2 LSB, on the spheres' silhouettes). On
// the spheres' interior pixels the forward error is bounded by the tessellation's own shading
// difference (the exact trace against the trace of the triangles) plus the same 0.75 LSB.
TEST(Analytic, ForwardMatchesTrace) {
    Scene s = analytic_scene();
    auto t0 = std::chrono::steady_clock::now();
    AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const auto mask = interior_mask(tr, kSize, kSize);
    std::printf("[ stats    ] trace %dx%d in %.1f ms; %.2f%% of pixels on silhouettes excluded\n", kSize, kSize, ms,
                100 * excluded_fraction(mask));
    EXPECT_LE(excluded_fraction(mask), 0.06);
    const auto flat = untessellated(s, tr, mask), spheres = only_spheres(s, tr, mask);
    const auto same = same_surface(s, tr);
    AnalyticOptions tri;
    tri.triangles = true;
    const ImageDiff tess = logged_masked("exact trace vs trace of the triangles, sphere interiors", tr.image,
                                         analytic_trace(s, kSize, kSize, tri).image, spheres, kLsb);
    for (ForwardMode mode : {ForwardMode::single, ForwardMode::multi}) {
        const char* name = mode == ForwardMode::single ? "forward single" : "forward multi";
        auto fwd = render_forward(s, kSize, kSize, forward_mode(mode));
        logged_masked(std::string(name) + " vs trace, every interior pixel", fwd.image, tr.image, mask, kLsb);
        compare_logged(std::string(name) + " vs trace, all pixels", fwd.image, tr.image, 2 * kLsb);
        ImageDiff in = logged_masked(std::string(name) + " vs trace, planes' interior", fwd.image, tr.image, flat, kLsb);
        ImageDiff sph = logged_masked(std::string(name) + " vs trace, spheres' interior", fwd.image, tr.image, spheres,
                                      kLsb);
        ImageDiff all = logged_masked(std::string(name) + " vs trace, pixels where shapes and triangles agree",
                                      fwd.image, tr.image, same, 2 * kLsb);
        if (in.max_lsb() > 0.75) write_failure_images("forward_vs_trace", fwd.image, tr.image);
        EXPECT_LE(in.max_lsb(), 0.75);
        EXPECT_LE(in.mean_lsb(), 0.3);
        EXPECT_LE(all.failing_fraction(), 0.001);
        EXPECT_LE(sph.max_lsb(), tess.max_lsb() + 0.75);
    }
}

// The goal: the analytic scene within 2 LSB for the depth-texture path (the analytic reference:
// docs/accuracy.md). On interior pixels the deferred image is within 2 codes of the correctly
// rounded reference (measured max 2 at 96, 128 and 256; against the float reference max 2.07
// LSB at 128, 1 pixel of 15650 just over 2).
// The error is the deferred path's quantisation (next test), not geometry: the forward renderer
// on the same triangles is within 0.5 LSB. Silhouette pixels are excluded as above; over all
// pixels at most 0.1% may be over 2 LSB (measured 2 of 16384).
TEST(Analytic, DeferredDepthTextureWithinTwoLsb) {
    Scene s = analytic_scene();
    AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    const auto mask = interior_mask(tr, kSize, kSize);
    ShaderOptions tex;
    tex.depth = DepthPath::texture;
    auto def = render_scene(s, kSize, kSize, tex);
    std::printf("[ renderer ] %s\n", def.renderer.c_str());
    ImageDiff q = logged_masked("deferred (depth texture) vs rounded trace", def.image, rounded(tr.image), mask,
                                2 * kLsb);
    ImageDiff f = logged_masked("deferred (depth texture) vs trace", def.image, tr.image, mask, 2 * kLsb);
    compare_logged("deferred (depth texture) vs trace, all pixels", def.image, tr.image, 2 * kLsb);
    // Restricted (docs/accuracy.md) to the pixels where the exact shapes and the renderer's triangles
    // show the same mesh, less the spheres' silhouette ring (same_surface): over all pixels 28 of
    // 16384 are now over 2 LSB, on the spheres' silhouettes, where the exact sphere covers pixels
    // its facets do not or meets the ray at grazing incidence.
    ImageDiff all = logged_masked("deferred (depth texture) vs trace, pixels where shapes and triangles agree",
                                  def.image, tr.image, same_surface(s, tr), 2 * kLsb);
    if (q.max_lsb() > 2) write_failure_images("deferred_vs_trace", def.image, tr.image);
    EXPECT_LE(q.max_lsb(), 2.0);
    EXPECT_LE(f.failing_fraction(), 0.001);
    EXPECT_LE(f.mean_lsb(), 0.3);
    EXPECT_LE(all.failing_fraction(), 0.001);

    // The packed path rebuilds the same 24-bit depth codes (tests/test_pipeline.cpp); logged.
    ShaderOptions packed;
    packed.depth = DepthPath::packed;
    auto pk = render_scene(s, kSize, kSize, packed);
    ImageDiff p = logged_masked("deferred (packed depth) vs rounded trace", pk.image, rounded(tr.image), mask,
                                2 * kLsb);
    EXPECT_LE(p.max_lsb(), 2.0);
}

// Where the deferred error comes from: the trace with the deferred path's roundings switched on
// one at a time (AnalyticOptions). Measured at 128 (interior, max / mean LSB against the plain
// trace): 8-bit normals 1.70 / 0.059, 8-bit materials and shininess code 0.32 / 0.096, 8-bit
// accumulation of the 3 passes 1.32 / 0.216, all three 2.10 / 0.244; the deferred render is
// 2.07 / 0.247. Against the full model the deferred image is off by 0 codes on 91%, 1 code on
// 8.5% of channels (mean 0.054 LSB), a rare 2-3 (0.10% of pixels) where float and double land
// on opposite sides of a rounding step (a normal component one code off moves a highlight). So the model accounts for the error: the deferred path's mean error
// against the model must be well under its mean error against the reference.
// Those figures were measured against the trace of the renderer's triangles. Against the exact
// spheres the model leaves out the 48x24 tessellation: 8-bit normals 1.86 / 0.059,
// all three 2.37 / 0.244, the render 2.06 / 0.253, and against the model max 4.00, mean 0.060,
// 28 of 15650 pixels off by 1.5 LSB or more (0.18%); the assertions below are unchanged.
TEST(Analytic, DeferredErrorIsGBufferAndPassQuantisation) {
    Scene s = analytic_scene();
    AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    const auto mask = interior_mask(tr, kSize, kSize);
    AnalyticOptions normals, materials, passes, model;
    normals.gbuffer_normals_8bit = true;
    materials.gbuffer_materials_8bit = true;
    passes.passes_8bit = true;
    model.gbuffer_normals_8bit = model.gbuffer_materials_8bit = model.passes_8bit = true;
    logged_masked("trace, 8-bit normals vs trace", analytic_trace(s, kSize, kSize, normals).image, tr.image, mask,
                  2 * kLsb);
    logged_masked("trace, 8-bit materials vs trace", analytic_trace(s, kSize, kSize, materials).image, tr.image,
                  mask, 2 * kLsb);
    logged_masked("trace, 8-bit passes vs trace", analytic_trace(s, kSize, kSize, passes).image, tr.image, mask,
                  2 * kLsb);
    const Image m = analytic_trace(s, kSize, kSize, model).image;
    logged_masked("trace, all three vs trace", m, tr.image, mask, 2 * kLsb);

    auto def = render_scene(s, kSize, kSize, ShaderOptions{});
    ImageDiff vs_ref = compare_images_masked(def.image, tr.image, mask, 2 * kLsb);
    ImageDiff vs_model = logged_masked("deferred vs model", def.image, m, mask, 1.5 * kLsb);
    EXPECT_LE(vs_model.mean_lsb(), 0.1);
    // Measured 0.10% of pixels off by 2 codes or more; a 5% error in the shininess decode
    // (exp2(11a) * 1.05 in lighting.glsl) gave 0.56%.
    EXPECT_LE(vs_model.failing_fraction(), 0.003);
    EXPECT_LE(vs_model.max_lsb(), 4.0);
    EXPECT_LT(vs_model.mean_lsb(), 0.5 * vs_ref.mean_lsb());
}

// ---- References that do not share the renderer's code (docs/accuracy.md) ----

namespace {
// A plane that fills the view, seen obliquely (about 35 degrees from its normal at the centre
// of the view), lit by two lights: every pixel is interior, and the material's maps are
// magnified everywhere (AnalyticTrace::max_texel_footprint < 1), so GL_LINEAR at level 0 is
// what the renderer samples.
Scene mapped_plane(glm::vec3 diffuse, glm::vec3 specular, float shininess) {
    Scene s;
    s.camera.pos = {0, 2.0f, 1.6f};
    s.camera.target = {0, 0, -0.6f};
    s.camera.up = {0, 1, 0};
    s.camera.fov_deg = 50;
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.1f);
    s.background = {0.25f, 0.5f, 0.75f};
    Material m;
    m.name = "mapped";
    m.diffuse = diffuse;
    m.specular = specular;
    m.shininess = shininess;
    s.materials.push_back(m);
    add_plane(s, 8, {0, 0, 0}, 0);
    s.lights.push_back({{-0.8f, 1.2f, 0.2f}, {1, 0.9f, 0.8f}, 4.0f});
    s.lights.push_back({{1.0f, 0.6f, -1.2f}, {0.4f, 0.6f, 1}, 2.5f});
    return s;
}

// A diffuse map with strong texel-to-texel contrast (so bilinear weights matter), on 8-bit
// codes: a closed-form pattern of two sinusoids and a hashed checker.
Image contrast_map(int w, int h) {
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 1.0f);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double u = (i + 0.5) / w, v = (j + 0.5) / h;
            const unsigned hsh = (unsigned(i) * 73856093u) ^ (unsigned(j) * 19349663u);
            const double chk = ((i + j) & 1) ? 0.35 : -0.35;
            float* p = img.at(i, j);
            p[0] = float(std::round(255 * std::clamp(0.55 + chk + 0.08 * std::sin(6.283 * 3 * u), 0.0, 1.0)) / 255);
            p[1] = float(std::round(255 * std::clamp(0.5 + 0.4 * std::sin(6.283 * (2 * u + 5 * v)), 0.0, 1.0)) / 255);
            p[2] = float(((hsh >> 7) % 200 + 40) / 255.0);
        }
    return img;
}

struct MappedResult {
    ImageDiff rounded, exact;
    double footprint = 0;
};

// The depth-texture path against the trace on interior pixels (here: the whole plane).
MappedResult measure_mapped(const std::string& name, const Scene& s, const AnalyticOptions& opts) {
    AnalyticTrace tr = analytic_trace(s, kSize, kSize, opts);
    const auto mask = interior_mask(tr, kSize, kSize);
    ShaderOptions tex;
    tex.depth = DepthPath::texture;
    auto def = render_scene(s, kSize, kSize, tex);
    MappedResult r;
    r.footprint = tr.max_texel_footprint;
    std::printf("[ stats    ] %s: largest pixel footprint %.3f texels (< 1: magnified), %.1f%% interior\n",
                name.c_str(), r.footprint, 100 * (1 - excluded_fraction(mask)));
    r.rounded = logged_masked(name + ", deferred (depth texture) vs rounded trace", def.image, rounded(tr.image), mask,
                              2 * kLsb);
    r.exact = logged_masked(name + ", deferred (depth texture) vs trace", def.image, tr.image, mask, 2 * kLsb);
    if (r.rounded.max_lsb() > 2) write_failure_images(name, def.image, tr.image);
    return r;
}
}  // namespace

// The exact shapes against the renderer's triangles. Planes and boxes are exactly their
// triangles, so the exact and the triangle traces agree there to float rounding of the
// vertices; the 48x24 sphere's facets lie inside it by at most sphere_tessellation_gap()
// (closed form for the equatorial facets: the right triangle's hypotenuse midpoint, half of
// a 10.6-degree arc: 1 - cos(5.3 deg) = 0.43% of r), and the facet's interpolated normal is
// the radial direction of the facet point, off the exact normal by about gap / cos(incidence).
TEST(Analytic, ExactShapesAndTheSphereTessellationBound) {
    const double gap = sphere_tessellation_gap(48, 24);
    const double pi = 3.14159265358979323846;
    const double edge = 1 - std::cos(pi / 48);  // the midpoint of one 7.5-degree edge
    const double diag = 1 - std::cos(0.5 * std::acos(std::cos(2 * pi / 48) * std::cos(pi / 24)));
    std::printf("[ bound    ] sphere 48x24: facets at most %.5f r inside the sphere (edge midpoint %.5f, quad "
                "diagonal midpoint %.5f); normal error <= %.3f deg head-on, %.3f deg at 60 deg incidence\n",
                gap, edge, diag, gap / (1 - gap) * 180 / pi, gap / ((1 - gap) * 0.5) * 180 / pi);
    EXPECT_GE(gap, edge);
    EXPECT_LE(gap, diag * 1.0001);
    EXPECT_LT(gap, 0.005);

    Scene s = analytic_scene();
    AnalyticTrace exact = analytic_trace(s, kSize, kSize);
    AnalyticOptions tri;
    tri.triangles = true;
    AnalyticTrace tris = analytic_trace(s, kSize, kSize, tri);
    const auto mask = interior_mask(exact, kSize, kSize);
    // Per mesh: how far the exact trace is from the triangle trace (interior pixels), in depth
    // (relative to the sphere's radius) and in shading.
    for (size_t m = 0; m < s.objects.size(); ++m) {
        std::vector<uint8_t> on(mask.size(), 0);
        double dz = 0;
        for (size_t p = 0; p < mask.size(); ++p) {
            on[p] = mask[p] && exact.mesh[p] == int(m) && tris.mesh[p] == int(m);
            if (on[p]) dz = std::max(dz, std::fabs(exact.eye_depth[p] - tris.eye_depth[p]));
        }
        const bool sphere = s.objects[m].shape->kind == ShapeDesc::Kind::sphere;
        ImageDiff d = logged_masked("mesh " + std::to_string(m) + (sphere ? " (sphere)" : " (plane)") +
                                        ", exact vs triangle trace",
                                    exact.image, tris.image, on, 2 * kLsb);
        std::printf("[ bound    ] mesh %zu: max depth difference %.5f (radius %.2f)\n", m, dz,
                    sphere ? s.objects[m].shape->radius : 0.0f);
        if (!sphere) {
            EXPECT_LE(d.max_lsb(), 0.01);
            EXPECT_LE(dz, 1e-5);
        } else {
            // Facets are inside the sphere: the exact hit is nearer, by at most gap / cos(incidence).
            EXPECT_GT(d.max_lsb(), 0.0);
            EXPECT_GT(dz, 0.0);
        }
    }
    // The exact sphere is hit where the triangles are not (the facets lie inside it), never the
    // other way round.
    long long only_exact = 0, only_tris = 0;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (exact.mesh[p] == 1 && tris.mesh[p] != 1) ++only_exact;
        if (tris.mesh[p] == 1 && exact.mesh[p] != 1) ++only_tris;
    }
    std::printf("[ bound    ] sphere 1: %lld pixels hit only by the exact sphere, %lld only by its triangles\n",
                only_exact, only_tris);
    EXPECT_EQ(only_tris, 0);
}

// Exact shapes by hand: a ray straight down the axis of a sphere meets it at distance - r.
TEST(Analytic, ExactSphereByHand) {
    Scene s = plane_from_above();
    s.meshes.clear();
    s.objects.clear();
    add_sphere(s, 1.0f, {0, 0, 0}, 0);
    const int n = 65;
    AnalyticTrace t = analytic_trace(s, n, n);
    EXPECT_NEAR(t.eye_depth[32 * n + 32], 4.0, 1e-12);
    AnalyticOptions tri;
    tri.triangles = true;
    // The pole of the tessellated sphere is a vertex: the same depth there.
    EXPECT_NEAR(analytic_trace(s, n, n, tri).eye_depth[32 * n + 32], 4.0, 1e-6);
    // A box seen from above: its top face at y = 0.5.
    s.meshes.clear();
    s.objects.clear();
    add_box(s, {1, 1, 1}, {0, 0, 0}, 0);
    EXPECT_NEAR(analytic_trace(s, n, n).eye_depth[32 * n + 32], 4.5, 1e-12);
    // From inside the box nothing is seen (back faces culled).
    s.camera.pos = {0, 0.2f, 0};
    EXPECT_EQ(analytic_trace(s, n, n).mesh[32 * n + 32], -1);
}

TEST(Analytic, RefusesMapsWithoutAClosedForm) {
    Scene s = mapped_plane(glm::vec3(0.8f), glm::vec3(0), 1);
    s.textures.push_back(contrast_map(8, 8));
    s.materials[0].diffuse_map = 0;
    EXPECT_THROW(analytic_trace(s, 8, 8), Error);  // diffuse maps need bilinear_diffuse_maps
    AnalyticOptions o;
    o.bilinear_diffuse_maps = true;
    EXPECT_NO_THROW(analytic_trace(s, 8, 8, o));
    s.materials[0].normal_map = 0;
    EXPECT_THROW(analytic_trace(s, 8, 8, o), Error);  // a normal map with no formula
    o.bump_maps[0] = BumpMap{};
    EXPECT_NO_THROW(analytic_trace(s, 8, 8, o));
    s.materials[0].specular_map = 0;
    EXPECT_THROW(analytic_trace(s, 8, 8, o), Error);  // specular maps: none
    s.materials[0].specular_map = -1;
    add_sphere(s, 0.5f, {0, 0.5f, 0}, 0);
    EXPECT_THROW(analytic_trace(s, 8, 8, o), Error);  // a map on a sphere: no uv here
}

// (ii) A textured plane seen without minification: the reference samples the map bilinearly
// on the CPU as GL_LINEAR at level 0 does. Goals (docs/accuracy.md): <= 2 LSB diffuse only, <= 4 LSB
// with specular, against the correctly rounded trace on interior pixels.
TEST(Analytic, DeferredTexturedPlaneMatchesBilinearReference) {
    AnalyticOptions o;
    o.bilinear_diffuse_maps = true;
    Scene diffuse = mapped_plane(glm::vec3(1.0f), glm::vec3(0), 1);
    diffuse.textures.push_back(contrast_map(32, 32));
    diffuse.materials[0].diffuse_map = 0;
    MappedResult d = measure_mapped("textured plane, diffuse only", diffuse, o);
    EXPECT_GT(d.footprint, 0.1);
    EXPECT_LT(d.footprint, 1.0);
    EXPECT_LE(d.rounded.max_lsb(), 2.0 + 1e-3);  // whole codes; 1e-3 absorbs float's k/255

    Scene spec = diffuse;
    spec.materials[0].specular = glm::vec3(0.5f);
    spec.materials[0].shininess = 32;
    MappedResult sp = measure_mapped("textured plane, with specular", spec, o);
    EXPECT_LE(sp.rounded.max_lsb(), 4.0 + 1e-3);

    // The check can fail: the reference with the map's rows flipped (t -> 1 - t) is far off.
    Scene flipped = diffuse;
    const Image& map = diffuse.textures[0];
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i)
            for (int k = 0; k < 4; ++k) flipped.textures[0].at(i, j)[k] = map.at(i, map.height - 1 - j)[k];
    AnalyticTrace tr_flip = analytic_trace(flipped, kSize, kSize, o);
    ShaderOptions tex;
    tex.depth = DepthPath::texture;
    auto def = render_scene(diffuse, kSize, kSize, tex);
    ImageDiff bad = compare_images_masked(def.image, tr_flip.image, interior_mask(tr_flip, kSize, kSize), 2 * kLsb);
    std::printf("[ image    ] against a reference with the map flipped: max %.1f LSB\n", bad.max_lsb());
    EXPECT_GT(bad.max_lsb(), 20.0);
}

// (i) A normal-mapped plane whose map is made from a closed form (sinusoidal bumps,
// make_bump_normal_map); the reference shades with the formula's exact normal at the hit's uv,
// not the texture. Goal (docs/accuracy.md): <= 3 LSB against the correctly rounded trace, interior.
TEST(Analytic, DeferredNormalMappedPlaneMatchesClosedForm) {
    const BumpMap bumps{0.04, 2};
    Scene s = mapped_plane(glm::vec3(0.8f), glm::vec3(0.3f), 16);
    s.textures.push_back(make_bump_normal_map(bumps, 64, 64));
    s.materials[0].normal_map = 0;
    AnalyticOptions o;
    o.bump_maps[0] = bumps;
    MappedResult r = measure_mapped("normal-mapped plane", s, o);
    EXPECT_LE(r.rounded.max_lsb(), 3.0 + 1e-3);
    // The bumps are visible: against the flat plane's trace the render is far off.
    Scene flat = s;
    flat.materials[0].normal_map = -1;
    AnalyticTrace tf = analytic_trace(flat, kSize, kSize);
    ShaderOptions tex;
    tex.depth = DepthPath::texture;
    auto def = render_scene(s, kSize, kSize, tex);
    ImageDiff bad = compare_images_masked(def.image, tf.image, interior_mask(tf, kSize, kSize), 2 * kLsb);
    std::printf("[ image    ] normal-mapped plane against the flat plane's trace: max %.1f LSB\n", bad.max_lsb());
    EXPECT_GT(bad.max_lsb(), 20.0);
}
