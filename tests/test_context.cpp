// The GL context seam (src/platform/context.h): create_context by backend name, the entry-point
// table loaded through proc_address (src/gl/entry_points.h), switching between contexts, and
// the promise that libdsr_core.a links against any libGL: nm finds no OSMesa symbol and no GL
// function newer than 1.1 left undefined in it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "analysis/image_metrics.h"
#include "cli_fixture.h"
#include "scene/image.h"
#include "dsr_error.h"
#include "gl/entry_points.h"
#include "gl/gl.h"
#include "platform/context.h"

using namespace dsr;
using namespace dsr::test;

namespace {

// The colour of pixel (x, y) of the current context's frame buffer.
std::array<int, 4> pixel(int x, int y) {
    unsigned char p[4] = {0, 0, 0, 0};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return {p[0], p[1], p[2], p[3]};
}

void clear_to(float r, float g, float b) {
    glClearColor(r, g, b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
}

// A context that hides some entry points of a real one, to stand for a poorer driver.
class HidingContext : public GLContext {
public:
    HidingContext(const GLContext& real, std::set<std::string> hidden) : real_(real), hidden_(std::move(hidden)) {}
    int width() const override { return real_.width(); }
    int height() const override { return real_.height(); }
    std::string backend() const override { return "hiding"; }
    void* proc_address(const char* name) const override {
        return hidden_.count(name) ? nullptr : real_.proc_address(name);
    }
    void make_current() override {}

private:
    const GLContext& real_;
    std::set<std::string> hidden_;
};

std::string shell(const std::string& cmd) {
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return out;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    pclose(p);
    return out;
}

}  // namespace

TEST(Context, OSMesaIsCurrentAtTheAskedSizeWithEveryEntryPoint) {
    auto ctx = create_context(ContextDesc{"osmesa", 37, 23});
    EXPECT_EQ(ctx->backend(), "osmesa");
    EXPECT_EQ(ctx->width(), 37);
    EXPECT_EQ(ctx->height(), 23);
    // Current: GL answers, and a fresh context's viewport is its frame buffer.
    ASSERT_NE(glGetString(GL_RENDERER), nullptr);
    GLint vp[4] = {-1, -1, -1, -1};
    glGetIntegerv(GL_VIEWPORT, vp);
    EXPECT_EQ(vp[2], 37);
    EXPECT_EQ(vp[3], 23);

    void* bind_fbo = ctx->proc_address("glBindFramebufferEXT");
    ASSERT_NE(bind_fbo, nullptr);
    EXPECT_EQ(reinterpret_cast<void*>(gl_entry.BindFramebufferEXT), bind_fbo);
    int required = 0;
    for (const auto& e : gl_entry_point_status()) {
        required += e.required;
        if (e.required) {
            EXPECT_TRUE(e.loaded) << e.name;
        }
    }
    EXPECT_GE(required, 40);
    // A call through the table reaches GL: an FBO name can be made and bound.
    GLuint fbo = 0;
    glGenFramebuffersEXT(1, &fbo);
    EXPECT_NE(fbo, 0u);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
    GLint bound = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING_EXT, &bound);
    EXPECT_EQ(bound, GLint(fbo));
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glDeleteFramebuffersEXT(1, &fbo);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Context, UnknownBackendNamesItAndTheBuiltOnes) {
    try {
        create_context(ContextDesc{"vulkan-please", 16, 16});
        FAIL() << "create_context accepted an unknown backend";
    } catch (const Error& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("'vulkan-please'"), std::string::npos) << m;
        ASSERT_FALSE(context_backends().empty());
        for (const auto& b : context_backends()) EXPECT_NE(m.find(b), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

TEST(Context, MakeCurrentSwitchesBackToTheFirstContext) {
    auto a = create_context(ContextDesc{"osmesa", 16, 16});
    clear_to(1, 0, 0);
    auto b = create_context(ContextDesc{"osmesa", 8, 8});
    clear_to(0, 1, 0);
    EXPECT_EQ(pixel(2, 2), (std::array<int, 4>{0, 255, 0, 255}));

    a->make_current();
    EXPECT_EQ(pixel(2, 2), (std::array<int, 4>{255, 0, 0, 255})) << "the first context's frame buffer";
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    EXPECT_EQ(vp[2], 16) << "the first context's state";
    GLfloat cc[4] = {0, 0, 0, 0};
    glGetFloatv(GL_COLOR_CLEAR_VALUE, cc);
    EXPECT_EQ(cc[0], 1.0f);
    EXPECT_EQ(cc[1], 0.0f);

    b->make_current();
    EXPECT_EQ(pixel(2, 2), (std::array<int, 4>{0, 255, 0, 255}));
    glGetIntegerv(GL_VIEWPORT, vp);
    EXPECT_EQ(vp[2], 8);
}

TEST(Context, MissingRequiredEntryPointIsNamedAndLeavesTheTableAlone) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    const auto real_use_program = gl_entry.UseProgram;
    ASSERT_NE(real_use_program, nullptr);
    HidingContext poor(*ctx, {"glUseProgram", "glDrawBuffersARB"});
    try {
        load_gl_entry_points(poor);
        FAIL() << "a context without glUseProgram was accepted";
    } catch (const Error& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("glUseProgram"), std::string::npos) << m;
        EXPECT_NE(m.find("glDrawBuffersARB"), std::string::npos) << m;
        EXPECT_NE(m.find("'hiding'"), std::string::npos) << m;
        EXPECT_EQ(m.find("glBindFramebufferEXT"), std::string::npos) << m;
    }
    EXPECT_EQ(gl_entry.UseProgram, real_use_program);
    EXPECT_NE(gl_entry.DrawBuffersARB, nullptr);

    // An optional one may be absent: loading succeeds and leaves it null.
    HidingContext no_timer(*ctx, {"glQueryCounter"});
    EXPECT_NO_THROW(load_gl_entry_points(no_timer));
    EXPECT_EQ(gl_entry.QueryCounter, nullptr);
    EXPECT_EQ(gl_entry.UseProgram, real_use_program);
    load_gl_entry_points(*ctx);  // as create_context left it, for the tests after this one
    EXPECT_NE(gl_entry.QueryCounter, nullptr);
}

// libdsr_core.a must link against any libGL (or none but the backend's): every OSMesa call and
// every GL call newer than 1.1 stays in the backends or goes through gl_entry.
TEST(Context, CoreLibraryNeedsNoOSMesaAndNoGLBeyond11) {
    if (shell("command -v nm").empty()) GTEST_SKIP() << "nm not found (binutils); cannot check libdsr_core.a";
    const std::string bin = dsr_binary();
    const std::string lib = bin.substr(0, bin.find_last_of('/')) + "/libdsr_core.a";
    ASSERT_TRUE(exists(lib)) << lib << " not beside the test binary";

    std::set<std::string> gl11;
    std::ifstream list(std::string(DSR_SOURCE_DIR) + "/tests/data/gl11_functions.txt");
    for (std::string line; std::getline(list, line);)
        if (!line.empty() && line[0] != '#') gl11.insert(line);
    ASSERT_EQ(gl11.size(), 336u) << "tests/data/gl11_functions.txt";

    // -A: each line "lib.a[member.o]: symbol U"; -P: portable, one symbol a line.
    std::istringstream nm(shell("nm -A -P -u '" + lib + "' 2>&1"));
    std::set<std::string> members, gl_used, bad;
    for (std::string line; std::getline(nm, line);) {
        std::istringstream f(line);
        std::string where, sym, type;
        if (!(f >> where >> sym >> type) || type != "U") continue;
        members.insert(where.substr(0, where.find(']') + 1));
        if (sym.rfind("OSMesa", 0) == 0) bad.insert(sym + " (" + where + ")");
        if (sym.size() > 2 && sym.rfind("gl", 0) == 0 && std::isupper(static_cast<unsigned char>(sym[2]))) {
            gl_used.insert(sym);
            if (!gl11.count(sym)) bad.insert(sym + " (" + where + ")");
        }
    }
    // The parse saw the archive: many members, and the GL 1.1 calls the renderer makes.
    EXPECT_GE(members.size(), 10u);
    EXPECT_TRUE(gl_used.count("glEnable")) << "nm output not understood";
    EXPECT_TRUE(gl_used.count("glTexImage2D"));
    for (const auto& m : members) {
        EXPECT_EQ(m.find("osmesa_context.o"), std::string::npos) << "backend in the core: " << m;
        EXPECT_EQ(m.find("headless_backends.o"), std::string::npos) << "backend in the core: " << m;
    }
    std::string all;
    for (const auto& b : bad) all += "\n  " + b;
    EXPECT_TRUE(bad.empty()) << "libdsr_core.a leaves undefined:" << all;
}

TEST(Context, CommandLineFlagAndEnvironmentPickTheBackend) {
    RunResult ok = run("info --context osmesa");
    ASSERT_EQ(ok.status, 0) << ok.output;
    EXPECT_NE(ok.output.find("context        osmesa"), std::string::npos) << ok.output;

    for (const std::string cmd : {"info --context nope", "render --context nope -o /tmp/dsr-ctx-never.png",
                                  "figures --context nope -o /tmp/dsr-ctx-never"}) {
        RunResult r = run(cmd);
        EXPECT_EQ(r.status, 1) << cmd << ": " << r.output;
        EXPECT_NE(r.output.find("unknown GL context backend 'nope'"), std::string::npos) << cmd << ": " << r.output;
        EXPECT_NE(r.output.find("osmesa"), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << cmd << ": " << r.output;
    }
    EXPECT_FALSE(exists("/tmp/dsr-ctx-never.png"));

    RunResult env = run("info", "DSR_CONTEXT=nope");
    EXPECT_EQ(env.status, 1) << env.output;
    EXPECT_NE(env.output.find("'nope'"), std::string::npos) << env.output;
    RunResult flag_wins = run("info --context osmesa", "DSR_CONTEXT=nope");
    EXPECT_EQ(flag_wins.status, 0) << flag_wins.output;
}

// The EGL backend (a pbuffer on the device platform; llvmpipe through Mesa's EGL here, a GPU
// elsewhere) renders what OSMesa renders: the same renderer objects, another context.
TEST(Context, EglRendersTheDefaultSceneAsOSMesaDoes) {
    const std::string d = temp_dir();
    RunResult info = run("info --context egl");
    if (info.status != 0) GTEST_SKIP() << "no EGL desktop OpenGL context here: " << info.output;
    EXPECT_NE(info.output.find("context        EGL "), std::string::npos) << info.output;
    RunResult e = run("render --context egl --size 160x120 -o " + d + "/egl.png --stats " + d + "/egl.json");
    ASSERT_EQ(e.status, 0) << e.output;
    RunResult o = run("render --context osmesa --size 160x120 -o " + d + "/osmesa.png");
    ASSERT_EQ(o.status, 0) << o.output;
    ImageDiff diff = compare_images(load_image(d + "/egl.png"), load_image(d + "/osmesa.png"), 1.0 / 255.0);
    std::printf("[ image    ] EGL vs OSMesa, default scene 160x120: max %.1f LSB, %lld pixels over 1 LSB\n",
                diff.max_lsb(), diff.failing);
    EXPECT_LE(diff.max_lsb(), 1.001);
    EXPECT_EQ(diff.failing, 0);
}

TEST(Context, EglDeviceOutOfRangeIsOneClearLine) {
    RunResult info = run("info --context egl");
    if (info.status != 0) GTEST_SKIP() << "no EGL desktop OpenGL context here: " << info.output;
    RunResult r = run("info --context egl --egl-device 15");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--egl-device 15"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

// --render-target pbuffer (docs/gpu.md): every P-buffer and the G-buffer an EGL pbuffer surface of its
// own, copied to its textures; the fbo image within 2 LSB, on both depth paths and with a light
// geometry that needs P-buffer 0's depth and stencil. OSMesa has no pbuffer surfaces: refused.
TEST(Context, PbufferRenderTargetMatchesFbo) {
    const std::string d = temp_dir();
    RunResult info = run("info --context egl");
    if (info.status != 0) GTEST_SKIP() << "no EGL desktop OpenGL context here: " << info.output;
    for (const char* extra : {"--depth texture", "--depth packed --bloom --aa", "--light-geometry stencil"}) {
        SCOPED_TRACE(extra);
        const std::string common = std::string("render --context egl --size 96x80 ") + extra;
        RunResult f = run(common + " --render-target fbo -o " + d + "/fbo.png");
        ASSERT_EQ(f.status, 0) << f.output;
        RunResult p = run(common + " --render-target pbuffer -o " + d + "/pb.png --stats " + d + "/pb.json");
        ASSERT_EQ(p.status, 0) << p.output;
        std::ifstream in(d + "/pb.json");
        const std::string stats((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_NE(stats.find("\"render_target\": \"pbuffer\""), std::string::npos) << stats.substr(0, 400);
        ImageDiff diff = compare_images(load_image(d + "/pb.png"), load_image(d + "/fbo.png"), 2.0 / 255.0);
        EXPECT_LE(diff.max_lsb(), 2.001);
        EXPECT_EQ(diff.failing, 0);
    }
    RunResult refused = run("render --context osmesa --size 32x32 --render-target pbuffer -o " + d + "/no.png");
    EXPECT_NE(refused.status, 0);
    EXPECT_NE(refused.output.find("--context egl"), std::string::npos) << refused.output;
    EXPECT_FALSE(exists(d + "/no.png"));
}
