// OBJ/MTL loading (obj_loader.h). tinyobjloader does the parsing and triangulation; it is
// lenient (a bad number reads as 0, an unknown material as none, an out-of-range index is kept
// or silently dropped), so every OBJ and MTL line is first checked here, with its line number,
// against what tinyobjloader will make of it. What tinyobjloader returns is then checked again
// (sizes, indices) before it is used, so a disagreement is an error and never a wrong image.
// The line checks are mtl_check / obj_check (over obj_text's scanner), the geometry after
// tinyobjloader is obj_geometry; this file is the glue: files, tinyobjloader, materials.
#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <istream>
#include <map>

#include "dsr_error.h"
#include "scene/mtl_check.h"
#include "scene/obj_check.h"
#include "scene/obj_geometry.h"
#include "scene/obj_text.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

namespace fs = std::filesystem;
using std::string;
using obj::check_mtl;
using obj::check_obj;
using obj::line_of;
using obj::MemBuf;
using obj::MtlFile;
using obj::MtlMaterialInfo;
using obj::ObjCheck;
using obj::quote;
using obj::read_regular_file;
using obj::read_regular_image;

// ---- tinyobjloader glue ---------------------------------------------------------------------

// Hands tinyobjloader the MTL texts already read and checked, keyed by the name in mtllib.
class CheckedMtlReader : public tinyobj::MaterialReader {
public:
    explicit CheckedMtlReader(std::map<string, MtlFile>& files) : files_(files) {}
    bool operator()(const string& id, std::vector<tinyobj::material_t>* materials, std::map<string, int>* map,
                    string* warn, string* err) override {
        auto it = files_.find(id);
        if (it == files_.end()) return false;  // an empty piece of a split name; the checked one follows
        MemBuf buf(it->second.text.data(), it->second.text.size());
        std::istream in(&buf);
        tinyobj::LoadMtl(map, materials, &in, warn, err);
        return true;
    }

private:
    std::map<string, MtlFile>& files_;
};

// Step 3 of parse_obj: materials and their maps, appended to model.materials and model.textures.
// Each file is read once; a greyscale normal map is converted once per -bm value.
void add_materials(const string& path, const string& obj_name, const std::vector<tinyobj::material_t>& mats,
                   const std::map<string, MtlMaterialInfo>& mtl_info, const ObjOptions& options, ObjModel& model) {
    std::map<string, int> texture_index;  // texture_paths entry -> model.textures
    size_t texels = 0;                     // of model.textures, against options.max_texels
    auto texture = [&](const MtlMaterialInfo& info, const string& key, const string& line_key, string name,
                       bool normal_map, double bm) -> int {
        while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
        const string where = info.file + ":" + std::to_string(line_of(info, line_key));
        fs::path p(name);
        if (p.is_relative()) p = fs::path(info.file).parent_path() / p;
        const string resolved = p.lexically_normal().string();
        const string height_key = resolved + " (height map, bm " + std::to_string(bm) + ")";
        if (normal_map && texture_index.count(height_key)) return texture_index[height_key];
        auto it = texture_index.find(resolved);
        if (it != texture_index.end() && !(normal_map && is_greyscale(model.textures[size_t(it->second)])))
            return it->second;
        Image img;
        const size_t left = options.max_texels > texels ? options.max_texels - texels : 0;
        auto over_budget = [&](size_t w, size_t h) {
            throw Error(where + ": expected textures within " +
                        (options.budget_note.empty() ? std::to_string(options.max_texels) + " texels"
                                                     : options.budget_note) +
                        ", got " + key + " " + quote(name) + " of " + std::to_string(w * h) + " (" + std::to_string(w) +
                        " x " + std::to_string(h) + ") after " + std::to_string(texels));
        };
        if (it != texture_index.end()) {
            img = model.textures[size_t(it->second)];  // a greyscale map used as colour and as height
        } else {
            try {
                img = options.read_image ? options.read_image(resolved) : read_regular_image(resolved, left);
            } catch (const ImageTooLarge& e) {
                over_budget(size_t(e.width), size_t(e.height));
            } catch (const Error& e) {
                throw Error(where + ": expected a readable image for " + key + ", got " + quote(name) + ": " + e.what());
            }
            model.inputs.push_back(resolved);
            if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * size_t(img.height) * 4)
                throw Error(where + ": expected a readable image for " + key + ", got " + quote(name) + ": no pixels");
            for (float f : img.rgba)
                if (!std::isfinite(f)) throw Error(where + ": expected finite texel values in " + quote(name) + " for " + key);
        }
        if (size_t(img.width) * size_t(img.height) > left) over_budget(size_t(img.width), size_t(img.height));
        texels += size_t(img.width) * size_t(img.height);
        string stored = resolved;
        if (normal_map && is_greyscale(img)) {
            if (!std::isfinite(bm)) throw Error(where + ": expected a finite -bm for " + key);
            img = height_to_normal(img, float(bm));
            stored = height_key;
        }
        model.textures.push_back(std::move(img));
        model.texture_paths.push_back(stored);
        texture_index[stored] = int(model.textures.size() - 1);
        return int(model.textures.size() - 1);
    };
    for (const tinyobj::material_t& m : mats) {
        auto info_it = mtl_info.find(m.name);
        if (info_it == mtl_info.end()) throw Error(path + ": tinyobjloader returned material " + quote(m.name) + " that no MTL defines");
        const MtlMaterialInfo& info = info_it->second;
        const string where = info.file + ":" + std::to_string(info.line);
        Material out;
        out.name = obj_name + ":" + m.name;
        out.diffuse = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        out.specular = {m.specular[0], m.specular[1], m.specular[2]};
        out.shininess = std::clamp(float(m.shininess), 1.0f, 2048.0f);
        out.opacity = std::clamp(float(m.dissolve), 0.0f, 1.0f);
        if (!m.diffuse_texname.empty())
            out.diffuse_map = texture(info, "map_Kd", "map_Kd", m.diffuse_texname, false, 1);
        if (!m.specular_texname.empty()) {
            out.specular_map = texture(info, "map_Ks", "map_Ks", m.specular_texname, false, 1);
            if (!m.specular_highlight_texname.empty())
                model.warnings.push_back(info.file + ":" + std::to_string(line_of(info, "map_Ns")) +
                                         ": map_Ns ignored: map_Ks already gives " + quote(m.name) + " a specular map");
        } else if (!m.specular_highlight_texname.empty()) {
            // Some exported models give their specular map as map_Ns, as WebGL2
            // Fundamentals reads it: a specular colour map, not a shininess map.
            out.specular_map = texture(info, "map_Ns (read as a specular map)", "map_Ns",
                                       m.specular_highlight_texname, false, 1);
        }
        if (out.specular_map >= 0 && out.specular == glm::vec3(0)) {
            out.specular = glm::vec3(1);
            model.warnings.push_back(where + ": material " + quote(m.name) +
                                     " has a specular map and Ks 0: Ks taken as 1 so the map gives the specular colour");
        }
        if (!m.normal_texname.empty()) {
            out.normal_map = texture(info, "norm", "norm", m.normal_texname, true, m.normal_texopt.bump_multiplier);
            if (!m.bump_texname.empty())
                model.warnings.push_back(info.file + ":" + std::to_string(line_of(info, "bump")) +
                                         ": bump map ignored: norm already gives " + quote(m.name) + " a normal map");
        } else if (!m.bump_texname.empty()) {
            out.normal_map = texture(info, "map_bump", "bump", m.bump_texname, true, m.bump_texopt.bump_multiplier);
        }
        model.materials.push_back(out);
    }
}

}  // namespace

ObjModel load_obj(const string& path, const ObjOptions& options) {
    string text = options.read_text ? options.read_text(path) : read_regular_file(path, "OBJ file");
    ObjModel model = parse_obj(path, std::move(text), options);
    model.inputs.insert(model.inputs.begin(), path);
    return model;
}

ObjModel parse_obj(const string& path, string text, const ObjOptions& options) {
    ObjModel model;
    model.path = path;
    const fs::path dir = fs::path(path).parent_path();
    const string obj_name = fs::path(path).filename().string();
    auto read_text = [&](const string& p, const string& what) {
        return options.read_text ? options.read_text(p) : read_regular_file(p, what);
    };

    // 1. Check the OBJ, then every MTL it names, line by line (text from a hook too).
    check_user_text(path, text);
    ObjCheck check = check_obj(path, text, model.warnings, options.max_triangles, options.budget_note);
    std::map<string, MtlFile> mtls;  // keyed by the name in mtllib
    std::map<string, MtlMaterialInfo> mtl_info;
    for (const auto& [name, line] : check.mtllibs) {
        if (mtls.count(name)) continue;
        fs::path p(name);
        if (p.is_relative()) p = dir / p;
        MtlFile f;
        f.path = p.lexically_normal().string();
        try {
            f.text = read_text(f.path, "MTL file");
        } catch (const Error& e) {
            throw Error(path + ":" + std::to_string(line) + ": expected a readable MTL file for mtllib, got " +
                        quote(name) + ": " + e.what());
        }
        check_user_text(f.path, f.text);
        model.inputs.push_back(f.path);
        check_mtl(f, mtl_info, model.warnings);
        for (auto& [mname, info] : mtl_info)
            if (info.mtllib_line == 0) info.mtllib_line = line;
        mtls.emplace(name, std::move(f));
    }
    for (const auto& [name, line] : check.usemtls) {
        auto it = mtl_info.find(name);
        // tinyobjloader looks a name up when it reads usemtl: the mtllib must come first.
        if (it == mtl_info.end() || it->second.mtllib_line > line)
            throw Error(path + ":" + std::to_string(line) + ": expected a material defined in an MTL file named by an " +
                        "mtllib line before this one, got " + quote(name) +
                        (it == mtl_info.end() ? string() : " (its mtllib is on line " + std::to_string(it->second.mtllib_line) + ")"));
    }
    if (check.faces == 0) throw Error(path + ": expected at least one face (f line), got none: an empty mesh");

    // 2. Parse with tinyobjloader (triangulating).
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> mats;
    string warn, err;
    CheckedMtlReader reader(mtls);
    bool ok;
    {
        MemBuf buf(text.data(), text.size());
        std::istream in(&buf);
        ok = tinyobj::LoadObj(&attrib, &shapes, &mats, &warn, &err, &in, &reader, true, false);
    }
    string().swap(text);
    if (!ok || !err.empty()) throw Error(path + ": tinyobjloader: " + (err.empty() ? string("failed") : err));
    if (attrib.vertices.size() != 3 * check.v || attrib.texcoords.size() != 2 * check.vt ||
        attrib.normals.size() != 3 * check.vn)
        throw Error(path + ": tinyobjloader read " + std::to_string(attrib.vertices.size() / 3) + " vertices, " +
                    std::to_string(attrib.texcoords.size() / 2) + " uvs, " + std::to_string(attrib.normals.size() / 3) +
                    " normals; expected " + std::to_string(check.v) + ", " + std::to_string(check.vt) + ", " +
                    std::to_string(check.vn));

    // 3. Materials and their maps.
    add_materials(path, obj_name, mats, mtl_info, options, model);

    // 4. Triangles: corners checked against what tinyobjloader read, face normals in double.
    obj::Triangles tris = obj::collect_triangles(path, obj_name, attrib, shapes, model);

    // 5. Normals: a file normal where the corner has a usable one; otherwise smoothing clusters
    // per position: greedy, each face joins the first cluster whose seed normal is within the
    // angle (or, past kMaxClusters, the nearest), so the work is linear in the corners.
    const obj::Normals normals = obj::smooth_normals(path, attrib, options.smooth_angle_deg, tris, model.warnings);

    // 6. Group by material (Listing 9) and share vertices by hash of their corner key.
    obj::group_by_material(attrib, tris, normals, model);
    if (!warn.empty()) {
        // tinyobjloader's own warnings, after the checks above: worth passing on, one line each.
        size_t b = 0;
        while (b < warn.size()) {
            size_t e = warn.find('\n', b);
            if (e == string::npos) e = warn.size();
            if (e > b) model.warnings.push_back(path + ": tinyobjloader: " + warn.substr(b, e - b));
            b = e + 1;
        }
    }
    return model;
}

}  // namespace dsr
