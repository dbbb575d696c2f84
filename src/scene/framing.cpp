#include "scene/framing.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "dsr_error.h"
#include "scene/model_data.h"

namespace dsr {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
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
    const Camera c = fit_camera(b, fit.from, fit.fov_deg, 1.0f);
    // The framed camera is held to a written camera line's rules (scene_file.cpp): every number
    // finite and within +-1e12, fov in (0, 180), near > 0, far / near at most kMaxFarOverNear, the
    // target away from the position and up not along the view.
    const std::string at = fit.where + ": camera fit: expected ";
    char fov[32];
    std::snprintf(fov, sizeof fov, "%g", double(c.fov_deg));
    const glm::vec3 v[3] = {c.pos, c.target, c.up};
    for (const glm::vec3& p : v)
        for (int i = 0; i < 3; ++i)
            if (!(std::fabs(p[i]) <= kMaxSceneNumber))
                throw Error(at + "a camera within +-1e12, got a position of " + number_text(c.pos.x) + " " +
                            number_text(c.pos.y) + " " + number_text(c.pos.z) + " (fov " + fov + ")");
    if (!(c.fov_deg > 0 && c.fov_deg < 180)) throw Error(at + "fov in (0, 180) degrees, got " + fov);
    if (!(c.near_plane > 0 && double(c.far_plane) > double(c.near_plane) &&
          double(c.far_plane) <= kMaxFarOverNear * double(c.near_plane)))
        throw Error(at + "far / near at most 1e7, got " + number_text(c.far_plane) + " / " + number_text(c.near_plane) +
                    " (fov " + fov + " frames the scene from too near: use a smaller fov)");
    const glm::vec3 dir = c.target - c.pos;
    if (!(glm::length(dir) > 0) || !(glm::length(glm::cross(glm::normalize(dir), c.up)) > 1e-4f * glm::length(c.up)))
        throw Error(at + "a camera away from its target with up not along the view, got position " +
                    number_text(c.pos.x) + " " + number_text(c.pos.y) + " " + number_text(c.pos.z) + " and target " +
                    number_text(c.target.x) + " " + number_text(c.target.y) + " " + number_text(c.target.z));
    scene.camera = c;
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

bool is_model_path(const std::string& path) { return is_model_file(path); }

namespace {

// The file's camera `index` (GltfCamera), its far plane set from the bounds where the file left
// it infinite, and near raised as far as nothing drawn is cut: half the distance to the model's
// bounding sphere and (with a ground) to the ground's plane. A file's near is often far smaller
// than it needs to be, and depth precision, which reconstructed positions and shadow tests rest
// on, falls with far / near.
Camera file_camera(const std::string& path, const std::vector<GltfCamera>& cams, int index, const SceneBounds& b,
                   bool ground, double ground_y) {
    if (index >= int(cams.size()))
        throw Error(path + ": --camera " + std::to_string(index) + ": expected a camera index in 0.." +
                    std::to_string(int(cams.size()) - 1) + " (the file has " + std::to_string(cams.size()) + ")");
    Camera c = cams[size_t(index)].camera;
    const double to_centre = glm::length(glm::dvec3(c.pos) - b.centre);
    if (!cams[size_t(index)].far_given) c.far_plane = float(std::max(1.05 * (to_centre + b.radius), 2.0 * double(c.near_plane)));
    double clear = to_centre - b.radius;  // nothing of the model nearer than this
    if (ground) clear = std::min(clear, double(c.pos.y) - ground_y);
    if (clear > 0) c.near_plane = std::max(c.near_plane, float(0.5 * clear));
    c.near_plane = std::max(c.near_plane, float(double(c.far_plane) / kMaxFarOverNear));
    if (!(c.far_plane > c.near_plane)) c.far_plane = 2 * c.near_plane;
    return c;
}

}  // namespace

Scene model_scene(const std::string& path, const LoadOptions& options, bool gltf) {
    Scene s;
    s.path = path;
    ModelData data = read_model(path, {}, gltf);
    const std::vector<GltfCamera> cameras = data.cameras;
    const std::vector<Light> file_lights = data.lights;
    const int model = add_model_data(s, std::move(data));
    s.instances.push_back(place_model(s, model, glm::dmat4(1.0), -1, false));
    const SceneBounds b = scene_bounds(s);
    const std::string why = unframeable(b);
    if (!why.empty()) throw Error(path + ": expected a model with finite, non-empty bounds, got " + why);
    // Vertices are 32-bit floats: a model narrower than about one float step at its distance from
    // the origin lost its shape when it was read, and one smaller than kMinModelRadius cannot be
    // lit in 32-bit (squared distances underflow).
    const double reach = std::max(glm::length(b.min), glm::length(b.max));
    if (b.radius < kModelPrecision * reach)
        throw Error(path + ": expected a model wider than 1e-7 of its distance from the origin (its "
                    "coordinates are 32-bit floats), got a radius of " + number_text(b.radius) + " at " +
                    number_text(reach) + ": move it nearer the origin");
    if (b.radius < kMinModelRadius)
        throw Error(path + ": expected a model at least " + number_text(kMinModelRadius) +
                    " units across, got a radius of " + number_text(b.radius) + ": scale it up");
    const double r = b.radius;
    const bool own_camera = !cameras.empty() && !options.from;
    if (options.camera >= 0 && cameras.empty())
        throw Error(path + ": --camera " + std::to_string(options.camera) + ": expected a model with cameras, got none");
    const double ground_y = b.min.y - 1e-3 * b.radius;  // the ground's plane, where the rig lights the model
    s.camera = own_camera ? file_camera(path, cameras, std::max(options.camera, 0), b, file_lights.empty(), ground_y)
                          : fit_camera(b, options.from.value_or(kFitFrom), kFitFovDeg, 1.0f);
    s.background = {0.23f, 0.27f, 0.34f};
    if (!file_lights.empty()) {
        // The file's lights replace the rig; glTF has no ambient term.
        s.lights = file_lights;
        s.ambient = options.ambient.value_or(glm::vec3(0.0f));
        return s;
    }
    s.ambient = options.ambient.value_or(glm::vec3(0.2f));

    // The ground: a grey square just under the lowest point (a thousandth of the radius, so a
    // model's flat base does not fight it for depth), centred under the bounding sphere.
    Material ground;
    ground.name = kGroundMaterial;
    ground.diffuse = glm::vec3(0.55f);
    ground.specular = glm::vec3(0.1f);
    ground.shininess = 16;
    s.materials.push_back(ground);
    const double side = 8 * r;
    const glm::dvec3 at(b.centre.x, ground_y, b.centre.z);
    ShapeDesc shape;
    shape.kind = ShapeDesc::Kind::plane;
    shape.centre = glm::vec3(at);
    shape.size = glm::vec3(float(side), 0, float(side));
    s.add(make_plane(float(side), int(s.materials.size() - 1)), glm::translate(glm::dmat4(1.0), at), shape);
    if (!own_camera) {
        // far reaches the ground's farthest corner (the sphere alone sets it otherwise).
        double far = s.camera.far_plane;
        for (int c = 0; c < 4; ++c) {
            const glm::dvec3 corner = at + glm::dvec3((c & 1) ? side / 2 : -side / 2, 0, (c & 2) ? side / 2 : -side / 2);
            far = std::max(far, 1.05 * glm::length(corner - glm::dvec3(s.camera.pos)));
        }
        s.camera.far_plane = float(far);
    }

    // The rig, in bounding radii from the centre; each radius reaches past the ground's corners.
    // The key light casts a shadow (scene.h LightShadow), so the model stands on the ground.
    const glm::dvec3 c = b.centre;
    Light key = point_light(c + 3.0 * r * glm::normalize(glm::dvec3(1.5, 2.0, 1.2)), {1.0f, 0.95f, 0.85f}, 10 * r);
    key.shadow.on = true;
    s.lights.push_back(key);
    s.lights.push_back(point_light(c + 3.0 * r * glm::normalize(glm::dvec3(-2.0, 0.6, 1.0)), {0.30f, 0.36f, 0.48f}, 8 * r));
    s.lights.push_back(point_light(c + 3.0 * r * glm::normalize(glm::dvec3(-0.6, 1.4, -2.0)), {0.55f, 0.55f, 0.6f}, 7 * r));
    return s;
}

}  // namespace dsr
