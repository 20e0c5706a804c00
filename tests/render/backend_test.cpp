// The off-screen back ends (OSMesa; EGL surfaceless and on Mesa's software device) draw the same
// frames: all are Mesa's llvmpipe behind the renderer's own framebuffers, so every byte must
// agree, with multisampling and with the edge filter, shadows, a grid and a pane of glass.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "support/result_text.hpp"

namespace tumble::render {
namespace {

const std::string kShaders = std::string(TUMBLE_SOURCE_DIR) + "/shaders";

// A cube and a box on a gridded floor, a wall seen from its back (glass) and one from its front.
FrameView scene() {
  FrameView view;
  view.camera.position = Vec3(3.0, 2.2, 4.0);
  view.boxes.push_back(
      Box{.orientation = Quat(Eigen::AngleAxisd(0.5, Vec3(1, 2, 0).normalized()))});
  view.boxes.push_back(Box{.position = Vec3(-1.3, -0.2, -0.6),
                           .size = Vec3(0.6, 0.6, 1.2),
                           .color = Color(0.3, 0.7, 0.3)});
  view.quads.push_back(Quad{.center = Vec3(0.0, 0.5, -2.0),
                            .orientation = Quat::FromTwoVectors(Vec3::UnitY(), Vec3::UnitZ()),
                            .width = 5.0,
                            .depth = 3.0,
                            .grid_spacing = 0.5});
  view.quads.push_back(Quad{.center = Vec3(0.0, 0.5, 2.2),
                            .orientation = Quat::FromTwoVectors(Vec3::UnitY(), Vec3::UnitZ()),
                            .width = 5.0,
                            .depth = 3.0,
                            .grid_spacing = 0.5});
  return view;
}

io::Image draw_with(Backend backend, int msaa, std::string& description,
                    int egl_device = kAutomaticEglDevice) {
  RenderSettings settings;
  settings.width = 320;
  settings.height = 180;
  settings.msaa = msaa;
  settings.ground.height = -0.5;
  settings.backend = backend;
  settings.egl_device = egl_device;
  std::string error;
  const auto renderer =
      ::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error);
  EXPECT_TRUE(renderer) << backend_name(backend) << ": " << error;
  io::Image image;
  if (!renderer) return image;
  renderer->draw(scene(), image);
  description = renderer->description();
  return image;
}

std::size_t differing_bytes(const io::Image& a, const io::Image& b) {
  EXPECT_EQ(a.rgb.size(), b.rgb.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < std::min(a.rgb.size(), b.rgb.size()); ++i)
    differing += a.rgb[i] != b.rgb[i];
  return differing;
}

// The index of Mesa's software device in EGL's list (the renderer says which device drew), or -1.
int software_device() {
  for (int device = 0; device < 8; ++device) {
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.backend = Backend::egl;
    settings.egl_device = device;
    std::string error;
    const auto renderer =
        ::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error);
    if (!renderer) return -1;  // past the end of the list
    if (renderer->device().find("Mesa software") != std::string::npos) return device;
  }
  return -1;
}

TEST(Backend, NamesAreTheScenesWords) {
  EXPECT_STREQ(backend_name(Backend::automatic), "auto");
  EXPECT_STREQ(backend_name(Backend::osmesa), "osmesa");
  EXPECT_STREQ(backend_name(Backend::egl), "egl");
}

TEST(Backend, EglAndOsmesaDrawTheSameBytes) {
  if (!backend_built(Backend::osmesa) || !backend_built(Backend::egl)) {
    GTEST_SKIP() << "this build lacks a back end (OSMesa " << backend_built(Backend::osmesa)
                 << ", EGL " << backend_built(Backend::egl) << ")";
  }
  for (const int msaa : {kEdgeFilter, 4}) {
    SCOPED_TRACE(msaa == kEdgeFilter ? "edge filter" : "msaa 4");
    std::string osmesa_says, egl_says;
    const io::Image osmesa = draw_with(Backend::osmesa, msaa, osmesa_says);
    const io::Image egl = draw_with(Backend::egl, msaa, egl_says);
    EXPECT_NE(osmesa_says.find("(OSMesa)"), std::string::npos) << osmesa_says;
    EXPECT_NE(egl_says.find("(EGL surfaceless)"), std::string::npos) << egl_says;
    ASSERT_EQ(osmesa.width, 320);
    ASSERT_EQ(egl.width, 320);
    EXPECT_EQ(differing_bytes(osmesa, egl), 0u) << "bytes of " << osmesa.rgb.size();
    // The scene is not blank: the check above compares pictures.
    std::size_t distinct_from_first = 0;
    for (std::size_t i = 3; i < osmesa.rgb.size(); i += 3) {
      distinct_from_first += osmesa.rgb[i] != osmesa.rgb[0];
    }
    EXPECT_GT(distinct_from_first, osmesa.rgb.size() / 30);
  }
}

// EGL's device platform on Mesa's software device (EGL_MESA_device_software) is llvmpipe too:
// the same bytes as the surfaceless platform and as OSMesa.
TEST(Backend, EglSoftwareDeviceDrawsTheSameBytes) {
  if (!backend_built(Backend::egl)) GTEST_SKIP() << "built without EGL";
  const int device = software_device();
  if (device < 0) GTEST_SKIP() << "this EGL lists no Mesa software device";
  for (const int msaa : {kEdgeFilter, 4}) {
    SCOPED_TRACE(msaa == kEdgeFilter ? "edge filter" : "msaa 4");
    std::string surfaceless_says, device_says;
    const io::Image surfaceless = draw_with(Backend::egl, msaa, surfaceless_says);
    const io::Image on_device = draw_with(Backend::egl, msaa, device_says, device);
    EXPECT_NE(surfaceless_says.find("(EGL surfaceless)"), std::string::npos) << surfaceless_says;
    EXPECT_NE(device_says.find("(EGL device " + std::to_string(device) + " of "), std::string::npos)
        << device_says;
    ASSERT_EQ(on_device.width, 320);
    EXPECT_EQ(differing_bytes(surfaceless, on_device), 0u);
    if (backend_built(Backend::osmesa)) {
      std::string osmesa_says;
      EXPECT_EQ(differing_bytes(draw_with(Backend::osmesa, msaa, osmesa_says), on_device), 0u);
    }
  }
}

// A device EGL does not list is an error that lists the ones it does, for any back end that
// takes EGL (a named device makes `automatic` take EGL).
TEST(Backend, UnlistedEglDeviceFailsNamingTheDevices) {
  if (!backend_built(Backend::egl)) GTEST_SKIP() << "built without EGL";
  for (const Backend backend : {Backend::egl, Backend::automatic}) {
    RenderSettings settings;
    settings.backend = backend;
    settings.egl_device = common::kMaxEglDevice;
    std::string error;
    EXPECT_FALSE(::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error));
    EXPECT_NE(error.find("egl_device 255: no such EGL device (this machine's: 0: "),
              std::string::npos)
        << error;
  }
}

// With no GPU among EGL's devices (this machine's and CI's), no device is chosen for EGL and
// `automatic` keeps to OSMesa.
TEST(Backend, WithoutAGpuEglHasNoHardwareDevice) {
  if (!backend_built(Backend::egl)) GTEST_SKIP() << "built without EGL";
  if (egl_has_gpu()) GTEST_SKIP() << "this machine has a GPU";
  std::string says;
  draw_with(Backend::egl, kEdgeFilter, says);
  EXPECT_NE(says.find("(EGL surfaceless)"), std::string::npos) << says;
}

// `automatic` takes OSMesa where it is built in (the back end every golden was drawn with) and
// EGL has no GPU.
TEST(Backend, AutomaticPrefersOsmesa) {
  if (!backend_built(Backend::osmesa)) GTEST_SKIP() << "built without OSMesa";
  if (egl_has_gpu()) GTEST_SKIP() << "this machine has a GPU: EGL comes first";
  std::string says;
  draw_with(Backend::automatic, kEdgeFilter, says);
  EXPECT_NE(says.find("(OSMesa)"), std::string::npos) << says;
}

}  // namespace
}  // namespace tumble::render
