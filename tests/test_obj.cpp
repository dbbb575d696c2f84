// OBJ/MTL loading (docs/scene-format.md): the loader on small files written here, normals and
// tangent frames against brute force, every kind of bad input as its own case (the message must
// name the file and line), the `mesh` scene directive, and, unless DSR_OBJ_LOADER_ONLY (the
// ASan + UBSan build of the loader, `make test`), renders of each model of the optional local test
// assets (not part of the repository) that is present, and of a generated 1-million-triangle OBJ.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "dsr_clock.h"
#include "dsr_error.h"
#include "scene/image.h"
#include "scene/obj_loader.h"
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

TEST_F(ObjFiles, MissingMtl) {
    const std::string e = bad_obj(std::string(kQuad) + "mtllib gone.mtl\nf 1 2 3\n");
    EXPECT_HAS(e, "bad.obj:9: expected a readable MTL file for mtllib, got 'gone.mtl'");
    EXPECT_HAS(e, "No such file or directory");
}

TEST_F(ObjFiles, DirectoryWhereTheMtlShouldBe) {
    fs::create_directories(path("d.mtl"));
    const std::string e = bad_obj("mtllib d.mtl\n" + std::string(kQuad) + "f 1 2 3\n");
    EXPECT_HAS(e, "bad.obj:1:");
    EXPECT_HAS(e, "got a directory");
}

TEST_F(ObjFiles, MissingTexture) {
    write("m.mtl", "newmtl a\nKd 1 1 1\n\nmap_Kd missing.png\n");
    const std::string e = bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n");
    EXPECT_HAS(e, "m.mtl:4: expected a readable image for map_Kd, got 'missing.png'");
}

TEST_F(ObjFiles, DirectoryWhereTheTextureShouldBe) {
    fs::create_directories(path("tex.png"));
    write("m.mtl", "newmtl a\nmap_Kd tex.png\n");
    const std::string e = bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n");
    EXPECT_HAS(e, "m.mtl:2: expected a readable image for map_Kd");
    EXPECT_HAS(e, "got a directory");
}

TEST_F(ObjFiles, TruncatedTexture) {
    const std::string png = image("t.png", 64, 64, {0.3f, 0.6f, 0.9f});
    const auto size = fs::file_size(png);
    fs::resize_file(png, size / 2);
    write("m.mtl", "newmtl a\nKd 1 1 1\nmap_Ks t.png\n");
    const std::string e = bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n");
    EXPECT_HAS(e, "m.mtl:3: expected a readable image for map_Ks, got 't.png'");
}

TEST_F(ObjFiles, UnreadableTexture) {
    write("junk.jpg", "this is not a JPEG at all");
    write("m.mtl", "newmtl a\nnorm junk.jpg\n");
    const std::string e = bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "usemtl a\nf 1 2 3\n");
    EXPECT_HAS(e, "m.mtl:2: expected a readable image for norm, got 'junk.jpg'");
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
    EXPECT_HAS(bad_obj(std::string(kQuad) + "# no faces\n"), "an empty mesh");
    EXPECT_HAS(bad_obj(std::string(kQuad) + "f 1 1 2\nf 1 2 1\n"), "bad.obj: expected at least one triangle with area");
}

TEST_F(ObjFiles, AbsurdSizes) {
    EXPECT_HAS(bad_obj("v 1e13 0 0\n"), "bad.obj:1: expected a vertex coordinate within +-1e12, got '1e13' (an absurd size)");
    std::string f = "f";
    for (int i = 1; i <= 300; ++i) f += " 1";
    EXPECT_HAS(bad_obj(std::string(kQuad) + f + "\n"), "bad.obj:9: expected a face of at most 256 corners, got 300");
}

TEST_F(ObjFiles, UnknownDirectives) {
    EXPECT_HAS(bad_obj(std::string(kQuad) + "bogus 1 2 3\n"), "bad.obj:9: expected an OBJ statement (v, vt, vn, f,");
    EXPECT_HAS(bad_obj("usemtlx a\n"), "bad.obj:1: expected an OBJ statement");
    write("m.mtl", "newmtl a\nKd 1 1 1\nKq 1\n");
    EXPECT_HAS(bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "f 1 2 3\n"), "m.mtl:3: expected an MTL statement (newmtl, Kd,");
}

TEST_F(ObjFiles, MalformedMtlLines) {
    auto mtl_error = [&](const std::string& mtl) {
        write("m.mtl", mtl);
        return bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "f 1 2 3\n");
    };
    EXPECT_HAS(mtl_error("newmtl a\nKd 1 1\n"), "m.mtl:2: expected three numbers r g b for Kd");
    EXPECT_HAS(mtl_error("newmtl a\nKs 1 -1 1\n"), "m.mtl:2: expected Ks components >= 0, got '-1'");
    EXPECT_HAS(mtl_error("newmtl a\nNs shiny\n"), "m.mtl:2: expected a number for Ns, got 'shiny'");
    EXPECT_HAS(mtl_error("newmtl a\nd 2\n"), "m.mtl:2: expected d in [0, 1], got '2'");
    EXPECT_HAS(mtl_error("newmtl a\nd -halo 0.5\n"), "m.mtl:2: expected one number for d");
    EXPECT_HAS(mtl_error("Kd 1 1 1\n"), "m.mtl:1: expected newmtl before 'Kd'");
    EXPECT_HAS(mtl_error("newmtl a\nnewmtl a\n"), "m.mtl:2: expected a material name not defined before, got 'a' (first defined at");
    EXPECT_HAS(mtl_error("newmtl a b\n"), "m.mtl:1: expected one material name");
    EXPECT_HAS(mtl_error("newmtl a\nmap_Kd\n"), "m.mtl:2: expected a texture file name for map_Kd");
    EXPECT_HAS(mtl_error("newmtl a\nmap_Kd -s 1 t.png\n"), "m.mtl:2: expected a number for map_Kd -s, got 't.png'");
    EXPECT_HAS(mtl_error("newmtl a\nbump -zz t.png\n"), "m.mtl:2: expected a texture option");
    EXPECT_HAS(mtl_error("newmtl a\nbump -bm nan t.png\n"), "m.mtl:2: expected a number for bump -bm, got 'nan'");
}

TEST_F(ObjFiles, UnknownMaterial) {
    write("m.mtl", "newmtl a\n");
    EXPECT_HAS(bad_obj("mtllib m.mtl\n" + std::string(kQuad) + "usemtl b\nf 1 2 3\n"),
               "bad.obj:10: expected a material defined in an MTL file named by an mtllib line before this one, got 'b'");
    EXPECT_HAS(bad_obj("usemtl a\nmtllib m.mtl\n" + std::string(kQuad) + "f 1 2 3\n"), "bad.obj:1: expected a material");
}

TEST_F(ObjFiles, NulByte) {
    EXPECT_HAS(bad_obj(std::string("v 0 0 0\nv 1 0\0 0\n", 18)), "bad.obj:2: expected text, got a NUL byte");
}

// `make fuzz` findings become cases here. First run (FUZZ_SECONDS=60 each): obj 461,686
// executions, scene_file 60,744, no crash, leak, timeout or sanitizer report.

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
    EXPECT_HAS(scene_error("mesh t.obj"), "s.scene:2: expected a readable OBJ file for mesh, got 't.obj': " + path("t.obj") + ":5: vertex index 9");
    EXPECT_HAS(scene_error("mesh none.obj"), "s.scene:2: expected a readable OBJ file for mesh, got 'none.obj'");
    EXPECT_HAS(scene_error("mesh"), "s.scene:2: expected an OBJ file name, got end of line");
    EXPECT_HAS(scene_error("mesh ok.obj scale -1"), "s.scene:2: expected mesh scale > 0, got '-1'");
    EXPECT_HAS(scene_error("mesh ok.obj spin 3"), "s.scene:2: expected one of scale, at, rotate_y, material, got 'spin'");
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
