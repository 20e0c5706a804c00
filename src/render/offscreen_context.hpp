// An OpenGL 3.3 core context with no window: frames are drawn into the renderer's own
// framebuffers in memory. Two back ends provide it, both Mesa's: OSMesa (Debian 12's, gone from
// Mesa 25.1) and EGL on the surfaceless platform (EGL_MESA_platform_surfaceless, no display and no
// GPU needed); which API each uses is known only to its .cpp file.
#pragma once

#include <memory>
#include <string>

#include "common/render_settings.hpp"

namespace tumble::render {

// The choice, named where scenes can name it too (common/render_settings.hpp).
using common::Backend;
using common::backend_name;

class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;

  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual Backend backend() const = 0;  // osmesa or egl: the one that made this context
  // GL_RENDERER and GL_VERSION and the back end, e.g. "llvmpipe (LLVM 15.0.6, 256 bits),
  // OpenGL 4.5 (Core Profile) Mesa 22.3.6 (OSMesa)".
  virtual std::string description() const = 0;
};

// Whether this build has the back end (CMake found its library).
bool backend_built(Backend backend);

// Creates the context with `backend` and makes it current on the calling thread, with the GL
// entry points of render/gl.hpp loaded from it. On failure returns null and sets `error` (for
// `automatic`, what each back end tried said).
std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height, Backend backend,
                                                           std::string& error);

// The back ends' own constructors (osmesa_context.cpp, egl_context.cpp), for the one above.
std::unique_ptr<OffscreenContext> create_osmesa_context(int width, int height, std::string& error);
std::unique_ptr<OffscreenContext> create_egl_context(int width, int height, std::string& error);

}  // namespace tumble::render
