// A GL dialect's shader prelude (DESIGN.md, "a GL dialect is a context plus a shader prelude"):
// the glsl120/ sources as GLSL ES 1.00 for OpenGL ES 2.0, not a second copy of each shader. Pure
// text, no GL: program.cpp reads the dialect off the current context and hands it here.
#pragma once
#include <string>
#include <vector>

namespace dsr {

struct GlslDialect {
    bool es = false;               // GLSL ES 1.00; false: desktop GLSL, the source as written
    std::string draw_buffers;      // "GL_EXT_draw_buffers", "GL_NV_draw_buffers" or "" (gl_FragData[0] only)
    bool frag_depth = false;       // GL_EXT_frag_depth: gl_FragDepth as gl_FragDepthEXT
    bool shadow_samplers = false;  // GL_EXT_shadow_samplers: shadow2D as shadow2DEXT
};

// The attributes and uniforms the ES prelude gives a vertex shader in place of GLSL 1.20's
// fixed-function built-ins (gl_Vertex, gl_MultiTexCoordN, gl_ModelViewMatrix, ftransform() ...),
// with the attribute locations the program binds them to: the drawing code feeds these under ES
// (gl/es_draw.h), where the desktop feeds the fixed-function arrays and the matrix stack.
struct EsAttribute {
    const char* glsl;  // "dsr_Vertex"
    int location;
};
const std::vector<EsAttribute>& es_attributes();
// The number of gl_MultiTexCoordN the prelude maps (0 .. N-1): location es_texcoord_location(i).
constexpr int kEsTexCoords = 8;
constexpr int kEsVertexLocation = 0, kEsNormalLocation = 1, kEsColorLocation = 2;
constexpr int es_texcoord_location(int unit) { return 3 + unit; }

// `src` (a glsl120/ source with its includes expanded and defines inserted) in dialect `d`:
// unchanged for desktop GLSL; for GLSL ES its #version 120 line becomes #version 100 and the
// prelude (precision, the extensions it has among those the source names: draw buffers for
// gl_FragData, EXT_frag_depth for gl_FragDepth, EXT_shadow_samplers for shadow2D; the built-ins
// above). `vertex`: a vertex shader. Throws dsr::Error naming `label` where there is no #version.
std::string glsl_in_dialect(const std::string& src, const GlslDialect& d, bool vertex, const std::string& label);

}  // namespace dsr
