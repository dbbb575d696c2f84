// The glTF node hierarchy (gltf_internal.h): parents, cycles and depth checked before anything is
// walked, world matrices composed in double, and the cameras and KHR_lights_punctual lights of the
// default scene's nodes placed by them.
#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_internal.h"
#include "scene/light_law.h"
#include "scene/user_file.h"

namespace dsr::gltf {

using nlohmann::json;
using std::string;

namespace {

glm::dmat4 local_matrix(const Context& ctx, int i) {
    const tinygltf::Node& n = ctx.tm.nodes[size_t(i)];
    const string np = "/nodes/" + std::to_string(i);
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) ctx.fail(np + "/matrix", "expected 16 numbers");
        if (!n.translation.empty() || !n.rotation.empty() || !n.scale.empty())
            ctx.fail(np, "expected a matrix or translation/rotation/scale, got both");
        glm::dmat4 m;
        for (int k = 0; k < 16; ++k) glm::value_ptr(m)[k] = n.matrix[size_t(k)];
        if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
            ctx.fail(np + "/matrix", "expected an affine matrix (last row 0 0 0 1), got a projective one");
        return m;
    }
    glm::dmat4 m(1.0);
    if (!n.translation.empty()) m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    if (!n.rotation.empty()) {
        glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // glTF: x, y, z, w
        const double l = glm::length(q);
        if (!(l > 1e-6)) ctx.fail(np + "/rotation", "expected a unit quaternion, got one of length " + num(l));
        m = m * glm::mat4_cast(q / l);
    }
    if (!n.scale.empty()) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

bool is_similarity(const glm::dmat4& m) {
    const glm::dmat3 a(m);
    const double det = glm::determinant(a);
    if (!(det > 0) || !std::isfinite(det)) return false;
    const glm::dmat3 b = a / std::cbrt(det);
    const glm::dmat3 g = glm::transpose(b) * b;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::fabs(g[c][r] - (c == r ? 1.0 : 0.0)) > 1e-6) return false;
    return true;
}

std::vector<NodePlacement> walk_scene(Context& ctx) {
    const auto& nodes = ctx.tm.nodes;
    const size_t n = nodes.size();
    std::vector<int> parent(n, -1);
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < nodes[i].children.size(); ++k) {
            const int c = nodes[i].children[k];
            const string cp = "/nodes/" + std::to_string(i) + "/children/" + std::to_string(k);
            if (c < 0 || size_t(c) >= n)
                ctx.fail(cp, "expected a node index below " + std::to_string(n) + ", got " + std::to_string(c));
            if (size_t(c) == i) ctx.fail(cp, "expected another node, got the node itself (a cycle)");
            if (parent[size_t(c)] >= 0)
                ctx.fail(cp, "expected a node with one parent, got node " + std::to_string(c) + ", already a child of node " +
                                 std::to_string(parent[size_t(c)]));
            parent[size_t(c)] = int(i);
        }
    // Each node has at most one parent: a cycle is a loop of parent links.
    std::vector<char> state(n, 0);  // 0 unseen, 1 on the current walk up, 2 done
    for (size_t i = 0; i < n; ++i) {
        std::vector<size_t> walk;
        for (size_t j = i;;) {
            if (state[j] == 1)
                ctx.fail("/nodes/" + std::to_string(parent[j]) + "/children",
                         "expected a tree, got a cycle through node " + std::to_string(j));
            if (state[j] == 2) break;
            state[j] = 1;
            walk.push_back(j);
            if (parent[j] < 0) break;
            j = size_t(parent[j]);
        }
        for (size_t w : walk) state[w] = 2;
    }

    std::vector<int> roots;
    if (ctx.tm.scenes.empty()) {
        if (n > 0) ctx.warn("/", "no scenes: every root node is drawn");
        for (size_t i = 0; i < n; ++i)
            if (parent[i] < 0) roots.push_back(int(i));
    } else {
        int s = ctx.tm.defaultScene;
        if (s < 0) s = 0;
        if (size_t(s) >= ctx.tm.scenes.size())
            ctx.fail("/scene", "expected a scene index below " + std::to_string(ctx.tm.scenes.size()) + ", got " + std::to_string(s));
        const auto& list = ctx.tm.scenes[size_t(s)].nodes;
        std::vector<char> listed(n, 0);
        for (size_t k = 0; k < list.size(); ++k) {
            const int r = list[k];
            const string rp = "/scenes/" + std::to_string(s) + "/nodes/" + std::to_string(k);
            if (r < 0 || size_t(r) >= n) ctx.fail(rp, "expected a node index below " + std::to_string(n) + ", got " + std::to_string(r));
            if (parent[size_t(r)] >= 0)
                ctx.fail(rp, "expected a root node, got node " + std::to_string(r) + ", a child of node " + std::to_string(parent[size_t(r)]));
            if (listed[size_t(r)]) ctx.fail(rp, "expected each root once, got node " + std::to_string(r) + " again");
            listed[size_t(r)] = 1;
            roots.push_back(r);
        }
    }

    std::vector<NodePlacement> out;
    struct Item {
        int node, depth;
        glm::dmat4 parent_world;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, 1, glm::dmat4(1.0)});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const string np = "/nodes/" + std::to_string(item.node);
        if (item.depth > kMaxNodeDepth)
            ctx.fail(np, "expected a node hierarchy at most " + std::to_string(kMaxNodeDepth) + " deep, got deeper (an absurd size)");
        const glm::dmat4 world = item.parent_world * local_matrix(ctx, item.node);
        if (!finite(world) || std::fabs(world[3][0]) > kMaxCoordinate || std::fabs(world[3][1]) > kMaxCoordinate ||
            std::fabs(world[3][2]) > kMaxCoordinate)
            ctx.fail(np, "expected a world placement within +-1e12, got one beyond");
        out.push_back({item.node, world});
        const auto& ch = nodes[size_t(item.node)].children;
        for (auto it = ch.rbegin(); it != ch.rend(); ++it) stack.push_back({*it, item.depth + 1, world});
    }
    return out;
}

void read_cameras_and_lights(Context& ctx, const std::vector<NodePlacement>& placed) {
    const json* lights = ctx.at("/extensions/KHR_lights_punctual/lights");
    for (const NodePlacement& np : placed) {
        const tinygltf::Node& node = ctx.tm.nodes[size_t(np.node)];
        const string nptr = "/nodes/" + std::to_string(np.node);
        const glm::dmat3 a(np.world);
        const glm::dvec3 pos(np.world[3]);
        auto axis = [&](glm::dvec3 v) {
            const glm::dvec3 w = a * v;
            const double l = glm::length(w);
            return l > 0 && std::isfinite(l) ? w / l : glm::dvec3(0);
        };
        const glm::dvec3 forward = axis({0, 0, -1}), up = axis({0, 1, 0});
        if (node.camera >= 0) {
            if (size_t(node.camera) >= ctx.tm.cameras.size())
                ctx.fail(nptr + "/camera", "expected a camera index below " + std::to_string(ctx.tm.cameras.size()) + ", got " +
                                               std::to_string(node.camera));
            const tinygltf::Camera& c = ctx.tm.cameras[size_t(node.camera)];
            const string cp = "/cameras/" + std::to_string(node.camera);
            if (c.type == "orthographic") {
                ctx.warn(cp, "orthographic camera skipped (dsr's cameras are perspective)");
            } else if (c.type != "perspective") {
                ctx.fail(cp + "/type", "expected perspective or orthographic, got " + quote(c.type));
            } else {
                const auto& p = c.perspective;
                if (!(p.yfov > 0 && p.yfov < M_PI)) ctx.fail(cp + "/perspective/yfov", "expected radians in (0, pi), got " + num(p.yfov));
                if (!(p.znear > 0)) ctx.fail(cp + "/perspective/znear", "expected a number > 0, got " + num(p.znear));
                bool far_given = ctx.at(cp + "/perspective/zfar") != nullptr;
                if (far_given && !(p.zfar > p.znear))
                    ctx.fail(cp + "/perspective/zfar", "expected a number > znear " + num(p.znear) + ", got " + num(p.zfar));
                if (far_given && p.zfar / p.znear > 1e7) {
                    // dsr's depth paths hold at most 1e7 (docs/scene-format.md): far comes from the bounds.
                    ctx.warn(cp + "/perspective/zfar", "zfar / znear " + num(p.zfar / p.znear) +
                                                           " is beyond dsr's 1e7: zfar ignored, the far plane set from the model's bounds");
                    far_given = false;
                }
                if (forward == glm::dvec3(0) || up == glm::dvec3(0) || glm::length(glm::cross(forward, up)) < 1e-6)
                    ctx.fail(nptr, "expected a placement that keeps the camera's -Z and +Y apart, got a degenerate one");
                GltfCamera gc;
                gc.name = c.name.empty() ? "#" + std::to_string(node.camera) : c.name;
                gc.camera.pos = glm::vec3(pos);
                gc.camera.target = glm::vec3(pos + forward);
                gc.camera.up = glm::vec3(up);
                gc.camera.fov_deg = float(glm::degrees(p.yfov));
                gc.camera.near_plane = float(p.znear);
                if (far_given) gc.camera.far_plane = float(p.zfar);
                gc.far_given = far_given;
                ctx.out.cameras.push_back(gc);
            }
        }
        const json* ref = ctx.at(nptr + "/extensions/KHR_lights_punctual/light");
        if (!ref) continue;
        const size_t li = ref->get<size_t>();
        if (!lights || li >= lights->size())
            ctx.fail(nptr + "/extensions/KHR_lights_punctual/light",
                     "expected a light index below " + std::to_string(lights ? lights->size() : 0) + ", got " + std::to_string(li));
        const json& gl = (*lights)[li];
        const string lp = "/extensions/KHR_lights_punctual/lights/" + std::to_string(li);
        auto number = [&](const json& o, const char* key, double dflt) {
            auto it = o.find(key);
            return it == o.end() ? dflt : it->get<double>();
        };
        glm::dvec3 colour(1);
        if (auto it = gl.find("color"); it != gl.end())
            for (int c = 0; c < 3; ++c) {
                colour[c] = (*it)[size_t(c)].get<double>();
                if (!(colour[c] >= 0 && colour[c] <= 1)) ctx.fail(lp + "/color/" + std::to_string(c), "expected a number in [0, 1], got " + num(colour[c]));
            }
        const double intensity = number(gl, "intensity", 1.0);
        if (!(intensity >= 0 && intensity <= 1e12))
            ctx.fail(lp + "/intensity", "expected a number in [0, 1e12], got " + num(intensity));
        const string type = gl.at("type").get<string>();
        // KHR_lights_punctual's units and laws (scene.h Light, docs/metal_rough.md): colour times
        // candela or lux.
        Light l;
        l.physical = true;
        l.color = glm::vec3(colour * intensity);
        const double i_max = std::max({double(l.color.r), double(l.color.g), double(l.color.b)});
        if (type == "directional") {
            l.type = Light::Type::directional;
            l.dir = glm::vec3(forward);
            if (forward == glm::dvec3(0)) ctx.fail(nptr, "expected a placement with a direction for the light, got a degenerate one");
            l.pos = glm::vec3(pos);
            l.radius = 1;
        } else if (type == "point" || type == "spot") {
            l.type = type == "point" ? Light::Type::point : Light::Type::spot;
            l.pos = glm::vec3(pos);
            if (auto it = gl.find("range"); it != gl.end()) {
                const double range = it->get<double>();
                // 1e-12: 1 / range^2 stays a finite float (the light shaders' window).
                if (!(range >= 1e-12 && range <= 1e12))
                    ctx.fail(lp + "/range", "expected a number in [1e-12, 1e12], got " + num(range));
                l.range = float(range);
            }
            const double radius = physical_radius(i_max, l.range);
            if (!(radius > 0)) {
                ctx.warn(lp, "a light of intensity 0 is left out");
                continue;
            }
            if (!(radius <= 1e12)) ctx.fail(lp + "/intensity", "expected an intensity whose bound is within 1e12, got one of " + num(radius));
            l.radius = float(radius);
            if (l.type == Light::Type::spot) {
                if (forward == glm::dvec3(0)) ctx.fail(nptr, "expected a placement with a direction for the light, got a degenerate one");
                l.dir = glm::vec3(forward);
                const json* spot = ctx.at(lp + "/spot");
                const double inner = spot ? number(*spot, "innerConeAngle", 0.0) : 0.0;
                const double outer = spot ? number(*spot, "outerConeAngle", M_PI / 4) : M_PI / 4;
                if (!(outer > 0 && outer <= M_PI / 2))
                    ctx.fail(lp + "/spot/outerConeAngle", "expected radians in (0, pi/2], got " + num(outer));
                if (!(inner >= 0 && inner < outer))
                    ctx.fail(lp + "/spot/innerConeAngle", "expected radians in [0, outerConeAngle), got " + num(inner));
                l.angle_deg = float(glm::degrees(outer));
                l.inner_deg = float(glm::degrees(inner));
            }
        } else {
            ctx.fail(lp + "/type", "expected point, spot or directional, got " + quote(type));
        }
        ctx.out.lights.push_back(l);
    }
}

}  // namespace dsr::gltf
