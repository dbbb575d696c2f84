// The OBJ loader's geometry (obj_geometry.h): triangles, normals and material groups from what
// tinyobjloader returned, each linear in the corners (but ear clipping, within its budget).
#include "scene/obj_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "dsr_error.h"
#include "scene/obj_triangulate.h"
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

Material default_material(const string& obj_name) {
    Material d;
    d.name = obj_name + ":(default)";
    d.diffuse = glm::vec3(0.8f);
    return d;
}

Triangles collect_triangles(const string& path, const string& obj_name, const tinyobj::attrib_t& attrib,
                            const std::vector<tinyobj::shape_t>& shapes, const ObjCheck& check,
                            const std::vector<int>& slot_material, ObjModel& model, Notes& notes) {
    const size_t nv = attrib.vertices.size() / 3, nvt = attrib.texcoords.size() / 2, nvn = attrib.normals.size() / 3;
    // A face's corners: tinyobjloader's count, which wraps past 255, or the check's for those faces.
    size_t large = 0;
    auto corners_of = [&](size_t face, unsigned char counted) -> size_t {
        while (large < check.large_faces.size() && check.large_faces[large].first < face) ++large;
        if (large < check.large_faces.size() && check.large_faces[large].first == face) {
            if (check.large_faces[large].second % 256 != counted)
                throw Error(path + ": tinyobjloader returned a face whose corners the check counted otherwise");
            return check.large_faces[large].second;
        }
        if (counted < 3) throw Error(path + ": tinyobjloader returned a face of fewer than 3 corners");
        return counted;
    };
    size_t faces = 0, corners_in = 0;
    for (const tinyobj::shape_t& sh : shapes) {
        const auto& mesh = sh.mesh;
        if (mesh.material_ids.size() != mesh.num_face_vertices.size())
            throw Error(path + ": tinyobjloader returned faces without materials");
        size_t k = 0;
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) k += corners_of(faces + f, mesh.num_face_vertices[f]);
        if (k != mesh.indices.size()) throw Error(path + ": tinyobjloader returned faces and corners that disagree");
        faces += mesh.num_face_vertices.size();
        corners_in += k;
    }
    large = 0;
    if (faces != check.faces || corners_in != check.corners || check.face_line.size() != faces)
        throw Error(path + ": tinyobjloader read " + std::to_string(faces) + " faces of " + std::to_string(corners_in) +
                    " corners; expected " + std::to_string(check.faces) + " of " + std::to_string(check.corners));
    Triangles out;
    std::vector<Corner>& corners = out.corners;
    std::vector<int>& tri_material = out.material;
    std::vector<glm::dvec3>& face_n = out.face_n;
    corners.reserve(check.triangles * 3);
    tri_material.reserve(check.triangles);
    face_n.reserve(check.triangles);
    out.face.reserve(check.triangles);
    bool default_used = false;
    size_t face = 0, run = 0, work = 0;
    std::vector<Corner> c;
    std::vector<uint32_t> local;
    std::vector<glm::dvec3> poly;
    for (const tinyobj::shape_t& sh : shapes) {
        const auto& mesh = sh.mesh;
        size_t first = 0;
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++face) {
            const size_t k = corners_of(face, mesh.num_face_vertices[f]);
            c.resize(k);
            for (size_t j = 0; j < k; ++j) {
                const tinyobj::index_t& ix = mesh.indices[first + j];
                if (ix.vertex_index < 0 || size_t(ix.vertex_index) >= nv || ix.texcoord_index >= long(nvt) ||
                    ix.normal_index >= long(nvn) || ix.texcoord_index < -1 || ix.normal_index < -1)
                    throw Error(path + ": tinyobjloader returned a face index out of range");
                c[j] = {ix.vertex_index, ix.texcoord_index, ix.normal_index};
            }
            first += k;
            const int line = int(check.face_line[face]);
            local.clear();
            if (k == 3) {
                local = {0, 1, 2};
            } else if (k == 4) {
                std::array<glm::vec3, 4> q;
                for (size_t j = 0; j < 4; ++j) q[j] = glm::vec3(vec_at(attrib.vertices, size_t(c[j].v)));
                triangulate_quad(q, local);
            } else {
                poly.resize(k);
                for (size_t j = 0; j < k; ++j) poly[j] = vec_at(attrib.vertices, size_t(c[j].v));
                const Polygon how = triangulate_polygon(poly, local, work);
                const string corners_text = "a face of " + std::to_string(k) + " corners";
                if (how == Polygon::fan_no_area)
                    notes.add(path, line, "fan: no area", corners_text + " has no area in any plane: drawn as a fan");
                else if (how == Polygon::fan_not_simple)
                    notes.add(path, line, "fan: not simple",
                              corners_text + " crosses itself (ear clipping found no ear): the rest drawn as a fan");
                else if (how == Polygon::fan_over_budget)
                    notes.add(path, line, "fan: budget",
                              corners_text + " past the ear-clipping budget of " + std::to_string(kMaxEarClipWork) +
                                  " point tests a file: drawn as a fan");
            }
            while (run + 1 < check.material_runs.size() && check.material_runs[run + 1].first <= face) ++run;
            const int slot = check.material_runs.empty() ? -1 : check.material_runs[run].second;
            int mat = slot < 0 ? -1 : slot_material[size_t(slot)];
            if (mat < 0 || size_t(mat) >= model.materials.size()) mat = -1;
            bool dropped = false;
            for (size_t t = 0; t + 2 < local.size(); t += 3) {
                const Corner& c0 = c[local[t]];
                const Corner& c1 = c[local[t + 1]];
                const Corner& c2 = c[local[t + 2]];
                const glm::dvec3 p0 = vec_at(attrib.vertices, size_t(c0.v)), p1 = vec_at(attrib.vertices, size_t(c1.v)),
                                 p2 = vec_at(attrib.vertices, size_t(c2.v));
                const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
                if (!(glm::dot(n, n) > 0)) {
                    dropped = true;
                    continue;
                }
                default_used = default_used || mat < 0;
                corners.push_back(c0);
                corners.push_back(c1);
                corners.push_back(c2);
                tri_material.push_back(mat);
                face_n.push_back(n);
                out.face.push_back(uint32_t(face));
            }
            if (dropped) notes.add(path, line, "zero area", "triangles without area dropped");
        }
    }
    if (tri_material.empty()) throw Error(path + ": expected at least one triangle with area, got none: an empty mesh");
    if (default_used) {
        model.materials.push_back(default_material(obj_name));
        for (int& m : tri_material)
            if (m < 0) m = int(model.materials.size() - 1);
    }
    return out;
}

Normals smooth_normals(const string& path, const tinyobj::attrib_t& attrib, float smooth_angle_deg, Triangles& tris,
                       const ObjCheck& check, Notes& notes) {
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
    uint32_t noted_face = uint32_t(-1);  // one count per face line
    for (size_t i = 0; i < corners.size(); ++i) {
        Corner& c = corners[i];
        if (c.vn >= 0 && !file_normal_ok[size_t(c.vn)]) {
            c.vn = -1;
            if (tris.face[i / 3] != noted_face)
                notes.add(path, int(check.face_line[tris.face[i / 3]]), "zero normal",
                          "a corner's normal is zero: computed from the faces around it");
            noted_face = tris.face[i / 3];
        }
    }
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

void group_by_material(const string& path, const tinyobj::attrib_t& attrib, const Triangles& triangles,
                       const Normals& normals, const ObjCheck& check, ObjModel& model, Notes& notes) {
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
        mesh.two_sided = true;  // OBJ faces are seen from both sides (Blender, MeshLab)
        mesh.indices.reserve((j - i) * 3);
        // Vertex colours where a corner of this group names a coloured vertex.
        bool coloured = false;
        if (!check.coloured.empty())
            for (size_t k = i; k < j && !coloured; ++k)
                for (int q = 0; q < 3; ++q)
                    coloured = coloured || check.coloured[size_t(corners[size_t(order[k]) * 3 + size_t(q)].v)];
        int uncoloured_line = 0;
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
                    if (coloured) {
                        glm::vec4 col(1);
                        if (check.coloured[size_t(c.v)]) {
                            for (int ch = 0; ch < 3; ++ch)
                                col[ch] = std::clamp(attrib.colors[3 * size_t(c.v) + size_t(ch)], 0.0f, 1.0f);
                        } else if (uncoloured_line == 0) {
                            uncoloured_line = int(check.face_line[triangles.face[order[k]]]);
                        }
                        mesh.colors.push_back(col);
                    }
                }
                mesh.indices.push_back(idx);
            }
        if (uncoloured_line)
            notes.add(path, uncoloured_line, "uncoloured",
                      "vertices without a colour in a group with vertex colours: drawn white");
        compute_tangents(mesh);
        model.vertices += mesh.vertices.size();
        model.triangles += mesh.indices.size() / 3;
        model.groups.push_back(std::move(mesh));
        i = j;
    }
}

}  // namespace dsr::obj
