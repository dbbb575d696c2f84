// A run's outputs (output_set.h): declared, written to temporaries, renamed together.
#include "scene/output_set.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "dsr_error.h"

namespace dsr {

namespace {

// Where a path would land: the file's identity when it exists, else its folder's and its name,
// so two spellings of one new file compare equal too.
struct Place {
    std::optional<FileId> file, dir;
    std::string name;
    bool same(const Place& o) const {
        if (file && o.file) return *file == *o.file;
        return !file && !o.file && dir && o.dir && *dir == *o.dir && name == o.name;
    }
};

Place place_of(const std::string& path) {
    Place p;
    p.file = file_id(path);
    const std::filesystem::path fp(path);
    const std::string dir = fp.parent_path().string();
    p.dir = file_id(dir.empty() ? "." : dir);
    p.name = fp.filename().string();
    return p;
}

// "FLAG: " before a message, nothing for an output without one (write_image's).
std::string label(const std::string& flag) { return flag.empty() ? "" : flag + ": "; }

// What is in an output's way, as the readers name it (user_file.h kind_of); outputs say folder.
std::string in_the_way(mode_t m) { return S_ISDIR(m) ? "a folder" : kind_of(m); }

}  // namespace

OutputSet::OutputSet(std::string command) : command_(std::move(command)) {}

OutputSet::~OutputSet() {
    if (!committed_) discard();
}

void OutputSet::fail(const std::string& what) const {
    throw Error(command_.empty() ? what : command_ + ": " + what);
}

void OutputSet::discard() {
    for (Output& o : outputs_)
        if (!o.temp.empty()) {
            ::unlink(o.temp.c_str());
            o.temp.clear();
        }
    for (auto d = new_dirs_.rbegin(); d != new_dirs_.rend(); ++d) ::rmdir(d->c_str());
    new_dirs_.clear();
}

void OutputSet::check_against_inputs(const Output& out, const Input& in) const {
    const std::optional<FileId> id = file_id(out.path);
    if (id && *id == in.id)
        fail(label(out.flag) + "expected a file that is not an input of this run, got " + quote(out.path) + " (" + in.what +
             " " + in.path + ")");
}

void OutputSet::add_input(const std::string& path, const std::string& what) {
    const std::optional<FileId> id = file_id(path);
    if (!id) return;  // never read, then
    inputs_.push_back({path, what, *id});
    for (const Output& o : outputs_) check_against_inputs(o, inputs_.back());
}

OutputSet::Output& OutputSet::declared(const std::string& flag, const std::string& path) {
    const Place here = place_of(path);
    for (Output& o : outputs_)
        if (o.path == path || here.same(place_of(o.path))) {
            if (o.flag == flag && o.path == path) return o;
            fail(label(flag) + "expected a file no other output names, got " + quote(path) + " (also " + o.flag + " " +
                 o.path + ")");
        }
    add(flag, path);
    return outputs_.back();
}

void OutputSet::add(const std::string& flag, const std::string& path) {
    if (path.empty()) fail(label(flag) + "expected a file name, got ''");
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        fail(label(flag) + "expected a file to write, got " + quote(path) + ", " + in_the_way(st.st_mode));
    // Its folder must be there (figures' and bench's are made first, by make_dir): said now,
    // before the work, rather than when the output is ready.
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (::stat(dir.empty() ? "." : dir.c_str(), &st) != 0) fail(label(flag) + "cannot write " + path + ": " + std::strerror(errno));
    if (!S_ISDIR(st.st_mode)) fail(label(flag) + "cannot write " + path + ": " + std::strerror(ENOTDIR));
    const Place here = place_of(path);
    for (const Output& o : outputs_)
        if (here.same(place_of(o.path)))
            fail(label(flag) + "expected a file no other output names, got " + quote(path) + " (also " + o.flag + " " +
                 o.path + ")");
    outputs_.push_back({flag, path, ""});
    for (const Input& in : inputs_) check_against_inputs(outputs_.back(), in);
}

void OutputSet::make_dir(const std::string& flag, const std::string& dir) {
    if (dir.empty()) fail(label(flag) + "expected a folder name, got ''");
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0) {
        if (!S_ISDIR(st.st_mode)) fail(label(flag) + "expected a folder, got " + quote(dir) + ", " + in_the_way(st.st_mode));
        return;
    }
    if (::mkdir(dir.c_str(), 0777) != 0) fail("cannot create " + dir + ": " + std::strerror(errno));
    new_dirs_.push_back(dir);
}

// A new hidden file beside the output (same folder, so the rename is atomic), its extension
// kept last; short, so a file name near the system's limit still has room for it.
std::string OutputSet::create_temp(const Output& out) {
    const std::string ext = image_extension(out.path);
    const std::string dir = std::filesystem::path(out.path).parent_path().string();
    for (int n = 0;; ++n) {
        const std::string temp = (dir.empty() ? "" : dir + "/") + ".dsr-" + std::to_string(long(::getpid())) + "-" +
                                 std::to_string(n) + ext;
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return temp;
        }
        if (errno != EEXIST || n > 100) fail(label(out.flag) + "cannot write " + out.path + ": " + std::strerror(errno));
    }
}

void OutputSet::put_image(const std::string& flag, const std::string& path, const Image& img) {
    Output& o = declared(flag, path);
    if (o.temp.empty()) o.temp = create_temp(o);
    try {
        encode_image(o.temp, o.path, img);
    } catch (const Error& e) {
        fail(label(o.flag) + e.what());
    }
}

void OutputSet::put_text(const std::string& flag, const std::string& path, const std::string& text) {
    Output& o = declared(flag, path);
    if (o.temp.empty()) o.temp = create_temp(o);
    const int fd = ::open(o.temp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) fail(label(o.flag) + "cannot write " + o.path + ": " + std::strerror(errno));
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int e = n < 0 ? errno : EIO;
            ::close(fd);
            fail(label(o.flag) + "cannot write " + o.path + ": " + std::strerror(e));
        }
        done += size_t(n);
    }
    if (::close(fd) != 0) fail(label(o.flag) + "cannot write " + o.path + ": " + std::strerror(errno));
}

void OutputSet::commit() {
    // Inputs again: a link or rename since the outputs were declared must not slip through.
    for (const Output& o : outputs_)
        for (const Input& in : inputs_) check_against_inputs(o, in);
    std::vector<std::string> renamed;
    for (Output& o : outputs_) {
        if (o.temp.empty()) continue;  // declared, never put: nothing to write
        if (std::rename(o.temp.c_str(), o.path.c_str()) != 0) {
            const int e = errno;
            for (const std::string& r : renamed) ::unlink(r.c_str());  // all or none
            discard();
            fail(label(o.flag) + "cannot write " + o.path + ": " + std::strerror(e));
        }
        o.temp.clear();
        renamed.push_back(o.path);
    }
    written_ = renamed;
    committed_ = true;
    new_dirs_.clear();
}

void write_image(const std::string& path, const Image& img) {
    OutputSet out("");
    out.put_image("", path, img);
    out.commit();
}

}  // namespace dsr
