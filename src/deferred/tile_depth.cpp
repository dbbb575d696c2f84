// The tiles' depth spans (tile_depth.h).
#include "deferred/tile_depth.h"

#include <chrono>
#include <string>
#include <thread>

#include "deferred/render_targets.h"
#include "deferred/screen_quad.h"
#include "deferred/tile_spans.h"
#include "dsr_clock.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

namespace {

// Between two looks at the query: short against the spans' wait on a GPU (the G-buffer's fill,
// about a millisecond at 1920x1080), so that the read-back starts soon after the GPU is done.
constexpr auto kPollSleep = std::chrono::microseconds(20);

// Waits for the GPU to finish what the read-back reads, timed into stats (where given): the
// read-back after it then copies and does not wait, so the wait and the copy are told apart.
// With `drawn` (an occlusion query ended after the last pass the read-back reads), the thread
// sleeps between looks at whether its result has come, instead of glFinish, which a GPU's
// driver may spend spinning.
void wait_for_gpu(GLuint drawn, TileStats* stats) {
    const double wall = now_ms(), cpu = thread_cpu_ms();
    if (drawn) {
        glFlush();  // the passes handed to the GPU, or the result never comes
        for (GLuint done = 0;;) {
            glGetQueryObjectuiv(drawn, GL_QUERY_RESULT_AVAILABLE, &done);
            if (done) break;
            std::this_thread::sleep_for(kPollSleep);
        }
    } else {
        glFinish();
    }
    if (!stats) return;
    stats->wait_ms += now_ms() - wall;
    stats->wait_cpu_ms += thread_cpu_ms() - cpu;
}

}  // namespace

TileDepthPass::TileDepthPass(const ShaderConfig& c, ProgramSet& programs, int width, int height)
    : tile_size_(c.opts.tile_size), pow2_(!c.caps.npot), readback_(tile_spans_by_readback(c)) {
    if (!readback_) {
        rows_prog_ = programs.take("tile_depth");
        reduce_prog_ = programs.take("tile_depth_reduce");
        if (c.caps.occlusion_query) glGenQueries(1, &drawn_query_);
    }
    resize(width, height);
}

TileDepthPass::~TileDepthPass() {
    if (drawn_query_) glDeleteQueries(1, &drawn_query_);
}

void TileDepthPass::resize(int w, int h) {
    tiles_.reset();
    rows_.reset();
    if (readback_) return;  // no buffers of its own
    const int ts = tile_size_;
    PBufferDesc d;
    d.width = (w + ts - 1) / ts;
    d.height = h;  // a fragment per row of a tile
    d.color_formats = {GL_RGBA32F_ARB};
    d.pow2 = pow2_;
    rows_ = std::make_unique<PBuffer>("tile depth rows", d);
    d.height = (h + ts - 1) / ts;  // a texel per tile
    tiles_ = std::make_unique<PBuffer>("tile depth", d);
}

std::vector<DepthSpan> TileDepthPass::spans(const FrameDef& f, const PBuffer& gbuffer, TileTimeline* timeline,
                                            TileStats* stats) {
    if (readback_) return spans_by_readback(f, gbuffer, stats);
    const int tx = tiles_->width(), ty = tiles_->height(), rows = rows_->height();
    RenderState s = fixed_function_2d();  // spans written, not blended
    // Pass 1: each tile column's span over each window row.
    rows_->bind_render();
    gl_state().set_camera(pixel_ortho(float(tx), float(rows)));
    s.program = rows_prog_.id();
    gl_state().apply(s);
    rows_prog_.set("normal_map", 0);
    rows_prog_.set("depth_map", 3);
    rows_prog_.set("planes", f.planes);
    rows_prog_.set("zrange", f.zrange);
    rows_prog_.set("texel", f.uv_scale);
    rows_prog_.set("size", glm::vec2(float(f.width), float(f.height)));
    draw_quad(float(tx), float(rows), 1, 1);  // both passes read gl_FragCoord, not texture coordinates
    rows_->unbind_render();
    // Pass 2: each tile's rows together, on unit 4 (not one of the G-buffer's 0..3).
    tiles_->bind_render();
    gl_state().set_camera(pixel_ortho(float(tx), float(ty)));
    s.program = reduce_prog_.id();
    gl_state().apply(s);
    rows_->bind_texture(0, 4);
    reduce_prog_.set("row_spans", 4);
    reduce_prog_.set("texel", glm::vec2(1.0f / float(rows_->texture_width()), 1.0f / float(rows_->texture_height())));
    reduce_prog_.set("rows", float(rows));
    if (drawn_query_) glBeginQuery(GL_SAMPLES_PASSED, drawn_query_);
    draw_quad(float(tx), float(ty), 1, 1);
    if (drawn_query_) glEndQuery(GL_SAMPLES_PASSED);
    // Read from the bound framebuffer: one texel per tile, two floats used of four.
    std::vector<float> px(size_t(tx) * ty * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (timeline) timeline->mark(TileTimeline::spans_end);
    wait_for_gpu(drawn_query_, stats);
    glReadPixels(0, 0, tx, ty, GL_RGBA, GL_FLOAT, px.data());
    rows_->unbind_texture(0, 4);
    tiles_->unbind_render();
    glActiveTexture(GL_TEXTURE0);
    check_gl_stage("tile depth spans");
    std::vector<DepthSpan> out(size_t(tx) * ty);
    for (size_t i = 0; i < out.size(); ++i) out[i] = DepthSpan{px[4 * i], px[4 * i + 1]};
    return out;
}

std::vector<DepthSpan> TileDepthPass::spans_by_readback(const FrameDef& f, const PBuffer& gbuffer, TileStats* stats) {
    // Texel (x, y) is window pixel (x, y): the G-buffer is the frame's size (padded to powers of
    // two at most, which the stride takes).
    if (gbuffer.width() != f.width || gbuffer.height() != f.height)
        throw Error("tile depth spans: the G-buffer (" + std::to_string(gbuffer.width()) + "x" +
                    std::to_string(gbuffer.height()) + ") is not the frame's size");
    const int tw = gbuffer.texture_width(), th = gbuffer.texture_height();
    depth_.resize(size_t(tw) * size_t(th));
    normal_.resize(size_t(tw) * size_t(th) * 4);
    wait_for_gpu(0, stats);  // no pass of its own to query: the G-buffer's draws are another stage's
    // On unit 4, not one of the G-buffer's 0..3, and unbound again.
    glActiveTexture(GL_TEXTURE4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, gbuffer.texture(PBuffer::DEPTH));
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth_.data());
    glBindTexture(GL_TEXTURE_2D, gbuffer.texture(G_NORMAL));
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, normal_.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    check_gl_stage("tile depth spans (read back)");
    return spans_from_depth(GbufferReadback{depth_.data(), normal_.data(), tw}, f.width, f.height, tile_size_,
                            f.planes, f.camera.far_plane);
}

}  // namespace dsr
