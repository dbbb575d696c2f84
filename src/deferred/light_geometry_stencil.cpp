// Light geometry `stencil` (Vasilovici §4.2; ogldev's stencil light volumes): per light, a
// stencil pass over the whole volume mesh, colour writes off, counting with the depth test
// against the scene's depth (handed to P-buffer 0): a back face behind the surface adds one, a
// front face behind it takes one away (GL_INCR_WRAP / GL_DECR_WRAP on depth fail). What stays
// non-zero is exactly where the surface lies inside the volume, also with the camera inside it
// (its clipped front faces would have passed the depth test anyway). Then the light pass over
// the back faces, only where the stencil is non-zero, zeroing it for the next light; its shader
// has no discard (the table's "light_stencil"), so the GPU can test the stencil before running it.
// The two faces in one pass with glStencilOpSeparate (GL 2.0) or EXT_stencil_two_side; with
// neither, two one-sided passes (back faces, then front faces).
#include "deferred/light_geometry.h"
#include "deferred/light_mesh.h"
#include "deferred/light_pass.h"

namespace dsr {

namespace {

StencilFace counting_face(GLenum zfail) {
    StencilFace f;
    f.func = GL_ALWAYS;
    f.zfail = zfail;
    return f;
}

class StencilGeometry final : public LightGeometryPass {
public:
    StencilGeometry(const ShaderConfig& c, ProgramSet& programs)
        : quads_(programs, false), progs_(programs, "light_stencil"), faces_(c.paths.stencil_faces) {
        // The stencil pass: no colour, no shader, depth tested (GL_LESS: a face on or behind the
        // surface fails), nothing written but the stencil.
        mark_.color_write = false;
        mark_.depth_test = true;
        mark_.depth_func = GL_LESS;
        mark_.depth_write = false;
        mark_.stencil_test = true;
        mark_.stencil_two_side_ext = faces_ == Paths::StencilFaces::two_side_ext;
        mark_.stencil_front = counting_face(GL_DECR_WRAP);
        mark_.stencil_back = counting_face(GL_INCR_WRAP);
        // One-sided: the same op on both faces, each pass culling the other face.
        mark_back_ = mark_front_ = mark_;
        mark_back_.stencil_front = mark_back_.stencil_back = counting_face(GL_INCR_WRAP);
        mark_back_.cull = true;
        mark_back_.cull_face = GL_FRONT;
        mark_front_.stencil_front = mark_front_.stencil_back = counting_face(GL_DECR_WRAP);
        mark_front_.cull = true;
        mark_front_.cull_face = GL_BACK;
        // The light pass: back faces (each pixel of the volume's outline once), where the stencil
        // is non-zero; the pass zeroes what it passes, so every light starts from a clear stencil.
        light_ = light_pass_state(0, false);  // the light's program per light
        light_.cull = true;
        light_.cull_face = GL_FRONT;
        light_.stencil_test = true;
        StencilFace lit;
        lit.func = GL_NOTEQUAL;
        lit.ref = 0;
        lit.zpass = GL_ZERO;
        light_.stencil_front = light_.stencil_back = lit;
        light_.stencil_two_side_ext = mark_.stencil_two_side_ext;
    }

    void draw(const FrameDef& f, RenderTargets&, LightQueries& q, FrameStats& stats) override {
        meshes_.draw_quads_past_far(f, quads_, q, stats);
        progs_.begin(f);
        meshes_.begin(f);
        for (const LightDraw& l : f.lights) {
            if (meshes_.past_far(f, l)) continue;
            if (faces_ == Paths::StencilFaces::one_sided) {
                gl_state().apply(mark_back_);
                meshes_.draw(l);
                gl_state().apply(mark_front_);
                meshes_.draw(l);
            } else {
                gl_state().apply(mark_);
                meshes_.draw(l);
            }
            Program& prog = progs_.form(l);
            light_.program = prog.id();
            gl_state().apply(light_);
            bind_shadow(prog, f, l);
            meshes_.shade(l, prog, q, stats);
            unbind_shadow(l);
        }
    }

private:
    LightQuads quads_;
    LightMeshes meshes_;
    LightPrograms progs_;
    Paths::StencilFaces faces_;
    RenderState mark_, mark_back_, mark_front_, light_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_stencil_geometry(const ShaderConfig& c, ProgramSet& programs) {
    return std::make_unique<StencilGeometry>(c, programs);
}

}  // namespace dsr
