// The OpenGL 3.3 core API. Mesa's libraries export every entry point, so prototypes are used
// directly and no loader is needed.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
