// The MTL line check for the OBJ loader (mtl_check.h): every statement against what
// tinyobjloader will make of it.
#include "scene/mtl_check.h"

#include <algorithm>
#include <cstring>
#include <set>

namespace dsr::obj {

using std::string;

int line_of(const MtlMaterialInfo& info, const string& key) {
    auto it = info.lines.find(key);
    return it == info.lines.end() ? info.line : it->second;
}

string check_mtl(const string& path, string& text, MtlMaterials& all, Notes& notes) {
    LineScanner s(path, text);
    static const std::set<string> ignored = {
        "Ka", "Ke", "Tf", "Ni", "illum", "map_Ka", "map_Ke", "disp", "decal", "refl", "sharpness",
        "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "map_Pr", "map_Pm", "map_Ps", "map_aat"};
    static const std::set<string> maps = {"map_Kd", "map_Ks", "map_Ns", "map_bump", "map_Bump", "bump", "norm", "map_d"};
    const size_t kMaxUnknownKinds = 16;
    std::set<string> unknown;
    string tiny;
    MtlMaterialInfo* current = nullptr;
    while (s.next()) {
        const auto& t = s.tokens();
        if (t.empty()) continue;
        const string k(t[0]);
        if (k == "newmtl") {
            const string name(s.rest_after_keyword());
            auto it = all.by_name.find(name);
            if (it != all.by_name.end()) {
                const MtlMaterialInfo& first = all.materials[it->second];
                s.fail("expected a material name not defined before, got " + quote(name) + " (first defined at " +
                       first.file + ":" + std::to_string(first.line) + ")");
            }
            all.by_name[name] = all.materials.size();
            tiny += "newmtl m" + std::to_string(all.materials.size()) + "\n";
            all.materials.emplace_back();
            current = &all.materials.back();
            current->name = name;
            current->file = path;
            current->line = s.number();
            continue;
        }
        const bool is_ignored = ignored.count(k) > 0, is_map = maps.count(k) > 0;
        if (!is_ignored && !is_map && k != "Kd" && k != "Ks" && k != "Ns" && k != "d" && k != "Tr") {
            // Not a statement dsr knows: a warning per keyword, never given to tinyobjloader.
            if (unknown.size() < kMaxUnknownKinds || unknown.count(k)) {
                unknown.insert(k);
                notes.add(path, s.number(), k, quote(k) + " is not an MTL statement dsr knows: ignored");
            } else {
                notes.add(path, s.number(), " more", "more statements dsr does not know: ignored");
            }
            continue;
        }
        if (!current) s.fail("expected newmtl before " + quote(k));
        current->lines[k] = s.number();
        string line(s.line());
        if (k == "Kd" || k == "Ks" || k == "Ka" || k == "Ke" || k == "Tf") {
            // r g b, or one number for all three (the MTL format's rule).
            if (t.size() != 4 && t.size() != 2) s.expected("three numbers r g b (or one) for " + k, std::min<size_t>(t.size(), 4));
            for (size_t i = 1; i < t.size(); ++i)
                if (s.number(i, k) < 0) s.expected(k + " components >= 0", i);
            if (t.size() == 2) line = k + " " + string(t[1]) + " " + string(t[1]) + " " + string(t[1]);
        } else if (k == "Ns" || k == "Ni" || k == "d" || k == "Tr" || k == "illum" || k == "sharpness" || k == "Pr" ||
                   k == "Pm" || k == "Ps" || k == "Pc" || k == "Pcr" || k == "aniso" || k == "anisor") {
            if (t.size() != 2) s.expected("one number for " + k, std::min<size_t>(t.size(), 2));
            const double v = s.number(1, k);
            if (k == "Ns" && v < 0) s.expected("Ns >= 0", 1);
            if ((k == "d" || k == "Tr") && !(v >= 0 && v <= 1)) s.expected(k + " in [0, 1]", 1);
        } else {
            // A map: options, then the file name (the rest of the line, as tinyobjloader reads it).
            size_t i = 1;
            auto count_numbers = [&](const string& opt, size_t n) {
                for (size_t j = 0; j < n; ++j) s.number(i + 1 + j, k + " " + opt);
                i += 1 + n;
            };
            while (i < t.size() && t[i].size() > 1 && t[i][0] == '-') {
                const string o(t[i]);
                if (o == "-bm" || o == "-boost" || o == "-texres") count_numbers(o, 1);
                else if (o == "-mm") count_numbers(o, 2);
                else if (o == "-o" || o == "-s" || o == "-t") count_numbers(o, 3);
                else if (o == "-blendu" || o == "-blendv" || o == "-clamp") {
                    if (i + 1 >= t.size() || (t[i + 1] != "on" && t[i + 1] != "off")) s.expected("on or off after " + o, i + 1);
                    i += 2;
                } else if (o == "-imfchan") {
                    if (i + 1 >= t.size() || t[i + 1].size() != 1 || !std::strchr("rgbmlz", t[i + 1][0]))
                        s.expected("one of r g b m l z after -imfchan", i + 1);
                    i += 2;
                } else if (o == "-type" || o == "-colorspace") {
                    if (i + 1 >= t.size()) s.expected("a value after " + o, i + 1);
                    i += 2;
                } else {
                    s.expected("a texture option (-bm, -blendu, -blendv, -boost, -clamp, -imfchan, -mm, -o, -s, -t, "
                               "-texres, -type) or a file name",
                               i);
                }
            }
            if (i >= t.size()) s.expected("a texture file name for " + k, i);
            if (k == "bump" || k == "map_bump" || k == "map_Bump") current->lines["bump"] = s.number();
            if (is_map && backslashes_to_slashes(line))
                notes.add(path, s.number(), "backslash",
                          "'\\' in the file name " + quote(s.rest_after_keyword()) + " read as '/'");
        }
        if (is_ignored) notes.add(path, s.number(), k, quote(k) + " ignored (dsr does not use it)");
        else tiny += line + "\n";
    }
    return tiny;
}

}  // namespace dsr::obj
