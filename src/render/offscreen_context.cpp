#include "render/offscreen_context.hpp"

namespace tumble::render {

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

std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height, Backend backend,
                                                           std::string& error) {
  const auto unbuilt = [&](Backend wanted) {
    error = std::string("this tumble was built without the ") + backend_name(wanted) +
            " back end (CMake did not find " +
            (wanted == Backend::osmesa ? "OSMesa: Debian's libosmesa6-dev" : "EGL: libegl-dev") +
            ")";
    return nullptr;
  };
  switch (backend) {
    case Backend::osmesa:
      if (!backend_built(backend)) return unbuilt(backend);
      return create_osmesa_context(width, height, error);
    case Backend::egl:
      if (!backend_built(backend)) return unbuilt(backend);
      return create_egl_context(width, height, error);
    case Backend::automatic:
      break;
  }
  // OSMesa first: the back end every frame was drawn with before EGL came (the two give the same
  // bytes on llvmpipe, tested), then EGL, which newer Mesas keep.
  std::string tried;
  for (const Backend each : {Backend::osmesa, Backend::egl}) {
    if (!backend_built(each)) continue;
    std::string failure;
    auto context = create_offscreen_context(width, height, each, failure);
    if (context) return context;
    tried += std::string(tried.empty() ? "" : "; ") + backend_name(each) + ": " + failure;
  }
  error = tried.empty() ? "this tumble was built with no off-screen back end" : tried;
  return nullptr;
}

}  // namespace tumble::render
