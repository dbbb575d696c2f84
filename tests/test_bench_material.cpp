// The bench's material-model rows (analysis/bench_scenes.h metal_rough_twin, analysis/
// bench_material.h): the twin changes the materials alone, and each variant's metallic-roughness row
// is paired with its own Phong row, never with another variant's or configuration's.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/bench_material.h"
#include "analysis/bench_scenes.h"
#include "render_fixture.h"

using namespace dsr;

namespace {

TEST(BenchMaterial, TwinChangesTheMaterialsAlone) {
    const Scene s = test::default_scene();
    ASSERT_TRUE(has_phong_material(s));
    const Scene t = metal_rough_twin(s);
    EXPECT_FALSE(has_phong_material(t));
    ASSERT_EQ(t.materials.size(), s.materials.size());
    for (size_t i = 0; i < s.materials.size(); ++i) {
        const Material &a = s.materials[i], &b = t.materials[i];
        EXPECT_TRUE(b.metal_rough());
        EXPECT_EQ(b.diffuse, a.diffuse);          // the base colour
        EXPECT_EQ(b.diffuse_map, a.diffuse_map);  // the base colour's map
        EXPECT_EQ(b.normal_map, a.normal_map);
        EXPECT_EQ(b.specular_map, -1);
        EXPECT_EQ(b.metallic, 0.0f);
        // GGX's alpha = roughness^2 as the Beckmann width sqrt(2 / (n + 2)) of Blinn-Phong's exponent n.
        EXPECT_NEAR(double(b.roughness) * b.roughness, std::sqrt(2.0 / (double(a.shininess) + 2.0)), 1e-6) << a.name;
    }
    ASSERT_EQ(t.objects.size(), s.objects.size());
    for (size_t i = 0; i < s.objects.size(); ++i) {
        EXPECT_EQ(t.objects[i].mesh, s.objects[i].mesh);
        EXPECT_EQ(t.objects[i].model, s.objects[i].model);
    }
    ASSERT_EQ(t.lights.size(), s.lights.size());
    for (size_t i = 0; i < s.lights.size(); ++i) EXPECT_EQ(t.lights[i].pos, s.lights[i].pos);
    EXPECT_EQ(t.camera.pos, s.camera.pos);
    // A material that is metallic-roughness already stays as it is.
    Scene mr = s;
    mr.materials.resize(1);
    mr.materials[0].model = Material::Model::metallic_roughness;
    mr.materials[0].roughness = 0.3f;
    EXPECT_FALSE(has_phong_material(mr));
    EXPECT_EQ(metal_rough_twin(mr).materials[0].roughness, 0.3f);
}

bench::Row quad_row(const std::string& scene, int lights, double lights_ms, long long pairs) {
    bench::Row r;
    r.scene = scene;
    r.lights = lights;
    r.w = r.h = 64;
    r.scissor = true;
    r.lights_ms = lights_ms;
    FrameStats st;
    st.lights.fragments = pairs;
    st.lights.fragments_counted = true;
    r.frame = st;
    return r;
}

TEST(BenchMaterial, EachVariantsRowsArePaired) {
    std::vector<bench::Row> rows = {quad_row("default", 32, 2.0, 1000), quad_row("default", 256, 8.0, 4000)};
    bench::Row volume = quad_row("default", 256, 1.0, 4000);  // another geometry: never the pair
    volume.light_geometry = LightGeometry::volume;
    rows.push_back(volume);
    bench::Row linear = quad_row("default", 256, 1.0, 4000);  // a linear-law twin: never the pair
    linear.linear_law = true;
    rows.insert(rows.begin(), linear);
    bench::Row mr = quad_row(bench::metal_rough_name("default"), 256, 10.0, 4000);
    mr.metal_rough = true;
    rows.push_back(mr);
    bench::Row lone = quad_row(bench::metal_rough_name("analytic"), 32, 3.0, 500);  // no Phong row of its own
    lone.metal_rough = true;
    rows.push_back(lone);
    EXPECT_FALSE(bench::default_configuration(mr));  // no goal reads it as dsr's default
    const std::vector<bench::MaterialCost> c = bench::material_costs(rows);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].phong, &rows[2]);
    EXPECT_EQ(c[0].metal_rough, &rows[4]);
    EXPECT_DOUBLE_EQ(c[0].ratio, 10.0 / 8.0);
    ASSERT_TRUE(c[0].phong_ns && c[0].metal_rough_ns);
    EXPECT_DOUBLE_EQ(*c[0].phong_ns, 8.0e6 / 4000);
    EXPECT_DOUBLE_EQ(*c[0].metal_rough_ns, 10.0e6 / 4000);
    const std::string line = bench::material_cost_text(c[0]);
    EXPECT_NE(line.find("= 1.25 on the same 4000 pixel-light pairs"), std::string::npos) << line;
    EXPECT_NE(bench::material_cost_markdown(rows).find("| default | "), std::string::npos);
}

}  // namespace
