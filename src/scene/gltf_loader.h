// glTF 2.0 models (.gltf with external or data: buffers and images, .glb), read with tinygltf and
// checked here, so that every mistake in a file is one dsr::Error naming the file and the JSON
// pointer of what is wrong ("model.gltf: /accessors/3/count: expected ..., got ..."). Pure: no GL.
// Images go through the image interface (scene/image.h).
//
// What is read, approximated and refused: docs/gltf.md.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

struct GltfOptions {
    // How files are read (the .gltf/.glb itself, external buffers and images). Empty: the file
    // system (regular files only, user_file.h). The fuzzer and tests replace it; throws dsr::Error.
    std::function<std::string(const std::string& path)> read_file;
    // Budgets, as ObjOptions's: triangles drawn (every placement of a mesh counts), texels of all
    // textures; `budget_note` names whose budget it is in messages ("" for the file's own limits).
    size_t max_triangles = 20'000'000;
    size_t max_texels = kMaxImageTexels;
    std::string budget_note;
};

// A camera of the file, as dsr's Camera (aspect ratio is the image's), with its name.
struct GltfCamera {
    std::string name;
    Camera camera;
    bool far_given = true;  // false: the file's zfar was absent (infinite); far set from the bounds later
};

// A glTF scene as read, in the file's world space (the default scene's node hierarchy resolved).
// meshes are uploaded once; placements say where each is drawn: a mesh used by several nodes is
// one Mesh with several placements. Each placement's matrix is rigid with a uniform scale (the
// renderers' rule, scene.h Object); a node whose world matrix is not is baked into a copy of the
// mesh instead (positions, normals by the inverse transpose, winding flipped where it mirrors).
struct GltfModel {
    std::string path;
    std::vector<Material> materials;  // names "FILE:NAME" (or "FILE:#INDEX")
    std::vector<Image> textures;
    std::vector<std::string> texture_paths;       // a file path, or "FILE#/images/N" for embedded ones
    std::vector<TextureSampling> texture_sampling;  // parallel to textures
    std::vector<Mesh> meshes;                     // Mesh::material indexes materials
    struct Placement {
        size_t mesh = 0;
        glm::dmat4 model{1.0};
    };
    std::vector<Placement> placements;
    std::vector<GltfCamera> cameras;  // in the order the default scene's nodes reach them
    std::vector<Light> lights;        // KHR_lights_punctual, placed; empty: the file has none
    size_t triangles = 0;             // drawn: over placements
    std::vector<std::string> warnings;  // "FILE: /POINTER: ..." for what was skipped or substituted
    std::vector<std::string> inputs;    // every file read: the .gltf/.glb, buffers, images
};

// Reads a .gltf or .glb file (chosen by its first bytes: "glTF" is binary) and what it refers to.
GltfModel load_gltf(const std::string& path, const GltfOptions& options = {});
// The same from the file's bytes already in memory; `path` names it in messages and resolves URIs.
GltfModel parse_gltf(const std::string& path, const std::string& bytes, const GltfOptions& options = {});

// True for a path ending ".gltf" or ".glb" in any case.
bool is_gltf_path(const std::string& path);

}  // namespace dsr
