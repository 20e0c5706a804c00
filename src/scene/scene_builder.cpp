#include "scene/scene_builder.hpp"

#include <cmath>

namespace tumble::scene {

physics::BodyConstants body_constants(const BodySpec& body) {
  switch (body.shape) {
    case Shape::cube:
      return physics::cube_constants(body.mass, body.size.x());
    case Shape::box:
      return physics::box_constants(body.mass, body.size);
  }
  return {};
}

physics::BodyState initial_state(const BodySpec& body) {
  return physics::make_state(body_constants(body), body.position, body.velocity, body.orientation,
                             body.angular_velocity);
}

std::int64_t step_count(const Scene& scene) {
  return std::llround(scene.duration / scene.physics.dt);
}

sim::Simulation build_simulation(const Scene& scene) {
  std::vector<physics::BodyModel> models;
  std::vector<physics::BodyState> initial;
  for (const BodySpec& body : scene.bodies) {
    models.push_back({.constants = body_constants(body), .forces = body.forces});
    initial.push_back(initial_state(body));
  }
  return sim::Simulation(std::move(models), std::move(initial), scene.physics.integrator,
                         scene.physics.dt);
}

}  // namespace tumble::scene
