#include "scene/framing.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "dsr_error.h"
#include "scene/obj_loader.h"

namespace dsr {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Appends the model's textures, materials (maps re-indexed) and material groups to `scene`,
// with one identity instance drawing every group, as a `mesh FILE` line would.
void add_model(Scene& scene, ObjModel obj) {
    const int tex_base = int(scene.textures.size()), mat_base = int(scene.materials.size());
    for (size_t i = 0; i < obj.textures.size(); ++i) {
        scene.textures.push_back(std::move(obj.textures[i]));
        scene.texture_paths.push_back(obj.texture_paths[i]);
    }
    for (Material m : obj.materials) {
        for (int* map : {&m.diffuse_map, &m.normal_map, &m.specular_map})
            if (*map >= 0) *map += tex_base;
        scene.materials.push_back(m);
    }
    MeshModel model;
    model.path = obj.path;
    model.triangles = obj.triangles;
    model.first_mesh = scene.meshes.size();
    model.mesh_count = obj.groups.size();
    MeshInstance inst;
    inst.model = int(scene.models.size());
    inst.first_object = scene.objects.size();
    for (Mesh& g : obj.groups) {
        g.material += mat_base;
        scene.add(std::move(g));
    }
    inst.object_count = scene.objects.size() - inst.first_object;
    for (std::string& w : obj.warnings) scene.warnings.push_back(std::move(w));
    scene.models.push_back(std::move(model));
    scene.instances.push_back(inst);
}

Light point_light(const glm::dvec3& pos, glm::vec3 colour, double radius) {
    Light l;
    l.pos = glm::vec3(pos);
    l.color = colour;
    l.radius = float(radius);
    return l;
}

}  // namespace

SceneBounds scene_bounds(const Scene& scene) {
    SceneBounds b;
    // Only vertices a triangle uses: what is drawn (a loader may keep the corners of triangles
    // it dropped).
    std::vector<std::vector<uint32_t>> used(scene.meshes.size());
    for (const Object& o : scene.objects) {
        const Mesh& m = scene.meshes.at(o.mesh);
        std::vector<uint32_t>& u = used[o.mesh];
        if (!u.empty() || m.indices.empty()) continue;
        std::vector<char> seen(m.vertices.size(), 0);
        for (uint32_t i : m.indices)
            if (i < seen.size() && !seen[i]) seen[i] = 1, u.push_back(i);
    }
    // Two passes over the transformed vertices: the box, then the farthest vertex from its
    // centre (tighter than the box's half diagonal, so a model fills more of the frame).
    auto each = [&](auto&& f) {
        for (const Object& o : scene.objects)
            for (uint32_t i : used[o.mesh])
                f(glm::dvec3(o.model * glm::dvec4(glm::dvec3(scene.meshes[o.mesh].vertices[i].pos), 1.0)));
    };
    each([&](const glm::dvec3& p) {
        if (!finite(p)) b.finite = false;
        b.min = b.vertices ? glm::min(b.min, p) : p;
        b.max = b.vertices ? glm::max(b.max, p) : p;
        ++b.vertices;
    });
    if (!b.vertices || !b.finite) return b;
    b.centre = 0.5 * (b.min + b.max);
    double r2 = 0;
    each([&](const glm::dvec3& p) {
        const glm::dvec3 d = p - b.centre;
        r2 = std::max(r2, glm::dot(d, d));
    });
    b.radius = std::sqrt(r2);
    if (!std::isfinite(b.radius)) b.finite = false;  // a box wider than 1e308 overflows the square
    return b;
}

std::string unframeable(const SceneBounds& b) {
    if (b.vertices == 0) return "no triangles";
    if (!b.finite) return "a coordinate that is not finite";
    if (!(b.radius > 0)) return "every vertex at one point";
    return "";
}

Camera fit_camera(const SceneBounds& b, glm::vec3 from, float fov_deg, float aspect) {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(from));
    // The half-angle of the image's smaller dimension: the vertical one unless taller than wide.
    double half = glm::radians(double(fov_deg)) * 0.5;
    if (aspect < 1) half = std::atan(std::tan(half) * double(aspect));
    // A sphere of radius r at distance d projects to +-tan(asin(r / d)) on the image plane at
    // distance 1, where the image spans +-tan(half): solve tan(alpha) = kFitFill * tan(half).
    const double alpha = std::atan(kFitFill * std::tan(half));
    const double d = b.radius / std::sin(alpha);
    Camera c;
    c.fov_deg = fov_deg;
    c.target = glm::vec3(b.centre);
    c.pos = glm::vec3(b.centre + dir * d);
    const bool vertical = glm::length(glm::cross(dir, glm::dvec3(0, 1, 0))) < 1e-3;
    c.up = vertical ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    c.near_plane = float(0.5 * (d - b.radius));
    c.far_plane = float(1.05 * (d + b.radius));
    return c;
}

void apply_camera_fit(Scene& scene, const CameraFit& fit) {
    const SceneBounds b = scene_bounds(scene);
    const std::string why = unframeable(b);
    if (!why.empty()) throw Error(fit.where + ": camera fit: expected something to frame, got " + why);
    scene.camera = fit_camera(b, fit.from, fit.fov_deg, 1.0f);
}

Camera reframe(const Scene& scene, const Camera& current, float aspect) {
    const SceneBounds b = scene_bounds(scene);
    const glm::vec3 back = current.pos - current.target;
    if (!unframeable(b).empty() || !(glm::length(back) > 0)) return current;
    Camera c = fit_camera(b, back, current.fov_deg, aspect);
    // Keep the user's up unless the new view direction runs along it.
    if (glm::length(glm::cross(glm::normalize(back), current.up)) > 1e-3f * glm::length(current.up)) c.up = current.up;
    return c;
}

bool is_model_path(const std::string& path) {
    if (path.size() < 4) return false;
    std::string tail = path.substr(path.size() - 4);
    for (char& ch : tail) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return tail == ".obj";
}

Scene model_scene(const std::string& path) {
    Scene s;
    s.path = path;
    add_model(s, load_obj(path));
    const SceneBounds b = scene_bounds(s);
    const std::string why = unframeable(b);
    if (!why.empty()) throw Error(path + ": expected a model with finite, non-empty bounds, got " + why);
    const double r = b.radius;
    s.camera = fit_camera(b, kFitFrom, kFitFovDeg, 1.0f);
    s.ambient = glm::vec3(0.2f);
    s.background = {0.23f, 0.27f, 0.34f};

    // The ground: a grey square just under the lowest point (a thousandth of the radius, so a
    // model's flat base does not fight it for depth), centred under the bounding sphere.
    Material ground;
    ground.name = kGroundMaterial;
    ground.diffuse = glm::vec3(0.55f);
    ground.specular = glm::vec3(0.1f);
    ground.shininess = 16;
    s.materials.push_back(ground);
    const double side = 8 * r;
    const glm::dvec3 at(b.centre.x, b.min.y - 1e-3 * r, b.centre.z);
    ShapeDesc shape;
    shape.kind = ShapeDesc::Kind::plane;
    shape.centre = glm::vec3(at);
    shape.size = glm::vec3(float(side), 0, float(side));
    s.add(make_plane(float(side), int(s.materials.size() - 1)), glm::translate(glm::dmat4(1.0), at), shape);
    // far reaches the ground's farthest corner (the sphere alone sets it otherwise).
    double far = s.camera.far_plane;
    for (int c = 0; c < 4; ++c) {
        const glm::dvec3 corner = at + glm::dvec3((c & 1) ? side / 2 : -side / 2, 0, (c & 2) ? side / 2 : -side / 2);
        far = std::max(far, 1.05 * glm::length(corner - glm::dvec3(s.camera.pos)));
    }
    s.camera.far_plane = float(far);

    // The rig, in bounding radii from the centre; each radius reaches past the ground's corners.
    const glm::dvec3 c = b.centre;
    s.lights.push_back(point_light(c + 3.0 * r * glm::normalize(glm::dvec3(1.5, 2.0, 1.2)), {1.0f, 0.95f, 0.85f}, 10 * r));
    s.lights.push_back(point_light(c + 3.0 * r * glm::normalize(glm::dvec3(-2.0, 0.6, 1.0)), {0.30f, 0.36f, 0.48f}, 8 * r));
    s.lights.push_back(point_light(c + 3.0 * r * glm::normalize(glm::dvec3(-0.6, 1.4, -2.0)), {0.55f, 0.55f, 0.6f}, 7 * r));
    return s;
}

}  // namespace dsr
