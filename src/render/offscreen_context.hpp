// An OpenGL 3.3 core context with no window: frames are drawn into memory. Which API provides it
// (OSMesa today; EGL surfaceless once Mesa drops OSMesa) is known only to its .cpp file.
#pragma once

#include <memory>
#include <string>

namespace tumble::render {

class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;

  virtual int width() const = 0;
  virtual int height() const = 0;
  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa".
  virtual std::string description() const = 0;
};

// Creates the context and makes it current on the calling thread. On failure returns null and
// sets `error`.
std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height,
                                                           std::string& error);

}  // namespace tumble::render
