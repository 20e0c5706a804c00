// The scene as plain data, as read from a scene file and validated. Building the physics from it
// is scene_builder's job; drawing it will be render's.
#pragma once

#include <string>
#include <vector>

#include "physics/forces.hpp"
#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::scene {

enum class Shape { cube, box };

struct BodySpec {
  std::string name;
  Shape shape = Shape::cube;
  physics::Vec3 size = physics::Vec3::Ones();              // edge lengths along the body axes (m)
  double mass = 1.0;                                       // kg
  physics::Vec3 position = physics::Vec3::Zero();          // world frame (m)
  physics::Vec3 velocity = physics::Vec3::Zero();          // world frame (m/s)
  physics::Quat orientation = physics::Quat::Identity();   // body-to-world, unit
  physics::Vec3 angular_velocity = physics::Vec3::Zero();  // world frame (rad/s)
  std::vector<physics::ForceLaw> forces;                   // only what the scene lists
};

struct PhysicsSettings {
  double dt = 0.01;  // fixed step (s)
  physics::Integrator integrator = physics::Integrator::rk4;
};

struct Scene {
  std::string name;         // used for output folder and file names
  std::string source_path;  // the file it was read from, for messages
  double duration = 0.0;    // simulated time (s)
  PhysicsSettings physics;
  std::vector<BodySpec> bodies;
};

}  // namespace tumble::scene
