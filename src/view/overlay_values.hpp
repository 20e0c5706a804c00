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
#include "view/joint_view.hpp"

namespace tumble::view {

// A vector quantity of the state (world frame; m, m/s, rad/s or kg m²/s); for a number
// quantity, the number in x and zeros.
physics::Vec3 body_quantity(scene::BodyQuantity quantity, const physics::BodyState& state);

// One placeholder as printf's "%.<precision><conversion>" writes it; a whole vector as
// "(x, y, z)". `states` are every body's at time t (s), the frame's number `frame`, `joints`
// every joint's values there (joint_view.hpp).
std::string format_value(const scene::Placeholder& value,
                         const std::vector<physics::BodyState>& states, double t,
                         std::int64_t frame, std::span<const JointValue> joints = {});

// The whole text with each placeholder formatted.
std::string format_text(const scene::TextTemplate& text,
                        const std::vector<physics::BodyState>& states, double t, std::int64_t frame,
                        std::span<const JointValue> joints = {});

// The vector the overlay's arrow draws (world frame, in the quantity's unit: m/s, rad/s,
// kg m²/s, N, or as written for a constant) for `body` in `state` at time t (s).
physics::Vec3 vector_value(const scene::VectorOverlay& overlay, const scene::BodySpec& body,
                           const physics::BodyState& state, double t);

}  // namespace tumble::view
