// Analytic reference: double-precision ray tracing of the scene's triangles, Equations 1-6.
#include "analysis/analytic_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "deferred/gpu_scene.h"
#include "dsr_error.h"

namespace dsr {

namespace {

using dvec3 = glm::dvec3;

struct Tri {
    dvec3 p0, e1, e2;  // p1 = p0 + e1, p2 = p0 + e2
    dvec3 n0, n1, n2;  // vertex normals, as the rasteriser interpolates them
};

struct Box {
    dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    void add(const dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Slab test: can the ray hit anything inside before t_max?
    bool hit(const dvec3& o, const dvec3& inv_d, double t_max) const {
        double t0 = 0, t1 = t_max;
        for (int a = 0; a < 3; ++a) {
            double ta = (lo[a] - o[a]) * inv_d[a], tb = (hi[a] - o[a]) * inv_d[a];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
            if (t0 > t1) return false;
        }
        return true;
    }
};

// Triangles in runs of kChunk (index order keeps a run spatially close on the shapes the scene
// format makes), each run with its box: two-level rejection, enough for small analytic scenes.
constexpr size_t kChunk = 32;

struct TracedMesh {
    std::vector<Tri> tris;
    std::vector<Box> chunks;
    Box box;
};

std::vector<TracedMesh> prepare(const Scene& scene) {
    std::vector<TracedMesh> out;
    for (const Mesh& m : scene.meshes) {
        TracedMesh t;
        for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
            const Vertex& a = m.vertices.at(m.indices[i]);
            const Vertex& b = m.vertices.at(m.indices[i + 1]);
            const Vertex& c = m.vertices.at(m.indices[i + 2]);
            Tri tri;
            tri.p0 = dvec3(a.pos);
            tri.e1 = dvec3(b.pos) - tri.p0;
            tri.e2 = dvec3(c.pos) - tri.p0;
            tri.n0 = dvec3(a.normal);
            tri.n1 = dvec3(b.normal);
            tri.n2 = dvec3(c.normal);
            if (t.tris.size() % kChunk == 0) t.chunks.emplace_back();
            for (const Vertex* v : {&a, &b, &c}) {
                t.chunks.back().add(dvec3(v->pos));
                t.box.add(dvec3(v->pos));
            }
            t.tris.push_back(tri);
        }
        out.push_back(std::move(t));
    }
    return out;
}

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    int mesh = -1;
    const Tri* tri = nullptr;
    double u = 0, v = 0;
};

// Möller-Trumbore with back faces culled: det > 0 exactly when the ray meets the triangle's
// counter-clockwise side, the side GL keeps with glCullFace(GL_BACK).
void intersect(const Tri& tr, const dvec3& o, const dvec3& d, double t_min, int mesh, Hit& best) {
    const dvec3 pv = glm::cross(d, tr.e2);
    const double det = glm::dot(tr.e1, pv);
    if (!(det > 0)) return;
    const dvec3 tv = o - tr.p0;
    const double u = glm::dot(tv, pv);
    if (u < 0 || u > det) return;
    const dvec3 qv = glm::cross(tv, tr.e1);
    const double v = glm::dot(d, qv);
    if (v < 0 || u + v > det) return;
    const double t = glm::dot(tr.e2, qv) / det;
    if (t < t_min || t >= best.t) return;
    best.t = t;
    best.mesh = mesh;
    best.tri = &tr;
    best.u = u / det;
    best.v = v / det;
}

double unorm8(double c) { return std::round(std::clamp(c, 0.0, 1.0) * 255.0) / 255.0; }
dvec3 unorm8(const dvec3& c) { return dvec3(unorm8(c.x), unorm8(c.y), unorm8(c.z)); }

}  // namespace

AnalyticTrace analytic_trace(const Scene& scene, int width, int height, const AnalyticOptions& opts) {
    if (width <= 0 || height <= 0) throw Error("analytic reference: bad size");
    for (const Material& m : scene.materials)
        if (m.diffuse_map >= 0 || m.normal_map >= 0 || m.specular_map >= 0)
            throw Error("analytic reference: material '" + m.name +
                        "' has a texture map; only constant materials have an analytic reference");
    for (const Mesh& m : scene.meshes)
        if (m.material < 0 || size_t(m.material) >= scene.materials.size())
            throw Error("analytic reference: a mesh has no material");

    const std::vector<TracedMesh> meshes = prepare(scene);

    // The camera of Camera::view() / projection() in double: glm::lookAt's frame, and
    // glm::perspective's vertical field of view with aspect = width / height.
    const Camera& cam = scene.camera;
    const dvec3 eye(cam.pos);
    const dvec3 f = glm::normalize(dvec3(cam.target) - eye);
    const dvec3 s = glm::normalize(glm::cross(f, dvec3(cam.up)));
    const dvec3 up = glm::cross(s, f);
    const double tan_half = std::tan(double(cam.fov_deg) * 3.14159265358979323846 / 360.0);
    const double aspect = double(width) / double(height);
    const double near_plane = cam.near_plane, far_plane = cam.far_plane;

    AnalyticTrace out;
    out.image.width = width;
    out.image.height = height;
    out.image.rgba.assign(size_t(width) * height * 4, 1.0f);
    out.mesh.assign(size_t(width) * height, -1);
    out.eye_depth.assign(size_t(width) * height, 0.0);

    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            // The ray through the pixel centre, with a forward component of 1 so that t is the
            // eye-space depth -z, the quantity the near and far planes clip.
            const double x = ((i + 0.5) / width * 2 - 1) * tan_half * aspect;
            const double y = ((j + 0.5) / height * 2 - 1) * tan_half;
            const dvec3 d = f + x * s + y * up;
            const dvec3 inv_d = 1.0 / d;
            Hit hit;
            for (size_t m = 0; m < meshes.size(); ++m) {
                const TracedMesh& tm = meshes[m];
                if (!tm.box.hit(eye, inv_d, std::min(hit.t, far_plane))) continue;
                for (size_t c = 0; c < tm.chunks.size(); ++c) {
                    if (!tm.chunks[c].hit(eye, inv_d, std::min(hit.t, far_plane))) continue;
                    const size_t end = std::min(tm.tris.size(), (c + 1) * kChunk);
                    for (size_t k = c * kChunk; k < end; ++k) intersect(tm.tris[k], eye, d, near_plane, int(m), hit);
                }
            }
            float* px = out.image.at(i, j);
            if (hit.mesh < 0 || hit.t > far_plane) {
                px[0] = scene.background.r;
                px[1] = scene.background.g;
                px[2] = scene.background.b;
                continue;
            }
            out.mesh[size_t(j) * width + i] = hit.mesh;
            out.eye_depth[size_t(j) * width + i] = hit.t;  // the ray's forward component is 1

            const Tri& tr = *hit.tri;
            const Material& mat = scene.materials[scene.meshes[hit.mesh].material];
            const dvec3 p = eye + hit.t * d;
            // Phong shading (§2.3): the vertex normals mixed with the hit's barycentric weights,
            // which is what perspective-correct interpolation gives at the pixel centre.
            dvec3 n = glm::normalize((1 - hit.u - hit.v) * tr.n0 + hit.u * tr.n1 + hit.v * tr.n2);
            dvec3 Mdiff(mat.diffuse), Mspec(mat.specular);
            double Mshi = mat.shininess;
            if (opts.gbuffer_normals_8bit) n = glm::normalize(unorm8(n * 0.5 + 0.5) - 0.5);
            if (opts.gbuffer_materials_8bit) {
                Mdiff = unorm8(Mdiff);
                Mspec = unorm8(Mspec);
                Mshi = std::exp2(11.0 * unorm8(double(encode_shininess(mat.shininess))));
            }
            // With passes_8bit every pass's contribution is rounded before the sum (blending
            // into an RGBA8 target); the clamp to [0, 1] comes last either way.
            auto pass = [&](const dvec3& x) { return opts.passes_8bit ? unorm8(x) : x; };
            const dvec3 v = glm::normalize(eye - p);     // Eq. 5: from p to the viewer
            dvec3 c = pass(Mdiff * dvec3(scene.ambient));  // Eq. 6
            for (const Light& light : scene.lights) {
                dvec3 l = dvec3(light.pos) - p;  // towards the light (docs/errata.md #3)
                const double dist = glm::length(l);
                const double att = std::max(0.0, 1.0 - dist / double(light.radius));  // Eq. 2
                if (att <= 0) continue;
                l = dist > 0 ? l / dist : n;
                const dvec3 hv = l + v;
                const double hl = glm::length(hv);
                const dvec3 h = hl > 1e-12 ? hv / hl : n;  // Eq. 5
                const dvec3 S(light.color);
                const dvec3 Idiff = std::max(0.0, glm::dot(l, n)) * Mdiff * S;                   // Eq. 3
                const dvec3 Ispec = std::pow(std::max(0.0, glm::dot(h, n)), Mshi) * Mspec * S;  // Eq. 4
                c += pass(att * (Idiff + Ispec));                                                // Eq. 1
            }
            for (int k = 0; k < 3; ++k) px[k] = float(std::clamp(c[k], 0.0, 1.0));
        }
    }
    return out;
}

Image analytic_reference(const Scene& scene, int width, int height) {
    return analytic_trace(scene, width, height).image;
}

std::vector<uint8_t> interior_mask(const AnalyticTrace& trace, int width, int height) {
    if (trace.mesh.size() != size_t(width) * height) throw Error("interior_mask: size differs from the trace");
    std::vector<uint8_t> mask(trace.mesh.size(), 0);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const int id = trace.mesh[size_t(j) * width + i];
            bool same = true;
            for (int dj = -1; dj <= 1 && same; ++dj)
                for (int di = -1; di <= 1 && same; ++di) {
                    const int x = i + di, y = j + dj;
                    if (x < 0 || y < 0 || x >= width || y >= height) continue;
                    same = trace.mesh[size_t(y) * width + x] == id;
                }
            mask[size_t(j) * width + i] = same;
        }
    return mask;
}

ImageDiff compare_images_masked(const Image& a, const Image& b, const std::vector<uint8_t>& mask,
                                double fail_threshold) {
    if (a.width != b.width || a.height != b.height || mask.size() != size_t(a.width) * a.height)
        throw Error("compare_images_masked: sizes differ");
    ImageDiff d;
    double sum = 0, sum2 = 0;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        ++d.pixels;
        bool fail = false;
        for (int k = 0; k < 3; ++k) {
            const double e = std::fabs(double(a.rgba[p * 4 + k]) - double(b.rgba[p * 4 + k]));
            d.max_abs = std::max(d.max_abs, e);
            sum += e;
            sum2 += e * e;
            fail = fail || e > fail_threshold;
        }
        d.failing += fail;
    }
    const double n = 3.0 * double(std::max<long long>(d.pixels, 1));
    d.mean_abs = sum / n;
    d.psnr_db = sum2 > 0 ? 20.0 * std::log10(1.0 / std::sqrt(sum2 / n)) : std::numeric_limits<double>::infinity();
    return d;
}

}  // namespace dsr
