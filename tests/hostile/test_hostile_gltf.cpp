// Hostile glTF files and the buffers and images they name, rendered as models (`dsr render
// m.gltf`): the file rules of user_file.h, then the glTF reader's checks, each one line naming the
// file and the JSON pointer (docs/gltf.md, "Limits and refusals").
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;
using nlohmann::json;

std::string b64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = unsigned((unsigned char)in[i]) << 16 | unsigned((unsigned char)in[i + 1]) << 8 | (unsigned char)in[i + 2];
        out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += t[v & 63];
    }
    if (i + 1 == in.size()) {
        const unsigned v = unsigned((unsigned char)in[i]) << 16;
        out += t[v >> 18], out += t[(v >> 12) & 63], out += "==";
    } else if (i + 2 == in.size()) {
        const unsigned v = unsigned((unsigned char)in[i]) << 16 | unsigned((unsigned char)in[i + 1]) << 8;
        out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += '=';
    }
    return out;
}

std::string le32(unsigned v) { return {char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; }

std::string floats(std::vector<float> v) { return std::string(reinterpret_cast<const char*>(v.data()), v.size() * 4); }

// One triangle: positions in view 0 (accessor 0), normals in view 1 (accessor 1); the buffer is
// returned in `bin`.
json triangle(std::string& bin, float x = 1) {
    bin = floats({0, 0, 0, x, 0, 0, 0, 1, 0}) + floats({0, 0, 1, 0, 0, 1, 0, 0, 1});
    return json{{"asset", {{"version", "2.0"}}},
                {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 36}}}},
                {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                               {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
                {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}}}}}}},
                {"nodes", {{{"mesh", 0}}}},
                {"scenes", {{{"nodes", {0}}}}}};
}

// The triangle as .gltf text with its buffer as a data: URI, after `edit`.
std::string gltf(std::function<void(json&)> edit = nullptr, float x = 1) {
    std::string bin;
    json d = triangle(bin, x);
    d["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + b64(bin)}}};
    if (edit) edit(d);
    return d.dump();
}

std::string glb() {
    std::string bin;
    json d = triangle(bin);
    d["buffers"] = {{{"byteLength", bin.size()}}};
    std::string j = d.dump();
    while (j.size() % 4) j += ' ';
    return "glTF" + le32(2) + le32(unsigned(28 + j.size() + bin.size())) + le32(unsigned(j.size())) + "JSON" + j +
           le32(unsigned(bin.size())) + std::string("BIN\0", 4) + bin;
}

Case model(const std::string& name, const std::string& file, std::function<void(D)> setup, const std::string& expect) {
    return {name, setup, "render " + file + " --size 16x16 -o out.png", expect};
}
Case text(const std::string& name, const std::string& content, const std::string& expect) {
    return model(name, "m.gltf", [content](D d) { write(d, "m.gltf", content); }, expect);
}

std::vector<Case> cases() {
    std::vector<Case> c;
    // ---- not a file, not readable
    c.push_back(model("gltf_fifo", "m.gltf", [](D d) { fifo(d, "m.gltf"); }, "m.gltf: expected a regular file, got a FIFO"));
    c.push_back(model("glb_to_dev_zero", "m.glb", [](D d) { symlink_to(d, "m.glb", "/dev/zero"); }, "m.glb: expected a regular file, got a character device"));
    c.push_back(model("buffer_missing", "m.gltf", [](D d) { write(d, "m.gltf", gltf([](json& j) { j["buffers"][0]["uri"] = "gone.bin"; })); },
                      "m.gltf: /buffers/0/uri: expected a readable buffer file, got 'gone.bin': cannot open glTF buffer or image gone.bin: No such file or directory"));
    c.push_back(model("buffer_fifo", "m.gltf", [](D d) { write(d, "m.gltf", gltf([](json& j) { j["buffers"][0]["uri"] = "b.bin"; })); fifo(d, "b.bin"); },
                      "m.gltf: /buffers/0/uri: expected a readable buffer file, got 'b.bin': cannot open glTF buffer or image b.bin: expected a regular file, got a FIFO"));
    c.push_back(model("buffer_dev_zero", "m.gltf", [](D d) { write(d, "m.gltf", gltf([](json& j) { j["buffers"][0]["uri"] = "b.bin"; })); symlink_to(d, "b.bin", "/dev/zero"); },
                      "m.gltf: /buffers/0/uri: expected a readable buffer file, got 'b.bin': cannot open glTF buffer or image b.bin: expected a regular file, got a character device"));
    c.push_back(model("buffer_short", "m.gltf", [](D d) { write(d, "m.gltf", gltf([](json& j) { j["buffers"][0]["uri"] = "b.bin"; })); write(d, "b.bin", "short"); },
                      "m.gltf: tinygltf: File size mismatch"));
    c.push_back(text("gltf_nul_byte", std::string("{\"asset\"\0:1}", 12), "m.gltf:1: expected text, got a NUL byte at column 9"));
    // ---- .glb chunks
    c.push_back(model("glb_truncated", "m.glb", [](D d) { write(d, "m.glb", glb().substr(0, 100)); },
                      "m.glb: expected the .glb header's length"));
    c.push_back(model("glb_json_chunk_lies", "m.glb", [](D d) { std::string g = glb(); g.replace(12, 4, le32(1u << 30)); write(d, "m.glb", g); },
                      "m.glb: expected a JSON chunk within the file's"));
    c.push_back(model("glb_bin_chunk_lies", "m.glb", [](D d) {
                          std::string g = glb();
                          const unsigned j = unsigned((unsigned char)g[12]) | unsigned((unsigned char)g[13]) << 8;
                          g.replace(20 + j, 4, le32(0xFFFFFFF0u));
                          write(d, "m.glb", g);
                      },
                      "m.glb: expected a BIN chunk within the file's"));
    c.push_back(model("glb_version_1", "m.glb", [](D d) { write(d, "m.glb", "glTF" + le32(1) + le32(20) + le32(0) + "JSON"); },
                      "m.glb: glTF 1.0 is not read; dsr reads glTF 2.0"));
    // ---- JSON
    c.push_back(text("not_json", "{\"asset\": ", "m.gltf: expected JSON, got: "));
    c.push_back(text("json_too_deep", std::string(10000, '[') + std::string(10000, ']'), "m.gltf: expected JSON nested at most 64 deep, got more at byte 65 (an absurd size)"));
    c.push_back(text("wrong_json_type", gltf([](json& j) { j["accessors"][0]["count"] = "3"; }),
                     "m.gltf: /accessors/0/count: expected an integer in [0, 2147483647], got the string '3'"));
    c.push_back(text("integer_wraps", gltf([](json& j) { j["nodes"][0]["mesh"] = 4294967296ull; }),
                     "m.gltf: /nodes/0/mesh: expected an integer in [0, 2147483647], got 4294967296"));
    c.push_back(text("gltf_1_0", gltf([](json& j) { j["asset"]["version"] = "1.0"; }), "m.gltf: glTF 1.0 is not read; dsr reads glTF 2.0"));
    c.push_back(text("required_draco", gltf([](json& j) { j["extensionsRequired"] = {"KHR_draco_mesh_compression"}; }),
                     "m.gltf: /extensionsRequired/0: the file requires 'KHR_draco_mesh_compression', which dsr does not read"));
    c.push_back(text("bad_base64", gltf([](json& j) { std::string u = j["buffers"][0]["uri"]; u[45] = '*'; j["buffers"][0]["uri"] = u; }),
                     "m.gltf: /buffers/0/uri: expected base64 data, got '*' at character 46"));
    // ---- accessors and indices
    c.push_back(text("accessor_out_of_bounds", gltf([](json& j) { j["accessors"][0]["count"] = 4; }),
                     "m.gltf: /accessors/0: expected 4 elements of 12 bytes, 12 apart from byte 0, within buffer view 0's 36 bytes"));
    c.push_back(text("accessor_offset_overflow", gltf([](json& j) { j["accessors"][0]["byteOffset"] = 2147483647; }),
                     "m.gltf: /accessors/0: expected 3 elements of 12 bytes"));
    c.push_back(text("view_beyond_buffer", gltf([](json& j) { j["bufferViews"][1]["byteLength"] = 100000; }),
                     "m.gltf: /bufferViews/1: expected bytes within buffer 0's 72, got byteLength 100000 at byteOffset 36"));
    c.push_back(text("huge_count", gltf([](json& j) { j["accessors"][0]["count"] = 2000000000; }),
                     "m.gltf: /accessors/0/count: expected a count in [1, 20000000], got 2000000000 (an absurd size)"));
    c.push_back(text("index_out_of_range", gltf([](json& j) {
                         j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 12}, {"byteLength", 6}});  // 0, 16256, 0
                         j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
                         j["meshes"][0]["primitives"][0]["indices"] = 2;
                     }),
                     "m.gltf: /accessors/2: expected vertex indices below POSITION's count 3 (for /meshes/0/primitives/0/indices)"));
    c.push_back(text("infinite_position", gltf(nullptr, INFINITY),
                     "m.gltf: /accessors/0: expected finite numbers (for /meshes/0/primitives/0/attributes/POSITION), got inf in element 1"));
    c.push_back(text("huge_position", gltf(nullptr, 1e30f), "m.gltf: /accessors/0: expected positions within +-1e12, got 1.00000002e+30 in element 1"));
    // ---- nodes
    c.push_back(text("node_cycle", gltf([](json& j) {
                         j["nodes"] = {{{"mesh", 0}}, {{"children", {2}}}, {{"children", {1}}}};
                     }),
                     "m.gltf: /nodes/2/children: expected a tree, got a cycle through node 1"));
    c.push_back(text("node_own_child", gltf([](json& j) { j["nodes"][0]["children"] = {0}; }),
                     "m.gltf: /nodes/0/children/0: expected another node, got the node itself (a cycle)"));
    c.push_back(text("node_two_parents", gltf([](json& j) { j["nodes"].push_back({{"children", {0}}}); j["nodes"].push_back({{"children", {0}}}); }),
                     "m.gltf: /nodes/2/children/0: expected a node with one parent, got node 0, already a child of node 1"));
    c.push_back(text("node_too_deep", gltf([](json& j) {
                         for (int i = 1; i <= 300; ++i) j["nodes"].push_back({{"children", {i - 1}}});
                         j["scenes"][0]["nodes"] = {300};
                     }),
                     "expected a node hierarchy at most 256 deep, got deeper (an absurd size)"));
    // ---- images
    auto textured = [](const std::string& uri) {
        return gltf([uri](json& j) {
            j["images"] = {{{"uri", uri}}};
            j["textures"] = {{{"source", 0}}};
            j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
            j["meshes"][0]["primitives"][0]["material"] = 0;
        });
    };
    c.push_back(model("image_header_absurd", "m.gltf", [textured](D d) { write(d, "m.gltf", textured("t.png")); header_only_png(d, "t.png", 20000, 20); },
                      "m.gltf: /images/0: expected a readable image for /materials/0/pbrMetallicRoughness/baseColorTexture, got: cannot read image t.png: 20000 x 20 pixels, expected at most 16384 a side"));
    c.push_back(model("image_fifo", "m.gltf", [textured](D d) { write(d, "m.gltf", textured("t.png")); fifo(d, "t.png"); },
                      "m.gltf: /images/0/uri: expected a readable image file, got 't.png': cannot open glTF buffer or image t.png: expected a regular file, got a FIFO"));
    c.push_back(model("image_truncated", "m.gltf", [textured](D d) {
                          write(d, "m.gltf", textured("t.png"));
                          image(d, "full.png", 64, 64);
                          truncated(d, "t.png", "full.png", -20);
                      },
                      "m.gltf: /images/0: expected a readable image for /materials/0/pbrMetallicRoughness/baseColorTexture, got: cannot read image t.png:"));
    c.push_back(text("image_not_png", textured("data:image/png;base64," + b64("GIF89a not a png")),
                     "m.gltf: /images/0: expected a readable image for /materials/0/pbrMetallicRoughness/baseColorTexture, got: cannot read image m.gltf#/images/0: expected PNG"));
    c.push_back(text("image_uri_scheme", textured("http://example.com/t.png"),
                     "m.gltf: /images/0/uri: expected a relative file name or a data URI, got 'http://example.com/t.png'"));
    return c;
}

INSTANTIATE_TEST_SUITE_P(Gltf, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
