// The one place that includes the OpenGL headers. OSMesa's library exports the
// core-profile entry points directly, so no loader is needed.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <GL/gl.h>
#include <GL/glext.h>
