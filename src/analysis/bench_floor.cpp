// The frame's floor (bench_floor.h): the fill floor, the light pass's per-fragment floor, the
// post floor's arithmetic.
#include "analysis/bench_floor.h"

#include <algorithm>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "deferred/gpu_scene.h"
#include "deferred/render_targets.h"
#include "dsr_clock.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/pbuffer.h"
#include "gl/program.h"
#include "gl/state.h"

namespace dsr::bench {

std::optional<double> floor_ms(const FloorParts& f, std::optional<long long> ideal) {
    if (!ideal) return std::nullopt;
    return f.fill_ms + double(*ideal) * f.light_ns_per_fragment * 1e-6 + f.post_ms + f.output_ms;
}

std::optional<double> floor_ratio(double ms_median, std::optional<double> floor) {
    if (!floor || !(*floor > 0)) return std::nullopt;
    return ms_median / *floor;
}

long long post_texel_reads(const PostOptions& post, int w, int h) {
    long long n = 0;
    const long long full = (long long)w * h;
    if (post.bloom) {
        const int s = std::max(1, post.bloom_scale);
        const long long small = (long long)std::max(1, w / s) * std::max(1, h / s);
        n += 2 * small * post.bloom_taps + full;  // horizontal and vertical blur, then the add
    }
    if (post.aa) {
        const bool normal = post.aa_source != AaSource::depth, depth = post.aa_source != AaSource::normal;
        n += full * (9 * normal + 9 * depth + 9);
    }
    return n;
}

double post_floor_ms(const PostOptions& post, int w, int h, double light_ns_per_fragment) {
    return double(post_texel_reads(post, w, h)) * light_ns_per_fragment / 4.0 * 1e-6;
}

FloorBench::FloorBench(const Caps& caps, int w, int h, const GbufferLayout& layout, const std::string& shader_dir)
    : w_(w), h_(h), layout_(layout) {
    if (!caps.fbo) throw Error("bench floor: needs EXT_framebuffer_object");
    PBufferDesc g;
    g.width = w, g.height = h;
    for (TargetFormat f : layout.formats) g.color_formats.push_back(gl_format(f));
    g.depth = layout.depth_texture ? DepthAttachment::texture : DepthAttachment::renderbuffer;
    gbuf_ = std::make_unique<PBuffer>("floor G-buffer", g);
    PBufferDesc a;
    a.width = w, a.height = h;
    a.color_formats = {GL_RGBA8};
    a.filter = GL_LINEAR;
    accum_ = std::make_unique<PBuffer>("floor P-buffer 0", a);
    fill_ = std::make_unique<Program>(shader_dir, "floor_fill.vert", "floor_fill.frag",
                                      std::vector<std::string>{"TARGETS " + std::to_string(layout.formats.size())});
    light_ = std::make_unique<Program>(shader_dir, "post.vert", "floor_light.frag");
    light_->use();
    for (int u = 0; u < 4; ++u) light_->set(("t" + std::to_string(u)).c_str(), u);
    gl_state().use_program(0);
    check_gl("bench floor: creating its buffers and programs");
}

FloorBench::~FloorBench() = default;

void FloorBench::set_scene(const Scene& scene) { gpu_ = std::make_unique<GpuScene>(scene); }

double FloorBench::fill_frame(const Scene& scene) {
    if (!gpu_) throw Error("bench floor: fill_frame before set_scene");
    glFinish();  // nothing of the previous work in this frame's time
    const double t0 = now_ms();
    gbuf_->bind_render();
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(scene.camera.projection(float(w_) / float(h_))));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(scene.camera.view()));
    gpu_->set_view(scene.camera.view_d());
    RenderState s;  // one pass: the depth pre-pass's geometry state with colour on and a shader
    s.cull = true;
    s.cull_face = GL_BACK;
    s.depth_test = true;
    s.depth_func = GL_LEQUAL;
    s.depth_write = true;
    s.program = fill_->id();
    gl_state().apply(s);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gpu_->bind_positions();
    gpu_->draw_all();
    gpu_->unbind();
    gbuf_->unbind_render();
    glFinish();
    const double ms = now_ms() - t0;
    check_gl("bench floor: fill pass");
    return ms;
}

// draw() into the output target under the pixel camera, between two glFinish calls: its wall ms.
template <class Draw>
double FloorBench::output_pass_ms(const char* what, Draw&& draw) {
    glFinish();
    const double t0 = now_ms();
    accum_->bind_render();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w_, 0, h_, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    draw();
    accum_->unbind_render();
    glFinish();
    const double ms = now_ms() - t0;
    check_gl(what);
    return ms;
}

double FloorBench::light_batch_ms(int passes) {
    const int targets[4] = {0, 1, 2, layout_.depth_texture ? PBuffer::DEPTH : 3};
    return output_pass_ms("bench floor: light passes", [&] {
        RenderState s;  // the light pass's state: additive, no depth test
        s.blend = true;
        s.blend_src = s.blend_dst = GL_ONE;
        s.program = light_->id();
        gl_state().apply(s);
        for (int u = 0; u < 4; ++u) gbuf_->bind_texture(targets[u], u);
        for (int i = 0; i < passes; ++i) {
            glBegin(GL_QUADS);
            const float xs[4] = {0, float(w_), float(w_), 0}, ys[4] = {0, 0, float(h_), float(h_)};
            for (int k = 0; k < 4; ++k) {
                glMultiTexCoord2f(GL_TEXTURE0, xs[k] / float(w_), ys[k] / float(h_));
                glVertex2f(xs[k], ys[k]);
            }
            glEnd();
        }
        for (int u = 3; u >= 0; --u) gbuf_->unbind_texture(targets[u], u);
    });
}

double FloorBench::light_ns_per_fragment(int batches) {
    light_batch_ms(1);  // warm-up: shader compiled on first draw
    const double one = std::max(1e-3, light_batch_ms(1));
    const int passes = std::clamp(int(30.0 / one), 2, 256);
    std::vector<double> ns;
    for (int b = 0; b < batches; ++b)
        ns.push_back(light_batch_ms(passes) * 1e6 / (double(passes) * w_ * h_));
    return median(ns);
}

// `n` times a one-pixel point into the output target, each after a clear of the whole target with
// `clear`. The point keeps a GL from merging a clear into the next one.
double FloorBench::output_batch_ms(int n, bool clear) {
    return output_pass_ms("bench floor: output clears", [&] {
        gl_state().apply(RenderState{});  // fixed function, no scissor, every channel written
        glClearColor(0, 0, 0, 0);
        for (int i = 0; i < n; ++i) {
            if (clear) glClear(GL_COLOR_BUFFER_BIT);
            glBegin(GL_POINTS);
            glVertex2f(0.5f, 0.5f);
            glEnd();
        }
    });
}

double FloorBench::output_clear_ms(int batches) {
    output_batch_ms(2, true);  // warm-up
    const double one = std::max(1e-3, output_batch_ms(4, true) / 4);
    const int n = std::clamp(int(30.0 / one), 4, 1024);
    std::vector<double> with, without;
    for (int b = 0; b < batches; ++b) {
        with.push_back(output_batch_ms(n, true));
        without.push_back(output_batch_ms(n, false));
    }
    return std::max(0.0, (median(with) - median(without)) / n);
}

}  // namespace dsr::bench
