// gl/gl_api.hpp — the OpenGL 3.3 core API for onetip's GL code (the viewer
// and the simulator's GLSL renderer): core-profile prototypes from Khronos'
// glcorearb.h, resolved at link time against glvnd's libOpenGL, which
// dispatches to whichever context (EGL or GLFW's GLX) is current on the
// calling thread. Include this instead of any other GL header.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
