#include "gl/frame_timer.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "dsr_clock.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/entry_points.h"
#include "gl/state.h"

namespace dsr {

const char* timing_name(TimingSource s) { return s == TimingSource::gpu_timer ? "gpu-timer" : "wall"; }

FrameTimer::~FrameTimer() {
    if (!pool_.empty()) glDeleteQueries(GLsizei(pool_.size()), pool_.data());
}

void FrameTimer::begin_frame(int slots) {
    ms_.assign(size_t(slots), 0.0);
    used_.clear();
    open_ = -1;
    frame_t0_ = now_ms();
}

void FrameTimer::begin(int slot) {
    if (open_ >= 0) throw Error("FrameTimer: stage " + std::to_string(slot) + " begun inside another");
    open_ = slot;
    // A stage run on its own (tests, figures) times into a frame that was never begun.
    if (size_t(slot) >= ms_.size()) ms_.resize(size_t(slot) + 1, 0.0);
    if (source_ == TimingSource::wall) {
        stage_t0_ = now_ms();
        return;
    }
    if (used_.size() == pool_.size()) {
        pool_.push_back(0);
        glGenQueries(1, &pool_.back());
    }
    GLuint q = pool_[used_.size()];
    used_.emplace_back(slot, q);
    glBeginQuery(GL_TIME_ELAPSED, q);
}

void FrameTimer::end() {
    if (open_ < 0) throw Error("FrameTimer: end without begin");
    if (source_ == TimingSource::wall) {
        glFinish();
        ms_[size_t(open_)] += now_ms() - stage_t0_;
    } else {
        glEndQuery(GL_TIME_ELAPSED);
    }
    open_ = -1;
}

double FrameTimer::end_frame(std::vector<double>& stage_ms) {
    if (open_ >= 0) end();
    // The frame ends when the GPU has finished it, waited for by glFinish as the wall-clock stages,
    // the forward renderer and the bench's floor wait. Waiting on the first unfinished query
    // instead makes the frames longer by the time the CPU takes to notice, not the GPU's
    // (docs/gpu_frame.md, "Choices these costs decide").
    if (!used_.empty()) glFinish();
    const double frame_ms = now_ms() - frame_t0_;
    for (auto& [slot, q] : used_) {  // finished: no wait
        GLuint64 ns = 0;
        glGetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
        ms_[size_t(slot)] += double(ns) * 1e-6;
    }
    used_.clear();
    stage_ms = ms_;
    return frame_ms;
}

namespace {

// The calibration work: full-screen additive quads, fixed function, over the current frame buffer.
void draw_passes(int w, int h, int passes) {
    RenderState s = fixed_function_2d();
    s.blend = true;
    s.blend_src = s.blend_dst = GL_ONE;
    gl_state().apply(s);
    glViewport(0, 0, w, h);
    gl_state().set_camera(glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f));  // the unit square
    glColor4f(0.001f, 0.001f, 0.001f, 1.0f);
    for (int i = 0; i < passes; ++i) {
        glBegin(GL_QUADS);
        glVertex2f(0, 0);
        glVertex2f(1, 0);
        glVertex2f(1, 1);
        glVertex2f(0, 1);
        glEnd();
    }
    glColor4f(1, 1, 1, 1);
}

TimingChoice& timing_choice() {
    static TimingChoice c = TimingChoice::measure;
    return c;
}

}  // namespace

void set_timing_choice(TimingChoice c) { timing_choice() = c; }

const TimingCheck& choose_timing(const Caps& caps, int w, int h) {
    static TimingCheck check;
    static bool done = false;
    if (done) return check;
    done = true;
    const TimingChoice forced = timing_choice();
    if (forced == TimingChoice::wall) {
        check.reason = "forced by --timing wall or $DSR_TIMING";
        return check;
    }
    if (!caps.timer_query || !gl_entry.GetQueryObjectui64v) {
        check.reason = "no ARB_timer_query";
        return check;
    }
    if (forced == TimingChoice::gpu_timer) {
        check.source = TimingSource::gpu_timer;
        check.reason = "forced by --timing gpu-timer or $DSR_TIMING";
        return check;
    }
    // Enough work that a real GPU's fill shows and a driver's fixed cost (glFinish's round trip)
    // does not dominate: 4 passes over 1024x1024 in a target of its own where framebuffer
    // objects exist (so the caller's frame buffer is untouched), else over the current one;
    // the best of 3 tries each way.
    const int passes = 4;
    GLuint fbo = 0, rb = 0;
    if (caps.fbo) {
        w = h = 1024;
        glGenFramebuffersEXT(1, &fbo);
        glGenRenderbuffersEXT(1, &rb);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
        glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGBA8, w, h);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, 0);
        glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
        glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_RENDERBUFFER_EXT, rb);
        glDrawBuffer(GL_COLOR_ATTACHMENT0_EXT);
    }
    glFinish();
    double best_wall = 1e30, best_query = 1e30;
    GLuint q = 0;
    glGenQueries(1, &q);
    for (int t = 0; t < 3; ++t) {
        double t0 = now_ms();
        draw_passes(w, h, passes);
        glFinish();
        best_wall = std::min(best_wall, now_ms() - t0);
        glBeginQuery(GL_TIME_ELAPSED, q);
        draw_passes(w, h, passes);
        glEndQuery(GL_TIME_ELAPSED);
        GLuint64 ns = 0;
        glGetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
        best_query = std::min(best_query, double(ns) * 1e-6);
    }
    glDeleteQueries(1, &q);
    if (fbo) {
        glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
        glDeleteFramebuffersEXT(1, &fbo);
        glDeleteRenderbuffersEXT(1, &rb);
        glDrawBuffer(GL_BACK);
    }
    drain_gl_errors();
    check.query_ms = best_query;
    check.wall_ms = best_wall;
    // NOTE: softpipe's queries do read its (synchronous) work, but rendering a frame with
    // timer queries open changes softpipe's image by 1 LSB at some pixels, where glFinish
    // between stages does not; a software rasteriser has no GPU to keep busy, so it always
    // gets the wall clock and its images do not depend on how they were timed.
    const bool software = caps.renderer.find("llvmpipe") != std::string::npos ||
                          caps.renderer.find("softpipe") != std::string::npos ||
                          caps.renderer.find("swrast") != std::string::npos;
    if (best_query < 0.5 * best_wall) {
        check.reason = "timer queries read under half the wall clock: they miss the rasterisation";
    } else if (software) {
        check.reason = "a software rasteriser: the wall clock, as its images differ with timer queries open";
    } else {
        check.source = TimingSource::gpu_timer;
        check.reason = "timer queries read at least half the wall clock";
    }
    return check;
}

}  // namespace dsr
