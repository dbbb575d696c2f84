// OBJ/MTL loading (obj_loader.h). tinyobjloader does the parsing and triangulation; it is
// lenient (a bad number reads as 0, an unknown material as none, an out-of-range index is kept
// or silently dropped), so every OBJ and MTL line is first checked here, with its line number,
// against what tinyobjloader will make of it. What tinyobjloader returns is then checked again
// (sizes, indices) before it is used, so a disagreement is an error and never a wrong image.
#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <map>
#include <set>
#include <streambuf>
#include <string_view>
#include <unordered_map>

#include "dsr_error.h"
#include "scene/tangents.h"

namespace dsr {

namespace {

namespace fs = std::filesystem;
using std::string;
using std::string_view;

string quote(string_view s) {
    const size_t max = 60;
    string out(s.substr(0, max));
    if (s.size() > max) out += "...";
    for (char& c : out)
        if ((unsigned char)c < 32 || (unsigned char)c == 127) c = '?';
    return "'" + out + "'";
}

// Reads a whole regular file; a directory, device, missing file or one over kMaxObjBytes is an
// error naming `what` (e.g. "OBJ file") and the path.
string read_regular_file(const string& path, const string& what) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) throw Error("cannot open " + what + " " + path + ": no such file");
    if (fs::is_directory(st)) throw Error("cannot open " + what + " " + path + ": expected a file, got a directory");
    if (!fs::is_regular_file(st)) throw Error("cannot open " + what + " " + path + ": expected a regular file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Error("cannot read " + what + " " + path + ": " + ec.message());
    if (size > kMaxObjBytes)
        throw Error("cannot read " + what + " " + path + ": " + std::to_string(size) + " bytes, expected at most " +
                    std::to_string(kMaxObjBytes));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + what + " " + path + ": " + std::strerror(errno));
    string text(size_t(size), '\0');
    in.read(text.data(), std::streamsize(size));
    if (in.gcount() != std::streamsize(size)) throw Error("cannot read " + what + " " + path + ": short read");
    return text;
}

Image read_regular_image(const string& path) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) throw Error("cannot read image " + path + ": no such file");
    if (fs::is_directory(st)) throw Error("cannot read image " + path + ": expected a file, got a directory");
    if (!fs::is_regular_file(st)) throw Error("cannot read image " + path + ": expected a regular file");
    return load_image(path);
}

// A read-only streambuf over a string, so tinyobjloader reads the checked text without a copy.
struct MemBuf : std::streambuf {
    MemBuf(const char* b, size_t n) {
        char* p = const_cast<char*>(b);
        setg(p, p, p + n);
    }
};

// ---- line scanning -------------------------------------------------------------------------

// Walks a text line by line. Comments ('#' to end of line) are blanked in place, so the parser
// that reads the text afterwards sees exactly the tokens checked here.
class LineScanner {
public:
    LineScanner(const string& file, string& text) : file_(file), text_(text) {}

    // Next line's tokens (separated by spaces and tabs); false at the end. A line ends at "\n",
    // "\r\n" or a lone "\r", as tinyobjloader's reader ends it.
    bool next() {
        if (pos_ >= text_.size()) return false;
        ++number_;
        size_t end = pos_;
        while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
        size_t after = end + 1;
        if (end < text_.size() && text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n') ++after;
        size_t stop = end;
        const void* nul = std::memchr(text_.data() + pos_, '\0', end - pos_);
        if (nul) fail("expected text, got a NUL byte");
        const void* hash = std::memchr(text_.data() + pos_, '#', end - pos_);
        if (hash) {
            stop = size_t(static_cast<const char*>(hash) - text_.data());
            std::fill(text_.begin() + long(stop), text_.begin() + long(end), ' ');
        }
        tokens_.clear();
        size_t i = pos_;
        while (i < stop) {
            while (i < stop && is_space(text_[i])) ++i;
            const size_t b = i;
            while (i < stop && !is_space(text_[i])) ++i;
            if (i > b) tokens_.emplace_back(text_.data() + b, i - b);
        }
        line_begin_ = pos_;
        line_end_ = stop;
        pos_ = after;
        return true;
    }

    const std::vector<string_view>& tokens() const { return tokens_; }
    int number() const { return number_; }
    string where() const { return file_ + ":" + std::to_string(number_); }
    // The line after its first token, trimmed (file names may hold spaces).
    string_view rest_after_keyword() const {
        string_view line(text_.data() + line_begin_, line_end_ - line_begin_);
        size_t i = 0;
        while (i < line.size() && is_space(line[i])) ++i;
        while (i < line.size() && !is_space(line[i])) ++i;
        while (i < line.size() && is_space(line[i])) ++i;
        size_t e = line.size();
        while (e > i && is_space(line[e - 1])) --e;
        return line.substr(i, e - i);
    }

    [[noreturn]] void fail(const string& problem) const { throw Error(where() + ": " + problem); }
    [[noreturn]] void expected(const string& what, size_t token) const {
        if (token < tokens_.size()) fail("expected " + what + ", got " + quote(tokens_[token]));
        fail("expected " + what + ", got end of line");
    }

    // Token `i` as a finite number within kMaxObjCoordinate. Only the characters both strtod
    // and tinyobjloader read the same way are accepted (no hex, no "nan"/"inf").
    double number(size_t i, const string& subject) const {
        if (i >= tokens_.size()) expected("a number for " + subject, i);
        const string_view t = tokens_[i];
        bool digit = false;
        for (char c : t) {
            if (c >= '0' && c <= '9') digit = true;
            else if (!(c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E')) expected("a number for " + subject, i);
        }
        if (!digit || t.size() > 64) expected("a number for " + subject, i);
        char buf[80];
        std::memcpy(buf, t.data(), t.size());
        buf[t.size()] = '\0';
        char* end = nullptr;
        const double d = std::strtod(buf, &end);
        if (end != buf + t.size()) expected("a number for " + subject, i);
        if (!std::isfinite(d)) expected("a finite number for " + subject, i);
        if (std::fabs(d) > kMaxObjCoordinate)
            fail("expected " + subject + " within +-1e12, got " + quote(t) + " (an absurd size)");
        return d;
    }

    // Token `i` as a (possibly negative) integer; empty tokens are not integers.
    long integer(string_view t, const string& subject) const {
        bool digit = false;
        for (size_t k = 0; k < t.size(); ++k) {
            const char c = t[k];
            if (c >= '0' && c <= '9') digit = true;
            else if (!(k == 0 && (c == '-' || c == '+'))) fail("expected an integer " + subject + ", got " + quote(t));
        }
        if (!digit || t.size() > 18) fail("expected an integer " + subject + " of at most 18 digits, got " + quote(t));
        return std::strtol(string(t).c_str(), nullptr, 10);
    }

    // tinyobjloader's separators; anything else is part of a token.
    static bool is_space(char c) { return c == ' ' || c == '\t'; }

private:
    const string& file_;
    string& text_;
    size_t pos_ = 0, line_begin_ = 0, line_end_ = 0;
    int number_ = 0;
    std::vector<string_view> tokens_;
};

// "first line and count" of statements that are skipped, for one warning per keyword.
struct Ignored {
    std::map<string, std::pair<int, int>> seen;  // keyword -> (first line, count)
    void add(const string& k, int line) {
        auto it = seen.find(k);
        if (it == seen.end()) seen[k] = {line, 1};
        else ++it->second.second;
    }
    void report(const string& file, const string& why, std::vector<string>& warnings) const {
        for (const auto& [k, v] : seen)
            warnings.push_back(file + ":" + std::to_string(v.first) + ": '" + k + "' ignored (" + why + "; " +
                               std::to_string(v.second) + (v.second == 1 ? " line)" : " lines)"));
    }
};

// ---- MTL check ------------------------------------------------------------------------------

struct MtlMaterialInfo {
    string file;  // the MTL, as resolved
    int line = 0;  // newmtl
    std::map<string, int> lines;  // statement -> line (last one)
    int mtllib_line = 0;  // the OBJ's mtllib line that read this MTL
};

int line_of(const MtlMaterialInfo& info, const string& key) {
    auto it = info.lines.find(key);
    return it == info.lines.end() ? info.line : it->second;
}

struct MtlFile {
    string path, text;  // text with comments blanked
};

// Checks one MTL text line by line; records each material's lines.
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

// ---- OBJ check ------------------------------------------------------------------------------

struct ObjCheck {
    size_t v = 0, vt = 0, vn = 0, faces = 0, triangles = 0;
    std::vector<std::pair<string, int>> mtllibs;  // name as written (unescaped), line
    std::vector<std::pair<string, int>> usemtls;  // name, line
};

// One mtllib argument as tinyobjloader splits it: on spaces, with "\ " an escaped space.
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

ObjCheck check_obj(const string& path, string& text, std::vector<string>& warnings) {
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
            if (c.triangles > kMaxObjElements) too_many("triangles");
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

// ---- geometry -------------------------------------------------------------------------------

struct Corner {
    int v, vt, vn;  // vn < 0: computed (then `cluster` names the smoothing cluster)
};

// Open-addressing table from a corner key to its vertex index: linear in the corners.
class CornerTable {
public:
    explicit CornerTable(size_t expected) {
        size_t cap = 16;
        while (cap < expected * 2) cap *= 2;
        keys_.assign(cap, Key{-1, 0, 0});
        values_.resize(cap);
        mask_ = cap - 1;
    }
    // Index for the key, inserting `next` when new; sets `inserted`.
    uint32_t find_or_add(int a, int b, int c, uint32_t next, bool& inserted) {
        size_t h = (size_t(uint32_t(a)) * 0x9E3779B97F4A7C15ull) ^ (size_t(uint32_t(b)) * 0xC2B2AE3D27D4EB4Full) ^
                   (size_t(uint32_t(c)) * 0x165667B19E3779F9ull);
        h ^= h >> 29;
        for (size_t i = h & mask_;; i = (i + 1) & mask_) {
            Key& k = keys_[i];
            if (k.a == -1) {
                k = Key{a, b, c};
                values_[i] = next;
                inserted = true;
                return next;
            }
            if (k.a == a && k.b == b && k.c == c) {
                inserted = false;
                return values_[i];
            }
        }
    }

private:
    struct Key { int a, b, c; };
    std::vector<Key> keys_;
    std::vector<uint32_t> values_;
    size_t mask_ = 0;
};

glm::dvec3 vec_at(const std::vector<tinyobj::real_t>& a, size_t i) {
    return {double(a[3 * i]), double(a[3 * i + 1]), double(a[3 * i + 2])};
}

}  // namespace

bool is_greyscale(const Image& img) {
    const float tol = 2.0f / 255.0f;
    for (size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
        const float r = img.rgba[i], g = img.rgba[i + 1], b = img.rgba[i + 2];
        if (std::fabs(r - g) > tol || std::fabs(g - b) > tol) return false;
    }
    return true;
}

Image height_to_normal(const Image& height, float strength) {
    Image out;
    out.width = height.width;
    out.height = height.height;
    out.rgba.resize(height.rgba.size());
    const int w = height.width, h = height.height;
    auto hgt = [&](int x, int y) { return double(height.at((x + w) % w, (y + h) % h)[0]); };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = (hgt(x + 1, y) - hgt(x - 1, y)) * 0.5, dy = (hgt(x, y + 1) - hgt(x, y - 1)) * 0.5;
            glm::dvec3 n(-double(strength) * dx, -double(strength) * dy, 1.0);
            n /= std::sqrt(glm::dot(n, n));
            float* d = out.at(x, y);
            d[0] = float(n.x * 0.5 + 0.5);
            d[1] = float(n.y * 0.5 + 0.5);
            d[2] = float(n.z * 0.5 + 0.5);
            d[3] = 1.0f;
        }
    return out;
}

ObjModel load_obj(const string& path, const ObjOptions& options) {
    string text = options.read_text ? options.read_text(path) : read_regular_file(path, "OBJ file");
    return parse_obj(path, std::move(text), options);
}

ObjModel parse_obj(const string& path, string text, const ObjOptions& options) {
    ObjModel model;
    model.path = path;
    const fs::path dir = fs::path(path).parent_path();
    const string obj_name = fs::path(path).filename().string();
    auto read_text = [&](const string& p, const string& what) {
        return options.read_text ? options.read_text(p) : read_regular_file(p, what);
    };

    // 1. Check the OBJ, then every MTL it names, line by line.
    ObjCheck check = check_obj(path, text, model.warnings);
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
    // Each file is read once; a greyscale normal map is converted once per -bm value.
    std::map<string, int> texture_index;  // texture_paths entry -> model.textures
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
        if (it != texture_index.end()) {
            img = model.textures[size_t(it->second)];  // a greyscale map used as colour and as height
        } else {
            try {
                img = options.read_image ? options.read_image(resolved) : read_regular_image(resolved);
            } catch (const Error& e) {
                throw Error(where + ": expected a readable image for " + key + ", got " + quote(name) + ": " + e.what());
            }
            if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * size_t(img.height) * 4)
                throw Error(where + ": expected a readable image for " + key + ", got " + quote(name) + ": no pixels");
            for (float f : img.rgba)
                if (!std::isfinite(f)) throw Error(where + ": expected finite texel values in " + quote(name) + " for " + key);
        }
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
            // The windmill (../shared/assets) gives its specular map as map_Ns, as WebGL2
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

    // 4. Triangles: corners checked against what tinyobjloader read, face normals in double.
    const size_t nv = check.v, nvt = check.vt, nvn = check.vn;
    size_t ntri = 0;
    for (const tinyobj::shape_t& sh : shapes) ntri += sh.mesh.num_face_vertices.size();
    std::vector<Corner> corners;
    std::vector<int> tri_material;
    std::vector<glm::dvec3> face_n;
    corners.reserve(ntri * 3);
    tri_material.reserve(ntri);
    face_n.reserve(ntri);
    size_t degenerate = 0;
    bool default_material = false;
    for (const tinyobj::shape_t& sh : shapes) {
        const auto& mesh = sh.mesh;
        if (mesh.indices.size() != 3 * mesh.num_face_vertices.size() || mesh.material_ids.size() != mesh.num_face_vertices.size())
            throw Error(path + ": tinyobjloader returned faces that are not triangles");
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            if (mesh.num_face_vertices[f] != 3) throw Error(path + ": tinyobjloader returned a face that is not a triangle");
            Corner c[3];
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& ix = mesh.indices[3 * f + size_t(k)];
                if (ix.vertex_index < 0 || size_t(ix.vertex_index) >= nv || ix.texcoord_index >= long(nvt) ||
                    ix.normal_index >= long(nvn) || ix.texcoord_index < -1 || ix.normal_index < -1)
                    throw Error(path + ": tinyobjloader returned a face index out of range");
                c[k] = {ix.vertex_index, ix.texcoord_index, ix.normal_index};
            }
            const glm::dvec3 p0 = vec_at(attrib.vertices, size_t(c[0].v)), p1 = vec_at(attrib.vertices, size_t(c[1].v)),
                             p2 = vec_at(attrib.vertices, size_t(c[2].v));
            const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
            if (!(glm::dot(n, n) > 0)) {
                ++degenerate;
                continue;
            }
            int mat = mesh.material_ids[f];
            if (mat < 0 || size_t(mat) >= model.materials.size()) {
                mat = -1;
                default_material = true;
            }
            for (const Corner& k : c) corners.push_back(k);
            tri_material.push_back(mat);
            face_n.push_back(n);
        }
    }
    if (degenerate)
        model.warnings.push_back(path + ": " + std::to_string(degenerate) + " zero-area triangles dropped");
    const size_t tris = tri_material.size();
    if (tris == 0) throw Error(path + ": expected at least one triangle with area, got none: an empty mesh");
    if (default_material) {
        Material d;
        d.name = obj_name + ":(default)";
        d.diffuse = glm::vec3(0.8f);
        model.materials.push_back(d);
        for (int& m : tri_material)
            if (m < 0) m = int(model.materials.size() - 1);
    }

    // 5. Normals: a file normal where the corner has a usable one; otherwise smoothing clusters
    // per position: greedy, each face joins the first cluster whose seed normal is within the
    // angle (or, past kMaxClusters, the nearest), so the work is linear in the corners.
    std::vector<glm::vec3> file_normal(nvn);
    std::vector<char> file_normal_ok(nvn, 0);
    for (size_t i = 0; i < nvn; ++i) {
        const glm::dvec3 n = vec_at(attrib.normals, i);
        const double l = std::sqrt(glm::dot(n, n));
        if (l > 0 && std::isfinite(l)) file_normal[i] = glm::vec3(n / l), file_normal_ok[i] = 1;
    }
    size_t zero_normals = 0;
    for (Corner& c : corners)
        if (c.vn >= 0 && !file_normal_ok[size_t(c.vn)]) c.vn = -1, ++zero_normals;
    if (zero_normals)
        model.warnings.push_back(path + ": " + std::to_string(zero_normals) + " corners with a zero normal: normals computed there");
    std::vector<uint32_t> cluster(corners.size(), 0);
    std::vector<glm::dvec3> cluster_sum;
    {
        // Positions are smoothed across by value, not index: files made of patches (the Newell
        // teapot) repeat each seam vertex, which would otherwise leave a crease along every seam.
        std::vector<uint32_t> same(nv);
        CornerTable by_value(nv);
        for (size_t i = 0; i < nv; ++i) {
            static_assert(sizeof(tinyobj::real_t) == sizeof(int), "float positions");
            int bits[3];
            std::memcpy(bits, &attrib.vertices[3 * i], sizeof bits);
            bool inserted = false;
            same[i] = by_value.find_or_add(bits[0] == -1 ? 0 : bits[0], bits[1], bits[2], uint32_t(i), inserted);
        }
        std::vector<uint32_t> start(nv + 1, 0);
        for (const Corner& c : corners)
            if (c.vn < 0) ++start[size_t(same[size_t(c.v)]) + 1];
        for (size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
        std::vector<uint32_t> fill(start.begin(), start.end() - 1), list(start[nv]);
        for (size_t i = 0; i < corners.size(); ++i)
            if (corners[i].vn < 0) list[fill[size_t(same[size_t(corners[i].v)])]++] = uint32_t(i);
        const double cos_limit = std::cos(double(options.smooth_angle_deg) * 3.14159265358979323846 / 180.0);
        const size_t kMaxClusters = 64;
        std::vector<glm::dvec3> seeds;
        std::vector<uint32_t> ids;
        for (size_t p = 0; p < nv; ++p) {
            seeds.clear();
            ids.clear();
            for (uint32_t j = start[p]; j < start[p + 1]; ++j) {
                const uint32_t corner = list[j];
                const glm::dvec3& fn = face_n[corner / 3];
                const glm::dvec3 u = fn / std::sqrt(glm::dot(fn, fn));
                size_t found = seeds.size(), nearest = 0;
                double nearest_dot = -2;
                for (size_t s = 0; s < seeds.size(); ++s) {
                    const double d = glm::dot(seeds[s], u);
                    if (d >= cos_limit) { found = s; break; }
                    if (d > nearest_dot) nearest_dot = d, nearest = s;
                }
                if (found == seeds.size()) {
                    if (seeds.size() < kMaxClusters) {
                        seeds.push_back(u);
                        ids.push_back(uint32_t(cluster_sum.size()));
                        cluster_sum.push_back(glm::dvec3(0));
                    } else {
                        found = nearest;
                    }
                }
                const size_t best = found;
                cluster_sum[ids[best]] += fn;
                cluster[corner] = ids[best];
            }
        }
    }

    // 6. Group by material (Listing 9) and share vertices by hash of their corner key.
    std::vector<uint32_t> order(tris);
    {
        std::vector<uint32_t> start(model.materials.size() + 1, 0);
        for (int m : tri_material) ++start[size_t(m) + 1];
        for (size_t i = 0; i < model.materials.size(); ++i) start[i + 1] += start[i];
        for (uint32_t t = 0; t < tris; ++t) order[start[size_t(tri_material[t])]++] = t;
    }
    size_t i = 0;
    while (i < tris) {
        const int mat = tri_material[order[i]];
        size_t j = i;
        while (j < tris && tri_material[order[j]] == mat) ++j;
        Mesh mesh;
        mesh.material = mat;
        mesh.indices.reserve((j - i) * 3);
        CornerTable table((j - i) * 3);
        for (size_t k = i; k < j; ++k)
            for (int q = 0; q < 3; ++q) {
                const size_t ci = size_t(order[k]) * 3 + size_t(q);
                const Corner& c = corners[ci];
                const int nkey = c.vn >= 0 ? c.vn : -2 - int(cluster[ci]);
                bool inserted = false;
                const uint32_t idx = table.find_or_add(c.v, c.vt, nkey, uint32_t(mesh.vertices.size()), inserted);
                if (inserted) {
                    Vertex v;
                    v.pos = glm::vec3(vec_at(attrib.vertices, size_t(c.v)));
                    if (c.vt >= 0) v.uv = {attrib.texcoords[2 * size_t(c.vt)], attrib.texcoords[2 * size_t(c.vt) + 1]};
                    if (c.vn >= 0) {
                        v.normal = file_normal[size_t(c.vn)];
                    } else {
                        // Within a cluster the face normals lie within the angle of its seed, so
                        // the sum is not zero; past kMaxClusters it might be: the face's own.
                        glm::dvec3 s = cluster_sum[cluster[ci]];
                        if (!(glm::dot(s, s) > 0) || !std::isfinite(glm::dot(s, s))) s = face_n[ci / 3];
                        v.normal = glm::vec3(s / std::sqrt(glm::dot(s, s)));
                    }
                    mesh.vertices.push_back(v);
                }
                mesh.indices.push_back(idx);
            }
        compute_tangents(mesh);
        model.vertices += mesh.vertices.size();
        model.triangles += mesh.indices.size() / 3;
        model.groups.push_back(std::move(mesh));
        i = j;
    }
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
