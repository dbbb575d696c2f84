#include "gl/invocation_probe.h"

#include "gl/caps.h"
#include "gl/check.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "gl/state.h"

namespace dsr {

std::optional<InvocationProbe> probe_invocation_counter(const std::string& shader_dir, int size) {
    const Caps caps = probe_caps();
    GLint stencil_bits = 0;
    glGetIntegerv(GL_STENCIL_BITS, &stencil_bits);
    if (!caps.pipeline_statistics || !caps.occlusion_query || stencil_bits <= 0) return std::nullopt;
    Program prog(shader_dir, "post.vert", "invocation_probe.frag", {});
    RenderState s = fixed_function_2d();
    s.program = prog.id();
    s.color_write = false;
    s.stencil_test = true;
    s.stencil_front.func = s.stencil_back.func = GL_NEVER;
    s.stencil_front.write_mask = s.stencil_back.write_mask = 0;
    gl_state().apply(s);
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glViewport(0, 0, size, size);  // size x size pixels, whatever the framebuffer's size
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, size, 0, size, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    GLuint q[2] = {0, 0};
    glGenQueries(2, q);
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, q[1]);
    glBegin(GL_QUADS);
    glVertex2f(0, 0), glVertex2f(float(size), 0), glVertex2f(float(size), float(size)), glVertex2f(0, float(size));
    glEnd();
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0, invocations = 0;
    glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &samples);
    glGetQueryObjectuiv(q[1], GL_QUERY_RESULT, &invocations);
    glDeleteQueries(2, q);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    gl_state().apply(fixed_function_2d());
    check_gl("invocation counter probe");
    InvocationProbe p;
    p.pixels = (long long)size * size;
    p.invocations = (long long)invocations;
    p.samples = (long long)samples;
    return p;
}

}  // namespace dsr
