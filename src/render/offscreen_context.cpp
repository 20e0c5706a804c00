#include "render/offscreen_context.hpp"

#include "render/gl_loader.hpp"

namespace tumble::render {
namespace {

// The context current on this thread, as far as the contexts made here know.
thread_local const OffscreenContext* current_context = nullptr;

Result<std::unique_ptr<OffscreenContext>> create_context(int width, int height, Backend backend,
                                                         int egl_device);

}  // namespace

OffscreenContext::~OffscreenContext() {
  if (current_context == this) current_context = nullptr;
}

bool OffscreenContext::use() {
  if (current_context == this) return true;
  if (!make_current()) return false;
  current_context = this;
  return true;
}

Result<std::unique_ptr<OffscreenContext>> create_offscreen_context(int width, int height,
                                                                   Backend backend,
                                                                   int egl_device) {
  Result<std::unique_ptr<OffscreenContext>> made =
      create_context(width, height, backend, egl_device);
  if (made) current_context = made.value().get();
  return made;
}

std::string OffscreenContext::description() const {
  return gl_description() +
         (backend() == Backend::osmesa ? " (OSMesa)" : " (EGL " + device() + ")");
}

bool egl_has_gpu() {
#ifdef TUMBLE_HAVE_EGL
  return egl_hardware_device() != kAutomaticEglDevice;
#else
  return false;
#endif
}

bool backend_built(Backend backend) {
  switch (backend) {
    case Backend::automatic:
      return backend_built(Backend::osmesa) || backend_built(Backend::egl);
    case Backend::osmesa:
#ifdef TUMBLE_HAVE_OSMESA
      return true;
#else
      return false;
#endif
    case Backend::egl:
#ifdef TUMBLE_HAVE_EGL
      return true;
#else
      return false;
#endif
  }
  return false;
}

namespace {

Result<std::unique_ptr<OffscreenContext>> create_context(int width, int height, Backend backend,
                                                         int egl_device) {
  const auto unbuilt = [&](Backend wanted) -> Result<std::unique_ptr<OffscreenContext>> {
    return Error{
        std::string("this tumble was built without the ") + backend_name(wanted) +
        " back end (CMake did not find " +
        (wanted == Backend::osmesa ? "OSMesa: Debian's libosmesa6-dev" : "EGL: libegl-dev") + ")"};
  };
  switch (backend) {
    case Backend::osmesa:
      if (!backend_built(backend)) return unbuilt(backend);
      return create_osmesa_context(width, height);
    case Backend::egl:
      if (!backend_built(backend)) return unbuilt(backend);
      return create_egl_context(width, height, egl_device);
    case Backend::automatic:
      break;
  }
  // A named EGL device asks for EGL. Else EGL first when it has a GPU; else OSMesa first, the back
  // end every frame was drawn with before EGL came (the two give the same bytes on llvmpipe,
  // tested), then EGL, which newer Mesas keep.
  if (egl_device != kAutomaticEglDevice) {
    return create_context(width, height, Backend::egl, egl_device);
  }
  const bool egl_first = egl_has_gpu();
  std::string tried;
  const Backend order[2] = {egl_first ? Backend::egl : Backend::osmesa,
                            egl_first ? Backend::osmesa : Backend::egl};
  for (const Backend each : order) {
    if (!backend_built(each)) continue;
    Result<std::unique_ptr<OffscreenContext>> context =
        create_context(width, height, each, egl_device);
    if (context) return context;
    tried += std::string(tried.empty() ? "" : "; ") + backend_name(each) + ": " + context.error();
  }
  return Error{tried.empty() ? "this tumble was built with no off-screen back end" : tried};
}

}  // namespace

}  // namespace tumble::render
