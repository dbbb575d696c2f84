// The OBJ line check for the OBJ loader (obj_check.h): every statement, with its line number,
// against what tinyobjloader will make of it.
#include "scene/obj_check.h"

#include <algorithm>
#include <map>
#include <set>

#include "scene/obj_loader.h"

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

namespace {

// "\ " as a space, nothing split.
string unescape_spaces(string_view s) {
    string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == ' ') { out += ' '; ++i; }
        else out += s[i];
    }
    return out;
}

}  // namespace

ObjCheck check_obj(const string& path, string& text, Notes& notes, size_t max_triangles, const string& budget_note) {
    ObjCheck c;
    LineScanner s(path, text);
    static const std::set<string> free_form = {"vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
                                               "parm", "trim", "hole", "scrv", "sp", "end", "con", "mg",
                                               "ctech", "stech", "bevel", "c_interp", "d_interp", "lod",
                                               "usemap", "maplib", "shadow_obj", "trace_obj"};
    // Statements dsr does not know: one warning per keyword, up to kMaxUnknownKinds keywords.
    const size_t kMaxUnknownKinds = 16;
    std::set<string> unknown;
    std::map<string, int> slot_of;  // usemtl name -> slot
    int slot = -1;
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
            bool outside = false;
            for (size_t i = 1; i < t.size(); ++i) {
                const double d = s.number(i, i <= 3 ? "a vertex coordinate" : "a vertex colour");
                if (i >= 4 && i <= 6 && t.size() >= 7 && !(d >= 0 && d <= 1)) outside = true;
            }
            if (t.size() >= 7) {
                if (c.coloured.empty()) c.coloured.assign(c.v, 0);
                c.coloured.push_back(1);
                if (outside) notes.add(path, s.number(), "colour range", "vertex colours outside 0..1: clamped");
            } else if (!c.coloured.empty()) {
                c.coloured.push_back(0);
            }
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
            c.triangles += corners - 2;
            if (c.triangles > std::min(max_triangles, kMaxObjElements)) {
                if (budget_note.empty() || max_triangles >= kMaxObjElements) too_many("triangles");
                s.fail("more than " + std::to_string(max_triangles) + " triangles (" + budget_note + ")");
            }
            if (c.material_runs.empty() || c.material_runs.back().second != slot) c.material_runs.push_back({c.faces, slot});
            c.face_line.push_back(uint32_t(s.number()));
            if (corners > 255) c.large_faces.push_back({c.faces, corners});
            c.corners += corners;
            ++c.faces;
        } else {
            // Everything below is read here, never by tinyobjloader.
            if (k == "o" || k == "g" || k == "s") {
                // names and smoothing groups: nothing to check (smoothing comes from the angle)
            } else if (k == "mtllib") {
                ObjCheck::Mtllib m;
                m.line = s.number();
                string rest(s.rest_after_keyword());
                m.names = split_escaped(rest);
                m.whole = unescape_spaces(rest);
                bool slashes = backslashes_to_slashes(m.whole);
                for (string& n : m.names) slashes = backslashes_to_slashes(n) || slashes;
                if (slashes)
                    notes.add(path, s.number(), "backslash", "'\\' in the file name " + quote(rest) + " read as '/'");
                if (m.names.empty()) notes.add(path, s.number(), "mtllib empty", "mtllib without a file name: ignored");
                else c.mtllibs.push_back(std::move(m));
            } else if (k == "usemtl") {
                const string name(s.rest_after_keyword());
                auto [it, fresh] = slot_of.try_emplace(name, int(c.usemtl_names.size()));
                if (fresh) {
                    c.usemtl_names.push_back(name);
                    c.usemtl_lines.push_back(s.number());
                    c.usemtl_count.push_back(0);
                }
                ++c.usemtl_count[size_t(it->second)];
                slot = it->second;
            } else if (k == "l" || k == "p") {
                ++c.points_and_lines;
                notes.add(path, s.number(), string(k), quote(k) + " ignored (dsr draws faces only)");
            } else if (free_form.count(string(k))) {
                notes.add(path, s.number(), string(k), quote(k) + " ignored (free-form geometry is not supported)");
            } else if (unknown.size() < kMaxUnknownKinds || unknown.count(string(k))) {
                unknown.insert(string(k));
                notes.add(path, s.number(), string(k),
                          quote(k) + " is not an OBJ statement dsr knows (v, vt, vn, f, o, g, s, mtllib, usemtl): ignored");
            } else {
                notes.add(path, s.number(), " more", "more statements dsr does not know: ignored");
            }
            s.blank();
        }
    }
    return c;
}

}  // namespace dsr::obj
