// Impulse contact between a box and static planes, against closed forms of mechanics: bounce
// apexes e^{2n} h₀, sliding stops at v₀²/(2μg), slopes stick iff tanθ <= μ, no energy gained, no
// tunnelling, and a tumbling cube that comes to rest and stays still.
#include "physics/plane_contact_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;           // m/s²
constexpr double kStep = 1.0 / 60.0;  // s

// A unit cube of 1 kg (so its bottom face is 0.5 m below its centre) over a floor at y = 0.
struct DropSetup {
  Vec3 position = Vec3(0.0, 0.5, 0.0);  // m
  Vec3 velocity = Vec3::Zero();         // m/s
  Quat orientation = Quat::Identity();
  Vec3 angular_velocity = Vec3::Zero();  // rad/s
  Material body = {.restitution = 0.0, .friction = 0.5};
  std::vector<Plane> planes = {Plane{}};
  bool gravity = true;
  Integrator integrator = Integrator::rk4;
  double dt = kStep;
  bool sleep = true;  // ContactSettings::sleep
};

sim::Simulation simulation(const DropSetup& s) {
  BodyModel model{.constants = cube_constants(1.0, 1.0),
                  .forces = {},
                  .shape = box_shape(Vec3::Constant(0.5)),
                  .material = s.body};
  if (s.gravity) model.forces.push_back(Gravity{.acceleration = Vec3(0.0, -kG, 0.0)});
  const BodyState start =
      make_state(model.constants, s.position, s.velocity, s.orientation, s.angular_velocity);
  return sim::Simulation({model}, {start}, s.integrator, s.dt, s.planes, {.sleep = s.sleep});
}

// Kinetic plus potential energy m g y (J).
double energy(const sim::Simulation& simulation, bool gravity = true) {
  const BodyState& state = simulation.current().front();
  return kinetic_energy(state) + (gravity ? kG * state.position().y() : 0.0);
}

Plane plane_through(const Vec3& point, const Vec3& normal, Material material) {
  const Vec3 unit = normal.normalized();
  return Plane{.normal = unit, .offset = unit.dot(point), .material = material};
}

TEST(PlaneContact, BounceApexesFollowRestitutionSquaredAndTheCubeComesToRest) {
  DropSetup s;
  s.position = Vec3(0.0, 1.5, 0.0);  // bottom face 1 m above the floor
  s.body = {.restitution = 0.5, .friction = 0.0};
  s.planes = {Plane{.material = {.restitution = 0.5, .friction = 0.0}}};
  sim::Simulation world = simulation(s);
  std::vector<double> apexes;  // bottom-face height at each apex, from the ballistic flight (m)
  double previous_velocity = 0.0;
  while (world.time() < 4.0) {
    world.step();
    const BodyState& state = world.current().front();
    const double vy = state.velocity().y();
    // The first step after an impact leaves the floor upwards; its flight's apex is exact from
    // the ballistic formula, whatever the step.
    if (vy > 0.0 && previous_velocity <= 0.0) {
      apexes.push_back(state.position().y() - 0.5 + vy * vy / (2.0 * kG));
    }
    previous_velocity = vy;
  }
  ASSERT_GE(apexes.size(), 3u);
  for (int n = 1; n <= 3; ++n) {
    const double expected = std::pow(0.5, 2 * n);
    std::printf("[ measured ] bounce %d apex %.6f m, closed form %.6f m (%.3f%%)\n", n,
                apexes[n - 1], expected, 100.0 * (apexes[n - 1] / expected - 1.0));
    EXPECT_NEAR(apexes[n - 1], expected, 0.01 * expected) << "bounce " << n;
  }
  const BodyState& rest = world.current().front();
  EXPECT_LT(rest.velocity().norm(), 1e-6);
  EXPECT_NEAR(rest.position().y(), 0.5, 1e-4);
}

struct Slide {
  Vec3 direction;
  double friction;
};

class Sliding : public ::testing::TestWithParam<Slide> {};

TEST_P(Sliding, StopsAtTheClosedFormDistanceAndTimeWithoutTipping) {
  const Slide slide = GetParam();
  const double v0 = 5.0, mu = slide.friction;
  DropSetup s;
  s.velocity = v0 * slide.direction.normalized();
  s.body = {.restitution = 0.0, .friction = mu};
  s.planes = {Plane{.material = {.restitution = 0.0, .friction = mu}}};
  sim::Simulation world = simulation(s);
  double stop_time = -1.0;
  while (world.time() < 3.0) {
    world.step();
    // Stopped: below 1/80 of the speed friction takes away in one step.
    if (stop_time < 0.0 && world.current().front().velocity().norm() < 1e-3) {
      stop_time = world.time();
    }
  }
  const BodyState& end = world.current().front();
  const double distance = (end.position() - s.position).norm();
  const double expected_distance = v0 * v0 / (2.0 * mu * kG);
  const double expected_time = v0 / (mu * kG);
  std::printf(
      "[ measured ] mu %.1f: stopped after %.5f m (closed form %.5f) at t = %.4f s (%.4f)\n", mu,
      distance, expected_distance, stop_time, expected_time);
  EXPECT_NEAR(distance, expected_distance, 0.01 * expected_distance);
  EXPECT_NEAR(stop_time, expected_time, kStep);
  EXPECT_LT(angle_between(end.orientation(), Quat::Identity()), 1e-6) << "it tipped";
  EXPECT_NEAR(end.position().y(), 0.5, 1e-6);
  EXPECT_LT(end.velocity().norm(), 1e-6) << "it creeps after stopping";
}

INSTANTIATE_TEST_SUITE_P(AlongXAndDiagonal, Sliding,
                         ::testing::Values(Slide{Vec3::UnitX(), 0.5}, Slide{Vec3(1, 0, 1), 0.5},
                                           Slide{Vec3::UnitX(), 1.0}, Slide{Vec3(1, 0, 1), 1.0}));

TEST(PlaneContact, FrictionOfOneDeceleratesAtG) {
  DropSetup s;
  s.velocity = Vec3(5.0, 0.0, 0.0);
  s.body = {.restitution = 0.0, .friction = 1.0};
  s.planes = {Plane{.material = {.restitution = 0.0, .friction = 1.0}}};
  sim::Simulation world = simulation(s);
  while (world.time() < 0.25 - 1e-12) world.step();
  const double deceleration = (5.0 - world.current().front().velocity().x()) / world.time();
  std::printf("[ measured ] deceleration at mu = 1: %.6f m/s² (g = %.2f)\n", deceleration, kG);
  EXPECT_NEAR(deceleration, kG, 0.01 * kG);
}

class ElasticDrop : public ::testing::TestWithParam<double /* tilt, degrees */> {};

TEST_P(ElasticDrop, NeverRisesAboveItsStartOrGainsEnergy) {
  DropSetup s;
  s.position = Vec3(0.0, 2.0, 0.0);
  s.orientation = Quat(Eigen::AngleAxisd(GetParam() * std::numbers::pi / 180.0, Vec3::UnitZ()));
  s.body = {.restitution = 1.0, .friction = 0.0};
  s.planes = {Plane{.material = {.restitution = 1.0, .friction = 0.0}}};
  sim::Simulation world = simulation(s);
  const double start_energy = energy(world);
  double highest = 0.0, most_energy = 0.0;
  int bounces = 0;
  double previous_velocity = 0.0;
  while (bounces < 10 && world.time() < 30.0) {
    world.step();
    const BodyState& state = world.current().front();
    highest = std::max(highest, state.position().y() - s.position.y());
    most_energy = std::max(most_energy, energy(world) - start_energy);
    if (state.velocity().y() > 0.0 && previous_velocity <= 0.0) ++bounces;
    previous_velocity = state.velocity().y();
  }
  std::printf(
      "[ measured ] tilt %.0f°: %d bounces, highest rise %.3g m, energy gain %.3g J of %.3g\n",
      GetParam(), bounces, highest, most_energy, start_energy);
  EXPECT_EQ(bounces, 10);
  EXPECT_LE(highest, 1e-9);
  EXPECT_LE(most_energy, 1e-9 * start_energy);
}

INSTANTIATE_TEST_SUITE_P(FlatAndOnAnEdge, ElasticDrop, ::testing::Values(0.0, 30.0));

// A unit cube resting on a face on a slope of angle θ: the slope's plane through the origin, the
// cube's bottom face on it.
DropSetup on_slope(double degrees, double friction) {
  const double theta = degrees * std::numbers::pi / 180.0;
  const Vec3 normal(-std::sin(theta), std::cos(theta), 0.0);  // rises along +x: downhill is -x
  DropSetup s;
  s.position = 0.5 * normal;
  s.orientation = Quat(Eigen::AngleAxisd(theta, Vec3::UnitZ()));
  s.body = {.restitution = 0.0, .friction = friction};
  s.planes = {plane_through(Vec3::Zero(), normal, {.restitution = 0.0, .friction = friction})};
  return s;
}

TEST(PlaneContact, CubeOnASlopeSticksWhenFrictionExceedsTheTangent) {
  const DropSetup s = on_slope(20.0, 0.5);
  sim::Simulation world = simulation(s);
  while (world.time() < 10.0 - 1e-12) world.step();
  const double moved = (world.current().front().position() - s.position).norm();
  std::printf("[ measured ] 20° slope, mu 0.5: moved %.3g m in 10 s\n", moved);
  EXPECT_LT(moved, 1e-3);
}

TEST(PlaneContact, CubeOnASlopeSlidesWithTheClosedFormAcceleration) {
  const double theta = 20.0 * std::numbers::pi / 180.0, mu = 0.2;
  const DropSetup s = on_slope(20.0, mu);
  sim::Simulation world = simulation(s);
  while (world.time() < 2.0 - 1e-12) world.step();
  const double distance = (world.current().front().position() - s.position).norm();
  const double acceleration = 2.0 * distance / (world.time() * world.time());
  const double expected = kG * (std::sin(theta) - mu * std::cos(theta));
  std::printf("[ measured ] 20° slope, mu 0.2: %.5f m/s² (closed form %.5f)\n", acceleration,
              expected);
  EXPECT_NEAR(acceleration, expected, 0.01 * expected);
}

// The solver alone (sleep = false) must bring the cube to rest and hold it without jitter or
// creep; with sleeping (the default) the cube falls asleep on the way and stays exactly still.
void expect_tumbling_cube_to_rest(bool sleep) {
  SCOPED_TRACE(sleep ? "sleep on" : "sleep off");
  DropSetup s;
  s.sleep = sleep;
  s.position = Vec3(0.0, 2.0, 0.0);
  // A corner first: rotated 45° about z, then about x by atan(1/√2), spinning.
  s.orientation = Quat(Eigen::AngleAxisd(std::atan(1.0 / std::sqrt(2.0)), Vec3::UnitX())) *
                  Quat(Eigen::AngleAxisd(std::numbers::pi / 4.0, Vec3::UnitZ()));
  s.angular_velocity = Vec3(1.0, 4.0, 0.5);
  s.body = {.restitution = 0.3, .friction = 0.5};
  s.planes = {Plane{.material = {.restitution = 0.3, .friction = 0.5}}};
  sim::Simulation world = simulation(s);
  while (world.time() < 10.0 - 1e-12) world.step();
  const BodyState rest = world.current().front();
  // The face most nearly facing down: its normal against the floor's.
  double face_angle = std::numbers::pi;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 face = rest.orientation() * Vec3::Unit(axis);
    face_angle = std::min(face_angle, std::acos(std::min(1.0, std::abs(face.y()))));
  }
  const double penetration = -closest_corner_separation(rest, Vec3::Constant(0.5), s.planes[0]);
  std::printf(
      "[ measured ] sleep %s, at 10 s: |v| %.3g m/s, |w| %.3g rad/s, face %.3g rad, penetration "
      "%.3g m\n",
      sleep ? "on" : "off", rest.velocity().norm(), rest.angular_velocity().norm(), face_angle,
      penetration);
  EXPECT_LT(rest.velocity().norm(), 1e-3);
  EXPECT_LT(rest.angular_velocity().norm(), 1e-3);
  EXPECT_LT(face_angle, 1e-3);
  EXPECT_LT(penetration, 1e-3);
  double largest_move = 0.0;
  BodyState previous = rest;
  while (world.time() < 60.0 - 1e-12) {
    world.step();
    const BodyState& now = world.current().front();
    for (int feature = 0; feature < 8; ++feature) {
      const Vec3 c = corner(Vec3::Constant(0.5), feature);
      largest_move = std::max(
          largest_move, (body_point_to_world(now, c) - body_point_to_world(previous, c)).norm());
    }
    previous = now;
  }
  std::printf("[ measured ] sleep %s, 10-60 s: largest corner move in a step %.3g m\n",
              sleep ? "on" : "off", largest_move);
  EXPECT_LT(largest_move, 1e-5);
}

TEST(PlaneContact, TumblingCubeComesToRestOnAFaceAndStaysStill) {
  expect_tumbling_cube_to_rest(false);
  expect_tumbling_cube_to_rest(true);
}

// A cube resting awake on a face: what the solve leaves of its momenta is set to exactly zero
// before it becomes a subnormal number (the FPU's slow path), so that the momenta end exactly zero.
TEST(PlaneContact, RestingCubeAwakeEndsWithExactlyZeroMomentaAndNoSubnormal) {
  DropSetup s;
  s.sleep = false;
  sim::Simulation world = simulation(s);
  int subnormal_steps = 0;
  // Left alone, the residue would shrink from 1e-8 to subnormal by about 24 s.
  while (world.time() < 30.0 - 1e-12) {
    world.step();
    const BodyState& now = world.current().front();
    for (int i = 0; i < 3; ++i) {
      if (std::fpclassify(now.momentum()[i]) == FP_SUBNORMAL ||
          std::fpclassify(now.angular_momentum()[i]) == FP_SUBNORMAL) {
        ++subnormal_steps;
      }
    }
  }
  const BodyState& rest = world.current().front();
  EXPECT_EQ(subnormal_steps, 0);
  EXPECT_EQ(rest.momentum(), Vec3::Zero());
  EXPECT_EQ(rest.angular_momentum(), Vec3::Zero());
}

TEST(PlaneContact, ElasticCubeBetweenTwoWallsKeepsItsEnergy) {
  DropSetup s;
  s.position = Vec3::Zero();
  s.velocity = Vec3(7.0, 0.0, 0.0);
  s.angular_velocity = Vec3(0.3, 0.7, -0.2);
  s.gravity = false;
  s.body = {.restitution = 1.0, .friction = 0.0};
  const Material wall{.restitution = 1.0, .friction = 0.0};
  s.planes = {plane_through(Vec3(-2, 0, 0), Vec3::UnitX(), wall),
              plane_through(Vec3(2, 0, 0), -Vec3::UnitX(), wall)};
  sim::Simulation world = simulation(s);
  const double start = energy(world, false);
  int bounces = 0;
  double previous = s.velocity.x();
  while (bounces < 100) {
    world.step();
    const double vx = world.current().front().velocity().x();
    if ((vx > 0.0) != (previous > 0.0)) ++bounces;
    previous = vx;
    ASSERT_LT(world.time(), 1000.0);
  }
  const double drift = std::abs(energy(world, false) - start) / start;
  std::printf("[ measured ] 100 elastic wall bounces: relative energy change %.3g\n", drift);
  EXPECT_LT(drift, 1e-6);
}

class Tunnelling : public ::testing::TestWithParam<double /* dt */> {};

TEST_P(Tunnelling, CubeAt100MetresPerSecondBouncesOffAWall) {
  DropSetup s;
  s.position = Vec3(-3.0, 0.0, 0.0);
  s.velocity = Vec3(100.0, 0.0, 0.0);
  s.gravity = false;
  s.dt = GetParam();
  s.body = {.restitution = 0.5, .friction = 0.5};
  s.planes = {plane_through(Vec3::Zero(), -Vec3::UnitX(), {.restitution = 0.5, .friction = 0.5})};
  sim::Simulation world = simulation(s);
  double furthest = -10.0;
  while (world.time() < 0.5) {
    world.step();
    furthest = std::max(furthest, world.current().front().position().x());
  }
  EXPECT_LE(furthest, -0.5 + 1e-6);  // the face never passed the wall
  EXPECT_NEAR(world.current().front().velocity().x(), -50.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(AtCoarseSteps, Tunnelling, ::testing::Values(1.0 / 60.0, 1.0 / 30.0));

// No energy from nowhere: kinetic plus potential energy never rises above its start by more than
// 1e-9 of it, in every kind of contact above (restitution <= 1), with rk4 for 10 s.
struct EnergyCase {
  const char* name;
  DropSetup setup;
};

class NoEnergyFromNowhere : public ::testing::TestWithParam<EnergyCase> {};

TEST_P(NoEnergyFromNowhere, EnergyNeverRisesAboveItsStart) {
  sim::Simulation world = simulation(GetParam().setup);
  const double start = energy(world);
  double largest_gain = 0.0;
  while (world.time() < 10.0 - 1e-12) {
    world.step();
    largest_gain = std::max(largest_gain, energy(world) - start);
  }
  std::printf("[ measured ] %s: largest energy gain %.3g J of %.3g J\n", GetParam().name,
              largest_gain, start);
  EXPECT_LE(largest_gain, 1e-9 * std::abs(start));
}

std::vector<EnergyCase> energy_cases() {
  std::vector<EnergyCase> out;
  DropSetup bounce;
  bounce.position = Vec3(0.0, 1.5, 0.0);
  bounce.body = {.restitution = 0.5, .friction = 0.0};
  out.push_back({"bounce", bounce});
  DropSetup slide;
  slide.velocity = Vec3(5.0, 0.0, 5.0);
  out.push_back({"diagonal_slide", slide});
  out.push_back({"slope_sticks", on_slope(20.0, 0.5)});
  out.push_back({"slope_slides", on_slope(20.0, 0.2)});
  DropSetup tumble;
  tumble.position = Vec3(0.0, 2.0, 0.0);
  tumble.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 0.3, 0.2).normalized()));
  tumble.angular_velocity = Vec3(2.0, 1.0, -3.0);
  tumble.body = {.restitution = 0.3, .friction = 0.5};
  out.push_back({"tumbling_drop", tumble});
  DropSetup walls = tumble;
  walls.velocity = Vec3(6.0, 2.0, -4.0);
  walls.body = {.restitution = 1.0, .friction = 0.3};
  const Material wall{.restitution = 0.8, .friction = 0.4};
  walls.planes = {Plane{.material = wall}, plane_through(Vec3(2, 0, 0), -Vec3::UnitX(), wall),
                  plane_through(Vec3(0, 0, -2), Vec3::UnitZ(), wall)};
  out.push_back({"thrown_into_a_corner", walls});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Contact, NoEnergyFromNowhere, ::testing::ValuesIn(energy_cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// Every integrator composes with impulse contact: the tumbling drop comes to rest on a face, just
// touching the floor, and stays there.
class EveryIntegrator : public ::testing::TestWithParam<Integrator> {};

TEST_P(EveryIntegrator, TumblingDropComesToRestTouchingTheFloor) {
  DropSetup s;
  s.integrator = GetParam();
  s.position = Vec3(0.0, 2.0, 0.0);
  s.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 0.3, 0.2).normalized()));
  s.angular_velocity = Vec3(2.0, 1.0, -3.0);
  s.body = {.restitution = 0.3, .friction = 0.5};
  s.planes = {Plane{.material = {.restitution = 0.3, .friction = 0.5}}};
  sim::Simulation world = simulation(s);
  double deepest = 0.0;
  while (world.time() < 10.0 - 1e-12) {
    world.step();
    deepest = std::max(deepest, -closest_corner_separation(world.current().front(),
                                                           Vec3::Constant(0.5), s.planes[0]));
  }
  const BodyState& rest = world.current().front();
  std::printf("[ measured ] %s: deepest %.3g m, at 10 s |v| %.3g m/s, |w| %.3g rad/s\n",
              std::string(integrator_name(GetParam())).c_str(), deepest, rest.velocity().norm(),
              rest.angular_velocity().norm());
  EXPECT_FALSE(world.blow_up());
  EXPECT_LT(deepest, 1e-3);
  EXPECT_LT(rest.velocity().norm(), 1e-3);
  EXPECT_LT(rest.angular_velocity().norm(), 1e-3);
  EXPECT_NEAR(rest.position().y(), 0.5, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Contact, EveryIntegrator, ::testing::ValuesIn(kAllIntegrators),
                         [](const auto& info) { return std::string(integrator_name(info.param)); });

}  // namespace
}  // namespace tumble::physics
