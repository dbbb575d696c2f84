#include "gl/blit.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

void draw_texture_to_framebuffer0(GLuint texture, int out_w, int out_h, glm::vec2 ts, bool has_fbo) {
    if (has_fbo) glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);  // no-FBO path: already there
    glDrawBuffer(GL_BACK);
    glViewport(0, 0, out_w, out_h);
    gl_state().set_camera(glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f));  // the unit square
    gl_state().apply(textured_2d(GL_REPLACE));  // fixed function, every test off
    glColor4f(1, 1, 1, 1);
    glBindTexture(GL_TEXTURE_2D, texture);
    // Same size: nearest is exact. Scaled: bilinear (§3.6, e.g. 512x512 shown at 640x480).
    GLint tw = 0, th = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &tw);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &th);
    const bool same = std::lround(tw * ts.x) == out_w && std::lround(th * ts.y) == out_h;
    GLint filter = same ? GL_NEAREST : GL_LINEAR, old_min = 0, old_mag = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &old_min);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &old_mag);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(ts.x, 0); glVertex2f(1, 0);
    glTexCoord2f(ts.x, ts.y); glVertex2f(1, 1);
    glTexCoord2f(0, ts.y); glVertex2f(0, 1);
    glEnd();
    // Leave the texture as the post passes expect it (they sample P-buffer 0 bilinearly).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, old_min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, old_mag);
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl_stage("drawing a texture into the main frame buffer (final stage)");
}

void draw_clip_square() {
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
}

}  // namespace dsr
