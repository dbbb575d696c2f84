// The GLSL ES 1.00 prelude (glsl_dialect.h). Built-ins are renamed by the preprocessor, so a
// shader reads the same under both dialects and no source is edited: GLSL ES reserves macro names
// beginning "GL_" and "__", not "gl_".
#include "gl/glsl_dialect.h"

#include <regex>

#include "dsr_error.h"

namespace dsr {

const std::vector<EsAttribute>& es_attributes() {
    static const std::vector<EsAttribute> t = [] {
        std::vector<EsAttribute> v = {{"dsr_Vertex", kEsVertexLocation}, {"dsr_Normal", kEsNormalLocation},
                                      {"dsr_Color", kEsColorLocation}};
        static const char* tc[kEsTexCoords] = {"dsr_MultiTexCoord0", "dsr_MultiTexCoord1", "dsr_MultiTexCoord2",
                                               "dsr_MultiTexCoord3", "dsr_MultiTexCoord4", "dsr_MultiTexCoord5",
                                               "dsr_MultiTexCoord6", "dsr_MultiTexCoord7"};
        for (int i = 0; i < kEsTexCoords; ++i) v.push_back({tc[i], es_texcoord_location(i)});
        return v;
    }();
    return t;
}

namespace {

bool uses(const std::string& src, const char* word) {
    return std::regex_search(src, std::regex(std::string("\\b") + word + "\\b"));
}

// Every name of the 1.20 vertex built-ins the source uses, as an attribute or uniform with a macro.
std::string vertex_prelude(const std::string& src) {
    std::string p;
    auto attr = [&](const char* builtin, const char* mine, const char* type) {
        if (!uses(src, builtin)) return;
        p += std::string("attribute ") + type + " " + mine + ";\n#define " + builtin + " " + mine + "\n";
    };
    const bool ftransform = uses(src, "ftransform");
    if (ftransform || uses(src, "gl_Vertex")) p += "attribute vec4 dsr_Vertex;\n#define gl_Vertex dsr_Vertex\n";
    attr("gl_Normal", "dsr_Normal", "vec3");
    attr("gl_Color", "dsr_Color", "vec4");
    for (int i = 0; i < kEsTexCoords; ++i) {
        const std::string b = "gl_MultiTexCoord" + std::to_string(i), m = "dsr_MultiTexCoord" + std::to_string(i);
        attr(b.c_str(), m.c_str(), "vec4");
    }
    auto uni = [&](const char* builtin, const char* mine, const char* type) {
        if (!uses(src, builtin)) return;
        p += std::string("uniform ") + type + " " + mine + ";\n#define " + builtin + " " + mine + "\n";
    };
    uni("gl_ModelViewMatrix", "dsr_ModelViewMatrix", "mat4");
    uni("gl_ProjectionMatrix", "dsr_ProjectionMatrix", "mat4");
    if (ftransform || uses(src, "gl_ModelViewProjectionMatrix"))
        p += "uniform mat4 dsr_ModelViewProjectionMatrix;\n#define gl_ModelViewProjectionMatrix dsr_ModelViewProjectionMatrix\n";
    // ftransform() is position-invariant with the fixed-function pipeline; ES has none to match.
    if (ftransform) p += "#define ftransform() (dsr_ModelViewProjectionMatrix * dsr_Vertex)\n";
    return p;
}

// The extensions are enabled where the dialect has them, whatever branch of the source uses them:
// a name may sit in a branch the defines leave out (the material pass's ambient target, the
// shadow maps' depth-texture form), so a missing one is left to the compiler, and choose_paths
// keeps a configuration off the paths that need it (docs/gles2.md).
std::string fragment_prelude(const std::string& src, const GlslDialect& d) {
    std::string p;
    if (!d.draw_buffers.empty() && uses(src, "gl_FragData")) p += "#extension " + d.draw_buffers + " : enable\n";
    if (d.frag_depth && uses(src, "gl_FragDepth"))
        p += "#extension GL_EXT_frag_depth : enable\n#define gl_FragDepth gl_FragDepthEXT\n";
    if (d.shadow_samplers && uses(src, "shadow2D"))
        p += "#extension GL_EXT_shadow_samplers : enable\n#define shadow2D(s, c) vec4(shadow2DEXT(s, c))\n";
    // highp where the fragment stage has it (optional in ES 2.0): the depth codecs need 24 bits.
    p += "#ifdef GL_FRAGMENT_PRECISION_HIGH\nprecision highp float;\nprecision highp int;\n#else\n"
         "precision mediump float;\nprecision mediump int;\n#endif\n";
    return p;
}

}  // namespace

std::string glsl_in_dialect(const std::string& src, const GlslDialect& d, bool vertex, const std::string& label) {
    if (!d.es) return src;
    const size_t v = src.find("#version");
    if (v == std::string::npos) throw Error("shader " + label + ": expected a #version 120 line");
    const size_t eol = src.find('\n', v);
    const std::string body = src.substr(eol == std::string::npos ? src.size() : eol + 1);
    // Extensions come before any other statement (GLSL ES 1.00 §3.4); the defines the loader put
    // after #version follow the prelude.
    std::string out = src.substr(0, v) + "#version 100\n";
    out += vertex ? "precision highp float;\nprecision highp int;\n" + vertex_prelude(body) : fragment_prelude(body, d);
    out += "#define DSR_GLSL_ES 1\n";
    return out + body;
}

}  // namespace dsr
