// The EGL implementation of OffscreenContext, with no display, no window system and no surface:
// a context made current without one (EGL_KHR_surfaceless_context), the renderer drawing into
// framebuffer objects of its own. The display comes from one of two platforms, never from
// eglGetDisplay(EGL_DEFAULT_DISPLAY), which binds to X11 wherever DISPLAY is set:
// - the device platform (EGL_EXT_platform_device), on a device of EGL's list
//   (EGL_EXT_device_enumeration): a GPU's driver (NVIDIA's, a Mesa DRM driver) or Mesa's
//   software device (EGL_MESA_device_software, llvmpipe);
// - Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), llvmpipe where there is no GPU.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "render/gl_loader.hpp"
#include "render/offscreen_context.hpp"

namespace tumble::render {
namespace {

std::string egl_error_text() {
  char text[32];
  std::snprintf(text, sizeof text, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return text;
}

bool has_extension(const char* list, std::string_view name) {
  const std::string_view extensions = list ? list : "";
  for (std::size_t at = extensions.find(name); at != std::string_view::npos;
       at = extensions.find(name, at + 1)) {
    const bool starts = at == 0 || extensions[at - 1] == ' ';
    const std::size_t end = at + name.size();
    if (starts && (end == extensions.size() || extensions[end] == ' ')) return true;
  }
  return false;
}

bool client_has(std::string_view extension) {
  return has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), extension);
}

template <typename Function>
Function egl_function(const char* name) {
  return reinterpret_cast<Function>(eglGetProcAddress(name));
}

// EGL's devices in the order of eglQueryDevicesEXT, which `egl_device` counts in.
Result<std::vector<EGLDeviceEXT>> list_devices() {
  const auto query = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  if (!client_has("EGL_EXT_device_enumeration") || !query) {
    return Error{"this EGL cannot list its devices (no EGL_EXT_device_enumeration)"};
  }
  EGLint count = 0;
  if (!query(0, nullptr, &count)) return Error{"eglQueryDevicesEXT failed: " + egl_error_text()};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (count > 0 && !query(count, devices.data(), &count)) {
    return Error{"eglQueryDevicesEXT failed: " + egl_error_text()};
  }
  devices.resize(static_cast<std::size_t>(count));
  return devices;
}

const char* device_string(EGLDeviceEXT device, EGLint name) {
  const auto query = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  return query ? query(device, name) : nullptr;
}

bool is_software(EGLDeviceEXT device) {
  return has_extension(device_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

// What a person knows the device by: "Mesa software", "CUDA device 1, /dev/dri/renderD129".
std::string device_name(EGLDeviceEXT device) {
  if (is_software(device)) return "Mesa software";
  std::string name;
  const auto attribute = egl_function<PFNEGLQUERYDEVICEATTRIBEXTPROC>("eglQueryDeviceAttribEXT");
  EGLAttrib cuda = 0;
  if (has_extension(device_string(device, EGL_EXTENSIONS), "EGL_NV_device_cuda") && attribute &&
      attribute(device, EGL_CUDA_DEVICE_NV, &cuda)) {
    name = "CUDA device " + std::to_string(cuda);
  }
  for (const EGLint file : {EGL_DRM_RENDER_NODE_FILE_EXT, EGL_DRM_DEVICE_FILE_EXT}) {
    if (const char* path = device_string(device, file)) {
      return name + (name.empty() ? "" : ", ") + path;
    }
  }
  return name.empty() ? "a device EGL does not name" : name;
}

// Every device as "0: Mesa software; 1: CUDA device 0, /dev/dri/renderD128", for messages.
std::string device_list_text(const std::vector<EGLDeviceEXT>& devices) {
  std::string text;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    text += (i ? "; " : "") + std::to_string(i) + ": " + device_name(devices[i]);
  }
  return text.empty() ? "none" : text;
}

class EglContext final : public OffscreenContext {
 public:
  EglContext(EGLDisplay display, std::string device, int width, int height)
      : display_(display), device_(std::move(device)), width_(width), height_(height) {}
  ~EglContext() override {
    if (eglGetCurrentContext() == context_) {  // another renderer's context may be current
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    // No eglTerminate: a platform's display is one per process (per device), shared by every
    // context made on it (two renderers in one process, a test drawing with each back end), and
    // terminating it under another context would pull the driver from beneath it.
  }

  Result<void> open() {
    const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
    if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
      return Error{"the EGL display lacks EGL_KHR_surfaceless_context"};
    }
    if (!eglBindAPI(EGL_OPENGL_API))
      return Error{"eglBindAPI(EGL_OPENGL_API) failed: " + egl_error_text()};
    // No config where the display allows it (EGL_KHR_no_config_context: Mesa): the context never
    // gets a surface. Elsewhere any config that renders desktop OpenGL.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
      const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint found = 0;
      if (!eglChooseConfig(display_, wanted, &config, 1, &found) || found < 1) {
        return Error{"eglChooseConfig: no config for desktop OpenGL (" + egl_error_text() + ")"};
      }
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
      return Error{"eglCreateContext: no OpenGL 3.3 core context (" + egl_error_text() + ")"};
    }
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      return Error{"eglMakeCurrent without a surface failed: " + egl_error_text()};
    }
    if (const Result<void> loaded = load_gl_functions(eglGetProcAddress); !loaded) {
      return Error{"eglGetProcAddress has no " + loaded.error()};
    }
    return Result<void>::success();
  }

  bool make_current() override {
    return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE;
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  Backend backend() const override { return Backend::egl; }
  std::string device() const override { return device_; }

 private:
  EGLDisplay display_;
  std::string device_;  // "surfaceless" or "device I of N: <its name>"
  EGLContext context_ = EGL_NO_CONTEXT;
  int width_;
  int height_;
};

Result<std::unique_ptr<OffscreenContext>> open_display(EGLenum platform, void* native,
                                                       std::string device, int width, int height) {
  const auto get_platform_display =
      egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!get_platform_display) {
    return Error{"EGL lacks eglGetPlatformDisplayEXT"};
  }
  const EGLDisplay display = get_platform_display(platform, native, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    return Error{"eglInitialize on the " + device + " failed: " + egl_error_text()};
  }
  auto out = std::make_unique<EglContext>(display, std::move(device), width, height);
  if (Result<void> opened = out->open(); !opened) return Error{opened.error()};
  return std::unique_ptr<OffscreenContext>(std::move(out));
}

Result<std::unique_ptr<OffscreenContext>> open_device(const std::vector<EGLDeviceEXT>& devices,
                                                      std::size_t index, int width, int height) {
  if (!client_has("EGL_EXT_platform_device")) {
    return Error{"this EGL has no device platform (EGL_EXT_platform_device)"};
  }
  const std::string device = "device " + std::to_string(index) + " of " +
                             std::to_string(devices.size()) + ": " + device_name(devices[index]);
  return open_display(EGL_PLATFORM_DEVICE_EXT, devices[index], device, width, height);
}

// The first device that is not Mesa's software one (a GPU), else kAutomaticEglDevice.
int first_hardware(const Result<std::vector<EGLDeviceEXT>>& devices) {
  for (std::size_t i = 0; devices && i < devices->size(); ++i) {
    if (!is_software((*devices)[i])) return static_cast<int>(i);
  }
  return kAutomaticEglDevice;
}

}  // namespace

int egl_hardware_device() {
  return first_hardware(list_devices());
}

Result<std::unique_ptr<OffscreenContext>> create_egl_context(int width, int height, int device) {
  const Result<std::vector<EGLDeviceEXT>> devices = list_devices();
  if (device == kAutomaticEglDevice) device = first_hardware(devices);
  if (device != kAutomaticEglDevice) {
    if (!devices) {
      return Error{"egl_device " + std::to_string(device) + ": " + devices.error()};
    }
    if (device < 0 || static_cast<std::size_t>(device) >= devices->size()) {
      return Error{"egl_device " + std::to_string(device) +
                   ": no such EGL device (this machine's: " + device_list_text(*devices) + ")"};
    }
    return open_device(*devices, static_cast<std::size_t>(device), width, height);
  }
  if (!client_has("EGL_MESA_platform_surfaceless")) {
    return Error{
        "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless: is Mesa's EGL "
        "installed? Debian: libegl-mesa0) and no hardware device"};
  }
  return open_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "surfaceless", width,
                      height);
}

}  // namespace tumble::render
