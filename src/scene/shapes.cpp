// The scene format's shapes, built in object space (centred on the origin) with the tangent frames the material pass
// needs (Listing 10): tangent = direction of +u, binormal = direction of +v, and
// cross(tangent, binormal) = normal everywhere, so a tangent-space normal map reads the same
// on every face. The plane's and box's frames come from compute_tangents (scene/tangents.h),
// the routine OBJ meshes use (every figure and image is byte-identical to the hand-written
// frames it replaced); the sphere keeps its exact analytic frame (see make_sphere).
// Triangles wind counter-clockwise seen from outside (GL front faces).
#include <cmath>

#include "dsr_error.h"
#include "scene/scene.h"
#include "scene/tangents.h"

namespace dsr {

namespace {

// One quad with uv (0,0)..(1,1): corners at centre +- half_t * t +- half_b * b.
// The corners go round counter-clockwise in the (t, b) plane, so with cross(t, b) = n the
// triangles face n.
void add_quad(Mesh& m, glm::vec3 centre, glm::vec3 n, glm::vec3 t, glm::vec3 b, float half_t,
              float half_b) {
    const uint32_t base = uint32_t(m.vertices.size());
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const glm::vec2& uv : uvs) {
        Vertex v;
        v.pos = centre + (2 * uv.x - 1) * half_t * t + (2 * uv.y - 1) * half_b * b;
        v.normal = n;
        v.uv = uv;
        m.vertices.push_back(v);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

}  // namespace

Mesh make_plane(float size, int material) {
    Mesh m;
    m.material = material;
    // u along +X, v along -Z: cross(+X, -Z) = +Y.
    add_quad(m, glm::vec3(0), {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, size / 2, size / 2);
    compute_tangents(m);
    return m;
}

Mesh make_box(glm::vec3 size, int material) {
    Mesh m;
    m.material = material;
    const glm::vec3 h = size / 2.0f;
    // For each face: normal, tangent, binormal with cross(t, b) = n; v runs up (+Y) on the
    // sides, so bricks on walls stand the right way up.
    struct Face { glm::vec3 n, t, b; float half_n, half_t, half_b; };
    const Face faces[6] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}, h.x, h.z, h.y},   // +X
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, h.x, h.z, h.y},   // -X
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, h.y, h.x, h.z},   // +Y
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, h.y, h.x, h.z},   // -Y
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, h.z, h.x, h.y},    // +Z
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, h.z, h.x, h.y},  // -Z
    };
    for (const Face& f : faces) add_quad(m, f.half_n * f.n, f.n, f.t, f.b, f.half_t, f.half_b);
    compute_tangents(m);
    return m;
}

Mesh make_sphere(float radius, int material, int slices, int stacks) {
    if (slices < 3 || stacks < 2) throw Error("make_sphere: need slices >= 3 and stacks >= 2");
    Mesh m;
    m.material = material;
    const double pi = 3.14159265358979323846;
    // Grid of (slices+1) x (stacks+1) vertices: the seam column u = 1 is duplicated so uv
    // stays continuous; pole rows are duplicated per slice so each keeps its own tangent.
    for (int j = 0; j <= stacks; ++j) {
        const float v = float(j) / float(stacks);
        const double theta = pi * v;  // 0 at the south pole, pi at the north pole
        const float sin_t = float(std::sin(theta)), cos_t = float(std::cos(theta));
        for (int i = 0; i <= slices; ++i) {
            const float u = float(i) / float(slices);
            const double phi = 2 * pi * u;
            const float sin_p = float(std::sin(phi)), cos_p = float(std::cos(phi));
            Vertex vx;
            // Around the equator the point moves toward -Z as u grows from +X, so that
            // cross(dP/du, dP/dv) points outward.
            vx.normal = glm::vec3(sin_t * cos_p, -cos_t, -sin_t * sin_p);
            if (j == 0) vx.normal = {0, -1, 0};
            if (j == stacks) vx.normal = {0, 1, 0};
            vx.pos = radius * vx.normal;
            vx.uv = {u, v};
            // dP/du / |dP/du| is the azimuthal direction, which also stays defined at the poles.
            // The sphere keeps this exact frame of its parametrisation rather than
            // compute_tangents' per-vertex average of the facets, which on a coarse sphere leans
            // up to 40 degrees off a facet's dP/dv (Shapes.TangentFollowsUAndBinormalFollowsV).
            vx.tangent = glm::vec3(-sin_p, 0, -cos_p);
            vx.binormal = glm::cross(vx.normal, vx.tangent);
            m.vertices.push_back(vx);
        }
    }
    const uint32_t row = uint32_t(slices + 1);
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            const uint32_t a = uint32_t(j) * row + uint32_t(i), b = a + 1, c = b + row, d = a + row;
            // Quad a b c d is counter-clockwise seen from outside; drop the triangle that
            // collapses to a line at each pole.
            if (j != 0) for (uint32_t k : {a, b, c}) m.indices.push_back(k);
            if (j != stacks - 1) for (uint32_t k : {a, c, d}) m.indices.push_back(k);
        }
    }
    return m;
}

static glm::dmat4 translation(glm::vec3 at) {
    glm::dmat4 t(1.0);
    t[3] = glm::dvec4(glm::dvec3(at), 1.0);
    return t;
}

size_t add_plane(Scene& scene, float size, glm::vec3 at, int material) {
    return scene.add(make_plane(size, material), translation(at),
                     ShapeDesc{ShapeDesc::Kind::plane, at, {size, 0, size}, 0});
}

size_t add_box(Scene& scene, glm::vec3 size, glm::vec3 at, int material) {
    return scene.add(make_box(size, material), translation(at), ShapeDesc{ShapeDesc::Kind::box, at, size, 0});
}

size_t add_sphere(Scene& scene, float radius, glm::vec3 at, int material, int slices, int stacks) {
    return scene.add(make_sphere(radius, material, slices, stacks), translation(at),
                     ShapeDesc{ShapeDesc::Kind::sphere, at, glm::vec3(2 * radius), radius});
}

size_t Scene::add(Mesh mesh, const glm::dmat4& model, std::optional<ShapeDesc> shape) {
    Object o;
    o.mesh = meshes.size();
    o.model = model;
    o.material = mesh.material;
    o.shape = shape;
    meshes.push_back(std::move(mesh));
    objects.push_back(o);
    return objects.size() - 1;
}

size_t Scene::triangle_count() const {
    size_t n = 0;
    for (const Object& o : objects) n += meshes.at(o.mesh).indices.size() / 3;
    return n;
}

glm::mat4 camera_relative(const glm::dmat4& view, const glm::dmat4& model) { return glm::mat4(view * model); }

}  // namespace dsr
