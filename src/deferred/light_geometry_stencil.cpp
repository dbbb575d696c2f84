// Light geometry `stencil` (Vasilovici §4.2; ogldev's stencil light volumes): per light, a
// stencil pass over the whole volume mesh, colour writes off, counting with the depth test
// against the scene's depth (handed to P-buffer 0): a back face behind the surface adds one, a
// front face behind it takes one away (GL_INCR_WRAP / GL_DECR_WRAP on depth fail). What stays
// non-zero is exactly where the surface lies inside the volume, also with the camera inside it
// (its clipped front faces would have passed the depth test anyway). Then the light pass over
// the back faces, only where the stencil is non-zero, zeroing it for the next light; its shader
// has no discard (light_stencil_prog_), so the GPU can test the stencil before running it.
// The two faces in one pass with glStencilOpSeparate (GL 2.0) or EXT_stencil_two_side; with
// neither, two one-sided passes (back faces, then front faces).
#include <glm/gtc/type_ptr.hpp>

#include "deferred/deferred_shader.h"
#include "deferred/light_queries.h"
#include "gl/state.h"

namespace dsr {

namespace {

StencilFace counting_face(GLenum zfail) {
    StencilFace f;
    f.func = GL_ALWAYS;
    f.zfail = zfail;
    return f;
}

}  // namespace

void DeferredShader::draw_lights_stencil(const std::vector<LightDraw>& lights, FrameStats& stats) {
    LightQueries q(counting_ && paths_.count_fragments, counting_ && caps_.pipeline_statistics);
    begin_light_meshes(lights, q, stats);  // light_geometry_volume.cpp

    // The stencil pass: no colour, no shader, depth tested (GL_LESS: a face on or behind the
    // surface fails), nothing written but the stencil.
    RenderState mark;
    mark.color_write = false;
    mark.depth_test = true;
    mark.depth_func = GL_LESS;
    mark.depth_write = false;
    mark.stencil_test = true;
    const Paths::StencilFaces faces = paths_.stencil_faces;
    mark.stencil_two_side_ext = faces == Paths::StencilFaces::two_side_ext;
    mark.stencil_front = counting_face(GL_DECR_WRAP);
    mark.stencil_back = counting_face(GL_INCR_WRAP);
    // One-sided: the same op on both faces, each pass culling the other face.
    RenderState mark_back = mark, mark_front = mark;
    mark_back.stencil_front = mark_back.stencil_back = counting_face(GL_INCR_WRAP);
    mark_back.cull = true;
    mark_back.cull_face = GL_FRONT;
    mark_front.stencil_front = mark_front.stencil_back = counting_face(GL_DECR_WRAP);
    mark_front.cull = true;
    mark_front.cull_face = GL_BACK;

    // The light pass: back faces (each pixel of the volume's outline once), where the stencil is
    // non-zero; the pass zeroes what it passes, so every light starts from a clear stencil.
    RenderState light = light_pass_state(light_stencil_prog_.id(), false);
    light.cull = true;
    light.cull_face = GL_FRONT;
    light.stencil_test = true;
    StencilFace lit;
    lit.func = GL_NOTEQUAL;
    lit.ref = 0;
    lit.zpass = GL_ZERO;
    light.stencil_front = light.stencil_back = lit;
    light.stencil_two_side_ext = mark.stencil_two_side_ext;

    for (const LightDraw& l : lights) {
        if (mesh_past_far(l)) continue;
        if (faces == Paths::StencilFaces::one_sided) {
            gl_state().apply(mark_back);
            draw_light_mesh(l);
            gl_state().apply(mark_front);
            draw_light_mesh(l);
        } else {
            gl_state().apply(mark);
            draw_light_mesh(l);
        }
        gl_state().apply(light);
        draw_light_mesh_pass(l, q, light_stencil_prog_);  // light_geometry_volume.cpp
    }
    end_light_meshes(q, stats);
}

}  // namespace dsr
