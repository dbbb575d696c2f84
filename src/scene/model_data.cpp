#include "scene/model_data.h"

#include <algorithm>
#include <cctype>

#include "scene/obj_loader.h"

namespace dsr {

namespace {

std::string lower_extension(const std::string& path) {
    const size_t slash = path.find_last_of('/'), dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot);
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

ModelData from_obj(ObjModel obj) {
    ModelData d;
    d.path = std::move(obj.path);
    d.materials = std::move(obj.materials);
    d.textures = std::move(obj.textures);
    d.texture_paths = std::move(obj.texture_paths);
    d.texture_sampling.assign(d.textures.size(), TextureSampling{});
    d.meshes = std::move(obj.groups);
    for (size_t i = 0; i < d.meshes.size(); ++i) d.placements.push_back({i, glm::dmat4(1.0)});
    d.triangles = obj.triangles;
    d.warnings = std::move(obj.warnings);
    d.inputs = std::move(obj.inputs);
    return d;
}

ModelData from_gltf(GltfModel g) {
    ModelData d;
    d.path = std::move(g.path);
    d.materials = std::move(g.materials);
    d.textures = std::move(g.textures);
    d.texture_paths = std::move(g.texture_paths);
    d.texture_sampling = std::move(g.texture_sampling);
    d.texture_sampling.resize(d.textures.size());
    d.meshes = std::move(g.meshes);
    for (const GltfModel::Placement& p : g.placements) d.placements.push_back({p.mesh, p.model});
    d.triangles = g.triangles;
    d.cameras = std::move(g.cameras);
    d.lights = std::move(g.lights);
    d.warnings = std::move(g.warnings);
    d.inputs = std::move(g.inputs);
    return d;
}

}  // namespace

bool is_model_file(const std::string& path) {
    const std::string e = lower_extension(path);
    return e == ".obj" || e == ".gltf" || e == ".glb";
}

ModelData read_model(const std::string& path, const ModelBudget& budget, bool gltf) {
    if (gltf || is_gltf_path(path)) {
        GltfOptions o;
        o.max_triangles = budget.max_triangles;
        o.max_texels = budget.max_texels;
        o.budget_note = budget.note;
        return from_gltf(load_gltf(path, o));
    }
    ObjOptions o;
    o.max_triangles = budget.max_triangles;
    o.max_texels = budget.max_texels;
    o.budget_note = budget.note;
    return from_obj(load_obj(path, o));
}

int add_model_data(Scene& scene, ModelData model, size_t* new_texels) {
    if (scene.texture_sampling.size() < scene.textures.size()) scene.texture_sampling.resize(scene.textures.size());
    std::vector<int> tex(model.textures.size(), -1);
    size_t added = 0;
    for (size_t i = 0; i < model.textures.size(); ++i) {
        for (size_t j = 0; j < scene.texture_paths.size() && tex[i] < 0; ++j)
            if (scene.texture_paths[j] == model.texture_paths[i] && scene.texture_sampling[j] == model.texture_sampling[i])
                tex[i] = int(j);
        if (tex[i] >= 0) continue;
        added += size_t(model.textures[i].width) * size_t(model.textures[i].height);
        scene.textures.push_back(std::move(model.textures[i]));
        scene.texture_paths.push_back(model.texture_paths[i]);
        scene.texture_sampling.push_back(model.texture_sampling[i]);
        tex[i] = int(scene.textures.size() - 1);
    }
    if (new_texels) *new_texels = added;
    const int mat_base = int(scene.materials.size());
    for (Material m : model.materials) {
        for (int* map : {&m.diffuse_map, &m.normal_map, &m.specular_map})
            if (*map >= 0) *map = tex[size_t(*map)];
        scene.materials.push_back(std::move(m));
    }
    MeshModel mm;
    mm.path = model.path;
    mm.triangles = model.triangles;
    mm.first_mesh = scene.meshes.size();
    mm.mesh_count = model.meshes.size();
    for (Mesh& g : model.meshes) {
        g.material += mat_base;
        scene.meshes.push_back(std::move(g));
    }
    for (MeshModel::Placement p : model.placements) {
        p.mesh += mm.first_mesh;
        mm.placements.push_back(p);
    }
    for (std::string& w : model.warnings) scene.warnings.push_back(std::move(w));
    for (std::string& f : model.inputs) scene.inputs.push_back(std::move(f));
    scene.models.push_back(std::move(mm));
    return int(scene.models.size() - 1);
}

MeshInstance place_model(Scene& scene, int model, const glm::dmat4& m, int material, bool one_sided) {
    MeshInstance inst;
    inst.model = model;
    inst.material = material;
    inst.first_object = scene.objects.size();
    for (const MeshModel::Placement& p : scene.models[size_t(model)].placements) {
        Object o;
        o.mesh = p.mesh;
        o.model = m * p.model;
        o.material = material >= 0 ? material : scene.meshes[p.mesh].material;
        o.two_sided = scene.meshes[p.mesh].two_sided && !one_sided;
        scene.objects.push_back(o);
    }
    inst.object_count = scene.objects.size() - inst.first_object;
    return inst;
}

}  // namespace dsr

