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
    glm::dmat4 view_d() const;                   // the same in double (camera-relative composition)
    glm::vec3 to_eye(glm::vec3 world) const;     // view_d() applied in double, rounded once
    glm::mat4 projection(float aspect) const;    // glm::perspective, OpenGL clip conventions
};

// A light: colour is S_diff = S_spec (Eq. 3-4). The tutorial has only point lights with
// Equation 2's linear law; dsr adds spot and directional lights (Vasilovici §4.4) and
// LearnOpenGL's attenuation law (scene/light_law.h has the laws, docs/scene-format.md the scene syntax,
// docs/light_geometry.md the light geometries).
//   point        pos, radius
//   spot         pos, dir, radius (range), angle_deg = half-angle as GL_SPOT_CUTOFF, exponent
//   directional  dir only: lights everything, no attenuation
// radius is S_radius of Equation 2 when `attenuation` is off; with it, the distance where
// color_max / (kc + kl d + kq d^2) falls to `threshold` (attenuation_radius), beyond which the
// light adds nothing.
// `physical`: KHR_lights_punctual's units and laws instead (docs/metal_rough.md, "Lights in
// physical units"): color is the colour times the intensity in candela (point, spot) or lux
// (directional); point and spot fall off as 1 / d^2, windowed to 0 at `range` where range > 0;
// a spot fades from inner_deg to angle_deg (the outer cone) by the extension's squared
// scale-and-offset curve. radius is then the range, or where the light falls under half an
// 8-bit step (physical_radius, scene/light_law.h); attenuation, kc, kl, kq, threshold and
// exponent are unused.
// The first three fields stay pos, color, radius so {pos, color, radius} still makes a point light.
// A light's shadow map (`shadow [size N] [bias B] [slope S]`, docs/scene-format.md; the
// renderer's shadow stage, src/deferred/shadow_stage.h). The map stores each surface's depth from
// the light as a fraction of the map's depth range: the distance from the light over `radius` for
// spot and point lights, the depth across the fitted orthographic box for directional ones. A
// pixel is lit where its own depth, less the bias, is at most the map's:
//   bias   constant part, as a fraction of that depth range (0.001 of a radius 10 light: 0.01 units)
//   slope  slope-scaled part, in map texels: slope x (the world size of one texel at the pixel)
//          x tan(angle between the surface's normal and the light), over the depth range
// The defaults are the bias sweep's (`dsr stress`, docs/accuracy.md).
struct LightShadow {
    bool on = false;
    int size = 1024;       // texels per side (per cube face for point lights): a power of two in [64, 8192]
    float bias = 0.0001f;  // >= 0
    float slope = 2.0f;    // >= 0
};

struct Light {
    enum class Type { point, spot, directional };
    glm::vec3 pos{0}, color{1};
    float radius = 1.0f;
    Type type = Type::point;
    glm::vec3 dir{0, 0, -1};      // spot, directional: unit direction the light travels
    float angle_deg = 45.0f;      // spot: cone half-angle in (0, 90]
    float exponent = 0.0f;        // spot: GL_SPOT_EXPONENT, >= 0
    bool attenuation = false;     // false: Equation 2's 1 - d / S_radius
    float kc = 1.0f, kl = 0.0f, kq = 0.0f;  // attenuation law, each >= 0
    float threshold = 5.0f / 256.0f;        // LearnOpenGL's 5/256
    bool physical = false;        // KHR_lights_punctual's units and laws (above)
    float range = 0.0f;           // physical point, spot: the window's range, 0 for none (infinite)
    float inner_deg = 0.0f;       // physical spot: where the fade begins, in [0, angle_deg)
    LightShadow shadow{};                   // off unless the light line says `shadow`
};

// Texture maps are indices into Scene::textures, -1 when absent.
// shininess is M_shi of Equation 4; tile scales texture coordinates (Listing 13).
struct Material {
    std::string name;
    glm::vec3 diffuse{1}, specular{0};
    float shininess = 16.0f;
    int diffuse_map = -1, normal_map = -1, specular_map = -1;
    float tile = 1.0f;
    // `opacity A` or MTL d (1 - Tr): below 1 the material is left out of the G-buffer and drawn
    // by the forward pass after the lights, blended (docs/forward.md; docs/guide.md, "Transparent surfaces").
    float opacity = 1.0f;
    bool transparent() const { return opacity < 1.0f; }
    // Cut-out (alpha testing): above 0, a fragment whose coverage (the diffuse map's alpha times
    // the vertex colour's alpha) is below alpha_cutoff is discarded by the material pass and the
    // shadow casters, as if the surface were not there (an MTL map_d, a glTF alphaMode MASK).
    float alpha_cutoff = 0.0f;
    bool cut_out() const { return alpha_cutoff > 0.0f; }
    // The material model (docs/metal_rough.md): the tutorial's Phong (diffuse, specular, shininess
    // and their maps), or glTF 2.0's metallic-roughness, whose base colour is `diffuse` (times
    // diffuse_map, the base colour map) and which reads metallic, roughness and the maps below;
    // its specular, shininess and specular_map are unused. Each factor is in [0, 1].
    enum class Model { phong, metallic_roughness };
    Model model = Model::phong;
    float metallic = 1.0f, roughness = 1.0f;  // glTF's defaults
    // glTF's metallicRoughnessTexture: roughness in green, metallic in blue, times the factors.
    int metallic_roughness_map = -1;
    // glTF's occlusionTexture (red), mixed by occlusion_strength: 1 + strength (map - 1). It scales
    // the ambient term only (the glTF spec: occlusion applies to indirect light).
    int occlusion_map = -1;
    float occlusion_strength = 1.0f;
    glm::vec3 emissive{0};  // emissiveFactor, times emissive_map (linear RGB, added once)
    int emissive_map = -1;
    bool metal_rough() const { return model == Model::metallic_roughness; }
};

// How a texture is sampled (glTF samplers; every other texture keeps the defaults, which are
// what dsr always used: repeat, trilinear mipmaps, stored values as they are).
struct TextureSampling {
    enum class Wrap { repeat, clamp, mirror };
    Wrap wrap_s = Wrap::repeat, wrap_t = Wrap::repeat;
    bool nearest_mag = false;  // magnification: nearest texel instead of linear
    bool nearest_min = false;  // minification: nearest (mipmapped where `mipmaps`) instead of linear
    bool mipmaps = true;       // minification reads mipmaps
    bool srgb = false;         // stored sRGB-encoded: decoded to linear when sampled (glTF colour maps)
    bool operator==(const TextureSampling& o) const {
        return wrap_s == o.wrap_s && wrap_t == o.wrap_t && nearest_mag == o.nearest_mag &&
               nearest_min == o.nearest_min && mipmaps == o.mipmaps && srgb == o.srgb;
    }
};

// Tangent frame per vertex (Listing 10's a2v): tangent follows +u, binormal +v.
struct Vertex {
    glm::vec3 pos{0}, normal{0, 0, 1};
    glm::vec2 uv{0};
    glm::vec3 tangent{1, 0, 0}, binormal{0, 1, 0};
};

// The exact shape an object was tessellated from, in world space (add_plane/add_box/add_sphere
// set it on the Object), so the analytic reference can trace the shape itself.
//   plane:  the XZ square of side size.x centred on centre, normal +Y (size = (s, 0, s))
//   box:    axis-aligned, edge lengths size, centred on centre
//   sphere: radius `radius` about centre (size = (2r, 2r, 2r))
struct ShapeDesc {
    enum class Kind { plane, box, sphere };
    Kind kind = Kind::plane;
    glm::vec3 centre{0}, size{0};
    float radius = 0;
};

// Object-space triangles with one material (a group of Listing 9): uploaded once however many
// objects draw it.
// colors: per-vertex colours (OBJ `v x y z r g b`, glTF COLOR_0), parallel to vertices, multiplying
// the diffuse colour (rgb) and the coverage (a); empty when the file gives none (white).
// two_sided: the loader's wish (OBJ faces; a glTF material's doubleSided); the Object decides.
struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    int material = 0;
    std::vector<glm::vec4> colors;
    bool two_sided = false;
};

// One thing drawn: a mesh and its object-to-world transform, kept in double. Renderers never
// multiply world-space points in float: they compose view * model in double on the CPU
// (camera_relative below), so the GPU only sees eye-space numbers, small near the camera however
// far from the origin the scene lies. Transforms are rigid with a uniform scale (normals need no
// inverse transpose).
// `shape`, in world space, is the exact shape the mesh was tessellated from (add_plane, add_box,
// add_sphere set it) so the analytic reference can trace the shape itself rather than the
// renderer's triangles; absent for meshes that are only triangles (hand-made, OBJ).
struct Object {
    size_t mesh = 0;  // index into Scene::meshes
    glm::dmat4 model{1.0};
    int material = 0;  // what it is drawn with: the mesh's, or a `mesh ... material` override
    std::optional<ShapeDesc> shape;
    // Drawn without back-face culling, a back face's normal flipped to face the camera
    // (gl_FrontFacing), as Blender and MeshLab show OBJ faces; shapes are one-sided.
    bool two_sided = false;
};

// A model file (OBJ or glTF) as read: its meshes are Scene::meshes[first_mesh, first_mesh +
// mesh_count), in object space. Read once per resolved path however many `mesh` lines name it
// (scene/model_data.h). A glTF model's meshes may be drawn several times each, by nodes with their
// own transforms: `placements` lists what one instance draws (an OBJ's: each group once, at
// identity).
struct MeshModel {
    std::string path;  // as resolved
    size_t first_mesh = 0, mesh_count = 0;
    size_t triangles = 0;  // drawn by one instance: over placements
    struct Placement {
        size_t mesh = 0;        // index into Scene::meshes
        glm::dmat4 model{1.0};  // in the model's space; rigid with a uniform scale
    };
    std::vector<Placement> placements;
};

// One `mesh` line: its model, transform and material override; it draws
// Scene::objects[first_object, first_object + object_count), one per group.
// model_matrix() = translate(at) * rotate_y(rotate_y_deg) * scale(scale), in double.
struct MeshInstance {
    int model = -1;  // index into Scene::models
    double scale = 1, rotate_y_deg = 0;
    glm::dvec3 at{0};
    int material = -1;  // `material NAME`: every group drawn with it; -1: the MTL's
    size_t first_object = 0, object_count = 0;
    int line = 0;  // in the scene file
    glm::dmat4 model_matrix() const;
};

struct Scene {
    std::string path;  // the scene file, "" for scenes built in code
    Camera camera;
    glm::vec3 ambient{0.2f}, background{0.0f};
    std::vector<Material> materials;
    std::vector<Image> textures;
    std::vector<std::string> texture_paths;  // parallel to textures, as resolved
    // Parallel to textures where a loader set it; a texture past its end samples with the defaults.
    std::vector<TextureSampling> texture_sampling;
    std::vector<Mesh> meshes;     // geometry, object space, each uploaded once
    std::vector<Object> objects;  // what is drawn: a mesh with its transform
    std::vector<Light> lights;
    bool post_bloom = false, post_aa = false;  // `post bloom aa` directive
    // `markers box SIZE` / `markers sphere`: what --show-lights draws at each light. A sphere of a
    // fixed share of the screen (marker_radius), or, as LearnOpenGL's demo draws its light boxes,
    // a cube of world half-size `marker_size`.
    enum class MarkerShape { sphere, box };
    MarkerShape marker_shape = MarkerShape::sphere;
    float marker_size = 0;  // the box's half-size in world units; unused for spheres
    std::vector<MeshModel> models;         // model files (`mesh` lines, a model as the scene), object space
    std::vector<MeshInstance> instances;   // one per `mesh` line
    // What the loaders read and ignored or substituted, one line each ("FILE:LINE: ..."), printed
    // to stderr, counted in --stats (`warnings`); --strict makes the first one an error.
    std::vector<std::string> warnings;
    // Every file the scene was read from: the scene file, its OBJ and MTL files and images, as
    // opened (no output of a run may be one of them).
    std::vector<std::string> inputs;

    // Appends `mesh` and one object drawing it with `model`; returns the object's index.
    size_t add(Mesh mesh, const glm::dmat4& model = glm::dmat4(1.0), std::optional<ShapeDesc> shape = {});
    size_t triangle_count() const;  // over objects: an instanced mesh counts once per object
};

// view * model in double, rounded to float once: the modelview matrix a renderer loads for an
// object (camera-relative, so far-from-origin scenes keep their precision).
glm::mat4 camera_relative(const glm::dmat4& view, const glm::dmat4& model);

// The scene file's limits (docs/scene-format.md), each checked where the file is read, before
// anything is allocated for it.
constexpr double kMaxSceneNumber = 1e12;              // |any number|, and world-space vertices
constexpr double kMaxFarOverNear = 1e7;               // camera far / near
constexpr size_t kMaxSceneTriangles = 20'000'000;     // drawn: shapes and every mesh instance
constexpr size_t kMaxSceneTexels = size_t(1) << 26;   // all textures together: 1 GiB as float RGBA
// Past this ratio of a triangle's longest edge to the camera's distance, load_scene warns.
constexpr double kMaxEdgeOverDistance = 1e5;

// How a scene or model is read: the render and view commands' --strict, --from, --camera and
// --ambient (docs/scene-format.md, "A model is a scene").
struct LoadOptions {
    bool strict = false;                // the first warning is an error: nothing substituted
    std::optional<glm::vec3> from;      // a framed model's view direction (framing.h kFitFrom)
    int camera = -1;                    // a glTF's camera N (0-based); -1: its first, if it has one
    std::optional<glm::vec3> ambient;   // replaces the scene's ambient term
};

// Parses a scene file (format in docs/scene-format.md); a path ending .obj, .gltf or .glb is a
// model, framed by model_scene (scene/framing.h). Throws dsr::Error whose message is
// "FILE:LINE: expected ..., got ..." for any mistake; textures are loaded here.
// Warnings (what the readers ignored or substituted) are in Scene::warnings and printed through
// the warning printer, each once; with options.strict the first is thrown instead.
Scene load_scene(const std::string& path, const LoadOptions& options = {});
// Where load_scene prints a warning: by default "warning: TEXT" to stderr on one line; a program
// fits them to its terminal (app/main.cpp: wrapped at 120 columns). Set once, before loading.
void set_warning_printer(void (*print)(const std::string& warning));
// The same from text in memory: `path` names it in messages and resolves relative files;
// warnings are only collected.
Scene parse_scene(const std::string& path, const std::string& text);

// Shapes of the scene format in object space, centred on the origin, with normals, uvs and
// tangent frames.
Mesh make_plane(float size, int material);       // XZ square, normal +Y, uv 0..1
Mesh make_box(glm::vec3 size, int material);     // axis-aligned, uv 0..1 per face
Mesh make_sphere(float radius, int material, int slices = 48, int stacks = 24);
// The same added to a scene as an object at `at` (model = translate(at)) with its exact shape.
size_t add_plane(Scene& scene, float size, glm::vec3 at, int material);
size_t add_box(Scene& scene, glm::vec3 size, glm::vec3 at, int material);
size_t add_sphere(Scene& scene, float radius, glm::vec3 at, int material, int slices = 48, int stacks = 24);

}  // namespace dsr
