// The tiles geometry's depth culling (tile_plan.h TileDepth): a pass of one fragment per tile column
// and window row (glsl120/tile_depth.frag) into a small float target, read back and taken together
// per tile, gives each tile's span of surface eye z; the plan then leaves out a tile's lights whose sphere lies wholly in front of or behind its
// surfaces. The read-back waits for the geometry pass, which the light passes wait for anyway; on a
// GPU it is a pipeline drain, measured with the rest of the light stage (ms.lights).
#include <algorithm>

#include "deferred/deferred_shader.h"
#include "gl/check.h"
#include "gl/readback.h"
#include "gl/state.h"

namespace dsr {

// At construction and resize, never inside a frame: creating its texture would disturb the
// G-buffer's texture bindings. Needs a float target behind a framebuffer object; without them the
// plan runs without depth culling.
void DeferredShader::make_tile_depth_buf() {
    tile_depth_buf_.reset();
    if (!opts_.tile_depth || paths_.light_geometry != LightGeometry::tiles) return;
    if (!caps_.fbo || !caps_.texture_float || !gbuf().uses_fbo()) return;
    if (!tile_depth_prog_.id()) {
        std::vector<std::string> defs = depth_defines();
        defs.push_back("TILE_SIZE " + std::to_string(opts_.tile_size));
        tile_depth_prog_ = Program(shader_dir_, "post.vert", "tile_depth.frag", defs);
    }
    const int ts = opts_.tile_size;
    PBufferDesc d;
    d.width = (w_ + ts - 1) / ts;
    d.height = h_;  // a fragment per row of a tile
    d.color_formats = {GL_RGBA32F_ARB};
    d.pow2 = !caps_.npot;
    tile_depth_buf_ = std::make_unique<PBuffer>("tile depth", d);
}

// Called with P-buffer 0 bound for rendering and the G-buffer's targets bound on units 0..3; leaves
// them so. Empty without the buffer (make_tile_depth_buf).
std::vector<DepthSpan> DeferredShader::tile_depth_spans() {
    if (!tile_depth_buf_) return {};
    const int ts = opts_.tile_size;
    const int tx = tile_depth_buf_->width(), rows = tile_depth_buf_->height(), ty = (rows + ts - 1) / ts;
    fb_unbind_render(P_ACCUM);
    tile_depth_buf_->bind_render();
    set_ortho(tx, rows);
    RenderState s = fixed_function_2d();  // spans written, not blended
    s.program = tile_depth_prog_.id();
    gl_state().apply(s);
    tile_depth_prog_.set("normal_map", 0);
    tile_depth_prog_.set("depth_map", 3);
    tile_depth_prog_.set("planes", planes_);
    tile_depth_prog_.set("zrange", zrange_);
    tile_depth_prog_.set("texel", glm::vec2(gbuf().tex_scale_x() / float(w_), gbuf().tex_scale_y() / float(h_)));
    tile_depth_prog_.set("size", glm::vec2(float(w_), float(h_)));
    glBegin(GL_QUADS);
    glVertex2f(0, 0), glVertex2f(float(tx), 0), glVertex2f(float(tx), float(rows)), glVertex2f(0, float(rows));
    glEnd();
    tile_depth_buf_->unbind_render();
    const PBuffer& pb = *tile_depth_buf_;
    glActiveTexture(GL_TEXTURE4);  // read_texture binds on the active unit: not one of the G-buffer's 0..3
    const Image img = read_texture(pb.texture(0), tx, rows, pb.texture_width(), pb.texture_height(), false);
    glActiveTexture(GL_TEXTURE0);
    fb_bind_render(P_ACCUM);  // framebuffer objects keep its contents
    set_ortho(w_, h_);
    check_gl("tile depth spans");
    std::vector<DepthSpan> spans(size_t(tx) * ty, DepthSpan{1e30f, -1e30f});
    for (int r = 0; r < rows; ++r)
        for (int x = 0; x < tx; ++x) {
            const float* p = img.at(x, r);
            DepthSpan& s = spans[size_t(r / ts) * tx + x];
            s.lo = std::min(s.lo, p[0]), s.hi = std::max(s.hi, p[1]);
        }
    return spans;
}

}  // namespace dsr
