// OBJ/MTL loading (docs/scene-format.md): the loader on small files written here, normals and
// tangent frames against brute force, every kind of bad input as its own case (the message must
// name the file and line), the `mesh` scene directive, and, unless DSR_OBJ_LOADER_ONLY (the
// ASan + UBSan build of the loader, `make test`), renders of each model of the optional local test
// assets (not part of the repository) that is present, and of a generated 1-million-triangle OBJ.
#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "dsr_clock.h"
#include "dsr_error.h"
#include "scene/image.h"
#include "scene/obj_loader.h"
#include "scene/obj_triangulate.h"
#include "scene/scene.h"
#include "scene/tangents.h"

#ifndef DSR_OBJ_LOADER_ONLY
#include "analysis/large_mesh.h"
#include "cli_fixture.h"
#include "deferred/gpu_scene.h"
#include "platform/context.h"
#include "render_fixture.h"
#endif

namespace {

namespace fs = std::filesystem;
using glm::vec2;
using glm::vec3;

// A fresh folder per test under the system temp dir; files written there by name.
class ObjFiles : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("dsr-obj-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string write(const std::string& name, const std::string& text) {
        const std::string p = (dir_ / name).string();
        fs::create_directories(fs::path(p).parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    std::string image(const std::string& name, int w, int h, vec3 colour) {
        dsr::Image img;
        img.width = w;
        img.height = h;
        img.rgba.resize(size_t(w) * h * 4);
        for (size_t i = 0; i < img.rgba.size(); i += 4) {
            img.rgba[i] = colour.r, img.rgba[i + 1] = colour.g, img.rgba[i + 2] = colour.b, img.rgba[i + 3] = 1;
        }
        const std::string p = (dir_ / name).string();
        dsr::write_image(p, img);
        return p;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // The error message of loading `obj` (which must fail).
    std::string obj_error(const std::string& obj) {
        try {
            dsr::load_obj(obj);
        } catch (const dsr::Error& e) {
            return e.what();
        }
        ADD_FAILURE() << "expected an error loading " << obj;
        return "";
    }
    // Writes `text` as bad.obj and returns its error.
    std::string bad_obj(const std::string& text) { return obj_error(write("bad.obj", text)); }
    // How many of the model's warnings hold `part` (the tests expect one).
    static int one_warning(const dsr::ObjModel& m, const std::string& part) {
        int n = 0;
        for (const std::string& w : m.warnings) n += w.find(part) != std::string::npos;
        if (n != 1) {
            std::string all;
            for (const std::string& w : m.warnings) all += "\n  " + w;
            ADD_FAILURE() << "wanted one warning holding '" << part << "', got:" << all;
        }
        return n;
    }

    fs::path dir_;
};

const char* kQuad =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

// ---- the loader on good input ------------------------------------------------------------

TEST_F(ObjFiles, QuadWithMaterialAndMaps) {
    image("red.png", 4, 4, {1, 0, 0});
    image("spec.png", 2, 2, {0.5f, 0.5f, 0.5f});
    write("m.mtl",
          "# comment\nnewmtl shiny\nKd 0.5 0.25 1\nKs 0.2 0.3 0.4\nNs 64\nd 0.75\nKa 1 1 1\nillum 2\n"
          "map_Kd red.png\nmap_Ks spec.png\n");
    const std::string obj = write("q.obj", std::string("mtllib m.mtl\n") + kQuad + "usemtl shiny\nf 1/1 2/2 3/3 4/4 # a quad\n");
    const dsr::ObjModel m = dsr::load_obj(obj);
    ASSERT_EQ(m.groups.size(), 1u);
    EXPECT_EQ(m.triangles, 2u);
    EXPECT_EQ(m.groups[0].vertices.size(), 4u) << "corners shared by hash";
    ASSERT_EQ(m.materials.size(), 1u);
    const dsr::Material& mat = m.materials[0];
    EXPECT_EQ(mat.name, "q.obj:shiny");
    EXPECT_EQ(mat.diffuse, vec3(0.5f, 0.25f, 1));
    EXPECT_EQ(mat.specular, vec3(0.2f, 0.3f, 0.4f));
    EXPECT_FLOAT_EQ(mat.shininess, 64);
    EXPECT_FLOAT_EQ(mat.opacity, 0.75f);
    EXPECT_TRUE(mat.transparent()) << "d below 1: drawn by the forward stage";
    ASSERT_GE(mat.diffuse_map, 0);
    ASSERT_GE(mat.specular_map, 0);
    EXPECT_EQ(m.textures[size_t(mat.diffuse_map)].width, 4);
    EXPECT_EQ(m.texture_paths[size_t(mat.diffuse_map)], path("red.png"));
    EXPECT_EQ(mat.normal_map, -1);
    // Ka and illum are read and ignored, with a warning naming the MTL and line.
    bool warned = false;
    for (const std::string& w : m.warnings) warned = warned || w.find("m.mtl:7: 'Ka' ignored") != std::string::npos;
    EXPECT_TRUE(warned);
    // Computed normal of the CCW quad is +Z; uvs kept.
    for (const dsr::Vertex& v : m.groups[0].vertices) {
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
        EXPECT_NEAR(v.uv.x, v.pos.x, 1e-6f);
        EXPECT_NEAR(v.uv.y, v.pos.y, 1e-6f);
        EXPECT_NEAR(glm::dot(v.tangent, vec3(1, 0, 0)), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(v.binormal, vec3(0, 1, 0)), 1.0f, 1e-6f);
    }
}

TEST_F(ObjFiles, FacesGroupedByMaterialAndTrOpacity) {
    write("m.mtl", "newmtl a\nKd 1 0 0\nTr 0.25\nnewmtl b\nKd 0 1 0\n");
    const std::string obj = write("g.obj", std::string("mtllib m.mtl\n") + kQuad +
                                               "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\nusemtl a\nf 3 2 1\n");
    const dsr::ObjModel m = dsr::load_obj(obj);
    ASSERT_EQ(m.groups.size(), 2u) << "one Mesh per material used (Listing 9)";
    std::map<std::string, size_t> tris;
    for (const dsr::Mesh& g : m.groups) tris[m.materials[size_t(g.material)].name] += g.indices.size() / 3;
    EXPECT_EQ(tris["g.obj:a"], 2u);
    EXPECT_EQ(tris["g.obj:b"], 1u);
    EXPECT_FLOAT_EQ(m.materials[0].opacity, 0.75f) << "Tr is 1 - d";
}

TEST_F(ObjFiles, NegativeIndicesAndPolygonsTriangulated) {
    const std::string obj = write("p.obj",
                                  "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 2 2 0\nv 0 2 0\nv -1 1 0\n"
                                  "f -6 -5 -4 -3 -2 -1\n");
    const dsr::ObjModel m = dsr::load_obj(obj);
    EXPECT_EQ(m.triangles, 4u) << "a hexagon is 4 triangles";
    double area = 0;
    for (const dsr::Mesh& g : m.groups)
        for (size_t i = 0; i < g.indices.size(); i += 3) {
            const vec3 a = g.vertices[g.indices[i]].pos, b = g.vertices[g.indices[i + 1]].pos, c = g.vertices[g.indices[i + 2]].pos;
            const vec3 n = glm::cross(b - a, c - a);
            EXPECT_GT(n.z, 0) << "winding kept";
            area += 0.5 * glm::length(n);
        }
    EXPECT_NEAR(area, 6.0, 1e-5) << "the hexagon covered exactly";
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].name, "p.obj:(default)");
}

// A cube without normals: every corner 90 degrees apart, so every face stays flat (24 vertices).
TEST_F(ObjFiles, CreasesSharperThanTheAngleStayFlat) {
    const std::string obj = write("cube.obj",
                                  "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                                  "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    const dsr::ObjModel m = dsr::load_obj(obj);
    ASSERT_EQ(m.groups.size(), 1u);
    const dsr::Mesh& g = m.groups[0];
    EXPECT_EQ(g.vertices.size(), 24u);
    for (size_t i = 0; i < g.indices.size(); i += 3) {
        const dsr::Vertex &a = g.vertices[g.indices[i]], &b = g.vertices[g.indices[i + 1]], &c = g.vertices[g.indices[i + 2]];
        const vec3 face = glm::normalize(glm::cross(b.pos - a.pos, c.pos - a.pos));
        for (const dsr::Vertex* v : {&a, &b, &c}) EXPECT_NEAR(glm::dot(v->normal, face), 1.0f, 1e-6f);
        EXPECT_GT(glm::dot(face, a.pos), 0) << "outward";
    }
}

// A tessellated sphere without normals or uvs: within the angle, each vertex normal is the
// normalised area-weighted sum of every face around its position (brute force), close to radial.
TEST_F(ObjFiles, SmoothNormalsMatchBruteForce) {
    std::ostringstream o;
    o.precision(9);  // floats round-trip exactly, so positions can be matched below
    const int slices = 24, stacks = 12;
    std::vector<vec3> pos;
    o << "v 0 -1 0\n";
    pos.push_back({0, -1, 0});
    for (int j = 1; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const double th = M_PI * j / stacks, ph = 2 * M_PI * i / slices;
            const vec3 p(float(std::sin(th) * std::cos(ph)), float(-std::cos(th)), float(-std::sin(th) * std::sin(ph)));
            pos.push_back(p);
            o << "v " << p.x << " " << p.y << " " << p.z << "\n";
        }
    o << "v 0 1 0\n";
    pos.push_back({0, 1, 0});
    std::vector<std::array<int, 3>> faces;
    auto id = [&](int j, int i) { return j == 0 ? 1 : j == stacks ? int(pos.size()) : 2 + (j - 1) * slices + (i % slices); };
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const int a = id(j, i), b = id(j, i + 1), c = id(j + 1, i + 1), d = id(j + 1, i);
            if (j != 0) faces.push_back({a, b, c});
            if (j != stacks - 1) faces.push_back({a, c, d});
        }
    for (auto& f : faces) o << "f " << f[0] << " " << f[1] << " " << f[2] << "\n";
    const dsr::ObjModel m = dsr::load_obj(write("s.obj", o.str()));
    ASSERT_EQ(m.groups.size(), 1u);
    const dsr::Mesh& g = m.groups[0];
    EXPECT_EQ(g.vertices.size(), pos.size()) << "one vertex per position on a smooth surface";
    for (const dsr::Vertex& v : g.vertices) {
        glm::dvec3 sum(0);
        for (auto& f : faces) {
            const vec3 &a = pos[size_t(f[0] - 1)], &b = pos[size_t(f[1] - 1)], &c = pos[size_t(f[2] - 1)];
            if (a == v.pos || b == v.pos || c == v.pos) sum += glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));
        }
        const vec3 brute = glm::vec3(glm::normalize(sum));
        EXPECT_GT(glm::dot(v.normal, brute), 1.0f - 1e-5f);
        EXPECT_GT(glm::dot(v.normal, glm::normalize(v.pos)), 0.99f);
        // No uvs: still an orthonormal frame, no NaN.
        EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v.binormal, v.normal), 0.0f, 1e-5f);
    }
}

// ---- compute_tangents ------------------------------------------------------------------------

dsr::Mesh grid(int n, bool mirror_u, float wobble) {
    dsr::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            dsr::Vertex v;
            const float x = float(i) / n, y = float(j) / n;
            v.pos = {x, y, wobble * std::sin(6 * x) * std::cos(5 * y)};
            // normal of z = f(x, y)
            const float fx = wobble * 6 * std::cos(6 * x) * std::cos(5 * y), fy = -wobble * 5 * std::sin(6 * x) * std::sin(5 * y);
            v.normal = glm::normalize(vec3(-fx, -fy, 1));
            v.uv = {mirror_u ? 1 - 2 * x : 2 * x, 3 * y};
            m.vertices.push_back(v);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = b + uint32_t(n + 1), d = a + uint32_t(n + 1);
            for (uint32_t k : {a, b, c, a, c, d}) m.indices.push_back(k);
        }
    return m;
}

// Brute force: per triangle, dP/du and dP/dv from the 2x2 system; each vertex's tangent must
// point along dP/du of its triangles and its binormal along dP/dv, with the frame orthonormal.
void check_frames(const dsr::Mesh& m, float handedness) {
    for (const dsr::Vertex& v : m.vertices) {
        ASSERT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::length(v.binormal), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(v.tangent, v.normal), 0.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(v.binormal, v.normal), 0.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(v.tangent, v.binormal), 0.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(glm::cross(v.tangent, v.binormal), v.normal), handedness, 1e-5f);
    }
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const dsr::Vertex &a = m.vertices[m.indices[i]], &b = m.vertices[m.indices[i + 1]], &c = m.vertices[m.indices[i + 2]];
        const vec3 e1 = b.pos - a.pos, e2 = c.pos - a.pos;
        const vec2 t1 = b.uv - a.uv, t2 = c.uv - a.uv;
        const float det = t1.x * t2.y - t2.x * t1.y;
        const vec3 dpdu = glm::normalize((e1 * t2.y - e2 * t1.y) / det), dpdv = glm::normalize((e2 * t1.x - e1 * t2.x) / det);
        for (const dsr::Vertex* v : {&a, &b, &c}) {
            EXPECT_GT(glm::dot(v->tangent, dpdu), 0.9f);
            EXPECT_GT(glm::dot(v->binormal, dpdv), 0.9f);
        }
    }
}

TEST(Tangents, FollowUVsOrthonormalRightHanded) {
    dsr::Mesh m = grid(12, false, 0.1f);
    dsr::compute_tangents(m);
    check_frames(m, 1.0f);
}

TEST(Tangents, MirroredUVsKeepHandedness) {
    dsr::Mesh m = grid(12, true, 0.1f);
    dsr::compute_tangents(m);
    check_frames(m, -1.0f);
}

TEST(Tangents, DegenerateOrMissingUVsGiveFramesWithoutNaN) {
    for (int kind = 0; kind < 3; ++kind) {
        SCOPED_TRACE(kind);
        dsr::Mesh m = grid(4, false, 0.2f);
        for (size_t i = 0; i < m.vertices.size(); ++i) {
            dsr::Vertex& v = m.vertices[i];
            if (kind == 0) v.uv = {0, 0};                       // no uvs at all
            if (kind == 1) v.uv = {float(i % 5), float(i % 5)};  // collinear uvs: zero uv area
            if (kind == 2) v.uv = {NAN, 0};                      // garbage
        }
        m.vertices[0].normal = vec3(0);  // a zero normal is replaced, not normalised to NaN
        dsr::compute_tangents(m);
        for (const dsr::Vertex& v : m.vertices) {
            for (float f : {v.normal.x, v.normal.y, v.normal.z, v.tangent.x, v.tangent.y, v.tangent.z, v.binormal.x,
                            v.binormal.y, v.binormal.z})
                ASSERT_TRUE(std::isfinite(f));
            EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.0f, 1e-5f);
            EXPECT_NEAR(std::fabs(glm::dot(glm::cross(v.tangent, v.binormal), v.normal)), 1.0f, 1e-5f);
        }
    }
}

// ---- maps -----------------------------------------------------------------------------------

TEST(HeightMaps, RampBecomesTiltedNormalMap) {
    dsr::Image h;
    h.width = 8, h.height = 4;
    h.rgba.resize(size_t(8 * 4 * 4));
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            float* p = h.at(x, y);
            p[0] = p[1] = p[2] = float(x) / 8, p[3] = 1;
        }
    EXPECT_TRUE(dsr::is_greyscale(h));
    const dsr::Image n = dsr::height_to_normal(h, 4.0f);
    EXPECT_FALSE(dsr::is_greyscale(n));
    const float* c = n.at(3, 2);  // interior: dh/dx = 1/8 per texel
    const vec3 d = glm::normalize(vec3(-4.0f / 8, 0, 1)) * 0.5f + 0.5f;
    EXPECT_NEAR(c[0], d.x, 1e-5f);
    EXPECT_NEAR(c[1], d.y, 1e-5f);
    EXPECT_NEAR(c[2], d.z, 1e-5f);
}

TEST_F(ObjFiles, GreyBumpIsConvertedColouredNormIsKept) {
    dsr::Image h;
    h.width = h.height = 4;
    h.rgba.assign(64, 0.5f);
    for (int i = 0; i < 4; ++i) h.at(i, 1)[0] = h.at(i, 1)[1] = h.at(i, 1)[2] = 1.0f;
    dsr::write_image(path("height.png"), h);
    image("nrm.png", 2, 2, {0.5f, 0.5f, 1.0f});
    image("spec.png", 2, 2, {1, 1, 1});
    write("m.mtl", "newmtl a\nKd 1 1 1\nKs 0 0 0\nNs 0\nmap_bump -bm 2.5 height.png\nmap_Ns spec.png\n"
                   "newmtl b\nKd 1 1 1\nnorm nrm.png\n");
    const dsr::ObjModel m = dsr::load_obj(write("b.obj", std::string("mtllib m.mtl\n") + kQuad +
                                                             "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n"));
    ASSERT_EQ(m.materials.size(), 2u);
    const dsr::Material &a = m.materials[0], &b = m.materials[1];
    ASSERT_GE(a.normal_map, 0);
    EXPECT_NE(m.texture_paths[size_t(a.normal_map)].find("(height map, bm 2.5"), std::string::npos);
    EXPECT_FALSE(dsr::is_greyscale(m.textures[size_t(a.normal_map)]));
    ASSERT_GE(a.specular_map, 0) << "map_Ns read as a specular map";
    EXPECT_EQ(a.specular, vec3(1)) << "Ks 0 with a specular map: the map gives the colour";
    EXPECT_FLOAT_EQ(a.shininess, 1.0f) << "Ns 0 clamped to the renderer's minimum";
    ASSERT_GE(b.normal_map, 0);
    EXPECT_EQ(m.texture_paths[size_t(b.normal_map)], path("nrm.png"));
}

// ---- bad input: one case each, the message names file and line ------------------------------

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << "message: " << (msg)

TEST_F(ObjFiles, MissingFile) {
    const std::string e = obj_error(path("nope.obj"));
    EXPECT_HAS(e, path("nope.obj"));
    EXPECT_HAS(e, "No such file or directory");
}

TEST_F(ObjFiles, DirectoryWhereTheObjShouldBe) {
    fs::create_directories(path("dir.obj"));
    const std::string e = obj_error(path("dir.obj"));
    EXPECT_HAS(e, path("dir.obj"));
    EXPECT_HAS(e, "expected a file, got a directory");
}

// An MTL or texture that cannot be read is a warning: the model is drawn with the default
// material, or without the map.
TEST_F(ObjFiles, MissingMtl) {
    const dsr::ObjModel m = dsr::load_obj(write("bad.obj", std::string(kQuad) + "mtllib gone.mtl\nusemtl a\nf 1 2 3\n"));
    EXPECT_EQ(one_warning(m, "bad.obj:9: mtllib 'gone.mtl' cannot be read (cannot open MTL file " + path("gone.mtl") +
                                 ": No such file or directory): its materials are drawn with the default material"),
              1);
    EXPECT_EQ(one_warning(m, "bad.obj:10: material \"a\" is defined in no MTL file: drawn with the default material "
                             "(grey diffuse 0.8, no specular)"),
              1);
    EXPECT_EQ(m.triangles, 1u);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].name, "bad.obj:(default)");
    EXPECT_EQ(m.materials[0].diffuse, vec3(0.8f));
    EXPECT_EQ(m.materials[0].specular, vec3(0));
}

TEST_F(ObjFiles, DirectoryWhereTheMtlShouldBe) {
    fs::create_directories(path("d.mtl"));
    const dsr::ObjModel m = dsr::load_obj(write("bad.obj", "mtllib d.mtl\n" + std::string(kQuad) + "f 1 2 3\n"));
    EXPECT_EQ(one_warning(m, "bad.obj:1: mtllib 'd.mtl' cannot be read ("), 1);
    EXPECT_EQ(one_warning(m, "expected a file, got a directory): its materials are drawn with the default material"), 1);
    EXPECT_EQ(m.triangles, 1u);
    EXPECT_EQ(m.materials.at(0).name, "bad.obj:(default)");
}

TEST_F(ObjFiles, MissingTexture) {
    write("m.mtl", "newmtl a\nKd 1 1 1\n\nmap_Kd missing.png\n");
    const dsr::ObjModel m = dsr::load_obj(write("bad.obj", "mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n"));
    EXPECT_EQ(one_warning(m, "m.mtl:4: map_Kd 'missing.png' cannot be read (cannot open image " + path("missing.png") +
                                 ": No such file or directory): drawn without it"),
              1);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].name, "bad.obj:a");
    EXPECT_EQ(m.materials[0].diffuse_map, -1) << "the map left out: the diffuse colour alone";
    EXPECT_EQ(m.materials[0].diffuse, vec3(1));
    EXPECT_TRUE(m.textures.empty());
}

TEST_F(ObjFiles, DirectoryWhereTheTextureShouldBe) {
    fs::create_directories(path("tex.png"));
    write("m.mtl", "newmtl a\nmap_Kd tex.png\n");
    const dsr::ObjModel m = dsr::load_obj(write("bad.obj", "mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n"));
    EXPECT_EQ(one_warning(m, "m.mtl:2: map_Kd 'tex.png' cannot be read ("), 1);
    EXPECT_EQ(one_warning(m, "got a directory): drawn without it"), 1);
    EXPECT_EQ(m.materials.at(0).diffuse_map, -1);
}

TEST_F(ObjFiles, TruncatedTexture) {
    const std::string png = image("t.png", 64, 64, {0.3f, 0.6f, 0.9f});
    const auto size = fs::file_size(png);
    fs::resize_file(png, size / 2);
    write("m.mtl", "newmtl a\nKd 1 1 1\nmap_Ks t.png\nnewmtl b\nmap_Kd t.png\n");
    const dsr::ObjModel m = dsr::load_obj(
        write("bad.obj", "mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n"));
    EXPECT_EQ(one_warning(m, "m.mtl:3: map_Ks 't.png' cannot be read (cannot read image " + path("t.png")), 1);
    EXPECT_EQ(one_warning(m, "(and 1 more line)"), 1) << "the same kind in the same file: one line, counted";
    EXPECT_EQ(m.materials.at(0).specular_map, -1);
    EXPECT_EQ(m.materials.at(1).diffuse_map, -1);
    EXPECT_EQ(m.triangles, 2u);
}

TEST_F(ObjFiles, UnreadableTexture) {
    write("junk.jpg", "this is not a JPEG at all");
    write("m.mtl", "newmtl a\nnorm junk.jpg\n");
    const dsr::ObjModel m = dsr::load_obj(write("bad.obj", "mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n"));
    EXPECT_EQ(one_warning(m, "m.mtl:2: norm 'junk.jpg' cannot be read (cannot read image " + path("junk.jpg")), 1);
    EXPECT_EQ(m.materials.at(0).normal_map, -1);
}

// A PNG whose header claims 100000 x 100000 pixels: refused before anything is allocated.
TEST_F(ObjFiles, AbsurdTextureSize) {
    auto crc32 = [](const std::string& s) {
        uint32_t c = 0xffffffffu;
        for (unsigned char ch : s) {
            c ^= ch;
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
        }
        return c ^ 0xffffffffu;
    };
    auto be32 = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
    const std::string ihdr = "IHDR" + be32(100000) + be32(100000) + std::string("\x08\x02\x00\x00\x00", 5);
    const std::string idat = "IDAT" + std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
    std::string png = "\x89PNG\r\n\x1a\n";
    png += be32(13) + ihdr + be32(crc32(ihdr));
    png += be32(8) + idat + be32(crc32(idat));
    png += be32(0) + "IEND" + be32(crc32("IEND"));
    write("huge.png", png);
    write("m.mtl", "newmtl a\nmap_Kd huge.png\n");
    const std::string e = bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n");
    EXPECT_HAS(e, "m.mtl:2: expected a readable image for map_Kd, got 'huge.png'");
    EXPECT_HAS(e, "100000");
}

TEST_F(ObjFiles, MalformedVertexLine) {
    EXPECT_HAS(bad_obj("v 1 2 3\nv 1 2\n"), "bad.obj:2: expected 3 coordinates x y z");
    EXPECT_HAS(bad_obj("v 1 x 3\n"), "bad.obj:1: expected a number for a vertex coordinate, got 'x'");
    EXPECT_HAS(bad_obj("v 1 2 3\nvt\n"), "bad.obj:2: expected 1 to 3 texture coordinates");
    EXPECT_HAS(bad_obj("vn 0 0\n"), "bad.obj:1: expected 3 normal components");
    EXPECT_HAS(bad_obj("v 0x10 0 0\n"), "bad.obj:1: expected a number");
}

TEST_F(ObjFiles, MalformedFaceLine) {
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1 2\n"), "bad.obj:9: expected at least 3 corners");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1/1/1/1 2 3\n"), "bad.obj:9: expected a corner v, v/t, v//n or v/t/n, got '1/1/1/1'");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1/ 2 3\n"), "bad.obj:9: expected a corner");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1 2 x\n"), "bad.obj:9: expected an integer vertex index, got 'x'");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 0 1 2\n"), "bad.obj:9: expected a non-zero vertex index");
}

TEST_F(ObjFiles, FaceIndexOutOfRangePositive) {
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1 2 5\n"), "bad.obj:9: vertex index 5 in '5' out of range: expected 1..4");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1/1 2/9 3/3\n"), "bad.obj:9: texture coordinate index 9");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1//1 2//1 3//1\n"), "bad.obj:9: normal index 1");
    // A vertex defined after the face that uses it is out of range too (tinyobjloader would drop it).
    EXPECT_HAS(bad_obj("f 1 2 3\n" + std::string(kQuad)), "bad.obj:1: vertex index 1");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1 2 99999999999999999999\n"), "bad.obj:9: expected an integer vertex index of at most 18 digits");
}

TEST_F(ObjFiles, FaceIndexOutOfRangeNegative) {
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f -1 -2 -5\n"), "bad.obj:9: vertex index -5 in '-5' out of range");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f -1/-1 -2/-2 -3/-9\n"), "bad.obj:9: texture coordinate index -9");
}

TEST_F(ObjFiles, NaNAndInfNumbers) {
    EXPECT_HAS(bad_obj("v nan 0 0\n"), "bad.obj:1: expected a number for a vertex coordinate, got 'nan'");
    EXPECT_HAS(bad_obj("v 0 inf 0\n"), "bad.obj:1: expected a number for a vertex coordinate, got 'inf'");
    EXPECT_HAS(bad_obj("v 0 0 1e999\n"), "bad.obj:1: expected a finite number for a vertex coordinate, got '1e999'");
    EXPECT_HAS(bad_obj("vt NaN 0\n"), "bad.obj:1: expected a number for a texture coordinate");
    write("m.mtl", "newmtl a\nKd nan 0 0\n");
    EXPECT_HAS(bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "f 1 2 3\n"), "m.mtl:2: expected a number for Kd, got 'nan'");
}

TEST_F(ObjFiles, EmptyMeshes) {
    EXPECT_HAS(bad_obj(""), "bad.obj: expected at least one face (f line), got none: an empty mesh");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "# no faces\n"), "got none: only vertices, and dsr draws faces");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "p 1 2\nl 1 2 3\n"), "got none: only points and lines (p, l), and dsr draws faces");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1 1 2\nf 1 2 1\n"), "bad.obj: expected at least one triangle with area");
}

TEST_F(ObjFiles, AbsurdSizes) {
    EXPECT_HAS(bad_obj("v 1e13 0 0\n"), "bad.obj:1: expected a vertex coordinate within +-1e12, got '1e13' (an absurd size)");
    // A face of 300 corners is read (faces have no corner limit but the triangle budget); one of
    // 300 times the same corner has no area.
    std::string f = "f";
    for (int i = 1; i <= 300; ++i) f += " 1";
    EXPECT_HAS(bad_obj(std::string(kQuad) + f + "\n"), "bad.obj: expected at least one triangle with area, got none");
    std::string circle, ring = "f";
    for (int i = 0; i < 300; ++i) {
        circle += "v " + std::to_string(std::cos(2 * M_PI * i / 300)) + " " + std::to_string(std::sin(2 * M_PI * i / 300)) + " 0\n";
        ring += " " + std::to_string(i + 1);
    }
    const dsr::ObjModel m = dsr::load_obj(write("c.obj", circle + ring + "\n"));
    EXPECT_EQ(m.triangles, 298u);
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    // The triangle budget still holds for one face.
    dsr::ObjOptions o;
    o.max_triangles = 100;
    o.budget_note = "a scene's budget";
    try {
        dsr::load_obj(path("c.obj"), o);
        ADD_FAILURE() << "a face over the triangle budget";
    } catch (const dsr::Error& e) {
        EXPECT_HAS(std::string(e.what()), "c.obj:301: more than 100 triangles (a scene's budget)");
    }
}

// Statements dsr does not know are warnings, one line per keyword with its first line and count;
// tinyobjloader never sees them (usemtlx would read as usemtl, t as a tag it allocates for).
TEST_F(ObjFiles, UnknownDirectives) {
    write("m.mtl", "newmtl a\nKd 1 0 0\nKq 1\nKm 0.05\nKq 2\n");
    const dsr::ObjModel m = dsr::load_obj(write("u.obj", "mtllib m.mtl\n" + std::string(kQuad) +
                                                             "bogus 1 2 3\nusemtl a\nusemtlx b\nt x 9/9/9\nbogus\nf 1 2 3\n"));
    EXPECT_EQ(one_warning(m, "u.obj:10: 'bogus' is not an OBJ statement dsr knows (v, vt, vn, f, o, g, s, mtllib, usemtl): "
                             "ignored (and 1 more line)"),
              1);
    EXPECT_EQ(one_warning(m, "u.obj:12: 'usemtlx' is not an OBJ statement dsr knows"), 1);
    EXPECT_EQ(one_warning(m, "u.obj:13: 't' is not an OBJ statement dsr knows"), 1);
    EXPECT_EQ(one_warning(m, "m.mtl:3: 'Kq' is not an MTL statement dsr knows: ignored (and 1 more line)"), 1);
    EXPECT_EQ(one_warning(m, "m.mtl:4: 'Km' is not an MTL statement dsr knows: ignored"), 1);
    EXPECT_EQ(m.triangles, 1u);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].diffuse, vec3(1, 0, 0)) << "usemtl a still holds: usemtlx is not usemtl";
    // A file of nothing dsr knows has no faces.
    EXPECT_HAS(bad_obj("usemtlx a\n"), "bad.obj: expected at least one face (f line), got none: an empty mesh");
    // Past 16 keywords, the rest share one line.
    std::string many;
    for (int i = 0; i < 20; ++i) many += "k" + std::to_string(i) + "\n";
    const dsr::ObjModel n = dsr::load_obj(write("n.obj", many + kQuad + "f 1 2 3\n"));
    EXPECT_EQ(one_warning(n, "n.obj:17: more statements dsr does not know: ignored (and 3 more lines)"), 1);
    EXPECT_EQ(n.warnings.size(), 17u);
}

TEST_F(ObjFiles, MalformedMtlLines) {
    auto mtl_error = [&](const std::string& mtl) {
        write("m.mtl", mtl);
        return bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "f 1 2 3\n");
    };
    EXPECT_HAS(mtl_error("newmtl a\nKd 1 1\n"), "m.mtl:2: expected three numbers r g b (or one) for Kd");
    EXPECT_HAS(mtl_error("newmtl a\nKs 1 -1 1\n"), "m.mtl:2: expected Ks components >= 0, got '-1'");
    EXPECT_HAS(mtl_error("newmtl a\nNs shiny\n"), "m.mtl:2: expected a number for Ns, got 'shiny'");
    EXPECT_HAS(mtl_error("newmtl a\nd 2\n"), "m.mtl:2: expected d in [0, 1], got '2'");
    EXPECT_HAS(mtl_error("newmtl a\nd -halo 0.5\n"), "m.mtl:2: expected one number for d");
    EXPECT_HAS(mtl_error("Kd 1 1 1\n"), "m.mtl:1: expected newmtl before 'Kd'");
    EXPECT_HAS(mtl_error("newmtl a\nnewmtl a\n"), "m.mtl:2: expected a material name not defined before, got 'a' (first defined at");
    EXPECT_HAS(mtl_error("newmtl a\nmap_Kd\n"), "m.mtl:2: expected a texture file name for map_Kd");
    EXPECT_HAS(mtl_error("newmtl a\nmap_Kd -s 1 t.png\n"), "m.mtl:2: expected a number for map_Kd -s, got 't.png'");
    EXPECT_HAS(mtl_error("newmtl a\nbump -zz t.png\n"), "m.mtl:2: expected a texture option");
    EXPECT_HAS(mtl_error("newmtl a\nbump -bm nan t.png\n"), "m.mtl:2: expected a number for bump -bm, got 'nan'");
}

// A usemtl naming no material of the MTLs: the default material, with a warning; an mtllib after
// the usemtl still defines it.
TEST_F(ObjFiles, UnknownMaterial) {
    write("m.mtl", "newmtl a\nKd 0 1 0\n");
    const dsr::ObjModel m = dsr::load_obj(
        write("b.obj", "mtllib m.mtl\n" + std::string(kQuad) + "usemtl b\nf 1 2 3\nusemtl a\nf 1 3 4\nusemtl b\nf 2 3 4\n"));
    EXPECT_EQ(one_warning(m, "b.obj:10: material \"b\" is defined in no MTL file: drawn with the default material (grey "
                             "diffuse 0.8, no specular) (and 1 more line)"),
              1);
    EXPECT_EQ(m.warnings.size(), 1u);
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[1].name, "b.obj:(default)");
    std::map<std::string, size_t> tris;
    for (const dsr::Mesh& g : m.groups) tris[m.materials[size_t(g.material)].name] += g.indices.size() / 3;
    EXPECT_EQ(tris["b.obj:(default)"], 2u);
    EXPECT_EQ(tris["b.obj:a"], 1u);
    const dsr::ObjModel late = dsr::load_obj(write("late.obj", "usemtl a\nmtllib m.mtl\n" + std::string(kQuad) + "f 1 2 3\n"));
    EXPECT_TRUE(late.warnings.empty()) << late.warnings.front();
    ASSERT_EQ(late.groups.size(), 1u);
    EXPECT_EQ(late.materials.at(size_t(late.groups[0].material)).name, "late.obj:a");
}

TEST_F(ObjFiles, NulByte) {
    EXPECT_HAS(bad_obj(std::string("v 0 0 0\nv 1 0\0 0\n", 18)), "bad.obj:2: expected text, got a NUL byte");
}

// `make fuzz` findings become cases here. First run (FUZZ_SECONDS=60 each): obj 461,686
// executions, scene_file 60,744, no crash, leak, timeout or sanitizer report.

// ---- triangulation -----------------------------------------------------------------------------

// Brute force on random simple polygons, convex and concave (star-shaped about a point, at
// random angles and radii), placed on random planes: n-2 triangles, each inside the polygon and
// wound as it is, their areas summing to the polygon's.
TEST(ObjTriangulate, EarClippingMatchesBruteForce) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> uni(0, 1);
    for (int trial = 0; trial < 400; ++trial) {
        const bool convex = trial % 3 == 0;
        const size_t n = 5 + size_t(uni(rng) * (trial < 300 ? 20 : 200));
        // Angles a little jittered around the circle (so the polygon winds once about the origin
        // and is simple), radii random (concave) or 1 (convex).
        std::vector<double> ang(n);
        for (size_t i = 0; i < n; ++i) ang[i] = (double(i) + 0.9 * uni(rng)) * 2 * M_PI / double(n);
        std::vector<glm::dvec2> q(n);
        for (size_t i = 0; i < n; ++i) {
            const double r = convex ? 1.0 : 0.2 + uni(rng);
            q[i] = {r * std::cos(ang[i]), r * std::sin(ang[i])};
        }
        // A random plane, and the polygon wound either way.
        const glm::dvec3 ax = glm::normalize(glm::dvec3(uni(rng) - 0.5, uni(rng) - 0.5, uni(rng) - 0.5));
        const glm::dvec3 ay = glm::normalize(glm::cross(ax, glm::dvec3(uni(rng) - 0.5, uni(rng) - 0.5, uni(rng) - 0.5)));
        const glm::dvec3 origin(uni(rng) * 10, uni(rng) * 10, uni(rng) * 10);
        if (trial % 2) std::reverse(q.begin(), q.end());
        std::vector<glm::dvec3> p(n);
        for (size_t i = 0; i < n; ++i) p[i] = origin + q[i].x * ax + q[i].y * ay;
        double signed_area = 0;
        for (size_t i = 0; i < n; ++i) signed_area += 0.5 * (q[i].x * q[(i + 1) % n].y - q[(i + 1) % n].x * q[i].y);
        const double sign = signed_area > 0 ? 1 : -1;
        auto inside = [&](glm::dvec2 c) {  // even-odd rule
            bool in = false;
            for (size_t i = 0, j = n - 1; i < n; j = i++)
                if ((q[i].y > c.y) != (q[j].y > c.y) && c.x < (q[j].x - q[i].x) * (c.y - q[i].y) / (q[j].y - q[i].y) + q[i].x)
                    in = !in;
            return in;
        };
        std::vector<uint32_t> tris;
        size_t work = 0;
        SCOPED_TRACE("trial " + std::to_string(trial) + ", " + std::to_string(n) + " corners");
        ASSERT_EQ(dsr::obj::triangulate_polygon(p, tris, work), dsr::obj::Polygon::ear_clipped);
        ASSERT_EQ(tris.size(), 3 * (n - 2));
        double area = 0;
        for (size_t t = 0; t < tris.size(); t += 3) {
            const glm::dvec2 a = q[tris[t]], b = q[tris[t + 1]], c = q[tris[t + 2]];
            const double ta = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) * sign;
            ASSERT_GT(ta, 0) << "a triangle wound against the polygon";
            area += ta;
            // Inside: its centroid, and points near each corner towards the centroid.
            const glm::dvec2 cen = (a + b + c) / 3.0;
            ASSERT_TRUE(inside(cen));
            for (glm::dvec2 k : {a, b, c}) ASSERT_TRUE(inside(k + (cen - k) * 1e-3));
        }
        EXPECT_NEAR(area, std::fabs(signed_area), 1e-9 * std::fabs(signed_area));
    }
}

// Past the work budget a polygon is a fan, still of n-2 triangles.
TEST(ObjTriangulate, PastTheBudgetAFan) {
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 40; ++i) {
        const double a = 2 * M_PI * i / 40, r = i % 2 ? 1.0 : 0.5;
        p.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    std::vector<uint32_t> tris;
    size_t work = 0;
    EXPECT_EQ(dsr::obj::triangulate_polygon(p, tris, work), dsr::obj::Polygon::ear_clipped);
    EXPECT_GT(work, 0u);
    tris.clear();
    work = dsr::obj::kMaxEarClipWork;
    EXPECT_EQ(dsr::obj::triangulate_polygon(p, tris, work), dsr::obj::Polygon::fan_over_budget);
    EXPECT_EQ(tris.size(), 3u * 38u);
}

// Quads split as tinyobjloader split them (triangulate=true), so models of quads draw as before:
// tinyobjloader on random quads, convex and not, against triangulate_quad, which differs only on
// concave quads whose shorter diagonal lies outside.
TEST(ObjTriangulate, QuadsSplitAsTinyobjloaderDid) {
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> uni(-1, 1);
    std::ostringstream obj;
    obj.precision(9);
    std::vector<std::array<glm::vec3, 4>> quads(2000);
    for (size_t k = 0; k < quads.size(); ++k) {
        for (glm::vec3& v : quads[k]) {
            v = {uni(rng), uni(rng), k % 2 ? 0.0f : uni(rng) * 0.1f};
            obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
        }
        obj << "f " << 4 * k + 1 << " " << 4 * k + 2 << " " << 4 * k + 3 << " " << 4 * k + 4 << "\n";
    }
    obj << "f 1 2 3\n";
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> mats;
    std::string warn, err;
    std::istringstream in(obj.str());
    ASSERT_TRUE(tinyobj::LoadObj(&attrib, &shapes, &mats, &warn, &err, &in, nullptr, true, false));
    ASSERT_EQ(shapes.size(), 1u);
    const auto& idx = shapes[0].mesh.indices;
    ASSERT_EQ(idx.size(), quads.size() * 6 + 3);
    size_t same = 0, concave_fixed = 0;
    for (size_t k = 0; k < quads.size(); ++k) {
        std::array<glm::vec3, 4> p;  // as tinyobjloader read them
        for (int j = 0; j < 4; ++j)
            p[size_t(j)] = {attrib.vertices[3 * (4 * k + size_t(j))], attrib.vertices[3 * (4 * k + size_t(j)) + 1],
                            attrib.vertices[3 * (4 * k + size_t(j)) + 2]};
        std::vector<uint32_t> mine;
        dsr::obj::triangulate_quad(p, mine);
        bool equal = true;
        for (size_t j = 0; j < 6; ++j) equal = equal && size_t(idx[6 * k + j].vertex_index) == 4 * k + mine[j];
        if (equal) {
            ++same;
            continue;
        }
        // Where they differ, tinyobjloader's split has a triangle wound against the quad.
        const glm::dvec3 n = glm::cross(glm::dvec3(p[2] - p[0]), glm::dvec3(p[3] - p[1]));
        bool flipped = false;
        for (size_t t = 0; t < 6; t += 3) {
            const glm::dvec3 a(p[size_t(idx[6 * k + t].vertex_index) - 4 * k]), b(p[size_t(idx[6 * k + t + 1].vertex_index) - 4 * k]),
                c(p[size_t(idx[6 * k + t + 2].vertex_index) - 4 * k]);
            flipped = flipped || glm::dot(glm::cross(b - a, c - a), n) < 0;
        }
        EXPECT_TRUE(flipped) << "quad " << k;
        ++concave_fixed;
    }
    EXPECT_GT(same, quads.size() * 3 / 4);
    EXPECT_GT(concave_fixed, 0u) << "random quads include concave ones";
    // Triangles are kept as they are.
    for (int j = 0; j < 3; ++j) EXPECT_EQ(idx[quads.size() * 6 + size_t(j)].vertex_index, j);
}

// ---- OBJ and MTL files as exporters write them: read, with a warning per substitution ----------

// Material names are the rest of the line (spaces and all, trimmed); tinyobjloader, which reads
// one token, is handed names it can read.
TEST_F(ObjFiles, MaterialNamesWithSpaces) {
    write("m.mtl", "newmtl my mat  \nKd 1 0 0\nnewmtl my  mat\nKd 0 1 0\nnewmtl my\nKd 0 0 1\nnewmtl m0\nKd 0.5\n");
    const dsr::ObjModel m = dsr::load_obj(write("s.obj", "mtllib m.mtl\n" + std::string(kQuad) +
                                                             "usemtl my mat   \nf 1 2 3\nusemtl my  mat\nf 1 3 4\n"
                                                             "usemtl my\nf 2 3 4\nusemtl m0\nf 1 2 4\n"));
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    ASSERT_EQ(m.materials.size(), 4u);
    EXPECT_EQ(m.materials[0].name, "s.obj:my mat");
    EXPECT_EQ(m.materials[1].name, "s.obj:my  mat");
    EXPECT_EQ(m.materials[2].name, "s.obj:my");
    EXPECT_EQ(m.materials[3].name, "s.obj:m0") << "a name like the tokens handed to tinyobjloader is still itself";
    EXPECT_EQ(m.materials[3].diffuse, vec3(0.5f)) << "one number for Kd is grey";
    ASSERT_EQ(m.groups.size(), 4u);
    for (const dsr::Mesh& g : m.groups) {
        EXPECT_EQ(g.indices.size(), 3u);
        const vec3 want[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5f, 0.5f, 0.5f}};
        EXPECT_EQ(m.materials[size_t(g.material)].diffuse, want[g.material]);
    }
}

// An empty usemtl is the default material, unless an MTL defines the empty name (Blender's
// "newmtl " for a material without a name).
TEST_F(ObjFiles, EmptyUsemtl) {
    const dsr::ObjModel m = dsr::load_obj(write("e.obj", std::string(kQuad) + "usemtl\nf 1 2 3\nusemtl  \nf 1 3 4\n"));
    EXPECT_EQ(one_warning(m, "e.obj:9: usemtl without a material name: drawn with the default material (grey diffuse "
                             "0.8, no specular) (and 1 more line)"),
              1);
    ASSERT_EQ(m.groups.size(), 1u);
    EXPECT_EQ(m.materials.at(size_t(m.groups[0].material)).name, "e.obj:(default)");
    write("n.mtl", "newmtl \nKd 0 0 1\n");
    const dsr::ObjModel n = dsr::load_obj(write("n.obj", "mtllib n.mtl\n" + std::string(kQuad) + "usemtl \nf 1 2 3\n"));
    EXPECT_TRUE(n.warnings.empty()) << n.warnings.front();
    EXPECT_EQ(n.materials.at(size_t(n.groups.at(0).material)).diffuse, vec3(0, 0, 1));
}

// Paths written on Windows: `\` read as `/` in mtllib and map file names, with a warning.
TEST_F(ObjFiles, BackslashesInPaths) {
    fs::create_directories(path("tex"));
    image("tex/red.png", 2, 2, {1, 0, 0});
    write("sub/m.mtl", "newmtl a\nmap_Kd ..\\tex\\red.png\nnewmtl b\nmap_Kd .\\..\\tex\\red.png\n");
    const dsr::ObjModel m =
        dsr::load_obj(write("w.obj", "mtllib .\\sub\\m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n"));
    EXPECT_EQ(one_warning(m, "w.obj:1: '\\' in the file name '.\\sub\\m.mtl' read as '/'"), 1);
    EXPECT_EQ(one_warning(m, "m.mtl:2: '\\' in the file name '..\\tex\\red.png' read as '/' (and 1 more line)"), 1);
    ASSERT_EQ(m.materials.size(), 2u);
    ASSERT_GE(m.materials[0].diffuse_map, 0);
    EXPECT_EQ(m.materials[0].diffuse_map, m.materials[1].diffuse_map) << "one file, read once";
    EXPECT_EQ(m.texture_paths.at(size_t(m.materials[0].diffuse_map)), path("tex/red.png"));
}

// An mtllib naming a file with spaces, or several files.
TEST_F(ObjFiles, MtllibNames) {
    write("my model.mtl", "newmtl a\nKd 1 0 0\n");
    write("b.mtl", "newmtl b\nKd 0 1 0\n");
    const dsr::ObjModel m = dsr::load_obj(write("l.obj", "mtllib my model.mtl\nmtllib b.mtl gone.mtl\n" + std::string(kQuad) +
                                                             "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n"));
    EXPECT_EQ(one_warning(m, "l.obj:2: mtllib 'gone.mtl' cannot be read"), 1);
    EXPECT_EQ(m.warnings.size(), 1u);
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[0].diffuse, vec3(1, 0, 0));
    EXPECT_EQ(m.materials[1].diffuse, vec3(0, 1, 0));
}

std::string utf16(const std::string& ascii_then, bool big_endian, const std::u16string& extra) {
    std::u16string units;
    for (char c : ascii_then) units += char16_t((unsigned char)c);
    units += extra;
    std::string out = big_endian ? "\xFE\xFF" : "\xFF\xFE";
    for (char16_t u : units) {
        const char hi = char(u >> 8), lo = char(u & 0xFF);
        out += big_endian ? std::string{hi, lo} : std::string{lo, hi};
    }
    return out;
}

// UTF-16 (by its byte-order mark) is decoded to UTF-8, with a warning; bad UTF-16 is an error.
TEST_F(ObjFiles, Utf16) {
    for (bool be : {true, false}) {
        SCOPED_TRACE(be ? "big-endian" : "little-endian");
        // A material name with an e acute and a character outside the BMP (a surrogate pair).
        const std::u16string name = u"caf\u00e9 \U0001F600\r\nf 1 2 3\r\n";
        std::map<std::string, std::string> files = {
            {"u.obj", utf16("mtllib u.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nusemtl ", be, name)},
            {"u.mtl", utf16("newmtl ", be, u"caf\u00e9 \U0001F600\nKd 0 1 0\n")}};
        dsr::ObjOptions o;
        o.read_text = [&](const std::string& p) {
            auto it = files.find(fs::path(p).filename().string());
            if (it == files.end()) throw dsr::Error("cannot open " + p);
            return it->second;
        };
        const dsr::ObjModel m = dsr::load_obj("u.obj", o);
        EXPECT_EQ(one_warning(m, std::string("u.obj:1: UTF-16 text (") + (be ? "big" : "little") +
                                     "-endian, by its byte-order mark) read as UTF-8"),
                  1);
        EXPECT_EQ(one_warning(m, "u.mtl:1: UTF-16 text"), 1);
        EXPECT_EQ(m.warnings.size(), 2u);
        ASSERT_EQ(m.materials.size(), 1u);
        EXPECT_EQ(m.materials[0].name, "u.obj:caf\xC3\xA9 \xF0\x9F\x98\x80");
        EXPECT_EQ(m.materials[0].diffuse, vec3(0, 1, 0));
        EXPECT_EQ(m.triangles, 1u);
    }
    EXPECT_HAS(bad_obj(std::string("\xFE\xFF\x00v\x00", 5)), "bad.obj:1: expected UTF-16 text (it begins with a UTF-16 byte-order mark), got an odd number of bytes");
    EXPECT_HAS(bad_obj(std::string("\xFF\xFEv\x00\n\x00\x00\xDC", 8)), "bad.obj:2: expected UTF-16 text (it begins with a UTF-16 byte-order mark), got an unpaired surrogate");
    EXPECT_HAS(bad_obj(std::string("\xFF\xFEv\x00\x00\x00", 6)), "bad.obj:1: expected text, got a NUL byte");
}

// The assimp test corpus's UTF-16 and long-line files, where the package is installed.
TEST_F(ObjFiles, AssimpCorpusFiles) {
    const std::string dir = "/usr/share/assimp/models/OBJ/";
    if (!fs::exists(dir + "box_UTF16BE.obj")) GTEST_SKIP() << "skipped: " << dir << " is absent (Debian assimp-testmodels)";
    const dsr::ObjModel u = dsr::load_obj(dir + "box_UTF16BE.obj");
    EXPECT_EQ(u.triangles, 12u);
    EXPECT_EQ(one_warning(u, "box_UTF16BE.obj:1: UTF-16 text (big-endian"), 1);
    // A face of 936 corners: the square 1 2 3 4 wound 234 times. Ear clipping drops the corners
    // that add no area (each repeat's first corner) and covers the square again and again.
    const dsr::ObjModel l = dsr::load_obj(dir + "box_longline.obj");
    EXPECT_EQ(l.triangles, 478u);
    for (const dsr::Mesh& g : l.groups)
        for (const dsr::Vertex& v : g.vertices) EXPECT_LE(glm::length(v.pos), 0.87f) << "within the box";
    const dsr::ObjModel c = dsr::load_obj(dir + "concave_polygon.obj");
    ASSERT_EQ(c.groups.size(), 1u);
    EXPECT_EQ(c.triangles, 64u) << "66 corners, ear clipped";
    EXPECT_TRUE(c.groups[0].two_sided);
}

// Faces of more than four corners are ear clipped: a concave L covers exactly its area.
TEST_F(ObjFiles, ConcavePolygonsEarClipped) {
    // An L of area 3 (a fan from the first corner would cover the notch), tilted out of every axis plane.
    const glm::dvec3 ex = glm::normalize(glm::dvec3(1, 2, 3)), ey = glm::normalize(glm::dvec3(-2, 1, 0));
    const double pts[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    std::string text;
    for (auto& p : pts) {
        const glm::dvec3 w = p[0] * ex + p[1] * ey;
        char line[128];
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", w.x, w.y, w.z);
        text += line;
    }
    // Starting at the reflex corner (4) so that a fan would go wrong.
    const dsr::ObjModel m = dsr::load_obj(write("l.obj", text + "f 4 5 6 1 2 3\n"));
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    EXPECT_EQ(m.triangles, 4u);
    double area = 0;
    const glm::dvec3 n = glm::normalize(glm::cross(ex, ey));
    for (const dsr::Mesh& g : m.groups)
        for (size_t i = 0; i < g.indices.size(); i += 3) {
            const glm::dvec3 a(g.vertices[g.indices[i]].pos), b(g.vertices[g.indices[i + 1]].pos), c(g.vertices[g.indices[i + 2]].pos);
            const glm::dvec3 tn = glm::cross(b - a, c - a);
            EXPECT_GT(glm::dot(tn, n), 0) << "winding kept";
            area += 0.5 * glm::length(tn);
            // Every triangle inside the L: its centroid is not in the notch [1,2]x[1,2].
            const glm::dvec3 cen = (a + b + c) / 3.0;
            const double x = glm::dot(cen, ex), y = glm::dot(cen, ey);
            EXPECT_FALSE(x > 1 && y > 1) << "a triangle over the notch";
        }
    EXPECT_NEAR(area, 3.0, 1e-5);
}

// A face of collinear corners has no area in any plane: a fan (every triangle without area,
// dropped), with warnings, beside a face that draws.
TEST_F(ObjFiles, DegeneratePolygonFallsBackToAFan) {
    const dsr::ObjModel m = dsr::load_obj(write("d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\nv 0 1 0\n"
                                                         "f 1 2 3 4 5\nf 1 2 6\n"));
    EXPECT_EQ(one_warning(m, "d.obj:7: a face of 5 corners has no area in any plane: drawn as a fan"), 1);
    EXPECT_EQ(one_warning(m, "d.obj:7: triangles without area dropped"), 1);
    EXPECT_EQ(m.triangles, 1u);
    // A hexagon crossing itself, where ear clipping finds no ear after the first: the rest a fan.
    const dsr::ObjModel x = dsr::load_obj(write("x.obj", "v 2 4 0\nv 7 2 0\nv 1 0 0\nv 4 4 0\nv 9 0 0\nv 2 9 0\nf 1 2 3 4 5 6\n"));
    EXPECT_EQ(one_warning(x, "x.obj:7: a face of 6 corners crosses itself (ear clipping found no ear): the rest drawn as a fan"), 1);
    EXPECT_EQ(x.triangles, 4u);
}

// Per-vertex colours (v x y z r g b): Mesh::colors parallel to the vertices, alpha 1, only in
// groups whose vertices have colours; corners of different colour never share a vertex.
TEST_F(ObjFiles, VertexColours) {
    write("m.mtl", "newmtl a\nnewmtl b\n");
    const dsr::ObjModel m = dsr::load_obj(write(
        "c.obj", "mtllib m.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 0.5 0.5 0.5\n"
                 "v 0 0 0 0 1 1\nv 5 5 5 1 1 1 0.5\n"
                 "usemtl a\nf 1 2 3\nf 5 3 4\nusemtl b\nf 1 3 4\n"));
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    ASSERT_EQ(m.groups.size(), 2u);
    for (const dsr::Mesh& g : m.groups) {
        EXPECT_TRUE(g.two_sided) << "OBJ faces are drawn two-sided";
        ASSERT_EQ(g.colors.size(), g.vertices.size());
        for (size_t i = 0; i < g.vertices.size(); ++i) {
            const vec3 p = g.vertices[i].pos;
            const glm::vec4 c = g.colors[i];
            EXPECT_EQ(c.a, 1.0f);
            if (p == vec3(1, 0, 0)) {
                EXPECT_EQ(c, glm::vec4(0, 1, 0, 1));
            } else if (p == vec3(1, 1, 0)) {
                EXPECT_EQ(c, glm::vec4(0, 0, 1, 1));
            } else if (p == vec3(0, 1, 0)) {
                EXPECT_EQ(c, glm::vec4(0.5f, 0.5f, 0.5f, 1));
            }
        }
    }
    // Vertices 1 and 5 share a position and differ in colour: two vertices, one of each colour.
    const dsr::Mesh& a = m.groups[0];
    std::set<std::array<float, 3>> at_origin;
    for (size_t i = 0; i < a.vertices.size(); ++i)
        if (a.vertices[i].pos == vec3(0)) at_origin.insert({a.colors[i].r, a.colors[i].g, a.colors[i].b});
    EXPECT_EQ(at_origin, (std::set<std::array<float, 3>>{{1, 0, 0}, {0, 1, 1}}));

    // No colours: colors stays empty. Colours in one group only: the other's stays empty; a
    // colour outside 0..1 is clamped, with a warning; a group mixing coloured and plain vertices
    // draws the plain ones white, with a warning.
    const dsr::ObjModel plain = dsr::load_obj(write("p.obj", std::string(kQuad) + "f 1 2 3\n"));
    EXPECT_TRUE(plain.groups.at(0).colors.empty());
    EXPECT_TRUE(plain.groups.at(0).two_sided);
    const dsr::ObjModel mixed = dsr::load_obj(write("x.obj", "mtllib m.mtl\nv 0 0 0 2 -1 0.5\nv 1 0 0 0 0 0\nv 0 1 0 0 0 0\n"
                                                             "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 6 1 0\n"
                                                             "usemtl a\nf 1 2 3\nf 4 5 6\nusemtl b\nf 5 7 6\n"));
    EXPECT_EQ(one_warning(mixed, "x.obj:2: vertex colours outside 0..1: clamped"), 1);
    EXPECT_EQ(one_warning(mixed, "x.obj:11: vertices without a colour in a group with vertex colours: drawn white"), 1);
    ASSERT_EQ(mixed.groups.size(), 2u);
    const dsr::Mesh& ga = mixed.groups[0];
    ASSERT_EQ(ga.colors.size(), ga.vertices.size());
    for (size_t i = 0; i < ga.vertices.size(); ++i) {
        if (ga.vertices[i].pos == vec3(0)) {
            EXPECT_EQ(ga.colors[i], glm::vec4(1, 0, 0.5f, 1));
        } else if (ga.vertices[i].pos.x >= 5) {
            EXPECT_EQ(ga.colors[i], glm::vec4(1));
        }
    }
    EXPECT_TRUE(mixed.groups[1].colors.empty()) << "no vertex of group b has a colour";
}

dsr::Image solid(int w, int h, glm::vec4 c) {
    dsr::Image img;
    img.width = w, img.height = h;
    img.rgba.resize(size_t(w) * size_t(h) * 4);
    for (size_t i = 0; i < img.rgba.size(); i += 4)
        for (int k = 0; k < 4; ++k) img.rgba[i + size_t(k)] = c[k];
    return img;
}

// Cut-outs: map_d's coverage becomes the diffuse map's alpha (a white one's without map_Kd),
// resampled to the diffuse map's size, and the material's alpha_cutoff 0.5; a diffuse map with
// alpha below 0.5 is a cut-out too; d below 1 stays opacity.
TEST_F(ObjFiles, CutOutMaterials) {
    std::map<std::string, dsr::Image> images;
    images["kd.png"] = solid(4, 2, {0.2f, 0.4f, 0.6f, 1});
    dsr::Image mask = solid(2, 1, {0, 0, 0, 1});  // red: left texel 0, right texel 1
    mask.at(1, 0)[0] = 1;
    images["mask.png"] = mask;
    dsr::Image amask = solid(4, 2, {1, 1, 1, 1});  // an alpha channel: coverage from alpha
    amask.at(0, 0)[3] = 0.25f;
    images["amask.png"] = amask;
    dsr::Image holes = solid(2, 2, {1, 1, 1, 1});
    holes.at(1, 1)[3] = 0.1f;
    images["holes.png"] = holes;
    images["faint.png"] = solid(2, 2, {1, 1, 1, 0.6f});
    dsr::ObjOptions o;
    o.read_image = [&](const std::string& p) {
        auto it = images.find(fs::path(p).filename().string());
        if (it == images.end()) throw dsr::Error("cannot open image " + p + ": no such file");
        return it->second;
    };
    write("m.mtl",
          "newmtl kd_and_d\nmap_Kd kd.png\nmap_d mask.png\n"
          "newmtl d_only\nKd 1 0 0\nmap_d amask.png\n"
          "newmtl holes\nmap_Kd holes.png\n"
          "newmtl faint\nmap_Kd faint.png\nd 0.5\n"
          "newmtl plain\nmap_Kd kd.png\n");
    const dsr::ObjModel m = dsr::load_obj(write("c.obj", "mtllib m.mtl\n" + std::string(kQuad) +
                                                             "usemtl kd_and_d\nf 1 2 3\nusemtl d_only\nf 1 2 3\n"
                                                             "usemtl holes\nf 1 2 3\nusemtl faint\nf 1 2 3\n"
                                                             "usemtl plain\nf 1 2 3\n"),
                                          o);
    EXPECT_EQ(one_warning(m, "m.mtl:3: map_d 'mask.png' (2 x 1) resampled to its diffuse map's 4 x 2 (nearest texel)"), 1);
    ASSERT_EQ(m.materials.size(), 5u);
    const dsr::Material &kd_d = m.materials[0], &d_only = m.materials[1], &hole = m.materials[2], &faint = m.materials[3],
                        &plain = m.materials[4];
    EXPECT_FLOAT_EQ(kd_d.alpha_cutoff, 0.5f);
    ASSERT_GE(kd_d.diffuse_map, 0);
    const dsr::Image& baked = m.textures[size_t(kd_d.diffuse_map)];
    EXPECT_EQ(m.texture_paths[size_t(kd_d.diffuse_map)], path("kd.png") + " (alpha from " + path("mask.png") + ")");
    ASSERT_EQ(baked.width, 4);
    ASSERT_EQ(baked.height, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            EXPECT_FLOAT_EQ(baked.at(x, y)[0], 0.2f) << "colour kept";
            EXPECT_FLOAT_EQ(baked.at(x, y)[3], x < 2 ? 0.0f : 1.0f) << "mask's red, nearest texel, at " << x << " " << y;
        }
    EXPECT_FLOAT_EQ(d_only.alpha_cutoff, 0.5f);
    ASSERT_GE(d_only.diffuse_map, 0);
    const dsr::Image& white = m.textures[size_t(d_only.diffuse_map)];
    EXPECT_EQ(white.width, 4);
    EXPECT_FLOAT_EQ(white.at(0, 0)[0], 1.0f) << "white: the Kd colour shows";
    EXPECT_FLOAT_EQ(white.at(0, 0)[3], 0.25f) << "the mask's alpha where it has one";
    EXPECT_FLOAT_EQ(white.at(1, 0)[3], 1.0f);
    EXPECT_EQ(d_only.diffuse, vec3(1, 0, 0));
    EXPECT_FLOAT_EQ(hole.alpha_cutoff, 0.5f) << "a diffuse map with alpha below 0.5";
    EXPECT_FLOAT_EQ(faint.alpha_cutoff, 0.0f) << "alpha 0.6 everywhere: not a cut-out";
    EXPECT_FLOAT_EQ(faint.opacity, 0.5f) << "d stays opacity";
    EXPECT_FLOAT_EQ(plain.alpha_cutoff, 0.0f);
    ASSERT_GE(plain.diffuse_map, 0);
    EXPECT_FLOAT_EQ(m.textures[size_t(plain.diffuse_map)].at(0, 0)[3], 1.0f) << "kd.png itself is left as it was";
    EXPECT_NE(plain.diffuse_map, kd_d.diffuse_map);
    // A map_d that cannot be read: a warning, no cut-out.
    write("n.mtl", "newmtl a\nmap_d gone.png\n");
    const dsr::ObjModel n = dsr::load_obj(write("n.obj", "mtllib n.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n"), o);
    EXPECT_EQ(one_warning(n, "n.mtl:2: map_d 'gone.png' cannot be read"), 1);
    EXPECT_FLOAT_EQ(n.materials.at(0).alpha_cutoff, 0.0f);
    EXPECT_EQ(n.materials.at(0).diffuse_map, -1);
}

// ---- the scene directive ----------------------------------------------------------------------

TEST_F(ObjFiles, MeshDirectiveParsesOnceDrawsTwice) {
    write("m.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
    write("models/t.obj", "mtllib ../m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n");
    const std::string scene = write("s.scene",
                                    "camera pos 0 0 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\n"
                                    "material grey diffuse 0.5 0.5 0.5 specular 0 0 0 shininess 1\n"
                                    "mesh models/t.obj\n"
                                    "mesh ./models/../models/t.obj scale 2 at 10 0 0 rotate_y 90 material grey\n");
    const dsr::Scene s = dsr::load_scene(scene);
    ASSERT_EQ(s.models.size(), 1u) << "the same file is parsed once";
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.models[0].mesh_count, 2u);
    ASSERT_EQ(s.meshes.size(), 2u) << "each group once, in object space, however many instances";
    ASSERT_EQ(s.objects.size(), 4u) << "one object per group per instance";
    EXPECT_EQ(s.materials.size(), 3u) << "grey + the MTL's two, added once";
    EXPECT_EQ(s.materials[1].name, "t.obj:a");
    const dsr::MeshInstance& b = s.instances[1];
    EXPECT_EQ(b.first_object, 2u);
    EXPECT_EQ(b.object_count, 2u);
    EXPECT_EQ(b.material, 0);
    for (size_t i = 2; i < 4; ++i) {
        EXPECT_EQ(s.objects[i].material, 0) << "material overrides the MTL";
        EXPECT_EQ(s.objects[i].mesh, s.objects[i - 2].mesh) << "both instances draw the same mesh";
        EXPECT_EQ(s.objects[i].model, b.model_matrix());
    }
    EXPECT_NE(s.objects[0].material, s.objects[1].material);
    EXPECT_EQ(s.objects[0].model, glm::dmat4(1.0));
    // rotate_y 90 takes +X to -Z; scale 2; at (10, 0, 0).
    const glm::dvec4 p = b.model_matrix() * glm::dvec4(1, 0, 0, 1);
    EXPECT_NEAR(p.x, 10, 1e-12);
    EXPECT_NEAR(p.z, -2, 1e-12);
    bool found = false;
    for (const dsr::Vertex& v : s.meshes[s.objects[2].mesh].vertices)
        if (glm::length(v.pos - vec3(1, 0, 0)) < 1e-6f) found = true;
    EXPECT_TRUE(found) << "vertices stay in object space";
    for (size_t i = 0; i < 2; ++i)
        for (const dsr::Vertex& v : s.meshes[i].vertices) {
            EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.0f, 1e-5f);
        }
}

TEST_F(ObjFiles, MeshDirectiveErrors) {
    auto scene_error = [&](const std::string& line) {
        const std::string p = write("s.scene", "camera pos 0 0 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\n" + line + "\n");
        try {
            dsr::load_scene(p);
        } catch (const dsr::Error& e) {
            return std::string(e.what());
        }
        ADD_FAILURE() << "no error for " << line;
        return std::string();
    };
    write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    write("ok.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    // (The scene reader's own words around the OBJ loader's are its own: only their shape is checked.)
    const std::string bad_index = scene_error("mesh t.obj");
    EXPECT_HAS(bad_index, "s.scene:2: expected a readable ");
    EXPECT_HAS(bad_index, " file for mesh, got 't.obj': " + path("t.obj") + ":5: vertex index 9");
    EXPECT_HAS(scene_error("mesh none.obj"), " file for mesh, got 'none.obj'");
    const std::string no_name = scene_error("mesh");
    EXPECT_HAS(no_name, "s.scene:2: expected a");
    EXPECT_HAS(no_name, "file name");
    EXPECT_HAS(no_name, "got end of line");
    EXPECT_HAS(scene_error("mesh ok.obj scale -1"), "s.scene:2: expected mesh scale > 0, got '-1'");
    const std::string spin = scene_error("mesh ok.obj spin 3");
    EXPECT_HAS(spin, "s.scene:2: expected one of scale, at, rotate_y, material");
    EXPECT_HAS(spin, "got 'spin'");
    EXPECT_HAS(scene_error("mesh ok.obj material nope"), "s.scene:2: expected a material defined on an earlier line");
    // Scale and at are bounded like OBJ coordinates, and so is every world-space vertex.
    EXPECT_HAS(scene_error("mesh ok.obj scale 3e38 at 3e38 0 0"), "s.scene:2: expected a number for mesh scale within +-1e12, got '3e38'");
    EXPECT_HAS(scene_error("mesh ok.obj scale 1e12 at 1e12 0 0"),
               "s.scene:2: expected scale and at that keep 'ok.obj' within +-1e12 in world space, got a vertex at 2e+12 0 0");
}

#ifndef DSR_OBJ_LOADER_ONLY

// `dsr render` on a bad mesh: non-zero exit, the message names file and line, no image written.
TEST_F(ObjFiles, RenderRefusesBadMeshWithoutWritingOutput) {
    write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 nan\n");
    const std::string scene = write("s.scene", "camera pos 0 0 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\nmesh t.obj\n");
    const std::string out = path("out.png");
    const dsr::test::RunResult r = dsr::test::run("render " + scene + " -o " + out + " --size 64x64");
    EXPECT_NE(r.status, 0);
    EXPECT_HAS(r.output, path("t.obj") + ":4: expected an integer vertex index, got 'nan'");
    EXPECT_FALSE(dsr::test::exists(out));
}

// What a render of a real model must show: something drawn, nothing NaN, a sensible share of
// the frame covered (not all background, not all model).
struct Coverage {
    double covered = 0;
    bool finite = true;
};
Coverage coverage(const dsr::Image& img, vec3 background) {
    Coverage c;
    size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float* p = img.at(x, y);
            for (int k = 0; k < 3; ++k) c.finite = c.finite && std::isfinite(p[k]);
            if (std::fabs(p[0] - background.r) + std::fabs(p[1] - background.g) + std::fabs(p[2] - background.b) > 3.0f / 255)
                ++n;
        }
    c.covered = double(n) / (double(img.width) * img.height);
    return c;
}

const std::string kAssets = std::string(DSR_SOURCE_DIR) + "/../shared/assets";

// Each asset with its scene in tests/data (paths there are relative to the scene file).
void render_asset(const std::string& folder, const std::string& scene_name, double min_cover, double max_cover) {
    if (!fs::is_directory(kAssets + "/" + folder))
        GTEST_SKIP() << "skipped: " << kAssets << "/" << folder << " is absent (optional local test assets, not part of the repository)";
    const double t0 = dsr::now_ms();
    const dsr::Scene scene = dsr::load_scene(std::string(DSR_SOURCE_DIR) + "/tests/data/" + scene_name);
    const double load_ms = dsr::now_ms() - t0;
    const size_t tris = scene.triangle_count();
    const int size = 256;
    const dsr::test::RenderResult r = dsr::test::render_scene(scene, size, size, dsr::ShaderOptions{});
    const Coverage c = coverage(r.image, scene.background);
    const std::string out = dsr::test::test_output_dir() + "/asset_" + folder + ".png";
    dsr::write_image(out, dsr::opaque(r.image));
    std::printf("[ asset    ] %s: %zu triangles, load %.0f ms, frame %.1f ms, %.1f%% covered, wrote %s\n", folder.c_str(),
                tris, load_ms, r.stats.ms.frame, 100 * c.covered, out.c_str());
    EXPECT_TRUE(c.finite);
    EXPECT_GT(c.covered, min_cover) << "hardly anything drawn";
    EXPECT_LT(c.covered, max_cover) << "the model fills the frame";
    EXPECT_GT(tris, 0u);
}

TEST(ObjAssets, Windmill) { render_asset("windmill", "asset_windmill.scene", 0.10, 0.90); }
TEST(ObjAssets, Chair) { render_asset("chair", "asset_chair.scene", 0.10, 0.90); }
TEST(ObjAssets, Teapot) { render_asset("teapot", "asset_teapot.scene", 0.10, 0.90); }
TEST(ObjAssets, Bunny) { render_asset("bunny", "asset_bunny.scene", 0.10, 0.90); }

// The windmill's normal and specular maps change the image: the same scene with its MTL maps
// overridden by a plain material differs in the shading, not in the silhouette.
TEST(ObjAssets, WindmillMapsAreUsed) {
    if (!fs::is_directory(kAssets + "/windmill")) GTEST_SKIP() << "skipped: " << kAssets << "/windmill is absent";
    const dsr::Scene s = dsr::load_scene(std::string(DSR_SOURCE_DIR) + "/tests/data/asset_windmill.scene");
    int with_normal = 0, with_spec = 0, with_diffuse = 0;
    for (const dsr::Material& m : s.materials) {
        with_normal += m.normal_map >= 0;
        with_spec += m.specular_map >= 0;
        with_diffuse += m.diffuse_map >= 0;
    }
    EXPECT_EQ(with_normal, 2);
    EXPECT_EQ(with_diffuse, 2);
    EXPECT_EQ(with_spec, 1) << "map_Ns on the base";
    const size_t tris = s.triangle_count();
    EXPECT_EQ(tris, 66u + 2u * 1328u) << "quads triangulated";
}

// The same OBJ used twice is uploaded once and drawn with two transforms. A box of two
// material groups, instanced left and right of the view: the vertex buffer holds its corners once,
// the draws are one per group per instance, and both instances appear where their transforms put
// them (the left one turned, the right one scaled).
TEST(ObjInstances, UploadedOnceDrawnPerInstance) {
    const std::string dir = dsr::test::test_output_dir() + "/instances";
    fs::create_directories(dir);
    std::ofstream(dir + "/box.mtl") << "newmtl red\nKd 0.9 0.2 0.2\nnewmtl blue\nKd 0.2 0.3 0.9\n";
    std::ofstream(dir + "/box.obj") << "mtllib box.mtl\n"
                                       "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
                                       "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
                                       "usemtl red\nf 5 6 7 8\nf 2 1 4 3\nf 6 2 3 7\nf 1 5 8 4\n"
                                       "usemtl blue\nf 8 7 3 4\nf 1 2 6 5\n";
    std::ofstream(dir + "/s.scene") << "camera pos 0 1.5 5 target 0 0 0 up 0 1 0 fov 50 near 0.1 far 50\n"
                                       "ambient 0.3 0.3 0.3\n"
                                       "mesh box.obj at -1.4 0 0 rotate_y 30\n"
                                       "mesh box.obj at 1.4 0 0 scale 1.5\n"
                                       "light point pos 0 3 3 color 1 1 1 radius 10\n";
    const dsr::Scene s = dsr::load_scene(dir + "/s.scene");
    ASSERT_EQ(s.meshes.size(), 2u);
    ASSERT_EQ(s.objects.size(), 4u);
    size_t vertices = 0;
    for (const dsr::Mesh& m : s.meshes) vertices += m.vertices.size();
    {
        auto ctx = dsr::create_context(dsr::ContextDesc{"osmesa", 64, 64});
        const dsr::GpuScene gpu(s);
        EXPECT_EQ(gpu.uploaded_vertices(), vertices) << "each mesh once";
        EXPECT_EQ(gpu.triangle_count(), 2 * s.models[0].triangles) << "drawn twice";
        ASSERT_EQ(gpu.ranges().size(), 4u) << "one draw per material group per instance";
        EXPECT_EQ(gpu.ranges()[0].material, gpu.ranges()[1].material) << "ordered by material";
    }
    const int w = 160, h = 96;
    const dsr::test::RenderResult r = dsr::test::render_scene(s, w, h, dsr::ShaderOptions{});
    dsr::write_image(dir + "/instances.png", dsr::opaque(r.image));
    // Each half of the image: its instance's pixels, centred where the transform put it.
    double cx[2] = {0, 0};
    int n[2] = {0, 0};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = r.image.at(x, y);
            if (p[0] + p[1] + p[2] < 3.0f / 255) continue;
            const int half = x < w / 2 ? 0 : 1;
            cx[half] += x;
            ++n[half];
        }
    ASSERT_GT(n[0], 200);
    ASSERT_GT(n[1], 200);
    EXPECT_GT(n[1], 1.5 * n[0]) << "the right instance is scaled 1.5x";
    // The centroids lie near the projections of the instances' origins (+-1.4, 0, 0).
    for (int k = 0; k < 2; ++k) {
        const glm::vec4 c = s.camera.projection(float(w) / h) * s.camera.view() * glm::vec4(k ? 1.4f : -1.4f, 0, 0, 1);
        EXPECT_NEAR(cx[k] / n[k], (c.x / c.w * 0.5 + 0.5) * w, 4) << (k ? "right" : "left");
    }
}

// A generated 1-million-triangle grid (a height field, so it is lit unevenly) loads and renders.
TEST(ObjLarge, MillionTriangles) {
    const int n = 708;  // 708 x 708 quads = 1,002,528 triangles
    const std::string dir = dsr::test::test_output_dir() + "/grid";
    std::error_code ec;
    fs::remove_all(dir, ec);  // written afresh: the test times the load of a file it just wrote
    const std::string scene_path = dsr::write_grid_scene(dir, n);
    const std::string obj = dir + "/grid_708.obj";
    const double t0 = dsr::now_ms();
    const dsr::Scene scene = dsr::load_scene(scene_path);
    const double load_ms = dsr::now_ms() - t0;
    ASSERT_EQ(scene.models.size(), 1u);
    EXPECT_EQ(scene.models[0].triangles, size_t(2) * n * n);
    EXPECT_EQ(scene.meshes.at(scene.models[0].first_mesh).vertices.size(), size_t(n + 1) * (n + 1)) << "every corner shared";
    const dsr::test::RenderResult r = dsr::test::render_scene(scene, 512, 512, dsr::ShaderOptions{});
    const Coverage c = coverage(r.image, scene.background);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    std::printf("[ large    ] %zu triangles (%.1f MB OBJ): load %.0f ms, frame %.0f ms at 512x512, %.1f%% covered, peak RSS %.0f MB\n",
                scene.models[0].triangles, double(fs::file_size(obj)) / 1e6, load_ms, r.stats.ms.frame, 100 * c.covered,
                double(ru.ru_maxrss) / 1024);
    dsr::write_image(dsr::test::test_output_dir() + "/grid_1m.png", dsr::opaque(r.image));
    EXPECT_TRUE(c.finite);
    EXPECT_GT(c.covered, 0.3);
    fs::remove(obj);
}

#endif  // DSR_OBJ_LOADER_ONLY

}  // namespace
