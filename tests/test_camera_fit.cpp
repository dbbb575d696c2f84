// `camera fit` held to a written camera's rules (scene/framing.cpp apply_camera_fit): a framed
// camera whose far / near passes 1e7 (a field of view near 180 degrees frames from just outside
// the bounding sphere) is refused naming the camera line, before anything renders.
#include <string>

#include <gtest/gtest.h>

#include "dsr_error.h"
#include "scene/scene.h"

namespace {

std::string fit_error(const std::string& camera_line) {
    try {
        dsr::parse_scene("a.scene", "material m diffuse 0.5 0.5 0.5 specular 0 0 0 shininess 2\n" + camera_line +
                                        "\nlight point pos 1 3 2 color 1 1 1 radius 10\nplane size 4 at 0 0 0 material m\n");
    } catch (const dsr::Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(FramingFit, WideFovRefusedByLine) {
    EXPECT_EQ(fit_error("camera fit"), "");
    EXPECT_EQ(fit_error("camera fit fov 170"), "");
    EXPECT_EQ(fit_error("camera fit fov 179.9"), "");  // far / near about 5e6
    const std::string e = fit_error("camera fit fov 179.99");
    EXPECT_EQ(e.rfind("a.scene:2: camera fit: expected far / near at most 1e7, got ", 0), 0u) << e;
    EXPECT_NE(e.find("(fov 179.99 frames the scene from too near: use a smaller fov)"), std::string::npos) << e;
    EXPECT_NE(fit_error("camera fit from 0 1 0 fov 179.999").find("a.scene:2: camera fit: expected far / near"),
              std::string::npos);
}

// What does pass is a camera the renderer takes: far / near within 1e7, near > 0, a view.
TEST(FramingFit, FramedCameraWithinTheWrittenLimits) {
    for (const char* line : {"camera fit", "camera fit fov 1e-3", "camera fit fov 179.9", "camera fit from 0 1 0",
                             "camera fit from 0 -1 0", "camera fit from 1e-20 0 0", "camera fit from 1e12 1e12 1e12"}) {
        dsr::Scene s;
        try {
            s = dsr::parse_scene("a.scene", std::string("material m diffuse 0.5 0.5 0.5 specular 0 0 0 shininess 2\n") + line +
                                                "\nplane size 4 at 0 0 0 material m\n");
        } catch (const dsr::Error& e) {
            ADD_FAILURE() << line << ": " << e.what();
            continue;
        }
        const dsr::Camera& c = s.camera;
        EXPECT_GT(c.near_plane, 0.0f) << line;
        EXPECT_LE(double(c.far_plane), 1e7 * double(c.near_plane)) << line;
        EXPECT_GT(glm::length(c.target - c.pos), 0.0f) << line;
    }
}
