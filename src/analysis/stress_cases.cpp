// The stress sweep's scenes (stress_cases.h). Every scene is built in code with constant
// materials, so the analytic reference (analytic_reference.h) can shade and trace it.
#include "analysis/stress_cases.h"

#include <cmath>
#include <cstdio>

#include "dsr_error.h"

namespace dsr {

namespace {

std::string sci(double v) {  // 1e-4, 1e6, 3e2: the names' number format
    char buf[32];
    const int e = int(std::floor(std::log10(v) + 1e-9));
    const double m = v / std::pow(10.0, e);
    if (std::fabs(m - 1) < 1e-9) std::snprintf(buf, sizeof buf, "1e%d", e);
    else std::snprintf(buf, sizeof buf, "%ge%d", m, e);
    return buf;
}

Material material(const std::string& name, glm::vec3 diffuse, glm::vec3 specular, float shininess) {
    Material m;
    m.name = name;
    m.diffuse = diffuse;
    m.specular = specular;
    m.shininess = shininess;
    return m;
}

// The unit room, scaled by s about the origin and then moved by `offset`: a floor, a glossy
// sphere, a box, two lights (radii 5 and 3). Camera 6.5 units from the scene, near 0.1, far 100.
Scene room(float s, glm::vec3 offset) {
    auto at = [&](glm::vec3 p) { return p * s + offset; };
    Scene sc;
    sc.camera.pos = at({0, 2.5f, 6});
    sc.camera.target = at({0, 0.7f, 0});
    sc.camera.up = {0, 1, 0};
    sc.camera.fov_deg = 50;
    sc.camera.near_plane = 0.1f * s;
    sc.camera.far_plane = 100.0f * s;
    sc.ambient = glm::vec3(0.1f);
    sc.background = {0.05f, 0.05f, 0.1f};
    sc.materials = {material("matte", glm::vec3(0.6f), glm::vec3(0), 1),
                    material("gloss", glm::vec3(0.8f), glm::vec3(0.5f), 32),
                    material("green", {0.1f, 0.7f, 0.2f}, glm::vec3(0.2f), 8)};
    add_plane(sc, 20 * s, at({0, 0, 0}), 0);
    add_sphere(sc, 1 * s, at({-1.2f, 1, 0}), 1);
    add_box(sc, glm::vec3(1.2f * s), at({1.5f, 0.6f, 0.5f}), 2);
    sc.lights.push_back({at({-2, 2.5f, 2}), {1, 0.9f, 0.8f}, 5 * s});
    sc.lights.push_back({at({2.5f, 1.5f, 1.5f}), {0.3f, 0.5f, 1}, 3 * s});
    return sc;
}

// The room seen from (0, 1.5, 4) straight down -Z with a 120-degree field of view: the view
// matrix is axis-aligned, so a point with world z = 4 has eye z exactly 0 in float as well, and
// the wide frustum (|x|, |y| < 1.73 (-z)) lets spheres near the eye plane reach visible surfaces.
// Eye space = world - (0, 1.5, 4).
Scene level_room() {
    Scene sc = room(1, glm::vec3(0));
    sc.camera.pos = {0, 1.5f, 4};
    sc.camera.target = {0, 1.5f, 0};
    sc.camera.fov_deg = 120;
    sc.lights.clear();
    return sc;
}

// Lights centred exactly on the eye plane (Listing 16 divides by l.z), the eye just outside each
// (distance 1.03 r or so), each reaching the floor or the room's objects in view.
Scene eye_plane_scene() {
    Scene sc = level_room();
    sc.lights.push_back({{0, 0, 4}, {1, 0.8f, 0.6f}, 1.45f});       // at the camera's foot: eye at 1.03 r
    sc.lights.push_back({{1.6f, 0.3f, 4}, {0.6f, 0.8f, 1}, 1.95f}); // right, low: eye at 1.03 r
    sc.lights.push_back({{-6, 1.5f, 4}, {0.8f, 1, 0.8f}, 5.9f});    // far left, large: eye at 1.02 r
    return sc;
}

Scene behind_whole_scene() {
    Scene sc = level_room();
    sc.lights.push_back({{0, 1.5f, 14}, {1, 1, 1}, 3});           // eye z = +10: wholly behind
    sc.lights.push_back({{1, 1, 6}, {1, 1, 1}, 2});               // z in [0, 4]: touches the eye plane
    sc.lights.push_back({{0.5f, 1.5f, 4.95f}, {1, 1, 1}, 1});     // reaches z = -0.05, short of near (0.1)
    return sc;
}

// Centre behind the eye (eye-space (1.5, -1.3, +0.3)), eye outside (distance 2.007 > r = 1.98),
// and the sphere reaches the floor in view, about 1 unit in front of the camera.
Scene behind_partly_scene() {
    Scene sc = level_room();
    sc.lights.push_back({{1.5f, 0.2f, 4.3f}, {1, 0.9f, 0.7f}, 1.98f});
    return sc;
}

Scene inside_scene() {
    Scene sc = level_room();
    sc.lights.push_back({{0.3f, 1.4f, 3.8f}, {0.8f, 0.8f, 0.8f}, 6});  // eye well inside
    sc.lights.push_back({{1.98f, 1.5f, 4}, {0.3f, 0.3f, 1}, 2});       // eye at 0.99 r, centre on the eye plane
    return sc;
}

// A floor seen from 0.05 above it, looking `incidence` degrees away from its normal at the centre
// of the view (89 degrees: the centre pixel's ray meets it 2.9 units away; 89.9: 29 units).
Scene grazing_scene(double incidence_deg) {
    Scene sc;
    const double below = (90.0 - incidence_deg) * M_PI / 180.0;
    sc.camera.pos = {0, 0.05f, 0};
    sc.camera.target = sc.camera.pos + glm::vec3(0, float(-std::sin(below)), float(-std::cos(below)));
    sc.camera.up = {0, 1, 0};
    sc.camera.fov_deg = 50;
    sc.camera.near_plane = 0.01f;
    sc.camera.far_plane = 100;
    sc.ambient = glm::vec3(0.1f);
    sc.background = {0.05f, 0.05f, 0.1f};
    sc.materials = {material("gloss", glm::vec3(0.7f), glm::vec3(0.5f), 32)};
    add_plane(sc, 400, {0, 0, 0}, 0);
    for (float d : {0.3f, 1.0f, 3.0f, 10.0f, 30.0f})
        sc.lights.push_back({{0.2f * d, 0.1f * d, -d}, {0.9f, 0.9f, 0.8f}, 0.6f * d});
    return sc;
}

// A quad in front of the room whose three vertex normals are all (0,0,0): the material pass
// normalises a zero vector (undefined in GLSL, NaN on IEEE hardware).
Scene zero_normal_scene() {
    Scene sc = room(1, glm::vec3(0));
    Mesh m;
    m.material = 1;
    const glm::vec3 corners[4] = {{-0.5f, 0.5f, 1.5f}, {0.5f, 0.5f, 1.5f}, {0.5f, 1.5f, 1.5f}, {-0.5f, 1.5f, 1.5f}};
    for (const glm::vec3& c : corners) {
        Vertex v;
        v.pos = c;
        v.normal = glm::vec3(0);
        v.tangent = glm::vec3(0);
        v.binormal = glm::vec3(0);
        m.vertices.push_back(v);
    }
    m.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from the camera (+Z side)
    sc.add(m);
    return sc;
}

// data/shadow.scene, written here so the sweep needs no file: a box resting on a floor, seen from
// the front and above, and the file's three lights, each casting the box's shadow towards the
// camera. Objects: 0 the floor, 1 the box.
Scene shadow_base(double range) {
    Scene sc;
    sc.camera.pos = {0, 4.2f, 6.2f};
    sc.camera.target = {0, 0.2f, 0.4f};
    sc.camera.up = {0, 1, 0};
    sc.camera.fov_deg = 45;
    sc.camera.near_plane = 0.5f;
    sc.camera.far_plane = float(30 * range);
    sc.ambient = glm::vec3(0.08f);
    sc.background = {0.02f, 0.02f, 0.05f};
    sc.materials = {material("floor", {0.7f, 0.7f, 0.68f}, glm::vec3(0), 1),
                    material("crate", {0.6f, 0.45f, 0.3f}, glm::vec3(0.2f), 16)};
    add_plane(sc, float(10 * range), {0, 0, 0}, 0);
    add_box(sc, glm::vec3(1), {0, 0.5f, 0}, 1);
    return sc;
}

StressCase make_case(const std::string& category, const std::string& variant, const std::string& path,
                     Scene scene) {
    StressCase c;
    c.category = category;
    c.path = path;
    c.name = category + "/" + (variant.empty() ? "" : variant + "/") + path;
    c.scene = std::move(scene);
    set_depth_path(c.opts, path);
    c.far_near = double(c.scene.camera.far_plane) / double(c.scene.camera.near_plane);
    c.light_radius = c.scene.lights.empty() ? 0 : c.scene.lights[0].radius;
    return c;
}

std::string short_number(double v) {  // 0, 1e-4, 3e-4, 0.001, 2: the shadow cases' names
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The bias sweep (stress_cases.h): each light at each (range, size) setting with every pair of a
// bias and a slope on the depth-texture maps, and at range 1 and the default size on the packed
// maps too. Quick: the defaults (LightShadow's) on both paths at range 1, the default size.
std::vector<StressCase> shadow_cases(bool quick) {
    const LightShadow defaults;
    const ShadowSweep& sw = shadow_sweep();
    struct Setting {
        double range;
        int size;
        bool packed_too;
    };
    std::vector<Setting> settings;
    for (double r : sw.ranges) settings.push_back({r, defaults.size, r == 1});
    for (int z : sw.sizes) settings.push_back({1, z, false});
    std::vector<std::pair<double, double>> pairs;
    if (quick) pairs = {{defaults.bias, defaults.slope}};
    else
        for (double b : sw.biases)
            for (double sl : sw.slopes) pairs.push_back({b, sl});
    std::vector<StressCase> out;
    for (const char* light : {"spot", "directional", "point"})
        for (const Setting& st : settings) {
            if (quick && (st.range != 1 || st.size != defaults.size)) continue;
            for (const auto& [bias, slope] : pairs)
                for (const char* path : {"texture", "packed"}) {
                    const bool packed = std::string(path) == "packed";
                    if (packed && !st.packed_too) continue;
                    LightShadow sh;
                    sh.size = st.size;
                    sh.bias = float(bias);
                    sh.slope = float(slope);
                    const std::string variant = std::string(light) + "/x" + short_number(st.range) + "/" +
                                                std::to_string(st.size) + "/b" + short_number(bias) + ",s" +
                                                short_number(slope);
                    StressCase c = make_case("shadow", variant, packed ? "corrected" : "texture",
                                             shadow_case_scene(light, st.range, sh));
                    c.path = path;
                    c.name = "shadow/" + variant + "/" + path;
                    if (packed) c.caps_off = {"no-depth-texture"};
                    c.opts.shadows.on = true;
                    c.opts.shadow_lights = true;
                    c.shadow = true;
                    c.shadow_light = light;
                    c.shadow_range = st.range;
                    out.push_back(std::move(c));
                }
        }
    return out;
}

}  // namespace

Scene shadow_case_scene(const std::string& light, double range, const LightShadow& shadow) {
    Scene sc = shadow_base(light == "directional" ? range : 1);
    Light l;
    if (light == "spot") {
        l.type = Light::Type::spot;
        l.pos = {-2, 4, -2.5f};
        l.dir = glm::normalize(glm::vec3(0.45f, -0.8f, 0.55f));
        l.color = {0.55f, 0.5f, 0.45f};
        l.radius = float(12 * range);
        l.angle_deg = 40;
    } else if (light == "directional") {
        l.type = Light::Type::directional;
        l.dir = glm::normalize(glm::vec3(0.05f, -0.75f, 0.65f));
        l.color = {0.3f, 0.32f, 0.35f};
    } else if (light == "point") {
        l.pos = {1.8f, 3.2f, -1.8f};
        l.color = {0.5f, 0.5f, 0.55f};
        l.radius = float(9 * range);
    } else {
        throw Error("shadow_case_scene: no light '" + light + "' (spot, directional, point)");
    }
    l.shadow = shadow;
    l.shadow.on = true;
    sc.lights = {l};
    return sc;
}

const ShadowSweep& shadow_sweep() {
    static const ShadowSweep s = {{1, 10, 100}, {256, 2048}, {0, 1e-4, 3e-4, 1e-3, 3e-3}, {0, 1, 2, 4}};
    return s;
}

const std::vector<std::string>& stress_paths() {
    static const std::vector<std::string> p = {"texture", "literal", "corrected", "linear", "log", "position16",
                                               "position32"};
    return p;
}

void set_depth_path(ShaderOptions& opts, const std::string& path) {
    if (path == "texture" || path == "position16" || path == "position32") {
        opts.depth = depth_path_from_name(path);
        return;
    }
    opts.depth = DepthPath::packed;
    opts.encoding = encoding_from_name(path);  // throws for anything else
}

const std::vector<double>& stress_ratios() {
    static const std::vector<double> r = {1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7};
    return r;
}

// Camera at the origin looking down -Z (eye space = world space). The screen is cut into 8x8
// cells (32x32 pixels at the cases' 256x256); tile k (row-major from the bottom left) covers its cell exactly and is tilted so that
// its eye depth runs from z_k at the cell's left edge to z_{k+1} at its right edge, with z_k
// log-spaced from 1.02 near to 0.98 far: every decade of the range gets the same number of
// pixels, and within a row the tiles join into one continuous staircase. The two edges of a tile
// are parallel (both along y), so each tile is planar. One light per tile, 0.85 of the way
// from the eye to the tile's centre, radius 0.35 of that distance (the eye stays outside).
Scene depth_range_scene(double far_near) {
    const int N = 8;
    Scene sc;
    sc.camera.pos = {0, 0, 0};
    sc.camera.target = {0, 0, -1};
    sc.camera.up = {0, 1, 0};
    sc.camera.fov_deg = 60;
    const double n = 0.1, f = n * far_near;
    sc.camera.near_plane = float(n);
    sc.camera.far_plane = float(f);
    sc.ambient = glm::vec3(0.1f);
    sc.background = {0.2f, 0.3f, 0.4f};
    sc.materials = {material("tile", glm::vec3(0.7f), glm::vec3(0.3f), 20)};
    const double t = std::tan(60.0 * M_PI / 360.0);  // aspect 1: the same half-extent in x and y
    const double z_lo = 1.02 * n, z_hi = 0.98 * f;
    auto zk = [&](int k) { return z_lo * std::pow(z_hi / z_lo, double(k) / (N * N)); };
    for (int k = 0; k < N * N; ++k) {
        const int ci = k % N, cj = k / N;
        const double a0 = -t + 2 * t * ci / N, a1 = a0 + 2 * t / N;
        const double b0 = -t + 2 * t * cj / N, b1 = b0 + 2 * t / N;
        const double z0 = zk(k), z1 = zk(k + 1);
        const glm::dvec3 p[4] = {{a0 * z0, b0 * z0, -z0}, {a1 * z1, b0 * z1, -z1},
                                 {a1 * z1, b1 * z1, -z1}, {a0 * z0, b1 * z0, -z0}};
        glm::dvec3 nrm = glm::normalize(glm::cross(p[1] - p[0], p[3] - p[0]));
        if (glm::dot(nrm, -p[0]) < 0) nrm = -nrm;  // towards the eye (it always is; kept as a guard)
        Mesh m;
        m.material = 0;
        for (const glm::dvec3& q : p) {
            Vertex v;
            v.pos = glm::vec3(q);
            v.normal = glm::vec3(nrm);
            m.vertices.push_back(v);
        }
        m.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise on screen: front faces
        sc.add(m);
        const double zc = std::sqrt(z0 * z1);
        const glm::dvec3 centre(0.5 * (a0 + a1) * zc, 0.5 * (b0 + b1) * zc, -zc);
        const float hue = float(k % 3);
        sc.lights.push_back({glm::vec3(0.85 * centre), {0.6f + 0.2f * (hue == 0), 0.6f + 0.2f * (hue == 1),
                                                         0.6f + 0.2f * (hue == 2)},
                             float(0.35 * glm::length(centre))});
    }
    return sc;
}

std::vector<StressCase> stress_cases(bool quick) {
    std::vector<StressCase> out;
    const std::vector<std::string>& all_paths = stress_paths();
    // The special cases run on the depth texture, the default packing and the best encoding.
    const std::vector<std::string> special = quick ? std::vector<std::string>{"texture"}
                                                   : std::vector<std::string>{"texture", "corrected", "log"};

    for (double r : stress_ratios()) {
        if (quick && r != 1e2 && r != 1e4 && r != 1e6) continue;
        for (const std::string& p : all_paths) {
            StressCase c = make_case("ratio", sci(r), p, depth_range_scene(r));
            c.far_near = r;  // nominal: the float near and far give r only to float precision
            out.push_back(std::move(c));
        }
    }
    if (!quick) {
        // Past 1e7: planes.x = -f/(f-n) rounds to -1 in float once f/n > 2^24 (docs/depth_precision.md, "Past the required range").
        for (double r : {2e7, 1e8})
            for (const char* p : {"texture", "corrected", "log"}) {
                StressCase c = make_case("limit", sci(r), p, depth_range_scene(r));
                c.far_near = r;
                c.limit = true;
                out.push_back(std::move(c));
            }
    }
    // Light radius r: the room scaled by r/5 (its first light has radius 5).
    for (int e = -4; e <= 6; ++e) {
        if (quick && e != -4 && e != 6) continue;
        const double r = std::pow(10.0, e);
        for (const std::string& p : special) out.push_back(make_case("radius", sci(r), p, room(float(r / 5), glm::vec3(0))));
    }
    for (const std::string& p : special) {
        Scene tiny = room(1, glm::vec3(0));
        tiny.lights = {{{0.5f, 5e-5f, 1}, {1, 1, 1}, 1e-4f}};  // 50 um above the floor, in view
        out.push_back(make_case("radius-fixed", "1e-4", p, tiny));
        Scene huge = room(1, glm::vec3(0));
        huge.lights = {{{0, 10, 0}, {1, 1, 1}, 1e6f}};  // the whole scene deep inside it
        out.push_back(make_case("radius-fixed", "1e6", p, huge));
    }
    for (const std::string& p : special) {
        out.push_back(make_case("eye-plane", "", p, eye_plane_scene()));
        out.push_back(make_case("behind", "whole", p, behind_whole_scene()));
        out.push_back(make_case("behind", "partly", p, behind_partly_scene()));
        out.push_back(make_case("inside", "", p, inside_scene()));
        for (double deg : {89.0, 89.9}) {
            if (quick && deg != 89.9) continue;
            char v[16];
            std::snprintf(v, sizeof v, "%gdeg", deg);
            out.push_back(make_case("grazing", v, p, grazing_scene(deg)));
        }
        // The room moved far from the origin; coords/0, the room where it is, is the baseline
        // the offset is measured against (the sphere's facets alone cost ~2.4 LSB there).
        for (double o : {0.0, 1e3, 1e4, 1e5, 1e6}) {
            if (quick && o != 0 && o != 1e6) continue;
            out.push_back(make_case("coords", o == 0 ? "0" : sci(o), p, room(1, float(o) * glm::vec3(1, 0.25f, -1))));
        }
        if (p == special.front())  // the position paths at the origin and 1e6 from it (the other documents' G-buffer)
            for (const char* pos : {"position16", "position32"})
                for (double o : {0.0, 1e6})
                    out.push_back(make_case("coords", o == 0 ? "0" : sci(o), pos,
                                            room(1, float(o) * glm::vec3(1, 0.25f, -1))));
        StressCase z = make_case("zero-normal", "", p, zero_normal_scene());
        z.no_reference_meshes = {3};
        z.opts.skip.light_depth_test = false;  // background pixels reach the normal test
        z.opts.skip.light_sphere_test = false;
        z.opts.scissor = false;                // ... all of them
        out.push_back(std::move(z));
    }
    for (StressCase& c : shadow_cases(quick)) out.push_back(std::move(c));
    return out;
}

}  // namespace dsr
