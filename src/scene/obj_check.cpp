// The OBJ line check for the OBJ loader (obj_check.h): every statement, with its line number,
// against what tinyobjloader will make of it.
#include "scene/obj_check.h"

#include <algorithm>
#include <set>

#include "scene/obj_loader.h"
#include "scene/obj_text.h"

namespace dsr::obj {

using std::string;
using std::string_view;

std::vector<string> split_escaped(string_view s) {
    std::vector<string> out;
    string cur;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == ' ') { cur += ' '; ++i; }
        else if (s[i] == ' ' || s[i] == '\t') { if (!cur.empty()) out.push_back(cur); cur.clear(); }
        else cur += s[i];
    }
    if (!cur.empty()) out.push_back(cur);
    return out;
}

ObjCheck check_obj(const string& path, string& text, std::vector<string>& warnings, size_t max_triangles,
                   const string& budget_note) {
    ObjCheck c;
    LineScanner s(path, text);
    Ignored skipped_lines, skipped_free;
    static const std::set<string> free_form = {"vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
                                               "parm", "trim", "hole", "scrv", "sp", "end", "con", "mg",
                                               "ctech", "stech", "bevel", "c_interp", "d_interp", "lod",
                                               "usemap", "maplib", "shadow_obj", "trace_obj"};
    const string known = "an OBJ statement (v, vt, vn, f, o, g, s, mtllib, usemtl; l, p and free-form ignored)";
    auto too_many = [&](const char* what) {
        s.fail(string("more than ") + std::to_string(kMaxObjElements) + " " + what + " (an absurd size)");
    };
    while (s.next()) {
        const auto& t = s.tokens();
        if (t.empty()) continue;
        const string_view k = t[0];
        if (k == "v") {
            if (t.size() != 4 && t.size() != 5 && t.size() != 7 && t.size() != 8)
                s.expected("3 coordinates x y z (optionally w, or r g b)", std::min<size_t>(t.size(), 4));
            for (size_t i = 1; i < t.size(); ++i) s.number(i, i <= 3 ? "a vertex coordinate" : "a vertex colour");
            if (++c.v > kMaxObjElements) too_many("vertices");
        } else if (k == "vt") {
            if (t.size() < 2 || t.size() > 4) s.expected("1 to 3 texture coordinates u [v [w]]", std::min<size_t>(t.size(), 4));
            for (size_t i = 1; i < t.size(); ++i) s.number(i, "a texture coordinate");
            if (++c.vt > kMaxObjElements) too_many("texture coordinates");
        } else if (k == "vn") {
            if (t.size() != 4) s.expected("3 normal components x y z", std::min<size_t>(t.size(), 4));
            for (size_t i = 1; i < 4; ++i) s.number(i, "a normal component");
            if (++c.vn > kMaxObjElements) too_many("normals");
        } else if (k == "f") {
            const size_t corners = t.size() - 1;
            if (corners < 3) s.expected("at least 3 corners for a face", t.size());
            if (corners > size_t(kMaxPolygonVertices))
                s.fail("expected a face of at most " + std::to_string(kMaxPolygonVertices) + " corners, got " +
                       std::to_string(corners) + " (an absurd size)");
            for (size_t i = 1; i < t.size(); ++i) {
                const string_view ref = t[i];
                string_view part[3];
                int parts = 0;
                size_t b = 0;
                for (size_t j = 0; j <= ref.size(); ++j) {
                    if (j == ref.size() || ref[j] == '/') {
                        if (parts == 3) s.expected("a corner v, v/t, v//n or v/t/n", i);
                        part[parts++] = ref.substr(b, j - b);
                        b = j + 1;
                    }
                }
                const bool ok = !part[0].empty() && (parts == 1 || (parts == 2 && !part[1].empty()) ||
                                                     (parts == 3 && !part[2].empty()));
                if (!ok) s.expected("a corner v, v/t, v//n or v/t/n", i);
                const char* names[3] = {"vertex", "texture coordinate", "normal"};
                const size_t counts[3] = {c.v, c.vt, c.vn};
                for (int p = 0; p < parts; ++p) {
                    if (part[p].empty()) continue;
                    const long idx = s.integer(part[p], string(names[p]) + " index");
                    const long n = long(counts[p]);
                    if (idx == 0) s.fail("expected a non-zero " + string(names[p]) + " index, got " + quote(ref));
                    if (idx > n || -idx > n)
                        s.fail(string(names[p]) + " index " + std::to_string(idx) + " in " + quote(ref) +
                               " out of range: expected 1.." + std::to_string(n) + " or -1..-" + std::to_string(n) +
                               " (" + std::to_string(n) + " defined before this line)");
                }
            }
            ++c.faces;
            c.triangles += corners - 2;
            if (c.triangles > std::min(max_triangles, kMaxObjElements)) {
                if (budget_note.empty() || max_triangles >= kMaxObjElements) too_many("triangles");
                s.fail("more than " + std::to_string(max_triangles) + " triangles (" + budget_note + ")");
            }
        } else if (k == "o" || k == "g" || k == "s") {
            // names and smoothing groups: nothing to check (smoothing comes from the angle)
        } else if (k == "mtllib") {
            const std::vector<string> names = split_escaped(s.rest_after_keyword());
            if (names.size() != 1) s.expected("one MTL file name after mtllib (\"\\ \" for a space)", names.empty() ? 1 : 2);
            c.mtllibs.push_back({names[0], s.number()});
        } else if (k == "usemtl") {
            if (t.size() != 2) s.expected("one material name (no spaces) after usemtl", t.size() < 2 ? 1 : 2);
            c.usemtls.push_back({string(t[1]), s.number()});
        } else if (k == "l" || k == "p") {
            skipped_lines.add(string(k), s.number());
        } else if (free_form.count(string(k))) {
            skipped_free.add(string(k), s.number());
        } else {
            s.expected(known, 0);
        }
    }
    skipped_lines.report(path, "dsr draws faces only", warnings);
    skipped_free.report(path, "free-form geometry is not supported", warnings);
    return c;
}

}  // namespace dsr::obj
