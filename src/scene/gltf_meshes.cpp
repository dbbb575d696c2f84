// glTF primitives as dsr Meshes (gltf_internal.h): strips and fans triangulated as glTF 2.0
// orders them, missing normals flat per face (glTF requires flat ones), uvs through the
// material's KHR_texture_transform and flipped to dsr's bottom-row-first images, tangent frames
// from compute_tangents.
#include <cmath>
#include <string>

#include "scene/gltf_internal.h"
#include "scene/tangents.h"

namespace dsr::gltf {

using std::string;

namespace {

constexpr int kAllComponents[] = {TINYGLTF_COMPONENT_TYPE_BYTE,  TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                  TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                  TINYGLTF_COMPONENT_TYPE_INT,   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                  TINYGLTF_COMPONENT_TYPE_FLOAT};

AccessorRule rule(std::vector<int> types) {
    AccessorRule r;
    r.types = std::move(types);
    r.component_types.assign(std::begin(kAllComponents), std::end(kAllComponents));
    return r;
}

int mode_of(const tinygltf::Primitive& p) { return p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode; }

const char* mode_name(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    }
    return "?";
}

int attribute(const tinygltf::Primitive& p, const char* name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

// Triangles from n indices in `mode`, glTF 2.0's order (3.7.2.1): strips {i, i+1+i%2, i+2-i%2},
// fans {i+1, i+2, 0}.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& idx, int mode) {
    std::vector<uint32_t> out;
    const size_t n = idx.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(idx.begin(), idx.begin() + long(n / 3 * 3));
    } else if (n >= 3) {
        out.reserve((n - 2) * 3);
        for (size_t i = 0; i + 2 < n; ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                out.push_back(idx[i]);
                out.push_back(idx[i + 1 + i % 2]);
                out.push_back(idx[i + 2 - i % 2]);
            } else {
                out.push_back(idx[i + 1]);
                out.push_back(idx[i + 2]);
                out.push_back(idx[0]);
            }
        }
    }
    return out;
}

}  // namespace

size_t primitive_triangles(const Context& ctx, int mesh, int prim) {
    const tinygltf::Primitive& p = ctx.tm.meshes[size_t(mesh)].primitives[size_t(prim)];
    const int mode = mode_of(p);
    if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN) return 0;
    const string pp = "/meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(prim);
    const int pos = attribute(p, "POSITION");
    if (pos < 0) return 0;
    const size_t n = p.indices >= 0 ? accessor_count(ctx, p.indices, pp + "/indices")
                                    : accessor_count(ctx, pos, pp + "/attributes/POSITION");
    return mode == TINYGLTF_MODE_TRIANGLES ? n / 3 : n >= 2 ? n - 2 : 0;
}

std::vector<PrimitiveMesh> read_mesh(Context& ctx, int mesh_index, const std::vector<MaterialUse>& materials) {
    std::vector<PrimitiveMesh> out;
    const tinygltf::Mesh& gm = ctx.tm.meshes[size_t(mesh_index)];
    const string mp = "/meshes/" + std::to_string(mesh_index);
    for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
        const tinygltf::Primitive& p = gm.primitives[pi];
        const string pp = mp + "/primitives/" + std::to_string(pi);
        const int mode = mode_of(p);
        if (mode < TINYGLTF_MODE_TRIANGLES) {
            ctx.warn_once(string("mode ") + mode_name(mode), pp + "/mode",
                          string(mode_name(mode)) + " primitives skipped (dsr draws triangles)");
            continue;
        }
        if (mode > TINYGLTF_MODE_TRIANGLE_FAN) ctx.fail(pp + "/mode", "expected a primitive mode in [0, 6], got " + std::to_string(mode));
        const int pos_acc = attribute(p, "POSITION");
        if (pos_acc < 0) {
            ctx.warn(pp + "/attributes", "a primitive without POSITION is skipped");
            continue;
        }
        if (!p.targets.empty())
            ctx.warn_once("morph", pp + "/targets", "morph targets ignored: drawn in the rest pose");
        if (p.material >= 0 && size_t(p.material) + 1 >= materials.size())
            ctx.fail(pp + "/material", "expected a material index below " + std::to_string(materials.size() - 1) +
                                           ", got " + std::to_string(p.material));
        const size_t mat = p.material >= 0 ? size_t(p.material) : materials.size() - 1;
        const MaterialUse& use = materials[mat];

        const Values pos = read_accessor(ctx, pos_acc, pp + "/attributes/POSITION", rule({TINYGLTF_TYPE_VEC3}));
        const size_t n = pos.count;
        for (size_t i = 0; i < pos.v.size(); ++i)
            if (!(std::fabs(pos.v[i]) <= kMaxCoordinate))
                ctx.fail("/accessors/" + std::to_string(pos_acc),
                         "expected positions within +-1e12, got " + num(pos.v[i]) + " in element " + std::to_string(i / 3));
        auto read_attr = [&](const char* name, std::vector<int> types) -> Values {
            const int a = attribute(p, name);
            if (a < 0) return {};
            Values v = read_accessor(ctx, a, pp + "/attributes/" + name, rule(std::move(types)));
            if (v.count != n)
                ctx.fail(pp + "/attributes/" + name, "expected " + std::to_string(n) + " elements (POSITION's count), got " +
                                                         std::to_string(v.count));
            return v;
        };
        const Values normal = read_attr("NORMAL", {TINYGLTF_TYPE_VEC3});
        const string uv_name = "TEXCOORD_" + std::to_string(use.uv_set);
        const Values uv = read_attr(uv_name.c_str(), {TINYGLTF_TYPE_VEC2});
        if (use.needs_uvs && uv.count == 0)
            ctx.warn(pp + "/attributes", "the material's maps read " + uv_name + ", which the primitive does not have: uv 0 used");
        const Values colour = read_attr("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4});

        std::vector<uint32_t> idx;
        if (p.indices >= 0) {
            AccessorRule r;
            r.types = {TINYGLTF_TYPE_SCALAR};
            r.component_types = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
            const Values iv = read_accessor(ctx, p.indices, pp + "/indices", r);
            idx.resize(iv.count);
            for (size_t i = 0; i < iv.count; ++i) {
                if (!(iv.v[i] < double(n)))
                    ctx.fail("/accessors/" + std::to_string(p.indices),
                             "expected vertex indices below POSITION's count " + std::to_string(n) + " (for " + pp +
                                 "/indices), got " + num(iv.v[i]) + " at " + std::to_string(i));
                idx[i] = uint32_t(iv.v[i]);
            }
        } else {
            idx.resize(n);
            for (size_t i = 0; i < n; ++i) idx[i] = uint32_t(i);
        }
        if (mode == TINYGLTF_MODE_TRIANGLES && idx.size() % 3 != 0)
            ctx.warn(p.indices >= 0 ? pp + "/indices" : pp + "/attributes/POSITION",
                     std::to_string(idx.size()) + " vertices for TRIANGLES, not a multiple of 3: the last " +
                         std::to_string(idx.size() % 3) + " left out");
        const std::vector<uint32_t> tri = triangulate(idx, mode);
        if (tri.empty()) {
            ctx.warn(pp, "a primitive with no triangles is skipped");
            continue;
        }

        PrimitiveMesh pm;
        pm.pointer = pp;
        Mesh& m = pm.mesh;
        m.material = int(mat);
        m.two_sided = use.double_sided;
        auto vertex = [&](size_t i) {
            Vertex v;
            v.pos = glm::vec3(float(pos.at(i, 0)), float(pos.at(i, 1)), float(pos.at(i, 2)));
            if (normal.count) {
                glm::dvec3 nn(normal.at(i, 0), normal.at(i, 1), normal.at(i, 2));
                const double l = glm::length(nn);
                v.normal = l > 0 ? glm::vec3(nn / l) : glm::vec3(0);
            }
            if (uv.count) {
                glm::dvec3 t(uv.at(i, 0), uv.at(i, 1), 1.0);
                if (use.has_transform) t = use.uv_transform * t;
                if (!(std::fabs(t.x) <= kMaxCoordinate && std::fabs(t.y) <= kMaxCoordinate))
                    ctx.fail(pp + "/attributes/" + uv_name, "expected uvs within +-1e12" +
                                                                string(use.has_transform ? " after KHR_texture_transform" : "") +
                                                                ", got (" + num(t.x) + ", " + num(t.y) + ") in element " + std::to_string(i));
                v.uv = glm::vec2(float(t.x), float(1.0 - t.y));  // glTF's origin is the image's top left
            }
            return v;
        };
        auto colour_of = [&](size_t i) {
            return glm::vec4(float(colour.at(i, 0)), float(colour.at(i, 1)), float(colour.at(i, 2)),
                             colour.comps == 4 ? float(colour.at(i, 3)) : 1.0f);
        };
        if (normal.count) {
            m.vertices.reserve(n);
            for (size_t i = 0; i < n; ++i) m.vertices.push_back(vertex(i));
            if (colour.count)
                for (size_t i = 0; i < n; ++i) m.colors.push_back(colour_of(i));
            m.indices = tri;
        } else {
            // Flat normals (glTF 2.0, 3.7.2.1): three vertices of its own per triangle.
            m.vertices.reserve(tri.size());
            for (size_t t = 0; t < tri.size(); t += 3) {
                Vertex v[3] = {vertex(tri[t]), vertex(tri[t + 1]), vertex(tri[t + 2])};
                const glm::dvec3 a(v[0].pos), b(v[1].pos), c(v[2].pos);
                const glm::dvec3 fn = glm::cross(b - a, c - a);
                const double l = glm::length(fn);
                for (Vertex& x : v) {
                    x.normal = l > 0 && std::isfinite(l) ? glm::vec3(fn / l) : glm::vec3(0);
                    m.indices.push_back(uint32_t(m.vertices.size()));
                    m.vertices.push_back(x);
                }
                if (colour.count)
                    for (int k = 0; k < 3; ++k) m.colors.push_back(colour_of(tri[t + size_t(k)]));
            }
        }
        compute_tangents(m);
        out.push_back(std::move(pm));
    }
    return out;
}

Mesh bake(const Mesh& mesh, const glm::dmat4& world) {
    Mesh m = mesh;
    const glm::dmat3 a(world);
    const glm::dmat3 nt = glm::transpose(glm::inverse(a));
    for (Vertex& v : m.vertices) {
        v.pos = glm::vec3(glm::dvec3(world * glm::dvec4(glm::dvec3(v.pos), 1.0)));
        const glm::dvec3 n = nt * glm::dvec3(v.normal);
        const double l = glm::length(n);
        v.normal = l > 0 && std::isfinite(l) ? glm::vec3(n / l) : glm::vec3(0);
    }
    if (glm::determinant(a) < 0)
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
    compute_tangents(m);
    return m;
}

}  // namespace dsr::gltf
