// What a model file brings to a scene, whichever reader read it: the OBJ/MTL reader
// (obj_loader.h) and the glTF reader (gltf_loader.h) both end here, so nothing downstream
// knows the file format. Pure: no GL.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace dsr {

// A model in its own space: meshes uploaded once, placements saying where each is drawn.
struct ModelData {
    std::string path;
    std::vector<Material> materials;
    std::vector<Image> textures;
    std::vector<std::string> texture_paths;
    std::vector<TextureSampling> texture_sampling;  // parallel to textures
    std::vector<Mesh> meshes;                       // Mesh::material indexes materials
    std::vector<MeshModel::Placement> placements;   // Placement::mesh indexes meshes
    size_t triangles = 0;                           // drawn by the placements
    std::vector<GltfCamera> cameras;                // glTF only
    std::vector<Light> lights;                      // glTF's KHR_lights_punctual; empty: none
    std::vector<std::string> warnings;
    std::vector<std::string> inputs;                // every file read
};

// The budget left for a model: triangles drawn and texels of its new textures; `note` says whose
// budget it is in messages ("" for the file's own limits).
struct ModelBudget {
    size_t max_triangles = kMaxSceneTriangles;
    size_t max_texels = kMaxSceneTexels;
    std::string note;
};

// True for the paths read as models: .obj, .gltf, .glb in any case.
bool is_model_file(const std::string& path);

// Reads the model at `path`: glTF when `gltf` (a file whose bytes say so, whatever its name) or
// its extension says .gltf/.glb, else OBJ. Throws the reader's dsr::Error.
ModelData read_model(const std::string& path, const ModelBudget& budget = {}, bool gltf = false);

// Appends the model's textures (a path already in the scene reuses its texture), materials (maps
// re-indexed) and meshes to `scene` as one Scene::models entry; returns its index. Warnings and
// inputs join the scene's. `new_texels` receives the texels of the textures it added.
int add_model_data(Scene& scene, ModelData model, size_t* new_texels = nullptr);

// One instance of scene.models[model] at `m` (rigid, uniform scale): an object per placement,
// drawn with `material` (-1: each mesh's own), two-sided where the mesh asks unless one_sided.
// Returns the instance (not yet appended to scene.instances).
MeshInstance place_model(Scene& scene, int model, const glm::dmat4& m, int material, bool one_sided);

}  // namespace dsr
