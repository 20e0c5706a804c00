#include "scene/scene_builder.hpp"

#include <cmath>

#include "physics/mass_properties.hpp"

namespace tumble::scene {

physics::BodyConstants body_constants(const BodySpec& body) {
  if (body.is_static) return physics::static_constants();
  switch (body.shape) {
    case Shape::cube:
      return physics::cube_constants(body.mass, body.size.x());
    case Shape::box:
      return physics::box_constants(body.mass, body.size);
    case Shape::sphere:
      return physics::sphere_constants(body.mass, body.radius);
    case Shape::capsule:
      return physics::constants_from_moments(
          body.mass, physics::capsule_inertia(body.mass, body.radius, body.length).diagonal());
    case Shape::cylinder:
      return physics::constants_from_moments(
          body.mass, physics::cylinder_inertia(body.mass, body.radius, body.length).diagonal());
    case Shape::hull:
      return body.hull->constants;
  }
  return {};
}

physics::Shape physics_shape(const BodySpec& body) {
  switch (body.shape) {
    case Shape::sphere:
      return physics::sphere_shape(body.radius);
    case Shape::capsule:
      return physics::capsule_shape(body.radius, 0.5 * body.length);
    case Shape::cylinder:
      return physics::cylinder_shape(body.radius, 0.5 * body.length);
    case Shape::hull:
      return physics::hull_shape(body.hull->hull);
    case Shape::cube:
    case Shape::box:
      break;
  }
  return physics::box_shape(0.5 * body.size);
}

physics::BodyState initial_state(const BodySpec& body) {
  return physics::make_state(body_constants(body), body.position, body.velocity, body.orientation,
                             body.angular_velocity);
}

std::int64_t step_count(const Scene& scene) {
  return std::llround(scene.duration / scene.physics.dt);
}

physics::Plane plane(const PlaneSpec& spec) {
  return {.normal = spec.normal, .offset = spec.normal.dot(spec.point), .material = spec.material};
}

physics::BodyModel body_model(const Scene& scene, const BodySpec& body) {
  physics::BodyModel model{.constants = body_constants(body),
                           .forces = body.forces,
                           .shape = physics_shape(body),
                           .material = body.material,
                           .collides = body.collide,
                           .is_static = body.is_static};
  const physics::ContactSettings& contact = scene.physics.contact;
  if (!scene.planes.empty() && contact.method == physics::ContactMethod::penalty) {
    std::vector<physics::Plane> planes;
    for (const PlaneSpec& spec : scene.planes) planes.push_back(plane(spec));
    model = physics::with_penalty_contact(std::move(model), std::move(planes), contact.stiffness,
                                          contact.damping);
  }
  return model;
}

physics::Joint joint(const JointSpec& spec, std::span<const physics::BodyState> initial) {
  physics::Joint out = physics::place_joint(spec.kind, spec.body_a, spec.body_b, initial,
                                            spec.anchor_a, spec.anchor_b, spec.axis);
  out.name = spec.name;
  out.limits = spec.limits;
  out.motor = spec.motor;
  if (spec.kind == physics::JointKind::distance) {
    out.min_length = spec.min_length;
    out.max_length = spec.max_length;
    out.stiffness = spec.stiffness;
    out.damping = spec.damping;
  }
  out.collide_connected = spec.collide_connected;
  return out;
}

sim::Simulation build_simulation(const Scene& scene) {
  std::vector<physics::BodyModel> models;
  std::vector<physics::BodyState> initial;
  for (const BodySpec& body : scene.bodies) {
    models.push_back(body_model(scene, body));
    initial.push_back(initial_state(body));
  }
  std::vector<physics::Joint> joints;
  for (const JointSpec& spec : scene.joints) joints.push_back(joint(spec, initial));
  // Impulse contact is the world step's; penalty contact is each body's force law (above).
  std::vector<physics::Plane> planes;
  if (scene.physics.contact.method == physics::ContactMethod::impulse) {
    for (const PlaneSpec& spec : scene.planes) planes.push_back(plane(spec));
  }
  return sim::Simulation(std::move(models), std::move(initial), scene.physics.integrator,
                         scene.physics.dt, std::move(planes), scene.physics.contact,
                         std::move(joints));
}

}  // namespace tumble::scene
