// The one place GL headers come in. GL 1.1 functions (glBegin, glEnable, glTexImage2D ...) are
// called directly: every libGL exports them. Everything newer goes through dsr's entry-point
// table (gl/entry_points.h), loaded through GLContext::proc_address when create_context makes
// a context current: libOSMesa exports every GL function, but a system libGL or an EGL driver
// does not export the ...EXT/...ARB ones, so linking them directly ties the renderer core to
// libOSMesa. Each macro below maps the plain GL name to its table slot, so call sites stay
// plain GL. (Mesa's gl.h also declares GL 1.2/1.3 prototypes such as glActiveTexture; the
// macros, defined after it, still redirect the calls. Never take a GL function's address.)
// Without GL_GLEXT_PROTOTYPES glext.h declares only the PFNGL...PROC types: a call to a
// function not in the table does not compile. Add it to gl/entry_points.h and here.
#pragma once
#include "gl/entry_points.h"
#include "gl/fixed_function.h"

#define glActiveTexture ::dsr::gl_entry.ActiveTexture
#define glClientActiveTexture ::dsr::gl_entry.ClientActiveTexture
#define glMultiTexCoord2f ::dsr::gl_entry.MultiTexCoord2f
#define glMultiTexCoord3f ::dsr::gl_entry.MultiTexCoord3f
#define glGenBuffers ::dsr::gl_entry.GenBuffers
#define glBindBuffer ::dsr::gl_entry.BindBuffer
#define glBufferData ::dsr::gl_entry.BufferData
#define glDeleteBuffers ::dsr::gl_entry.DeleteBuffers
#define glGenQueries ::dsr::gl_entry.GenQueries
#define glDeleteQueries ::dsr::gl_entry.DeleteQueries
#define glBeginQuery ::dsr::gl_entry.BeginQuery
#define glEndQuery ::dsr::gl_entry.EndQuery
#define glGetQueryObjectuiv ::dsr::gl_entry.GetQueryObjectuiv
#define glStencilFuncSeparate ::dsr::gl_entry.StencilFuncSeparate
#define glStencilOpSeparate ::dsr::gl_entry.StencilOpSeparate
#define glStencilMaskSeparate ::dsr::gl_entry.StencilMaskSeparate
#define glCreateShader ::dsr::gl_entry.CreateShader
#define glShaderSource ::dsr::gl_entry.ShaderSource
#define glCompileShader ::dsr::gl_entry.CompileShader
#define glGetShaderiv ::dsr::gl_entry.GetShaderiv
#define glGetShaderInfoLog ::dsr::gl_entry.GetShaderInfoLog
#define glDeleteShader ::dsr::gl_entry.DeleteShader
#define glCreateProgram ::dsr::gl_entry.CreateProgram
#define glAttachShader ::dsr::gl_entry.AttachShader
#define glLinkProgram ::dsr::gl_entry.LinkProgram
#define glGetProgramiv ::dsr::gl_entry.GetProgramiv
#define glGetProgramInfoLog ::dsr::gl_entry.GetProgramInfoLog
#define glUseProgram ::dsr::gl_entry.UseProgram
#define glDeleteProgram ::dsr::gl_entry.DeleteProgram
#define glGetUniformLocation ::dsr::gl_entry.GetUniformLocation
#define glUniform1f ::dsr::gl_entry.Uniform1f
#define glUniform1i ::dsr::gl_entry.Uniform1i
#define glUniform2f ::dsr::gl_entry.Uniform2f
#define glUniform2fv ::dsr::gl_entry.Uniform2fv
#define glUniform3f ::dsr::gl_entry.Uniform3f
#define glUniform3fv ::dsr::gl_entry.Uniform3fv
#define glUniform4f ::dsr::gl_entry.Uniform4f
#define glUniform4fv ::dsr::gl_entry.Uniform4fv
#define glUniformMatrix3fv ::dsr::gl_entry.UniformMatrix3fv
#define glUniformMatrix4fv ::dsr::gl_entry.UniformMatrix4fv
#define glBindAttribLocation ::dsr::gl_entry.BindAttribLocation
#define glVertexAttribPointer ::dsr::gl_entry.VertexAttribPointer
#define glEnableVertexAttribArray ::dsr::gl_entry.EnableVertexAttribArray
#define glDisableVertexAttribArray ::dsr::gl_entry.DisableVertexAttribArray
#define glVertexAttrib4f ::dsr::gl_entry.VertexAttrib4f
#define glDrawBuffersARB ::dsr::gl_entry.DrawBuffersARB
#define glGenFramebuffersEXT ::dsr::gl_entry.GenFramebuffersEXT
#define glBindFramebufferEXT ::dsr::gl_entry.BindFramebufferEXT
#define glDeleteFramebuffersEXT ::dsr::gl_entry.DeleteFramebuffersEXT
#define glFramebufferTexture2DEXT ::dsr::gl_entry.FramebufferTexture2DEXT
#define glFramebufferRenderbufferEXT ::dsr::gl_entry.FramebufferRenderbufferEXT
#define glCheckFramebufferStatusEXT ::dsr::gl_entry.CheckFramebufferStatusEXT
#define glGenRenderbuffersEXT ::dsr::gl_entry.GenRenderbuffersEXT
#define glBindRenderbufferEXT ::dsr::gl_entry.BindRenderbufferEXT
#define glDeleteRenderbuffersEXT ::dsr::gl_entry.DeleteRenderbuffersEXT
#define glRenderbufferStorageEXT ::dsr::gl_entry.RenderbufferStorageEXT
#define glQueryCounter ::dsr::gl_entry.QueryCounter
#define glGetQueryObjectui64v ::dsr::gl_entry.GetQueryObjectui64v
#define glActiveStencilFaceEXT ::dsr::gl_entry.ActiveStencilFaceEXT
#define glDepthBoundsEXT ::dsr::gl_entry.DepthBoundsEXT
#define glBlitFramebufferEXT ::dsr::gl_entry.BlitFramebufferEXT
#define glGenerateMipmap ::dsr::gl_entry.GenerateMipmap
// GL 1.1 calls with an OpenGL ES 2.0 stand-in (gl/fixed_function.h): the desktop call on desktop GL.
#define glColor4f ::dsr::ff_color4f
#define glClearDepth ::dsr::ff_clear_depth
#define glDrawBuffer ::dsr::ff_draw_buffer
#define glReadBuffer ::dsr::ff_read_buffer
