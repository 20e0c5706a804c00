// The values overlays show, from the interpolated state a frame draws (so that the text, the
// arrows and `tumble simulate` at that time agree): the quantities of text placeholders, their
// formatting, and the vector of a vector overlay.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "physics/rigid_body.hpp"
#include "scene/overlays.hpp"
#include "scene/scene.hpp"
#include "sim/simulation.hpp"
#include "view/joint_view.hpp"

namespace tumble::view {

// The two physics steps around a frame's time t. A quantity of the physics shown at t is that
// quantity at each step, interpolated as itself (energy and speeds as numbers, momenta and
// velocities as vectors: q(previous) + alpha (q(current) - q(previous))), not the quantity of
// the drawn state (lerped momenta and a slerped orientation conserve nothing): a conserved
// quantity reads constant to its printed digits. At a step's own time it is that step's value.
struct StepPair {
  const std::vector<physics::BodyState>& previous;
  const std::vector<physics::BodyState>& current;
  double alpha = 0.0;  // where t is from previous (0) to current (1)
};

// A vector quantity of the state (world frame; m, m/s, rad/s or kg m²/s); for a number
// quantity, the number in x and zeros.
physics::Vec3 body_quantity(scene::BodyQuantity quantity, const physics::BodyState& state);
// The same of body `body` at the frame's time, interpolated as the quantity (StepPair).
physics::Vec3 body_quantity(scene::BodyQuantity quantity, const StepPair& steps, std::size_t body);

// `text` padded to the placeholder's width with its fill and alignment, as Python pads.
std::string padded(std::string text, const scene::Placeholder& as);

// The number a placeholder of a body's or joint's number (a scalar quantity, or a vector's
// component) stands for, as format_value shows it before formatting.
double placeholder_number(const scene::Placeholder& value, const StepPair& steps,
                          std::span<const JointValue> joints = {});

// One placeholder as printf's "%<sign>.<precision><conversion>" writes it, padded to its width;
// a whole vector as "(x, y, z)", each number padded. `steps` are every body's around time t (s),
// the frame's number `frame`, `joints` every joint's values there (joint_view.hpp).
std::string format_value(const scene::Placeholder& value, const StepPair& steps, double t,
                         std::int64_t frame, std::span<const JointValue> joints = {});

// The whole text with each placeholder formatted.
std::string format_text(const scene::TextTemplate& text, const StepPair& steps, double t,
                        std::int64_t frame, std::span<const JointValue> joints = {});

// The vector the overlay's arrow draws (world frame, in the quantity's unit: m/s, rad/s,
// kg m²/s, N, N m, or as written for a constant) for `body`: a quantity of the state
// interpolated as itself (StepPair), a force or torque as the force laws give it on the drawn
// state `drawn` at time t (s). A contact force and a joint's come from contact_forces and the
// joints' values: zero here.
physics::Vec3 vector_value(const scene::VectorOverlay& overlay, const scene::BodySpec& body,
                           const StepPair& steps, const physics::BodyState& drawn, double t);

// The contacts on one body over a physics step.
struct BodyContact {
  physics::Vec3 force = physics::Vec3::Zero();  // world frame (N)
  physics::Vec3 point = physics::Vec3::Zero();  // its centre of pressure, world frame (m)
};

// Each body's contact force over the simulation's last step, from previous() to current(): the
// change of its momentum less the impulse of its force laws (the trapezoid rule over the step:
// exact for gravity and constant forces) and of its joints, over dt. With penalty contact its
// contact law is the contact; with impulse contact a body with no contact point at the step
// has none. The centre of pressure is the mean of the body's contact points at the last step
// weighted by their normal impulses (their plain mean when all are zero; the body's centre when
// it touches nothing, or with penalty contact).
std::vector<BodyContact> contact_forces(const sim::Simulation& simulation);

}  // namespace tumble::view
