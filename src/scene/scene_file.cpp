// The scene-file parser (format: docs/scene-format.md). Every mistake is one dsr::Error
// "FILE:LINE: expected <what>, got '<token>'" so a user can fix the file without guessing.
// Directives that take keywords accept them in any order, each once. Every number is checked
// against its documented range here, where the user wrote it, so that nothing downstream (the
// projection, the culling planes, the depth codecs) ever meets a value it cannot represent; the
// scene's triangles and texels are counted against their budgets before anything is allocated.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "dsr_error.h"
#include "scene/framing.h"
#include "scene/light_law.h"
#include "scene/model_data.h"
#include "scene/scene.h"
#include "scene/shadow_budget.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

// One line's tokens and a cursor, with the error helpers that name file and line.
class Line {
public:
    Line(const std::string& file, int number, std::vector<std::string> tokens)
        : file_(file), number_(number), tokens_(std::move(tokens)) {}

    std::string where() const { return file_ + ":" + std::to_string(number_); }
    int number() const { return number_; }
    bool done() const { return pos_ >= tokens_.size(); }
    const std::string& peek() const { return tokens_.at(pos_); }  // the next token, not consumed

    [[noreturn]] void fail(const std::string& problem) const { throw Error(where() + ": " + problem); }
    // "expected X, got 'tok'", or "got end of line" when the tokens ran out.
    [[noreturn]] void expected(const std::string& what, size_t at) const {
        if (at < tokens_.size()) fail("expected " + what + ", got " + quote(tokens_[at]));
        fail("expected " + what + ", got end of line");
    }
    [[noreturn]] void expected_here(const std::string& what) const { expected(what, pos_); }
    [[noreturn]] void expected_last(const std::string& what) const { expected(what, pos_ - 1); }

    // Consumes the next token when it is `w`.
    bool accept(const std::string& w) {
        if (done() || tokens_[pos_] != w) return false;
        ++pos_;
        return true;
    }

    const std::string& word(const std::string& what) {
        if (done()) expected_here(what);
        return tokens_[pos_++];
    }

    // Strict full-token conversion: "1.5x", "nan", "inf" and "1e999" are all refused, and so is
    // anything beyond +-kMaxSceneNumber (the OBJ reader's bound). `subject` names the value, e.g.
    // "fov" gives "expected a number for fov". Tokens longer than 64 characters are not numbers
    // (strtod's time grows with the digits).
    float number(const std::string& subject) {
        if (done()) expected_here("a number for " + subject);
        const std::string& tok = tokens_[pos_];
        if (tok.size() > 64) expected_here("a number for " + subject);
        char* end = nullptr;
        const double d = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end != '\0') expected_here("a number for " + subject);
        const float f = float(d);
        if (!std::isfinite(d) || !std::isfinite(f)) expected_here("a finite number for " + subject);
        if (std::fabs(d) > kMaxSceneNumber) expected_here("a number for " + subject + " within +-1e12");
        ++pos_;
        return f;
    }

    glm::vec3 vec3(const std::string& subject) {
        glm::vec3 v(0);
        for (int i = 0; i < 3; ++i) v[i] = number(subject);
        return v;
    }

    // A colour: three finite numbers, each >= 0.
    glm::vec3 colour(const std::string& subject) {
        glm::vec3 c(0);
        for (int i = 0; i < 3; ++i) {
            c[i] = number(subject);
            if (c[i] < 0) expected_last(subject + " component >= 0");
        }
        return c;
    }

    float positive(const std::string& subject) {
        const float f = number(subject);
        if (!(f > 0)) expected_last(subject + " > 0");
        return f;
    }

    float non_negative(const std::string& subject) {
        const float f = number(subject);
        if (!(f >= 0)) expected_last(subject + " >= 0");
        return f;
    }

    void end() {
        if (!done()) expected_here("end of line");
    }

    // Keyword-value directives: reads the next key, which must be one of `keys` and new.
    std::string key(const std::vector<std::string>& keys, std::set<std::string>& seen) {
        std::string list;
        for (const std::string& k : keys) list += (list.empty() ? "" : ", ") + k;
        const std::string& k = word("one of " + list);
        bool known = false;
        for (const std::string& c : keys) known = known || c == k;
        if (!known) expected_last("one of " + list);
        if (!seen.insert(k).second) expected_last("each of " + list + " at most once");
        return k;
    }
    // After the keys: every required key must have been given.
    void require(const std::vector<std::string>& keys, const std::set<std::string>& seen) const {
        for (const std::string& k : keys)
            if (!seen.count(k)) expected(k, tokens_.size());
    }

private:
    std::string file_;
    int number_;
    std::vector<std::string> tokens_;
    size_t pos_ = 0;
};

// Drawn triangles of the built-in shapes (shapes.cpp), counted before one is made.
size_t shape_triangles(const std::string& kind) {
    if (kind == "plane") return 2;
    if (kind == "box") return 12;
    return 48 * (2 * 24 - 2);  // make_sphere's default slices x stacks, less the poles' halves
}

std::string count(size_t n) { return std::to_string(n); }

class Parser {
public:
    explicit Parser(const std::string& path) : path_(path) {
        scene_.path = path;
        dir_ = std::filesystem::path(path).parent_path();
    }

    Scene run() {
        std::string text = read_user_text(path_, "scene file", kMaxSceneBytes);
        scene_.inputs.push_back(path_);
        run_lines(text);
        return finish();
    }

    Scene run_text(std::string text) {
        check_user_text(path_, text);
        run_lines(text);
        return finish();
    }

private:
    void run_lines(const std::string& text) {
        TextLines lines(text);
        for (std::string_view l; lines.next(l);) {
            const std::vector<std::string_view> views = split_tokens(l);
            if (views.empty()) continue;
            Line line(path_, lines.number(), std::vector<std::string>(views.begin(), views.end()));
            directive(line);
        }
    }

    Scene finish() {
        if (camera_line_ == 0) throw Error(path_ + ": no camera line");
        if (fit_) apply_camera_fit(scene_, *fit_);  // `camera fit`: once every object is placed
        precision_warnings();
        return std::move(scene_);
    }

    // Triangles whose edges are very long against the camera's distance to them lose their
    // edges and shading in the rasteriser's float clipping and interpolation (docs/scene-format.md,
    // "Precision warning", shows how far): legal, so one warning, naming the first line that has
    // such triangles, from the scene's camera.
    void precision_warnings() {
        const glm::dvec3 eye(scene_.camera.pos);
        const double near_plane = scene_.camera.near_plane;
        struct Extent {
            double edge = -1;  // longest edge in object space; -1: not measured yet
            glm::dvec3 lo{0}, hi{0};
        };
        std::vector<Extent> extents(scene_.meshes.size());  // per mesh, shared by its instances
        for (const auto& [line, object] : object_lines_) {
            const Object& o = scene_.objects[object];
            Extent& x = extents[o.mesh];
            if (x.edge < 0) {
                const Mesh& mesh = scene_.meshes[o.mesh];
                x.edge = 0;
                for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
                    for (size_t k = 0; k < 3; ++k) {
                        const glm::dvec3 a(mesh.vertices[mesh.indices[t + k]].pos);
                        const glm::dvec3 b(mesh.vertices[mesh.indices[t + (k + 1) % 3]].pos);
                        x.edge = std::max(x.edge, glm::length(b - a));
                        x.lo = t + k == 0 ? a : glm::min(x.lo, a);
                        x.hi = t + k == 0 ? a : glm::max(x.hi, a);
                    }
            }
            // Rigid with a uniform scale (scene.h Object): lengths scale by a column's length.
            const double edge = x.edge * glm::length(glm::dvec3(o.model[0]));
            glm::dvec3 lo(0), hi(0);
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? x.hi.x : x.lo.x, (c & 2) ? x.hi.y : x.lo.y, (c & 4) ? x.hi.z : x.lo.z);
                const glm::dvec3 w(o.model * glm::dvec4(corner, 1.0));
                lo = c == 0 ? w : glm::min(lo, w);
                hi = c == 0 ? w : glm::max(hi, w);
            }
            const double distance = std::max(glm::length(eye - glm::clamp(eye, lo, hi)), near_plane);
            if (edge > kMaxEdgeOverDistance * distance) {
                scene_.warnings.push_back(path_ + ":" + std::to_string(line) + ": triangles " + fmt(float(edge)) +
                                          " long, " + fmt(float(edge / distance)) +
                                          " times the camera's distance to them: past 1e5 their edges and shading "
                                          "lose precision (docs/scene-format.md)");
                return;
            }
        }
    }

    void directive(Line& line) {
        const std::string kinds =
            "a directive (camera, ambient, background, material, plane, box, sphere, mesh, light, post, markers)";
        const std::string d = line.word(kinds);
        if (d == "camera") camera(line);
        else if (d == "ambient") { scene_.ambient = line.colour("ambient"); line.end(); }
        else if (d == "background") { scene_.background = line.colour("background"); line.end(); }
        else if (d == "material") material(line);
        else if (d == "plane" || d == "box" || d == "sphere") shape(line, d);
        else if (d == "mesh") mesh(line);
        else if (d == "light") light(line);
        else if (d == "post") post(line);
        else if (d == "markers") markers(line);
        else line.expected_last(kinds);
    }

    void camera(Line& line) {
        if (camera_line_ != 0)
            line.expected_last("one camera line (the first is line " + std::to_string(camera_line_) + ")");
        camera_line_ = line.number();
        if (line.accept("fit")) return camera_fit(line);
        Camera& c = scene_.camera;
        const std::vector<std::string> keys = {"pos", "target", "up", "fov", "near", "far"};
        std::set<std::string> seen;
        while (!line.done()) {
            const std::string k = line.key(keys, seen);
            if (k == "pos") c.pos = line.vec3("camera pos");
            else if (k == "target") c.target = line.vec3("camera target");
            else if (k == "up") c.up = line.vec3("camera up");
            else if (k == "fov") {
                c.fov_deg = line.number("fov");
                if (!(c.fov_deg > 0 && c.fov_deg < 180)) line.expected_last("fov in (0, 180) degrees");
            } else if (k == "near") {
                c.near_plane = line.positive("near");
                if (seen.count("far") && !(c.near_plane < c.far_plane)) line.expected_last("near < far");
            } else {
                c.far_plane = line.number("far");
                if (seen.count("near") && !(c.far_plane > c.near_plane)) line.expected_last("far > near");
            }
        }
        line.require(keys, seen);
        // Past 1e7 the projection's far row rounds to the near row's (docs/depth_precision.md: at 1e8
        // every path loses its far plane).
        if (!(double(c.far_plane) <= kMaxFarOverNear * double(c.near_plane)))
            line.fail("expected far / near at most 1e7, got " + fmt(c.far_plane) + " / " + fmt(c.near_plane) + " = " +
                      fmt(double(c.far_plane) / double(c.near_plane)));
        const glm::vec3 dir = c.target - c.pos;
        if (!(glm::length(dir) > 0)) line.fail("camera target equals camera pos");
        const float cross_len = glm::length(glm::cross(glm::normalize(dir), c.up));
        if (!(glm::length(c.up) > 0) || !(cross_len > 1e-4f * glm::length(c.up)))
            line.fail("expected camera up not parallel to target - pos, got '" + fmt(c.up.x) + " " +
                      fmt(c.up.y) + " " + fmt(c.up.z) + "'");
    }

    // camera fit [from X Y Z] [fov DEG] (scene/framing.h): recorded here, resolved in finish().
    void camera_fit(Line& line) {
        CameraFit f;
        f.where = line.where();
        std::set<std::string> seen;
        while (!line.done()) {
            if (line.key({"from", "fov"}, seen) == "from") {
                f.from = line.vec3("camera fit from");
                if (!(glm::length(f.from) > 0)) line.expected_last("a non-zero direction for camera fit from");
            } else {
                f.fov_deg = line.number("fov");
                if (!(f.fov_deg > 0 && f.fov_deg < 180)) line.expected_last("fov in (0, 180) degrees");
            }
        }
        fit_ = f;
    }

    void material(Line& line) {
        Material m;
        m.name = line.word("a material name");
        for (size_t i = 0; i < scene_.materials.size(); ++i)
            if (scene_.materials[i].name == m.name)
                line.expected_last("a material name not used before (first defined on line " +
                                   std::to_string(material_lines_[i]) + ")");
        // Phong (the tutorial's): diffuse, specular, shininess and their maps. Metallic-roughness
        // (glTF's, docs/metal_rough.md): base, metallic, roughness, their maps and emissive. A
        // line is one or the other, as its first key says.
        const std::vector<std::string> phong = {"diffuse", "specular", "shininess", "diffuse_map",
                                                "normal_map", "specular_map", "tile", "opacity"};
        const std::vector<std::string> metal = {"base", "metallic", "roughness", "base_map", "metallic_roughness_map",
                                                "normal_map", "emissive", "tile", "opacity"};
        if (!line.done() && line.peek() == "base") m.model = Material::Model::metallic_roughness;
        const std::vector<std::string>& keys = m.metal_rough() ? metal : phong;
        std::set<std::string> seen;
        auto unit = [&](const char* what) {
            const float f = line.number(what);
            if (!(f >= 0 && f <= 1)) line.expected_last(std::string(what) + " in [0, 1]");
            return f;
        };
        while (!line.done()) {
            const std::string k = line.key(keys, seen);
            if (k == "base") {
                m.diffuse = line.colour("base");
                for (int c = 0; c < 3; ++c)
                    if (m.diffuse[c] > 1) line.expected_last("base component in [0, 1]");
            } else if (k == "metallic") m.metallic = unit("metallic");
            else if (k == "roughness") m.roughness = unit("roughness");
            else if (k == "emissive") m.emissive = line.colour("emissive");
            else if (k == "base_map" || k == "metallic_roughness_map") {
                const std::string& file = line.word("a file name for " + k);
                (k == "base_map" ? m.diffuse_map : m.metallic_roughness_map) = texture(line, k, file);
            } else if (k == "diffuse") m.diffuse = line.colour("diffuse");
            else if (k == "specular") m.specular = line.colour("specular");
            else if (k == "shininess") {
                m.shininess = line.number("shininess");
                if (!(m.shininess >= 1 && m.shininess <= 2048)) line.expected_last("shininess in [1, 2048]");
            } else if (k == "tile") m.tile = line.positive("tile");
            else if (k == "opacity") {  // below 1: drawn by the forward pass after the lights (docs/forward.md)
                m.opacity = line.number("opacity");
                if (!(m.opacity > 0 && m.opacity <= 1)) line.expected_last("opacity in (0, 1]");
            } else {
                const std::string& file = line.word("a file name for " + k);
                const int index = texture(line, k, file);
                if (k == "diffuse_map") m.diffuse_map = index;
                else if (k == "normal_map") m.normal_map = index;
                else m.specular_map = index;
            }
        }
        if (m.metal_rough()) {
            line.require({"base", "metallic", "roughness"}, seen);
            m.specular = glm::vec3(0);  // unused by the model; the forward stage's Phong sees no highlight
        } else {
            line.require({"diffuse", "specular", "shininess"}, seen);
        }
        scene_.materials.push_back(m);
        material_lines_.push_back(line.number());
    }

    // Loads (once per resolved path) and returns the index into Scene::textures.
    int texture(const Line& line, const std::string& key, const std::string& file) {
        std::filesystem::path p(file);
        if (p.is_relative()) p = dir_ / p;
        const std::string resolved = p.lexically_normal().string();
        for (size_t i = 0; i < scene_.texture_paths.size(); ++i)
            if (scene_.texture_paths[i] == resolved) return int(i);
        Image img;
        try {
            img = load_image(resolved, kMaxSceneTexels - texels_);
        } catch (const ImageTooLarge& e) {
            line.fail("expected textures within the scene's budget of " + count(kMaxSceneTexels) + " texels, got " +
                      key + " " + quote(file) + " of " + count(size_t(e.width) * size_t(e.height)) + " (" +
                      std::to_string(e.width) + " x " + std::to_string(e.height) + ") after " + count(texels_));
        } catch (const Error& e) {
            line.fail("expected a readable image for " + key + ", got " + quote(file) + ": " + e.what());
        }
        texels_ += size_t(img.width) * size_t(img.height);
        scene_.inputs.push_back(resolved);
        scene_.textures.push_back(std::move(img));
        scene_.texture_paths.push_back(resolved);
        return int(scene_.textures.size() - 1);
    }

    // Before a shape or mesh instance adds `n` drawn triangles.
    void spend_triangles(const Line& line, const std::string& what, size_t n) {
        if (n > kMaxSceneTriangles - triangles_)
            line.fail("expected at most " + count(kMaxSceneTriangles) + " triangles in the scene, got " + what + " of " +
                      count(n) + " after " + count(triangles_));
        triangles_ += n;
    }

    // A world-space point of `what` beyond +-kMaxSceneNumber (as OBJ coordinates are bounded).
    void check_world(const Line& line, const std::string& what, const glm::dvec3& p) {
        for (int i = 0; i < 3; ++i)
            if (!(std::fabs(p[i]) <= kMaxSceneNumber))
                line.fail("expected " + what + " within +-1e12 in world space, got a vertex at " + fmt(float(p.x)) +
                          " " + fmt(float(p.y)) + " " + fmt(float(p.z)));
    }

    void shape(Line& line, const std::string& kind) {
        const std::string size_key = kind == "sphere" ? "radius" : "size";
        const std::vector<std::string> keys = {size_key, "at", "material"};
        std::set<std::string> seen;
        glm::vec3 size(1), at(0);
        int material = -1;
        while (!line.done()) {
            const std::string k = line.key(keys, seen);
            if (k == size_key) {
                if (kind == "box")
                    for (int i = 0; i < 3; ++i) size[i] = line.positive("box size");
                else
                    size = glm::vec3(line.positive(kind + " " + size_key));
            } else if (k == "at") {
                at = line.vec3(kind + " at");
            } else {
                const std::string& name = line.word("a material name");
                for (size_t i = 0; i < scene_.materials.size(); ++i)
                    if (scene_.materials[i].name == name) material = int(i);
                if (material < 0) line.expected_last("a material defined on an earlier line");
            }
        }
        line.require(keys, seen);
        const glm::dvec3 half = glm::dvec3(size) * 0.5;
        check_world(line, kind, glm::abs(glm::dvec3(at)) + half);
        spend_triangles(line, "a " + kind, shape_triangles(kind));
        size_t object;
        if (kind == "plane") object = add_plane(scene_, size.x, at, material);
        else if (kind == "box") object = add_box(scene_, size, at, material);
        else object = add_sphere(scene_, size.x, at, material);
        object_lines_.push_back({line.number(), object});
    }

    // mesh FILE [scale S] [at X Y Z] [rotate_y DEGREES] [material NAME] [one-sided]
    // FILE: an OBJ (.obj) or glTF 2.0 (.gltf, .glb) model (scene/model_data.h).
    void mesh(Line& line) {
        const std::string file = line.word("a model file name (.obj, .gltf or .glb)");
        std::filesystem::path p(file);
        if (p.is_relative()) p = dir_ / p;
        const std::string resolved = p.lexically_normal().string();
        const std::vector<std::string> keys = {"scale", "at", "rotate_y", "material", "one-sided"};
        std::set<std::string> seen;
        MeshInstance inst;
        inst.line = line.number();
        bool one_sided = false;
        while (!line.done()) {
            const std::string k = line.key(keys, seen);
            if (k == "scale") inst.scale = line.positive("mesh scale");
            else if (k == "at") inst.at = glm::dvec3(line.vec3("mesh at"));
            else if (k == "rotate_y") inst.rotate_y_deg = line.number("mesh rotate_y (degrees)");
            else if (k == "one-sided") one_sided = true;
            else inst.material = material_named(line);
        }
        if (!is_model_file(file)) line.expected_last("a model file ending .obj, .gltf or .glb");
        // The same file is read once (cached by resolved path), its materials and textures
        // added to the scene once.
        auto cached = model_index_.find(resolved);
        if (cached == model_index_.end()) {
            ModelData model;
            ModelBudget budget;
            // What is left of the scene's budgets, checked by the reader before it allocates.
            budget.max_triangles = kMaxSceneTriangles - triangles_;
            budget.max_texels = kMaxSceneTexels - texels_;
            budget.note = "the scene's budget of " + count(kMaxSceneTriangles) + " triangles and " +
                          count(kMaxSceneTexels) + " texels has " + count(budget.max_triangles) + " and " +
                          count(budget.max_texels) + " left";
            try {
                model = read_model(resolved, budget);
            } catch (const Error& e) {
                line.fail("expected a readable model file for mesh, got " + quote(file) + ": " + e.what());
            }
            if (!model.cameras.empty() || !model.lights.empty())
                scene_.warnings.push_back(line.where() + ": the cameras and lights of " + quote(file) +
                                          " are not used: a scene file's own camera and lights light it");
            size_t added = 0;
            const int index = add_model_data(scene_, std::move(model), &added);
            texels_ += added;
            material_lines_.resize(scene_.materials.size(), line.number());
            cached = model_index_.emplace(resolved, index).first;
        }
        // The model stays in object space, uploaded once; each instance is one object per
        // placement drawn with model_matrix() x the placement's (composed with the view in
        // double by the renderers).
        const glm::dmat4 m = inst.model_matrix();
        const MeshModel& model = scene_.models[size_t(cached->second)];
        // Every vertex must stay within +-1e12 in world space, as OBJ coordinates and the scene's
        // own numbers do (the analytic reference and the bounds the renderers cull with are
        // world-space): checked on each placed mesh's bounding box corners.
        for (const MeshModel::Placement& pl : model.placements) {
            glm::vec3 lo(0), hi(0);
            bool first = true;
            for (const Vertex& v : scene_.meshes[pl.mesh].vertices) {
                lo = first ? v.pos : glm::min(lo, v.pos);
                hi = first ? v.pos : glm::max(hi, v.pos);
                first = false;
            }
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
                check_world(line, "scale and at that keep " + quote(file), glm::dvec3(m * pl.model * glm::dvec4(corner, 1.0)));
            }
        }
        spend_triangles(line, "mesh " + quote(file), model.triangles);
        const MeshInstance placed = place_model(scene_, cached->second, m, inst.material, one_sided);
        inst.model = placed.model;
        inst.first_object = placed.first_object;
        inst.object_count = placed.object_count;
        for (size_t o = inst.first_object; o < inst.first_object + inst.object_count; ++o)
            object_lines_.push_back({line.number(), o});
        scene_.instances.push_back(inst);
    }

    int material_named(Line& line) {
        const std::string& name = line.word("a material name");
        for (size_t i = 0; i < scene_.materials.size(); ++i)
            if (scene_.materials[i].name == name) return int(i);
        line.expected_last("a material defined on an earlier line");
    }

    // light point|spot|directional (docs/scene-format.md; scene.h Light, scene/light_law.h).
    void light(Line& line) {
        const std::string& kind = line.word("light kind 'point', 'spot' or 'directional'");
        Light l;
        float intensity = 1;
        std::vector<std::string> keys, required;
        // `intensity I candela|lux` makes the light physical (KHR_lights_punctual's units and
        // laws, docs/metal_rough.md), with `range R` and a spot's `inner DEGREES`.
        if (kind == "point") {
            keys = {"pos", "color", "radius", "attenuation", "threshold", "intensity", "range"};
            required = {"pos", "color"};
        } else if (kind == "spot") {
            l.type = Light::Type::spot;
            keys = {"pos", "dir", "color", "radius", "attenuation", "threshold", "angle", "exponent", "intensity", "range", "inner"};
            required = {"pos", "dir", "color", "angle"};
        } else if (kind == "directional") {
            l.type = Light::Type::directional;
            keys = {"dir", "color", "intensity"};
            required = {"dir", "color"};
        } else {
            line.expected_last("light kind 'point', 'spot' or 'directional'");
        }
        keys.push_back("shadow");
        std::set<std::string> seen;
        while (!line.done()) {
            for (const char* sub : {"size", "bias", "slope"})
                if (line.accept(sub)) line.expected_last("shadow before " + std::string(sub) + " (shadow [size N] [bias B] [slope S])");
            const std::string k = line.key(keys, seen);
            if (k == "pos") l.pos = line.vec3("light pos");
            else if (k == "shadow") shadow(line, l.shadow);
            else if (k == "color") l.color = line.colour("light color");
            else if (k == "radius") {
                if (seen.count("attenuation")) line.expected_last("radius or attenuation, not both");
                l.radius = line.positive("light radius");
            } else if (k == "attenuation") {
                if (seen.count("radius")) line.expected_last("radius or attenuation, not both");
                l.attenuation = true;
                l.kc = line.positive("attenuation KC");  // KC = 0 would be infinite at the light
                l.kl = line.non_negative("attenuation KL");
                l.kq = line.non_negative("attenuation KQ");
                if (l.kl == 0 && l.kq == 0) line.expected_last("attenuation KL or KQ > 0 (else it never falls)");
            } else if (k == "threshold") {
                l.threshold = line.positive("attenuation threshold");
            } else if (k == "dir") {
                l.dir = line.vec3("light dir");
                // 1e-12: its squared length stays a normal float, so normalising it is exact enough.
                if (!(glm::length(glm::dvec3(l.dir)) >= 1e-12)) line.expected_last("a non-zero light dir (length >= 1e-12)");
                l.dir = glm::normalize(l.dir);
            } else if (k == "angle") {
                l.angle_deg = line.number("spot angle");
                if (!(l.angle_deg > 0 && l.angle_deg <= 90)) line.expected_last("spot angle in (0, 90] degrees");
            } else if (k == "intensity") {
                l.physical = true;
                intensity = line.non_negative("light intensity");
                const char* unit = l.type == Light::Type::directional ? "lux" : "candela";
                if (!line.accept(unit)) line.expected_here(std::string("the intensity's unit '") + unit + "'");
            } else if (k == "range") {
                l.range = line.positive("light range");
            } else if (k == "inner") {
                l.inner_deg = line.non_negative("spot inner angle");
            } else {
                l.exponent = line.non_negative("spot exponent");
            }
        }
        line.require(required, seen);
        if (l.physical) {
            physical_light(line, l, seen, intensity);
        } else {
            for (const char* k : {"range", "inner"})
                if (seen.count(k)) line.fail("expected " + std::string(k) + " only with intensity I candela");
            if (l.type != Light::Type::directional && !seen.count("radius") && !seen.count("attenuation"))
                line.expected(kind == "spot" ? "radius or attenuation (the spot's range)" : "radius or attenuation",
                              size_t(-1));
            if (seen.count("threshold") && !seen.count("attenuation"))
                line.fail("expected threshold only with attenuation KC KL KQ");
            if (l.attenuation) {
                const float i_max = std::max(l.color.r, std::max(l.color.g, l.color.b));
                l.radius = float(attenuation_radius(l.kc, l.kl, l.kq, l.threshold, i_max));
                if (i_max > 0 && !(l.radius > 0))
                    line.fail("expected attenuation under which the light reaches threshold " + fmt(l.threshold) +
                              " somewhere (KC < largest colour / threshold), got KC " + fmt(l.kc));
                if (!(l.radius <= kMaxSceneNumber))
                    line.fail("expected attenuation whose radius (where it reaches threshold " + fmt(l.threshold) +
                              ") is within 1e12, got " + fmt(l.radius));
            }
        }
        // Every shadow map of the scene together within kMaxShadowBytes, at the most a texel
        // takes on any path (scene/shadow_budget.h).
        if (l.shadow.on) {
            const long long bytes = shadow_map_bytes(l, kMaxShadowTexelBytes);
            if (bytes > kMaxShadowBytes - shadow_bytes_)
                line.fail("expected " + shadow_budget_text(l, shadow_bytes_, kMaxShadowTexelBytes));
            shadow_bytes_ += bytes;
        }
        scene_.lights.push_back(l);
    }

    // A light line with `intensity` (KHR_lights_punctual's units; scene.h Light): colour times
    // the intensity, and the radius its bound (physical_radius). The Equation 2 and attenuation
    // words do not mix with it.
    void physical_light(Line& line, Light& l, const std::set<std::string>& seen, float intensity) {
        for (const char* k : {"radius", "attenuation", "threshold", "exponent"})
            if (seen.count(k)) line.fail("expected " + std::string(k) + " or intensity, not both");
        if (l.type == Light::Type::spot && !(l.inner_deg < l.angle_deg))
            line.fail("expected spot inner angle below the angle " + fmt(l.angle_deg) + ", got " + fmt(l.inner_deg));
        l.color *= intensity;
        const double i_max = std::max(l.color.r, std::max(l.color.g, l.color.b));
        if (!std::isfinite(i_max) || i_max > kMaxSceneNumber)
            line.fail("expected color times intensity within 1e12, got " + fmt(float(i_max)));
        if (l.type == Light::Type::directional) return;
        l.radius = float(physical_radius(i_max, l.range));
        if (!(l.radius <= kMaxSceneNumber))
            line.fail("expected intensity whose radius (where it falls under half an 8-bit step) is within 1e12, got " +
                      fmt(l.radius));
    }

    // `shadow [size N] [bias B] [slope S]` (scene.h LightShadow): the three right after `shadow`,
    // each at most once, in any order.
    void shadow(Line& line, LightShadow& sh) {
        sh.on = true;
        std::set<std::string> seen;
        for (;;) {
            std::string k;
            for (const char* sub : {"size", "bias", "slope"})
                if (k.empty() && line.accept(sub)) k = sub;
            if (k.empty()) return;
            if (!seen.insert(k).second) line.expected_last("each of shadow's size, bias, slope at most once");
            if (k == "size") {
                const float n = line.number("shadow size");
                const bool pow2 = n >= 64 && n <= 8192 && n == std::floor(n) && (int(n) & (int(n) - 1)) == 0;
                if (!pow2) line.expected_last("shadow size a power of two in [64, 8192]");
                sh.size = int(n);
            } else if (k == "bias") {
                sh.bias = line.non_negative("shadow bias");
            } else {
                sh.slope = line.non_negative("shadow slope");
            }
        }
    }

    void post(Line& line) {
        std::set<std::string> seen;
        scene_.post_bloom = scene_.post_aa = false;
        while (!line.done()) {
            const std::string k = line.key({"bloom", "aa"}, seen);
            (k == "bloom" ? scene_.post_bloom : scene_.post_aa) = true;
        }
    }

    // `markers sphere` (the default) or `markers box SIZE`: the shape --show-lights draws.
    void markers(Line& line) {
        std::set<std::string> seen;
        const std::string k = line.key({"sphere", "box"}, seen);
        if (k == "sphere") {
            scene_.marker_shape = Scene::MarkerShape::sphere;
            scene_.marker_size = 0;
        } else {
            scene_.marker_shape = Scene::MarkerShape::box;
            scene_.marker_size = line.positive("markers box half-size");
        }
        line.end();
    }

    static std::string fmt(double f) {
        std::ostringstream s;
        s << std::setprecision(6) << f;
        return s.str();
    }

    std::string path_;
    std::filesystem::path dir_;
    Scene scene_;
    int camera_line_ = 0;
    std::optional<CameraFit> fit_;
    std::vector<int> material_lines_;  // parallel to scene_.materials
    std::map<std::string, int> model_index_;  // resolved OBJ path -> scene_.models
    size_t triangles_ = 0, texels_ = 0;       // spent of kMaxSceneTriangles, kMaxSceneTexels
    long long shadow_bytes_ = 0;              // spent of kMaxShadowBytes
    std::vector<std::pair<int, size_t>> object_lines_;  // (line, index into scene_.objects)
};

}  // namespace

glm::dmat4 MeshInstance::model_matrix() const {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), at);
    m = glm::rotate(m, glm::radians(rotate_y_deg), glm::dvec3(0, 1, 0));
    return glm::scale(m, glm::dvec3(scale));
}

namespace {

// Formats other programs read and dsr does not: a file named so gets one line saying what dsr reads.
bool foreign_model(const std::string& path) {
    static const char* const exts[] = {".fbx", ".dae", ".3ds", ".ply", ".stl", ".blend", ".off", ".x", ".ase", ".lwo",
                                       ".lws", ".md2", ".md3", ".md5mesh", ".ms3d", ".3mf", ".amf", ".wrl", ".x3d",
                                       ".ifc", ".usd", ".usda", ".usdc", ".usdz", ".abc", ".b3d", ".ac", ".irr", ".cob",
                                       ".dxf", ".smd", ".mdl", ".nff", ".ter", ".xgl", ".ogex", ".q3o", ".sib", ".iqm"};
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const char* x : exts)
        if (e == x) return true;
    return false;
}

// What the first bytes of a file that is not named as a model say it is: glTF binary ("glTF"),
// JSON (a '{' first: a .gltf), or anything else (a scene file, or what its parser will refuse).
enum class Sniffed { text, glb, json };
Sniffed sniff(const std::string& path) {
    const int fd = open_user_file(path, "scene file", kMaxSceneBytes);
    char head[64] = {};
    const ssize_t n = ::read(fd, head, sizeof head);
    ::close(fd);
    if (n >= 4 && std::string(head, 4) == "glTF") return Sniffed::glb;
    for (ssize_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(head[i]);
        if (c == 0xEF || c == 0xBB || c == 0xBF || std::isspace(c)) continue;  // a UTF-8 mark, blanks
        return c == '{' ? Sniffed::json : Sniffed::text;
    }
    return Sniffed::text;
}

}  // namespace

namespace {
void print_warning_line(const std::string& w) { std::fprintf(stderr, "warning: %s\n", w.c_str()); }
void (*warning_printer)(const std::string&) = print_warning_line;
}  // namespace

Scene load_scene(const std::string& path, const LoadOptions& options) {
    Scene s;
    if (is_model_path(path)) {
        s = model_scene(path, options);  // a model is a scene
    } else if (foreign_model(path)) {
        throw Error(path + ": expected a scene file (docs/scene-format.md) or a model dsr reads: OBJ (.obj) or "
                    "glTF 2.0 (.gltf, .glb); this format is not one of them");
    } else if (sniff(path) != Sniffed::text) {
        s = model_scene(path, options, true);  // glTF, whatever its name
    } else {
        s = Parser(path).run();
        if (options.ambient) s.ambient = *options.ambient;
    }
    if (options.strict && !s.warnings.empty()) throw Error(s.warnings.front() + " (--strict: a warning is an error)");
    for (const std::string& w : s.warnings) warning_printer(w);
    return s;
}

void set_warning_printer(void (*print)(const std::string& warning)) { warning_printer = print; }

Scene parse_scene(const std::string& path, const std::string& text) { return Parser(path).run_text(text); }

}  // namespace dsr
