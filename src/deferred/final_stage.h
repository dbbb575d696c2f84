// Final stage (§3.6, Appendix A step 4): P-buffer 0 drawn into the main frame buffer by fixed
// function, scaled with bilinear filtering when the output size differs from the buffers'. The
// debug views (--view) draw their buffers the same way.
#pragma once
#include <glm/glm.hpp>

#include "deferred/render_targets.h"
#include "gl/gl.h"

namespace dsr {

class FinalStage {
public:
    // fbo: the P-buffers are framebuffer objects (the main one is bound back first).
    explicit FinalStage(bool fbo) : fbo_(fbo) {}
    void draw(const RenderTargets& targets, int out_w, int out_h) const;
    // Any texture, its content `extent` in texture coordinates, into the main frame buffer.
    void draw_texture(GLuint texture, int out_w, int out_h, glm::vec2 extent = {1, 1}) const;

private:
    bool fbo_;
};

}  // namespace dsr
