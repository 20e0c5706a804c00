// The two off-screen back ends (OSMesa, EGL surfaceless) draw the same frames: both are Mesa's
// llvmpipe behind the renderer's own framebuffers, so every byte must agree, with multisampling
// and with the edge filter, shadows, a grid and a pane of glass.
#include <gtest/gtest.h>

#include <string>

#include "render/renderer.hpp"

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

io::Image draw_with(Backend backend, int msaa, std::string& description) {
  RenderSettings settings;
  settings.width = 320;
  settings.height = 180;
  settings.msaa = msaa;
  settings.ground.height = -0.5;
  settings.backend = backend;
  std::string error;
  const auto renderer = Renderer::create(settings, kShaders, error);
  EXPECT_TRUE(renderer) << backend_name(backend) << ": " << error;
  io::Image image;
  if (!renderer) return image;
  renderer->draw(scene(), image);
  description = renderer->description();
  return image;
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
    std::size_t differing = 0;
    for (std::size_t i = 0; i < osmesa.rgb.size(); ++i) differing += osmesa.rgb[i] != egl.rgb[i];
    EXPECT_EQ(differing, 0u) << "bytes of " << osmesa.rgb.size();
    // The scene is not blank: the check above compares pictures.
    std::size_t distinct_from_first = 0;
    for (std::size_t i = 3; i < osmesa.rgb.size(); i += 3) {
      distinct_from_first += osmesa.rgb[i] != osmesa.rgb[0];
    }
    EXPECT_GT(distinct_from_first, osmesa.rgb.size() / 30);
  }
}

// `automatic` takes OSMesa where it is built in (the back end every golden was drawn with).
TEST(Backend, AutomaticPrefersOsmesa) {
  if (!backend_built(Backend::osmesa)) GTEST_SKIP() << "built without OSMesa";
  std::string says;
  draw_with(Backend::automatic, kEdgeFilter, says);
  EXPECT_NE(says.find("(OSMesa)"), std::string::npos) << says;
}

}  // namespace
}  // namespace tumble::render
