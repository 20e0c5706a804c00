// How planes become the drawn floor and quads, and how much of them the default camera frames.
#include "view/plane_view.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "view/scene_view.hpp"

namespace tumble::view {
namespace {

using render::Vec3;

// A still cube resting on the origin's floor, and the planes in `planes` (TOML).
scene::Scene scene_with(const std::string& planes) {
  const Result<scene::Scene> loaded = scene::parse_scene(
      "duration = 0.1\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\nposition = [0, 0.5, "
      "0]\n" +
          planes,
      "planes.toml");
  if (!loaded) {
    ADD_FAILURE() << loaded.error();
    return {};
  }
  return *loaded;
}

// The quad's axes in the world: across (local x), its front (local y), up its slope (local z).
Eigen::Matrix3d axes(const render::Quad& quad) {
  return quad.orientation.toRotationMatrix();
}

TEST(PlaneView, TheLowestVisibleLevelPlaneIsTheFloorAndTheOthersAreQuads) {
  const DrawnPlanes drawn = drawn_planes(scene_with(R"(
[[planes]]
name = "raised"
point = [0, -0.5, 0]
normal = [0, 1, 0]
[[planes]]
name = "hidden"
point = [0, -2, 0]
normal = [0, 1, 0]
visible = false
[[planes]]
name = "floor"
point = [3, -1, 4]
normal = [0, 5, 0]
[[planes]]
name = "slope"
point = [0, -6, 0]
normal = [-0.342, 0.94, 0]
)"));
  EXPECT_TRUE(drawn.ground.enabled);
  EXPECT_EQ(drawn.ground.height, -1.0);
  ASSERT_EQ(drawn.quads.size(), 2u);  // raised and slope; hidden is not drawn
  EXPECT_EQ(drawn.quads[0].center, Vec3(0, -0.5, 0));
  EXPECT_EQ(drawn.quads[1].center, Vec3(0, -6, 0));
}

// A slope is drawn as a quad whatever its height; with no level plane there is no ground, not
// even the one [ground] would place without planes.
TEST(PlaneView, WithoutALevelPlaneNoGroundIsDrawn) {
  const DrawnPlanes drawn = drawn_planes(scene_with(R"(
[[planes]]
point = [0, -1, 0]
normal = [-0.342, 0.94, 0]
[[planes]]
point = [0, -3, 0]
normal = [0, 1, 0]
visible = false
)"));
  EXPECT_FALSE(drawn.ground.enabled);
  ASSERT_EQ(drawn.quads.size(), 1u);
  EXPECT_NEAR(axes(drawn.quads[0]).col(1).y(), 0.94 / std::hypot(0.342, 0.94), 1e-15);
}

// size = [across, up the slope]: a wall's first extent is horizontal and its second vertical; a
// level plane's run along x, then z. [ground] gives the grid, and a lighter colour.
TEST(PlaneView, AQuadsSizeRunsAcrossThePlaneThenUpItsSlope) {
  const DrawnPlanes drawn = drawn_planes(scene_with(R"(
[[planes]]
point = [-2, 1.5, 0]
normal = [1, 0, 0]
size = [6, 3]
[[planes]]
point = [0, -0.5, 0]
normal = [0, 1, 0]
size = [4, 2]
[[planes]]
point = [0, -1, 0]
normal = [0, 1, 0]
[ground]
grid_spacing = 0.25
)"));
  ASSERT_EQ(drawn.quads.size(), 2u);
  const render::Quad& wall = drawn.quads[0];
  EXPECT_EQ(wall.width, 6.0);
  EXPECT_EQ(wall.depth, 3.0);
  EXPECT_NEAR(std::abs(axes(wall).col(0).z()), 1.0, 1e-15);  // across: horizontal, in the wall
  EXPECT_NEAR(axes(wall).col(1).x(), 1.0, 1e-15);            // front: the normal
  EXPECT_NEAR(axes(wall).col(2).y(), 1.0, 1e-15);            // up
  const render::Quad& shelf = drawn.quads[1];
  EXPECT_TRUE(axes(shelf).isApprox(Eigen::Matrix3d::Identity(), 1e-15));
  EXPECT_EQ(wall.grid_spacing, 0.25);
  const render::Color ground = drawn.ground.color;
  EXPECT_GT(wall.color.x(), ground.x());
  EXPECT_GT(wall.color.z(), ground.z());
}

// A wall at x facing -x, centred at y = 0.5: `width` along y, `height` along z.
render::Quad wall_at_x(double x, double width, double height) {
  return render::Quad{.center = Vec3(x, 0.5, 0),
                      .orientation = render::Quat::FromTwoVectors(Vec3::UnitY(), -Vec3::UnitX()),
                      .width = width,
                      .depth = height};
}

TEST(PlaneView, AWallIsFramedOnlyAsFarAsItLiesNearTheMotion) {
  Vec3 low(0, 0.5, 0), high(0, 0.5, 0);
  frame_walls({wall_at_x(1.0, 20.0, 20.0)}, 2.0, low, high);
  EXPECT_TRUE(low.isApprox(Vec3(0, -1.5, -2)));
  EXPECT_TRUE(high.isApprox(Vec3(1, 2.5, 2)));
}

TEST(PlaneView, AWallSmallerThanTheReachIsFramedWhole) {
  Vec3 low(0, 0.5, 0), high(0, 0.5, 0);
  frame_walls({wall_at_x(1.0, 1.0, 2.0)}, 2.0, low, high);
  EXPECT_TRUE(low.isApprox(Vec3(0, 0, -1)));
  EXPECT_TRUE(high.isApprox(Vec3(1, 1, 1)));
}

TEST(PlaneView, FarWallsFloorsAndSlopesAreNotFramed) {
  Vec3 low(0, 0.5, 0), high(0, 0.5, 0);
  const render::Quad shelf{.center = Vec3(0, 0, 0), .width = 40.0, .depth = 40.0};
  const render::Quad slope{
      .center = Vec3(0, 0, 0),
      .orientation = render::Quat(Eigen::AngleAxisd(0.7, Vec3::UnitZ())),  // 40° from level
      .width = 40.0,
      .depth = 40.0};
  frame_walls({wall_at_x(3.0, 20.0, 20.0), shelf, slope}, 2.0, low, high);
  EXPECT_EQ(low, Vec3(0, 0.5, 0));
  EXPECT_EQ(high, Vec3(0, 0.5, 0));
}

// Through frame_scene: the floor plane places the ground, the wall's quad is drawn every frame
// and pulls the camera's aim towards it.
TEST(PlaneView, AFramedSceneDrawsTheFloorPlaneAndLooksTowardsItsWall) {
  const scene::Scene scene = scene_with(R"(
[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
[[planes]]
point = [-1.5, 1, 0]
normal = [1, 0, 0]
size = [3, 2]
)");
  const Result<Framing> framed = frame_scene(scene, 6, [] { return false; });
  ASSERT_TRUE(framed) << framed.error();
  const Framing& framing = *framed;
  EXPECT_TRUE(framing.ground.enabled);
  EXPECT_EQ(framing.ground.height, 0.0);
  ASSERT_EQ(framing.quads.size(), 1u);
  EXPECT_LT(framing.camera.look_at.x(), -0.5);  // half way from the cube to the wall
  const render::FrameView view =
      frame_view(scene, framing, {scene::initial_state(scene.bodies[0])}, 0.0);
  EXPECT_EQ(view.quads.size(), 1u);
}

}  // namespace
}  // namespace tumble::view
