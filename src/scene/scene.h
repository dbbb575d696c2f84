// The scene as data: camera, lights, materials, meshes, textures. No GL here.
// Units are free, right-handed, the camera looks down -Z in eye space.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/image.h"

namespace dsr {

struct Camera {
    glm::vec3 pos{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
    float fov_deg = 60.0f;  // vertical field of view
    float near_plane = 0.1f, far_plane = 100.0f;
    glm::mat4 view() const;                      // glm::lookAt
    glm::mat4 projection(float aspect) const;    // glm::perspective, OpenGL clip conventions
};

// A point light (the tutorial's only kind): colour is S_diff = S_spec (Eq. 3-4),
// radius is S_radius of Equation 2.
struct Light {
    glm::vec3 pos{0}, color{1};
    float radius = 1.0f;
};

// Texture maps are indices into Scene::textures, -1 when absent.
// shininess is M_shi of Equation 4; tile scales texture coordinates (Listing 13).
struct Material {
    std::string name;
    glm::vec3 diffuse{1}, specular{0};
    float shininess = 16.0f;
    int diffuse_map = -1, normal_map = -1, specular_map = -1;
    float tile = 1.0f;
};

// Tangent frame per vertex (Listing 10's a2v): tangent follows +u, binormal +v.
struct Vertex {
    glm::vec3 pos{0}, normal{0, 0, 1};
    glm::vec2 uv{0};
    glm::vec3 tangent{1, 0, 0}, binormal{0, 1, 0};
};

// The exact shape a mesh was tessellated from (make_plane/make_box/make_sphere set it), so the
// analytic reference can trace the shape itself rather than the renderer's triangles.
//   plane:  the XZ square of side size.x centred on centre, normal +Y (size = (s, 0, s))
//   box:    axis-aligned, edge lengths size, centred on centre
//   sphere: radius `radius` about centre (size = (2r, 2r, 2r))
struct ShapeDesc {
    enum class Kind { plane, box, sphere };
    Kind kind = Kind::plane;
    glm::vec3 centre{0}, size{0};
    float radius = 0;
};

// World-space triangles with one material; `shape` is absent for meshes that are only
// triangles (hand-made, OBJ).
struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    int material = 0;
    std::optional<ShapeDesc> shape;
};

struct Scene {
    std::string path;  // the scene file, "" for scenes built in code
    Camera camera;
    glm::vec3 ambient{0.2f}, background{0.0f};
    std::vector<Material> materials;
    std::vector<Image> textures;
    std::vector<std::string> texture_paths;  // parallel to textures, as resolved
    std::vector<Mesh> meshes;
    std::vector<Light> lights;
    bool post_bloom = false, post_aa = false;  // `post bloom aa` directive
};

// Parses a scene file (format in README.md). Throws dsr::Error whose message is
// "FILE:LINE: expected ..., got ..." for any mistake; textures are loaded here.
Scene load_scene(const std::string& path);

// Shapes of the scene format, in world space, with normals, uvs and tangent frames.
Mesh make_plane(float size, glm::vec3 at, int material);       // XZ square, normal +Y, uv 0..1
Mesh make_box(glm::vec3 size, glm::vec3 at, int material);     // axis-aligned, uv 0..1 per face
Mesh make_sphere(float radius, glm::vec3 at, int material, int slices = 48, int stacks = 24);

}  // namespace dsr
