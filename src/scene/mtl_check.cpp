// The MTL line check for the OBJ loader (mtl_check.h): every statement against what
// tinyobjloader will make of it.
#include "scene/mtl_check.h"

#include <algorithm>
#include <cstring>
#include <set>

#include "scene/obj_text.h"

namespace dsr::obj {

using std::string;

int line_of(const MtlMaterialInfo& info, const string& key) {
    auto it = info.lines.find(key);
    return it == info.lines.end() ? info.line : it->second;
}

void check_mtl(MtlFile& mtl, std::map<string, MtlMaterialInfo>& info, std::vector<string>& warnings) {
    LineScanner s(mtl.path, mtl.text);
    static const std::set<string> ignored = {
        "Ka", "Ke", "Tf", "Ni", "illum", "map_Ka", "map_d", "map_Ke", "disp", "decal", "refl", "sharpness",
        "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "map_Pr", "map_Pm", "map_Ps", "map_aat"};
    static const std::set<string> maps = {"map_Kd", "map_Ks", "map_Ns", "map_bump", "map_Bump", "bump", "norm"};
    const string known =
        "an MTL statement (newmtl, Kd, Ks, Ns, d, Tr, map_Kd, map_Ks, map_Ns, map_bump, bump, norm; "
        "Ka, Ke, Ni, illum, Tf, map_Ka, map_d, disp, refl are read and ignored)";
    Ignored skipped;
    MtlMaterialInfo* current = nullptr;
    while (s.next()) {
        const auto& t = s.tokens();
        if (t.empty()) continue;
        const string k(t[0]);
        if (k == "newmtl") {
            if (t.size() != 2) s.expected("one material name (no spaces) after newmtl", t.size() < 2 ? 1 : 2);
            const string name(t[1]);
            auto it = info.find(name);
            if (it != info.end())
                s.fail("expected a material name not defined before, got " + quote(name) + " (first defined at " +
                       it->second.file + ":" + std::to_string(it->second.line) + ")");
            current = &info[name];
            current->file = mtl.path;
            current->line = s.number();
            continue;
        }
        const bool is_ignored = ignored.count(k) > 0;
        if (!is_ignored && !maps.count(k) && k != "Kd" && k != "Ks" && k != "Ns" && k != "d" && k != "Tr")
            s.expected(known, 0);
        if (!current) s.fail("expected newmtl before " + quote(k));
        current->lines[k] = s.number();
        if (k == "Kd" || k == "Ks" || k == "Ka" || k == "Ke" || k == "Tf") {
            if (t.size() != 4) s.expected("three numbers r g b for " + k, std::min<size_t>(t.size(), 4));
            for (size_t i = 1; i < 4; ++i)
                if (s.number(i, k) < 0) s.expected(k + " components >= 0", i);
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
        }
        if (is_ignored) skipped.add(k, s.number());
    }
    skipped.report(mtl.path, "dsr does not use it", warnings);
}

}  // namespace dsr::obj
