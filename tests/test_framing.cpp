// Framing (scene/framing.h): a model is a scene, `camera fit`, the viewer's reframe, and the
// generated windmill (scene/generated_model.h). Models at extreme scales and offsets are written
// by the tests, rendered headless, and the share of the image they cover is measured.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "deferred/option_table.h"
#include "dsr_error.h"
#include "render_fixture.h"
#include "scene/framing.h"
#include "scene/generated_model.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"

namespace {

using namespace dsr;
namespace fs = std::filesystem;

std::string write_file(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

std::string num(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

// A test model `size` units tall: a cube of side `size` with a square pyramid of the same
// height on it (so it is taller than wide, like most things on a ground), its base centred on
// `at`. No MTL: the loader's default material.
std::string model_obj(double size, glm::dvec3 at) {
    const double h = size / 2;  // cube side and pyramid height, each half the model's height
    std::string s;
    auto v = [&](double x, double y, double z) {
        s += "v " + num(at.x + x) + " " + num(at.y + y) + " " + num(at.z + z) + "\n";
    };
    for (int i = 0; i < 8; ++i) v((i & 1) ? h / 2 : -h / 2, (i & 2) ? h : 0, (i & 4) ? h / 2 : -h / 2);
    v(0, 2 * h, 0);
    // Cube faces, counter-clockwise from outside (1-based: 1 = (-,0,-), 2 = (+,0,-), 3 = (-,h,-) ...).
    s += "f 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\nf 1 5 7 3\nf 2 4 8 6\n";
    s += "f 3 9 4\nf 4 9 8\nf 8 9 7\nf 7 9 3\n";  // the pyramid on the top face
    return s;
}

// Rows (bottom first) holding any pixel more than 3 LSB from `bg`: the covered height as a
// share of the image's height; 0 when nothing but background.
double covered_height(const Image& img, glm::vec3 bg) {
    int lo = img.height, hi = -1;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float* p = img.at(x, y);
            if (std::abs(p[0] - bg.r) > 3.5f / 255 || std::abs(p[1] - bg.g) > 3.5f / 255 || std::abs(p[2] - bg.b) > 3.5f / 255) {
                lo = std::min(lo, y);
                hi = std::max(hi, y);
                break;
            }
        }
    return hi < 0 ? 0.0 : double(hi - lo + 1) / img.height;
}

// The scene without model_scene's ground, so only the model differs from the background.
Scene without_ground(Scene s) {
    std::vector<Object> kept;
    for (const Object& o : s.objects)
        if (s.materials.at(size_t(o.material)).name != kGroundMaterial) kept.push_back(o);
    EXPECT_EQ(kept.size() + 1, s.objects.size()) << "one ground object";
    s.objects = kept;
    return s;
}

class Framing : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::temp_dir(); }
    void TearDown() override { fs::remove_all(dir_); }
    std::string dir_;
};

// The bounding sphere's silhouette, projected with the fitted camera, spans kFitFill of the
// image's smaller dimension: measured by projecting points of the sphere, not by the formula.
TEST(FitCamera, SphereFillsTheDocumentedShare) {
    for (float aspect : {1.0f, 16.0f / 9.0f, 0.5f})
        for (float fov : {20.0f, 45.0f, 90.0f}) {
            SceneBounds b;
            b.centre = {3, -2, 7};
            b.radius = 2.5;
            b.min = b.centre - 1.0, b.max = b.centre + 1.0, b.vertices = 8;
            const Camera c = fit_camera(b, kFitFrom, fov, aspect);
            const glm::dmat4 pv = glm::dmat4(c.projection(aspect)) * c.view_d();
            double max_x = 0, max_y = 0;
            for (int i = 0; i <= 200; ++i)
                for (int j = 0; j < 400; ++j) {
                    const double th = M_PI * i / 200, ph = 2 * M_PI * j / 400;
                    const glm::dvec3 p = b.centre + b.radius * glm::dvec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
                    const glm::dvec4 q = pv * glm::dvec4(p, 1);
                    ASSERT_GT(q.w, 0);
                    max_x = std::max(max_x, std::abs(q.x / q.w));
                    max_y = std::max(max_y, std::abs(q.y / q.w));
                }
            const double fill = aspect >= 1 ? max_y : max_x;  // the smaller dimension
            EXPECT_NEAR(fill, kFitFill, 0.01) << "aspect " << aspect << " fov " << fov;
            EXPECT_LE(std::max(max_x, max_y), 0.95) << "aspect " << aspect << " fov " << fov;
            // near in front of the sphere, far behind it, and a ratio that keeps depth precise.
            const double d = glm::length(glm::dvec3(c.pos) - b.centre);
            EXPECT_LT(c.near_plane, d - b.radius);
            EXPECT_GT(c.far_plane, d + b.radius);
            EXPECT_LT(c.far_plane / c.near_plane, fov > 45 ? 8.0 : 4.5);
            EXPECT_NEAR(glm::dot(glm::normalize(glm::dvec3(c.pos) - b.centre), glm::normalize(glm::dvec3(kFitFrom))), 1.0, 1e-6);
        }
}

TEST(FitCamera, StraightDownHasAnUpVector) {
    SceneBounds b;
    b.radius = 1, b.vertices = 2;
    const Camera c = fit_camera(b, {0, 1, 0}, 45, 1);
    EXPECT_GT(glm::length(glm::cross(glm::normalize(c.target - c.pos), c.up)), 0.5f);
}

// Bounds are every vertex after its object's transform, in double; empty and non-finite ones
// are refused with the reason.
TEST(SceneBounds, TransformedVerticesAndRefusals) {
    Scene s;
    s.materials.push_back(Material{});
    add_box(s, {2, 4, 6}, {10, 20, 30}, 0);
    s.add(make_box({1, 1, 1}, 0), glm::scale(glm::translate(glm::dmat4(1), glm::dvec3(-5e5, 0, 0)), glm::dvec3(2)));
    const SceneBounds b = scene_bounds(s);
    EXPECT_EQ(b.min, glm::dvec3(-5e5 - 1, -1, -1));
    EXPECT_EQ(b.max, glm::dvec3(11, 22, 33));
    EXPECT_EQ(b.centre, 0.5 * (b.min + b.max));
    EXPECT_NEAR(b.radius, glm::length(glm::dvec3(11, 22, 33) - b.centre), 1e-6);
    EXPECT_EQ(unframeable(b), "");

    EXPECT_EQ(unframeable(scene_bounds(Scene{})), "no triangles");
    Scene nan = s;
    nan.meshes[0].vertices[0].pos.x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(unframeable(scene_bounds(nan)), "a coordinate that is not finite");
    Scene inf = s;
    inf.objects[1].model[3][1] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(unframeable(scene_bounds(inf)), "a coordinate that is not finite");
    Scene point = s;
    for (Mesh& m : point.meshes)
        for (Vertex& v : m.vertices) v.pos = glm::vec3(0);
    point.objects.resize(1);
    EXPECT_EQ(unframeable(scene_bounds(point)), "every vertex at one point");
    EXPECT_THROW(apply_camera_fit(nan, CameraFit{}), Error);
}

TEST(SceneBounds, ModelPathsAreObjOrGltfInAnyCase) {
    for (const char* p : {"a.obj", "dir/B.OBJ", "c.Obj", ".obj", "m.gltf", "M.GLB", "d/x.Gltf"}) EXPECT_TRUE(is_model_path(p)) << p;
    for (const char* p : {"a.scene", "obj", "a.obj.scene", "a.objx", "", "a.gltf.scene", "glb"}) EXPECT_FALSE(is_model_path(p)) << p;
}

// `dsr render MODEL.obj`'s scene at 1e-3, 1 and 1e4 units, at the origin and +-1e6 away (and a
// 1e-3 model 1e3 away): rendered headless, the model alone covers 40-90% of the image height,
// and the whole scene (ground and rig) renders with the model lit.
TEST_F(Framing, ModelsOfEveryScaleFillTheImage) {
    struct Case {
        double size;
        glm::dvec3 at;
    };
    const Case cases[] = {{1e-3, {0, 0, 0}}, {1, {0, 0, 0}},      {1e4, {0, 0, 0}},     {1, {1e6, 0, 0}},
                          {1, {-1e6, -1e6, 1e6}}, {1e4, {-1e6, 1e6, -1e6}}, {1e-3, {1e3, -1e3, 1e3}}};
    for (const Case& c : cases) {
        const std::string name = "size " + num(c.size) + " at " + num(c.at.x) + " " + num(c.at.y) + " " + num(c.at.z);
        const std::string path = write_file(dir_ + "/m.obj", model_obj(c.size, c.at));
        const Scene s = load_scene(path);  // the .obj shortcut
        EXPECT_EQ(s.lights.size(), 3u) << name;
        const SceneBounds b = scene_bounds(without_ground(s));
        EXPECT_NEAR(b.max.y - b.min.y, c.size, c.size * 1e-3 + std::abs(c.at.y) * 1e-7) << name;
        const test::RenderResult alone = test::render_scene(without_ground(s), 128, 128, ShaderOptions{});
        const double h = covered_height(alone.image, s.background);
        EXPECT_GE(h, 0.4) << name;
        EXPECT_LE(h, 0.9) << name;
        std::printf("[ framing  ] %s: the model covers %.0f%% of the image height\n", name.c_str(), 100 * h);
        // With the ground: it lies under the model (the image's lowest rows are ground, not
        // background) and the model is lit (its brightest pixel is well over the ambient term).
        const test::RenderResult whole = test::render_scene(s, 128, 128, ShaderOptions{});
        const float* corner = whole.image.at(64, 2);
        EXPECT_GT(std::abs(corner[0] - s.background.r) + std::abs(corner[2] - s.background.b), 0.05f) << name;
        float brightest = 0;
        for (size_t i = 0; i < whole.image.rgba.size(); i += 4) brightest = std::max(brightest, whole.image.rgba[i]);
        EXPECT_GT(brightest, 0.6f) << name;
    }
}

// OBJ coordinates are 32-bit floats: a 1e-3 model 1e6 from the origin is one point before dsr
// sees it, every triangle of zero area, and the loader refuses it as empty, naming the file.
TEST_F(Framing, CollapsedOrDegenerateModelIsRefused) {
    const std::string far = write_file(dir_ + "/far.obj", model_obj(1e-3, {1e6, 1e6, -1e6}));
    try {
        load_scene(far);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), far + ": expected at least one triangle with area, got none: an empty mesh");
    }
    const std::string point = write_file(dir_ + "/point.obj", "v 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\n");
    try {
        load_scene(point);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(point + ": "), std::string::npos) << e.what();
    }
}

TEST_F(Framing, CameraFitFramesWhatTheSceneHolds) {
    // The camera line first: resolved after the meshes and shapes below it are placed.
    write_file(dir_ + "/m.obj", model_obj(2, {0, 0, 0}));
    const std::string text =
        "camera fit from 0 0 1 fov 30\n"
        "material grey diffuse 0.5 0.5 0.5 specular 0 0 0 shininess 8\n"
        "mesh m.obj scale 10 at 100 0 0\n"
        "box size 1 1 1 at 100 -0.5 0 material grey\n";
    const Scene s = parse_scene(dir_ + "/fit.scene", text);
    const SceneBounds b = scene_bounds(s);
    EXPECT_EQ(b.min.y, -1.0);
    EXPECT_EQ(b.max.y, 20.0);
    EXPECT_EQ(s.camera.target, glm::vec3(b.centre));
    EXPECT_FLOAT_EQ(s.camera.fov_deg, 30.0f);
    EXPECT_EQ(glm::normalize(s.camera.pos - s.camera.target), glm::vec3(0, 0, 1));
    const Camera expected = fit_camera(b, {0, 0, 1}, 30, 1);
    EXPECT_EQ(s.camera.pos, expected.pos);
    EXPECT_EQ(s.camera.near_plane, expected.near_plane);
    EXPECT_EQ(s.camera.far_plane, expected.far_plane);
    // Defaults: the documented direction and field of view.
    const Scene d = parse_scene(dir_ + "/fit.scene", "camera fit\nmesh m.obj\n");
    EXPECT_FLOAT_EQ(d.camera.fov_deg, kFitFovDeg);
    EXPECT_NEAR(glm::dot(glm::normalize(d.camera.pos - d.camera.target), glm::normalize(kFitFrom)), 1.0f, 1e-6f);
}

TEST_F(Framing, CameraFitErrorsNameFileAndLine) {
    write_file(dir_ + "/m.obj", model_obj(1, {0, 0, 0}));
    const std::string f = dir_ + "/bad.scene";
    const std::pair<std::string, std::string> bad[] = {
        {"camera fit\n", f + ":1: camera fit: expected something to frame, got no triangles"},
        {"mesh m.obj\ncamera fit from 0 0 0\n", f + ":2: expected a non-zero direction for camera fit from, got '0'"},
        {"mesh m.obj\ncamera fit fov 180\n", f + ":2: expected fov in (0, 180) degrees, got '180'"},
        {"mesh m.obj\ncamera fit from 1 1\n", f + ":2: expected a number for camera fit from, got end of line"},
        {"mesh m.obj\ncamera fit near 1\n", f + ":2: expected one of from, fov, got 'near'"},
        {"mesh m.obj\ncamera fit fov 30 fov 40\n", f + ":2: expected each of from, fov at most once, got 'fov'"},
        {"camera fit\ncamera pos 0 0 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 50\n",
         f + ":2: expected one camera line (the first is line 1), got 'camera'"},
    };
    for (const auto& [text, message] : bad) {
        try {
            parse_scene(f, text);
            ADD_FAILURE() << "no error for:\n" << text;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), message) << text;
        }
    }
}

// The viewer's F key: the same view direction and up, the scene framed.
TEST(Reframe, KeepsTheViewDirectionAndFramesTheScene) {
    Scene s;
    s.materials.push_back(Material{});
    add_sphere(s, 3, {50, 0, 0}, 0);
    Camera c;
    c.pos = {0, 10, 0};
    c.target = {0, 10, -1};
    c.up = {0, 1, 0};
    c.fov_deg = 60;
    const Camera r = reframe(s, c, 16.0f / 9.0f);
    const SceneBounds b = scene_bounds(s);
    EXPECT_EQ(r.target, glm::vec3(b.centre));
    EXPECT_NEAR(glm::dot(glm::normalize(r.target - r.pos), glm::vec3(0, 0, -1)), 1.0f, 1e-6f);
    EXPECT_EQ(r.up, c.up);
    EXPECT_EQ(r.fov_deg, 60.0f);
    EXPECT_EQ(r.pos, fit_camera(b, c.pos - c.target, 60, 16.0f / 9.0f).pos);
    EXPECT_EQ(reframe(Scene{}, c, 1).pos, c.pos);  // nothing to frame: unchanged
}

// The generated windmill loads with the OBJ loader exactly as written: five materials, each
// with a diffuse, a normal and a specular map, no statement ignored, and renders as a scene.
TEST_F(Framing, GeneratedModelLoadsAndRenders) {
    const GeneratedModel m = windmill_model();
    const std::string obj = write_model(m, dir_ + "/windmill");
    EXPECT_EQ(obj, dir_ + "/windmill/windmill.obj");
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir_ + "/windmill")) {
        EXPECT_EQ(e.path().filename().string()[0] == '.', false) << "left behind: " << e.path();
        ++files;
    }
    EXPECT_EQ(files, m.files.size());
    EXPECT_EQ(m.files.size(), 2u + 5 * 3);

    const ObjModel model = load_obj(obj);
    EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
    EXPECT_EQ(model.materials.size(), 5u);
    EXPECT_EQ(model.groups.size(), 5u);
    std::set<std::string> names;
    for (const Material& mat : model.materials) {
        names.insert(mat.name);
        EXPECT_GE(mat.diffuse_map, 0) << mat.name;
        EXPECT_GE(mat.normal_map, 0) << mat.name;
        EXPECT_GE(mat.specular_map, 0) << mat.name;
    }
    EXPECT_EQ(names, (std::set<std::string>{"windmill.obj:brick", "windmill.obj:stone", "windmill.obj:metal",
                                            "windmill.obj:shingle", "windmill.obj:wood"}));
    EXPECT_EQ(model.textures.size(), 15u);
    EXPECT_GT(model.triangles, 300u);
    // Taller than wide, standing on y = 0.
    const Scene s = load_scene(obj);
    const SceneBounds b = scene_bounds(without_ground(s));
    EXPECT_NEAR(b.min.y, 0.0, 1e-6);
    EXPECT_GT(b.max.y - b.min.y, b.max.x - b.min.x);

    const test::RenderResult r = test::render_scene(without_ground(s), 128, 128, ShaderOptions{});
    const double h = covered_height(r.image, s.background);
    EXPECT_GE(h, 0.4);
    EXPECT_LE(h, 0.9);
    // Several materials show: many distinct colours among the covered pixels.
    std::set<int> colours;
    for (size_t i = 0; i < r.image.rgba.size(); i += 4)
        colours.insert(int(r.image.rgba[i] * 15) * 256 + int(r.image.rgba[i + 1] * 15) * 16 + int(r.image.rgba[i + 2] * 15));
    EXPECT_GT(colours.size(), 40u);
    // The same bytes every time (the figure regenerates identically).
    const GeneratedModel again = windmill_model();
    ASSERT_EQ(again.files.size(), m.files.size());
    for (size_t i = 0; i < m.files.size(); ++i) {
        EXPECT_EQ(again.files[i].text, m.files[i].text) << m.files[i].name;
        EXPECT_EQ(again.files[i].image.rgba, m.files[i].image.rgba) << m.files[i].name;
    }
}

TEST_F(Framing, WriteModelIntoAFileFailsWholly) {
    const std::string blocker = write_file(dir_ + "/file", "not a folder");
    EXPECT_THROW(write_model(windmill_model(), blocker), Error);
    std::string text;
    std::getline(std::ifstream(blocker), text);
    EXPECT_EQ(text, "not a folder");
}

// The command line: `dsr gen-model DIR`, then `dsr render DIR/windmill.obj` with --stats
// reporting the bounds; a degenerate model is one line naming it, and nothing is written.
TEST_F(Framing, CommandLine) {
    test::RunResult g = test::run("gen-model " + dir_ + "/wm");
    ASSERT_EQ(g.status, 0) << g.output;
    EXPECT_NE(g.output.find("dsr render " + dir_ + "/wm/windmill.obj"), std::string::npos) << g.output;
    test::RunResult r = test::run("render " + dir_ + "/wm/windmill.obj --size 96x96 -o " + dir_ + "/a.png --stats " + dir_ + "/s.json");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(test::exists(dir_ + "/a.png"));
    std::ifstream in(dir_ + "/s.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_TRUE(j.contains("bounds")) << j.dump();
    const Scene s = load_scene(dir_ + "/wm/windmill.obj");
    const SceneBounds b = scene_bounds(s);
    for (int i = 0; i < 3; ++i) {
        EXPECT_DOUBLE_EQ(j["bounds"]["min"][i].get<double>(), b.min[i]);
        EXPECT_DOUBLE_EQ(j["bounds"]["max"][i].get<double>(), b.max[i]);
        EXPECT_DOUBLE_EQ(j["bounds"]["centre"][i].get<double>(), b.centre[i]);
    }
    EXPECT_DOUBLE_EQ(j["bounds"]["radius"].get<double>(), b.radius);
    EXPECT_EQ(j["lights_total"].get<int>(), 3);

    const std::string point = write_file(dir_ + "/Point.OBJ", model_obj(1e-3, {1e6, 1e6, 1e6}));
    r = test::run("render " + point + " -o " + dir_ + "/b.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, point + ": expected at least one triangle with area, got none: an empty mesh\n");
    EXPECT_FALSE(test::exists(dir_ + "/b.png"));
    r = test::run("gen-model");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("expected an output folder"), std::string::npos) << r.output;
}

// The rig's key light casts a shadow, so the model stands on its ground: the ground right under
// the model is darker than with the key's shadow off, and the shadow falls on the side away from
// the key (in the image: left of the model, as the key lights from the front-right).
TEST_F(Framing, KeyLightShadowsTheGround) {
    const std::string path = write_file(dir_ + "/m.obj", model_obj(1, {0, 0, 0}));
    const Scene s = load_scene(path);
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_TRUE(s.lights[0].shadow.on) << "the key";
    EXPECT_FALSE(s.lights[1].shadow.on);
    EXPECT_FALSE(s.lights[2].shadow.on);
    Scene unshadowed = s;
    unshadowed.lights[0].shadow.on = false;
    const Image with = test::render_scene(s, 96, 96, RenderOptions{}.resolved(s)).image;
    const Image without = test::render_scene(unshadowed, 96, 96, RenderOptions{}.resolved(unshadowed)).image;
    int darker = 0;
    for (size_t i = 0; i < with.rgba.size(); i += 4) darker += with.rgba[i] + 2.0f / 255 < without.rgba[i];
    EXPECT_GT(darker, 96 * 96 / 50) << "the shadow darkens at least 2% of the image";
}

// --from picks the side the model is seen from: `back` puts the camera on -Z of the centre, a
// direction X,Y,Z puts it along that direction, the framing's fill unchanged.
TEST_F(Framing, FromPicksTheSide) {
    const std::string path = write_file(dir_ + "/m.obj", model_obj(1, {0, 0, 0}));
    const Scene front = load_scene(path);
    LoadOptions o;
    o.from = glm::vec3(-1, 1, -2);
    const Scene back = load_scene(path, o);
    const glm::vec3 c = front.camera.target;
    EXPECT_GT(front.camera.pos.z, c.z);
    EXPECT_LT(back.camera.pos.z, c.z);
    EXPECT_NEAR(glm::length(front.camera.pos - c), glm::length(back.camera.pos - c), 1e-4f);
    test::RunResult r = test::run("render " + path + " --from back --size 32x32 -o " + dir_ + "/b.png --stats " + dir_ + "/b.json");
    ASSERT_EQ(r.status, 0) << r.output;
    r = test::run("render " + path + " --from 0,1,0 --size 32x32 -o " + dir_ + "/t.png");
    ASSERT_EQ(r.status, 0) << r.output;
}

// --ambient replaces the ambient term; --strict turns the first warning into the error.
TEST_F(Framing, AmbientAndStrict) {
    const std::string path = write_file(dir_ + "/m.obj", model_obj(1, {0, 0, 0}) + "l 1 2\n");
    LoadOptions o;
    o.ambient = glm::vec3(0.5f, 0.25f, 0);
    const Scene s = load_scene(path, o);
    EXPECT_EQ(s.ambient, glm::vec3(0.5f, 0.25f, 0));
    ASSERT_FALSE(s.warnings.empty()) << "the l line is skipped with a warning";
    o.strict = true;
    try {
        load_scene(path, o);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), s.warnings.front() + " (--strict: a warning is an error)");
    }
}

// A model's MTL and textures are inputs of the run like the OBJ: no output may replace them.
TEST_F(Framing, ModelFilesAreInputs) {
    write_file(dir_ + "/m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd t.png\n");
    Image t;
    t.width = t.height = 2;
    t.rgba.assign(16, 1.0f);
    write_image(dir_ + "/t.png", t);
    const std::string path = write_file(dir_ + "/m.obj", "mtllib m.mtl\n" + model_obj(1, {0, 0, 0}) + "usemtl a\nf 1 2 3\n");
    const Scene s = load_scene(path);
    std::set<std::string> in(s.inputs.begin(), s.inputs.end());
    EXPECT_TRUE(in.count(path)) << "the OBJ";
    EXPECT_TRUE(in.count(dir_ + "/m.mtl")) << "its MTL";
    EXPECT_TRUE(in.count(dir_ + "/t.png")) << "its texture";
    const test::RunResult r = test::run("render " + path + " --size 16x16 -o " + dir_ + "/t.png");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("t.png"), std::string::npos) << r.output;
}

// A glTF model as the scene: its first camera and its own lights (with no ambient term, no
// ground), --camera picking another, --from framing it instead, --ambient adding one.
TEST_F(Framing, GltfCamerasAndLights) {
    const float tri[9] = {-1, 0, 0, 1, 0, 0, 0, 2, 0};
    std::ofstream(dir_ + "/t.bin", std::ios::binary).write(reinterpret_cast<const char*>(tri), sizeof tri);
    const std::string gltf = R"({"asset": {"version": "2.0"},
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "color": [1, 0.5, 0.25], "intensity": 20}]}},
      "buffers": [{"uri": "t.bin", "byteLength": 36}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [-1, 0, 0], "max": [1, 2, 0]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 50}},
                  {"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.2}}],
      "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 1, 6]}, {"camera": 1, "translation": [0, 1, -6],
                 "rotation": [0, 1, 0, 0]}, {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 1, 2]}],
      "scenes": [{"nodes": [0, 1, 2, 3]}]})";
    const std::string path = write_file(dir_ + "/m.gltf", gltf);
    const Scene s = load_scene(path);
    EXPECT_NEAR(s.camera.pos.z, 6.0f, 1e-5f) << "the first camera";
    EXPECT_NEAR(s.camera.fov_deg, glm::degrees(0.8f), 1e-3f);
    EXPECT_NEAR(s.camera.far_plane, 50.0f, 1e-4f);
    // The file's near (0.1) raised to half the distance to the model's bounding sphere (centre
    // (0, 1, 0), radius sqrt 2, 6 away): depth precision for what is drawn.
    EXPECT_NEAR(s.camera.near_plane, 0.5f * (6.0f - std::sqrt(2.0f)), 1e-4f);
    ASSERT_EQ(s.lights.size(), 1u) << "the file's light, not the rig";
    EXPECT_NEAR(s.lights[0].pos.z, 2.0f, 1e-5f);
    EXPECT_EQ(s.ambient, glm::vec3(0)) << "glTF has no ambient term";
    for (const Object& o : s.objects) EXPECT_NE(s.materials.at(size_t(o.material)).name, kGroundMaterial) << "no ground";
    LoadOptions o;
    o.camera = 1;
    const Scene second = load_scene(path, o);
    EXPECT_NEAR(second.camera.pos.z, -6.0f, 1e-5f);
    EXPECT_GT(second.camera.target.z, second.camera.pos.z) << "it looks back towards +Z";
    EXPECT_GT(second.camera.far_plane, 6.0f) << "no zfar: the far plane reaches past the model";
    o.camera = 2;
    try {
        load_scene(path, o);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": --camera 2: expected a camera index in 0..1 (the file has 2)");
    }
    LoadOptions from;
    from.from = glm::vec3(0, 0, -1);
    from.ambient = glm::vec3(0.1f);
    const Scene framed = load_scene(path, from);
    EXPECT_LT(framed.camera.pos.z, 0.0f) << "--from frames it instead";
    EXPECT_EQ(framed.ambient, glm::vec3(0.1f));
    const test::RunResult r = test::run("render " + path + " --size 32x32 -o " + dir_ + "/g.png");
    EXPECT_EQ(r.status, 0) << r.output;
}

}  // namespace

