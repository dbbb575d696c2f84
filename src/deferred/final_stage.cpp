// Final stage (§3.6): P-buffer 0 drawn into the main frame buffer by fixed function,
// scaled with bilinear filtering when the output size differs from the buffers'.
#include "deferred/deferred_shader.h"
#include "gl/blit.h"

namespace dsr {

void DeferredShader::final_stage(int out_w, int out_h) {
    const PBuffer& accum = pbuf(P_ACCUM);
    draw_texture_to_main(accum.texture(0), out_w, out_h, {accum.tex_scale_x(), accum.tex_scale_y()});
}

void DeferredShader::draw_texture_to_main(GLuint texture, int out_w, int out_h, glm::vec2 ts) {
    draw_texture_to_framebuffer0(texture, out_w, out_h, ts, caps_.fbo);
}

}  // namespace dsr
