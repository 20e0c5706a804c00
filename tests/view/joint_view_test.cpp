// Joints in a frame (view/joint_view.hpp): a distance joint drawn as a rod between its anchors, a
// hinge as a pin along its axis, a ball as a ball, nothing for a hidden one; and the values texts
// show, from the frame's states.
#include "view/joint_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"

namespace tumble::view {
namespace {

using physics::Vec3;

constexpr const char* kScene = R"(duration = 1.0
[[bodies]]
name = "bob"
shape = "sphere"
radius = 0.1
mass = 1.0
position = [1.0, 0.0, 0.0]
[[bodies]]
name = "door"
shape = "box"
size = [1.0, 2.0, 0.1]
mass = 10.0
position = [3.5, 1.0, 0.0]
[[joints]]
name = "rod"
kind = "distance"
body_a = "bob"
anchor_a = [1.0, 0.0, 0.0]
anchor_b = [1.0, 2.0, 0.0]
[[joints]]
name = "hinge"
kind = "hinge"
body_a = "door"
anchor = [3.0, 1.0, 0.0]
axis = [0.0, 1.0, 0.0]
[[joints]]
name = "hidden"
kind = "ball"
body_a = "bob"
body_b = "door"
anchor = [2.0, 0.0, 0.0]
visible = false
)";

TEST(JointView, DrawsARodBetweenAnchorsAndAPinAlongAHinge) {
  const Result<scene::Scene> scene = scene::parse_scene(kScene, "joints.toml");
  ASSERT_TRUE(scene) << scene.error();
  EXPECT_TRUE(draws_joints(*scene));
  const sim::Simulation simulation = scene::build_simulation(*scene);
  render::FrameView view;
  add_joints(*scene, simulation.joints(), simulation.current(), view);
  ASSERT_EQ(view.boxes.size(), 2u);  // the hidden ball joint draws nothing
  const render::Box& rod = view.boxes[0];
  EXPECT_EQ(rod.solid, render::Solid::cylinder);
  EXPECT_TRUE(rod.position.isApprox(Vec3(1.0, 1.0, 0.0), 1e-12));
  EXPECT_NEAR(rod.size.y(), 2.0, 1e-12);  // anchor to anchor
  EXPECT_TRUE((rod.orientation * Vec3::UnitY()).isApprox(Vec3::UnitY(), 1e-12));
  const render::Box& pin = view.boxes[1];
  EXPECT_EQ(pin.solid, render::Solid::cylinder);
  EXPECT_TRUE(pin.position.isApprox(Vec3(3.0, 1.0, 0.0), 1e-12));
  EXPECT_NEAR(std::abs((pin.orientation * Vec3::UnitY()).y()), 1.0, 1e-12);  // along the axis
}

// At the start, at rest under gravity: the rod (its pivot above the ball's centre) holds the
// ball's weight, m g up on body_a, and measures its length; the hinge holds the door's weight up
// and measures its angle and speed, 0. The forces within 1e-8: K is regularised by 1e-10 of its
// largest diagonal entry (joint_solve.cpp), which moves the hinge's by 1.2e-9 of itself.
TEST(JointView, ValuesAreTheJointsForcesAndCoordinates) {
  const Result<scene::Scene> scene = scene::parse_scene(R"(duration = 1.0
[[bodies]]
name = "bob"
shape = "sphere"
radius = 0.1
mass = 1.0
position = [1.0, 0.0, 0.0]
[[bodies.forces]]
kind = "gravity"
[[bodies]]
name = "door"
shape = "box"
size = [1.0, 2.0, 0.1]
mass = 10.0
position = [3.5, 1.0, 0.0]
[[bodies.forces]]
kind = "gravity"
[[joints]]
name = "rod"
kind = "distance"
body_a = "bob"
anchor_a = [1.0, 0.0, 0.0]
anchor_b = [1.0, 2.0, 0.0]
[[joints]]
name = "hinge"
kind = "hinge"
body_a = "door"
anchor = [3.0, 1.0, 0.0]
axis = [0.0, 1.0, 0.0]
)",
                                                        "joints.toml");
  ASSERT_TRUE(scene) << scene.error();
  const sim::Simulation simulation = scene::build_simulation(*scene);
  const std::vector<JointValue> values =
      joint_values(simulation.joints(), simulation.current(), 0.0);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_TRUE(values[0].force.isApprox(Vec3(0.0, 9.81, 0.0), 1e-8)) << values[0].force.transpose();
  EXPECT_NEAR(values[0].coordinate, 2.0, 1e-12);  // the rod's length
  EXPECT_TRUE(values[0].anchor.isApprox(Vec3(1.0, 0.0, 0.0), 1e-12));
  EXPECT_TRUE(values[1].force.isApprox(Vec3(0.0, 98.1, 0.0), 1e-8)) << values[1].force.transpose();
  EXPECT_NEAR(values[1].coordinate, 0.0, 1e-12);
  EXPECT_NEAR(values[1].rate, 0.0, 1e-12);
}

}  // namespace
}  // namespace tumble::view
