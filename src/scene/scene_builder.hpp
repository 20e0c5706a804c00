// From scene data to physics objects.
#pragma once

#include <span>

#include "scene/scene.hpp"
#include "sim/simulation.hpp"

namespace tumble::scene {

physics::BodyConstants body_constants(const BodySpec& body);
// The body's shape for contact: its box, or its sphere.
physics::Shape physics_shape(const BodySpec& body);
physics::BodyState initial_state(const BodySpec& body);
// Number of fixed steps that cover the scene: round(duration / dt).
std::int64_t step_count(const Scene& scene);
// The contact plane of a plane as written: n·x = n·point.
physics::Plane plane(const PlaneSpec& spec);
// A body's model: mass, laws, box and material; with penalty contact, its PenaltyContact law.
physics::BodyModel body_model(const Scene& scene, const BodySpec& body);
// The joint of `spec` placed on the bodies' states at t = 0 (`initial`, one per body).
physics::Joint joint(const JointSpec& spec, std::span<const physics::BodyState> initial);

sim::Simulation build_simulation(const Scene& scene);

}  // namespace tumble::scene
