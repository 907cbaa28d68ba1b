#pragma once
// Core OpenGL 4.5 entry points, resolved directly from glvnd's libOpenGL (no loader library).
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
