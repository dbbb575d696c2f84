#include "scene/generated_model.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include <glm/glm.hpp>

#include "dsr_error.h"
#include "scene/procedural_textures.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

namespace fs = std::filesystem;
using glm::dvec2;
using glm::dvec3;

constexpr int kSegments = 16;  // around every round part

// The kSegments points of the unit circle, angle k * 360 / kSegments degrees, by bisecting the
// quarter circle (normalize(a + b) is the point between a and b): exact symmetry, no libm.
std::array<dvec2, kSegments> circle() {
    std::vector<dvec2> q = {{1, 0}, {0, 1}};
    while (int(q.size()) - 1 < kSegments / 4) {
        std::vector<dvec2> finer;
        for (size_t i = 0; i + 1 < q.size(); ++i) {
            finer.push_back(q[i]);
            finer.push_back(glm::normalize(q[i] + q[i + 1]));
        }
        finer.push_back(q.back());
        q = finer;
    }
    std::array<dvec2, kSegments> c;
    const int n = kSegments / 4;
    for (int k = 0; k < n; ++k) {
        c[size_t(k)] = q[size_t(k)];
        c[size_t(k + n)] = {-q[size_t(k)].y, q[size_t(k)].x};
        c[size_t(k + 2 * n)] = -q[size_t(k)];
        c[size_t(k + 3 * n)] = {q[size_t(k)].y, -q[size_t(k)].x};
    }
    return c;
}

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.5f", v);
    std::string s = b;
    return s == "-0.00000" ? "0.00000" : s;
}

struct Corner {
    dvec3 p;
    dvec2 uv;
    dvec3 n{0};  // zero: no normal given (the loader computes one)
};

// OBJ text one object at a time: its v/vt/vn lines, then its faces. Positions, uvs and normals
// are shared by value across the whole file, as an exporter's are.
class ObjWriter {
public:
    explicit ObjWriter(const std::string& header) : out_(header) {}

    void begin(const std::string& name, const std::string& material, bool smooth, bool relative) {
        flush();
        out_ += "o " + name + "\nusemtl " + material + "\ns " + (smooth ? "1" : "off") + "\n";
        relative_ = relative;
    }

    // One polygon; its corners are put in counter-clockwise order seen from `outward`.
    void face(std::vector<Corner> c, const dvec3& outward) {
        dvec3 newell(0);
        for (size_t i = 0; i < c.size(); ++i) newell += glm::cross(c[i].p, c[(i + 1) % c.size()].p);
        if (glm::dot(newell, outward) < 0) std::reverse(c.begin(), c.end());
        std::vector<std::array<int, 3>> f;
        for (const Corner& k : c)
            f.push_back({index(v_, nv_, "v " + num(k.p.x) + " " + num(k.p.y) + " " + num(k.p.z)),
                         index(vt_, nvt_, "vt " + num(k.uv.x) + " " + num(k.uv.y)),
                         k.n == dvec3(0) ? 0 : index(vn_, nvn_, "vn " + num(k.n.x) + " " + num(k.n.y) + " " + num(k.n.z))});
        faces_.push_back(f);
    }

    std::string finish() {
        flush();
        return out_;
    }

private:
    int index(std::map<std::string, int>& seen, int& count, const std::string& line) {
        auto it = seen.find(line);
        if (it != seen.end()) return it->second;
        verts_ += line + "\n";
        return seen[line] = ++count;
    }

    void flush() {
        out_ += verts_;
        // Relative indices count back from the last v, vt, vn before the face.
        auto ref = [&](int i, int count) { return std::to_string(relative_ ? i - count - 1 : i); };
        for (const auto& f : faces_) {
            out_ += "f";
            for (const auto& k : f)
                out_ += " " + ref(k[0], nv_) + "/" + ref(k[1], nvt_) + (k[2] ? "/" + ref(k[2], nvn_) : "");
            out_ += "\n";
        }
        verts_.clear();
        faces_.clear();
    }

    std::string out_, verts_;
    std::map<std::string, int> v_, vt_, vn_;
    int nv_ = 0, nvt_ = 0, nvn_ = 0;
    std::vector<std::vector<std::array<int, 3>>> faces_;
    bool relative_ = false;
};

// A rotation about +Z by the angle whose cosine and sine are (c, s), then a move.
struct Place {
    dvec2 cs{1, 0};
    dvec3 at{0};
    dvec3 dir(const dvec3& v) const { return {cs.x * v.x - cs.y * v.y, cs.y * v.x + cs.x * v.y, v.z}; }
    dvec3 point(const dvec3& v) const { return dir(v) + at; }
};

// A box of edge lengths `size` about `centre` (before `place`), uv in units of `tile` across
// each face: u to the right and v up seen from outside (on top, v toward -Z).
void box(ObjWriter& w, dvec3 centre, dvec3 size, double tile, const Place& place = {}) {
    const dvec3 h = size * 0.5;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            dvec3 n(0), u(0), v(0);
            n[axis] = sign;
            if (axis == 1) u = {1, 0, 0}, v = {0, 0, -double(sign)};
            else v = {0, 1, 0}, u = glm::cross(v, n);
            const double hu = glm::dot(glm::abs(u), h), hv = glm::dot(glm::abs(v), h), hn = glm::dot(glm::abs(n), h);
            std::vector<Corner> c;
            for (const dvec2 k : {dvec2(-1, -1), dvec2(1, -1), dvec2(1, 1), dvec2(-1, 1)}) {
                const dvec3 p = centre + n * hn + u * (k.x * hu) + v * (k.y * hv);
                c.push_back({place.point(p), dvec2((k.x + 1) * hu, (k.y + 1) * hv) / tile});
            }
            w.face(c, place.dir(n));
        }
}

// The side of a frustum about the Y axis from (r0, y0) to (r1, y1) (r1 = 0: a cone), smooth
// normals, u around (`u_tiles` repeats, increasing to the right seen from outside), v up the
// slant in units of `tile`.
void frustum(ObjWriter& w, double r0, double y0, double r1, double y1, double u_tiles, double tile) {
    const auto c = circle();
    const double slant = std::sqrt((r0 - r1) * (r0 - r1) + (y1 - y0) * (y1 - y0));
    // Outward normal at angle k: (h cos, r0 - r1, -h sin), normalised; position (r cos, y, -r sin).
    auto at = [&](int k, double r, double y) { return dvec3(r * c[size_t(k % kSegments)].x, y, -r * c[size_t(k % kSegments)].y); };
    auto normal = [&](dvec2 cs) { return glm::normalize(dvec3((y1 - y0) * cs.x, r0 - r1, -(y1 - y0) * cs.y)); };
    for (int k = 0; k < kSegments; ++k) {
        const double u0 = u_tiles * k / kSegments, u1 = u_tiles * (k + 1) / kSegments;
        const dvec3 n0 = normal(c[size_t(k)]), n1 = normal(c[size_t((k + 1) % kSegments)]);
        const dvec3 mid = glm::normalize(n0 + n1);
        std::vector<Corner> q = {{at(k, r0, y0), {u0, 0}, n0}, {at(k + 1, r0, y0), {u1, 0}, n1}};
        if (r1 > 0) {
            q.push_back({at(k + 1, r1, y1), {u1, slant / tile}, n1});
            q.push_back({at(k, r1, y1), {u0, slant / tile}, n0});
        } else {  // the apex, one per segment so each keeps its own uv and normal
            q.push_back({at(k, 0, y1), {0.5 * (u0 + u1), slant / tile}, mid});
        }
        w.face(q, mid);
    }
}

// A flat kSegments-gon of radius r about `centre`, facing `normal` (+Y, -Y or +Z), uv planar.
void disc(ObjWriter& w, dvec3 centre, double r, dvec3 normal, double tile, bool give_normal) {
    const auto c = circle();
    std::vector<Corner> p;
    for (const dvec2& k : c) {
        const dvec3 off = normal.z != 0 ? dvec3(r * k.x, r * k.y, 0) : dvec3(r * k.x, 0, -r * k.y);
        p.push_back({centre + off, dvec2(r * (k.x + 1), r * (k.y + 1)) / tile, give_normal ? normal : dvec3(0)});
    }
    w.face(p, normal);
}

// A cylinder along +Z from z0 to z1 about (x, y), radius r, smooth normals.
void cylinder_z(ObjWriter& w, dvec2 axis, double r, double z0, double z1, double tile) {
    const auto c = circle();
    for (int k = 0; k < kSegments; ++k) {
        const dvec2 a = c[size_t(k)], b = c[size_t((k + 1) % kSegments)];
        const double u0 = 2.0 * k / kSegments, u1 = 2.0 * (k + 1) / kSegments, v1 = (z1 - z0) / tile;
        w.face({{dvec3(axis + r * a, z0), {u0, 0}, dvec3(a, 0)},
                {dvec3(axis + r * b, z0), {u1, 0}, dvec3(b, 0)},
                {dvec3(axis + r * b, z1), {u1, v1}, dvec3(b, 0)},
                {dvec3(axis + r * a, z1), {u0, v1}, dvec3(a, 0)}},
               dvec3(glm::normalize(a + b), 0));
    }
}

std::string windmill_obj() {
    ObjWriter w("# A windmill made by `dsr gen-model` (src/scene/generated_model.cpp): stands on y = 0,\n"
                "# sails facing +Z. Materials and maps in windmill.mtl.\n"
                "mtllib windmill.mtl\n");
    const double tower_r0 = 1.7, tower_r1 = 1.2, tower_y0 = 0.6, tower_y1 = 6.0;
    auto tower_r = [&](double y) { return tower_r0 + (tower_r1 - tower_r0) * (y - tower_y0) / (tower_y1 - tower_y0); };

    w.begin("base", "brick", false, false);
    box(w, {0, 0.3, 0}, {4.6, 0.6, 4.6}, 1.2);

    w.begin("tower", "stone", true, false);
    frustum(w, tower_r0, tower_y0, tower_r1, tower_y1, 4, 2.3);

    w.begin("band", "metal", true, false);
    frustum(w, 1.32, 5.85, 1.28, 6.1, 4, 1.0);

    w.begin("roof", "shingle", true, false);
    frustum(w, 1.6, 6.1, 0, 8.4, 3, 1.0);
    disc(w, {0, 6.1, 0}, 1.6, {0, -1, 0}, 1.0, false);

    // Door and window on the front, sunk a little into the sloping wall.
    w.begin("door", "wood", false, false);
    box(w, {0, 1.35, tower_r(1.35) - 0.02}, {0.8, 1.5, 0.2}, 0.8);
    w.begin("window", "metal", false, false);
    box(w, {0, 3.95, tower_r(3.95) - 0.03}, {0.45, 0.6, 0.16}, 0.6);

    const dvec2 hub(0, 7.0);
    w.begin("axle", "metal", true, false);
    cylinder_z(w, hub, 0.13, 0.5, 1.95, 1.0);
    w.begin("hub", "metal", true, false);
    cylinder_z(w, hub, 0.28, 1.95, 2.15, 1.0);
    disc(w, dvec3(hub, 2.15), 0.28, {0, 0, 1}, 1.0, true);

    // Four sails in an X: a stock along the arm and a board lattice on its trailing side.
    const double s = std::sqrt(0.5);
    const dvec2 arms[4] = {{s, s}, {-s, s}, {-s, -s}, {s, -s}};
    for (int i = 0; i < 4; ++i) {
        w.begin("sail" + std::to_string(i + 1), "wood", false, true);
        const Place place{arms[i], dvec3(hub, 0)};
        box(w, {2.5, 0, 2.07}, {4.6, 0.14, 0.1}, 1.0, place);
        box(w, {2.7, 0.5, 2.0}, {3.6, 0.85, 0.05}, 1.0, place);
    }
    return w.finish();
}

const char* const kWindmillMtl =
    "# The windmill's materials (`dsr gen-model`); every map from src/scene/procedural_textures.cpp.\n"
    "newmtl brick\n"
    "Kd 1 1 1\nKs 0.3 0.3 0.3\nNs 24\n"
    "map_Kd brick_diffuse.png\nmap_bump brick_normal.png\nmap_Ks brick_specular.png\n"
    "\n"
    "newmtl stone\n"
    "Kd 0.95 0.93 0.88\nKs 0.4 0.4 0.4\nNs 32\n"
    "map_Kd stone_diffuse.png\nnorm stone_normal.png\nmap_Ks stone_specular.png\n"
    "\n"
    "newmtl metal\n"
    "Kd 1 1 1\nKs 0.9 0.9 0.9\nNs 96\n"
    "map_Kd metal_diffuse.png\nmap_bump metal_normal.png\nmap_Ns metal_specular.png\n"
    "\n"
    "newmtl shingle\n"
    "Kd 1 1 1\nKs 0.5 0.5 0.5\nNs 48\n"
    "map_Kd shingle_diffuse.png\nmap_Bump shingle_normal.png\nmap_Ks shingle_specular.png\n"
    "\n"
    "newmtl wood\n"
    "Kd 1 1 1\nKs 0.25 0.25 0.25\nNs 16\n"
    "map_Kd wood_diffuse.png\nnorm wood_normal.png\nmap_Ks wood_specular.png\n";

}  // namespace

GeneratedModel windmill_model() {
    GeneratedModel m;
    m.obj_name = "windmill.obj";
    m.files.push_back({m.obj_name, windmill_obj(), {}});
    m.files.push_back({"windmill.mtl", kWindmillMtl, {}});
    auto add = [&](std::vector<std::pair<std::string, Image>> maps) {
        for (auto& [name, img] : maps) m.files.push_back({name, "", std::move(img)});
    };
    add(default_textures());
    add(model_textures());
    return m;
}

namespace {

// write_model's steps, undone in reverse by its destructor unless done() was called: folders it
// made, the hidden folder it writes into, and every file it moved into place (with the file that
// was there before, kept in the hidden folder until the end).
class ModelWrite {
public:
    explicit ModelWrite(const std::string& dir) : dir_(dir) {}
    ~ModelWrite() {
        if (!done_) undo();
    }
    ModelWrite(const ModelWrite&) = delete;
    ModelWrite& operator=(const ModelWrite&) = delete;

    [[noreturn]] void fail(const std::string& what) const { throw Error(what); }
    std::string in_dir(const std::string& name) const { return quote(name) + " in " + quote(dir_); }

    // dir_ and its missing parents, one level at a time (each removed again on failure).
    void make_folders() {
        struct stat st {};
        if (::stat(dir_.c_str(), &st) == 0) {
            if (!S_ISDIR(st.st_mode))
                fail("DIR: expected a folder, got " + quote(dir_) + ", " +
                     (S_ISREG(st.st_mode) ? std::string("a file") : kind_of(st.st_mode)));
            return;
        }
        std::string prefix;
        size_t i = 0;
        while (i < dir_.size()) {
            const size_t slash = dir_.find('/', i + 1);
            const size_t end = slash == std::string::npos ? dir_.size() : slash;
            prefix = dir_.substr(0, end);
            i = end;
            if (prefix == "/" || prefix.empty() || ::stat(prefix.c_str(), &st) == 0) continue;
            if (::mkdir(prefix.c_str(), 0777) != 0) fail("cannot create " + quote(prefix) + ": " + std::strerror(errno));
            made_.push_back(prefix);
        }
    }

    // Refuses a name already taken by anything but a file (a folder in the way), before any write.
    void check_target(const std::string& name) const {
        struct stat st {};
        if (::stat((dir_ + "/" + name).c_str(), &st) == 0 && !S_ISREG(st.st_mode))
            fail("DIR: expected a file to write, got " + in_dir(name) + ", " +
                 (S_ISDIR(st.st_mode) ? std::string("a folder") : kind_of(st.st_mode)));
    }

    // The hidden folder inside dir_ every file is written into first (same file system: the
    // moves into place are renames).
    void make_temp() {
        for (int n = 0;; ++n) {
            temp_ = dir_ + "/.dsr-" + std::to_string(long(::getpid())) + "-" + std::to_string(n);
            if (::mkdir(temp_.c_str(), 0777) == 0) return;
            if (errno != EEXIST || n > 100) {
                const int e = errno;
                temp_.clear();
                fail("cannot write into " + quote(dir_) + ": " + std::strerror(e));
            }
        }
    }

    void put(const GeneratedFile& f) {
        const std::string path = temp_ + "/" + f.name;
        const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) fail("cannot write " + in_dir(f.name) + ": " + std::strerror(errno));
        written_.push_back(f.name);
        if (f.is_image()) {
            ::close(fd);
            try {
                encode_image(path, f.name, f.image);
            } catch (const Error& e) {
                // The encoder names f.name; what follows is its reason.
                std::string why = e.what();
                const std::string head = "cannot write " + f.name + ": ";
                if (why.rfind(head, 0) == 0) why = why.substr(head.size());
                fail("cannot write " + in_dir(f.name) + ": " + why);
            }
            return;
        }
        size_t done = 0;
        while (done < f.text.size()) {
            const ssize_t n = ::write(fd, f.text.data() + done, f.text.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                const int e = n < 0 ? errno : EIO;
                ::close(fd);
                fail("cannot write " + in_dir(f.name) + ": " + std::strerror(e));
            }
            done += size_t(n);
        }
        if (::close(fd) != 0) fail("cannot write " + in_dir(f.name) + ": " + std::strerror(errno));
    }

    // Moves every written file into place, keeping whatever was there in the hidden folder.
    void move_into_place() {
        const std::string kept = temp_ + "/.kept";
        if (::mkdir(kept.c_str(), 0777) != 0) fail("cannot write into " + quote(dir_) + ": " + std::strerror(errno));
        for (const std::string& name : written_) {
            const std::string target = dir_ + "/" + name;
            struct stat st {};
            Moved m{name, false};
            if (::lstat(target.c_str(), &st) == 0) {
                if (::rename(target.c_str(), (kept + "/" + name).c_str()) != 0)
                    fail("cannot write " + in_dir(name) + ": " + std::strerror(errno));
                m.kept = true;
            }
            moved_.push_back(m);
            if (::rename((temp_ + "/" + name).c_str(), target.c_str()) != 0) {
                const int e = errno;
                moved_.back().placed = false;
                fail("cannot write " + in_dir(name) + ": " + std::strerror(e));
            }
        }
    }

    void done() {
        done_ = true;
        remove_temp();
    }

private:
    struct Moved {
        std::string name;
        bool kept;           // the file that was there is in temp_/.kept
        bool placed = true;  // the new file reached dir_
    };

    void remove_temp() {
        if (temp_.empty()) return;
        std::error_code ec;
        fs::remove_all(temp_, ec);
        temp_.clear();
    }

    void undo() {
        for (auto m = moved_.rbegin(); m != moved_.rend(); ++m) {
            const std::string target = dir_ + "/" + m->name;
            if (m->placed) ::unlink(target.c_str());
            if (m->kept) ::rename((temp_ + "/.kept/" + m->name).c_str(), target.c_str());
        }
        remove_temp();
        for (auto d = made_.rbegin(); d != made_.rend(); ++d) ::rmdir(d->c_str());
    }

    std::string dir_, temp_;
    std::vector<std::string> made_, written_;
    std::vector<Moved> moved_;
    bool done_ = false;
};

// "a/b//" -> "a/b": a folder's name without the slashes after it ("/" stays).
std::string without_trailing_slashes(std::string dir) {
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    return dir;
}

}  // namespace

std::string write_model(const GeneratedModel& model, const std::string& dir_as_given) {
    if (dir_as_given.empty()) throw Error("DIR: expected a folder name, got ''");
    const std::string dir = without_trailing_slashes(dir_as_given);
    ModelWrite w(dir);
    w.make_folders();
    for (const GeneratedFile& f : model.files) w.check_target(f.name);
    w.make_temp();
    for (const GeneratedFile& f : model.files) w.put(f);
    w.move_into_place();
    w.done();
    return dir + "/" + model.obj_name;
}

}  // namespace dsr
