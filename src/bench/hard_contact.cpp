#include "bench/hard_contact.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <utility>

#include "physics/box_box.hpp"
#include "physics/contact.hpp"
#include "physics/forces.hpp"
#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"
#include "sim/simulation.hpp"

namespace tumble::bench {
namespace {

using physics::BodyState;
using physics::Material;
using physics::Plane;
using physics::Quat;
using physics::Vec3;

constexpr double kDt = 1.0 / 60.0;  // s
constexpr double kG = 9.81;         // m/s²
constexpr double kInfinity = std::numeric_limits<double>::infinity();

const Material kElastic{.restitution = 1.0, .friction = 0.0};

// A box of the world: what the case sets, the rest at its default.
struct Box {
  double mass = 1.0;                     // kg
  Vec3 size = Vec3::Ones();              // edge lengths along the body axes (m)
  Vec3 position = Vec3::Zero();          // centre, world frame (m)
  Vec3 velocity = Vec3::Zero();          // world frame (m/s)
  Quat orientation = Quat::Identity();   // body to world
  Vec3 angular_velocity = Vec3::Zero();  // world frame (rad/s)
  Material material = {};
  Vec3 gravity = Vec3(0.0, -kG, 0.0);  // m/s²; zero for none
  Vec3 push = Vec3::Zero();            // a constant force through the centre (N, world frame)
};

struct World {
  std::vector<Box> boxes;
  std::vector<Plane> planes;
  double dt = kDt;                                                                  // s
  double restitution_threshold = physics::ContactSettings{}.restitution_threshold;  // m/s
};

Plane floor_plane(const Material& material = {}) {
  return Plane{.material = material};
}

// An empty world with a floor of `material` at y = 0, stepped at `dt` (s).
World on_floor(const Material& material = {}, double dt = kDt) {
  World world;
  world.planes.push_back(floor_plane(material));
  world.dt = dt;
  return world;
}

// The world as the solver sees it: impulse contact, rk4, sleeping off.
sim::Simulation simulation_of(const World& world) {
  std::vector<physics::BodyModel> models;
  std::vector<BodyState> states;
  for (const Box& box : world.boxes) {
    physics::BodyModel model{.constants = physics::box_constants(box.mass, box.size),
                             .forces = {},
                             .shape = physics::box_shape(box.size / 2.0),
                             .material = box.material};
    if (!box.gravity.isZero()) model.forces.push_back(physics::Gravity{box.gravity});
    if (!box.push.isZero()) model.forces.push_back(physics::ConstantForce{box.push});
    states.push_back(physics::make_state(model.constants, box.position, box.velocity,
                                         box.orientation, box.angular_velocity));
    models.push_back(std::move(model));
  }
  physics::ContactSettings contact;
  contact.sleep = false;
  contact.restitution_threshold = world.restitution_threshold;
  return sim::Simulation(std::move(models), std::move(states), physics::Integrator::rk4, world.dt,
                         world.planes, contact);
}

// Steps the world for `seconds`, calling `observe` with the time (s) and the states after each
// step. A blow-up ends the run early; the caller's figures then judge what it saw.
void run(const World& world, double seconds,
         const std::function<void(double, const std::vector<BodyState>&)>& observe) {
  sim::Simulation simulation = simulation_of(world);
  const auto steps = static_cast<std::int64_t>(std::llround(seconds / world.dt));
  for (std::int64_t n = 0; n < steps && !simulation.blow_up(); ++n) {
    simulation.step();
    observe(simulation.time(), simulation.current());
  }
}

// Kinetic plus potential energy of every box (J), the potential from each box's own gravity.
double energy(const World& world, const std::vector<BodyState>& states) {
  double total = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    total += physics::kinetic_energy(states[i]) -
             world.boxes[i].mass * world.boxes[i].gravity.dot(states[i].position());
  }
  return total;
}

double lowest_below(const World& world, const std::vector<BodyState>& states, std::size_t i) {
  return -physics::closest_corner_separation(states[i], world.boxes[i].size / 2.0,
                                             world.planes.front());
}

physics::BoxPose pose_of(const World& world, const BodyState& state, std::size_t i) {
  return {state.position(), state.rotation(), world.boxes[i].size / 2.0};
}

// A column of unit cubes of these masses (kg) on a floor, the first at the bottom, under `g`.
World column(const std::vector<double>& masses, double g = kG) {
  World world = on_floor();
  for (std::size_t i = 0; i < masses.size(); ++i) {
    world.boxes.push_back({.mass = masses[i],
                           .position = Vec3(0.0, 0.5 + static_cast<double>(i), 0.0),
                           .gravity = Vec3(0.0, -g, 0.0)});
  }
  return world;
}

// The largest distance any box moves from where it starts (m) and the deepest any box goes
// into the floor (m), over `seconds`.
std::vector<HardContactFigure> stays(const World& world, double seconds) {
  double moved = 0.0, deepest = 0.0;
  run(world, seconds, [&](double, const std::vector<BodyState>& states) {
    for (std::size_t i = 0; i < states.size(); ++i) {
      moved = std::max(moved, (states[i].position() - world.boxes[i].position).norm());
      deepest = std::max(deepest, lowest_below(world, states, i));
    }
  });
  return {{"largest move of a box (m)", moved, 1e-3},
          {"deepest into the floor (m)", deepest, 1e-3}};
}

HardContactFigure top_drift(const World& world, double seconds) {
  double drift = 0.0;
  run(world, seconds, [&](double, const std::vector<BodyState>& states) {
    drift = std::max(drift, (states.back().position() - world.boxes.back().position).norm());
  });
  return {"top drift (m)", drift, 1e-2};
}

HardContactCase load(double force /* N */) {
  World world = column({1.0});
  world.boxes[0].push = Vec3(0.0, -force, 0.0);
  double off = 0.0;
  run(world, 10.0, [&](double, const std::vector<BodyState>& states) {
    off = std::max(off, std::abs(states[0].position().y() - 0.5));
  });
  char name[32];
  std::snprintf(name, sizeof name, "load_%.0e", force);
  return {name,
          "a 1 kg cube on the floor pushed down by a constant force, 10 s",
          {{"largest offset of y from 0.5 m at a step (m)", off, 1e-3}}};
}

// Kinetic energy after one elastic impact of two spinning boxes against before (relative), with
// no gravity and no friction. An impact that never happened gives infinity, so the case cannot
// hold by missing.
HardContactFigure elastic_impact(const World& world) {
  const std::vector<BodyState> start = simulation_of(world).current();
  const double before = energy(world, start);
  std::vector<BodyState> end = start;
  run(world, 1.0, [&](double, const std::vector<BodyState>& states) { end = states; });
  const bool struck = (end[0].velocity() - start[0].velocity()).norm() > 1e-3;
  return {"kinetic energy change (relative)",
          struck ? std::abs(energy(world, end) - before) / before : kInfinity, 1e-9};
}

HardContactCase edge_on_edge() {
  World world;
  world.boxes.push_back(
      {.orientation = Quat(Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ())),
       .angular_velocity = Vec3(0.0, 0.0, 0.3),
       .material = kElastic,
       .gravity = Vec3::Zero()});
  world.boxes.push_back(
      {.position = Vec3(std::sqrt(2.0) + 0.3, 0.05, 0.05),
       .velocity = Vec3(-2.0, 0.0, 0.0),
       .orientation = Quat(Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitY())),
       .angular_velocity = Vec3(0.0, 0.4, 0.0),
       .material = kElastic,
       .gravity = Vec3::Zero()});
  return {"edge_on_edge",
          "an edge of a spinning cube strikes an edge of another, e = 1, mu = 0",
          {elastic_impact(world)}};
}

HardContactCase corner_on_face() {
  World world;
  world.boxes.push_back(
      {.angular_velocity = Vec3(0.0, 0.3, 0.0), .material = kElastic, .gravity = Vec3::Zero()});
  world.boxes.push_back(
      {.position = Vec3(0.5 + std::sqrt(3.0) / 2.0 + 0.3, 0.1, 0.05),
       .velocity = Vec3(-2.0, 0.0, 0.0),
       .orientation = Quat::FromTwoVectors(Vec3(1.0, 1.0, 1.0).normalized(), -Vec3::UnitX()),
       .angular_velocity = Vec3(0.4, 0.2, 0.1),
       .material = kElastic,
       .gravity = Vec3::Zero()});
  return {"corner_on_face",
          "a corner of a spinning cube strikes a face of another, e = 1, mu = 0",
          {elastic_impact(world)}};
}

HardContactCase closed_room() {
  World world;
  // Nothing rests without gravity: every impact bounces, as tumble check advises for such a
  // scene (the default threshold, for resting contact under gravity, would take the bounce of
  // every impact slower than 0.5 m/s).
  world.restitution_threshold = 0.0;
  const double half = 2.0;  // m: a 4 m room
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-1.0, 1.0}) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = -side;  // pointing into the room
      const double offset = axis == 1 ? (side < 0 ? 0.0 : -2 * half) : -half;
      world.planes.push_back({.normal = normal, .offset = offset, .material = kElastic});
    }
  }
  world.boxes.push_back({.position = Vec3(-0.8, 1.5, 0.3),
                         .velocity = Vec3(3.0, 1.0, -2.0),
                         .angular_velocity = Vec3(1.0, 2.0, 0.5),
                         .material = kElastic,
                         .gravity = Vec3::Zero()});
  world.boxes.push_back({.position = Vec3(0.9, 2.5, -0.4),
                         .velocity = Vec3(-2.0, 0.5, 1.5),
                         .angular_velocity = Vec3(-1.0, 0.3, 2.0),
                         .material = kElastic,
                         .gravity = Vec3::Zero()});
  const double start = energy(world, simulation_of(world).current());
  double highest = start, last = start;
  run(world, 60.0, [&](double, const std::vector<BodyState>& states) {
    last = energy(world, states);
    highest = std::max(highest, last);
  });
  return {"closed_room",
          "two cubes bouncing in a closed room of 6 planes, e = 1, mu = 0, no gravity, 60 s",
          {{"largest rise above the start (relative)", (highest - start) / start, 1e-9},
           {"energy lost by 60 s (relative)", (start - last) / start, 1e-2}}};
}

HardContactCase cradle() {
  constexpr double kSpeed = 2.0;  // m/s, the striker's
  World world;
  world.boxes.push_back({.position = Vec3(-1.5, 0.0, 0.0),
                         .velocity = Vec3(kSpeed, 0.0, 0.0),
                         .material = kElastic,
                         .gravity = Vec3::Zero()});
  for (int i = 0; i < 3; ++i) {
    world.boxes.push_back(
        {.position = Vec3(i, 0.0, 0.0), .material = kElastic, .gravity = Vec3::Zero()});
  }
  std::vector<BodyState> end;
  run(world, 3.0, [&](double, const std::vector<BodyState>& states) { end = states; });
  double others = 0.0;
  for (std::size_t i = 0; i + 1 < end.size(); ++i) {
    others = std::max(others, end[i].velocity().norm() / kSpeed);
  }
  return {"cradle",
          "a cube strikes three touching cubes end-on, e = 1, mu = 0, no gravity",
          {{"1 - last cube's speed / striker's", 1.0 - end.back().velocity().x() / kSpeed, 0.05},
           {"fastest other cube / striker", others, 0.05}}};
}

HardContactCase head_on() {
  World world;
  world.boxes.push_back({.position = Vec3(-1.0, 0.0, 0.0),
                         .velocity = Vec3(2.0, 0.0, 0.0),
                         .material = kElastic,
                         .gravity = Vec3::Zero()});
  world.boxes.push_back({.position = Vec3(1.0, 0.0, 0.0),
                         .velocity = Vec3(-1.25, 0.0, 0.0),
                         .material = kElastic,
                         .gravity = Vec3::Zero()});
  std::vector<BodyState> end;
  run(world, 1.5, [&](double, const std::vector<BodyState>& states) { end = states; });
  const double exchange = std::max((end[0].velocity() - Vec3(-1.25, 0.0, 0.0)).norm() / 1.25,
                                   (end[1].velocity() - Vec3(2.0, 0.0, 0.0)).norm() / 2.0);
  const double spin = std::max(end[0].angular_velocity().norm(), end[1].angular_velocity().norm());
  return {"head_on",
          "equal cubes head-on at +2 and -1.25 m/s, e = 1, mu = 0, no gravity",
          {{"velocity exchange error (relative)", exchange, 1e-9},
           {"spin afterwards (rad/s)", spin, 1e-9}}};
}

// A box of `size` standing on the floor on an edge, turned about z 1 degree past balance on it,
// friction 1: the energy must never rise above its start.
HardContactCase tipping(const std::string& name, const Vec3& size, double dt) {
  const double balance = std::atan2(size.x(), size.y());  // rad: the diagonal upright
  const Quat turn(Eigen::AngleAxisd(balance + std::numbers::pi / 180.0, Vec3::UnitZ()));
  double lowest = kInfinity;  // of the corners, relative to the centre (m)
  for (int feature = 0; feature < 8; ++feature) {
    lowest = std::min(lowest, (turn * physics::corner(size / 2.0, feature)).y());
  }
  const Material grip{.restitution = 0.0, .friction = 1.0};
  World world = on_floor(grip, dt);
  world.boxes.push_back(
      {.size = size, .position = Vec3(0.0, -lowest, 0.0), .orientation = turn, .material = grip});
  const double start = energy(world, simulation_of(world).current());
  double highest = start;
  run(world, 5.0, [&](double, const std::vector<BodyState>& states) {
    highest = std::max(highest, energy(world, states));
  });
  char summary[96];
  std::snprintf(summary, sizeof summary,
                "%s tipped 1 degree past an edge, friction 1, dt = 1/%.0f s", name.c_str(),
                1.0 / dt);
  return {name + (dt > 1.5 * kDt ? "_dt30" : ""),
          summary,
          {{"largest energy rise above the start (relative)", (highest - start) / start, 1e-9}}};
}

HardContactCase twist() {
  // Uniform pressure on a square of side s: the mean lever arm is (s/6)(sqrt 2 + ln(1 + sqrt 2)),
  // so a cube spinning at w0 stops at I w0 / (mu m g r), I = m s^2 / 6.
  constexpr double kSpin = 50.0;  // rad/s
  constexpr double kFriction = 0.5;
  const double lever = (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 6.0;  // m
  const double closed_form = (kSpin / 6.0) / (kFriction * kG * lever);           // s
  World world = on_floor({.restitution = 0.0, .friction = kFriction});
  world.boxes.push_back({.position = Vec3(0.0, 0.5, 0.0),
                         .angular_velocity = Vec3(0.0, kSpin, 0.0),
                         .material = {.friction = kFriction}});
  double stopped = kInfinity, moved = 0.0;
  run(world, 1.5 * closed_form, [&](double t, const std::vector<BodyState>& states) {
    if (stopped == kInfinity && std::abs(states[0].angular_velocity().y()) < 1e-2) stopped = t;
    moved = std::max(moved, (states[0].position() - world.boxes[0].position).norm());
  });
  return {"twist",
          "a unit cube spinning at 50 rad/s flat on the floor, mu = 0.5",
          {{"stop time against the closed form 4.44 s (relative)",
            std::abs(stopped - closed_form) / closed_form, 0.02},
           {"largest move of the centre (m)", moved, 1e-3}}};
}

HardContactCase symmetry() {
  World world = on_floor();
  world.boxes.push_back({.size = Vec3(1.0, 0.05, 1.0), .position = Vec3(0.0, 0.025, 0.0)});
  world.boxes.push_back({.size = Vec3::Constant(0.05),
                         .position = Vec3(0.0, 0.5, 0.0),
                         .velocity = Vec3(0.0, -150.0, 0.0)});
  double sideways = 0.0, spin = 0.0;
  run(world, 1.0, [&](double, const std::vector<BodyState>& states) {
    for (const BodyState& state : states) {
      sideways = std::max(sideways, std::hypot(state.velocity().x(), state.velocity().z()));
      spin = std::max(spin, state.angular_velocity().norm());
    }
  });
  return {"symmetry",
          "a 5 cm cube at 150 m/s face-on and centred onto a plate on the floor",
          {{"sideways speed (m/s)", sideways, 1e-6}, {"spin (rad/s)", spin, 1e-6}}};
}

// At rest by `by` s (and until `by` + 1 s): the fastest box and the fastest spin from then on,
// and the deepest two boxes go into each other at any step.
std::vector<HardContactFigure> comes_to_rest(const World& world, double by) {
  double speed = 0.0, spin = 0.0, overlap = 0.0;
  run(world, by + 1.0, [&](double t, const std::vector<BodyState>& states) {
    for (std::size_t i = 0; i < states.size(); ++i) {
      if (t >= by) {
        speed = std::max(speed, states[i].velocity().norm());
        spin = std::max(spin, states[i].angular_velocity().norm());
      }
      for (std::size_t j = i + 1; j < states.size(); ++j) {
        const double separation =
            physics::box_box_axis(pose_of(world, states[i], i), pose_of(world, states[j], j))
                .separation;
        overlap = std::max(overlap, -separation);
      }
    }
  });
  return {{"fastest box after 5 s (m/s)", speed, 1e-3},
          {"fastest spin after 5 s (rad/s)", spin, 1e-3},
          {"deepest overlap of two boxes (m)", overlap, 1e-3}};
}

World crossed_rods(double upper_height /* m */) {
  World world = on_floor();
  world.boxes.push_back({.size = Vec3(3.0, 0.05, 0.05), .position = Vec3(0.0, 0.025, 0.0)});
  world.boxes.push_back({.size = Vec3(0.05, 0.05, 3.0), .position = Vec3(0.3, upper_height, 0.2)});
  return world;
}

using CaseMaker = std::function<HardContactCase()>;

const std::vector<std::pair<std::string, CaseMaker>>& makers() {
  static const std::vector<std::pair<std::string, CaseMaker>> all = {
      {"ratio_100",
       [] {
         return HardContactCase{"ratio_100",
                                "a 100 kg cube resting on a 1 kg cube on the floor, 30 s",
                                stays(column({1.0, 100.0}), 30.0)};
       }},
      {"ratio_1000",
       [] {
         return HardContactCase{"ratio_1000",
                                "a 1000 kg cube resting on a 1 kg cube on the floor, 30 s",
                                stays(column({1.0, 1000.0}), 30.0)};
       }},
      {"plate_1000",
       [] {
         World world = on_floor();
         world.boxes.push_back({.size = Vec3(2.0, 0.02, 2.0), .position = Vec3(0.0, 0.01, 0.0)});
         world.boxes.push_back({.mass = 1000.0, .position = Vec3(0.0, 0.52, 0.0)});
         return HardContactCase{"plate_1000", "a 1000 kg cube on a 1 kg 2 x 0.02 x 2 m plate, 30 s",
                                stays(world, 30.0)};
       }},
      {"chain_1_100",
       [] {
         std::vector<double> masses;
         for (int i = 0; i < 10; ++i) masses.push_back(i % 2 ? 100.0 : 1.0);
         return HardContactCase{"chain_1_100",
                                "a column of 10 cubes of 1 and 100 kg in turn, 30 s",
                                {top_drift(column(masses), 30.0)}};
       }},
      {"load_1e+03", [] { return load(1e3); }},
      {"load_1e+04", [] { return load(1e4); }},
      {"load_1e+05", [] { return load(1e5); }},
      {"load_1e+06", [] { return load(1e6); }},
      {"stack_pushed",
       [] {
         World world = column({1.0, 1.0});
         world.boxes[1].push = Vec3(0.0, -2e5, 0.0);
         double fastest = 0.0;
         run(world, 10.0, [&](double, const std::vector<BodyState>& states) {
           for (const BodyState& state : states) {
             fastest = std::max(fastest, state.velocity().norm());
           }
         });
         return HardContactCase{"stack_pushed",
                                "a 2-stack with its top pushed down by 2e5 N, 10 s",
                                {{"fastest box at a step (m/s)", fastest, 0.01}}};
       }},
      {"edge_on_edge", edge_on_edge},
      {"corner_on_face", corner_on_face},
      {"closed_room", closed_room},
      {"cradle", cradle},
      {"head_on", head_on},
      {"tip_rod", [] { return tipping("tip_rod", Vec3(0.05, 3.0, 0.05), kDt); }},
      {"tip_rod_dt30", [] { return tipping("tip_rod", Vec3(0.05, 3.0, 0.05), 2.0 * kDt); }},
      {"tip_cube", [] { return tipping("tip_cube", Vec3::Ones(), kDt); }},
      {"tip_cube_dt30", [] { return tipping("tip_cube", Vec3::Ones(), 2.0 * kDt); }},
      {"twist", twist},
      {"symmetry", symmetry},
      {"rods_crossed",
       [] {
         return HardContactCase{"rods_crossed", "two 3 m rods lying crossed on the floor",
                                comes_to_rest(crossed_rods(0.075), 5.0)};
       }},
      {"rod_dropped",
       [] {
         return HardContactCase{"rod_dropped", "a 3 m rod dropped from 0.5 m across another",
                                comes_to_rest(crossed_rods(0.5), 5.0)};
       }},
      {"stack_dt10",
       [] {
         World world = column({1.0, 1.0, 1.0});
         world.dt = 0.1;
         std::vector<HardContactFigure> figures = comes_to_rest(world, 5.0);
         return HardContactCase{"stack_dt10", "a 3-cube stack at dt = 1/10 s", figures};
       }},
      {"tower_g100",
       [] {
         return HardContactCase{"tower_g100",
                                "a 5-cube tower under g = 100 m/s², 30 s",
                                {top_drift(column({1.0, 1.0, 1.0, 1.0, 1.0}, 100.0), 30.0)}};
       }},
  };
  return all;
}

}  // namespace

std::vector<std::string> hard_contact_case_names() {
  std::vector<std::string> names;
  for (const auto& [name, make] : makers()) names.push_back(name);
  return names;
}

HardContactCase run_hard_contact_case(const std::string& name) {
  for (const auto& [known, make] : makers()) {
    if (known == name) return make();
  }
  return {name, "unknown case", {}};
}

}  // namespace tumble::bench
