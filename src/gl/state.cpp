#include "gl/state.h"

#include <glm/gtc/type_ptr.hpp>

#include "gl/caps.h"

#include <cstdlib>
#include <cstring>

namespace dsr {

bool RenderState::operator==(const RenderState& o) const {
    return blend == o.blend && blend_src == o.blend_src && blend_dst == o.blend_dst && depth_test == o.depth_test &&
           depth_func == o.depth_func && depth_write == o.depth_write && stencil_test == o.stencil_test &&
           stencil_front == o.stencil_front && stencil_back == o.stencil_back &&
           stencil_two_side_ext == o.stencil_two_side_ext && depth_bounds_test == o.depth_bounds_test && cull == o.cull &&
           cull_face == o.cull_face && scissor == o.scissor && color_write == o.color_write &&
           alpha_test == o.alpha_test && alpha_func == o.alpha_func && alpha_ref == o.alpha_ref &&
           texture_2d == o.texture_2d && tex_env == o.tex_env && program == o.program && dither == o.dither &&
           point_size == o.point_size;
}

RenderState fixed_function_2d() { return RenderState{}; }

RenderState opaque_geometry() {
    RenderState s;
    s.cull = true;
    s.cull_face = GL_BACK;
    s.depth_test = true;
    s.depth_func = GL_LEQUAL;
    s.depth_write = true;
    return s;
}

RenderState textured_2d(GLenum env) {
    RenderState s;
    s.texture_2d = true;
    s.tex_env = env;
    return s;
}

GlState& gl_state() {
    static thread_local GlState state;
    return state;
}

namespace {
void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }
}  // namespace

bool GlState::es() {
    if (!es_known_) {
        es_ = current_gl_is_es();
        es_known_ = true;
    }
    return es_;
}

// The prelude's stand-ins for gl_ModelViewMatrix, gl_ProjectionMatrix and their product; a
// program without them (the compiler removed what it does not read) ignores the location -1.
void GlState::upload_matrices() {
    const GLuint p = cur_.program;
    if (!p) return;
    const glm::mat4 mvp = projection_ * modelview_;
    glUniformMatrix4fv(glGetUniformLocation(p, "dsr_ModelViewMatrix"), 1, GL_FALSE, glm::value_ptr(modelview_));
    glUniformMatrix4fv(glGetUniformLocation(p, "dsr_ProjectionMatrix"), 1, GL_FALSE, glm::value_ptr(projection_));
    glUniformMatrix4fv(glGetUniformLocation(p, "dsr_ModelViewProjectionMatrix"), 1, GL_FALSE, glm::value_ptr(mvp));
}

void GlState::use_program(GLuint program) {
    if (cache_ && valid_ && cur_.program == program) return;
    glUseProgram(program);
    cur_.program = program;
    ++calls_;
    if (es()) upload_matrices();
}

void GlState::set_camera(const glm::mat4& projection, const glm::mat4& modelview) {
    if (es()) {
        projection_ = projection;
        set_modelview(modelview);
        return;
    }
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(projection));
    set_modelview(modelview);
}

void GlState::set_modelview(const glm::mat4& modelview) {
    if (es()) {
        modelview_ = modelview;
        upload_matrices();
        return;
    }
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(modelview));
}

void GlState::apply(const RenderState& s) {
    const bool all = !cache_ || !valid_;
    const RenderState& c = cur_;
    // Each group: set when forced or when any of its fields differs.
    auto diff = [&](bool changed) {
        if (all || changed) {
            ++calls_;
            return true;
        }
        return false;
    };
    if (diff(s.blend != c.blend)) enable(GL_BLEND, s.blend);
    if (diff(s.blend_src != c.blend_src || s.blend_dst != c.blend_dst)) glBlendFunc(s.blend_src, s.blend_dst);
    if (diff(s.depth_test != c.depth_test)) enable(GL_DEPTH_TEST, s.depth_test);
    if (diff(s.depth_func != c.depth_func)) glDepthFunc(s.depth_func);
    if (diff(s.depth_write != c.depth_write)) glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    if (diff(s.stencil_test != c.stencil_test)) enable(GL_STENCIL_TEST, s.stencil_test);
    const StencilFace* faces[2] = {&s.stencil_front, &s.stencil_back};
    const StencilFace* old[2] = {&c.stencil_front, &c.stencil_back};
    const GLenum face_enum[2] = {GL_FRONT, GL_BACK};
    // NOTE: Mesa keeps EXT_stencil_two_side's back face apart from GL 2.0's, so switching between
    // the two ways sets every face field again.
    const bool ext_changed = all || s.stencil_two_side_ext != c.stencil_two_side_ext;
    if (ext_changed && (s.stencil_two_side_ext || has_two_side_ext_)) {
        enable(GL_STENCIL_TEST_TWO_SIDE_EXT, s.stencil_two_side_ext);
        ++calls_;
    }
    for (int f = 0; f < 2; ++f) {
        const StencilFace& n = *faces[f];
        const StencilFace& o = *old[f];
        const bool func = n.func != o.func || n.ref != o.ref || n.mask != o.mask || ext_changed;
        const bool op = n.fail != o.fail || n.zfail != o.zfail || n.zpass != o.zpass || ext_changed;
        const bool wmask = n.write_mask != o.write_mask || ext_changed;
        if (s.stencil_two_side_ext) {
            if (!(all || func || op || wmask)) continue;
            glActiveStencilFaceEXT(face_enum[f]);
            if (diff(func)) glStencilFunc(n.func, n.ref, n.mask);
            if (diff(op)) glStencilOp(n.fail, n.zfail, n.zpass);
            if (diff(wmask)) glStencilMask(n.write_mask);
            glActiveStencilFaceEXT(GL_FRONT);  // Mesa's glGet and glStencilFunc follow the active face
            continue;
        }
        if (diff(func)) glStencilFuncSeparate(face_enum[f], n.func, n.ref, n.mask);
        if (diff(op)) glStencilOpSeparate(face_enum[f], n.fail, n.zfail, n.zpass);
        if (diff(wmask)) glStencilMaskSeparate(face_enum[f], n.write_mask);
    }
    if (s.stencil_two_side_ext) has_two_side_ext_ = true;
    if (diff(s.depth_bounds_test != c.depth_bounds_test) && (s.depth_bounds_test || has_depth_bounds_))
        enable(GL_DEPTH_BOUNDS_TEST_EXT, s.depth_bounds_test);
    if (s.depth_bounds_test) has_depth_bounds_ = true;
    if (diff(s.cull != c.cull)) enable(GL_CULL_FACE, s.cull);
    if (diff(s.cull_face != c.cull_face)) glCullFace(s.cull_face);
    if (diff(s.scissor != c.scissor)) enable(GL_SCISSOR_TEST, s.scissor);
    if (diff(s.color_write != c.color_write)) {
        const GLboolean m = s.color_write ? GL_TRUE : GL_FALSE;
        glColorMask(m, m, m, m);
    }
    const bool fixed_function = !es();
    if (fixed_function) {
        if (diff(s.alpha_test != c.alpha_test)) enable(GL_ALPHA_TEST, s.alpha_test);
        if (diff(s.alpha_func != c.alpha_func || s.alpha_ref != c.alpha_ref)) glAlphaFunc(s.alpha_func, s.alpha_ref);
        // Fixed-function texturing is unit 0's; the passes leave GL_TEXTURE0 active.
        if (all || s.texture_2d != c.texture_2d || s.tex_env != c.tex_env) glActiveTexture(GL_TEXTURE0);
        if (diff(s.texture_2d != c.texture_2d)) enable(GL_TEXTURE_2D, s.texture_2d);
        if (diff(s.tex_env != c.tex_env)) glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(s.tex_env));
    }
    const bool program_changed = diff(s.program != c.program);
    if (program_changed) glUseProgram(s.program);
    if (diff(s.dither != c.dither)) enable(GL_DITHER, s.dither);
    if (fixed_function && diff(s.point_size != c.point_size)) glPointSize(s.point_size);
    cur_ = s;
    valid_ = true;
    if (program_changed && !fixed_function) upload_matrices();
}

RenderState read_gl_state() {
    RenderState s;
    auto geti = [](GLenum e) {
        GLint v = 0;
        glGetIntegerv(e, &v);
        return v;
    };
    s.blend = glIsEnabled(GL_BLEND);
    s.blend_src = GLenum(geti(GL_BLEND_SRC));
    s.blend_dst = GLenum(geti(GL_BLEND_DST));
    s.depth_test = glIsEnabled(GL_DEPTH_TEST);
    s.depth_func = GLenum(geti(GL_DEPTH_FUNC));
    GLboolean b = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &b);
    s.depth_write = b;
    s.stencil_test = glIsEnabled(GL_STENCIL_TEST);
    s.stencil_front = {GLenum(geti(GL_STENCIL_FUNC)),       geti(GL_STENCIL_REF),
                       GLuint(geti(GL_STENCIL_VALUE_MASK)), GLenum(geti(GL_STENCIL_FAIL)),
                       GLenum(geti(GL_STENCIL_PASS_DEPTH_FAIL)), GLenum(geti(GL_STENCIL_PASS_DEPTH_PASS)),
                       GLuint(geti(GL_STENCIL_WRITEMASK))};
    s.stencil_back = {GLenum(geti(GL_STENCIL_BACK_FUNC)),       geti(GL_STENCIL_BACK_REF),
                      GLuint(geti(GL_STENCIL_BACK_VALUE_MASK)), GLenum(geti(GL_STENCIL_BACK_FAIL)),
                      GLenum(geti(GL_STENCIL_BACK_PASS_DEPTH_FAIL)), GLenum(geti(GL_STENCIL_BACK_PASS_DEPTH_PASS)),
                      GLuint(geti(GL_STENCIL_BACK_WRITEMASK))};
    // GL keeps masks to the stencil buffer's 8 bits (and reads ~0 back clamped to INT_MAX).
    for (StencilFace* f : {&s.stencil_front, &s.stencil_back}) {
        f->mask &= 0xffu;
        f->write_mask &= 0xffu;
    }
    // Extension state only where the extension exists (glIsEnabled of an unknown enum is an error).
    if (has_extension("GL_EXT_stencil_two_side")) s.stencil_two_side_ext = glIsEnabled(GL_STENCIL_TEST_TWO_SIDE_EXT);
    if (has_extension("GL_EXT_depth_bounds_test")) s.depth_bounds_test = glIsEnabled(GL_DEPTH_BOUNDS_TEST_EXT);
    s.cull = glIsEnabled(GL_CULL_FACE);
    s.cull_face = GLenum(geti(GL_CULL_FACE_MODE));
    s.scissor = glIsEnabled(GL_SCISSOR_TEST);
    GLboolean cm[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    glGetBooleanv(GL_COLOR_WRITEMASK, cm);
    s.color_write = cm[0] && cm[1] && cm[2] && cm[3];
    s.alpha_test = glIsEnabled(GL_ALPHA_TEST);
    s.alpha_func = GLenum(geti(GL_ALPHA_TEST_FUNC));
    GLfloat ref = 0;
    glGetFloatv(GL_ALPHA_TEST_REF, &ref);
    s.alpha_ref = ref;
    GLint active = geti(GL_ACTIVE_TEXTURE);
    glActiveTexture(GL_TEXTURE0);
    s.texture_2d = glIsEnabled(GL_TEXTURE_2D);
    GLint env = 0;
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &env);
    s.tex_env = GLenum(env);
    glActiveTexture(GLenum(active));
    s.program = GLuint(geti(GL_CURRENT_PROGRAM));
    s.dither = glIsEnabled(GL_DITHER);
    glGetFloatv(GL_POINT_SIZE, &s.point_size);
    return s;
}

}  // namespace dsr
