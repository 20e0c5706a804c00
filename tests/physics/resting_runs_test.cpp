// Runs of one body among planes through the one contact solve (step_with_planes, the island
// solve of an island of one): drops, slides and a box thrown into a corner. They were the cases
// a second, hand-made solve of one body was held to the island solve's bits by; now they hold the
// one path to what those runs must do: touch from their first second on, every plane of them,
// never sink into a plane, gain no energy, and end at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>

#include "physics/plane_contact_step.hpp"

namespace tumble::physics {
namespace {

constexpr double kStep = 1.0 / 60.0;  // s

struct Case {
  const char* name;
  Vec3 size;  // m
  Vec3 position, velocity, angular_velocity;
  Quat orientation;
  Material material;
  std::vector<Plane> planes;
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);  // m/s²

  friend void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }
};

Plane plane_through(const Vec3& point, const Vec3& normal, Material material) {
  const Vec3 unit = normal.normalized();
  return Plane{.normal = unit, .offset = unit.dot(point), .material = material};
}

std::vector<Case> cases() {
  const Material sticky{.restitution = 0.0, .friction = 0.5};
  const Material lively{.restitution = 0.3, .friction = 0.5};
  const Quat tilted(Eigen::AngleAxisd(0.6, Vec3(1.0, 0.2, 0.7).normalized()));
  return {
      {"TumblingCube",
       Vec3::Ones(),
       Vec3(0.0, 2.0, 0.0),
       Vec3(1.0, 0.0, 0.0),
       Vec3(2.0, 5.0, 1.0),
       tilted,
       lively,
       {Plane{.material = lively}}},
      // A box with three different moments: the rows go through the rotated inertia tensor.
      {"TumblingBox",
       Vec3(1.0, 0.3, 2.0),
       Vec3(0.0, 1.5, 0.0),
       Vec3::Zero(),
       Vec3(3.0, 1.0, -2.0),
       tilted,
       sticky,
       {Plane{.material = sticky}}},
      {"SlidingCube",
       Vec3::Ones(),
       Vec3(0.0, 0.5, 0.0),
       Vec3(3.0, 0.0, 2.0),
       Vec3::Zero(),
       Quat::Identity(),
       sticky,
       {Plane{.material = sticky}}},
      // Into the corner of a floor and two walls, with gravity leaning into it: three planes'
      // patches in one solve.
      {"CubeIntoACorner",
       Vec3::Ones(),
       Vec3(1.0, 1.0, 1.0),
       Vec3(-4.0, 0.0, -3.0),
       Vec3(0.0, 2.0, 0.0),
       Quat::Identity(),
       sticky,
       {Plane{.material = sticky}, plane_through(Vec3::Zero(), Vec3::UnitX(), sticky),
        plane_through(Vec3::Zero(), Vec3::UnitZ(), sticky)},
       Vec3(-3.0, -9.81, -2.0)},
  };
}

class RestingRun : public ::testing::TestWithParam<Case> {};

// Kinetic energy plus the potential of the case's gravity (J, per kg of the 1 kg box).
double energy(const BodyState& state, const Vec3& gravity) {
  return 0.5 * state.velocity().squaredNorm() +
         0.5 * state.angular_velocity().dot(state.angular_momentum()) -
         gravity.dot(state.position());
}

TEST_P(RestingRun, TouchesEveryPlaneNeverSinksGainsNoEnergyAndEndsAtRest) {
  const Case& c = GetParam();
  BodyModel model{.constants = box_constants(1.0, c.size),
                  .forces = {Gravity{.acceleration = c.gravity}},
                  .shape = box_shape(0.5 * c.size),
                  .material = c.material};
  BodyState state =
      make_state(model.constants, c.position, c.velocity, c.orientation, c.angular_velocity);
  const ContactSettings settings{};
  WorldContacts contacts;
  const double start_energy = energy(state, c.gravity);
  int touching = 0, patches = 0;
  double deepest = 0.0, most_gained = -1.0;  // m, J
  for (int n = 0; n < 600; ++n) {
    state = step_with_planes(Integrator::rk4, model, state, n * kStep, kStep, c.planes, settings,
                             contacts);
    const std::vector<Manifold>& manifolds = contacts.memory.planes[0];
    const bool touches = std::any_of(manifolds.begin(), manifolds.end(),
                                     [](const Manifold& m) { return m.count > 0; });
    touching += touches;
    for (const Manifold& m : manifolds) patches += m.count > 0;
    for (const Plane& plane : c.planes) {
      deepest = std::max(deepest, -closest_corner_separation(state, model.shape.half_size, plane));
    }
    most_gained = std::max(most_gained, energy(state, c.gravity) - start_energy);
  }
  const double speed = state.velocity().norm() + state.angular_velocity().norm();
  std::printf(
      "[ measured ] %s: %d touching steps (%d patches), deepest %.1e m, energy gained "
      "at most %.1e J, final speed %.1e\n",
      c.name, touching, patches, deepest, most_gained, speed);
  EXPECT_GE(touching, 300);  // most of the run: the body touches from its first second on
  EXPECT_GE(patches, touching * static_cast<int>(c.planes.size()) / 2);  // each plane, mostly
  EXPECT_LT(deepest, 1e-9);  // the projection leaves no corner inside
  EXPECT_LE(most_gained, 1e-9);
  EXPECT_LT(speed, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Runs, RestingRun, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// A resting box struck downwards faster than the restitution threshold bounces: the one solve
// has the bounce and its energy guard.
TEST(RestingBounce, LeavesAtRestitutionTimesTheApproach) {
  BodyModel model{.constants = cube_constants(1.0, 1.0),
                  .forces = {},
                  .shape = box_shape(Vec3::Constant(0.5)),
                  .material = {.restitution = 0.5, .friction = 0.5}};
  const std::vector<Plane> planes = {Plane{.material = model.material}};
  // Resting on the floor, then struck downwards at 2 m/s: its corners touched at the start, so the
  // approach is a resting contact's, faster than the restitution threshold.
  const BodyState start = make_state(model.constants, Vec3(0.0, 0.5 - 1e-9, 0.0),
                                     Vec3(0.0, -2.0, 0.0), Quat::Identity(), Vec3::Zero());
  WorldContacts contacts;
  const BodyState bounced =
      step_with_planes(Integrator::rk4, model, start, 0.0, kStep, planes, {}, contacts);
  EXPECT_NEAR(bounced.velocity().y(), 1.0, 1e-9);
}

}  // namespace
}  // namespace tumble::physics
