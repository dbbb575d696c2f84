// Analytic reference: double-precision ray tracing of the scene's exact shapes (or its
// triangles, for meshes that have no shape), Equations 1-6, closed-form texture maps.
#include "analysis/analytic_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "deferred/gpu_scene.h"
#include "dsr_error.h"

namespace dsr {

namespace {

using dvec3 = glm::dvec3;
constexpr double kPi = 3.14159265358979323846;

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
    bool exact = false;  // trace `shape`, not the triangles
    ShapeDesc::Kind kind = ShapeDesc::Kind::plane;
    dvec3 centre{0}, half{0};  // plane: half side in x and z; box: half edges
    double radius = 0;
    std::vector<Tri> tris;
    std::vector<Box> chunks;
    Box box;
};

std::vector<TracedMesh> prepare(const Scene& scene, bool triangles) {
    std::vector<TracedMesh> out;
    for (const Object& o : scene.objects) {
        const Mesh& m = scene.meshes.at(o.mesh);
        TracedMesh t;
        if (o.shape) {  // kept with `triangles` too: a textured plane's uv comes from it
            t.kind = o.shape->kind;
            t.centre = dvec3(o.shape->centre);
            t.half = dvec3(o.shape->size) * 0.5;
            t.radius = o.shape->radius;
            if (!triangles) {
                t.exact = true;
                out.push_back(std::move(t));
                continue;
            }
        }
        // The object's triangles in world space, in double (rigid with a uniform scale: normals
        // turn with the rotation alone).
        const double scale = glm::length(dvec3(o.model[0]));
        const glm::dmat3 rot = glm::dmat3(o.model) / (scale > 0 ? scale : 1.0);
        auto world = [&](const Vertex& v) { return dvec3(o.model * glm::dvec4(dvec3(v.pos), 1.0)); };
        for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
            const Vertex& a = m.vertices.at(m.indices[i]);
            const Vertex& b = m.vertices.at(m.indices[i + 1]);
            const Vertex& c = m.vertices.at(m.indices[i + 2]);
            const dvec3 pa = world(a), pb = world(b), pc = world(c);
            Tri tri;
            tri.p0 = pa;
            tri.e1 = pb - tri.p0;
            tri.e2 = pc - tri.p0;
            tri.n0 = rot * dvec3(a.normal);
            tri.n1 = rot * dvec3(b.normal);
            tri.n2 = rot * dvec3(c.normal);
            if (t.tris.size() % kChunk == 0) t.chunks.emplace_back();
            for (const dvec3& p : {pa, pb, pc}) {
                t.chunks.back().add(p);
                t.box.add(p);
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
    const Tri* tri = nullptr;  // triangle hits: the triangle and barycentrics
    double u = 0, v = 0;
    dvec3 normal{0};           // exact-shape hits: the shape's unit normal
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

void take(Hit& best, double t, int mesh, const dvec3& n) {
    best.t = t;
    best.mesh = mesh;
    best.tri = nullptr;
    best.normal = n;
}

// The exact shapes. Each is convex and outward-facing, so the only front-facing hit is where the
// ray enters it; if that is nearer than the near plane it is clipped and the exit (a back face)
// is culled, as GL draws it: nothing. An eye inside sees nothing of the shape either.
void intersect_exact(const TracedMesh& s, const dvec3& o, const dvec3& d, double t_min, int mesh, Hit& best) {
    switch (s.kind) {
    case ShapeDesc::Kind::plane: {
        // y = centre.y, |x - cx| <= half.x, |z - cz| <= half.z; the front side is +Y.
        if (!(d.y < 0) || !(o.y > s.centre.y)) return;
        const double t = (s.centre.y - o.y) / d.y;
        if (t < t_min || t >= best.t) return;
        const dvec3 p = o + t * d;
        if (std::fabs(p.x - s.centre.x) > s.half.x || std::fabs(p.z - s.centre.z) > s.half.z) return;
        take(best, t, mesh, dvec3(0, 1, 0));
        return;
    }
    case ShapeDesc::Kind::box: {
        double t_in = -std::numeric_limits<double>::infinity(), t_out = std::numeric_limits<double>::infinity();
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            const double lo = s.centre[a] - s.half[a], hi = s.centre[a] + s.half[a];
            if (d[a] == 0) {
                if (o[a] < lo || o[a] > hi) return;
                continue;
            }
            double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
            if (ta > tb) std::swap(ta, tb);
            if (ta > t_in) t_in = ta, axis = a;
            t_out = std::min(t_out, tb);
        }
        if (axis < 0 || t_in > t_out || t_in <= 0 || t_in < t_min || t_in >= best.t) return;
        dvec3 n(0);
        n[axis] = d[axis] > 0 ? -1 : 1;
        take(best, t_in, mesh, n);
        return;
    }
    case ShapeDesc::Kind::sphere: {
        const dvec3 oc = o - s.centre;
        const double a = glm::dot(d, d), b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.radius * s.radius;
        if (!(c > 0)) return;  // the eye is inside (or on) the sphere
        const double disc = b * b - a * c;
        if (disc < 0 || b >= 0) return;  // missed, or the sphere is behind the eye
        // The nearer root without cancellation: t0 = c / (-b + sqrt(disc)).
        const double t = c / (-b + std::sqrt(disc));
        if (t < t_min || t >= best.t) return;
        take(best, t, mesh, glm::normalize(o + t * d - s.centre));
        return;
    }
    }
}

// ---- Shadow rays ----
// A light with shadow.on reaches p only if nothing lies on the segment from p to it (point and
// spot: to its position; directional: along -dir, unbounded). Unlike the camera rays these see
// both faces: a plane shades what is under it as well as what is over it, and the far side of a
// closed shape stops the ray as its near side does (a point on a face turned from the light
// sends its ray into its own shape: the exit hides the light, as the shadow map's nearer front
// face does). Each test asks whether any part of the open interval (t_min, t_max) of the ray
// o + t d (d unit) lies on or in the shape.

bool blocks_exact(const TracedMesh& s, const dvec3& o, const dvec3& d, double t_min, double t_max) {
    switch (s.kind) {
    case ShapeDesc::Kind::plane: {
        if (d.y == 0) return false;  // parallel: a point on the plane's own level is that plane
        const double t = (s.centre.y - o.y) / d.y;
        if (!(t > t_min && t < t_max)) return false;
        const dvec3 p = o + t * d;
        return std::fabs(p.x - s.centre.x) <= s.half.x && std::fabs(p.z - s.centre.z) <= s.half.z;
    }
    case ShapeDesc::Kind::box: {
        // The solid box: the ray's interval inside every slab, met with (t_min, t_max).
        double t0 = t_min, t1 = t_max;
        for (int a = 0; a < 3; ++a) {
            const double lo = s.centre[a] - s.half[a], hi = s.centre[a] + s.half[a];
            if (d[a] == 0) {
                if (o[a] < lo || o[a] > hi) return false;
                continue;
            }
            double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
            if (!(t0 < t1)) return false;
        }
        return true;
    }
    case ShapeDesc::Kind::sphere: {
        // The solid ball: roots of |o + t d - c|^2 = r^2 (|d| = 1), met with (t_min, t_max).
        const dvec3 oc = o - s.centre;
        const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.radius * s.radius;
        const double disc = b * b - c;
        if (!(disc > 0)) return false;
        const double q = -b + (b <= 0 ? std::sqrt(disc) : -std::sqrt(disc));  // no cancellation
        double r0 = q != 0 ? c / q : 0, r1 = q;                                    // the two roots
        if (r0 > r1) std::swap(r0, r1);
        return std::max(r0, t_min) < std::min(r1, t_max);
    }
    }
    return false;
}

// Möller-Trumbore with both faces: det of either sign, t in (t_min, t_max).
bool blocks_tri(const Tri& tr, const dvec3& o, const dvec3& d, double t_min, double t_max) {
    const dvec3 pv = glm::cross(d, tr.e2);
    const double det = glm::dot(tr.e1, pv);
    if (det == 0) return false;
    const double inv = 1 / det;
    const dvec3 tv = o - tr.p0;
    const double u = glm::dot(tv, pv) * inv;
    if (u < 0 || u > 1) return false;
    const dvec3 qv = glm::cross(tv, tr.e1);
    const double v = glm::dot(d, qv) * inv;
    if (v < 0 || u + v > 1) return false;
    const double t = glm::dot(tr.e2, qv) * inv;
    return t > t_min && t < t_max;
}

// Is anything between p and the light (unit direction l, distance t_max, infinite for a
// directional light)? `scale` bounds the magnitudes p was computed from (see t_min).
bool shadow_ray_blocked(const std::vector<TracedMesh>& meshes, const dvec3& p, const dvec3& l, double t_max,
                        double scale) {
    // t_min, the epsilon that keeps p's own surface from hiding it. p = eye + t d is rounded: its
    // distance from the true surface is a few ulps of the magnitudes that made it, below
    // 1e-15 * scale (scale = |eye| + t |d| + 1, the 1 for scenes around the origin). A ray leaving
    // the surface at an angle a to it meets that surface again at t <= 1e-15 scale / sin(a), so
    // t_min = 1e-9 scale misses the self-hit whenever sin(a) > 1e-6; below that n.l < 1e-6 and the
    // light's diffuse term is under 3e-4 LSB, so a wrongly blocked grazing light changes nothing
    // visible (the specular term at such a point is gated the same way by the renderer's shadow).
    // What t_min can hide: an occluder closer than 1e-9 scale to p (1e-9 units in a unit scene,
    // 1e-3 at 1e6 from the origin, still far below a pixel there), and what it may wrongly keep:
    // nothing, since a hit at t <= t_min is the surface p lies on or one touching it.
    const double t_min = 1e-9 * scale;
    const dvec3 inv_d = 1.0 / l;
    for (const TracedMesh& tm : meshes) {
        if (tm.exact) {
            if (blocks_exact(tm, p, l, t_min, t_max)) return true;
            continue;
        }
        if (!tm.box.hit(p, inv_d, t_max)) continue;
        for (size_t c = 0; c < tm.chunks.size(); ++c) {
            if (!tm.chunks[c].hit(p, inv_d, t_max)) continue;
            const size_t end = std::min(tm.tris.size(), (c + 1) * kChunk);
            for (size_t k = c * kChunk; k < end; ++k)
                if (blocks_tri(tm.tris[k], p, l, t_min, t_max)) return true;
        }
    }
    return false;
}

double unorm8(double c) { return std::round(std::clamp(c, 0.0, 1.0) * 255.0) / 255.0; }
dvec3 unorm8(const dvec3& c) { return dvec3(unorm8(c.x), unorm8(c.y), unorm8(c.z)); }

// GL_LINEAR at level 0 with GL_REPEAT on an RGBA8 texture (GL 2.1 §3.8.8): the texel grid is
// offset by half a texel, the four texels around (u W - 1/2, v H - 1/2) mixed by their
// fractions; texels are the image rounded to 8 bits, as glTexImage2D into GL_RGBA8 stores them.
dvec3 bilinear(const Image& img, double u, double v) {
    const double x = u * img.width - 0.5, y = v * img.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double a = x - fx, b = y - fy;
    auto wrap = [](long long i, int n) { return int(((i % n) + n) % n); };
    const int i0 = wrap((long long)fx, img.width), i1 = wrap((long long)fx + 1, img.width);
    const int j0 = wrap((long long)fy, img.height), j1 = wrap((long long)fy + 1, img.height);
    auto texel = [&](int i, int j) {
        const float* p = img.at(i, j);
        return unorm8(dvec3(p[0], p[1], p[2]));
    };
    return (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i1, j0) + (1 - a) * b * texel(i0, j1) +
           a * b * texel(i1, j1);
}

// uv of a point on a make_plane square (u along +X, v along -Z, 0..1 over the square).
glm::dvec2 plane_uv(const TracedMesh& s, const dvec3& p) {
    return {(p.x - (s.centre.x - s.half.x)) / (2 * s.half.x), ((s.centre.z + s.half.z) - p.z) / (2 * s.half.z)};
}

// Closest point of triangle abc to the origin (Ericson, Real-Time Collision Detection §5.1.5).
dvec3 closest_to_origin(const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 p(0), ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denom = 1 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

glm::dvec3 metal_rough_brdf(const dvec3& n, const dvec3& l, const dvec3& v, const dvec3& base, double metallic,
                            double roughness, BrdfTerm perturb, double perturb_by) {
    // Written from the glTF 2.0 specification's Appendix B and the Khronos sample viewer's
    // brdf.glsl (docs/metal_rough.md), not from lighting.glsl.
    auto scale = [&](BrdfTerm t) { return perturb == t ? 1.0 + perturb_by : 1.0; };
    if (perturb == BrdfTerm::metallic_mix) metallic = std::clamp(metallic + perturb_by, 0.0, 1.0);
    const dvec3 hv = l + v;
    const double hl = glm::length(hv);
    const dvec3 h = hl > 1e-12 ? hv / hl : n;
    const double NdotL = std::clamp(glm::dot(n, l), 0.0, 1.0), NdotV = std::clamp(glm::dot(n, v), 0.0, 1.0);
    const double NdotH = std::clamp(glm::dot(n, h), 0.0, 1.0), VdotH = std::clamp(glm::dot(v, h), 0.0, 1.0);
    const double r = std::max(roughness, kMinRoughness);
    const double alpha = r * r;
    // D and V enter as a product, so scaling either would be the same change: each is put off
    // through its own alpha instead.
    const double aD = alpha * scale(BrdfTerm::D), a2D = aD * aD;
    const double dd = NdotH * NdotH * (a2D - 1) + 1;
    const double D = a2D / (kPi * dd * dd);
    const double aV = alpha * scale(BrdfTerm::V), a2 = aV * aV;
    const double ggx = NdotL * std::sqrt(NdotV * NdotV * (1 - a2) + a2) + NdotV * std::sqrt(NdotL * NdotL * (1 - a2) + a2);
    const double V = ggx > 0 ? 0.5 / ggx : 0.0;
    const dvec3 F0 = glm::mix(dvec3(0.04), base, metallic);
    const dvec3 F = (F0 + (1.0 - F0) * std::pow(1 - VdotH, 5.0)) * scale(BrdfTerm::F);
    const dvec3 c_diff = glm::mix(base, dvec3(0.0), metallic);
    const dvec3 f = (1.0 - F) * c_diff / kPi * scale(BrdfTerm::diffuse) + F * D * V;
    return f * NdotL;
}

glm::dvec3 bump_normal(const BumpMap& b, double u, double v) {
    const double w = 2 * kPi * b.periods;
    const double dhdu = b.amplitude * w * std::cos(w * u) * std::sin(w * v);
    const double dhdv = b.amplitude * w * std::sin(w * u) * std::cos(w * v);
    return glm::normalize(dvec3(-dhdu, -dhdv, 1));
}

Image make_bump_normal_map(const BumpMap& b, int w, int h) {
    if (w <= 0 || h <= 0) throw Error("make_bump_normal_map: bad size");
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 1.0f);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const dvec3 c = unorm8(bump_normal(b, (i + 0.5) / w, (j + 0.5) / h) * 0.5 + 0.5);
            float* p = img.at(i, j);
            for (int k = 0; k < 3; ++k) p[k] = float(c[k]);
        }
    return img;
}

double sphere_tessellation_gap(int slices, int stacks) {
    const Mesh m = make_sphere(1.0f, 0, slices, stacks);
    double least = 1;
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const dvec3 p = closest_to_origin(dvec3(m.vertices[m.indices[i]].pos), dvec3(m.vertices[m.indices[i + 1]].pos),
                                          dvec3(m.vertices[m.indices[i + 2]].pos));
        least = std::min(least, glm::length(p));
    }
    return 1 - least;
}

namespace {

// What the trace can follow, or an error naming what it cannot: every object with a material,
// opaque materials only, and texture maps only with a closed form here, only on planes.
void check_traceable(const Scene& scene, const AnalyticOptions& opts) {
    for (const Object& o : scene.objects)
        if (o.material < 0 || size_t(o.material) >= scene.materials.size())
            throw Error("analytic reference: an object has no material");
    for (size_t mi = 0; mi < scene.materials.size(); ++mi) {
        const Material& m = scene.materials[mi];
        const std::string what = "analytic reference: material '" + m.name + "' ";
        if (m.transparent())  // the trace finds the nearest surface only: nothing is blended
            throw Error(what + "is transparent (opacity " + std::to_string(m.opacity) + "); the reference is opaque only");
        if (m.specular_map >= 0) throw Error(what + "has a specular map; the reference has none");
        if (m.metallic_roughness_map >= 0 || m.occlusion_map >= 0 || m.emissive_map >= 0)
            throw Error(what + "has a metallic-roughness, occlusion or emissive map; the reference has none");
        if (m.diffuse_map >= 0 && !opts.bilinear_diffuse_maps)
            throw Error(what + "has a diffuse map; only constant materials have an analytic reference "
                               "(AnalyticOptions::bilinear_diffuse_maps allows a magnified map on a plane)");
        if (m.normal_map >= 0 && !opts.bump_maps.count(m.normal_map))
            throw Error(what + "has a normal map with no closed form (AnalyticOptions::bump_maps)");
        for (int map : {m.diffuse_map, m.normal_map})
            if (map >= 0 && size_t(map) >= scene.textures.size()) throw Error(what + "names a missing texture");
        if (m.diffuse_map < 0 && m.normal_map < 0) continue;
        for (const Object& o : scene.objects)
            if (o.material == int(mi) && !(o.shape && o.shape->kind == ShapeDesc::Kind::plane))
                throw Error(what + "has a texture map on a mesh that is not a plane; the reference maps uv on planes only");
    }
}

// The camera of Camera::view() / projection() in double: glm::lookAt's frame, and
// glm::perspective's vertical field of view with aspect = width / height.
struct TraceCamera {
    dvec3 eye, f, s, up;
    double tan_half = 0, aspect = 0, near_plane = 0, far_plane = 0;
    int width = 0, height = 0;
    // The ray through pixel (x, y) in pixel units (centre of pixel i at x = i + 0.5), with a
    // forward component of 1 so that t is the eye-space depth -z, the quantity the near and far
    // planes clip.
    dvec3 ray(double x, double y) const {
        return f + ((x / width * 2 - 1) * tan_half * aspect) * s + ((y / height * 2 - 1) * tan_half) * up;
    }
};

TraceCamera trace_camera(const Camera& cam, int width, int height) {
    TraceCamera c;
    c.eye = dvec3(cam.pos);
    c.f = glm::normalize(dvec3(cam.target) - c.eye);
    c.s = glm::normalize(glm::cross(c.f, dvec3(cam.up)));
    c.up = glm::cross(c.s, c.f);
    c.tan_half = std::tan(double(cam.fov_deg) * kPi / 360.0);
    c.aspect = double(width) / double(height);
    c.near_plane = cam.near_plane, c.far_plane = cam.far_plane;
    c.width = width, c.height = height;
    return c;
}

// The nearest surface along the ray eye + t d at or past the near plane: exact shapes directly,
// triangle meshes through their bounding boxes and chunks.
Hit nearest_hit(const std::vector<TracedMesh>& meshes, const TraceCamera& cam, const dvec3& d) {
    const dvec3 inv_d = 1.0 / d;
    Hit hit;
    for (size_t m = 0; m < meshes.size(); ++m) {
        const TracedMesh& tm = meshes[m];
        if (tm.exact) {
            intersect_exact(tm, cam.eye, d, cam.near_plane, int(m), hit);
            continue;
        }
        if (!tm.box.hit(cam.eye, inv_d, std::min(hit.t, cam.far_plane))) continue;
        for (size_t c = 0; c < tm.chunks.size(); ++c) {
            if (!tm.chunks[c].hit(cam.eye, inv_d, std::min(hit.t, cam.far_plane))) continue;
            const size_t end = std::min(tm.tris.size(), (c + 1) * kChunk);
            for (size_t k = c * kChunk; k < end; ++k) intersect(tm.tris[k], cam.eye, d, cam.near_plane, int(m), hit);
        }
    }
    return hit;
}

// What the light pass reads at a surface point: its normal and material, as the G-buffer holds
// them (rounded to 8 bits where the options say the targets are RGBA8).
struct Surface {
    dvec3 n, diffuse, specular;
    double shininess = 0, metallic = 0, roughness = 0;
    bool metal_rough = false;
};

// The surface at hit point p of pixel (i, j): the interpolated or exact normal, the closed-form
// maps on a plane (their texel footprint raised into `max_texel_footprint`), the 8-bit rounding.
Surface surface_at(const Scene& scene, const TracedMesh& tm, const Material& mat, const Hit& hit, const dvec3& p,
                   const TraceCamera& cam, int i, int j, const AnalyticOptions& opts, double& max_texel_footprint) {
    Surface s;
    if (hit.tri) {
        // Phong shading (§2.3): the vertex normals mixed with the hit's barycentric
        // weights, which is what perspective-correct interpolation gives at the pixel centre.
        const Tri& tr = *hit.tri;
        s.n = glm::normalize((1 - hit.u - hit.v) * tr.n0 + hit.u * tr.n1 + hit.v * tr.n2);
    } else {
        s.n = hit.normal;
    }
    s.diffuse = dvec3(mat.diffuse), s.specular = dvec3(mat.specular);
    if (mat.diffuse_map >= 0 || mat.normal_map >= 0) {
        // A plane (check_traceable): uv from the hit, scaled by the material's tile.
        const glm::dvec2 uv = plane_uv(tm, p) * double(mat.tile);
        // The pixel's footprint in texels of each map (GL's rho): uv at the next pixel
        // centres, on the same plane.
        for (int map_index : {mat.diffuse_map, mat.normal_map}) {
            if (map_index < 0) continue;
            const Image& map = scene.textures[size_t(map_index)];
            double rho = 0;
            for (const dvec3& dn : {cam.ray(i + 1.5, j + 0.5), cam.ray(i + 0.5, j + 1.5)}) {
                if (!(dn.y < 0)) {
                    rho = std::numeric_limits<double>::infinity();
                    break;
                }
                const glm::dvec2 un = plane_uv(tm, cam.eye + ((tm.centre.y - cam.eye.y) / dn.y) * dn) * double(mat.tile);
                rho = std::max(rho, glm::length((un - uv) * glm::dvec2(map.width, map.height)));
            }
            max_texel_footprint = std::max(max_texel_footprint, rho);
        }
        if (mat.diffuse_map >= 0) s.diffuse *= bilinear(scene.textures[size_t(mat.diffuse_map)], uv.x, uv.y);
        if (mat.normal_map >= 0) {
            // The formula's normal in the plane's tangent frame (make_plane: tangent +X,
            // binormal -Z, normal +Y), as the material pass mixes it (Listing 13).
            const dvec3 nt = bump_normal(opts.bump_maps.at(mat.normal_map), uv.x, uv.y);
            s.n = glm::normalize(nt.x * dvec3(1, 0, 0) + nt.y * dvec3(0, 0, -1) + nt.z * dvec3(0, 1, 0));
        }
    }
    s.shininess = mat.shininess;
    if (opts.gbuffer_normals_8bit) s.n = glm::normalize(unorm8(s.n * 0.5 + 0.5) - 0.5);
    s.metal_rough = mat.metal_rough();
    s.metallic = mat.metallic, s.roughness = mat.roughness;
    if (opts.gbuffer_materials_8bit) {
        s.diffuse = unorm8(s.diffuse);
        s.specular = unorm8(s.specular);
        s.shininess = std::exp2(11.0 * unorm8(double(encode_shininess(mat.shininess))));
        s.metallic = unorm8(s.metallic);
        s.roughness = unorm8(s.roughness);
    }
    return s;
}

// A light at surface point p (normal n): the unit direction towards it and its attenuation,
// spot cone included; null where its law gives nothing there.
struct Incident {
    dvec3 l;
    double att = 1.0;
};
std::optional<Incident> incident_light(const Light& light, const dvec3& p, const dvec3& n, const AnalyticOptions& opts) {
    // The laws of docs/scene-format.md, written again here from their
    // definitions rather than taken from scene/light_law.h.
    Incident in;  // directional: no attenuation
    if (light.type == Light::Type::directional) {
        in.l = -glm::normalize(dvec3(light.dir));
        return in;
    }
    dvec3 l = dvec3(light.pos) - p;  // towards the light (docs/errata.md #3)
    double att = 1.0;
    const double dist = glm::length(l);
    const double R = light.radius;
    if (light.physical) {
        // KHR_lights_punctual's README, "Range Property": max(min(1 - (d/range)^4,
        // 1), 0) / d^2, or 1 / d^2 without a range; nothing beyond the light's bound.
        double range = light.range;
        if (opts.perturb_light == LightTerm::range_window) range *= 1.0 + opts.perturb_light_by;
        const double window = range > 0 ? std::max(std::min(1.0 - std::pow(dist / range, 4.0), 1.0), 0.0) : 1.0;
        att = dist < R && dist > 0 ? window / (dist * dist) : 0.0;
    } else if (!light.attenuation) {
        att = std::max(0.0, 1.0 - dist / R);  // Eq. 2
    } else {
        att = dist < R ? 1.0 / (light.kc + dist * (light.kl + dist * double(light.kq))) : 0.0;
    }
    if (att <= 0) return std::nullopt;
    l = dist > 0 ? l / dist : n;
    if (light.type == Light::Type::spot && light.physical) {
        // The README's "Inner and Outer Cone Angles": lightAngleScale =
        // 1 / max(0.001, cos inner - cos outer), lightAngleOffset = -cos outer *
        // scale, saturate(cd * scale + offset) squared, cd the cosine from the axis.
        const double ci = std::cos(glm::radians(double(light.inner_deg)));
        const double co = std::cos(glm::radians(double(light.angle_deg)));
        const double scale = 1.0 / std::max(0.001, ci - co), offset = -co * scale;
        const double cd = glm::dot(-l, glm::normalize(dvec3(light.dir)));
        const double a = std::clamp(cd * scale + offset, 0.0, 1.0);
        const double power = opts.perturb_light == LightTerm::spot_falloff ? 2.0 * (1.0 + opts.perturb_light_by) : 2.0;
        att *= std::pow(a, power);
        if (att <= 0) return std::nullopt;
    } else if (light.type == Light::Type::spot) {
        // GL_SPOT_CUTOFF: nothing at or beyond the half-angle; inside, the
        // exponent's cos^E times a smoothstep over the outer fifth of the angle.
        const double theta = std::acos(std::clamp(glm::dot(-l, glm::normalize(dvec3(light.dir))), -1.0, 1.0));
        const double a = glm::radians(double(light.angle_deg));
        if (!(theta < a)) return std::nullopt;
        const double co = std::cos(a), ci = std::cos(0.8 * a), ct = std::cos(theta);
        const double t = std::clamp((ct - co) / (ci - co), 0.0, 1.0);
        att *= t * t * (3 - 2 * t) * (light.exponent > 0 ? std::pow(ct, double(light.exponent)) : 1.0);
    }
    in.l = l;
    in.att = att;
    return in;
}

// Where the trace shades one pixel: the point, the direction to the viewer, the pixel's index
// and the scale its shadow rays' epsilon follows (shadow_ray_blocked).
struct ShadePoint {
    dvec3 p, v;
    size_t pixel = 0;
    double shadow_scale = 0;
};

// The pixel's colour before analytic_output: Equation 6's ambient (metallic-roughness: and the
// emissive colour), then each light's term (Equations 1-5, or glTF's BRDF); a light whose shadow
// ray is blocked adds nothing and is marked in `occluded`.
dvec3 shade(const Scene& scene, const std::vector<TracedMesh>& meshes, const Material& mat, const Surface& s,
            const ShadePoint& at, const std::vector<bool>& shadow_rays, const AnalyticOptions& opts,
            std::vector<std::vector<uint8_t>>& occluded) {
    // With passes_8bit every pass's contribution is rounded before the sum (blending
    // into an RGBA8 target); the clamp to [0, 1] comes last either way.
    auto pass = [&](const dvec3& x) { return opts.passes_8bit ? unorm8(x) : x; };
    const dvec3& n = s.n;
    // Eq. 6; metallic-roughness: occlusion (1 without a map) and the emissive colour.
    dvec3 c = pass(s.metal_rough ? s.diffuse * dvec3(scene.ambient) + dvec3(mat.emissive) : s.diffuse * dvec3(scene.ambient));
    for (size_t li = 0; li < scene.lights.size(); ++li) {
        const Light& light = scene.lights[li];
        const std::optional<Incident> in = incident_light(light, at.p, n, opts);
        if (!in) continue;
        const dvec3& l = in->l;
        if (shadow_rays[li]) {
            const double t_max = light.type == Light::Type::directional ? std::numeric_limits<double>::infinity()
                                                                        : glm::length(dvec3(light.pos) - at.p);
            if (shadow_ray_blocked(meshes, at.p, l, t_max, at.shadow_scale)) {
                occluded[li][at.pixel] = 1;
                continue;  // an occluded light adds nothing, its specular term included
            }
        }
        if (s.metal_rough) {  // glTF's BRDF in place of Equations 3-4 (Equation 1's attenuation kept)
            c += pass(in->att * dvec3(light.color) *
                      metal_rough_brdf(n, l, at.v, s.diffuse, s.metallic, s.roughness, opts.perturb, opts.perturb_by));
            continue;
        }
        const dvec3 hv = l + at.v;
        const double hl = glm::length(hv);
        const dvec3 h = hl > 1e-12 ? hv / hl : n;  // Eq. 5
        const dvec3 S(light.color);
        const dvec3 Idiff = std::max(0.0, glm::dot(l, n)) * s.diffuse * S;                         // Eq. 3
        const dvec3 Ispec = std::pow(std::max(0.0, glm::dot(h, n)), s.shininess) * s.specular * S;  // Eq. 4
        c += pass(in->att * (Idiff + Ispec));                                                      // Eq. 1
    }
    return c;
}

}  // namespace

AnalyticTrace analytic_trace(const Scene& scene, int width, int height, const AnalyticOptions& opts) {
    if (width <= 0 || height <= 0) throw Error("analytic reference: bad size");
    check_traceable(scene, opts);
    const std::vector<TracedMesh> meshes = prepare(scene, opts.triangles);
    const TraceCamera cam = trace_camera(scene.camera, width, height);

    AnalyticTrace out;
    out.image.width = width;
    out.image.height = height;
    out.image.rgba.assign(size_t(width) * height * 4, 1.0f);
    out.mesh.assign(size_t(width) * height, -1);
    out.eye_depth.assign(size_t(width) * height, 0.0);

    // Which lights cast shadows here: those the scene marks, unless the options turn them off.
    std::vector<bool> shadow_rays(scene.lights.size());
    out.occluded.resize(scene.lights.size());
    for (size_t li = 0; li < scene.lights.size(); ++li) {
        shadow_rays[li] = opts.shadows && scene.lights[li].shadow.on;
        if (shadow_rays[li]) out.occluded[li].assign(size_t(width) * height, 0);
    }

    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const dvec3 d = cam.ray(i + 0.5, j + 0.5);
            const Hit hit = nearest_hit(meshes, cam, d);
            float* px = out.image.at(i, j);
            if (hit.mesh < 0 || hit.t > cam.far_plane) {
                const dvec3 bg = analytic_output(dvec3(scene.background), opts);
                for (int k = 0; k < 3; ++k) px[k] = float(bg[k]);
                continue;
            }
            const size_t pixel = size_t(j) * width + i;
            out.mesh[pixel] = hit.mesh;
            out.eye_depth[pixel] = hit.t;  // the ray's forward component is 1

            const Material& mat = scene.materials[scene.objects[hit.mesh].material];
            ShadePoint at;
            at.p = cam.eye + hit.t * d;
            at.v = glm::normalize(cam.eye - at.p);  // Eq. 5: from p to the viewer
            at.pixel = pixel;
            at.shadow_scale = glm::length(cam.eye) + hit.t * glm::length(d) + 1;
            const Surface s = surface_at(scene, meshes[hit.mesh], mat, hit, at.p, cam, i, j, opts, out.max_texel_footprint);
            const dvec3 c = analytic_output(shade(scene, meshes, mat, s, at, shadow_rays, opts, out.occluded), opts);
            for (int k = 0; k < 3; ++k) px[k] = float(c[k]);
        }
    }
    return out;
}

glm::dvec3 analytic_output(glm::dvec3 c, const AnalyticOptions& opts) {
    using glm::dvec3;
    c = glm::max(c, dvec3(0.0)) * std::exp2(opts.exposure);
    if (opts.tonemap == ToneMap::reinhard) {  // Reinhard et al. 2002, Eq. 3, on Rec. 709 luminance
        const double L = glm::dot(c, dvec3(0.2126, 0.7152, 0.0722));
        c = L > 0 ? c / (1.0 + L) : dvec3(0.0);
    } else if (opts.tonemap == ToneMap::aces) {  // Narkowicz 2016's fit, per channel
        c = (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
    }
    c = glm::clamp(c, 0.0, 1.0);
    if (opts.srgb_output)  // IEC 61966-2-1
        for (int k = 0; k < 3; ++k) c[k] = c[k] <= 0.0031308 ? 12.92 * c[k] : 1.055 * std::pow(c[k], 1.0 / 2.4) - 0.055;
    return c;
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
