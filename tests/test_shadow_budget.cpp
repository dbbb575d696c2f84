// The shadow maps' memory budget (scene/shadow_budget.h): each light's texels as shadow_layout
// lays its map out, the bytes a texel takes on each path, the lights added in order against
// 1 GiB, the refusal's text, and a scene file's light lines refused by line.
#include <string>

#include <gtest/gtest.h>

#include "deferred/shadow_math.h"
#include "dsr_error.h"
#include "scene/scene.h"
#include "scene/shadow_budget.h"

namespace {

using dsr::Light;

Light shadowed(Light::Type type, int size, float angle = 40) {
    Light l;
    l.type = type;
    l.pos = glm::vec3(0, 3, 0);
    l.dir = glm::vec3(0, -1, 0);
    l.angle_deg = angle;
    l.radius = 10;
    l.shadow.on = true;
    l.shadow.size = size;
    return l;
}

dsr::ShadowFit some_fit() {
    dsr::Camera cam;
    cam.pos = glm::vec3(0, 2, 6);
    cam.target = glm::vec3(0);
    cam.up = glm::vec3(0, 1, 0);
    return dsr::shadow_fit(cam, 1.0f, {{glm::vec3(0), 3.0f}});
}

std::string parse_error(const std::string& text) {
    try {
        dsr::parse_scene("a.scene", text);
    } catch (const dsr::Error& e) {
        return e.what();
    }
    return "";
}

const char* const kHead =
    "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\n"
    "material m diffuse 0.5 0.5 0.5 specular 0 0 0 shininess 2\n"
    "plane size 4 at 0 0 0 material m\n";

}  // namespace

// The budget counts what the shadow stage allocates: the texels of shadow_layout's texture for
// every kind of light, size and texture limit.
TEST(ShadowBudget, TexelsAreTheLayoutsTexture) {
    const dsr::ShadowFit fit = some_fit();
    for (int size : {64, 1024, 8192})
        for (int max_texture : {1024, 4096, 16384, 32768})
            for (const Light& l : {shadowed(Light::Type::point, size), shadowed(Light::Type::spot, size, 40),
                                   shadowed(Light::Type::spot, size, 80), shadowed(Light::Type::directional, size)}) {
                const dsr::ShadowLayout s = dsr::shadow_layout(l, size, fit, max_texture);
                EXPECT_EQ(dsr::shadow_map_texels(l, max_texture), (long long)s.width * s.height)
                    << int(l.type) << " angle " << l.angle_deg << " size " << size << " max " << max_texture;
                EXPECT_EQ(dsr::shadow_map_is_cube(l), s.kind == dsr::ShadowKind::cube);
            }
    // Unclamped (a scene file's check): the size asked for.
    EXPECT_EQ(dsr::shadow_map_texels(shadowed(Light::Type::point, 8192)), 6LL * 8192 * 8192);
    EXPECT_EQ(dsr::shadow_map_texels(shadowed(Light::Type::spot, 8192)), 8192LL * 8192);
    Light off = shadowed(Light::Type::spot, 8192);
    off.shadow.on = false;
    EXPECT_EQ(dsr::shadow_map_texels(off), 0);
}

TEST(ShadowBudget, TexelBytesPerPath) {
    EXPECT_EQ(dsr::shadow_texel_bytes(false, true), 4);  // a 24-bit depth texture
    EXPECT_EQ(dsr::shadow_texel_bytes(false, false), 4);
    EXPECT_EQ(dsr::shadow_texel_bytes(true, true), 8);   // RGB8 and a depth renderbuffer
    EXPECT_EQ(dsr::shadow_texel_bytes(true, false), 4);  // RGB8; the main frame buffer's depth
    EXPECT_EQ(dsr::kMaxShadowTexelBytes, 8);
}

// Eight spots of 4096 at 8 bytes a texel are 1 GiB exactly; a ninth is refused, lights without a
// map are not counted, and 4 bytes a texel fits twice as many.
TEST(ShadowBudget, LightsAddedInOrder) {
    std::vector<Light> lights;
    for (int i = 0; i < 8; ++i) {
        lights.push_back(shadowed(Light::Type::spot, 4096));
        Light plain;
        lights.push_back(plain);
    }
    dsr::ShadowBudgetUse u = dsr::shadow_budget_use(lights, 8);
    EXPECT_FALSE(u.over);
    EXPECT_EQ(u.before, dsr::kMaxShadowBytes);
    lights.push_back(shadowed(Light::Type::spot, 4096));
    u = dsr::shadow_budget_use(lights, 8);
    EXPECT_TRUE(u.over);
    EXPECT_EQ(u.light, 16u);
    EXPECT_EQ(u.before, dsr::kMaxShadowBytes);
    EXPECT_EQ(u.bytes, 4096LL * 4096 * 8);
    EXPECT_FALSE(dsr::shadow_budget_use(lights, 4).over);
    // 65536 spots of 1024 (the bench's 65536-shadow) would be 256 GiB at 4 bytes: the 257th is refused.
    std::vector<Light> many(65536, shadowed(Light::Type::spot, 1024));
    u = dsr::shadow_budget_use(many, 4);
    EXPECT_TRUE(u.over);
    EXPECT_EQ(u.light, 256u);
    // One point light of 8192 a face: over unclamped, within where the GL's textures stop at 16384.
    const std::vector<Light> point = {shadowed(Light::Type::point, 8192)};
    EXPECT_TRUE(dsr::shadow_budget_use(point, 8).over);
    EXPECT_FALSE(dsr::shadow_budget_use(point, 4, 16384).over);
}

TEST(ShadowBudget, RefusalText) {
    EXPECT_EQ(dsr::shadow_budget_text(shadowed(Light::Type::point, 8192), 0, 8),
              "shadow maps within the budget of 1073741824 bytes (1 GiB), got a point light's 6 faces of 8192 x 8192 "
              "texels (3221225472 bytes at 8 a texel) after 0 bytes");
    EXPECT_EQ(dsr::shadow_budget_text(shadowed(Light::Type::spot, 8192), 5, 4, 4096),
              "shadow maps within the budget of 1073741824 bytes (1 GiB), got a spot light's map of 4096 x 4096 "
              "texels (67108864 bytes at 4 a texel) after 5 bytes");
}

// A scene file's light lines are counted as they are read, at 8 bytes a texel, and the first
// over the budget is named by its line.
TEST(ShadowBudget, SceneFileNamesTheLine) {
    std::string text = kHead;
    for (int i = 0; i < 8; ++i) text += "light spot pos 0 3 0 dir 0 -1 0 color 1 1 1 radius 9 angle 40 shadow size 4096\n";
    EXPECT_EQ(parse_error(text), "");
    text += "light point pos 0 3 0 color 1 1 1 radius 9\n";  // no map: not counted
    EXPECT_EQ(parse_error(text), "");
    text += "light directional dir 0 -1 0 color 1 1 1 shadow size 64\n";
    EXPECT_EQ(parse_error(text),
              "a.scene:13: expected shadow maps within the budget of 1073741824 bytes (1 GiB), got a directional "
              "light's map of 64 x 64 texels (32768 bytes at 8 a texel) after 1073741824 bytes");
    EXPECT_EQ(parse_error(std::string(kHead) + "light point pos 0 3 0 color 1 1 1 radius 9 shadow size 8192\n"),
              "a.scene:4: expected shadow maps within the budget of 1073741824 bytes (1 GiB), got a point light's "
              "6 faces of 8192 x 8192 texels (3221225472 bytes at 8 a texel) after 0 bytes");
}
