// Shadow maps through the main frame buffer (main_buffer_map.h).
#include "deferred/main_buffer_map.h"

namespace dsr {

int main_buffer_depth_bits() {
    GLint bits = 0;
    glGetIntegerv(GL_DEPTH_BITS, &bits);
    return int(bits);
}

bool shadow_maps_packed(const Caps& caps) {
    return maps_packed(caps.depth_texture, caps.shadow, !caps.fbo, caps.fbo ? 0 : main_buffer_depth_bits());
}

void draw_through_main_buffer(GLuint texture, const std::vector<MapPiece>& pieces, bool depth, GLbitfield clear,
                              const std::function<void(const MapPiece&)>& draw) {
    if (!depth) {
        // Read from the buffer the pass draws into (the back buffer of a window, OSMesa's one).
        GLint draw_buffer = GL_BACK;
        glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
        glReadBuffer(GLenum(draw_buffer));
    }
    for (const MapPiece& p : pieces) {
        glScissor(0, 0, p.width, p.height);
        glClear(clear);
        draw(p);
        // glCopyTexSubImage2D copies depth into a depth texture, colour into a colour one.
        glBindTexture(GL_TEXTURE_2D, texture);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, p.x, p.y, 0, 0, p.width, p.height);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
}

}  // namespace dsr
