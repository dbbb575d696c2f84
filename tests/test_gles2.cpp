// OpenGL ES 2.0 as a GL dialect (docs/gles2.md): the egl-gles2 context, its capability mapping,
// the GLSL ES 1.00 prelude. Tests that need an ES context skip in one line where none can be made.
#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"
#include "dsr_error.h"
#include "gl/glsl_dialect.h"

using namespace dsr;
using namespace dsr::test;

namespace {

// Mesa gives its newest ES for an ES 2.0 request; this holds it to 2.0, so what the tests see is
// what an ES 2.0 device shows.
const char* kEs20 = "MESA_GLES_VERSION_OVERRIDE=2.0";

GlslDialect es_dialect() {
    GlslDialect d;
    d.es = true;
    d.draw_buffers = "GL_EXT_draw_buffers";
    d.frag_depth = true;
    return d;
}

}  // namespace

TEST(GlslDialect, DesktopSourceIsUnchanged) {
    const std::string src = "#version 120\n#define X 1\nvoid main() { gl_Position = ftransform(); }\n";
    EXPECT_EQ(glsl_in_dialect(src, GlslDialect{}, true, "a.vert"), src);
}

TEST(GlslDialect, EsVertexShaderGetsAttributesForTheFixedFunctionBuiltIns) {
    const std::string src =
        "#version 120\n#define X 1\nvoid main() { vec4 t = gl_MultiTexCoord2; vec3 n = gl_Normal;\n"
        "  vec4 e = gl_ModelViewMatrix * gl_Vertex; gl_Position = ftransform(); }\n";
    const std::string es = glsl_in_dialect(src, es_dialect(), true, "a.vert");
    EXPECT_EQ(es.rfind("#version 100\n", 0), 0u) << es;
    EXPECT_EQ(es.find("#version 120"), std::string::npos) << es;
    for (const char* want : {"attribute vec4 dsr_Vertex;", "attribute vec3 dsr_Normal;", "attribute vec4 dsr_MultiTexCoord2;",
                             "uniform mat4 dsr_ModelViewMatrix;", "uniform mat4 dsr_ModelViewProjectionMatrix;",
                             "#define ftransform() (dsr_ModelViewProjectionMatrix * dsr_Vertex)", "#define X 1"})
        EXPECT_NE(es.find(want), std::string::npos) << want << "\n" << es;
    // Only what the source uses.
    EXPECT_EQ(es.find("dsr_MultiTexCoord0"), std::string::npos) << es;
    EXPECT_EQ(es.find("dsr_Color"), std::string::npos) << es;
    EXPECT_EQ(es.find("dsr_ProjectionMatrix"), std::string::npos) << es;
}

TEST(GlslDialect, EsFragmentShaderEnablesWhatItWrites) {
    const std::string mrt = "#version 120\n#define T 2\nvoid main() { gl_FragData[0] = vec4(1.0); gl_FragData[T] = vec4(0.0); }\n";
    const std::string es = glsl_in_dialect(mrt, es_dialect(), false, "m.frag");
    EXPECT_NE(es.find("#extension GL_EXT_draw_buffers : require"), std::string::npos) << es;
    EXPECT_NE(es.find("precision highp float;"), std::string::npos) << es;
    // The extension line comes before every statement.
    EXPECT_LT(es.find("#extension"), es.find("precision")) << es;
    GlslDialect nv = es_dialect();
    nv.draw_buffers = "GL_NV_draw_buffers";
    EXPECT_NE(glsl_in_dialect(mrt, nv, false, "m.frag").find("#extension GL_NV_draw_buffers : require"), std::string::npos);

    const std::string one = "#version 120\nvoid main() { gl_FragData[0] = vec4(1.0); }\n";
    GlslDialect none = es_dialect();
    none.draw_buffers.clear();
    EXPECT_EQ(glsl_in_dialect(one, none, false, "one.frag").find("#extension"), std::string::npos);
    try {
        glsl_in_dialect(mrt, none, false, "m.frag");
        FAIL() << "gl_FragData[T] without draw buffers was accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("m.frag"), std::string::npos) << m;
        EXPECT_NE(m.find("GL_EXT_draw_buffers"), std::string::npos) << m;
    }

    const std::string depth = "#version 120\nvoid main() { gl_FragDepth = 0.5; gl_FragColor = vec4(1.0); }\n";
    const std::string with = glsl_in_dialect(depth, es_dialect(), false, "d.frag");
    EXPECT_NE(with.find("#define gl_FragDepth gl_FragDepthEXT"), std::string::npos) << with;
    GlslDialect no_depth = es_dialect();
    no_depth.frag_depth = false;
    try {
        glsl_in_dialect(depth, no_depth, false, "d.frag");
        FAIL() << "gl_FragDepth without EXT_frag_depth was accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("d.frag"), std::string::npos) << m;
        EXPECT_NE(m.find("GL_EXT_frag_depth"), std::string::npos) << m;
    }
}

TEST(Gles2, InfoPrintsTheEsExtensionsAndTheMappedPaths) {
    const RunResult info = run("info --context egl-gles2", kEs20);
    if (info.status != 0) GTEST_SKIP() << "no OpenGL ES 2.0 context through EGL here: " << info.output;
    for (const char* want : {"OpenGL ES 2.0 context", "GL_VERSION     OpenGL ES 2.0", "capabilities on OpenGL ES 2.0",
                             "EXT_draw_buffers -> mrt", "OES_depth_texture -> --depth texture", "paths chosen"})
        EXPECT_NE(info.output.find(want), std::string::npos) << want << "\n" << info.output;
    // Hiding an ES capability takes the desktop fallback it maps onto.
    const RunResult packed = run("info --context egl-gles2 --caps no-depth-texture,no-mrt", kEs20);
    ASSERT_EQ(packed.status, 0) << packed.output;
    EXPECT_NE(packed.output.find("depth          packed"), std::string::npos) << packed.output;
    EXPECT_NE(packed.output.find("per-target"), std::string::npos) << packed.output;
}
