// The one place GL headers come in. GL_GLEXT_PROTOTYPES (set by the Makefile) makes
// glext.h declare extension entry points; libOSMesa exports every one of them.
#pragma once
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
