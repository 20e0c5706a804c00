// The EGL implementation of OffscreenContext: Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless), which needs no display, no window system and no GPU (llvmpipe
// draws when there is none), and a context with no surface at all (EGL_KHR_surfaceless_context):
// the renderer draws into framebuffer objects of its own, never into a default framebuffer.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "render/gl_loader.hpp"
#include "render/offscreen_context.hpp"

namespace tumble::render {
namespace {

std::string egl_error_text() {
  char text[32];
  std::snprintf(text, sizeof text, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return text;
}

bool has_extension(const char* list, const std::string& name) {
  const std::string extensions = list ? list : "";
  for (std::size_t at = extensions.find(name); at != std::string::npos;
       at = extensions.find(name, at + 1)) {
    const bool starts = at == 0 || extensions[at - 1] == ' ';
    const std::size_t end = at + name.size();
    if (starts && (end == extensions.size() || extensions[end] == ' ')) return true;
  }
  return false;
}

class EglContext final : public OffscreenContext {
 public:
  EglContext(EGLDisplay display, int width, int height)
      : display_(display), width_(width), height_(height) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    // No eglTerminate: the surfaceless display is one per process, shared by every context made
    // on it (two renderers in one process, a test drawing with each back end), and terminating
    // it under another context would pull the driver from beneath it.
  }

  std::string open() {
    if (!has_extension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
      return "the EGL display lacks EGL_KHR_surfaceless_context";
    }
    if (!eglBindAPI(EGL_OPENGL_API))
      return "eglBindAPI(EGL_OPENGL_API) failed: " + egl_error_text();
    // No config (EGL_KHR_no_config_context, which Mesa has): the context never gets a surface.
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
      return "eglCreateContext: no OpenGL 3.3 core context (" + egl_error_text() + ")";
    }
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      return "eglMakeCurrent without a surface failed: " + egl_error_text();
    }
    if (const std::string missing = load_gl_functions(eglGetProcAddress); !missing.empty()) {
      return "eglGetProcAddress has no " + missing;
    }
    return {};
  }

  int width() const override { return width_; }
  int height() const override { return height_; }
  Backend backend() const override { return Backend::egl; }
  std::string description() const override { return gl_description() + " (EGL surfaceless)"; }

 private:
  EGLDisplay display_;
  EGLContext context_ = EGL_NO_CONTEXT;
  int width_;
  int height_;
};

}  // namespace

std::unique_ptr<OffscreenContext> create_egl_context(int width, int height, std::string& error) {
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS),
                     "EGL_MESA_platform_surfaceless")) {
    error =
        "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless: is Mesa's EGL "
        "installed? Debian: libegl-mesa0)";
    return nullptr;
  }
  const auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) {
    error = "EGL lacks eglGetPlatformDisplayEXT";
    return nullptr;
  }
  const EGLDisplay display =
      get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    error = "eglInitialize on the surfaceless platform failed: " + egl_error_text();
    return nullptr;
  }
  auto out = std::make_unique<EglContext>(display, width, height);
  error = out->open();
  if (!error.empty()) return nullptr;
  return out;
}

}  // namespace tumble::render
