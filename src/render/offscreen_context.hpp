// An OpenGL 3.3 core context with no window: frames are drawn into the renderer's own
// framebuffers in memory. Two back ends provide it: OSMesa (Mesa's; Debian 12's, gone from Mesa
// 25.1) and EGL, on one of EGL's devices (EGL_EXT_platform_device: a GPU's driver, or Mesa's
// software device) or on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless); none needs
// a display. Which API each uses is known only to its .cpp file.
#pragma once

#include <memory>
#include <string>

#include "common/render_settings.hpp"
#include "common/result.hpp"

namespace tumble::render {

// The choice, named where scenes can name it too (common/render_settings.hpp).
using common::Backend;
using common::backend_name;
using common::kAutomaticEglDevice;

class OffscreenContext {
 public:
  virtual ~OffscreenContext();

  // Makes this context the calling thread's current one, if it is not already (a thread may hold
  // several renderers of one back end and draw with each in turn); false if the back end refused.
  bool use();

  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual Backend backend() const = 0;  // osmesa or egl: the one that made this context
  // Where it draws, within the back end: "" for OSMesa; for EGL "surfaceless" or
  // "device I of N: <name>" (e.g. "device 1 of 2: CUDA device 0, /dev/dri/renderD128").
  virtual std::string device() const = 0;
  // GL_RENDERER and GL_VERSION, the back end and its device, e.g. "llvmpipe (LLVM 15.0.6, 256
  // bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6 (OSMesa)" or "… (EGL device 0 of 1: Mesa
  // software)". With the context current.
  std::string description() const;

 protected:
  // The back end's own call, made by use() (its constructor makes the context current itself).
  virtual bool make_current() = 0;
};

// Whether this build has the back end (CMake found its library).
bool backend_built(Backend backend);

// Whether EGL is built in and lists a device that is not Mesa's software one: a GPU. Listing
// loads the EGL vendor libraries (about 10 ms of CPU on Mesa).
bool egl_has_gpu();

// Creates the context with `backend` and makes it current on the calling thread, with the GL
// entry points of render/gl.hpp loaded from it. `egl_device` is an index into EGL's device list
// or kAutomaticEglDevice (common/render_settings.hpp says what each chooses). For `automatic`, an
// error gives what each back end tried said.
Result<std::unique_ptr<OffscreenContext>> create_offscreen_context(int width, int height,
                                                                   Backend backend, int egl_device);

// The back ends' own constructors (osmesa_context.cpp, egl_context.cpp), for the one above.
Result<std::unique_ptr<OffscreenContext>> create_osmesa_context(int width, int height);
Result<std::unique_ptr<OffscreenContext>> create_egl_context(int width, int height, int device);
// The index of EGL's first device that is not Mesa's software one (a GPU), else
// kAutomaticEglDevice (egl_context.cpp).
int egl_hardware_device();

}  // namespace tumble::render
