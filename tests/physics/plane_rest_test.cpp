// The resting step of one body on planes (physics/plane_rest.hpp) against the island solve it
// stands in for (contact_island.hpp): from the same state and the same warm-start memory, at
// every touching step of drops, slides and a box thrown into a corner, the two give the same
// state and the same impulses, to the bit: the same operations in the same order.
#include "physics/plane_rest.hpp"

#include <gtest/gtest.h>

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

class PlaneRest : public ::testing::TestWithParam<Case> {};

TEST_P(PlaneRest, GivesTheIslandSolvesStateAndImpulses) {
  const Case& c = GetParam();
  BodyModel model{.constants = box_constants(1.0, c.size),
                  .forces = {Gravity{.acceleration = c.gravity}},
                  .half_size = 0.5 * c.size,
                  .material = c.material};
  BodyState state =
      make_state(model.constants, c.position, c.velocity, c.orientation, c.angular_velocity);
  const ContactSettings settings{};
  PlaneContacts memory;
  int compared = 0, patches = 0;
  double worst_position = 0.0, worst_turn = 0.0, worst_velocity = 0.0, worst_impulse = 0.0;
  for (int n = 0; n < 600; ++n) {
    const double t = n * kStep;
    PlaneContacts lone = memory;
    const PlaneAdvance advance =
        advance_among_planes(Integrator::rk4, model, state, t, kStep, c.planes, settings, lone);
    if (advance.touching) {
      PlaneContacts island = lone;
      BodyState by_lone;
      const bool taken =
          rest_alone_on_planes(model, advance.end, advance.rotation,
                               impulse_position_weight(Integrator::rk4, advance.remaining),
                               c.planes, settings, lone, by_lone);
      const BodyState by_island =
          rest_on_planes_as_island(Integrator::rk4, model, advance, c.planes, settings, island);
      if (taken) {
        ++compared;
        worst_position =
            std::max(worst_position, (by_lone.position() - by_island.position()).norm());
        worst_turn =
            std::max(worst_turn, by_lone.orientation().angularDistance(by_island.orientation()));
        worst_velocity = std::max(
            worst_velocity, (by_lone.velocity() - by_island.velocity()).norm() +
                                (by_lone.angular_velocity() - by_island.angular_velocity()).norm());
        for (std::size_t p = 0; p < c.planes.size(); ++p) {
          const Manifold& a = lone.manifolds[p];
          const Manifold& b = island.manifolds[p];
          ASSERT_EQ(a.count, b.count) << "step " << n << ", plane " << p;
          patches += a.count > 0;
          for (int k = 0; k < a.count; ++k) {
            const auto i = static_cast<std::size_t>(k);
            ASSERT_EQ(a.points[i].feature, b.points[i].feature);
            worst_impulse = std::max(
                worst_impulse, std::abs(a.points[i].impulses.normal - b.points[i].impulses.normal));
          }
          worst_impulse =
              std::max(worst_impulse, (a.friction.tangent - b.friction.tangent).norm() +
                                          std::abs(a.friction.twist - b.friction.twist));
        }
      }
    }
    // The run itself goes on as the program steps it.
    state = step_with_planes(Integrator::rk4, model, state, t, kStep, c.planes, settings, memory);
  }
  std::printf(
      "[ measured ] %s: %d touching steps compared (%d patches); largest differences: "
      "position %.1e m, turn %.1e rad, velocity %.1e, impulse %.1e N s\n",
      c.name, compared, patches, worst_position, worst_turn, worst_velocity, worst_impulse);
  EXPECT_GE(compared, 300);  // most of the run: the body touches from its first second on
  EXPECT_GE(patches, compared * static_cast<int>(c.planes.size()) / 2);  // each plane, mostly
  EXPECT_EQ(worst_position, 0.0);
  EXPECT_EQ(worst_turn, 0.0);
  EXPECT_EQ(worst_velocity, 0.0);
  EXPECT_EQ(worst_impulse, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Runs, PlaneRest, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// A bounce is left to the island solve, whose energy guard it needs; nothing is written then.
TEST(PlaneRestBounce, IsLeftToTheIslandSolve) {
  BodyModel model{.constants = cube_constants(1.0, 1.0),
                  .forces = {},
                  .half_size = Vec3::Constant(0.5),
                  .material = {.restitution = 0.5, .friction = 0.5}};
  const std::vector<Plane> planes = {Plane{.material = model.material}};
  // Resting on the floor, then struck downwards at 2 m/s: its corners touched at the start, so the
  // approach is a resting contact's, faster than the restitution threshold.
  const BodyState end = make_state(model.constants, Vec3(0.0, 0.5 - 1e-9, 0.0),
                                   Vec3(0.0, -2.0, 0.0), Quat::Identity(), Vec3::Zero());
  PlaneContacts memory;
  memory.manifolds.resize(1);
  memory.separations = {
      corner_separations(end.rotation(), end.position(), model.half_size, planes[0])};
  BodyState out = end;
  EXPECT_FALSE(
      rest_alone_on_planes(model, end, end.rotation(), 0.5 * kStep, planes, {}, memory, out));
  EXPECT_EQ(memory.manifolds[0].count, 0);
  EXPECT_EQ(out.position(), end.position());
  // The whole step bounces it: it leaves upwards at e × 2 m/s.
  PlaneAdvance advance{
      .end = end, .rotation = end.rotation(), .remaining = kStep, .touching = true};
  const BodyState bounced = rest_on_planes(Integrator::rk4, model, advance, planes, {}, memory);
  EXPECT_NEAR(bounced.velocity().y(), 1.0, 1e-9);
}

}  // namespace
}  // namespace tumble::physics
