#include "render/offscreen_context.hpp"

#include "render/gl_loader.hpp"

namespace tumble::render {

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

Result<std::unique_ptr<OffscreenContext>> create_offscreen_context(int width, int height,
                                                                   Backend backend,
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
    return create_offscreen_context(width, height, Backend::egl, egl_device);
  }
  const bool egl_first = egl_has_gpu();
  std::string tried;
  const Backend order[2] = {egl_first ? Backend::egl : Backend::osmesa,
                            egl_first ? Backend::osmesa : Backend::egl};
  for (const Backend each : order) {
    if (!backend_built(each)) continue;
    Result<std::unique_ptr<OffscreenContext>> context =
        create_offscreen_context(width, height, each, egl_device);
    if (context) return context;
    tried += std::string(tried.empty() ? "" : "; ") + backend_name(each) + ": " + context.error();
  }
  return Error{tried.empty() ? "this tumble was built with no off-screen back end" : tried};
}

}  // namespace tumble::render
