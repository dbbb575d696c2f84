// glTF 2.0 loading (gltf_loader.h): the glue. The file's bytes (a .glb's chunks checked here
// first), the JSON checked raw (gltf_json.cpp), tinygltf reading buffers through dsr's file
// reader, then materials, the node hierarchy, meshes and placements, cameras and lights, each
// checked again where it is used.
#include "scene/gltf_loader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

#include "scene/gltf_internal.h"
#include "scene/user_file.h"

namespace dsr {

using std::string;

namespace gltf {

void Context::fail(const string& pointer, const string& what) const {
    throw Error(path + ": " + pointer + ": " + what);
}

void Context::warn(const string& pointer, const string& what) { out.warnings.push_back(path + ": " + pointer + ": " + what); }

void Context::warn_once(const string& key, const string& pointer, const string& what) {
    if (warned.insert(key).second) warn(pointer, what);
}

const nlohmann::json* Context::at(const string& pointer) const {
    try {
        const nlohmann::json::json_pointer p(pointer);
        return doc.contains(p) ? &doc.at(p) : nullptr;
    } catch (const std::exception&) {
        return nullptr;
    }
}

}  // namespace gltf

namespace {

namespace fs = std::filesystem;
using gltf::Context;
using gltf::kMaxGltfBytes;

// A binary file through user_file.h's checks (regular, at most kMaxGltfBytes), read whole.
string read_binary(const string& path, const string& what) { return read_user_bytes(path, what, kMaxGltfBytes); }

uint32_t le32(const string& b, size_t at) {
    return uint32_t((unsigned char)b[at]) | uint32_t((unsigned char)b[at + 1]) << 8 |
           uint32_t((unsigned char)b[at + 2]) << 16 | uint32_t((unsigned char)b[at + 3]) << 24;
}

// A .glb's chunks (glTF 2.0, 4.4): every length checked against the file before tinygltf reads it.
struct Glb {
    string json;
    long long bin_size = -1;
};
Glb check_glb(const string& path, const string& b) {
    auto fail = [&](const string& what) -> void { throw Error(path + ": " + what); };
    if (b.size() < 12) fail("expected a 12-byte .glb header, got " + std::to_string(b.size()) + " bytes");
    const uint32_t version = le32(b, 4), length = le32(b, 8);
    if (version == 1) fail("glTF 1.0 is not read; dsr reads glTF 2.0");
    if (version != 2) fail("expected .glb version 2, got " + std::to_string(version));
    if (length != b.size())
        fail("expected the .glb header's length " + std::to_string(length) + " to be the file's size " + std::to_string(b.size()));
    if (b.size() < 20) fail("expected a JSON chunk after the .glb header, got " + std::to_string(b.size() - 12) + " bytes");
    const uint64_t json_len = le32(b, 12);
    if (le32(b, 16) != 0x4E4F534Au) fail("expected the first chunk to be JSON, got another type");
    if (json_len == 0 || 20 + json_len > b.size())
        fail("expected a JSON chunk within the file's " + std::to_string(b.size()) + " bytes, got a length of " +
             std::to_string(json_len) + " at byte 12");
    if (json_len % 4 != 0) fail("expected a JSON chunk length that is a multiple of 4, got " + std::to_string(json_len));
    Glb g;
    g.json = b.substr(20, size_t(json_len));
    const uint64_t at = 20 + json_len;
    if (at == b.size()) return g;
    if (at + 8 > b.size()) fail("expected an 8-byte chunk header at byte " + std::to_string(at) + ", got " + std::to_string(b.size() - at) + " bytes");
    const uint64_t bin_len = le32(b, size_t(at));
    if (le32(b, size_t(at + 4)) != 0x004E4942u) fail("expected the second chunk to be BIN, got another type");
    if (bin_len == 0 || at + 8 + bin_len > b.size())
        fail("expected a BIN chunk within the file's " + std::to_string(b.size()) + " bytes, got a length of " +
             std::to_string(bin_len) + " at byte " + std::to_string(at));
    if (bin_len % 4 != 0) fail("expected a BIN chunk length that is a multiple of 4, got " + std::to_string(bin_len));
    g.bin_size = (long long)bin_len;
    return g;
}

// tinygltf's file system: every buffer file through GltfOptions::read_file, cut to its byteLength
// (glTF allows a longer file; tinygltf wants the exact size). The k-th read is the k-th buffer
// with a file URI: tinygltf reads buffers in order and stops at the first failure.
struct FsState {
    const GltfOptions* options = nullptr;
    std::vector<std::pair<size_t, uint64_t>> files;  // (buffer index, byteLength), in order
    size_t next = 0;
    string failed_path, failed_why;
    size_t failed_buffer = 0;
    std::vector<string> read;
};

bool fs_exists(const string&, void*) { return true; }
string fs_expand(const string& p, void*) { return p; }
bool fs_write(string*, const string&, const std::vector<unsigned char>&, void*) { return false; }
bool fs_read(std::vector<unsigned char>* out, string* err, const string& path, void* user) {
    auto* st = static_cast<FsState*>(user);
    const size_t k = st->next++;
    try {
        string data = st->options->read_file(path);
        st->read.push_back(path);
        if (k < st->files.size() && data.size() > st->files[k].second) data.resize(size_t(st->files[k].second));
        out->assign(data.begin(), data.end());
        return true;
    } catch (const std::exception& e) {
        if (st->failed_path.empty()) {
            st->failed_path = path;
            st->failed_why = e.what();
            st->failed_buffer = k < st->files.size() ? st->files[k].first : 0;
        }
        if (err) *err = e.what();
        return false;
    }
}

// Images are decoded later by decode_image: tinygltf only hands over the bytes of embedded ones.
bool keep_image_bytes(tinygltf::Image* image, const int, string*, string*, int, int, const unsigned char* bytes, int size,
                      void*) {
    if (size < 0) return false;
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

string first_line(string s) {
    const size_t nl = s.find('\n');
    if (nl != string::npos) s.resize(nl);
    return one_line(s);
}

}  // namespace

bool is_gltf_path(const string& path) {
    string ext = image_extension(path);
    return ext == ".gltf" || ext == ".glb";
}

GltfModel load_gltf(const string& path, const GltfOptions& options) {
    const string bytes = options.read_file ? options.read_file(path) : read_binary(path, "glTF file");
    GltfModel m = parse_gltf(path, bytes, options);
    m.inputs.insert(m.inputs.begin(), path);
    return m;
}

GltfModel parse_gltf(const string& path, const string& bytes, const GltfOptions& options_in) {
    GltfOptions options = options_in;
    if (!options.read_file) options.read_file = [](const string& p) { return read_binary(p, "glTF buffer or image"); };
    GltfModel out;
    out.path = path;
    const string dir = fs::path(path).parent_path().string();
    if (bytes.size() > kMaxGltfBytes)
        throw Error(path + ": expected at most " + std::to_string(kMaxGltfBytes) + " bytes, got " + std::to_string(bytes.size()));

    const bool binary = bytes.compare(0, 4, "glTF") == 0;
    Glb glb;
    if (binary) glb = check_glb(path, bytes);
    const string& text = binary ? glb.json : bytes;
    if (!binary) {
        string checked = text;
        check_user_text(path, checked);
    }

    // The raw JSON: depth, then parsed and checked before tinygltf sees it.
    gltf::check_json_depth(path, text);
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const std::exception& e) {
        throw Error(path + ": expected JSON, got: " + first_line(e.what()));
    }
    gltf::check_document(path, doc, glb.bin_size, out.warnings);

    FsState fs_state;
    fs_state.options = &options;
    if (const auto* bufs = doc.contains("buffers") ? &doc["buffers"] : nullptr)
        for (size_t b = 0; b < bufs->size(); ++b) {
            const auto& buf = (*bufs)[b];
            if (buf.contains("uri") && buf["uri"].get_ref<const string&>().compare(0, 5, "data:") != 0)
                fs_state.files.push_back({b, buf["byteLength"].get<uint64_t>()});
        }

    tinygltf::Model tm;
    {
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(keep_image_bytes, nullptr);
        tinygltf::FsCallbacks cb{};
        cb.FileExists = fs_exists;
        cb.ExpandFilePath = fs_expand;
        cb.ReadWholeFile = fs_read;
        cb.WriteWholeFile = fs_write;
        cb.user_data = &fs_state;
        loader.SetFsCallbacks(cb);
        string err, warn;
        bool ok = false;
        try {
            if (binary)
                ok = loader.LoadBinaryFromMemory(&tm, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                 unsigned(bytes.size()), dir);
            else
                ok = loader.LoadASCIIFromString(&tm, &err, &warn, text.data(), unsigned(text.size()), dir);
        } catch (const std::exception& e) {
            throw Error(path + ": tinygltf: " + first_line(e.what()));
        }
        if (!fs_state.failed_path.empty()) {
            const auto& uri = doc["buffers"][fs_state.failed_buffer]["uri"].get_ref<const string&>();
            throw Error(path + ": /buffers/" + std::to_string(fs_state.failed_buffer) +
                        "/uri: expected a readable buffer file, got " + quote(uri) + ": " + first_line(fs_state.failed_why));
        }
        if (!ok || !err.empty()) throw Error(path + ": tinygltf: " + (err.empty() ? string("failed") : first_line(err)));
        (void)warn;  // what tinygltf warns about is checked here with a pointer
    }
    for (const string& p : fs_state.read) out.inputs.push_back(p);
    for (size_t b = 0; b < tm.buffers.size(); ++b) {
        const uint64_t want = doc["buffers"][b]["byteLength"].get<uint64_t>();
        if (tm.buffers[b].data.size() != want)
            throw Error(path + ": /buffers/" + std::to_string(b) + ": expected " + std::to_string(want) + " bytes, got " +
                        std::to_string(tm.buffers[b].data.size()));
    }

    Context ctx{path, dir, options, doc, tm, out, {}};
    const std::vector<gltf::MaterialUse> uses = gltf::read_materials(ctx);
    const std::vector<gltf::NodePlacement> placed = gltf::walk_scene(ctx);
    if (!tm.skins.empty()) ctx.warn("/skins", "skins ignored: meshes drawn in their bind pose");
    if (!tm.animations.empty()) ctx.warn("/animations", "animations ignored: drawn in the rest pose");

    // The triangle budget, from accessor counts, before any mesh is read.
    size_t triangles = 0;
    for (const gltf::NodePlacement& np : placed) {
        const int mesh = tm.nodes[size_t(np.node)].mesh;
        if (mesh < 0) continue;
        if (size_t(mesh) >= tm.meshes.size())
            ctx.fail("/nodes/" + std::to_string(np.node) + "/mesh",
                     "expected a mesh index below " + std::to_string(tm.meshes.size()) + ", got " + std::to_string(mesh));
        for (size_t p = 0; p < tm.meshes[size_t(mesh)].primitives.size(); ++p) {
            triangles += gltf::primitive_triangles(ctx, mesh, int(p));
            if (triangles > options.max_triangles)
                ctx.fail("/nodes/" + std::to_string(np.node),
                         "expected at most " +
                             (options.budget_note.empty() ? std::to_string(options.max_triangles) + " triangles"
                                                          : options.budget_note) +
                             ", got more with mesh " + std::to_string(mesh) + " drawn here");
        }
    }

    // Meshes, each read once; placed where the node's world matrix is a similarity, baked otherwise.
    std::map<int, std::vector<gltf::PrimitiveMesh>> read;
    std::map<int, std::vector<size_t>> uploaded;  // glTF mesh -> out.meshes of its primitives
    for (const gltf::NodePlacement& np : placed) {
        const tinygltf::Node& node = tm.nodes[size_t(np.node)];
        if (node.mesh < 0) continue;
        const string nptr = "/nodes/" + std::to_string(np.node);
        if (node.skin >= 0 && size_t(node.skin) >= tm.skins.size())
            ctx.fail(nptr + "/skin", "expected a skin index below " + std::to_string(tm.skins.size()) + ", got " + std::to_string(node.skin));
        auto it = read.find(node.mesh);
        if (it == read.end()) it = read.emplace(node.mesh, gltf::read_mesh(ctx, node.mesh, uses)).first;
        const double det = glm::determinant(glm::dmat3(np.world));
        if (det == 0 || !std::isfinite(det)) {
            ctx.warn(nptr, "a world matrix that flattens the mesh (a zero scale): not drawn");
            continue;
        }
        if (gltf::is_similarity(np.world)) {
            auto up = uploaded.find(node.mesh);
            if (up == uploaded.end()) {
                std::vector<size_t> idx;
                for (const gltf::PrimitiveMesh& pm : it->second) {
                    idx.push_back(out.meshes.size());
                    out.meshes.push_back(pm.mesh);
                }
                up = uploaded.emplace(node.mesh, std::move(idx)).first;
            }
            for (size_t k : up->second) {
                // The placed mesh's bounding box within +-1e12 (a uniform scale may be any size).
                glm::dvec3 lo(INFINITY), hi(-INFINITY);
                for (const Vertex& v : out.meshes[k].vertices) {
                    lo = glm::min(lo, glm::dvec3(v.pos));
                    hi = glm::max(hi, glm::dvec3(v.pos));
                }
                for (int c = 0; c < 8; ++c) {
                    const glm::dvec3 corner(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
                    const glm::dvec3 w(np.world * glm::dvec4(corner, 1.0));
                    for (int a = 0; a < 3; ++a)
                        if (!(std::fabs(w[a]) <= gltf::kMaxCoordinate))
                            ctx.fail(nptr, "expected world-space positions within +-1e12, got " + gltf::num(w[a]) + " for mesh " +
                                               std::to_string(node.mesh));
                }
                out.placements.push_back({k, np.world});
                out.triangles += out.meshes[k].indices.size() / 3;
            }
            continue;
        }
        for (const gltf::PrimitiveMesh& pm : it->second) {
            Mesh baked = gltf::bake(pm.mesh, np.world);
            for (const Vertex& v : baked.vertices)
                for (int c = 0; c < 3; ++c)
                    if (!(std::fabs(v.pos[c]) <= gltf::kMaxCoordinate))
                        ctx.fail(nptr, "expected world-space positions within +-1e12, got " + gltf::num(v.pos[c]) + " for " + pm.pointer);
            out.placements.push_back({out.meshes.size(), glm::dmat4(1.0)});
            out.triangles += baked.indices.size() / 3;
            out.meshes.push_back(std::move(baked));
        }
    }
    gltf::read_cameras_and_lights(ctx, placed);
    if (out.triangles == 0) {
        string skipped;
        for (const string& k : ctx.warned)
            if (k.compare(0, 5, "mode ") == 0) skipped += (skipped.empty() ? "" : ", ") + k.substr(5);
        throw Error(path + ": expected at least one triangle in the default scene, got none" +
                    (skipped.empty() ? string() : " (only " + skipped + " primitives, which dsr skips)"));
    }
    return out;
}

}  // namespace dsr
