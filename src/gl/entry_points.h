// dsr's table of GL entry points beyond GL 1.1, loaded once per context through the address
// function whoever made the context hands over (the context backends hand their proc_address).
// Only libOSMesa exports every GL function; a system libGL exports GL 1.1 (and a few 1.2/1.3
// ones) and an EGL driver nothing beyond what its loader gives, so everything newer is fetched at
// run time. gl/gl.h maps each glName to gl_entry.Name, so call sites stay plain GL. Adding a call
// to a function not listed here fails to compile (glext.h declares no prototypes without
// GL_GLEXT_PROTOTYPES): add it to a list below and to gl/gl.h.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>
#include <string>
#include <vector>

// Mesa's gl.h defines GL_VERSION_1_3, so glext.h skips its GL 1.3 typedefs; gl.h itself
// typedefs only some of them. The ones dsr needs, written out:
typedef void(APIENTRYP DSR_PFNGLCLIENTACTIVETEXTUREPROC)(GLenum texture);
typedef void(APIENTRYP DSR_PFNGLMULTITEXCOORD2FPROC)(GLenum target, GLfloat s, GLfloat t);
typedef void(APIENTRYP DSR_PFNGLMULTITEXCOORD3FPROC)(GLenum target, GLfloat s, GLfloat t, GLfloat r);

// X(type, Name): the function is "gl" #Name. A missing required one makes
// load_gl_entry_points throw; every one here is GL 2.1 core or an extension the tutorial's
// passes stand on (ARB_draw_buffers for the G-buffer's targets, EXT_framebuffer_object for §3.2's
// P-buffers).
#define DSR_GL_REQUIRED_ENTRY_POINTS(X)                              \
    /* GL 1.3 multitexture */                                        \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                         \
    X(DSR_PFNGLCLIENTACTIVETEXTUREPROC, ClientActiveTexture)         \
    X(DSR_PFNGLMULTITEXCOORD2FPROC, MultiTexCoord2f)                 \
    X(DSR_PFNGLMULTITEXCOORD3FPROC, MultiTexCoord3f)                 \
    /* GL 1.5 buffer objects */                                      \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                               \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                               \
    X(PFNGLBUFFERDATAPROC, BufferData)                               \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                         \
    /* GL 1.5 occlusion queries */                                   \
    X(PFNGLGENQUERIESPROC, GenQueries)                               \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                         \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                               \
    X(PFNGLENDQUERYPROC, EndQuery)                                   \
    X(PFNGLGETQUERYOBJECTUIVPROC, GetQueryObjectuiv)                 \
    /* GL 2.0 two-sided stencil */                                   \
    X(PFNGLSTENCILFUNCSEPARATEPROC, StencilFuncSeparate)             \
    X(PFNGLSTENCILOPSEPARATEPROC, StencilOpSeparate)                 \
    X(PFNGLSTENCILMASKSEPARATEPROC, StencilMaskSeparate)             \
    /* GL 2.0 shaders and programs */                                \
    X(PFNGLCREATESHADERPROC, CreateShader)                           \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                           \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                         \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                             \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                   \
    X(PFNGLDELETESHADERPROC, DeleteShader)                           \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                         \
    X(PFNGLATTACHSHADERPROC, AttachShader)                           \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                             \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                           \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                 \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                               \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                         \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)               \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                 \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                 \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                 \
    X(PFNGLUNIFORM2FVPROC, Uniform2fv)                               \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                 \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                               \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                 \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                               \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                   \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                   \
    /* GL 2.0 generic vertex attributes (OpenGL ES 2.0 has no others) */ \
    X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)               \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)             \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)     \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)   \
    X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f)                       \
    /* ARB_draw_buffers */                                           \
    X(PFNGLDRAWBUFFERSARBPROC, DrawBuffersARB)                       \
    /* EXT_framebuffer_object */                                     \
    X(PFNGLGENFRAMEBUFFERSEXTPROC, GenFramebuffersEXT)               \
    X(PFNGLBINDFRAMEBUFFEREXTPROC, BindFramebufferEXT)               \
    X(PFNGLDELETEFRAMEBUFFERSEXTPROC, DeleteFramebuffersEXT)         \
    X(PFNGLFRAMEBUFFERTEXTURE2DEXTPROC, FramebufferTexture2DEXT)     \
    X(PFNGLFRAMEBUFFERRENDERBUFFEREXTPROC, FramebufferRenderbufferEXT) \
    X(PFNGLCHECKFRAMEBUFFERSTATUSEXTPROC, CheckFramebufferStatusEXT) \
    X(PFNGLGENRENDERBUFFERSEXTPROC, GenRenderbuffersEXT)             \
    X(PFNGLBINDRENDERBUFFEREXTPROC, BindRenderbufferEXT)             \
    X(PFNGLDELETERENDERBUFFERSEXTPROC, DeleteRenderbuffersEXT)       \
    X(PFNGLRENDERBUFFERSTORAGEEXTPROC, RenderbufferStorageEXT)

// May be null after loading; whoever calls one checks it (and the matching Caps flag) first.
// ARB_timer_query, for GPU stage times; EXT_stencil_two_side and EXT_depth_bounds_test for the
// light geometries (Caps::stencil_two_side_ext, Caps::depth_bounds); EXT_framebuffer_blit for the
// depth hand-off (Caps::framebuffer_blit); glGenerateMipmap for OpenGL ES 2.0's textures.
#define DSR_GL_OPTIONAL_ENTRY_POINTS(X)                  \
    X(PFNGLQUERYCOUNTERPROC, QueryCounter)               \
    X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v) \
    X(PFNGLACTIVESTENCILFACEEXTPROC, ActiveStencilFaceEXT) \
    X(PFNGLDEPTHBOUNDSEXTPROC, DepthBoundsEXT)            \
    X(PFNGLBLITFRAMEBUFFEREXTPROC, BlitFramebufferEXT)    \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)           \
    X(PFNGLCLEARDEPTHFPROC, ClearDepthf)

namespace dsr {

struct GLEntryPoints {
#define DSR_GL_ENTRY_MEMBER(type, name) type name = nullptr;
    DSR_GL_REQUIRED_ENTRY_POINTS(DSR_GL_ENTRY_MEMBER)
    DSR_GL_OPTIONAL_ENTRY_POINTS(DSR_GL_ENTRY_MEMBER)
#undef DSR_GL_ENTRY_MEMBER
};

// The table the gl/gl.h macros call through. One per process: on every backend dsr has
// (OSMesa, GLX, EGL) an entry point's address is the same for every context.
extern GLEntryPoints gl_entry;

// Address of a GL entry point by its name ("glUseProgram"); null when absent.
using GLProcAddress = std::function<void*(const char* name)>;

// Whether the current context is OpenGL ES (its GL_VERSION starts "OpenGL ES").
bool current_gl_is_es();

// Fills gl_entry through proc_address, which answers for the current context; `source` names
// that context in the error (its backend, "osmesa"). When a required entry point is missing,
// throws one dsr::Error naming every missing one and leaves gl_entry as it was. On OpenGL ES 2.0
// each slot is filled by its ES name (glGenFramebuffers, glDrawBuffersEXT or glDrawBuffersNV,
// ...); the slots ES 2.0 lacks (the fixed-function texture coordinates, counting queries) stay null.
void load_gl_entry_points(const GLProcAddress& proc_address, const std::string& source);

// Every entry in the table, for tests and `dsr info`: its GL name, whether it is required and
// whether gl_entry holds an address for it now.
struct GLEntryPointStatus {
    std::string name;
    bool required;
    bool loaded;
};
std::vector<GLEntryPointStatus> gl_entry_point_status();

}  // namespace dsr
