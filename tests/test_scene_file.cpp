// Scene-file parser: every kind of mistake gives "FILE:LINE: expected ..., got '...'" with the
// right line, and the shipped scenes parse into something the renderer can draw.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "dsr_error.h"
#include "scene/scene.h"

namespace {

// A fresh temp folder per test, removed afterwards; bad scene files never go into the repo.
class SceneFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        char tmpl[] = "/tmp/dsr_scene_test_XXXXXX";
        ASSERT_NE(mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
    }
    void TearDown() override {
        for (const std::string& f : files_) std::remove(f.c_str());
        rmdir(dir_.c_str());
    }

    std::string write(const std::string& name, const std::string& text) {
        const std::string path = dir_ + "/" + name;
        std::ofstream(path) << text;
        files_.push_back(path);
        return path;
    }

    // Lines 1-2: a valid camera and material; tests append their bad line as line 3 or later.
    static std::string header() {
        return "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 50\n"
               "material grey diffuse 0.5 0.5 0.5 specular 0 0 0 shininess 8\n";
    }

    // Loads `text` and returns the error message, failing the test if nothing was thrown.
    std::string error_of(const std::string& text, std::string* path_out = nullptr) {
        const std::string path = write("bad.scene", text);
        if (path_out) *path_out = path;
        try {
            dsr::load_scene(path);
        } catch (const dsr::Error& e) {
            return e.what();
        }
        ADD_FAILURE() << "no error for:\n" << text;
        return "";
    }

    // The message starts with FILE:LINE: and contains every one of `parts`.
    void expect_error(const std::string& text, int line, std::initializer_list<std::string> parts) {
        std::string path;
        const std::string msg = error_of(text, &path);
        const std::string where = path + ":" + std::to_string(line) + ": ";
        EXPECT_EQ(msg.rfind(where, 0), 0u) << "message: " << msg << "\nwanted prefix: " << where;
        for (const std::string& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "message: " << msg << "\nwanted: " << p;
    }

    std::string dir_;
    std::vector<std::string> files_;
};

TEST_F(SceneFileTest, UnknownDirective) {
    expect_error(header() + "\n# a comment line\nteapot size 1\n", 5, {"expected a directive", "got 'teapot'"});
}

TEST_F(SceneFileTest, MissingToken) {
    // sphere radius needs a number; the line ends after "radius".
    expect_error(header() + "sphere at 0 0 0 material grey radius\n", 3,
                 {"expected a number for sphere radius", "got end of line"});
    // A required keyword left out entirely.
    expect_error(header() + "light point pos 0 1 0 color 1 1 1\n", 3, {"expected radius", "got end of line"});
}

TEST_F(SceneFileTest, ExtraToken) {
    expect_error(header() + "ambient 0.1 0.1 0.1 0.5\n", 3, {"expected end of line", "got '0.5'"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 radius 3 7\n", 3,
                 {"expected one of pos, color, radius", "got '7'"});
}

TEST_F(SceneFileTest, Markers) {
    const std::string p = write("markers.scene", header() + "markers box 0.125\n");
    const dsr::Scene s = dsr::load_scene(p);
    EXPECT_EQ(s.marker_shape, dsr::Scene::MarkerShape::box);
    EXPECT_FLOAT_EQ(s.marker_size, 0.125f);
    EXPECT_EQ(dsr::load_scene(write("m2.scene", header() + "markers box 2\nmarkers sphere\n")).marker_shape,
              dsr::Scene::MarkerShape::sphere);
    expect_error(header() + "markers box\n", 3, {"expected a number for markers box half-size", "got end of line"});
    expect_error(header() + "markers box -1\n", 3, {"expected markers box half-size > 0", "got '-1'"});
    expect_error(header() + "markers cone\n", 3, {"expected one of sphere, box", "got 'cone'"});
    expect_error(header() + "markers sphere 3\n", 3, {"expected end of line", "got '3'"});
}

TEST_F(SceneFileTest, BadNumber) {
    expect_error(header() + "sphere radius 1.5x at 0 0 0 material grey\n", 3,
                 {"expected a number for sphere radius", "got '1.5x'"});
    expect_error(header() + "light point pos 0 one 0 color 1 1 1 radius 3\n", 3,
                 {"expected a number for light pos", "got 'one'"});
}

TEST_F(SceneFileTest, NonFiniteNumber) {
    expect_error(header() + "light point pos 0 nan 0 color 1 1 1 radius 3\n", 3,
                 {"expected a finite number for light pos", "got 'nan'"});
    expect_error(header() + "background inf 0 0\n", 3, {"expected a finite number for background", "got 'inf'"});
    // Finite as a double would still overflow a float: refused too.
    expect_error(header() + "ambient 1e999 0 0\n", 3, {"expected a finite number for ambient", "got '1e999'"});
    expect_error(header() + "ambient 1e39 0 0\n", 3, {"expected a finite number for ambient", "got '1e39'"});
}

TEST_F(SceneFileTest, NegativeRadius) {
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 radius -2\n", 3, {"expected light radius > 0", "got '-2'"});
    expect_error(header() + "sphere radius 0 at 0 0 0 material grey\n", 3, {"expected sphere radius > 0", "got '0'"});
}

TEST_F(SceneFileTest, OutOfRangeValues) {
    expect_error(header() + "light point pos 0 1 0 color 1 -1 1 radius 2\n", 3,
                 {"expected light color component >= 0", "got '-1'"});
    expect_error(header() + "material m diffuse 1 1 1 specular 1 1 1 shininess 4096\n", 3,
                 {"expected shininess in [1, 2048]", "got '4096'"});
    expect_error(header() + "material m diffuse 1 1 1 specular 1 1 1 shininess 8 tile 0\n", 3,
                 {"expected tile > 0", "got '0'"});
    expect_error("camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 180 near 0.1 far 50\n", 1,
                 {"expected fov in (0, 180)", "got '180'"});
    expect_error("camera pos 0 5 0 target 0 0 0 up 0 2 0 fov 60 near 0.1 far 50\n", 1,
                 {"expected camera up not parallel", "got '0 2 0'"});
}

TEST_F(SceneFileTest, NearNotBelowFar) {
    expect_error("# comment\ncamera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 10 far 10\n", 2,
                 {"expected far > near", "got '10'"});
    // Keywords in another order: near given after far.
    expect_error("camera far 5 pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 6\n", 1, {"expected near < far", "got '6'"});
    expect_error("camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0 far 10\n", 1, {"expected near > 0", "got '0'"});
}

TEST_F(SceneFileTest, UnknownMaterial) {
    expect_error(header() + "plane size 4 at 0 0 0 material gold\n", 3,
                 {"expected a material defined on an earlier line", "got 'gold'"});
    // Defined later does not count.
    expect_error(header() + "box size 1 1 1 at 0 0 0 material late\n"
                            "material late diffuse 1 1 1 specular 0 0 0 shininess 2\n",
                 3, {"got 'late'"});
}

TEST_F(SceneFileTest, DuplicateMaterial) {
    expect_error(header() + "\nmaterial grey diffuse 1 1 1 specular 0 0 0 shininess 2\n", 4,
                 {"expected a material name not used before (first defined on line 2)", "got 'grey'"});
}

TEST_F(SceneFileTest, MissingCamera) {
    std::string path;
    const std::string msg = error_of("ambient 0.1 0.1 0.1\nlight point pos 0 1 0 color 1 1 1 radius 2\n", &path);
    EXPECT_EQ(msg, path + ": no camera line");
}

TEST_F(SceneFileTest, DuplicateCamera) {
    expect_error(header() + "ambient 0.1 0.1 0.1\ncamera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 50\n", 4,
                 {"expected one camera line (the first is line 1)", "got 'camera'"});
}

TEST_F(SceneFileTest, DuplicateKeyword) {
    expect_error(header() + "sphere radius 1 radius 2 at 0 0 0 material grey\n", 3, {"at most once", "got 'radius'"});
}

TEST_F(SceneFileTest, MissingTextureFile) {
    std::string path;
    const std::string msg = error_of(header() + "material bricks diffuse 1 1 1 specular 0 0 0 shininess 8 "
                                                "diffuse_map no_such_dir/missing.png\n",
                                     &path);
    // Names the scene file and line, the path as written and the path as resolved.
    EXPECT_EQ(msg.rfind(path + ":3: ", 0), 0u) << msg;
    EXPECT_NE(msg.find("expected a readable image for diffuse_map, got 'no_such_dir/missing.png'"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find(dir_ + "/no_such_dir/missing.png"), std::string::npos) << msg;
}

TEST_F(SceneFileTest, UnopenableSceneFile) {
    const std::string path = dir_ + "/does_not_exist.scene";
    try {
        dsr::load_scene(path);
        FAIL() << "no error";
    } catch (const dsr::Error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot open scene file " + path + ": No such file or directory");
    }
}

TEST_F(SceneFileTest, CommentsOrderAndDefaults) {
    const std::string path = write("ok.scene",
                                   "   # leading comment\r\n"
                                   "camera fov 45 near 0.5 far 20 up 0 1 0 target 0 0 0 pos 0 2 4  # any order\n"
                                   "\n"
                                   "material m specular 1 1 1 diffuse 0.2 0.3 0.4 shininess 2048 tile 2.5\n"
                                   "sphere material m at 1 2 3 radius 0.5\n"
                                   "light point radius 2 color 1 0 0 pos 0 1 0\n"
                                   "post aa\n");
    const dsr::Scene s = dsr::load_scene(path);
    EXPECT_EQ(s.path, path);
    EXPECT_FLOAT_EQ(s.camera.fov_deg, 45);
    EXPECT_FLOAT_EQ(s.camera.near_plane, 0.5f);
    EXPECT_FLOAT_EQ(s.camera.far_plane, 20);
    EXPECT_EQ(s.camera.pos, glm::vec3(0, 2, 4));
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].name, "m");
    EXPECT_EQ(s.materials[0].diffuse, glm::vec3(0.2f, 0.3f, 0.4f));
    EXPECT_FLOAT_EQ(s.materials[0].shininess, 2048);
    EXPECT_FLOAT_EQ(s.materials[0].tile, 2.5f);
    EXPECT_EQ(s.materials[0].normal_map, -1);
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_FLOAT_EQ(s.lights[0].radius, 2);
    EXPECT_FALSE(s.post_bloom);
    EXPECT_TRUE(s.post_aa);
}

// Checks a loaded scene is drawable: indices in range, materials and maps valid.
void expect_drawable(const dsr::Scene& s) {
    for (const dsr::Mesh& m : s.meshes) {
        ASSERT_FALSE(m.indices.empty());
        EXPECT_EQ(m.indices.size() % 3, 0u);
        for (uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
        ASSERT_GE(m.material, 0);
        ASSERT_LT(m.material, int(s.materials.size()));
    }
    for (const dsr::Object& o : s.objects) {
        ASSERT_LT(o.mesh, s.meshes.size());
        ASSERT_GE(o.material, 0);
        ASSERT_LT(o.material, int(s.materials.size()));
    }
    ASSERT_EQ(s.textures.size(), s.texture_paths.size());
    for (const dsr::Material& mat : s.materials)
        for (int t : {mat.diffuse_map, mat.normal_map, mat.specular_map}) {
            ASSERT_GE(t, -1);
            ASSERT_LT(t, int(s.textures.size()));
        }
    for (const dsr::Image& img : s.textures) {
        EXPECT_GT(img.width, 0);
        EXPECT_EQ(img.rgba.size(), size_t(img.width) * img.height * 4);
    }
}

TEST(ShippedScenes, DefaultSceneParses) {
    const dsr::Scene s = dsr::load_scene(std::string(DSR_SOURCE_DIR) + "/data/default.scene");
    expect_drawable(s);
    EXPECT_GE(s.lights.size(), 3u);
    int normal_mapped = 0;
    for (const dsr::Material& m : s.materials) normal_mapped += m.normal_map >= 0;
    EXPECT_GE(normal_mapped, 2);
    // Textures are shared by path: each file loaded once.
    for (size_t i = 0; i < s.texture_paths.size(); ++i)
        for (size_t j = i + 1; j < s.texture_paths.size(); ++j) EXPECT_NE(s.texture_paths[i], s.texture_paths[j]);
    EXPECT_EQ(s.textures.size(), 9u);
}

TEST(ShippedScenes, AnalyticSceneParses) {
    const dsr::Scene s = dsr::load_scene(std::string(DSR_SOURCE_DIR) + "/tests/data/analytic.scene");
    expect_drawable(s);
    EXPECT_EQ(s.lights.size(), 2u);
    EXPECT_TRUE(s.textures.empty());
}

TEST_F(SceneFileTest, TexturesDeduplicatedByResolvedPath) {
    // The same file named two ways resolves to one texture.
    const std::string src = std::string(DSR_SOURCE_DIR) + "/data/textures/brick_normal.png";
    const std::string text = "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 50\n"
                             "material a diffuse 1 1 1 specular 0 0 0 shininess 8 normal_map " + src + "\n"
                             "material b diffuse 1 1 1 specular 0 0 0 shininess 8 diffuse_map " +
                             std::string(DSR_SOURCE_DIR) + "/data/./textures/../textures/brick_normal.png\n";
    const dsr::Scene s = dsr::load_scene(write("dedup.scene", text));
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.materials[0].normal_map, 0);
    EXPECT_EQ(s.materials[1].diffuse_map, 0);
}

// What the file is made of: a byte-order mark is skipped, a lone CR ends a line as LF does, a
// control byte is refused with its line and column, and a long token is echoed cut.
TEST_F(SceneFileTest, TextRulesOfTheUserFileReader) {
    const std::string plain = header() + "sphere radius 1 at 0 0 0 material grey\n";
    const dsr::Scene a = dsr::load_scene(write("plain.scene", plain));
    const dsr::Scene b = dsr::load_scene(write("bom.scene", "\xEF\xBB\xBF" + plain));
    std::string cr = plain;
    for (char& c : cr)
        if (c == '\n') c = '\r';
    const dsr::Scene c = dsr::load_scene(write("cr.scene", cr));
    EXPECT_EQ(a.objects.size(), b.objects.size());
    EXPECT_EQ(a.objects.size(), c.objects.size());
    EXPECT_EQ(b.materials[0].name, "grey");
    expect_error(header() + "ambient 0.1 0.\x1b 0.1\n", 3, {"expected text, got the control byte 0x1B at column 15"});
    expect_error(header() + std::string("ambient 0.1 0.1 0.1 #\0\n", 23), 3, {"expected text, got a NUL byte at column 22"});
    std::string path;
    const std::string msg = error_of(header() + "ambient " + std::string(100000, '7') + " 0 0\n", &path);
    EXPECT_EQ(msg, path + ":3: expected a number for ambient, got '" + std::string(60, '7') + "...'");
    // The same rules for text given in memory.
    EXPECT_THROW(dsr::parse_scene("mem.scene", header() + std::string("\0", 1)), dsr::Error);
    EXPECT_EQ(dsr::parse_scene("mem.scene", "\xEF\xBB\xBF" + plain).objects.size(), a.objects.size());
}

// Every number within +-1e12, far/near at most 1e7, world-space extents within +-1e12: the
// values that failed later inside the renderer ("frustum_planes: degenerate far plane") or drew
// nothing are refused on their line.
TEST_F(SceneFileTest, NumbersWithinTheirDocumentedRanges) {
    const std::string cam = "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 ";
    expect_error(cam + "near 1e-45 far 100\n", 1, {"expected far / near at most 1e7, got 100 / 1.4013e-45"});
    expect_error(cam + "near 1e-30 far 100\n", 1, {"expected far / near at most 1e7, got 100 / 1e-30 = 1e+32"});
    expect_error(cam + "near 0.1 far 1e30\n", 1, {"expected a number for far within +-1e12, got '1e30'"});
    EXPECT_NO_THROW(dsr::parse_scene("ok.scene", cam + "near 0.125 far 1250000\n"));  // 1e7 exactly
    expect_error(cam + "near 0.125 far 1250001\n", 1, {"expected far / near at most 1e7"});
    expect_error(header() + "sphere radius 2e12 at 0 0 0 material grey\n", 3, {"expected a number for sphere radius within +-1e12, got '2e12'"});
    expect_error(header() + "box size 1 1 1 at 0 0 -1e13 material grey\n", 3, {"expected a number for box at within +-1e12, got '-1e13'"});
    expect_error(header() + "box size 1e12 1 1 at 6e11 0 0 material grey\n", 3, {"expected box within +-1e12 in world space, got a vertex at 1.1e+12"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 attenuation 1e-6 0 1e-24\n", 3, {"expected attenuation whose radius"});
    expect_error(header() + "light spot pos 0 1 0 dir 0 -1e-20 0 color 1 1 1 radius 2 angle 30\n", 3, {"expected a non-zero light dir"});
    EXPECT_NO_THROW(dsr::parse_scene("ok.scene", header() + "sphere radius 1e12 at 0 0 0 material grey\n"));
}

// The files a scene was read from, for the commands to keep their outputs off them.
TEST_F(SceneFileTest, InputsListEveryFileRead) {
    write("m.mtl", "newmtl a\nmap_Kd t.png\n");
    dsr::Image img;
    img.width = img.height = 2;
    img.rgba.assign(16, 0.5f);
    dsr::write_image(dir_ + "/t.png", img);
    files_.push_back(dir_ + "/t.png");
    write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl a\nf 1/1 2/1 3/1\n");
    const std::string scene = write("s.scene", header() + "mesh m.obj\nmaterial t diffuse 1 1 1 specular 0 0 0 shininess 2 diffuse_map t.png\n");
    const dsr::Scene s = dsr::load_scene(scene);
    EXPECT_EQ(s.inputs, (std::vector<std::string>{scene, dir_ + "/m.obj", dir_ + "/m.mtl", dir_ + "/t.png"}));
    EXPECT_EQ(s.textures.size(), 1u) << "one file, one texture";
}

// A triangle far larger than the camera's distance to it loses precision in the rasteriser: legal,
// one warning naming the line; the shipped scenes have none.
TEST_F(SceneFileTest, HugeTrianglesNearTheCameraAreWarnedAbout) {
    const dsr::Scene s = dsr::parse_scene("w.scene", header() + "plane size 1e6 at 0 0 0 material grey\n");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0].rfind("w.scene:3: triangles 1.41421e+06 long, ", 0), 0u) << s.warnings[0];
    EXPECT_TRUE(dsr::parse_scene("w.scene", header() + "plane size 1e4 at 0 0 0 material grey\n").warnings.empty());
    for (const char* f : {"/data/default.scene", "/data/lights.scene", "/data/mesh.scene", "/data/transparency.scene",
                          "/tests/data/analytic.scene"})
        EXPECT_TRUE(dsr::load_scene(std::string(DSR_SOURCE_DIR) + f).warnings.empty()) << f;
}

}  // namespace

namespace {

class LightLines : public SceneFileTest {};

// The light syntax of docs/light_geometry.md: spot, directional, attenuation; the laws' fields land in Light.
TEST_F(LightLines, SpotDirectionalAttenuation) {
    const std::string path = write("lights.scene",
                                   header() +
                                       "light spot pos 0 3 0 dir 0 -2 0 color 1 1 1 radius 5 angle 30 exponent 4\n"
                                       "light directional dir 0 0 -3 color 0.2 0.2 0.3\n"
                                       "light point pos 1 1 1 color 1 0.5 0.5 attenuation 1 0.7 1.8\n"
                                       "light point pos 1 1 1 color 1 1 1 attenuation 1 0.7 1.8 threshold 0.05\n"
                                       "light spot angle 90 dir 1 0 0 color 1 1 1 attenuation 1 0 1 pos 0 0 0\n");
    const dsr::Scene s = dsr::load_scene(path);
    ASSERT_EQ(s.lights.size(), 5u);
    EXPECT_EQ(s.lights[0].type, dsr::Light::Type::spot);
    EXPECT_EQ(s.lights[0].dir, glm::vec3(0, -1, 0));  // normalised
    EXPECT_FLOAT_EQ(s.lights[0].angle_deg, 30);
    EXPECT_FLOAT_EQ(s.lights[0].exponent, 4);
    EXPECT_FALSE(s.lights[0].attenuation);
    EXPECT_EQ(s.lights[1].type, dsr::Light::Type::directional);
    EXPECT_EQ(s.lights[1].dir, glm::vec3(0, 0, -1));
    EXPECT_TRUE(s.lights[2].attenuation);
    EXPECT_FLOAT_EQ(s.lights[2].threshold, 5.0f / 256.0f);
    // Radius where I_max / (1 + 0.7 d + 1.8 d^2) = T: the law there equals I_max / T.
    for (int i : {2, 3}) {
        const dsr::Light& l = s.lights[size_t(i)];
        const double d = l.radius;
        EXPECT_NEAR((1 + 0.7 * d + 1.8 * d * d) * l.threshold, 1.0, 1e-5) << i;
    }
    EXPECT_LT(s.lights[3].radius, s.lights[2].radius);
    EXPECT_NEAR(s.lights[4].radius, std::sqrt(256.0 / 5 - 1), 1e-4);
}

TEST_F(LightLines, BadValuesNameTheLine) {
    const std::string spot = "light spot pos 0 3 0 dir 0 -1 0 color 1 1 1 radius 5 ";
    expect_error(header() + spot + "angle 0\n", 3, {"expected spot angle in (0, 90] degrees", "got '0'"});
    expect_error(header() + spot + "angle 90.5\n", 3, {"expected spot angle in (0, 90] degrees", "got '90.5'"});
    expect_error(header() + spot + "angle 30 exponent -1\n", 3, {"expected spot exponent >= 0", "got '-1'"});
    expect_error(header() + "light spot pos 0 3 0 dir 0 0 0 color 1 1 1 radius 5 angle 30\n", 3,
                 {"expected a non-zero light dir", "got '0'"});
    expect_error(header() + "light spot pos 0 3 0 dir 0 -1 0 color 1 1 1 radius 5\n", 3,
                 {"expected angle", "got end of line"});
    expect_error(header() + "light spot pos 0 3 0 dir 0 -1 0 color 1 1 1 angle 20\n", 3,
                 {"expected radius or attenuation", "got end of line"});
    expect_error(header() + "light directional dir 0 -1 0 color 1 1 1 radius 3\n", 3,
                 {"expected one of dir, color", "got 'radius'"});
    expect_error(header() + "light directional color 1 1 1\n", 3, {"expected dir", "got end of line"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 attenuation 1 -0.7 1.8\n", 3,
                 {"expected attenuation KL >= 0", "got '-0.7'"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 attenuation 0 0.7 1.8\n", 3,
                 {"expected attenuation KC > 0", "got '0'"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 attenuation 1 0 0\n", 3,
                 {"expected attenuation KL or KQ > 0"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 radius 2 attenuation 1 1 1\n", 3,
                 {"expected radius or attenuation, not both", "got 'attenuation'"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 radius 2 threshold 0.1\n", 3,
                 {"expected threshold only with attenuation"});
    expect_error(header() + "light point pos 0 1 0 color 1 1 1 attenuation 1 1 1 threshold 0\n", 3,
                 {"expected attenuation threshold > 0", "got '0'"});
    expect_error(header() + "light point pos 0 1 0 color 0.1 0.1 0.1 attenuation 60 1 1\n", 3,
                 {"expected attenuation under which the light reaches threshold"});
    expect_error(header() + "light area pos 0 1 0\n", 3, {"expected light kind 'point', 'spot' or 'directional'", "got 'area'"});
}

// `shadow [size N] [bias B] [slope S]` on any light: off by default, the defaults of LightShadow
// where not given, the three in any order right after `shadow`.
TEST_F(LightLines, ShadowOnAnyLight) {
    const std::string path = write("shadows.scene",
                                   header() +
                                       "light spot pos 0 3 0 dir 0 -1 0 color 1 1 1 radius 5 angle 30 shadow\n"
                                       "light directional shadow size 2048 bias 0.01 slope 0 dir 0 -1 0 color 1 1 1\n"
                                       "light point pos 0 1 0 color 1 1 1 shadow slope 3 size 64 radius 4\n"
                                       "light point pos 0 1 0 color 1 1 1 radius 4\n");
    const dsr::Scene s = dsr::load_scene(path);
    ASSERT_EQ(s.lights.size(), 4u);
    const dsr::LightShadow d;
    EXPECT_TRUE(s.lights[0].shadow.on);
    EXPECT_EQ(s.lights[0].shadow.size, d.size);
    EXPECT_FLOAT_EQ(s.lights[0].shadow.bias, d.bias);
    EXPECT_FLOAT_EQ(s.lights[0].shadow.slope, d.slope);
    EXPECT_TRUE(s.lights[1].shadow.on);
    EXPECT_EQ(s.lights[1].shadow.size, 2048);
    EXPECT_FLOAT_EQ(s.lights[1].shadow.bias, 0.01f);
    EXPECT_FLOAT_EQ(s.lights[1].shadow.slope, 0.0f);
    EXPECT_EQ(s.lights[1].type, dsr::Light::Type::directional);
    EXPECT_TRUE(s.lights[2].shadow.on);
    EXPECT_EQ(s.lights[2].shadow.size, 64);
    EXPECT_FLOAT_EQ(s.lights[2].shadow.slope, 3.0f);
    EXPECT_FLOAT_EQ(s.lights[2].radius, 4.0f);
    EXPECT_FALSE(s.lights[3].shadow.on);
}

TEST_F(LightLines, BadShadowsNameTheLine) {
    const std::string point = "light point pos 0 1 0 color 1 1 1 radius 4 ";
    expect_error(header() + point + "shadow size 100\n", 3, {"expected shadow size a power of two in [64, 8192]", "got '100'"});
    expect_error(header() + point + "shadow size 32\n", 3, {"expected shadow size a power of two in [64, 8192]", "got '32'"});
    expect_error(header() + point + "shadow size 16384\n", 3, {"expected shadow size a power of two", "got '16384'"});
    expect_error(header() + point + "shadow size 512.5\n", 3, {"expected shadow size a power of two", "got '512.5'"});
    expect_error(header() + point + "shadow size\n", 3, {"expected a number for shadow size", "got end of line"});
    expect_error(header() + point + "shadow bias -0.1\n", 3, {"expected shadow bias >= 0", "got '-0.1'"});
    expect_error(header() + point + "shadow slope -1\n", 3, {"expected shadow slope >= 0", "got '-1'"});
    expect_error(header() + point + "shadow bias 0.1 bias 0.2\n", 3, {"expected each of shadow's size, bias, slope at most once", "got 'bias'"});
    expect_error(header() + point + "shadow shadow\n", 3, {"at most once", "got 'shadow'"});
    expect_error(header() + point + "size 512 shadow\n", 3, {"expected shadow before size", "got 'size'"});
    expect_error(header() + point + "bias 0.1\n", 3, {"expected shadow before bias", "got 'bias'"});
    expect_error(header() + "light point pos 0 1 0 shadow color 1 1 1 slope 2 radius 4\n", 3, {"expected shadow before slope", "got 'slope'"});
    expect_error(header() + point + "shadow size 512 blur 2\n", 3, {"expected one of pos, color", "shadow", "got 'blur'"});
}

}  // namespace
