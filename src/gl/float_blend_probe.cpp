#include "gl/float_blend_probe.h"

#include <cmath>

#include "gl/blit.h"
#include "gl/caps.h"
#include "gl/pbuffer.h"
#include "gl/state.h"

namespace dsr {

bool probe_float_blend(GLenum format) {
    if (!has_extension("GL_EXT_framebuffer_object")) return false;
    float px[4] = {0, 0, 0, 0};
    try {
        PBufferDesc d;
        d.width = d.height = 1;
        d.color_formats = {format};
        PBuffer target("float blend probe", d);
        target.bind_render();
        gl_state().reset();
        gl_state().set_camera(glm::mat4(1));
        RenderState add;
        add.blend = true;
        add.blend_src = add.blend_dst = GL_ONE;
        gl_state().apply(add);
        glClearColor(0.75f, 0.75f, 0.75f, 0.75f);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor4f(0.75f, 0.75f, 0.75f, 0.75f);
        draw_clip_square();
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
        glColor4f(1, 1, 1, 1);
        glClearColor(0, 0, 0, 0);
        target.unbind_render();
    } catch (...) {
        px[0] = 0;  // incomplete framebuffer: no float target to blend into
    }
    gl_state().reset();
    while (glGetError() != GL_NO_ERROR) {}
    return std::fabs(px[0] - 1.5f) < 1e-3f;
}

}  // namespace dsr
