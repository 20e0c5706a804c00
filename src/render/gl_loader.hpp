// How an off-screen back end hands the renderer its OpenGL: without GL's own headers, so that
// a back end whose API header brings GL/gl.h (OSMesa's does) can include it.
#pragma once

#include <string>

#include "common/result.hpp"

namespace tumble::render {

// A back end's GetProcAddress (OSMesaGetProcAddress, eglGetProcAddress): the entry point of that
// name, or null.
using GlProcLoader = void (*(*)(const char* name))();

// Points every entry point of render/gl.hpp at the back end's; the error is the name of the first
// entry point it lacks. Called by the back end once its context is current, before any drawing.
Result<void> load_gl_functions(GlProcLoader loader);

// GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits),
// OpenGL 4.5 (Core Profile) Mesa 22.3.6".
std::string gl_description();

}  // namespace tumble::render
