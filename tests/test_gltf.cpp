// The glTF 2.0 reader (scene/gltf_loader.h) on files the tests write themselves: JSON text with
// base64 data: buffers, and .glb files built here. Decoded vertices and indices byte-exact for
// every component type, strips and fans, instancing and baking, materials, textures, lights and
// cameras, and each kind of bad file as one error naming the JSON pointer. Then every glTF file
// of Debian's assimp-testmodels that is installed, loaded or refused with its line.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dsr_error.h"
#include "scene/gltf_loader.h"
#include "scene/image.h"
#include "scene/light_law.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using std::string;

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kInt = 5124, kUInt = 5125, kFloat = 5126;

string base64(const string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    string out;
    size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const uint32_t v = uint32_t((unsigned char)in[i]) << 16 | uint32_t((unsigned char)in[i + 1]) << 8 | (unsigned char)in[i + 2];
        out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += t[v & 63];
    }
    if (i + 1 == in.size()) {
        const uint32_t v = uint32_t((unsigned char)in[i]) << 16;
        out += t[v >> 18], out += t[(v >> 12) & 63], out += "==";
    } else if (i + 2 == in.size()) {
        const uint32_t v = uint32_t((unsigned char)in[i]) << 16 | uint32_t((unsigned char)in[i + 1]) << 8;
        out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += '=';
    }
    return out;
}

template <class T>
string bytes_of(const std::vector<T>& v) {
    return string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

string le32(uint32_t v) {
    string s(4, '\0');
    for (int i = 0; i < 4; ++i) s[size_t(i)] = char((v >> (8 * i)) & 0xFF);
    return s;
}

// A glTF document and its one buffer, built up by the tests.
struct Builder {
    json doc = {{"asset", {{"version", "2.0"}}}};
    string bin;

    int view(const string& bytes, int stride = 0) {
        while (bin.size() % 4) bin += '\0';
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
        if (stride) v["byteStride"] = stride;
        bin += bytes;
        doc["bufferViews"].push_back(v);
        return int(doc["bufferViews"].size() - 1);
    }
    int accessor(int view, int ct, size_t count, const char* type, bool normalized = false, size_t offset = 0) {
        json a = {{"bufferView", view}, {"componentType", ct}, {"count", count}, {"type", type}};
        if (normalized) a["normalized"] = true;
        if (offset) a["byteOffset"] = offset;
        doc["accessors"].push_back(a);
        return int(doc["accessors"].size() - 1);
    }
    template <class T>
    int data(const std::vector<T>& v, int ct, const char* type, bool normalized = false) {
        const int comps = string(type) == "SCALAR" ? 1 : type[3] - '0';
        return accessor(view(bytes_of(v)), ct, v.size() / size_t(comps), type, normalized);
    }
    // A mesh of one primitive; returns its index.
    int mesh(json attributes, int indices = -1, int mode = -1, int material = -1) {
        json p = {{"attributes", attributes}};
        if (indices >= 0) p["indices"] = indices;
        if (mode >= 0) p["mode"] = mode;
        if (material >= 0) p["material"] = material;
        doc["meshes"].push_back({{"primitives", json::array({p})}});
        return int(doc["meshes"].size() - 1);
    }
    int node(json n) {
        doc["nodes"].push_back(n);
        return int(doc["nodes"].size() - 1);
    }
    void scene(std::vector<int> roots) { doc["scenes"] = json::array({{{"nodes", roots}}}); }
    // The standard triangle: positions (0,0,0) (1,0,0) (0,1,0) with +Z normals.
    int triangle() {
        const int p = data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3");
        const int n = data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
        return mesh({{"POSITION", p}, {"NORMAL", n}});
    }
    string gltf() const {
        json d = doc;
        if (!bin.empty()) d["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        return d.dump();
    }
    string glb() const {
        json d = doc;
        string b = bin;
        while (b.size() % 4) b += '\0';
        if (!bin.empty()) d["buffers"] = json::array({{{"byteLength", bin.size()}}});
        string j = d.dump();
        while (j.size() % 4) j += ' ';
        string out = "glTF" + le32(2) + le32(uint32_t(12 + 8 + j.size() + (b.empty() ? 0 : 8 + b.size()))) + le32(uint32_t(j.size())) + "JSON" + j;
        if (!b.empty()) out += le32(uint32_t(b.size())) + string("BIN\0", 4) + b;
        return out;
    }
};

// Files a test hands the reader by name (nothing on disk).
struct Files {
    std::map<string, string> files;
    dsr::GltfOptions options() const {
        dsr::GltfOptions o;
        auto f = files;
        o.read_file = [f](const string& p) -> string {
            auto it = f.find(p);
            if (it == f.end()) throw dsr::Error("cannot open " + p + ": no such file");
            return it->second;
        };
        return o;
    }
};

dsr::GltfModel parse(const string& text, dsr::GltfOptions o = {}) {
    if (!o.read_file) o = Files{}.options();
    return dsr::parse_gltf("t/m.gltf", text, o);
}

string error_of(const string& text, dsr::GltfOptions o = {}) {
    try {
        parse(text, o);
    } catch (const dsr::Error& e) {
        const string m = e.what();
        EXPECT_EQ(m.find('\n'), string::npos) << "one line: " << m;
        return m;
    }
    ADD_FAILURE() << "expected an error";
    return "";
}

int count_holding(const std::vector<string>& lines, const string& part) {
    int n = 0;
    for (const string& l : lines) n += l.find(part) != string::npos;
    return n;
}

// A PNG of w x h pixels of `rgba` (dsr's own writer), as bytes.
string png_bytes(int w, int h, glm::vec4 rgba) {
    dsr::Image img;
    img.width = w;
    img.height = h;
    for (int i = 0; i < w * h; ++i) img.rgba.insert(img.rgba.end(), {rgba.r, rgba.g, rgba.b, rgba.a});
    const string p = (fs::temp_directory_path() / ("dsr-gltf-" + std::to_string(::getpid()) + ".png")).string();
    dsr::encode_image(p, p, img);
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    fs::remove(p);
    return ss.str();
}

uint32_t crc32(const string& s) {
    uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : s) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}
string be32(uint32_t v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }
string png_chunk(const string& type, const string& data) { return be32(uint32_t(data.size())) + type + data + be32(crc32(type + data)); }
// A PNG whose header claims w x h and which has no pixels.
string header_only_png(uint32_t w, uint32_t h) {
    return "\x89PNG\r\n\x1a\n" + png_chunk("IHDR", be32(w) + be32(h) + string("\x08\x02\x00\x00\x00", 5)) +
           png_chunk("IDAT", string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8)) + png_chunk("IEND", "");
}

// A textured quad whose material is `material` (JSON), its texture the PNG `image`.
Builder textured_quad(json material, const string& image, json sampler = nullptr) {
    Builder b;
    const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, kFloat, "VEC3");
    const int n = b.data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
    const int t = b.data(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}, kFloat, "VEC2");
    const int i = b.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort, "SCALAR");
    b.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(image)}}});
    json tex = {{"source", 0}};
    if (!sampler.is_null()) {
        b.doc["samplers"] = json::array({sampler});
        tex["sampler"] = 0;
    }
    b.doc["textures"] = json::array({tex});
    b.doc["materials"] = json::array({material});
    b.mesh({{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}, i, -1, 0);
    b.scene({b.node({{"mesh", 0}})});
    return b;
}

// ---- good input -------------------------------------------------------------------------------

TEST(Gltf, IsGltfPath) {
    EXPECT_TRUE(dsr::is_gltf_path("a/b.gltf"));
    EXPECT_TRUE(dsr::is_gltf_path("B.GLB"));
    EXPECT_FALSE(dsr::is_gltf_path("b.obj"));
    EXPECT_FALSE(dsr::is_gltf_path("gltf"));
}

TEST(Gltf, TriangleAsGltfAndGlb) {
    Builder b;
    b.scene({b.node({{"mesh", b.triangle()}})});
    for (const string& text : {b.gltf(), b.glb()}) {
        const dsr::GltfModel m = dsr::parse_gltf("t/m.glb", text, Files{}.options());
        ASSERT_EQ(m.meshes.size(), 1u);
        ASSERT_EQ(m.placements.size(), 1u);
        EXPECT_EQ(m.triangles, 1u);
        const dsr::Mesh& mesh = m.meshes[0];
        ASSERT_EQ(mesh.vertices.size(), 3u);
        EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
        EXPECT_EQ(mesh.vertices[1].pos, glm::vec3(1, 0, 0));
        EXPECT_EQ(mesh.vertices[2].normal, glm::vec3(0, 0, 1));
        ASSERT_EQ(m.materials.size(), 1u) << "the default material";
        EXPECT_EQ(m.materials[0].name, "m.glb:(default)");
        EXPECT_TRUE(m.warnings.empty());
    }
}

// Positions of every component type, as written, and normalized integers as glTF maps them.
TEST(Gltf, EveryComponentTypeByteExact) {
    struct Case {
        int ct;
        bool normalized;
        string bytes;
        std::vector<float> want;  // 3 vertices
    };
    const std::vector<Case> cases = {
        {kByte, false, bytes_of(std::vector<int8_t>{-128, 0, 127, 1, 2, 3, -1, -2, -3}), {-128, 0, 127, 1, 2, 3, -1, -2, -3}},
        {kUByte, false, bytes_of(std::vector<uint8_t>{0, 255, 7, 1, 2, 3, 9, 8, 7}), {0, 255, 7, 1, 2, 3, 9, 8, 7}},
        {kShort, false, bytes_of(std::vector<int16_t>{-32768, 32767, 5, 1, 2, 3, -7, 0, 7}), {-32768, 32767, 5, 1, 2, 3, -7, 0, 7}},
        {kUShort, false, bytes_of(std::vector<uint16_t>{65535, 0, 5, 1, 2, 3, 4, 5, 6}), {65535, 0, 5, 1, 2, 3, 4, 5, 6}},
        {kInt, false, bytes_of(std::vector<int32_t>{-100000, 100000, 5, 1, 2, 3, 4, 5, 6}), {-100000, 100000, 5, 1, 2, 3, 4, 5, 6}},
        {kUInt, false, bytes_of(std::vector<uint32_t>{4000000, 0, 5, 1, 2, 3, 4, 5, 6}), {4000000, 0, 5, 1, 2, 3, 4, 5, 6}},
        {kFloat, false, bytes_of(std::vector<float>{0.125f, -2.5f, 1e6f, 1, 2, 3, 4, 5, 6}), {0.125f, -2.5f, 1e6f, 1, 2, 3, 4, 5, 6}},
        {kByte, true, bytes_of(std::vector<int8_t>{-128, -127, 127, 64, 0, 1, 2, 3, 4}),
         {-1, -1, 1, float(64 / 127.0), 0, float(1 / 127.0), float(2 / 127.0), float(3 / 127.0), float(4 / 127.0)}},
        {kUByte, true, bytes_of(std::vector<uint8_t>{255, 0, 128, 1, 2, 3, 4, 5, 6}),
         {1, 0, float(128 / 255.0), float(1 / 255.0), float(2 / 255.0), float(3 / 255.0), float(4 / 255.0), float(5 / 255.0), float(6 / 255.0)}},
        {kShort, true, bytes_of(std::vector<int16_t>{-32768, 32767, 100, 1, 2, 3, 4, 5, 6}),
         {-1, 1, float(100 / 32767.0), float(1 / 32767.0), float(2 / 32767.0), float(3 / 32767.0), float(4 / 32767.0), float(5 / 32767.0), float(6 / 32767.0)}},
        {kUShort, true, bytes_of(std::vector<uint16_t>{65535, 0, 1000, 1, 2, 3, 4, 5, 6}),
         {1, 0, float(1000 / 65535.0), float(1 / 65535.0), float(2 / 65535.0), float(3 / 65535.0), float(4 / 65535.0), float(5 / 65535.0), float(6 / 65535.0)}},
    };
    for (const Case& c : cases) {
        Builder b;
        const int p = b.accessor(b.view(c.bytes), c.ct, 3, "VEC3", c.normalized);
        const int n = b.data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
        b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}, {"NORMAL", n}})}})});
        const dsr::GltfModel m = parse(b.gltf());
        ASSERT_EQ(m.meshes.size(), 1u);
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(m.meshes[0].vertices[size_t(v)].pos[k], c.want[size_t(v * 3 + k)])
                    << "component type " << c.ct << (c.normalized ? " normalized" : "") << " vertex " << v;
    }
}

TEST(Gltf, IndexComponentTypesByteExact) {
    for (int ct : {kUByte, kUShort, kUInt}) {
        Builder b;
        const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, kFloat, "VEC3");
        const int n = b.data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
        const std::vector<uint32_t> idx = {3, 1, 0, 2, 3, 0};
        string bytes;
        for (uint32_t i : idx) bytes += ct == kUByte ? string(1, char(i)) : ct == kUShort ? bytes_of(std::vector<uint16_t>{uint16_t(i)}) : le32(i);
        const int ia = b.accessor(b.view(bytes), ct, idx.size(), "SCALAR");
        b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}, {"NORMAL", n}}, ia)}})});
        const dsr::GltfModel m = parse(b.gltf());
        EXPECT_EQ(m.meshes[0].indices, idx) << ct;
    }
}

TEST(Gltf, ByteStrideInterleaved) {
    Builder b;
    // Position (3 floats) and a pad float per vertex: stride 16.
    const std::vector<float> v = {0, 0, 0, 99, 2, 0, 0, 99, 0, 3, 0, 99};
    const int view = b.view(bytes_of(v), 16);
    const int p = b.accessor(view, kFloat, 3, "VEC3");
    b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}})}})});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.meshes[0].vertices.size(), 3u);
    EXPECT_EQ(m.meshes[0].vertices[1].pos, glm::vec3(2, 0, 0));
    EXPECT_EQ(m.meshes[0].vertices[2].pos, glm::vec3(0, 3, 0));
}

TEST(Gltf, StripAndFanAsGltfOrdersThem) {
    for (int mode : {5, 6}) {
        Builder b;
        const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0}, kFloat, "VEC3");
        const int n = b.data(std::vector<float>(15, 0.0f), kFloat, "VEC3");
        b.doc["accessors"][size_t(n)]["count"] = 5;
        b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}, {"NORMAL", n}}, -1, mode)}})});
        const dsr::GltfModel m = parse(b.gltf());
        const std::vector<uint32_t> want = mode == 5 ? std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}
                                                     : std::vector<uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0};
        EXPECT_EQ(m.meshes[0].indices, want) << "mode " << mode;
        EXPECT_EQ(m.triangles, 3u);
    }
}

TEST(Gltf, PointsAndLinesSkippedWithOneWarningEach) {
    Builder b;
    const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3");
    json prims = json::array();
    for (int mode : {0, 1, 1, 2, 3, 4}) prims.push_back({{"attributes", {{"POSITION", p}}}, {"mode", mode}});
    b.doc["meshes"] = json::array({{{"primitives", prims}}});
    b.scene({b.node({{"mesh", 0}})});
    const dsr::GltfModel m = parse(b.gltf());
    EXPECT_EQ(m.triangles, 1u);
    EXPECT_EQ(count_holding(m.warnings, "LINES primitives skipped"), 1);
    EXPECT_EQ(count_holding(m.warnings, "POINTS primitives skipped"), 1);
    EXPECT_EQ(count_holding(m.warnings, "LINE_LOOP primitives skipped"), 1);
    EXPECT_EQ(count_holding(m.warnings, "LINE_STRIP primitives skipped"), 1);
}

TEST(Gltf, MissingNormalsAreFlatPerFace) {
    Builder b;
    const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, kFloat, "VEC3");
    const int i = b.data(std::vector<uint8_t>{0, 1, 2, 0, 3, 1}, kUByte, "SCALAR");
    b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}}, i)}})});
    const dsr::GltfModel m = parse(b.gltf());
    const dsr::Mesh& mesh = m.meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 6u) << "three vertices of its own per triangle";
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.vertices[size_t(k)].normal, glm::vec3(0, 0, 1));
    for (int k = 3; k < 6; ++k) EXPECT_EQ(mesh.vertices[size_t(k)].normal, glm::vec3(0, 1, 0));
}

TEST(Gltf, UvsFlippedAndColours) {
    Builder b;
    const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3");
    const int t = b.data(std::vector<float>{0, 0, 1, 0.25f, 0.5f, 1}, kFloat, "VEC2");
    const int c = b.data(std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 51, 0, 0, 255, 0}, kUByte, "VEC4", true);
    b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}, {"TEXCOORD_0", t}, {"COLOR_0", c}})}})});
    const dsr::GltfModel m = parse(b.gltf());
    const dsr::Mesh& mesh = m.meshes[0];
    ASSERT_EQ(mesh.colors.size(), mesh.vertices.size());
    // Flat normals: vertex k of the one triangle is glTF vertex k.
    EXPECT_EQ(mesh.vertices[0].uv, glm::vec2(0, 1));
    EXPECT_EQ(mesh.vertices[1].uv, glm::vec2(1, 0.75f));
    EXPECT_EQ(mesh.vertices[2].uv, glm::vec2(0.5f, 0));
    EXPECT_EQ(mesh.colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(mesh.colors[1], glm::vec4(0, 1, 0, 0.2f));
}

TEST(Gltf, SparseAccessorOverridesValues) {
    Builder b;
    const int base = b.view(bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
    const int si = b.view(bytes_of(std::vector<uint16_t>{2, 0}));
    const int sv = b.view(bytes_of(std::vector<float>{0, 5, 0}));
    b.doc["accessors"].push_back({{"bufferView", base}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"},
                                  {"sparse", {{"count", 1}, {"indices", {{"bufferView", si}, {"componentType", kUShort}}}, {"values", {{"bufferView", sv}}}}}});
    b.scene({b.node({{"mesh", b.mesh({{"POSITION", 0}})}})});
    const dsr::GltfModel m = parse(b.gltf());
    EXPECT_EQ(m.meshes[0].vertices[2].pos, glm::vec3(0, 5, 0));
}

TEST(Gltf, InstancingOneMeshTwoPlacements) {
    Builder b;
    const int mesh = b.triangle();
    b.scene({b.node({{"mesh", mesh}, {"translation", {5, 0, 0}}}), b.node({{"mesh", mesh}, {"scale", {2, 2, 2}}, {"rotation", {0, 0.7071067811865476, 0, 0.7071067811865476}}})});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.meshes.size(), 1u);
    ASSERT_EQ(m.placements.size(), 2u);
    EXPECT_EQ(m.placements[0].mesh, 0u);
    EXPECT_EQ(m.placements[1].mesh, 0u);
    EXPECT_EQ(m.placements[0].model[3][0], 5.0);
    EXPECT_NEAR(m.placements[1].model[0][2], -2.0, 1e-12) << "x axis turned to -z, scaled by 2";
    EXPECT_EQ(m.triangles, 2u) << "counted per placement";
}

TEST(Gltf, HierarchyComposesInDouble) {
    Builder b;
    const int mesh = b.triangle();
    const int child = b.node({{"mesh", mesh}, {"translation", {0, 1, 0}}});
    b.scene({b.node({{"children", {child}}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1e6, 0, 0.5, 1}}})});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.placements.size(), 1u);
    EXPECT_EQ(m.placements[0].model[3], glm::dvec4(1e6, 1, 0.5, 1));
}

TEST(Gltf, MirroredAndNonUniformNodesBaked) {
    for (const json& scale : {json{-1, 1, 1}, json{1, 3, 1}}) {
        Builder b;
        const int mesh = b.triangle();
        b.scene({b.node({{"mesh", mesh}, {"scale", scale}, {"translation", {0, 0, 2}}})});
        const dsr::GltfModel m = parse(b.gltf());
        ASSERT_EQ(m.meshes.size(), 1u);
        ASSERT_EQ(m.placements.size(), 1u);
        EXPECT_EQ(m.placements[0].model, glm::dmat4(1.0)) << "placed at identity";
        const dsr::Mesh& mesh_out = m.meshes[0];
        const bool mirror = scale[0].get<double>() < 0;
        EXPECT_EQ(mesh_out.vertices[1].pos, mirror ? glm::vec3(-1, 0, 2) : glm::vec3(1, 0, 2));
        EXPECT_EQ(mesh_out.vertices[2].pos, mirror ? glm::vec3(0, 1, 2) : glm::vec3(0, 3, 2));
        EXPECT_EQ(mesh_out.indices, mirror ? std::vector<uint32_t>({0, 2, 1}) : std::vector<uint32_t>({0, 1, 2}))
            << "winding flipped where it mirrors";
        // The face normal from the (flipped) winding agrees with the baked normal.
        const glm::vec3 a = mesh_out.vertices[mesh_out.indices[0]].pos, bb = mesh_out.vertices[mesh_out.indices[1]].pos,
                        c = mesh_out.vertices[mesh_out.indices[2]].pos;
        EXPECT_GT(glm::dot(glm::cross(bb - a, c - a), mesh_out.vertices[0].normal), 0.0f);
    }
}

TEST(Gltf, NoScenesDrawsEveryRootWithAWarning) {
    Builder b;
    const int mesh = b.triangle();
    b.node({{"mesh", mesh}});
    b.node({{"mesh", mesh}, {"translation", {1, 0, 0}}});
    const dsr::GltfModel m = parse(b.gltf());
    EXPECT_EQ(m.placements.size(), 2u);
    EXPECT_EQ(count_holding(m.warnings, "no scenes: every root node is drawn"), 1);
}

TEST(Gltf, MaterialMappingFromMetallicRoughness) {
    Builder b;
    const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3");
    b.doc["materials"] = json::array({{{"name", "gold"},
                                       {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0.5, 0.25, 1}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.5}}},
                                       {"doubleSided", true}},
                                      {{"alphaMode", "MASK"}},
                                      {{"alphaMode", "MASK"}, {"alphaCutoff", 0.3}},
                                      {{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.4}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}}}});
    json prims = json::array();
    for (int k = 0; k < 4; ++k) prims.push_back({{"attributes", {{"POSITION", p}}}, {"material", k}});
    b.doc["meshes"] = json::array({{{"primitives", prims}}});
    b.scene({b.node({{"mesh", 0}})});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.materials.size(), 5u);
    const dsr::Material& gold = m.materials[0];
    EXPECT_EQ(gold.name, "m.gltf:gold");
    EXPECT_TRUE(gold.metal_rough()) << "glTF's own material model (docs/metal_rough.md)";
    EXPECT_EQ(gold.diffuse, glm::vec3(1, 0.5f, 0.25f)) << "the base colour";
    EXPECT_EQ(gold.metallic, 1.0f);
    EXPECT_EQ(gold.roughness, 0.5f);
    EXPECT_EQ(m.materials[1].name, "m.gltf:#1");
    EXPECT_EQ(m.materials[1].alpha_cutoff, 0.5f) << "MASK's default cutoff";
    EXPECT_EQ(m.materials[2].alpha_cutoff, 0.3f);
    EXPECT_EQ(m.materials[3].opacity, 0.4f);
    EXPECT_EQ(m.materials[3].roughness, 0.0f);
    EXPECT_EQ(m.materials[3].metallic, 0.0f);
    EXPECT_TRUE(m.materials[4].metal_rough()) << "the default material";
    EXPECT_EQ(m.materials[4].metallic, 1.0f);
    EXPECT_EQ(m.materials[4].roughness, 1.0f);
    ASSERT_EQ(m.meshes.size(), 4u);
    EXPECT_TRUE(m.meshes[0].two_sided);
    EXPECT_FALSE(m.meshes[1].two_sided);
    EXPECT_EQ(m.meshes[2].material, 2);
}

TEST(Gltf, TexturesSrgbSamplingAndMaps) {
    const string png = png_bytes(2, 2, {0.5f, 1.0f, 0.0f, 1.0f});
    json mat = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 0}}}, {"metallicFactor", 1.0}}},
                {"normalTexture", {{"index", 0}, {"scale", 2.0}}}};
    Builder b = textured_quad(mat, png, {{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9729}});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.textures.size(), 3u) << "one image in three roles";
    const dsr::Material& mt = m.materials[0];
    ASSERT_GE(mt.diffuse_map, 0);
    ASSERT_GE(mt.normal_map, 0);
    ASSERT_GE(mt.metallic_roughness_map, 0);
    EXPECT_EQ(mt.specular_map, -1);
    const auto& s = m.texture_sampling[size_t(mt.diffuse_map)];
    EXPECT_TRUE(s.srgb) << "base colour is sRGB-encoded";
    EXPECT_FALSE(m.texture_sampling[size_t(mt.normal_map)].srgb);
    EXPECT_FALSE(m.texture_sampling[size_t(mt.metallic_roughness_map)].srgb);
    EXPECT_EQ(s.wrap_s, dsr::TextureSampling::Wrap::clamp);
    EXPECT_EQ(s.wrap_t, dsr::TextureSampling::Wrap::mirror);
    EXPECT_TRUE(s.nearest_mag);
    EXPECT_FALSE(s.mipmaps);
    EXPECT_EQ(m.texture_paths[size_t(mt.diffuse_map)], "t/m.gltf#/images/0");
    // The normal map with scale 2 baked: (0, 1, -1) scaled to (0, 2, -1), normalised.
    const float* n = m.textures[size_t(mt.normal_map)].at(0, 0);
    EXPECT_NEAR(n[1], 2 / std::sqrt(5.0) * 0.5 + 0.5, 2e-3);
    // The metallic-roughness map as stored (roughness in green, metallic in blue): the shader reads it.
    EXPECT_EQ(m.textures[size_t(mt.metallic_roughness_map)].at(1, 1)[1], 1.0f);
    EXPECT_EQ(m.textures[size_t(mt.metallic_roughness_map)].at(1, 1)[2], 0.0f);
}

TEST(Gltf, TextureTransformBakedIntoUvs) {
    const string png = png_bytes(1, 1, {1, 1, 1, 1});
    json mat = {{"pbrMetallicRoughness",
                 {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"scale", {2, 2}}}}}}}}}}};
    Builder b = textured_quad(mat, png);
    const dsr::GltfModel m = parse(b.gltf());
    // glTF uv (1, 0) -> (2 * 1 + 0.5, 0) -> dsr (2.5, 1).
    EXPECT_EQ(m.meshes[0].vertices[2].uv, glm::vec2(2.5f, 1.0f));
    // glTF uv (0, 1) -> (0.5, 2) -> dsr (0.5, -1).
    EXPECT_EQ(m.meshes[0].vertices[0].uv, glm::vec2(0.5f, -1.0f));
}

TEST(Gltf, TexCoord1WhenTheBaseColourAsksForIt) {
    const string png = png_bytes(1, 1, {1, 1, 1, 1});
    Builder b = textured_quad({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}}, png);
    const int t1 = b.data(std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f}, kFloat, "VEC2");
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = t1;
    const dsr::GltfModel m = parse(b.gltf());
    EXPECT_EQ(m.meshes[0].vertices[3].uv, glm::vec2(0.25f, 0.75f));
}

TEST(Gltf, ExternalBufferAndImageThroughTheReader) {
    Builder b;
    b.scene({b.node({{"mesh", b.triangle()}})});
    json d = json::parse(b.gltf());
    d["buffers"][0]["uri"] = "data/m%20a.bin";
    d["images"] = json::array({{{"uri", "tex.png"}}});
    d["textures"] = json::array({{{"source", 0}}});
    d["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    d["meshes"][0]["primitives"][0]["material"] = 0;
    Files f;
    f.files["t/data/m a.bin"] = b.bin + "padding beyond byteLength";
    f.files["t/tex.png"] = png_bytes(1, 1, {1, 0, 0, 1});
    const dsr::GltfModel m = dsr::parse_gltf("t/m.gltf", d.dump(), f.options());
    EXPECT_EQ(m.triangles, 1u);
    EXPECT_EQ(m.inputs, (std::vector<string>{"t/data/m a.bin", "t/tex.png"}));
    EXPECT_EQ(m.texture_paths[0], "t/tex.png");
    EXPECT_EQ(m.textures[0].at(0, 0)[0], 1.0f);
}

TEST(Gltf, LightsPlacedByTheirNodes) {
    Builder b;
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array(
        {{{"type", "point"}, {"color", {1, 0.5, 0}}, {"intensity", 10}},
         {{"type", "spot"}, {"intensity", 100}, {"range", 2}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.5}}}},
         {{"type", "directional"}, {"intensity", 3}}});
    const int mesh = b.triangle();
    const double s = std::sqrt(0.5);
    b.scene({b.node({{"mesh", mesh}}), b.node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}),
             b.node({{"translation", {0, 5, 0}}, {"rotation", {-s, 0, 0, s}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}),
             b.node({{"rotation", {0, s, 0, s}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}})});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.lights.size(), 3u);
    const dsr::Light& pt = m.lights[0];
    EXPECT_EQ(pt.type, dsr::Light::Type::point);
    EXPECT_EQ(pt.pos, glm::vec3(1, 2, 3));
    EXPECT_EQ(pt.color, glm::vec3(10, 5, 0)) << "colour times candela";
    EXPECT_TRUE(pt.physical);
    EXPECT_FALSE(pt.attenuation);
    EXPECT_EQ(pt.range, 0.0f);
    EXPECT_NEAR(pt.radius, std::sqrt(10 * dsr::kPhysicalResponse / dsr::kPhysicalThreshold), 1e-2)
        << "where 10 / d^2 falls under the threshold";
    const dsr::Light& sp = m.lights[1];
    EXPECT_EQ(sp.type, dsr::Light::Type::spot);
    EXPECT_TRUE(sp.physical);
    EXPECT_EQ(sp.range, 2.0f);
    EXPECT_EQ(sp.radius, 2.0f) << "the range";
    EXPECT_NEAR(sp.angle_deg, glm::degrees(0.5), 1e-4);
    EXPECT_NEAR(sp.inner_deg, glm::degrees(0.1), 1e-4);
    EXPECT_NEAR(sp.dir.y, -1.0f, 1e-6) << "-Z turned down";
    const dsr::Light& dl = m.lights[2];
    EXPECT_EQ(dl.type, dsr::Light::Type::directional);
    EXPECT_TRUE(dl.physical);
    EXPECT_NEAR(dl.dir.x, -1.0f, 1e-6) << "-Z turned to -X";
    EXPECT_EQ(dl.color, glm::vec3(3));
}

TEST(Gltf, CamerasPlacedByTheirNodes) {
    Builder b;
    b.doc["cameras"] = json::array({{{"type", "perspective"}, {"name", "main"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.25}}}},
                                    {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
                                    {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 1}, {"zfar", 50}}}}});
    const int mesh = b.triangle();
    b.scene({b.node({{"mesh", mesh}}), b.node({{"camera", 0}, {"translation", {0, 0, 10}}}), b.node({{"camera", 1}}),
             b.node({{"camera", 2}, {"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}})});
    const dsr::GltfModel m = parse(b.gltf());
    ASSERT_EQ(m.cameras.size(), 2u);
    EXPECT_EQ(m.cameras[0].name, "main");
    EXPECT_EQ(m.cameras[0].camera.pos, glm::vec3(0, 0, 10));
    EXPECT_EQ(m.cameras[0].camera.target, glm::vec3(0, 0, 9));
    EXPECT_EQ(m.cameras[0].camera.up, glm::vec3(0, 1, 0));
    EXPECT_NEAR(m.cameras[0].camera.fov_deg, glm::degrees(0.5), 1e-4);
    EXPECT_EQ(m.cameras[0].camera.near_plane, 0.25f);
    EXPECT_FALSE(m.cameras[0].far_given);
    EXPECT_TRUE(m.cameras[1].far_given);
    EXPECT_EQ(m.cameras[1].camera.far_plane, 50.0f);
    EXPECT_NEAR(m.cameras[1].camera.target.x, -1.0f, 1e-6);
    EXPECT_EQ(count_holding(m.warnings, "orthographic camera skipped"), 1);
}

TEST(Gltf, SkinsMorphsAnimationsAndUnknownExtensionsWarned) {
    Builder b;
    b.doc["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform"};
    b.scene({b.node({{"mesh", b.triangle()}})});
    b.doc["meshes"][0]["primitives"][0]["targets"] = json::array({json::object()});
    b.doc["animations"] = json::array({{{"channels", json::array()}, {"samplers", json::array()}}});
    b.doc["skins"] = json::array({{{"joints", {0}}, {"inverseBindMatrices", 0}}});  // tinygltf 2.7 wants inverseBindMatrices
    const dsr::GltfModel m = parse(b.gltf());
    EXPECT_EQ(count_holding(m.warnings, "'KHR_materials_clearcoat' ignored"), 1);
    EXPECT_EQ(count_holding(m.warnings, "KHR_texture_transform"), 0);
    EXPECT_EQ(count_holding(m.warnings, "morph targets ignored"), 1);
    EXPECT_EQ(count_holding(m.warnings, "animations ignored"), 1);
    EXPECT_EQ(count_holding(m.warnings, "skins ignored"), 1);
}

TEST(Gltf, DecodeImageChecksTheHeaderFirst) {
    const dsr::Image img = dsr::decode_image(png_bytes(3, 2, {0, 0.5f, 1, 1}), "x.png");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 2);
    EXPECT_THROW(dsr::decode_image(header_only_png(4, 4), "y.png", 15), dsr::ImageTooLarge);
    try {
        dsr::decode_image(header_only_png(100000, 100000), "z.png");
        ADD_FAILURE();
    } catch (const dsr::Error& e) {
        EXPECT_NE(string(e.what()).find("cannot read image z.png: 100000 x 100000 pixels, expected at most"), string::npos) << e.what();
    }
    // Cut inside a chunk, or damaged: refused from the chunk walk before the decoder reads past
    // the end (a fuzz finding: OpenImageIO's PNG reader leaked its message there).
    const string good = png_bytes(8, 8, {1, 0, 0, 1});
    for (const string& bad : {good.substr(0, good.size() - 20), good.substr(0, 40), good.substr(0, good.size() - 12)}) {
        try {
            dsr::decode_image(bad, "cut.png");
            ADD_FAILURE();
        } catch (const dsr::Error& e) {
            EXPECT_NE(string(e.what()).find("cannot read image cut.png: cut short"), string::npos) << e.what();
        }
    }
    string damaged = good;
    damaged[good.size() - 30] ^= 0x55;
    EXPECT_THROW(dsr::decode_image(damaged, "bad.png"), dsr::Error);
    try {
        dsr::decode_image("GIF89a....", "w.gif");
        ADD_FAILURE();
    } catch (const dsr::Error& e) {
        EXPECT_NE(string(e.what()).find("cannot read image w.gif: expected PNG"), string::npos) << e.what();
    }
}

// ---- bad input: one line with the JSON pointer ----------------------------------------------

struct Bad {
    string name;
    std::function<string()> file;
    string expect;
};

Builder one_triangle() {
    Builder b;
    b.scene({b.node({{"mesh", b.triangle()}})});
    return b;
}

string with(std::function<void(json&)> edit) {
    json d = json::parse(one_triangle().gltf());
    edit(d);
    return d.dump();
}

TEST(Gltf, BadFilesOneLineWithThePointer) {
    const std::vector<Bad> cases = {
        {"accessor out of bounds", [] { return with([](json& d) { d["accessors"][0]["count"] = 4; }); },
         "t/m.gltf: /accessors/0: expected 4 elements of 12 bytes, 12 apart from byte 0, within buffer view 0's 36 bytes"},
        {"accessor offset overflow", [] { return with([](json& d) { d["accessors"][0]["byteOffset"] = 2147483647; }); },
         "t/m.gltf: /accessors/0: expected 3 elements of 12 bytes"},
        {"view beyond buffer", [] { return with([](json& d) { d["bufferViews"][0]["byteLength"] = 1000; }); },
         "t/m.gltf: /bufferViews/0: expected bytes within buffer 0's 72, got byteLength 1000 at byteOffset 0"},
        {"huge count", [] { return with([](json& d) { d["accessors"][0]["count"] = 2000000000; }); },
         "t/m.gltf: /accessors/0/count: expected a count in [1, 20000000], got 2000000000 (an absurd size)"},
        {"index out of range",
         [] {
             Builder b;
             const int p = b.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3");
             const int i = b.data(std::vector<uint16_t>{0, 1, 3}, kUShort, "SCALAR");
             b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}}, i)}})});
             return b.gltf();
         },
         "t/m.gltf: /accessors/1: expected vertex indices below POSITION's count 3 (for /meshes/0/primitives/0/indices), got 3 at 2"},
        {"node cycle", [] { return with([](json& d) { d["nodes"][0]["children"] = {1}; d["nodes"].push_back({{"children", {0}}}); d["scenes"][0]["nodes"] = json::array(); }); },
         "t/m.gltf: /nodes/"},
        {"node its own child", [] { return with([](json& d) { d["nodes"][0]["children"] = {0}; }); },
         "t/m.gltf: /nodes/0/children/0: expected another node, got the node itself (a cycle)"},
        {"two parents", [] { return with([](json& d) { d["nodes"].push_back({{"children", {0}}}); d["nodes"].push_back({{"children", {0}}}); }); },
         "t/m.gltf: /nodes/2/children/0: expected a node with one parent, got node 0, already a child of node 1"},
        {"root with a parent", [] { return with([](json& d) { d["nodes"].push_back({{"children", {0}}}); }); },
         "t/m.gltf: /scenes/0/nodes/0: expected a root node, got node 0, a child of node 1"},
        {"required draco", [] { return with([](json& d) { d["extensionsRequired"] = {"KHR_draco_mesh_compression"}; }); },
         "t/m.gltf: /extensionsRequired/0: the file requires 'KHR_draco_mesh_compression', which dsr does not read"},
        {"glTF 1.0", [] { return with([](json& d) { d["asset"]["version"] = "1.0"; }); }, "t/m.gltf: glTF 1.0 is not read; dsr reads glTF 2.0"},
        {"light range 0",
         [] {
             return with([](json& d) {
                 d["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"range", 0}}};
                 d["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
             });
         },
         "t/m.gltf: /extensions/KHR_lights_punctual/lights/0/range: expected a number in [1e-12, 1e12], got 0"},
        {"glTF 1.0 dictionaries", [] { return string(R"({"meshes": {"m": {}}, "nodes": {}})"); }, "t/m.gltf: glTF 1.0 is not read; dsr reads glTF 2.0"},
        {"bad base64", [] { return with([](json& d) { string u = d["buffers"][0]["uri"]; u[40] = '!'; d["buffers"][0]["uri"] = u; }); },
         "t/m.gltf: /buffers/0/uri: expected base64 data, got '!' at character 41"},
        {"wrong type", [] { return with([](json& d) { d["accessors"][0]["count"] = "3"; }); },
         "t/m.gltf: /accessors/0/count: expected an integer in [0, 2147483647], got the string '3'"},
        {"float index", [] { return with([](json& d) { d["nodes"][0]["mesh"] = 0.5; }); },
         "t/m.gltf: /nodes/0/mesh: expected an integer in [0, 2147483647], got 0.5"},
        {"integer too large", [] { return with([](json& d) { d["nodes"][0]["mesh"] = 4294967296ull; }); },
         "t/m.gltf: /nodes/0/mesh: expected an integer in [0, 2147483647], got 4294967296"},
        {"mesh index", [] { return with([](json& d) { d["nodes"][0]["mesh"] = 7; }); }, "t/m.gltf: /nodes/0/mesh: expected a mesh index below 1, got 7"},
        {"infinite position",
         [] {
             Builder b;
             const int p = b.data(std::vector<float>{0, 0, 0, INFINITY, 0, 0, 0, 1, 0}, kFloat, "VEC3");
             b.scene({b.node({{"mesh", b.mesh({{"POSITION", p}})}})});
             return b.gltf();
         },
         "t/m.gltf: /accessors/0: expected finite numbers (for /meshes/0/primitives/0/attributes/POSITION), got inf in element 1"},
        {"missing buffer file", [] { return with([](json& d) { d["buffers"][0]["uri"] = "gone.bin"; }); },
         "t/m.gltf: /buffers/0/uri: expected a readable buffer file, got 'gone.bin': cannot open t/gone.bin: no such file"},
        {"not JSON", [] { return string("{\"asset\": "); }, "t/m.gltf: expected JSON, got: "},
        {"deep JSON", [] { return string(100, '[') + string(100, ']'); }, "t/m.gltf: expected JSON nested at most 64 deep"},
        {"bad alpha mode", [] { return with([](json& d) { d["materials"] = json::array({{{"alphaMode", "CLIP"}}}); d["meshes"][0]["primitives"][0]["material"] = 0; }); },
         "t/m.gltf: /materials/0/alphaMode: expected OPAQUE, MASK or BLEND, got 'CLIP'"},
        {"image too large",
         [] {
             return with([](json& d) {
                 d["images"] = json::array({{{"uri", "data:image/png;base64," + base64(header_only_png(16384, 16384))}}});
                 d["textures"] = json::array({{{"source", 0}}});
                 d["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
                 d["meshes"][0]["primitives"][0]["material"] = 0;
             });
         },
         "t/m.gltf: /images/0: expected a readable image for /materials/0/pbrMetallicRoughness/baseColorTexture, got: cannot read "
         "image t/m.gltf#/images/0: 16384 x 16384 pixels, expected at most 16384 a side and 67108864 in all (an absurd size)"},
        {"deep hierarchy",
         [] {
             return with([](json& d) {
                 for (int i = 1; i <= 300; ++i) d["nodes"].push_back({{"children", {i - 1}}});
                 d["scenes"][0]["nodes"] = {300};
             });
         },
         "expected a node hierarchy at most 256 deep"},
    };
    for (const Bad& c : cases) {
        SCOPED_TRACE(c.name);
        const string e = error_of(c.file());
        EXPECT_NE(e.find(c.expect), string::npos) << e;
    }
}

TEST(Gltf, TriangleBudget) {
    Builder b;
    const int mesh = b.triangle();
    b.scene({b.node({{"mesh", mesh}}), b.node({{"mesh", mesh}})});
    dsr::GltfOptions o = Files{}.options();
    o.max_triangles = 1;
    const string e = error_of(b.gltf(), o);
    EXPECT_NE(e.find("t/m.gltf: /nodes/1: expected at most 1 triangles, got more with mesh 0 drawn here"), string::npos) << e;
}

string glb_error(const string& bytes) {
    try {
        dsr::parse_gltf("t/m.glb", bytes, Files{}.options());
    } catch (const dsr::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected an error";
    return "";
}

TEST(Gltf, BadGlbChunks) {
    const string good = one_triangle().glb();
    ASSERT_NO_THROW(dsr::parse_gltf("t/m.glb", good, Files{}.options()));
    EXPECT_NE(glb_error(good.substr(0, good.size() - 8)).find("t/m.glb: expected the .glb header's length"), string::npos);
    string lie = good;
    lie.replace(12, 4, le32(1u << 30));
    EXPECT_NE(glb_error(lie).find("expected a JSON chunk within the file's"), string::npos) << glb_error(lie);
    string bin_lie = good;
    const uint32_t json_len = uint32_t((unsigned char)good[12]) | uint32_t((unsigned char)good[13]) << 8;
    bin_lie.replace(20 + json_len, 4, le32(0xFFFFFFF0u));
    EXPECT_NE(glb_error(bin_lie).find("expected a BIN chunk within the file's"), string::npos) << glb_error(bin_lie);
    EXPECT_NE(glb_error("glTF" + le32(1) + le32(12)).find("glTF 1.0 is not read"), string::npos);
    EXPECT_NE(glb_error("glTF").find("expected a 12-byte .glb header"), string::npos);
}

TEST(Gltf, FilesOnDisk) {
    const fs::path dir = fs::temp_directory_path() / ("dsr-gltf-disk-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    Builder b = one_triangle();
    {
        std::ofstream((dir / "m.glb").string(), std::ios::binary) << b.glb();
    }
    const dsr::GltfModel m = dsr::load_gltf((dir / "m.glb").string());
    EXPECT_EQ(m.triangles, 1u);
    EXPECT_EQ(m.inputs, std::vector<string>{(dir / "m.glb").string()});
    json d = json::parse(b.gltf());
    d["buffers"][0]["uri"] = "fifo.bin";
    {
        std::ofstream((dir / "f.gltf").string()) << d.dump();
    }
    ASSERT_EQ(::mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
    try {
        dsr::load_gltf((dir / "f.gltf").string());
        ADD_FAILURE();
    } catch (const dsr::Error& e) {
        EXPECT_NE(string(e.what()).find("/buffers/0/uri: expected a readable buffer file, got 'fifo.bin': cannot open glTF buffer or image"), string::npos) << e.what();
        EXPECT_NE(string(e.what()).find("expected a regular file, got a FIFO"), string::npos) << e.what();
    }
    fs::remove_all(dir);
}

// ---- Debian's assimp-testmodels ---------------------------------------------------------------

TEST(Gltf, AssimpTestModels) {
    const string root = "/usr/share/assimp/models/";
    if (!fs::exists(root + "glTF2")) GTEST_SKIP() << "assimp-testmodels is not installed";
    // Every file: "" loads; otherwise a part of the one line it is refused with.
    const std::map<string, string> expect = {
        {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", "glTF 1.0 is not read; dsr reads glTF 2.0"},
        {"glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf", "glTF 1.0 is not read"},
        {"glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", "glTF 1.0 is not read"},
        {"glTF/BoxTextured-glTF/BoxTextured.gltf", "glTF 1.0 is not read"},
        {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "glTF 1.0 is not read"},
        {"glTF/IncorrectVertexArrays/Cube_v1.gltf", "glTF 1.0 is not read"},
        {"glTF/TwoBoxes/TwoBoxes.gltf", "glTF 1.0 is not read"},
        {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", ""},
        {"glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb", ""},
        {"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", ""},
        {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", ""},
        {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", ""},
        {"glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", ""},
        {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "/extensionsRequired/0: the file requires 'KHR_technique_webgl'"},
        {"glTF2/BoxTextured-glTF/BoxTextured.gltf", ""},
        {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "/accessors/2: expected finite numbers (for /meshes/0/primitives/0/attributes/POSITION)"},
        {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", ""},
        {"glTF2/IncorrectVertexArrays/Cube.gltf", ""},
        {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "/accessors/0: expected vertex indices below POSITION's count 24"},
        {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "/accessors/0: expected vertex indices below POSITION's count 24"},
        {"glTF2/MissingBin/BoxTextured.gltf", "/buffers/0/uri: expected a readable buffer file, got 'BoxTextured0.bin'"},
        {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "expected a tree, got a cycle through node"},
        {"glTF2/SchemaFailures/sceneWrongType.gltf", "/scene: expected an integer in [0, 2147483647], got the string 'hello'"},
        {"glTF2/TestNoRootNode/NoScene.gltf", "expected at least one triangle in the default scene, got none"},
        {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", "expected at least one triangle in the default scene, got none"},
        {"glTF2/cameras/Cameras.gltf", ""},
        {"glTF2/draco/2CylinderEngine.gltf", "/extensionsRequired/0: the file requires 'KHR_draco_mesh_compression'"},
        {"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", ""},
        {"glTF2/issue_3269/texcoord_crash.gltf", ""},
        {"glTF2/simple_skin/simple_skin.gltf", ""},
        {"glTF2/textureTransform/TextureTransformTest.gltf", ""},
        {"glTF2/wrongTypes/badArray.gltf", "/meshes/0/primitives: expected an array of objects, got an object"},
        {"glTF2/wrongTypes/badExtension.gltf", "KHR_texture_transform: expected an object, got the string 'Not an object'"},
        {"glTF2/wrongTypes/badNumber.gltf", "/materials/0/normalTexture: expected a member 'index', got none"},
        {"glTF2/wrongTypes/badObject.gltf", "/materials/0/pbrMetallicRoughness: expected an object, got an array of 1"},
        {"glTF2/wrongTypes/badString.gltf", "/scenes/0/name: expected a string, got 42"},
        {"glTF2/wrongTypes/badUint.gltf", "/baseColorTexture/index: expected an integer in [0, 2147483647], got -1"},
    };
    for (int mode = 0; mode < 16; ++mode) {
        char name[96];
        std::snprintf(name, sizeof name, "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_%02d.gltf", mode);
        const bool drawn = mode >= 4 && mode <= 6 ? true : mode >= 11;
        const_cast<std::map<string, string>&>(expect)[name] = drawn ? "" : "expected at least one triangle in the default scene, got none (only";
    }
    int seen = 0;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        const string p = e.path().string();
        if (!e.is_regular_file() || !dsr::is_gltf_path(p)) continue;
        const string rel = p.substr(root.size());
        if (rel.compare(0, 5, "glTF/") != 0 && rel.compare(0, 6, "glTF2/") != 0) continue;
        ++seen;
        auto it = expect.find(rel);
        if (it == expect.end()) {
            ADD_FAILURE() << "no expectation for " << rel;
            continue;
        }
        try {
            const dsr::GltfModel m = dsr::load_gltf(p);
            EXPECT_EQ(it->second, "") << rel << " loaded";
            EXPECT_GT(m.triangles, 0u) << rel;
        } catch (const dsr::Error& err) {
            const string msg = err.what();
            EXPECT_FALSE(it->second.empty()) << rel << ": " << msg;
            EXPECT_NE(msg.find(it->second), string::npos) << rel << ": " << msg;
            EXPECT_EQ(msg.compare(0, p.size() + 2, p + ": "), 0) << "names the file: " << msg;
            EXPECT_EQ(msg.find('\n'), string::npos) << msg;
        }
    }
    EXPECT_EQ(seen, int(expect.size()));
}

TEST(Gltf, AssimpModelsDetails) {
    const string root = "/usr/share/assimp/models/glTF2/";
    if (!fs::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
    const dsr::GltfModel engine = dsr::load_gltf(root + "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    EXPECT_EQ(engine.triangles, 121496u);
    EXPECT_LT(engine.meshes.size(), engine.placements.size()) << "instanced";
    ASSERT_EQ(engine.cameras.size(), 1u);
    const dsr::GltfModel box = dsr::load_gltf(root + "BoxTextured-glTF/BoxTextured.gltf");
    ASSERT_EQ(box.textures.size(), 1u);
    EXPECT_EQ(box.texture_paths[0], root + "BoxTextured-glTF/CesiumLogoFlat.png");
    EXPECT_TRUE(box.texture_sampling[0].srgb);
    EXPECT_EQ(box.inputs.size(), 3u) << "the .gltf, its .bin and its image";
}

}  // namespace
