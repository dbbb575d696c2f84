// The tiles geometry's depth culling (tile_plan.h TileDepth): a pass of one fragment per tile column
// and window row (glsl120/tile_depth.frag) into a float target, a second that takes each tile's rows
// together (tile_depth_reduce.frag), and a read-back of one texel per tile give each tile's span of
// surface eye z; the plan then leaves out a tile's lights whose sphere lies wholly in front of or behind its
// surfaces. The read-back waits for the geometry pass, which the light passes wait for anyway; on a
// GPU it is a pipeline drain, measured with the rest of the light stage (ms.lights).
#include <algorithm>

#include "deferred/deferred_shader.h"
#include "deferred/screen_quad.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

// At construction and resize, never inside a frame: creating its texture would disturb the
// G-buffer's texture bindings. Needs a float target behind a framebuffer object; without them the
// plan runs without depth culling.
void DeferredShader::make_tile_depth_buf() {
    tile_depth_buf_.reset();
    tile_depth_rows_.reset();
    if (!opts_.tile_depth || paths_.light_geometry != LightGeometry::tiles) return;
    if (!caps_.fbo || !caps_.texture_float || !gbuf().uses_fbo()) return;
    if (!tile_depth_prog_.id()) {
        std::vector<std::string> defs = depth_defines();
        defs.push_back("TILE_SIZE " + std::to_string(opts_.tile_size));
        tile_depth_prog_ = Program(shader_dir_, "post.vert", "tile_depth.frag", defs);
    }
    if (!tile_reduce_prog_.id())
        tile_reduce_prog_ = Program(shader_dir_, "post.vert", "tile_depth_reduce.frag",
                                    {"TILE_SIZE " + std::to_string(opts_.tile_size)});
    const int ts = opts_.tile_size;
    PBufferDesc d;
    d.width = (w_ + ts - 1) / ts;
    d.height = h_;  // a fragment per row of a tile
    d.color_formats = {GL_RGBA32F_ARB};
    d.pow2 = !caps_.npot;
    tile_depth_rows_ = std::make_unique<PBuffer>("tile depth rows", d);
    d.height = (h_ + ts - 1) / ts;  // a texel per tile
    tile_depth_buf_ = std::make_unique<PBuffer>("tile depth", d);
}

// Called with P-buffer 0 bound for rendering and the G-buffer's targets bound on units 0..3; leaves
// them so. Empty without the buffer (make_tile_depth_buf).
std::vector<DepthSpan> DeferredShader::tile_depth_spans() {
    if (!tile_depth_buf_) return {};
    const int tx = tile_depth_buf_->width(), ty = tile_depth_buf_->height(), rows = tile_depth_rows_->height();
    fb_unbind_render(P_ACCUM);
    RenderState s = fixed_function_2d();  // spans written, not blended
    // Pass 1: each tile column's span over each window row.
    tile_depth_rows_->bind_render();
    set_ortho(tx, rows);
    s.program = tile_depth_prog_.id();
    gl_state().apply(s);
    tile_depth_prog_.set("normal_map", 0);
    tile_depth_prog_.set("depth_map", 3);
    tile_depth_prog_.set("planes", planes_);
    tile_depth_prog_.set("zrange", zrange_);
    tile_depth_prog_.set("texel", gbuffer_uv_scale());
    tile_depth_prog_.set("size", glm::vec2(float(w_), float(h_)));
    draw_quad(float(tx), float(rows), 1, 1);  // both passes read gl_FragCoord, not texture coordinates
    tile_depth_rows_->unbind_render();
    // Pass 2: each tile's rows together, on unit 4 (not one of the G-buffer's 0..3).
    tile_depth_buf_->bind_render();
    set_ortho(tx, ty);
    s.program = tile_reduce_prog_.id();
    gl_state().apply(s);
    tile_depth_rows_->bind_texture(0, 4);
    tile_reduce_prog_.set("row_spans", 4);
    tile_reduce_prog_.set("texel", glm::vec2(1.0f / float(tile_depth_rows_->texture_width()),
                                             1.0f / float(tile_depth_rows_->texture_height())));
    tile_reduce_prog_.set("rows", float(rows));
    draw_quad(float(tx), float(ty), 1, 1);
    // Read from the bound framebuffer: one texel per tile, two floats used of four.
    std::vector<float> px(size_t(tx) * ty * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, tx, ty, GL_RGBA, GL_FLOAT, px.data());
    tile_depth_rows_->unbind_texture(0, 4);
    tile_depth_buf_->unbind_render();
    glActiveTexture(GL_TEXTURE0);
    fb_bind_render(P_ACCUM);  // framebuffer objects keep its contents
    set_ortho(w_, h_);
    check_gl("tile depth spans");
    std::vector<DepthSpan> spans(size_t(tx) * ty);
    for (size_t t = 0; t < spans.size(); ++t) spans[t] = DepthSpan{px[4 * t], px[4 * t + 1]};
    return spans;
}

}  // namespace dsr
