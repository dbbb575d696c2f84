// The final stage (final_stage.h).
#include "deferred/final_stage.h"

#include "gl/blit.h"

namespace dsr {

void FinalStage::draw(const RenderTargets& t, int out_w, int out_h) const {
    const PBuffer& accum = t.pbuffer(P_ACCUM);
    draw_texture(accum.texture(0), out_w, out_h, {accum.tex_scale_x(), accum.tex_scale_y()});
}

void FinalStage::draw_texture(GLuint texture, int out_w, int out_h, glm::vec2 extent) const {
    draw_texture_to_framebuffer0(texture, out_w, out_h, extent, fbo_);
}

}  // namespace dsr
