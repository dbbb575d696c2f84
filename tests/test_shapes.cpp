// Shapes: unit normals, orthonormal right-handed tangent frames whose tangent really follows
// +u and binormal +v (so normal maps read correctly), CCW winding seen from outside
// (back-face culling is on), uvs in [0, 1].
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.h"

namespace {

using glm::vec3;

struct Case {
    std::string name;
    dsr::Mesh mesh;
    vec3 centre;
};

// A shape's object-space mesh moved to `at` (what the object's translate(at) does on the GPU).
dsr::Mesh placed(dsr::Mesh m, vec3 at) {
    for (dsr::Vertex& v : m.vertices) v.pos += at;
    return m;
}

std::vector<Case> cases() {
    return {
        // "centre" is a point inside: below the plane for the plane.
        {"plane", placed(dsr::make_plane(3.0f, 0), vec3(1, -2, 0.5f)), vec3(1, -3, 0.5f)},
        {"box", placed(dsr::make_box(vec3(1, 2, 0.3f), 0), vec3(-1, 0.5f, 2)), vec3(-1, 0.5f, 2)},
        {"sphere", placed(dsr::make_sphere(0.7f, 0), vec3(2, 1, -3)), vec3(2, 1, -3)},
        {"coarse sphere", dsr::make_sphere(2.0f, 0, 5, 3), vec3(0)},
    };
}

TEST(Shapes, FramesAreUnitOrthonormalRightHanded) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        ASSERT_FALSE(c.mesh.vertices.empty());
        for (const dsr::Vertex& v : c.mesh.vertices) {
            EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::length(v.binormal), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(v.binormal, v.normal), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(v.tangent, v.binormal), 0.0f, 1e-5f);
            EXPECT_GT(glm::dot(glm::cross(v.tangent, v.binormal), v.normal), 0.99f);
            EXPECT_GE(v.uv.x, 0.0f);
            EXPECT_LE(v.uv.x, 1.0f);
            EXPECT_GE(v.uv.y, 0.0f);
            EXPECT_LE(v.uv.y, 1.0f);
        }
    }
}

TEST(Shapes, WindingIsCounterClockwiseFromOutside) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const dsr::Mesh& m = c.mesh;
        ASSERT_EQ(m.indices.size() % 3, 0u);
        for (size_t i = 0; i < m.indices.size(); i += 3) {
            const dsr::Vertex &a = m.vertices.at(m.indices[i]), &b = m.vertices.at(m.indices[i + 1]),
                              &d = m.vertices.at(m.indices[i + 2]);
            const vec3 face = glm::cross(b.pos - a.pos, d.pos - a.pos);
            ASSERT_GT(glm::length(face), 1e-7f) << "degenerate triangle " << i / 3;
            const vec3 n = glm::normalize(face);
            // The GL front face (CCW) must face the way the vertex normals and the outside do.
            const vec3 vn = glm::normalize(a.normal + b.normal + d.normal);
            EXPECT_GT(glm::dot(n, vn), 0.9f) << "triangle " << i / 3;
            EXPECT_GT(glm::dot(n, (a.pos + b.pos + d.pos) / 3.0f - c.centre), 0.0f) << "triangle " << i / 3;
        }
    }
}

TEST(Shapes, TangentFollowsUAndBinormalFollowsV) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const dsr::Mesh& m = c.mesh;
        for (size_t i = 0; i < m.indices.size(); i += 3) {
            const dsr::Vertex &a = m.vertices[m.indices[i]], &b = m.vertices[m.indices[i + 1]],
                              &d = m.vertices[m.indices[i + 2]];
            // Solve for dP/du and dP/dv over the triangle.
            const vec3 e1 = b.pos - a.pos, e2 = d.pos - a.pos;
            const glm::vec2 t1 = b.uv - a.uv, t2 = d.uv - a.uv;
            const float det = t1.x * t2.y - t2.x * t1.y;
            ASSERT_GT(std::abs(det), 1e-9f);
            const vec3 dpdu = (e1 * t2.y - e2 * t1.y) / det, dpdv = (e2 * t1.x - e1 * t2.x) / det;
            const vec3 tangent = glm::normalize(a.tangent + b.tangent + d.tangent);
            const vec3 binormal = glm::normalize(a.binormal + b.binormal + d.binormal);
            EXPECT_GT(glm::dot(glm::normalize(dpdu), tangent), 0.9f) << "triangle " << i / 3;
            EXPECT_GT(glm::dot(glm::normalize(dpdv), binormal), 0.9f) << "triangle " << i / 3;
        }
    }
}

TEST(Shapes, PlaneLayout) {
    const dsr::Mesh m = placed(dsr::make_plane(4.0f, 7), vec3(1, 2, 3));
    EXPECT_EQ(m.material, 7);
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.indices.size(), 6u);
    for (const dsr::Vertex& v : m.vertices) {
        EXPECT_EQ(v.normal, vec3(0, 1, 0));
        EXPECT_FLOAT_EQ(v.pos.y, 2);
        EXPECT_FLOAT_EQ(std::abs(v.pos.x - 1), 2);
        EXPECT_FLOAT_EQ(std::abs(v.pos.z - 3), 2);
        // u along +X, v along -Z.
        EXPECT_FLOAT_EQ(v.uv.x, (v.pos.x - 1 + 2) / 4);
        EXPECT_FLOAT_EQ(v.uv.y, (3 + 2 - v.pos.z) / 4);
    }
}

TEST(Shapes, BoxLayout) {
    const vec3 size(2, 4, 6), at(1, 1, 1);
    const dsr::Mesh m = placed(dsr::make_box(size, 3), at);
    EXPECT_EQ(m.material, 3);
    ASSERT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.indices.size(), 36u);
    for (const dsr::Vertex& v : m.vertices) {
        const vec3 d = v.pos - at;
        for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(std::abs(d[k]), size[k] / 2);
        // Every vertex lies on the face its normal names.
        EXPECT_FLOAT_EQ(glm::dot(d, v.normal), glm::dot(size / 2.0f, glm::abs(v.normal)));
        // Side faces: v runs up, so wall textures stand upright.
        if (v.normal.y == 0) {
            EXPECT_EQ(v.binormal, vec3(0, 1, 0));
        }
    }
    // Each face spans the full 0..1 uv square.
    for (int f = 0; f < 6; ++f) {
        glm::vec2 lo(1), hi(0);
        for (int k = 0; k < 4; ++k) {
            lo = glm::min(lo, m.vertices[f * 4 + k].uv);
            hi = glm::max(hi, m.vertices[f * 4 + k].uv);
        }
        EXPECT_EQ(lo, glm::vec2(0));
        EXPECT_EQ(hi, glm::vec2(1));
    }
}

TEST(Shapes, SphereLayout) {
    const float r = 1.5f;
    const vec3 at(0, 1, 0);
    const dsr::Mesh m = placed(dsr::make_sphere(r, 2, 16, 8), at);
    EXPECT_EQ(m.vertices.size(), size_t(17 * 9));
    // Two triangles per quad, less one at each pole per slice.
    EXPECT_EQ(m.indices.size(), size_t(3 * (2 * 16 * 8 - 2 * 16)));
    float vmin = 1, vmax = 0;
    for (const dsr::Vertex& v : m.vertices) {
        EXPECT_NEAR(glm::length(v.pos - at), r, 1e-5f);
        EXPECT_LT(glm::length(v.normal - (v.pos - at) / r), 1e-5f);
        // v runs from the south pole (0) to the north pole (1).
        if (v.uv.y == 0) {
            EXPECT_NEAR(v.pos.y, at.y - r, 1e-6f);
        }
        if (v.uv.y == 1) {
            EXPECT_NEAR(v.pos.y, at.y + r, 1e-6f);
        }
        vmin = std::min(vmin, v.uv.y);
        vmax = std::max(vmax, v.uv.y);
    }
    EXPECT_EQ(vmin, 0.0f);
    EXPECT_EQ(vmax, 1.0f);
}

}  // namespace

// add_* put the object-space mesh in the scene once, at `at` by its model matrix, with the
// exact shape in world space.
TEST(Shapes, AddPlacesAnObjectWithItsShape) {
    dsr::Scene s;
    const size_t o = dsr::add_box(s, vec3(1, 2, 3), vec3(4, 5, 6), 0);
    ASSERT_EQ(o, 0u);
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.objects.size(), 1u);
    const dsr::Object& obj = s.objects[0];
    EXPECT_EQ(obj.mesh, 0u);
    ASSERT_TRUE(obj.shape.has_value());
    EXPECT_EQ(obj.shape->kind, dsr::ShapeDesc::Kind::box);
    EXPECT_EQ(obj.shape->centre, vec3(4, 5, 6));
    EXPECT_EQ(obj.model[3], glm::dvec4(4, 5, 6, 1));
    vec3 lo(1e9f), hi(-1e9f);
    for (const dsr::Vertex& v : s.meshes[0].vertices) lo = glm::min(lo, v.pos), hi = glm::max(hi, v.pos);
    EXPECT_EQ(lo, vec3(-0.5f, -1, -1.5f)) << "object space: centred on the origin";
    EXPECT_EQ(hi, vec3(0.5f, 1, 1.5f));
    EXPECT_EQ(s.triangle_count(), 12u);
}
