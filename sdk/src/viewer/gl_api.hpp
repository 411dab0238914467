// viewer/gl_api.hpp — the OpenGL 3.3 core API for the viewer: core-profile
// prototypes from Khronos' glcorearb.h, resolved at link time against glvnd's
// libOpenGL, which dispatches to whichever context (EGL or GLFW's GLX) is
// current. Include this instead of any other GL header.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
