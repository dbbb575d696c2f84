// OBJ/MTL loading (obj_loader.h). tinyobjloader does the parsing of numbers and faces and of the
// MTL statements dsr reads; it is lenient (a bad number reads as 0, an unknown material as none,
// an out-of-range index is kept or silently dropped), so every OBJ and MTL line is first checked
// here, with its line number, and tinyobjloader is handed only text it reads as checked: the
// OBJ's v, vt, vn and f lines (the rest blanked in place), and MTL text rewritten by the check
// (mtl_check.h). What tinyobjloader returns is then checked again (sizes, indices) before it is
// used, so a disagreement is an error and never a wrong image. Materials, names and the
// statements dsr skips are read by the checks; faces are triangulated by obj_geometry.
// The line checks are mtl_check / obj_check (over obj_text's scanner), the geometry after
// tinyobjloader is obj_geometry; this file is the glue: files, tinyobjloader, materials.
#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <istream>
#include <map>
#include <set>

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
using obj::dquote;
using obj::line_of;
using obj::MemBuf;
using obj::MtlMaterialInfo;
using obj::MtlMaterials;
using obj::Notes;
using obj::quote;

const char* const kDefaultMaterial = "the default material (grey diffuse 0.8, no specular)";

// Step 3 of parse_obj: materials and their maps, appended to model.materials and model.textures.
// Each file is read once; a greyscale normal map is converted once per -bm value; a map_d is
// baked into the alpha of the diffuse map (or of a white one).
void add_materials(const std::vector<tinyobj::material_t>& mats, const MtlMaterials& all, const string& obj_name,
                   const ObjOptions& options, ObjModel& model, Notes& notes) {
    std::map<string, int> texture_index;  // texture_paths entry -> model.textures
    std::map<string, Image> side;          // images read and not (yet) a texture of the model
    std::map<string, string> failed;       // resolved path -> why it cannot be read
    size_t texels = 0;                     // of model.textures, against options.max_texels
    auto left = [&] { return options.max_texels > texels ? options.max_texels - texels : 0; };
    auto over_budget = [&](const string& where, const string& key, const string& name, size_t w, size_t h) {
        throw Error(where + ": expected textures within " +
                    (options.budget_note.empty() ? std::to_string(options.max_texels) + " texels" : options.budget_note) +
                    ", got " + key + " " + quote(name) + " of " + std::to_string(w * h) + " (" + std::to_string(w) +
                    " x " + std::to_string(h) + ") after " + std::to_string(texels));
    };
    auto where_of = [](const MtlMaterialInfo& info, const string& line_key) {
        return info.file + ":" + std::to_string(line_of(info, line_key));
    };
    // Reads the map's image once per file into `side` (or finds it); false, with a warning, when
    // it cannot be read. Over the texel budget or of an absurd size is an error.
    auto fetch = [&](const MtlMaterialInfo& info, const string& key, const string& line_key, string& name,
                     string& resolved) -> bool {
        while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
        fs::path p(name);
        if (p.is_relative()) p = fs::path(info.file).parent_path() / p;
        resolved = p.lexically_normal().string();
        if (texture_index.count(resolved) || side.count(resolved)) return true;
        auto f = failed.find(resolved);
        string why;
        if (f == failed.end()) {
            const string where = where_of(info, line_key);
            Image img;
            try {
                img = options.read_image ? options.read_image(resolved) : obj::read_regular_image(resolved, left());
            } catch (const ImageTooLarge& e) {
                over_budget(where, key, name, size_t(e.width), size_t(e.height));
            } catch (const Error& e) {
                const string said = e.what();
                // A header claiming an absurd size is refused, as every file over dsr's limits is.
                if (said.find("(an absurd size)") != string::npos)
                    throw Error(where + ": expected a readable image for " + key + ", got " + quote(name) + ": " + said);
                why = said;
            }
            if (why.empty()) {
                model.inputs.push_back(resolved);
                if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * size_t(img.height) * 4)
                    why = "no pixels";
                else if (!std::all_of(img.rgba.begin(), img.rgba.end(), [](float v) { return std::isfinite(v); }))
                    why = "texel values that are not finite";
            }
            if (why.empty()) {
                side.emplace(resolved, std::move(img));
                return true;
            }
            failed[resolved] = why;
        } else {
            why = f->second;
        }
        notes.add(info.file, line_of(info, line_key), "texture unreadable",
                  key + " " + quote(name) + " cannot be read (" + why + "): drawn without it");
        return false;
    };
    auto image_of = [&](const string& resolved) -> const Image& {
        auto it = texture_index.find(resolved);
        return it != texture_index.end() ? model.textures[size_t(it->second)] : side.at(resolved);
    };
    // Adds `img` to the model as `stored` (once), within the texel budget.
    auto add = [&](const string& where, const string& key, const string& name, Image img, const string& stored) {
        const size_t w = size_t(img.width), h = size_t(img.height);
        if (w * h > left()) over_budget(where, key, name, w, h);
        texels += w * h;
        model.textures.push_back(std::move(img));
        model.texture_paths.push_back(stored);
        texture_index[stored] = int(model.textures.size() - 1);
        return int(model.textures.size() - 1);
    };
    auto texture = [&](const MtlMaterialInfo& info, const string& key, const string& line_key, string name,
                       bool normal_map, double bm) -> int {
        string resolved;
        if (!fetch(info, key, line_key, name, resolved)) return -1;
        const string where = where_of(info, line_key);
        if (normal_map && is_greyscale(image_of(resolved))) {
            const string height_key = resolved + " (height map, bm " + std::to_string(bm) + ")";
            auto it = texture_index.find(height_key);
            if (it != texture_index.end()) return it->second;
            if (!std::isfinite(bm)) throw Error(where + ": expected a finite -bm for " + key);
            return add(where, key, name, height_to_normal(image_of(resolved), float(bm)), height_key);
        }
        auto it = texture_index.find(resolved);
        if (it != texture_index.end()) return it->second;
        Image img = std::move(side.at(resolved));
        side.erase(resolved);
        return add(where, key, name, std::move(img), resolved);
    };
    std::vector<signed char> has_cutout(0);  // per texture: some alpha below 0.5 (-1: not looked at)
    for (size_t i = 0; i < mats.size(); ++i) {
        const tinyobj::material_t& m = mats[i];
        const MtlMaterialInfo& info = all.materials[i];
        const string where = info.file + ":" + std::to_string(info.line);
        Material out;
        out.name = obj_name + ":" + info.name;
        out.diffuse = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        out.specular = {m.specular[0], m.specular[1], m.specular[2]};
        out.shininess = std::clamp(float(m.shininess), 1.0f, 2048.0f);
        out.opacity = std::clamp(float(m.dissolve), 0.0f, 1.0f);
        if (!m.diffuse_texname.empty())
            out.diffuse_map = texture(info, "map_Kd", "map_Kd", m.diffuse_texname, false, 1);
        if (!m.specular_texname.empty()) {
            out.specular_map = texture(info, "map_Ks", "map_Ks", m.specular_texname, false, 1);
            if (!m.specular_highlight_texname.empty())
                notes.add(info.file, line_of(info, "map_Ns"), "map_Ns and map_Ks",
                          "map_Ns ignored: map_Ks already gives " + quote(info.name) + " a specular map");
        } else if (!m.specular_highlight_texname.empty()) {
            // Some exported models give their specular map as map_Ns, as WebGL2
            // Fundamentals reads it: a specular colour map, not a shininess map.
            out.specular_map = texture(info, "map_Ns (read as a specular map)", "map_Ns",
                                       m.specular_highlight_texname, false, 1);
        }
        if (out.specular_map >= 0 && out.specular == glm::vec3(0)) {
            out.specular = glm::vec3(1);
            notes.add(info.file, info.line, "Ks 0 with a map",
                      "material " + quote(info.name) +
                          " has a specular map and Ks 0: Ks taken as 1 so the map gives the specular colour");
        }
        if (!m.normal_texname.empty()) {
            out.normal_map = texture(info, "norm", "norm", m.normal_texname, true, m.normal_texopt.bump_multiplier);
            if (!m.bump_texname.empty())
                notes.add(info.file, line_of(info, "bump"), "bump and norm",
                          "bump map ignored: norm already gives " + quote(info.name) + " a normal map");
        } else if (!m.bump_texname.empty()) {
            out.normal_map = texture(info, "map_bump", "bump", m.bump_texname, true, m.bump_texopt.bump_multiplier);
        }
        // Cut-out: map_d's coverage (its alpha where it has any below 1, else its red) becomes
        // the diffuse map's alpha, resampled (nearest texel) to the diffuse map's size.
        string d_name = m.alpha_texname, d_resolved;
        if (!d_name.empty() && fetch(info, "map_d", "map_d", d_name, d_resolved)) {
            const string base = out.diffuse_map >= 0 ? model.texture_paths[size_t(out.diffuse_map)] : string("white");
            const string stored = base + " (alpha from " + d_resolved + ")";
            auto it = texture_index.find(stored);
            if (it != texture_index.end()) {
                out.diffuse_map = it->second;
            } else {
                Image baked;
                const Image& d = image_of(d_resolved);
                if (out.diffuse_map >= 0) {
                    baked = model.textures[size_t(out.diffuse_map)];
                } else {
                    baked.width = d.width;
                    baked.height = d.height;
                    baked.rgba.assign(size_t(d.width) * size_t(d.height) * 4, 1.0f);
                }
                if (baked.width != d.width || baked.height != d.height)
                    notes.add(info.file, line_of(info, "map_d"), "map_d resampled",
                              "map_d " + quote(d_name) + " (" + std::to_string(d.width) + " x " + std::to_string(d.height) +
                                  ") resampled to its diffuse map's " + std::to_string(baked.width) + " x " +
                                  std::to_string(baked.height) + " (nearest texel)");
                bool alpha = false;
                for (size_t k = 3; k < d.rgba.size() && !alpha; k += 4) alpha = d.rgba[k] < 1.0f;
                for (int y = 0; y < baked.height; ++y)
                    for (int x = 0; x < baked.width; ++x) {
                        const int sx = std::min(d.width - 1, int((double(x) + 0.5) * d.width / baked.width));
                        const int sy = std::min(d.height - 1, int((double(y) + 0.5) * d.height / baked.height));
                        baked.at(x, y)[3] = std::clamp(d.at(sx, sy)[alpha ? 3 : 0], 0.0f, 1.0f);
                    }
                out.diffuse_map = add(where_of(info, "map_d"), "map_d", d_name, std::move(baked), stored);
            }
            out.alpha_cutoff = 0.5f;
        }
        // A diffuse map with alpha below 0.5 anywhere is a cut-out too.
        if (out.diffuse_map >= 0 && !out.cut_out()) {
            const size_t t = size_t(out.diffuse_map);
            if (has_cutout.size() <= t) has_cutout.resize(t + 1, -1);
            if (has_cutout[t] < 0) {
                const std::vector<float>& px = model.textures[t].rgba;
                has_cutout[t] = 0;
                for (size_t k = 3; k < px.size(); k += 4)
                    if (px[k] < 0.5f) {
                        has_cutout[t] = 1;
                        break;
                    }
            }
            if (has_cutout[t]) out.alpha_cutoff = 0.5f;
        }
        model.materials.push_back(out);
    }
}

}  // namespace

ObjModel load_obj(const string& path, const ObjOptions& options) {
    string text = options.read_text ? options.read_text(path) : obj::read_regular_file(path, "OBJ file");
    ObjModel model = parse_obj(path, std::move(text), options);
    model.inputs.insert(model.inputs.begin(), path);
    return model;
}

ObjModel parse_obj(const string& path, string text, const ObjOptions& options) {
    ObjModel model;
    model.path = path;
    const fs::path dir = fs::path(path).parent_path();
    const string obj_name = fs::path(path).filename().string();
    Notes notes;

    // 1. Check the OBJ, then every MTL it names, line by line (text from a hook too).
    obj::decode_text(path, text, model.warnings);
    const obj::ObjCheck check = obj::check_obj(path, text, notes, options.max_triangles, options.budget_note);
    if (check.faces == 0)
        throw Error(path + ": expected at least one face (f line), got none: " +
                    (check.points_and_lines ? "only points and lines (p, l), and dsr draws faces"
                                            : check.v ? "only vertices, and dsr draws faces" : std::string("an empty mesh")));
    MtlMaterials all;
    std::vector<std::pair<string, size_t>> mtl_texts;  // text for tinyobjloader, materials it defines
    std::set<string> read;                               // MTLs read or tried, as resolved
    for (const obj::ObjCheck::Mtllib& lib : check.mtllibs) {
        // The rest of the line names one file (spaces and all); failing that, each name is one.
        std::vector<string> tries = {lib.whole};
        if (lib.names.size() > 1) tries.insert(tries.end(), lib.names.begin(), lib.names.end());
        for (size_t k = 0; k < tries.size(); ++k) {
            const string& name = tries[k];
            fs::path p(name);
            if (p.is_relative()) p = dir / p;
            const string resolved = p.lexically_normal().string();
            if (!read.insert(resolved).second) {
                if (k == 0) break;
                continue;
            }
            string mtext;
            try {
                mtext = options.read_text ? options.read_text(resolved) : obj::read_regular_file(resolved, "MTL file");
            } catch (const obj::FileTooLarge& e) {
                throw Error(path + ":" + std::to_string(lib.line) + ": expected a readable MTL file for mtllib, got " +
                            quote(name) + ": " + e.what());
            } catch (const Error& e) {
                if (k == 0 && tries.size() > 1) continue;  // then each name on its own
                notes.add(path, lib.line, "mtllib unreadable",
                          "mtllib " + quote(name) + " cannot be read (" + e.what() + "): its materials are drawn with " +
                              kDefaultMaterial);
                continue;
            }
            model.inputs.push_back(resolved);
            obj::decode_text(resolved, mtext, model.warnings);
            const size_t before = all.materials.size();
            mtl_texts.push_back({obj::check_mtl(resolved, mtext, all, notes), all.materials.size() - before});
            if (k == 0) break;
        }
    }
    // Each usemtl name's material: one an MTL defines (wherever its mtllib line is), else the default.
    std::vector<int> slot_material(check.usemtl_names.size(), -1);
    for (size_t i = 0; i < check.usemtl_names.size(); ++i) {
        const string& name = check.usemtl_names[i];
        auto it = all.by_name.find(name);
        if (it != all.by_name.end()) slot_material[i] = int(it->second);
        else if (name.empty())
            notes.add(path, check.usemtl_lines[i], "usemtl empty",
                      string("usemtl without a material name: drawn with ") + kDefaultMaterial, check.usemtl_count[i]);
        else
            notes.add(path, check.usemtl_lines[i], "usemtl undefined",
                      "material " + dquote(name) + " is defined in no MTL file: drawn with " + kDefaultMaterial,
                      check.usemtl_count[i]);
    }

    // 2. Parse with tinyobjloader: the geometry (faces as they are: obj_geometry triangulates),
    // then each MTL's materials.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    string warn, err;
    bool ok;
    {
        std::vector<tinyobj::material_t> none;
        MemBuf buf(text.data(), text.size());
        std::istream in(&buf);
        ok = tinyobj::LoadObj(&attrib, &shapes, &none, &warn, &err, &in, nullptr, false, !check.coloured.empty());
    }
    string().swap(text);
    if (!ok || !err.empty()) throw Error(path + ": tinyobjloader: " + (err.empty() ? string("failed") : err));
    if (attrib.vertices.size() != 3 * check.v || attrib.texcoords.size() != 2 * check.vt ||
        attrib.normals.size() != 3 * check.vn ||
        (!check.coloured.empty() && (attrib.colors.size() != 3 * check.v || check.coloured.size() != check.v)))
        throw Error(path + ": tinyobjloader read " + std::to_string(attrib.vertices.size() / 3) + " vertices, " +
                    std::to_string(attrib.texcoords.size() / 2) + " uvs, " + std::to_string(attrib.normals.size() / 3) +
                    " normals; expected " + std::to_string(check.v) + ", " + std::to_string(check.vt) + ", " +
                    std::to_string(check.vn));
    std::vector<tinyobj::material_t> mats(all.materials.size());
    std::vector<char> seen(all.materials.size(), 0);
    for (const auto& [tiny, count] : mtl_texts) {
        std::vector<tinyobj::material_t> got;
        std::map<string, int> map;
        string mwarn, merr;
        MemBuf buf(tiny.data(), tiny.size());
        std::istream in(&buf);
        tinyobj::LoadMtl(&map, &got, &in, &mwarn, &merr);
        if (count == 0) continue;  // tinyobjloader returns one unnamed material for a file without any
        if (got.size() != count) throw Error(path + ": tinyobjloader read materials the MTL check did not count");
        for (tinyobj::material_t& m : got) {
            // Its name is "m" and the material's number (mtl_check.h).
            size_t k = 0;
            bool named = m.name.size() >= 2 && m.name.size() <= 12 && m.name[0] == 'm';
            for (size_t j = 1; named && j < m.name.size(); ++j) {
                named = m.name[j] >= '0' && m.name[j] <= '9';
                k = k * 10 + size_t(m.name[j] - '0');
            }
            if (!named || k >= mats.size() || seen[k])
                throw Error(path + ": tinyobjloader returned a material the MTL check did not name");
            seen[k] = 1;
            mats[k] = std::move(m);
        }
    }
    if (std::count(seen.begin(), seen.end(), 0)) throw Error(path + ": tinyobjloader left out a material of an MTL");

    // 3. Materials and their maps.
    add_materials(mats, all, obj_name, options, model, notes);

    // 4. Triangles: faces triangulated, corners checked against what tinyobjloader read, face
    // normals in double.
    obj::Triangles tris = obj::collect_triangles(path, obj_name, attrib, shapes, check, slot_material, model, notes);

    // 5. Normals: a file normal where the corner has a usable one; otherwise smoothing clusters
    // per position: greedy, each face joins the first cluster whose seed normal is within the
    // angle (or, past kMaxClusters, the nearest), so the work is linear in the corners.
    const obj::Normals normals = obj::smooth_normals(path, attrib, options.smooth_angle_deg, tris, check, notes);

    // 6. Group by material (Listing 9) and share vertices by hash of their corner key.
    obj::group_by_material(path, attrib, tris, normals, check, model, notes);
    notes.flush(model.warnings);
    if (!warn.empty()) {
        // tinyobjloader's own warnings, after the checks above: worth passing on, one line each.
        size_t b = 0;
        while (b < warn.size()) {
            size_t e = warn.find('\n', b);
            if (e == string::npos) e = warn.size();
            if (e > b) model.warnings.push_back(path + ": tinyobjloader: " + quote(warn.substr(b, e - b)));
            b = e + 1;
        }
    }
    return model;
}

}  // namespace dsr
