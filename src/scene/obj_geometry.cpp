// The OBJ loader's geometry (obj_geometry.h): triangles, normals and material groups from what
// tinyobjloader returned, each linear in the corners.
#include "scene/obj_geometry.h"

#include <cmath>
#include <cstring>

#include "dsr_error.h"
#include "scene/tangents.h"

namespace dsr::obj {

using std::string;

namespace {

// Open-addressing table from a corner key to its vertex index: linear in the corners.
class CornerTable {
public:
    explicit CornerTable(size_t expected) {
        size_t cap = 16;
        while (cap < expected * 2) cap *= 2;
        keys_.assign(cap, Key{-1, 0, 0});
        values_.resize(cap);
        mask_ = cap - 1;
    }
    // Index for the key, inserting `next` when new; sets `inserted`.
    uint32_t find_or_add(int a, int b, int c, uint32_t next, bool& inserted) {
        size_t h = (size_t(uint32_t(a)) * 0x9E3779B97F4A7C15ull) ^ (size_t(uint32_t(b)) * 0xC2B2AE3D27D4EB4Full) ^
                   (size_t(uint32_t(c)) * 0x165667B19E3779F9ull);
        h ^= h >> 29;
        for (size_t i = h & mask_;; i = (i + 1) & mask_) {
            Key& k = keys_[i];
            if (k.a == -1) {
                k = Key{a, b, c};
                values_[i] = next;
                inserted = true;
                return next;
            }
            if (k.a == a && k.b == b && k.c == c) {
                inserted = false;
                return values_[i];
            }
        }
    }

private:
    struct Key { int a, b, c; };
    std::vector<Key> keys_;
    std::vector<uint32_t> values_;
    size_t mask_ = 0;
};

glm::dvec3 vec_at(const std::vector<tinyobj::real_t>& a, size_t i) {
    return {double(a[3 * i]), double(a[3 * i + 1]), double(a[3 * i + 2])};
}

}  // namespace

Triangles collect_triangles(const string& path, const string& obj_name, const tinyobj::attrib_t& attrib,
                            const std::vector<tinyobj::shape_t>& shapes, ObjModel& model) {
    const size_t nv = attrib.vertices.size() / 3, nvt = attrib.texcoords.size() / 2, nvn = attrib.normals.size() / 3;
    size_t ntri = 0;
    for (const tinyobj::shape_t& sh : shapes) ntri += sh.mesh.num_face_vertices.size();
    Triangles out;
    std::vector<Corner>& corners = out.corners;
    std::vector<int>& tri_material = out.material;
    std::vector<glm::dvec3>& face_n = out.face_n;
    corners.reserve(ntri * 3);
    tri_material.reserve(ntri);
    face_n.reserve(ntri);
    size_t degenerate = 0;
    bool default_material = false;
    for (const tinyobj::shape_t& sh : shapes) {
        const auto& mesh = sh.mesh;
        if (mesh.indices.size() != 3 * mesh.num_face_vertices.size() || mesh.material_ids.size() != mesh.num_face_vertices.size())
            throw Error(path + ": tinyobjloader returned faces that are not triangles");
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            if (mesh.num_face_vertices[f] != 3) throw Error(path + ": tinyobjloader returned a face that is not a triangle");
            Corner c[3];
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& ix = mesh.indices[3 * f + size_t(k)];
                if (ix.vertex_index < 0 || size_t(ix.vertex_index) >= nv || ix.texcoord_index >= long(nvt) ||
                    ix.normal_index >= long(nvn) || ix.texcoord_index < -1 || ix.normal_index < -1)
                    throw Error(path + ": tinyobjloader returned a face index out of range");
                c[k] = {ix.vertex_index, ix.texcoord_index, ix.normal_index};
            }
            const glm::dvec3 p0 = vec_at(attrib.vertices, size_t(c[0].v)), p1 = vec_at(attrib.vertices, size_t(c[1].v)),
                             p2 = vec_at(attrib.vertices, size_t(c[2].v));
            const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
            if (!(glm::dot(n, n) > 0)) {
                ++degenerate;
                continue;
            }
            int mat = mesh.material_ids[f];
            if (mat < 0 || size_t(mat) >= model.materials.size()) {
                mat = -1;
                default_material = true;
            }
            for (const Corner& k : c) corners.push_back(k);
            tri_material.push_back(mat);
            face_n.push_back(n);
        }
    }
    if (degenerate)
        model.warnings.push_back(path + ": " + std::to_string(degenerate) + " zero-area triangles dropped");
    const size_t tris = tri_material.size();
    if (tris == 0) throw Error(path + ": expected at least one triangle with area, got none: an empty mesh");
    if (default_material) {
        Material d;
        d.name = obj_name + ":(default)";
        d.diffuse = glm::vec3(0.8f);
        model.materials.push_back(d);
        for (int& m : tri_material)
            if (m < 0) m = int(model.materials.size() - 1);
    }
    return out;
}

Normals smooth_normals(const string& path, const tinyobj::attrib_t& attrib, float smooth_angle_deg, Triangles& tris,
                       std::vector<string>& warnings) {
    const size_t nv = attrib.vertices.size() / 3, nvn = attrib.normals.size() / 3;
    std::vector<Corner>& corners = tris.corners;
    const std::vector<glm::dvec3>& face_n = tris.face_n;
    Normals out;
    std::vector<glm::vec3>& file_normal = out.file;
    file_normal.resize(nvn);
    std::vector<char> file_normal_ok(nvn, 0);
    for (size_t i = 0; i < nvn; ++i) {
        const glm::dvec3 n = vec_at(attrib.normals, i);
        const double l = std::sqrt(glm::dot(n, n));
        if (l > 0 && std::isfinite(l)) file_normal[i] = glm::vec3(n / l), file_normal_ok[i] = 1;
    }
    size_t zero_normals = 0;
    for (Corner& c : corners)
        if (c.vn >= 0 && !file_normal_ok[size_t(c.vn)]) c.vn = -1, ++zero_normals;
    if (zero_normals)
        warnings.push_back(path + ": " + std::to_string(zero_normals) + " corners with a zero normal: normals computed there");
    std::vector<uint32_t>& cluster = out.cluster;
    cluster.assign(corners.size(), 0);
    std::vector<glm::dvec3>& cluster_sum = out.cluster_sum;
    {
        // Positions are smoothed across by value, not index: files made of patches (the Newell
        // teapot) repeat each seam vertex, which would otherwise leave a crease along every seam.
        std::vector<uint32_t> same(nv);
        CornerTable by_value(nv);
        for (size_t i = 0; i < nv; ++i) {
            static_assert(sizeof(tinyobj::real_t) == sizeof(int), "float positions");
            int bits[3];
            std::memcpy(bits, &attrib.vertices[3 * i], sizeof bits);
            bool inserted = false;
            same[i] = by_value.find_or_add(bits[0] == -1 ? 0 : bits[0], bits[1], bits[2], uint32_t(i), inserted);
        }
        std::vector<uint32_t> start(nv + 1, 0);
        for (const Corner& c : corners)
            if (c.vn < 0) ++start[size_t(same[size_t(c.v)]) + 1];
        for (size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
        std::vector<uint32_t> fill(start.begin(), start.end() - 1), list(start[nv]);
        for (size_t i = 0; i < corners.size(); ++i)
            if (corners[i].vn < 0) list[fill[size_t(same[size_t(corners[i].v)])]++] = uint32_t(i);
        const double cos_limit = std::cos(double(smooth_angle_deg) * 3.14159265358979323846 / 180.0);
        const size_t kMaxClusters = 64;
        std::vector<glm::dvec3> seeds;
        std::vector<uint32_t> ids;
        for (size_t p = 0; p < nv; ++p) {
            seeds.clear();
            ids.clear();
            for (uint32_t j = start[p]; j < start[p + 1]; ++j) {
                const uint32_t corner = list[j];
                const glm::dvec3& fn = face_n[corner / 3];
                const glm::dvec3 u = fn / std::sqrt(glm::dot(fn, fn));
                size_t found = seeds.size(), nearest = 0;
                double nearest_dot = -2;
                for (size_t s = 0; s < seeds.size(); ++s) {
                    const double d = glm::dot(seeds[s], u);
                    if (d >= cos_limit) { found = s; break; }
                    if (d > nearest_dot) nearest_dot = d, nearest = s;
                }
                if (found == seeds.size()) {
                    if (seeds.size() < kMaxClusters) {
                        seeds.push_back(u);
                        ids.push_back(uint32_t(cluster_sum.size()));
                        cluster_sum.push_back(glm::dvec3(0));
                    } else {
                        found = nearest;
                    }
                }
                const size_t best = found;
                cluster_sum[ids[best]] += fn;
                cluster[corner] = ids[best];
            }
        }
    }
    return out;
}

void group_by_material(const tinyobj::attrib_t& attrib, const Triangles& triangles, const Normals& normals,
                       ObjModel& model) {
    const std::vector<Corner>& corners = triangles.corners;
    const std::vector<int>& tri_material = triangles.material;
    const std::vector<glm::dvec3>& face_n = triangles.face_n;
    const std::vector<glm::vec3>& file_normal = normals.file;
    const std::vector<uint32_t>& cluster = normals.cluster;
    const std::vector<glm::dvec3>& cluster_sum = normals.cluster_sum;
    const size_t tris = tri_material.size();
    std::vector<uint32_t> order(tris);
    {
        std::vector<uint32_t> start(model.materials.size() + 1, 0);
        for (int m : tri_material) ++start[size_t(m) + 1];
        for (size_t i = 0; i < model.materials.size(); ++i) start[i + 1] += start[i];
        for (uint32_t t = 0; t < tris; ++t) order[start[size_t(tri_material[t])]++] = t;
    }
    size_t i = 0;
    while (i < tris) {
        const int mat = tri_material[order[i]];
        size_t j = i;
        while (j < tris && tri_material[order[j]] == mat) ++j;
        Mesh mesh;
        mesh.material = mat;
        mesh.indices.reserve((j - i) * 3);
        CornerTable table((j - i) * 3);
        for (size_t k = i; k < j; ++k)
            for (int q = 0; q < 3; ++q) {
                const size_t ci = size_t(order[k]) * 3 + size_t(q);
                const Corner& c = corners[ci];
                const int nkey = c.vn >= 0 ? c.vn : -2 - int(cluster[ci]);
                bool inserted = false;
                const uint32_t idx = table.find_or_add(c.v, c.vt, nkey, uint32_t(mesh.vertices.size()), inserted);
                if (inserted) {
                    Vertex v;
                    v.pos = glm::vec3(vec_at(attrib.vertices, size_t(c.v)));
                    if (c.vt >= 0) v.uv = {attrib.texcoords[2 * size_t(c.vt)], attrib.texcoords[2 * size_t(c.vt) + 1]};
                    if (c.vn >= 0) {
                        v.normal = file_normal[size_t(c.vn)];
                    } else {
                        // Within a cluster the face normals lie within the angle of its seed, so
                        // the sum is not zero; past kMaxClusters it might be: the face's own.
                        glm::dvec3 s = cluster_sum[cluster[ci]];
                        if (!(glm::dot(s, s) > 0) || !std::isfinite(glm::dot(s, s))) s = face_n[ci / 3];
                        v.normal = glm::vec3(s / std::sqrt(glm::dot(s, s)));
                    }
                    mesh.vertices.push_back(v);
                }
                mesh.indices.push_back(idx);
            }
        compute_tangents(mesh);
        model.vertices += mesh.vertices.size();
        model.triangles += mesh.indices.size() / 3;
        model.groups.push_back(std::move(mesh));
        i = j;
    }
}

}  // namespace dsr::obj
