#include "bench/contact_cases.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include "physics/mass_properties.hpp"
#include "sim/penalty_modes.hpp"

namespace tumble::bench {
namespace {

using physics::BodyState;
using physics::Quat;
using physics::Vec3;

constexpr double kG = 9.81;  // m/s²

// A 1 kg unit cube under gravity, of the given surface, over a floor of the same surface at y = 0.
struct CubeOnFloor {
  physics::BodyModel model;
  std::vector<physics::Plane> planes;
  physics::ContactSettings penalty;
};

CubeOnFloor cube_on_floor(const physics::Material& material) {
  CubeOnFloor out{.model = {.constants = physics::cube_constants(1.0, 1.0),
                            .forces = {physics::Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                            .shape = physics::box_shape(Vec3::Constant(0.5)),
                            .material = material},
                  .planes = {physics::Plane{.material = material}},
                  .penalty = {.method = physics::ContactMethod::penalty}};
  // The default stiffness, damped for the surface's restitution: the default damping (500 N s/m,
  // ζ = c / sqrt(k m) = 1.6 for a landing on four corners) would leave no bounce, and its rocking
  // decays at 4c a²/I = 3000 /s, beyond every explicit method at every benchmarked step.
  out.penalty.damping = sim::penalty_damping_for_restitution(
      material.restitution, out.penalty.stiffness, out.model.constants.mass);
  return out;
}

// The height of the lowest corner above the floor (m): negative inside it.
double lowest_corner(const BodyState& state, const physics::BodyModel& model,
                     const physics::Plane& floor) {
  return physics::closest_corner_separation(state, model.shape.half_size, floor);
}

// The bottom face's height at the first apex after the first bounce (m): the vertex of the
// parabola through the highest step and its two neighbours (all in free flight, where each
// method's own flight is a parabola in the step number), so that sampling adds no error. 0 when
// the cube never rises again.
double first_apex(const std::vector<BodyState>& states, const physics::BodyModel& model,
                  const physics::Plane& floor) {
  std::size_t n = 1;
  while (n < states.size() && states[n].velocity().y() <= 0.0) ++n;  // falling, then pressed
  if (n == states.size()) return 0.0;
  for (; n + 1 < states.size(); ++n) {
    const double a = lowest_corner(states[n - 1], model, floor);
    const double b = lowest_corner(states[n], model, floor);
    const double c = lowest_corner(states[n + 1], model, floor);
    if (c >= b) continue;
    const double curvature = 2.0 * b - a - c;  // > 0 at a maximum
    return curvature > 0.0 ? b + (a - c) * (a - c) / (8.0 * curvature) : b;
  }
  // Still rising at the end (a bounce that gained energy): the apex of its ballistic flight.
  const BodyState& last = states.back();
  const double rise = std::max(0.0, last.velocity().y());  // m/s
  return lowest_corner(last, model, floor) + rise * rise / (2.0 * kG);
}

// Dropped flat from 1 m with restitution 0.5 and no friction: the first bounce rises to
// e² h₀ = 0.25 m.
ContactCase bounce() {
  constexpr double kDrop = 1.0, kRestitution = 0.5;
  CubeOnFloor setup = cube_on_floor({.restitution = kRestitution, .friction = 0.0});
  const physics::Plane floor = setup.planes.front();
  const physics::BodyModel model = setup.model;
  return {
      .name = "bounce",
      .summary =
          "A 1 kg unit cube dropped flat from 1 m onto a frictionless floor, restitution "
          "0.5, 1 s",
      .measure_note =
          "the bottom face's height at the first apex after the first bounce (the "
          "vertex of the parabola through the three highest steps) against "
          "e² h₀ = 0.25 m",
      .model = setup.model,
      .initial = physics::make_state(setup.model.constants, Vec3(0.0, 0.5 + kDrop, 0.0),
                                     Vec3::Zero(), Quat::Identity(), Vec3::Zero()),
      .planes = setup.planes,
      .duration = 1.0,
      .penalty = setup.penalty,
      .measures = {{.name = "apex_error_m", .label = "apex error (m)"}},
      .judge =
          [=](const std::vector<BodyState>& states, double) {
            const double exact = kRestitution * kRestitution * kDrop;
            return std::vector<double>{std::abs(first_apex(states, model, floor) - exact)};
          },
  };
}

// Launched along the floor at 5 m/s with friction 0.5: Coulomb friction stops it after
// v₀²/(2μg) = 2.548 m, at t = v₀/(μg) = 1.02 s.
ContactCase slide() {
  constexpr double kSpeed = 5.0, kFriction = 0.5;
  // Restitution plays no part (the cube starts on the floor); it sets the penalty damping.
  CubeOnFloor setup = cube_on_floor({.restitution = 0.5, .friction = kFriction});
  const Vec3 start(0.0, 0.5, 0.0);
  return {
      .name = "slide",
      .summary = "A 1 kg unit cube launched along the floor at 5 m/s, friction 0.5, 1.5 s",
      .measure_note =
          "the distance slid by the end (the cube stops at 1.02 s) against "
          "v₀²/(2μg) = 2.548 m",
      .model = setup.model,
      .initial = physics::make_state(setup.model.constants, start, Vec3(kSpeed, 0.0, 0.0),
                                     Quat::Identity(), Vec3::Zero()),
      .planes = setup.planes,
      .duration = 1.5,
      .penalty = setup.penalty,
      .measures = {{.name = "stop_distance_error_m", .label = "stop distance error (m)"}},
      .judge =
          [=](const std::vector<BodyState>& states, double) {
            const Vec3 slid = states.back().position() - start;
            const double exact = kSpeed * kSpeed / (2.0 * kFriction * kG);
            return std::vector<double>{std::abs(std::hypot(slid.x(), slid.z()) - exact)};
          },
  };
}

// Dropped corner first from 2 m, spinning, restitution 0.3, friction 0.5: it tumbles, settles on
// a face and must then lie still, neither sinking into the floor nor creeping.
ContactCase rest() {
  CubeOnFloor setup = cube_on_floor({.restitution = 0.3, .friction = 0.5});
  const physics::Plane floor = setup.planes.front();
  const physics::BodyModel model = setup.model;
  // Rotated 45° about z, then about x by atan(1/√2): a body diagonal vertical.
  const Quat corner_down = Quat(Eigen::AngleAxisd(std::atan(1.0 / std::sqrt(2.0)), Vec3::UnitX())) *
                           Quat(Eigen::AngleAxisd(std::numbers::pi / 4.0, Vec3::UnitZ()));
  constexpr double kDuration = 6.0, kWatched = 1.0;  // s
  return {
      .name = "rest",
      .summary =
          "A 1 kg unit cube dropped corner first from 2 m spinning at 4.2 rad/s, "
          "restitution 0.3, friction 0.5, left to settle, 6 s",
      .measure_note =
          "over the last second: the deepest any corner is inside the floor, and "
          "the furthest any corner moves in one step (both 0 for a box at rest)",
      .model = setup.model,
      .initial = physics::make_state(setup.model.constants, Vec3(0.0, 2.0, 0.0), Vec3::Zero(),
                                     corner_down, Vec3(1.0, 4.0, 0.5)),
      .planes = setup.planes,
      .duration = kDuration,
      .penalty = setup.penalty,
      .measures = {{.name = "penetration_m", .label = "penetration (m)"},
                   {.name = "corner_motion_m", .label = "corner motion per step (m)"}},
      .judge =
          [=](const std::vector<BodyState>& states, double dt) {
            const std::size_t watched = static_cast<std::size_t>(std::llround(kWatched / dt));
            const std::size_t first = states.size() - std::min(states.size() - 1, watched);
            double penetration = 0.0, motion = 0.0;  // m
            for (std::size_t n = first; n < states.size(); ++n) {
              penetration = std::max(penetration, -lowest_corner(states[n], model, floor));
              for (int feature = 0; feature < 8; ++feature) {
                const Vec3 c = physics::corner(model.shape.half_size, feature);
                motion = std::max(motion, (physics::body_point_to_world(states[n], c) -
                                           physics::body_point_to_world(states[n - 1], c))
                                              .norm());
              }
            }
            return std::vector<double>{penetration, motion};
          },
  };
}

// A round body of radius 0.25 m let go on a 30° slope with friction 0.5 (more than enough to roll):
// it rolls without slipping, down ½ (f g sin θ) t² in 2 s, f = 1 / (1 + I / (m r²)) about its
// rolling axis. Impulse contact only. `lying` turns the body's y axis across the slope.
ContactCase rolling(const char* name, const char* summary, const char* note,
                    const physics::BodyModel& model, double fraction, const Quat& lying) {
  constexpr double kRadius = 0.25, kDuration = 2.0;
  const double theta = std::numbers::pi / 6;
  const Vec3 n(std::sin(theta), std::cos(theta), 0.0), down(std::cos(theta), -std::sin(theta), 0.0);
  const physics::Material& material = model.material;
  const Vec3 start = kRadius * n;
  return {
      .name = name,
      .summary = summary,
      .measure_note = note,
      .model = model,
      .initial = physics::make_state(model.constants, start, Vec3::Zero(), lying, Vec3::Zero()),
      // A floor 10 m below first, never reached: the energy the bench bounds is measured above
      // it (energy_above_rest), and a run that rolls without losing or gaining any keeps it.
      .planes = {physics::Plane{.normal = Vec3::UnitY(), .offset = -10.0, .material = material},
                 physics::Plane{.normal = n, .offset = 0.0, .material = material}},
      .duration = kDuration,
      .penalty = {},  // not run with penalty contact
      .methods = {physics::ContactMethod::impulse},
      .measures = {{.name = "roll_distance_error_m", .label = "roll distance error (m)"},
                   {.name = "slip_speed_m_per_s", .label = "slip speed (m/s)"}},
      .judge =
          [=](const std::vector<BodyState>& states, double dt) {
            const double t = dt * static_cast<double>(states.size() - 1);  // s
            const double exact = 0.5 * fraction * kG * std::sin(theta) * t * t;
            double slip = 0.0;  // m/s
            for (const BodyState& s : states) {
              slip =
                  std::max(slip, (s.velocity() + s.angular_velocity().cross(-kRadius * n)).norm());
            }
            return std::vector<double>{
                std::abs((states.back().position() - start).dot(down) - exact), slip};
          },
  };
}

const physics::Material kRollingMaterial{.restitution = 0.0, .friction = 0.5};

// A ball: f = 5/7.
ContactCase roll() {
  return rolling("roll",
                 "A 1 kg ball of radius 0.25 m let go on a 30° slope, friction 0.5, 2 s "
                 "(impulse contact only)",
                 "the distance rolled down the slope by the end against "
                 "½ (5/7 g sin θ) t² = 4.378 m, and the contact point's fastest slip",
                 {.constants = physics::sphere_constants(1.0, 0.25),
                  .forces = {physics::Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                  .shape = physics::sphere_shape(0.25),
                  .material = kRollingMaterial},
                 5.0 / 7.0, Quat::Identity());
}

// A solid cylinder lying across the slope: f = 2/3. Its points are rim points found at each step,
// where the ball's is its centre's.
ContactCase roll_cylinder() {
  return rolling("roll_cylinder",
                 "A 1 kg solid cylinder of radius 0.25 m and length 0.5 m let go lying across a "
                 "30° slope, friction 0.5, 2 s (impulse contact only)",
                 "the distance rolled down the slope by the end against "
                 "½ (2/3 g sin θ) t² = 4.087 m, and the contact point's fastest slip",
                 {.constants = physics::constants_from_moments(
                      1.0, physics::cylinder_inertia(1.0, 0.25, 0.5).diagonal()),
                  .forces = {physics::Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                  .shape = physics::cylinder_shape(0.25, 0.25),
                  .material = kRollingMaterial},
                 2.0 / 3.0, Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX())));
}

}  // namespace

const std::vector<ContactCase>& contact_cases() {
  static const std::vector<ContactCase> cases = {bounce(), slide(), rest(), roll(),
                                                 roll_cylinder()};
  return cases;
}

double energy_above_rest(const ContactCase& c, const BodyState& state) {
  Vec3 gravity = Vec3::Zero();  // m/s²
  for (const physics::ForceLaw& law : c.model.forces) {
    if (const auto* g = std::get_if<physics::Gravity>(&law)) gravity += g->acceleration;
  }
  const double height = physics::separation(c.planes.front(), state.position()) -
                        c.model.shape.half_size.minCoeff();  // m, above the lowest rest on a face
  return physics::kinetic_energy(state) + c.model.constants.mass * gravity.norm() * height;
}

const ContactCase* find_contact_case(const std::string& name) {
  for (const ContactCase& c : contact_cases()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

sim::Simulation contact_simulation(const ContactCase& c, physics::ContactMethod method,
                                   physics::Integrator integrator, double dt) {
  if (method == physics::ContactMethod::impulse) {
    return sim::Simulation({c.model}, {c.initial}, integrator, dt, c.planes);
  }
  return sim::Simulation(
      {physics::with_penalty_contact(c.model, c.planes, c.penalty.stiffness, c.penalty.damping)},
      {c.initial}, integrator, dt, {}, c.penalty);
}

}  // namespace tumble::bench
