// The OSMesa (Mesa's software off-screen) implementation of OffscreenContext.
#include <GL/osmesa.h>

#include <cstdint>
#include <vector>

#include "render/gl_loader.hpp"
#include "render/offscreen_context.hpp"

namespace tumble::render {
namespace {

class OsmesaContext final : public OffscreenContext {
 public:
  OsmesaContext(OSMesaContext context, int width, int height)
      : context_(context), width_(width), height_(height), buffer_(4) {}
  ~OsmesaContext() override {
    // Release the buffer before the context, if this is the current one (another renderer's may
    // be).
    if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
  }

  bool make_current() override {
    return OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1);
  }

  int width() const override { return width_; }
  int height() const override { return height_; }
  Backend backend() const override { return Backend::osmesa; }
  std::string device() const override { return {}; }

 private:
  OSMesaContext context_;
  int width_;
  int height_;
  // The default framebuffer OSMesa needs to make the context current, one pixel: frames are
  // drawn into the renderer's own framebuffers and read from those, and a frame-sized default
  // framebuffer (with the depth buffer Mesa gives it) held 100 MB at 3840 × 2160 for nothing.
  std::vector<std::uint8_t> buffer_;
};

}  // namespace

Result<std::unique_ptr<OffscreenContext>> create_osmesa_context(int width, int height) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context) {
    return Error{
        "OSMesaCreateContextAttribs failed: no OpenGL 3.3 core context (is Mesa's OSMesa "
        "installed? Debian: libosmesa6)"};
  }
  auto out = std::make_unique<OsmesaContext>(context, width, height);
  if (!out->make_current()) {
    return Error{"OSMesaMakeCurrent failed for a context of " + std::to_string(width) + "x" +
                 std::to_string(height) + " frames"};
  }
  if (const Result<void> loaded = load_gl_functions(OSMesaGetProcAddress); !loaded) {
    return Error{"OSMesaGetProcAddress has no " + loaded.error()};
  }
  return std::unique_ptr<OffscreenContext>(std::move(out));
}

}  // namespace tumble::render
