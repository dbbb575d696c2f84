// The hostile suite's runner and input makers (hostile.h).
#include "hostile.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "../cli_fixture.h"
#include "scene/image.h"

namespace dsr::hostile {

namespace fs = std::filesystem;

namespace {

std::string at(const std::string& dir, const std::string& name) { return dir + "/" + name; }

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// What a folder holds, to compare before and after a run: every entry (links not followed, FIFOs
// and devices not opened) with its type and content. Files over 64 MiB (sparse ones made to be
// refused by size) by size, modification time and their first and last MiB.
struct Entry {
    std::string kind, content;
    bool operator==(const Entry& o) const { return kind == o.kind && content == o.content; }
};

std::string fnv(const std::string& bytes) {
    unsigned long long h = 1469598103934665603ull;
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return std::to_string(h) + "/" + std::to_string(bytes.size());
}

std::map<std::string, Entry> snapshot(const std::string& dir) {
    std::map<std::string, Entry> out;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::none, ec);
         it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string p = it->path().string();
        struct stat st {};
        if (lstat(p.c_str(), &st) != 0) continue;
        Entry e;
        if (S_ISLNK(st.st_mode)) {
            char buf[4096];
            const ssize_t n = readlink(p.c_str(), buf, sizeof buf);
            e = {"link", std::string(buf, n > 0 ? size_t(n) : 0)};
            it.disable_recursion_pending();
        } else if (S_ISDIR(st.st_mode)) {
            e = {"dir", std::to_string(st.st_mode & 07777)};
        } else if (S_ISREG(st.st_mode)) {
            if (st.st_size <= (64ll << 20)) {
                e = {"file", fnv(read_all(p))};
            } else {
                std::ifstream in(p, std::ios::binary);
                std::string head(1 << 20, '\0'), tail(1 << 20, '\0');
                in.read(head.data(), long(head.size()));
                in.seekg(st.st_size - (1 << 20));
                in.read(tail.data(), long(tail.size()));
                e = {"big", std::to_string(st.st_size) + "/" + std::to_string(st.st_mtim.tv_sec) + "." +
                                std::to_string(st.st_mtim.tv_nsec) + "/" + fnv(head) + "/" + fnv(tail)};
            }
        } else {
            e = {"special", std::to_string(st.st_mode)};
        }
        out[p.substr(dir.size() + 1)] = e;
    }
    return out;
}

// One Xvfb for the cases that open the viewer's window, started on first use.
std::string display() {
    static std::string name = [] {
        FILE* p = popen("command -v Xvfb 2>/dev/null", "r");
        char buf[256] = {0};
        const bool found = p && fgets(buf, sizeof buf, p);
        if (p) pclose(p);
        if (!found) return std::string();
        int n = 300;
        while (n < 400 && (test::exists("/tmp/.X11-unix/X" + std::to_string(n)) ||
                           test::exists("/tmp/.X" + std::to_string(n) + "-lock")))
            ++n;
        const pid_t pid = fork();
        if (pid == 0) {
            const int fd = open("/dev/null", O_WRONLY);
            if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
            const std::string d = ":" + std::to_string(n);
            execlp("Xvfb", "Xvfb", d.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp", (char*)nullptr);
            _exit(127);
        }
        static const pid_t xvfb = pid;  // stopped when the tests end
        std::atexit([] {
            kill(xvfb, SIGTERM);
            waitpid(xvfb, nullptr, 0);
        });
        const std::string sock = "/tmp/.X11-unix/X" + std::to_string(n);
        for (int i = 0; i < 200 && !test::exists(sock); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return test::exists(sock) ? ":" + std::to_string(n) : std::string();
    }();
    return name;
}

struct Outcome {
    bool hung = false;
    int status = -1;
    std::string out, err;
};

Outcome run_in(const std::string& dir, const std::string& args, const std::string& env_display) {
    const std::string logs = test::temp_dir();
    const std::string out_path = logs + "/stdout", err_path = logs + "/stderr";
    const std::string command = "exec " + test::dsr_binary() + " " + args;
    const pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);
        if (chdir(dir.c_str()) != 0) _exit(126);
        const int o = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int in = open("/dev/null", O_RDONLY);
        if (o < 0 || e < 0 || in < 0) _exit(126);
        dup2(in, 0), dup2(o, 1), dup2(e, 2);
        if (env_display.empty()) unsetenv("DISPLAY");
        else setenv("DISPLAY", env_display.c_str(), 1);
        execl("/bin/bash", "bash", "-c", command.c_str(), (char*)nullptr);
        _exit(127);
    }
    Outcome r;
    // A hang is a failure, not a stuck suite: 60 s is far above any case (the slowest loads a
    // quarter-million-triangle model and decodes a 64-megapixel image).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int st = 0;
    for (;;) {
        const pid_t w = waitpid(pid, &st, WNOHANG);
        if (w == pid) break;
        if (std::chrono::steady_clock::now() > deadline) {
            kill(-pid, SIGKILL);
            waitpid(pid, &st, 0);
            r.hung = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (!r.hung) r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
    r.out = read_all(out_path);
    r.err = read_all(err_path);
    fs::remove_all(logs);
    return r;
}

}  // namespace

void write(const std::string& dir, const std::string& name, const std::string& bytes) {
    std::ofstream(at(dir, name), std::ios::binary) << bytes;
}

void fifo(const std::string& dir, const std::string& name) { ASSERT_EQ(mkfifo(at(dir, name).c_str(), 0644), 0); }

void folder(const std::string& dir, const std::string& name) { fs::create_directories(at(dir, name)); }

void symlink_to(const std::string& dir, const std::string& name, const std::string& target) {
    ASSERT_EQ(::symlink(target.c_str(), at(dir, name).c_str()), 0);
}

void hardlink_to(const std::string& dir, const std::string& name, const std::string& target) {
    ASSERT_EQ(::link(at(dir, target).c_str(), at(dir, name).c_str()), 0);
}

void sparse(const std::string& dir, const std::string& name, long long bytes) {
    write(dir, name, "");
    ASSERT_EQ(::truncate(at(dir, name).c_str(), off_t(bytes)), 0);
}

void image(const std::string& dir, const std::string& name, int w, int h) {
    Image img;
    img.width = w, img.height = h;
    img.rgba.assign(size_t(w) * size_t(h) * 4, 0.5f);
    for (size_t i = 0; i < img.rgba.size(); i += 4) img.rgba[i] = float(i % 97) / 97.0f;  // not flat: real data
    write_image(at(dir, name), img);
}

void truncated(const std::string& dir, const std::string& name, const std::string& from, long long keep) {
    const std::string all = read_all(at(dir, from));
    const long long n = keep < 0 ? (long long)all.size() + keep : keep;
    write(dir, name, all.substr(0, size_t(std::max(0ll, n))));
}

void damaged(const std::string& dir, const std::string& name, const std::string& from, long long offset,
             const std::string& bytes) {
    std::string all = read_all(at(dir, from));
    if (size_t(offset) + bytes.size() <= all.size()) all.replace(size_t(offset), bytes.size(), bytes);
    write(dir, name, all);
}

namespace {

unsigned crc32(const std::string& s) {
    unsigned c = 0xffffffffu;
    for (unsigned char b : s) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

std::string be32(unsigned v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }

std::string chunk(const std::string& type, const std::string& data) {
    return be32(unsigned(data.size())) + type + data + be32(crc32(type + data));
}

}  // namespace

void grey_png(const std::string& dir, const std::string& name, int w, int h) {
    const std::string row = std::string(1, '\0') + std::string(size_t(w), '\x80');  // filter 0, grey 128
    std::string raw;
    raw.reserve(row.size() * size_t(h));
    for (int y = 0; y < h; ++y) raw += row;
    std::string z = "\x78\x01";  // zlib, no compression: stored blocks of at most 65535 bytes
    for (size_t i = 0; i < raw.size(); i += 65535) {
        const size_t n = std::min<size_t>(65535, raw.size() - i);
        z += char(i + n == raw.size() ? 1 : 0);
        z += char(n & 0xff), z += char(n >> 8), z += char(~n & 0xff), z += char((~n >> 8) & 0xff);
        z.append(raw, i, n);
    }
    unsigned a = 1, b = 0;
    for (unsigned char c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
    z += be32((b << 16) | a);
    const std::string ihdr = be32(unsigned(w)) + be32(unsigned(h)) + std::string("\x08\x00\x00\x00\x00", 5);
    write(dir, name, "\x89PNG\r\n\x1a\n" + chunk("IHDR", ihdr) + chunk("IDAT", z) + chunk("IEND", ""));
}

void header_only_png(const std::string& dir, const std::string& name, unsigned w, unsigned h) {
    const std::string ihdr = be32(w) + be32(h) + std::string("\x08\x02\x00\x00\x00", 5);
    write(dir, name,
          "\x89PNG\r\n\x1a\n" + chunk("IHDR", ihdr) + chunk("IDAT", std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8)) +
              chunk("IEND", ""));
}

std::string scene_text(const std::string& more, const std::string& material_extra) {
    return std::string(kCamera) + "material m diffuse 0.5 0.5 0.5 specular 0.2 0.2 0.2 shininess 16" + material_extra +
           "\nlight point pos 1 3 2 color 1 1 1 radius 10\nplane size 4 at 0 0 0 material m\n" + more;
}

std::string quad_obj(const std::string& mtl) {
    return (mtl.empty() ? std::string() : "mtllib " + mtl + "\n") +
           "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n" +
           (mtl.empty() ? "" : "usemtl a\n") + "f 1/1 4/4 3/3\nf 1/1 3/3 2/2\n";
}

void run_case(const Case& c) {
    std::string env_display;
    if (c.display) {
        env_display = display();
        if (env_display.empty()) GTEST_SKIP() << "Xvfb is not installed or did not start (make deps installs xvfb)";
    }
    const std::string dir = test::temp_dir();
    if (c.setup) c.setup(dir);
    if (::testing::Test::HasFatalFailure()) return;
    const auto before = snapshot(dir);
    const Outcome r = run_in(dir, c.args, env_display);
    const std::string said = "dsr " + c.args + "\nstderr: " + r.err + "stdout: " + r.out;
    EXPECT_FALSE(r.hung) << "hung (killed after 60 s): " << said;
    EXPECT_EQ(r.status, c.status) << said;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr is not one line: " << said;
    EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n') << said;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << "wanted '" << c.expect << "' in: " << said;
    EXPECT_LE(r.err.size(), 600u) << "a long error line: " << said;
    const auto after = snapshot(dir);
    for (const auto& [path, entry] : after) {
        auto it = before.find(path);
        if (it == before.end()) ADD_FAILURE() << "left behind: " << path << " by " << said;
        else EXPECT_TRUE(it->second == entry) << "changed: " << path << " by " << said;
    }
    for (const auto& [path, entry] : before)
        EXPECT_TRUE(after.count(path)) << "removed: " << path << " by " << said;
    std::error_code ec;
    fs::remove_all(dir, ec);
}

TEST_P(Hostile, OneLineNothingWrittenInputsKept) { run_case(GetParam()); }

}  // namespace dsr::hostile
