// Internal to the glTF reader (gltf_loader.h): what its files share. The JSON is checked twice:
// gltf_json.cpp looks at the raw document (nlohmann) before tinygltf sees it, so types, integer
// ranges, data URIs and references tinygltf itself would follow unchecked are refused with their
// JSON pointer; the other files read tinygltf's Model and check every index and byte range again
// before they use it.
#pragma once
// The same configuration as tinygltf_impl.cpp in every file that includes tinygltf.
#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#endif
#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "dsr_error.h"
#include "scene/gltf_loader.h"

namespace dsr::gltf {

// Limits (docs/gltf.md, "Limits and refusals").
constexpr size_t kMaxGltfBytes = size_t(2) << 30;       // a .gltf/.glb, each buffer and image file
constexpr size_t kMaxElements = 20'000'000;             // an accessor's count; vertices of a mesh
constexpr int kMaxNodeDepth = 256;                      // of the node hierarchy
constexpr int kMaxJsonDepth = 64;                       // nesting of the JSON document
constexpr double kMaxCoordinate = 1e12;                 // |positions| and translations, as OBJ's

// Everything the readers share about one file: its name in messages, the options, the two views
// of the JSON and the model being filled.
struct Context {
    std::string path;   // as given: names the file in messages
    std::string dir;    // where relative URIs start
    const GltfOptions& options;
    const nlohmann::json& doc;
    const tinygltf::Model& tm;
    GltfModel& out;
    std::set<std::string> warned;  // one warning per kind

    [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;
    void warn(const std::string& pointer, const std::string& what);
    void warn_once(const std::string& key, const std::string& pointer, const std::string& what);
    // The JSON value at `pointer`, or nullptr when absent.
    const nlohmann::json* at(const std::string& pointer) const;
};

// ---- gltf_json.cpp: the raw document --------------------------------------------------------

// Throws "PATH: expected JSON nested at most 64 deep, ..." before any parser recurses.
void check_json_depth(const std::string& path, const std::string& text);
// glTF 1.0 and versions other than 2.x; extensionsRequired; types and ranges of every member the
// reader uses; data: URIs; the byte ranges of images stored in buffer views (tinygltf reads them
// unchecked). `bin_size`: the GLB's BIN chunk, or -1 without one.
void check_document(const std::string& path, const nlohmann::json& doc, long long bin_size,
                    std::vector<std::string>& warnings);

// ---- gltf_accessors.cpp ---------------------------------------------------------------------

// An accessor read whole, each component as a double (normalized integers mapped to [-1, 1] or
// [0, 1] as glTF says), `comps` per element.
struct Values {
    size_t count = 0;
    int comps = 0;
    int component_type = 0;
    bool normalized = false;
    std::vector<double> v;  // count * comps
    double at(size_t i, int c) const { return v[i * size_t(comps) + size_t(c)]; }
};

// Components per element of a tinygltf type, 0 for an unknown one.
int type_components(int type);
// Bytes per component, 0 for an unknown componentType.
int component_bytes(int component_type);
// What `use` (e.g. "POSITION") accepts, checked before anything is read.
struct AccessorRule {
    std::vector<int> types;            // TINYGLTF_TYPE_*
    std::vector<int> component_types;  // TINYGLTF_COMPONENT_TYPE_*
};
// Reads accessor `index` (used at `user`, a JSON pointer) after checking it against `rule`, its
// buffer view and buffer: every byte range in 64 bits before it is read.
Values read_accessor(Context& ctx, int index, const std::string& user, const AccessorRule& rule);
// The element count only (for budgets before reading): checked index.
size_t accessor_count(const Context& ctx, int index, const std::string& user);

// ---- gltf_materials.cpp ---------------------------------------------------------------------

// Per glTF material: what the primitives using it need to know.
struct MaterialUse {
    int uv_set = 0;                           // TEXCOORD_n the dsr maps read
    bool has_transform = false;               // KHR_texture_transform of the base colour texture
    glm::dmat3 uv_transform{1.0};             // in glTF's uv space (origin top left)
    bool double_sided = false;
    bool needs_uvs = false;                   // some map is read
};
// Every material (and its textures, images decoded through decode_image within max_texels),
// appended to ctx.out; returns one MaterialUse per glTF material, plus a last one for
// primitives without a material (the glTF default material).
std::vector<MaterialUse> read_materials(Context& ctx);

// ---- gltf_meshes.cpp ------------------------------------------------------------------------

// One glTF primitive as read: a dsr Mesh in the mesh's own space.
struct PrimitiveMesh {
    Mesh mesh;
    std::string pointer;  // "/meshes/M/primitives/P"
};
// Triangles a primitive draws, from its accessor counts (0 for skipped modes), for the budget.
size_t primitive_triangles(const Context& ctx, int mesh, int prim);
// Reads every drawable primitive of glTF mesh `mesh` (positions checked finite and within
// kMaxCoordinate); skipped modes are warned about once each.
std::vector<PrimitiveMesh> read_mesh(Context& ctx, int mesh, const std::vector<MaterialUse>& materials);
// `mesh` transformed by the world matrix m: positions, normals by the inverse transpose, the
// winding flipped where det < 0, tangents recomputed.
Mesh bake(const Mesh& mesh, const glm::dmat4& m);

// ---- gltf_nodes.cpp -------------------------------------------------------------------------

struct NodePlacement {
    int node = 0;
    glm::dmat4 world{1.0};
};
// The default scene's nodes in depth-first order with their world matrices: cycles, shared
// children and depth checked first.
std::vector<NodePlacement> walk_scene(Context& ctx);
// True where m's upper 3x3 is a rotation times a uniform positive scale.
bool is_similarity(const glm::dmat4& m);
// Cameras and KHR_lights_punctual lights of the placed nodes, into ctx.out.
void read_cameras_and_lights(Context& ctx, const std::vector<NodePlacement>& nodes);

// "#/a/b" style number formatting for messages.
std::string num(double v);

}  // namespace dsr::gltf
