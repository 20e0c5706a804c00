// Joints in a frame: what holds what, drawn (a rod or string between a distance joint's
// anchors, a pin at a ball's or a hinge's anchor), and the values texts and arrows show of each
// joint, from the state the frame draws.
#pragma once

#include <span>
#include <vector>

#include "physics/joint_solve.hpp"
#include "render/frame.hpp"
#include "scene/scene.hpp"

namespace tumble::view {

// What a frame shows of one joint.
struct JointValue {
  double coordinate = 0.0;  // a hinge's angle (rad), a slider's travel or a distance's length (m)
  double rate = 0.0;        // its rate (rad/s or m/s)
  physics::Vec3 force = physics::Vec3::Zero();   // on body_a, world frame (N)
  physics::Vec3 anchor = physics::Vec3::Zero();  // its anchor on body_a, world frame (m)
};

// Each joint's values at the bodies' `states` at time t (s), in the scene's order.
std::vector<JointValue> joint_values(const physics::JointWorld& joints,
                                     const std::vector<physics::BodyState>& states, double t);

// Each joint's values at a frame's time t (s), `alpha` of the way from the physics step
// `previous` (at t_previous) to `current` (at t_current): each value at the two steps,
// interpolated as itself (a hinge's angle the short way round), as overlay_values.hpp's
// StepPair does the bodies' quantities.
std::vector<JointValue> joint_values(const physics::JointWorld& joints,
                                     const std::vector<physics::BodyState>& previous,
                                     const std::vector<physics::BodyState>& current, double alpha,
                                     double t_previous, double t_current);

// Whether the scene draws a joint (one is `visible`): then the renderer needs round solids.
bool draws_joints(const scene::Scene& scene);

// Adds the visible joints' rods and pins to `view.boxes`.
void add_joints(const scene::Scene& scene, const physics::JointWorld& joints,
                const std::vector<physics::BodyState>& states, render::FrameView& view);

}  // namespace tumble::view
