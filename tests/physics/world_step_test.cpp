// Contact between bodies through the world step, against closed forms and conserved quantities:
// an elastic head-on collision exchanges velocities, momentum is conserved through collisions,
// a tower stands, a fast cube does not pass through a thin box, and the same world gives the
// same bits.
#include "physics/world_step.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;           // m/s²
constexpr double kStep = 1.0 / 60.0;  // s

BodyModel box_model(const Vec3& size, double mass, Material material, bool gravity) {
  BodyModel model{.constants = box_constants(mass, size),
                  .forces = {},
                  .shape = box_shape(0.5 * size),
                  .material = material};
  if (gravity) model.forces.push_back(Gravity{.acceleration = Vec3(0.0, -kG, 0.0)});
  return model;
}

BodyState at_rest(const BodyModel& model, const Vec3& position, const Vec3& velocity = Vec3::Zero(),
                  const Quat& orientation = Quat::Identity(),
                  const Vec3& angular_velocity = Vec3::Zero()) {
  return make_state(model.constants, position, velocity, orientation, angular_velocity);
}

Vec3 total_momentum(const std::vector<BodyState>& states) {
  Vec3 total = Vec3::Zero();
  for (const BodyState& s : states) total += s.momentum();
  return total;
}

TEST(WorldStep, ElasticHeadOnCollisionOfEqualCubesExchangesTheirVelocities) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 1.0, .friction = 0.0}, false);
  const double speed = 3.0;  // m/s
  sim::Simulation world({cube, cube},
                        {at_rest(cube, Vec3(-1.5, 0.0, 0.0), Vec3(speed, 0.0, 0.0)),
                         at_rest(cube, Vec3(0.0, 0.0, 0.0))},
                        Integrator::rk4, kStep);
  const Vec3 momentum = total_momentum(world.current());
  while (world.time() < 1.0) {
    world.step();
    EXPECT_LT((total_momentum(world.current()) - momentum).norm(), 1e-12 * momentum.norm());
  }
  const BodyState& a = world.current()[0];
  const BodyState& b = world.current()[1];
  std::printf("[ measured ] after: a %.3e m/s, b %.12f m/s, spins %.1e %.1e rad/s\n",
              a.velocity().x(), b.velocity().x(), a.angular_velocity().norm(),
              b.angular_velocity().norm());
  EXPECT_LT(a.velocity().norm(), 1e-9 * speed);
  EXPECT_LT((b.velocity() - Vec3(speed, 0.0, 0.0)).norm(), 1e-9 * speed);
  EXPECT_LT(a.angular_velocity().norm() + b.angular_velocity().norm(), 1e-9);
  // They touched and parted: b is ahead of a by at least a cube's width.
  EXPECT_GE(b.position().x() - a.position().x(), 1.0 - 1e-9);
}

// Newton's cradle of ten touching cubes (e = 1, μ = 0, no gravity), struck at either end: the
// impact passes on pair by pair, so the far cube leaves with the striker's speed and every other
// cube stays still, whichever way the bodies' order runs against the pulse (impacts are taken
// again only where the last ones moved bodies, as often as the row needs).
TEST(WorldStep, ACradleOfTenCubesPassesTheImpactToTheFarEndFromEitherEnd) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 1.0, .friction = 0.0}, false);
  for (const double way : {1.0, -1.0}) {
    std::vector<BodyModel> models(11, cube);
    std::vector<BodyState> start;
    for (int k = 0; k < 10; ++k) start.push_back(at_rest(cube, Vec3(k, 0.0, 0.0)));
    const double from = way > 0.0 ? -1.5 : 10.5;  // m
    const BodyState striker = at_rest(cube, Vec3(from, 0.0, 0.0), Vec3(2.0 * way, 0.0, 0.0));
    if (way > 0.0) {
      start.insert(start.begin(), striker);
    } else {
      start.push_back(striker);
    }
    sim::Simulation world(models, start, Integrator::rk4, kStep);
    while (world.time() < 3.0) world.step();
    const std::vector<BodyState>& end = world.current();
    const std::size_t far = way > 0.0 ? 10 : 0;
    EXPECT_NEAR(end[far].velocity().x(), 2.0 * way, 1e-8) << way;
    for (std::size_t k = 0; k < end.size(); ++k) {
      if (k != far) {
        EXPECT_LT(end[k].velocity().norm(), 1e-8) << way << " cube " << k;
      }
    }
  }
}

// The stacks below measure the solver itself: they run awake, for a sleeping stack holds still
// whatever the solver would do.
constexpr ContactSettings kAwake{.sleep = false};

// A stack of unit cubes on a floor, each resting on the one below (faces touching at the start).
sim::Simulation stack(int count, Integrator integrator = Integrator::rk4) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  std::vector<BodyModel> models(static_cast<std::size_t>(count), cube);
  std::vector<BodyState> start;
  for (int k = 0; k < count; ++k) start.push_back(at_rest(cube, Vec3(0.0, 0.5 + k, 0.0)));
  return sim::Simulation(models, start, integrator, kStep,
                         {Plane{.material = {.restitution = 0.0, .friction = 0.5}}}, kAwake);
}

// A cube sliding slowly on another, 5e-7 m above it (no gravity, no friction: nothing pushes):
// its pair keeps the narrow phase's points while the cube has moved less than kReuseDistance
// since they were found, their separations measured anew, then gets fresh ones. Each step's
// manifold is checked against the narrow phase's at the step's start.
TEST(WorldStep, APairThatBarelyMovedKeepsItsPointsAndMeasuresThemAnew) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.0, .friction = 0.0}, false);
  const double speed = 1e-3;  // m/s along x: 1.67e-5 m a step
  const double gap = 5e-7;    // m: within the bounds' kTouchingDistance
  std::vector<BodyState> states = {at_rest(cube, Vec3::Zero()),
                                   at_rest(cube, Vec3(0.0, 1.0 + gap, 0.0), Vec3(speed, 0, 0))};
  const std::vector<BodyModel> models = {cube, cube};
  std::vector<BodyState> next(2);
  WorldContacts contacts;
  const ContactSettings settings;
  Vec3 found_at = states[1].position();  // where the kept points were found
  std::array<Vec3, 4> found;             // their A-frame positions
  int kept = 0, refreshed = 0;
  for (int n = 0; n < 20; ++n) {
    const std::vector<BodyState> start = states;
    step_world(Integrator::rk4, models, states, n * kStep, kStep, {}, settings, contacts, next);
    states.swap(next);
    ASSERT_EQ(contacts.memory.pairs.size(), 1u);
    const PairManifold& used = contacts.memory.pairs[0].manifold;
    const auto pose = [&](const BodyState& s) {
      return BoxPose{
          .position = s.position(), .rotation = s.rotation(), .half_size = cube.shape.half_size};
    };
    const PairManifold fresh = box_box_manifold(pose(start[0]), pose(start[1]), 1e-3);
    ASSERT_EQ(used.count, 4);
    ASSERT_EQ(fresh.count, 4);
    EXPECT_LT((used.normal - fresh.normal).norm(), 1e-15);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(used.points[k].separation, gap, 1e-15);
    // The fresh clip follows the sliding face; kept points stay where they were found.
    const bool keeps = n > 0 && (start[1].position() - found_at).norm() < kReuseDistance;
    if (keeps) {
      ++kept;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(used.points[k].point_a, found[k]) << "step " << n;
      EXPECT_NE(used.points[0].point_a, fresh.points[0].point_a) << "step " << n;
    } else {
      ++refreshed;
      found_at = start[1].position();
      for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(used.points[k].point_a, fresh.points[k].point_a) << "step " << n;
        found[k] = used.points[k].point_a;
      }
    }
  }
  std::printf("[ measured ] 20 steps: %d kept the points, %d found them anew\n", kept, refreshed);
  EXPECT_GT(kept, 10);
  EXPECT_GE(refreshed, 3);
}

// The sub-steps of an island: Box2D's four while nothing closes fast, one per kSubstepReach of
// the fastest closing beyond that, at most kMostSubsteps.
TEST(WorldStep, SubstepsFollowTheFastestClosing) {
  EXPECT_EQ(substeps_for(0.0), kSubsteps);
  EXPECT_EQ(substeps_for(kSubsteps * kSubstepReach), kSubsteps);
  EXPECT_EQ(substeps_for(kSubsteps * kSubstepReach * 1.01), kSubsteps + 1);
  EXPECT_EQ(substeps_for(10.0 * kSubstepReach), 10);
  EXPECT_EQ(substeps_for(1.0), kMostSubsteps);  // 60 m/s
}

TEST(WorldStep, TowerOfTenCubesStandsForAMinute) {
  sim::Simulation world = stack(10);
  const Vec3 top_start = world.current().back().position();
  double drift = 0.0, sink = 0.0, tilt = 0.0;  // largest over the run (m, m, rad)
  while (world.time() < 60.0) {
    world.step();
    ASSERT_FALSE(world.blow_up().has_value());
    const Vec3 top = world.current().back().position();
    drift = std::max(drift, std::hypot(top.x() - top_start.x(), top.z() - top_start.z()));
    sink = std::max(sink, std::abs(top.y() - top_start.y()));
    for (const BodyState& s : world.current()) {
      tilt = std::max(tilt, angle_between(Quat::Identity(), s.orientation()));
    }
  }
  std::printf(
      "[ measured ] top cube over 60 s: %.2e m sideways, %.2e m vertically; tilt %.2e rad\n", drift,
      sink, tilt);
  EXPECT_LT(drift, 0.01);
  EXPECT_LT(sink, 0.001);
  EXPECT_LT(tilt, 0.01);  // no box tips
}

// A 2D-style pyramid of unit cubes, ten rows (55 boxes), 5 cm apart within a row, each box on
// two below it: Box2D's classic stacking test, in 3D.
TEST(WorldStep, PyramidOfFiftyFiveCubesStandsForHalfAMinute) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  std::vector<BodyModel> models;
  std::vector<BodyState> start;
  for (int row = 0; row < 10; ++row) {
    const int count = 10 - row;
    for (int i = 0; i < count; ++i) {
      models.push_back(cube);
      start.push_back(at_rest(cube, Vec3(1.05 * (i - 0.5 * (count - 1)), 0.5 + row, 0.0)));
    }
  }
  sim::Simulation world(models, start, Integrator::rk4, kStep,
                        {Plane{.material = {.restitution = 0.0, .friction = 0.5}}}, kAwake);
  double worst = 0.0;  // the largest distance of any box from its start (m)
  while (world.time() < 30.0) {
    world.step();
    ASSERT_FALSE(world.blow_up().has_value());
    for (std::size_t i = 0; i < start.size(); ++i) {
      worst = std::max(worst, (world.current()[i].position() - start[i].position()).norm());
    }
  }
  std::printf("[ measured ] pyramid of 55 over 30 s: largest move of a box %.2e m\n", worst);
  EXPECT_LT(worst, 0.01);
}

// Twenty dominoes (0.1 × 1 × 0.5 m) 0.5 m apart in a row on a floor; the first is tipped.
TEST(WorldStep, DominoesFallInOrderAndTheLastEndsLyingDown) {
  const BodyModel domino =
      box_model(Vec3(0.1, 1.0, 0.5), 2.0, {.restitution = 0.0, .friction = 0.6}, true);
  constexpr int kCount = 20;
  std::vector<BodyModel> models(kCount, domino);
  std::vector<BodyState> start;
  for (int k = 0; k < kCount; ++k) {
    start.push_back(at_rest(domino, Vec3(0.5 * k, 0.5, 0.0), Vec3::Zero(), Quat::Identity(),
                            k == 0 ? Vec3(0.0, 0.0, -1.6) : Vec3::Zero()));
  }
  sim::Simulation world(models, start, Integrator::rk4, kStep,
                        {Plane{.material = {.restitution = 0.0, .friction = 0.6}}});
  std::vector<double> tipped(kCount, -1.0);  // when each passed 45° (s)
  while (world.time() < 8.0) {
    world.step();
    for (int k = 0; k < kCount; ++k) {
      const Vec3 up = world.current()[k].orientation() * Vec3::UnitY();
      if (tipped[k] < 0.0 && up.y() < std::cos(0.25 * 3.141592653589793)) tipped[k] = world.time();
    }
  }
  for (int k = 0; k < kCount; ++k) {
    ASSERT_GE(tipped[k], 0.0) << "domino " << k << " never fell";
    if (k > 0) {
      EXPECT_GT(tipped[k], tipped[k - 1]) << "domino " << k << " fell before " << k - 1;
    }
  }
  std::printf("[ measured ] dominoes past 45° from %.3f s to %.3f s\n", tipped.front(),
              tipped.back());
  const BodyState& last = world.current().back();
  EXPECT_LT(std::abs((last.orientation() * Vec3::UnitY()).y()), 0.05);  // lying down
  EXPECT_NEAR(last.position().y(), 0.05, 0.01);  // on its broad face, on the floor
}

class FastCube : public testing::TestWithParam<double> {};

// A 0.2 m cube at speed v (m/s) toward a free 5 cm plate of 2 × 2 m, no gravity: at 100 m/s it
// moves 1.7 m per step, 34 plate thicknesses, and must still hit the plate, not pass it.
TEST_P(FastCube, DoesNotPassThroughAThinBox) {
  const double speed = GetParam();
  const BodyModel cube =
      box_model(Vec3::Constant(0.2), 1.0, {.restitution = 0.5, .friction = 0.5}, false);
  const BodyModel plate =
      box_model(Vec3(0.05, 2.0, 2.0), 5.0, {.restitution = 0.5, .friction = 0.5}, false);
  sim::Simulation world({cube, plate},
                        {at_rest(cube, Vec3(-3.0, 0.1, 0.05), Vec3(speed, 0.0, 0.0)),
                         at_rest(plate, Vec3(0.0, 0.0, 0.0))},
                        Integrator::rk4, kStep);
  const Vec3 momentum = total_momentum(world.current());
  double deepest = 0.0;  // the largest overlap of the two boxes along their separating axis (m)
  while (world.time() < 2.0) {
    world.step();
    const BodyState& c = world.current()[0];
    const BodyState& p = world.current()[1];
    const BoxAxis axis = box_box_axis({c.position(), c.rotation(), cube.shape.half_size},
                                      {p.position(), p.rotation(), plate.shape.half_size});
    deepest = std::max(deepest, -axis.separation);
  }
  const BodyState& c = world.current()[0];
  const BodyState& p = world.current()[1];
  std::printf("[ measured ] %.0f m/s: deepest overlap %.2e m; cube %.3f, plate %.3f m/s\n", speed,
              deepest, c.velocity().x(), p.velocity().x());
  EXPECT_LT(deepest, 1e-3);                       // at most a millimetre inside, at any step
  EXPECT_LT(c.position().x(), p.position().x());  // still on the side it came from
  EXPECT_LT((total_momentum(world.current()) - momentum).norm(), 1e-12 * momentum.norm());
  // Restitution 0.5 between a 1 kg and a 5 kg body: the cube leaves at (1 - 5 e)/6 v, the plate at
  // (1 + e)/6 v, if the hit is central; within 5% (the points are 5 cm off the plate's centre).
  EXPECT_NEAR(p.velocity().x(), 1.5 / 6.0 * speed, 0.05 * 1.5 / 6.0 * speed);
}

INSTANTIATE_TEST_SUITE_P(Speeds, FastCube, testing::Values(10.0, 30.0, 100.0));

// Boxes thrown together in empty space: every collision moves momentum between them and none
// leaves the world; the same world run twice gives the same bits.
TEST(WorldStep, CollisionsConserveMomentumAndRepeatBitForBit) {
  const auto run = [] {
    std::vector<BodyModel> models;
    std::vector<BodyState> start;
    for (int k = 0; k < 12; ++k) {
      const Vec3 size(0.3 + 0.05 * (k % 3), 0.4 + 0.05 * (k % 4), 0.5 - 0.03 * (k % 5));
      models.push_back(
          box_model(size, 1.0 + 0.5 * k, {.restitution = 0.3, .friction = 0.4}, false));
      const double angle = 2.0 * 3.141592653589793 * k / 12.0;
      const Vec3 where(2.0 * std::cos(angle), 0.3 * (k % 2), 2.0 * std::sin(angle));
      start.push_back(at_rest(models.back(), where, -1.5 * where,
                              Quat(Eigen::AngleAxisd(0.3 * k, Vec3(1, 2, 3).normalized())),
                              Vec3(0.5, -0.2 * k, 0.1)));
    }
    sim::Simulation world(models, start, Integrator::rk4, kStep);
    const Vec3 momentum = total_momentum(world.current());
    double worst = 0.0;
    while (world.time() < 3.0) {
      world.step();
      worst = std::max(worst, (total_momentum(world.current()) - momentum).norm());
    }
    return std::make_pair(worst / momentum.norm(), world.current());
  };
  const auto [error, first] = run();
  const auto [again, second] = run();
  std::printf("[ measured ] largest momentum change, relative: %.1e\n", error);
  EXPECT_LT(error, 1e-12);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].position(), second[i].position());
    EXPECT_EQ(first[i].orientation().coeffs(), second[i].orientation().coeffs());
    EXPECT_EQ(first[i].momentum(), second[i].momentum());
  }
}

// A world stepped by hand, so that its sleeping can be read.
struct World {
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  std::vector<Plane> planes = {Plane{.material = {.restitution = 0.0, .friction = 0.5}}};
  ContactSettings settings;
  WorldContacts contacts;
  double time = 0.0;  // s
  void step() {
    std::vector<BodyState> next(states.size());
    step_world(Integrator::rk4, models, states, time, kStep, planes, settings, contacts, next);
    states.swap(next);
    time += kStep;
  }
  bool asleep(std::size_t body) const {
    return body < contacts.memory.asleep.size() && contacts.memory.asleep[body] != 0;
  }
};

// A cube set down on the floor falls asleep once still for kTimeToSleep, at rest: from then its
// state does not change by a bit. A second cube dropped on it wakes it, and the two end stacked
// where the same world ends without sleeping, to well within what a frame shows.
TEST(WorldStep, AStillBoxSleepsAndABoxLandingOnItWakesIt) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  const auto run = [&](bool sleep) {
    World world;
    world.models = {cube, cube};
    world.states = {at_rest(cube, Vec3(0.0, 0.5, 0.0)), at_rest(cube, Vec3(0.1, 3.0, 0.0))};
    world.settings.sleep = sleep;
    // The lower cube first settles in a world of its own, until it sleeps.
    World alone;
    alone.models = {cube};
    alone.states = {world.states[0]};
    alone.settings = world.settings;
    double slept_at = -1.0;  // s
    while (alone.time < 2.0) {
      alone.step();
      if (slept_at < 0.0 && alone.asleep(0)) slept_at = alone.time;
    }
    if (sleep) {
      std::printf("[ measured ] the resting cube fell asleep at %.3f s\n", slept_at);
      EXPECT_GT(slept_at, kTimeToSleep);
      EXPECT_LT(slept_at, kTimeToSleep + 0.1);
      EXPECT_EQ(alone.states[0].momentum(), Vec3::Zero());
      EXPECT_EQ(alone.states[0].angular_momentum(), Vec3::Zero());
      const BodyState before = alone.states[0];
      for (int n = 0; n < 60; ++n) alone.step();
      EXPECT_EQ(alone.states[0].position(), before.position());
      EXPECT_EQ(alone.states[0].orientation().coeffs(), before.orientation().coeffs());
    } else {
      EXPECT_LT(slept_at, 0.0);
    }
    // Now the same cube, as it stands, with the other one above it falling.
    world.states[0] = alone.states[0];
    world.contacts.memory.asleep = alone.contacts.memory.asleep;
    world.contacts.memory.asleep.resize(2, 0);
    world.contacts.memory.still_for = alone.contacts.memory.still_for;
    world.contacts.memory.still_for.resize(2, 0.0);
    world.contacts.memory.planes = alone.contacts.memory.planes;
    double woke_at = -1.0;                             // s
    const double landing = std::sqrt(2.0 * 1.5 / kG);  // s: the 1.5 m fall to the lower's top
    while (world.time < 4.0) {
      world.step();
      if (woke_at < 0.0 && sleep && !world.asleep(0)) woke_at = world.time;
    }
    if (sleep) {
      std::printf("[ measured ] it woke %.3f s into the other's fall of %.3f s\n", woke_at,
                  landing);
      EXPECT_GT(woke_at, landing - 3.0 * kStep);
      EXPECT_LT(woke_at, landing + kStep);
    }
    return world.states;
  };
  const std::vector<BodyState> awake = run(false), sleeping = run(true);
  for (std::size_t i = 0; i < 2; ++i) {
    const double apart = (awake[i].position() - sleeping[i].position()).norm();
    std::printf("[ measured ] cube %zu ends %.2e m from where it ends awake\n", i, apart);
    EXPECT_LT(apart, 1e-3);
  }
  EXPECT_NEAR(sleeping[1].position().y(), 1.5, 1e-3);  // stacked
}

// A world in which no two bodies can touch steps each body alone, without islands: a cube
// thrown spinning onto the floor (impacts, sliding, rest, sleep) steps to the same bits, and
// falls asleep at the same step, as the same cube beside another far away, whose world finds
// pairs and islands.
TEST(WorldStep, ABodyAloneStepsAsItsIslandOfOneWould) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.3, .friction = 0.5}, true);
  const BodyState thrown =
      at_rest(cube, Vec3(0.0, 2.0, 0.0), Vec3(3.0, 0.0, 1.0),
              Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 0.3, 0.2).normalized())), Vec3(2.0, 1.0, -3.0));
  World alone, beside;
  alone.models = {cube};
  alone.states = {thrown};
  beside.models = {cube, cube};
  beside.states = {thrown, at_rest(cube, Vec3(100.0, 0.5, 0.0))};
  bool slept = false;
  while (alone.time < 4.0) {
    alone.step();
    beside.step();
    ASSERT_EQ(alone.states[0].position(), beside.states[0].position()) << alone.time;
    ASSERT_EQ(alone.states[0].momentum(), beside.states[0].momentum()) << alone.time;
    ASSERT_EQ(alone.states[0].orientation().coeffs(), beside.states[0].orientation().coeffs());
    ASSERT_EQ(alone.states[0].angular_momentum(), beside.states[0].angular_momentum());
    ASSERT_EQ(alone.asleep(0), beside.asleep(0)) << alone.time;
    slept = slept || alone.asleep(0);
  }
  EXPECT_TRUE(slept);  // the run reached the sleeping part
}

// A body with a law that switches on in time never sleeps, for nothing else would wake it when
// the push comes: its run is the same to the bit with sleeping on or off.
TEST(WorldStep, ATimedPushKeepsItsBodyAwake) {
  BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  cube.forces.push_back(ForceAtPoint{.force = Vec3(20.0, 0.0, 0.0), .start = 2.0, .end = 2.5});
  const auto run = [&](bool sleep) {
    World world;
    world.models = {cube};
    world.states = {at_rest(cube, Vec3(0.0, 0.5, 0.0))};
    world.settings.sleep = sleep;
    while (world.time < 4.0) {
      world.step();
      EXPECT_FALSE(world.asleep(0));
    }
    return world.states[0];
  };
  const BodyState awake = run(false), sleeping = run(true);
  EXPECT_GT(sleeping.position().x(), 0.1);  // the push moved it
  EXPECT_EQ(sleeping.position(), awake.position());
  EXPECT_EQ(sleeping.orientation().coeffs(), awake.orientation().coeffs());
}

}  // namespace
}  // namespace tumble::physics
