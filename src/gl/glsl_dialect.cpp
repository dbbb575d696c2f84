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

std::string fragment_prelude(const std::string& src, const GlslDialect& d, const std::string& label) {
    std::string p;
    // Any index but a literal 0 (the material pass indexes by a define) may be a target beyond the first.
    if (std::regex_search(src, std::regex("gl_FragData\\s*\\[\\s*(?!0\\s*\\])"))) {
        if (d.draw_buffers.empty())
            throw Error("shader " + label + " writes gl_FragData[1..], which needs GL_EXT_draw_buffers or "
                        "GL_NV_draw_buffers, and this OpenGL ES 2.0 has neither");
        p += "#extension " + d.draw_buffers + " : require\n";
    }
    if (uses(src, "gl_FragDepth")) {
        if (!d.frag_depth)
            throw Error("shader " + label + " writes gl_FragDepth, which needs GL_EXT_frag_depth on OpenGL ES 2.0");
        p += "#extension GL_EXT_frag_depth : require\n#define gl_FragDepth gl_FragDepthEXT\n";
    }
    if (uses(src, "shadow2D") || uses(src, "sampler2DShadow")) {
        if (!d.shadow_samplers)
            throw Error("shader " + label + " compares depth in the lookup (shadow2D), which needs "
                        "GL_EXT_shadow_samplers on OpenGL ES 2.0");
        p += "#extension GL_EXT_shadow_samplers : require\n#define shadow2D(s, c) vec4(shadow2DEXT(s, c))\n";
    }
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
    out += vertex ? "precision highp float;\nprecision highp int;\n" + vertex_prelude(body) : fragment_prelude(body, d, label);
    out += "#define DSR_GLSL_ES 1\n";
    return out + body;
}

}  // namespace dsr
