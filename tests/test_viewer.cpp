// The viewer (`dsr view`, build/dsr_view) under its own Xvfb, driven by --script: its screenshot
// is `dsr render`'s image, the resize sequence reallocates the buffers without a GL error or a
// rebuilt shader, `set` changes what it must and nothing else, the panel is captured only where
// the script asks (`screenshot FILE panel`), and the executable links the system libGL, not
// libOSMesa. Skips, saying why, only when Xvfb cannot run here (`make deps` installs it).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "analysis/image_metrics.h"
#include "cli_fixture.h"
#include "scene/image.h"

using namespace dsr;
using namespace dsr::test;

namespace {

std::string shell_out(const std::string& cmd) {
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return out;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    pclose(p);
    return out;
}

bool file_exists(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0;
}

class Viewer : public ::testing::Test {
protected:
    static pid_t xvfb_;
    static int display_;
    static std::string skip_;

    // One Xvfb for the suite, on the first display number with no socket or lock file.
    static void SetUpTestSuite() {
        const std::string xvfb = shell_out("command -v Xvfb 2>/dev/null");
        if (xvfb.empty()) {
            skip_ = "Xvfb is not installed (make deps installs xvfb)";
            return;
        }
        for (int n = 91; n < 200 && display_ < 0; ++n)
            if (!file_exists("/tmp/.X11-unix/X" + std::to_string(n)) && !file_exists("/tmp/.X" + std::to_string(n) + "-lock"))
                display_ = n;
        if (display_ < 0) {
            skip_ = "no free X display number in :91..:199";
            return;
        }
        const std::string log = "/tmp/dsr-test-xvfb-" + std::to_string(display_) + ".log";
        xvfb_ = fork();
        if (xvfb_ == 0) {
            const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
            const std::string d = ":" + std::to_string(display_);
            execlp("Xvfb", "Xvfb", d.c_str(), "-screen", "0", "1600x1200x24", "-nolisten", "tcp", (char*)nullptr);
            _exit(127);
        }
        const std::string sock = "/tmp/.X11-unix/X" + std::to_string(display_);
        for (int i = 0; i < 200 && !file_exists(sock); ++i) {
            int status;
            if (waitpid(xvfb_, &status, WNOHANG) == xvfb_) {
                xvfb_ = -1;
                skip_ = "Xvfb exited at start: " + shell_out("tail -n 3 " + log);
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        if (!file_exists(sock)) skip_ = "Xvfb did not open " + sock + " in 10 s";
    }
    static void TearDownTestSuite() {
        if (xvfb_ > 0) {
            kill(xvfb_, SIGTERM);
            waitpid(xvfb_, nullptr, 0);
            xvfb_ = -1;
        }
    }
    void SetUp() override {
        if (!skip_.empty()) GTEST_SKIP() << skip_;
        dir_ = temp_dir();
    }

    // `dsr view ARGS --script` with the script's text, on this suite's display.
    RunResult view(const std::string& args, const std::string& script) {
        const std::string path = dir_ + "/s" + std::to_string(n_++) + ".script";
        std::ofstream(path) << script;
        return run("view " + args + " --script " + path, "DISPLAY=:" + std::to_string(display_));
    }
    std::string out(const std::string& name) const { return dir_ + "/" + name; }
    Image render(const std::string& args, const std::string& name) {
        RunResult r = run("render " + args + " -o " + out(name));
        EXPECT_EQ(r.status, 0) << r.output;
        return load_image(out(name));
    }

    std::string dir_;
    int n_ = 0;
};

pid_t Viewer::xvfb_ = -1;
int Viewer::display_ = -1;
std::string Viewer::skip_;

double max_lsb(const Image& a, const Image& b) { return compare_images(a, b, 0.5 / 255.0).max_lsb(); }

}  // namespace

// The scene's camera, the window's size: the screenshot is `dsr render`'s image (same Mesa, GLX
// instead of OSMesa) within 1 LSB, although the panel is open over it in the window.
TEST_F(Viewer, ScreenshotIsTheRenderWithoutThePanel) {
    RunResult r = view("--size 192x144", "frames 2\nscreenshot " + out("v.png") + "\nquit\n");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("panel on"), std::string::npos) << "the panel should be open: " << r.output;
    const Image v = load_image(out("v.png")), ref = render("--size 192x144", "r.png");
    ASSERT_EQ(v.width, 192);
    ASSERT_EQ(v.height, 144);
    EXPECT_LE(max_lsb(v, ref), 1.0) << r.output;
}

// `screenshot FILE panel` captures the window as shown: with the panel open it differs from the
// deferred image; with the panel closed it is the deferred image.
TEST_F(Viewer, ScreenshotPanelCapturesThePanel) {
    RunResult r = view("--size 320x240", "frames 2\nscreenshot " + out("plain.png") + "\nscreenshot " + out("panel.png") +
                                             " panel\nset panel off\nscreenshot " + out("closed.png") + " panel\nquit\n");
    ASSERT_EQ(r.status, 0) << r.output;
    const Image plain = load_image(out("plain.png")), panel = load_image(out("panel.png")),
                closed = load_image(out("closed.png"));
    ASSERT_EQ(panel.width, 320);
    ASSERT_EQ(panel.height, 240);
    EXPECT_GT(max_lsb(panel, plain), 50.0) << "the panel is not in the panel screenshot";
    EXPECT_LE(max_lsb(closed, plain), 1.0) << "with the panel closed, the window is the deferred image";
}

// A script ends when it ends: no `quit`, and the viewer closes after its last line (a `timeout`
// guard turns a viewer that stays open into a failure, status 124, rather than a hung test).
TEST_F(Viewer, ScriptWithoutQuitEndsAfterItsLastLine) {
    const std::string path = out("noquit.script");
    std::ofstream(path) << "frames 2\n";
    RunResult r = run("view --size 64x64 --script " + path, "DISPLAY=:" + std::to_string(display_) + " timeout 300");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("dsr view: 2 frames"), std::string::npos) << r.output;
}

// 512^2 -> 800x600 -> 300x200 -> 0x0 (minimised) -> 640x480: every stage checked for GL errors
// (--debug-gl), each screenshot at the new size, the buffers reallocated by resize() with no
// program built, and the last frame the render's at that size. With the quad geometry, whose
// programs are all built with the shader: auto builds some on first use (the tiles' programs for
// each count of lights a tile holds, which a new size or a path it tries may bring), which is not
// a rebuild.
TEST_F(Viewer, ResizeSequenceReallocatesWithoutRebuilding) {
    const std::string script = "frames 1\nscreenshot " + out("a.png") + "\nsize 800 600\nframes 1\nscreenshot " +
                               out("b.png") + "\nsize 300 200\nscreenshot " + out("c.png") +
                               "\nsize 0 0\nframes 3\nsize 640 480\nframes 1\nscreenshot " + out("d.png") + "\nquit\n";
    RunResult r = view("--size 512x512 --debug-gl --light-geometry quad", script);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("GL error"), std::string::npos) << r.output;
    const std::pair<const char*, std::pair<int, int>> shots[] = {
        {"a.png", {512, 512}}, {"b.png", {800, 600}}, {"c.png", {300, 200}}, {"d.png", {640, 480}}};
    for (const auto& [name, size] : shots) {
        const Image img = load_image(out(name));
        EXPECT_EQ(img.width, size.first) << name;
        EXPECT_EQ(img.height, size.second) << name;
    }
    EXPECT_NE(r.output.find("3 resizes, deferred shader built 1 time, 0 programs built since"), std::string::npos)
        << r.output;
    EXPECT_LE(max_lsb(load_image(out("d.png")), render("--size 640x480 --light-geometry quad", "r640.png")), 1.0);
}

// Scissor rectangles only limit where a light is shaded: off, the image is the same, and every
// drawn light then covers the whole frame (scissor_pixels = lights x W x H).
TEST_F(Viewer, SetScissorOffLeavesTheImage) {
    RunResult r = view("--size 128x128",
                       "screenshot " + out("on.png") + "\nset scissor off\nscreenshot " + out("off.png") + "\nquit\n");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_LE(max_lsb(load_image(out("on.png")), load_image(out("off.png"))), 1.0);
    std::smatch m;
    const std::regex line("off\\.png \\(128x128, view final, scissor off, panel on, (\\d+)/\\d+ lights drawn, scissor_pixels (\\d+)\\)");
    ASSERT_TRUE(std::regex_search(r.output, m, line)) << r.output;
    EXPECT_GT(std::stoll(m[1]), 0);
    EXPECT_EQ(std::stoll(m[2]), std::stoll(m[1]) * 128 * 128);
    const std::regex on_line("on\\.png \\(128x128, view final, scissor on, panel on, (\\d+)/\\d+ lights drawn, scissor_pixels (\\d+)\\)");
    ASSERT_TRUE(std::regex_search(r.output, m, on_line)) << r.output;
    EXPECT_LT(std::stoll(m[2]), std::stoll(m[1]) * 128 * 128) << "the rectangles should be smaller than the frame";
}

// `set view normal` shows the normal target: `dsr render --view normal`'s image, not the final one.
TEST_F(Viewer, SetViewNormalShowsTheNormalTarget) {
    RunResult r = view("--size 128x128",
                       "screenshot " + out("final.png") + "\nset view normal\nscreenshot " + out("normal.png") + "\nquit\n");
    ASSERT_EQ(r.status, 0) << r.output;
    const Image normal = load_image(out("normal.png"));
    EXPECT_LE(max_lsb(normal, render("--size 128x128 --view normal", "rn.png")), 1.0);
    EXPECT_GT(max_lsb(normal, load_image(out("final.png"))), 50.0);
}

// A bad script line is one error naming FILE:LINE before any window opens, and nothing is written.
TEST_F(Viewer, BadScriptLineIsOneErrorAndWritesNothing) {
    RunResult r = view("--size 64x64", "screenshot " + out("x.png") + "\nset scissor maybe\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find(".script:2: set scissor: expected on|off, got 'maybe'"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(file_exists(out("x.png")));
    RunResult flag = view("--size 64x64 --depth fast", "quit\n");
    EXPECT_EQ(flag.status, 1);
    EXPECT_EQ(flag.output, "dsr view: --depth: expected auto|texture|packed|position16|position32, got 'fast'\n");
}

// The viewer links the system libGL through GLFW and never libOSMesa (docs/architecture.md: never both in one
// executable); dsr itself links libOSMesa and not libglfw.
TEST(ViewerBinary, LinksLibGLAndNoOSMesa) {
    const std::string bin = dsr_binary() + "_view";
    ASSERT_TRUE(exists(bin)) << bin << " not built (make all builds it)";
    const std::string ldd = shell_out("ldd " + bin + " 2>&1");
    EXPECT_NE(ldd.find("libGL.so"), std::string::npos) << ldd;
    EXPECT_NE(ldd.find("libglfw"), std::string::npos) << ldd;
    EXPECT_EQ(ldd.find("OSMesa"), std::string::npos) << ldd;
    EXPECT_EQ(shell_out("nm -D -u " + bin + " | grep -c OSMesa"), "0\n");
    const std::string dsr_ldd = shell_out("ldd " + dsr_binary() + " 2>&1");
    EXPECT_NE(dsr_ldd.find("libOSMesa"), std::string::npos) << dsr_ldd;
    EXPECT_EQ(dsr_ldd.find("libglfw"), std::string::npos) << dsr_ldd;
}
