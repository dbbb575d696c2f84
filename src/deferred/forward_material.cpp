#include "deferred/forward_material.h"

namespace dsr {

void set_forward_material(Program& prog, const GpuMaterial& m, float shininess) {
    prog.set("diffuse", m.diffuse);
    prog.set("specular", m.specular);
    prog.set("shininess", shininess);
    prog.set("tile", m.tile);
    const GLuint tex[3] = {m.normal_tex, m.diffuse_tex, m.specular_tex};
    for (int u = 0; u < 3; ++u) {
        glActiveTexture(GL_TEXTURE0 + u);
        glBindTexture(GL_TEXTURE_2D, tex[u]);
    }
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace dsr
