#include "bench/joint_cases.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

#include "physics/mass_properties.hpp"

namespace tumble::bench {
namespace {

using physics::BodyModel;
using physics::BodyState;
using physics::Vec3;

constexpr double kG = 9.81;  // m/s²

BodyModel ball(double mass, double radius) {
  return {.constants = physics::sphere_constants(mass, radius),
          .forces = {physics::Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
          .shape = physics::sphere_shape(radius),
          .collides = false};
}

BodyState at_rest(const BodyModel& model, const Vec3& position) {
  return physics::make_state(model.constants, position, Vec3::Zero(), physics::Quat::Identity(),
                             Vec3::Zero());
}

// A 1 kg ball on a rod of 1 m from (0, 2, 0) to its centre, from 90°: its period against
// 4 √(L/g) K(sin 45°), from the upward crossings of the vertical (by the cubic through each
// crossing step's ends), and its rod's length.
JointCase pendulum() {
  JointCase c{.name = "pendulum",
              .summary =
                  "a ball on a rigid rod of 1 m (a distance joint to its centre), let go "
                  "from 90°, for 12 s",
              .measure_note =
                  "the period's relative error against 4 √(L/g) K(sin(θ0/2)) "
                  "(std::comp_ellint_1), the mean of the run's whole periods; the "
                  "rod's largest length error",
              .models = {ball(1.0, 0.05)},
              .duration = 12.0,
              .measures = {{"period_error", "period error (relative)"},
                           {"rod_error_m", "rod length error (m)"}}};
  const Vec3 pivot(0.0, 2.0, 0.0);
  c.initial = {at_rest(c.models[0], pivot + Vec3(1.0, 0.0, 0.0))};
  c.joints = {physics::place_joint(physics::JointKind::distance, 0, physics::kWorldBody, c.initial,
                                   c.initial[0].position(), pivot)};
  c.judge = [pivot](const std::vector<std::vector<BodyState>>& states, double dt) {
    const double exact =
        4.0 * std::sqrt(1.0 / kG) * std::comp_ellint_1(std::sin(0.25 * std::numbers::pi));
    std::vector<double> crossings;
    double rod = 0.0;
    for (std::size_t n = 1; n < states.size(); ++n) {
      const BodyState& a = states[n - 1][0];
      const BodyState& b = states[n][0];
      rod = std::max(rod, std::abs((b.position() - pivot).norm() - 1.0));
      if (!(a.position().x() < 0.0 && b.position().x() >= 0.0)) continue;
      const double s = crossing_in_step(a.position().x(), a.velocity().x() * dt, b.position().x(),
                                        b.velocity().x() * dt);
      crossings.push_back((static_cast<double>(n - 1) + s) * dt);
    }
    if (crossings.size() < 2) return std::vector<double>{1.0, rod};
    const double period =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    return std::vector<double>{std::abs(period / exact - 1.0), rod};
  };
  return c;
}

// Two 1 kg balls on rods of 1 m from horizontal: their angles at 3 s against the reduced
// equations at 1e-12, and the energy's drift.
JointCase double_pendulum() {
  JointCase c{
      .name = "double_pendulum",
      .summary =
          "two balls on rods of 1 m (point masses exactly), let go from "
          "horizontal, for 3 s (chaotic: errors grow by e every ~0.3 s)",
      .measure_note =
          "the larger of the two rods' angle errors at 3 s against the "
          "reduced angle equations integrated by Boost.Odeint's RKF78 at "
          "1e-12; the energy's largest relative drift",
      .models = {ball(1.0, 0.05), ball(1.0, 0.05)},
      .duration = 3.0,
      .measures = {{"angle_error_rad", "angle error (rad)"}, {"energy_drift", "energy drift"}}};
  const Vec3 pivot(0.0, 2.0, 0.0);
  c.initial = {at_rest(c.models[0], pivot + Vec3(1.0, 0.0, 0.0)),
               at_rest(c.models[1], pivot + Vec3(2.0, 0.0, 0.0))};
  c.joints = {physics::place_joint(physics::JointKind::distance, 0, physics::kWorldBody, c.initial,
                                   c.initial[0].position(), pivot),
              physics::place_joint(physics::JointKind::distance, 1, 0, c.initial,
                                   c.initial[1].position(), c.initial[0].position())};
  const double duration = c.duration;
  c.judge = [pivot, duration](const std::vector<std::vector<BodyState>>& states, double) {
    const std::vector<double> exact = double_pendulum_angles(
        {std::numbers::pi / 2.0, std::numbers::pi / 2.0, 0.0, 0.0}, 0.0, duration, 1e-12, kG);
    const auto energy = [](const std::vector<BodyState>& s) {
      double e = 0.0;
      for (const BodyState& b : s) e += physics::kinetic_energy(b) + kG * b.position().y();
      return e;
    };
    const double start = energy(states.front());
    double drift = 0.0;
    for (const auto& s : states)
      drift = std::max(drift, std::abs(energy(s) - start) / std::abs(start));
    const std::vector<BodyState>& end = states.back();
    const Vec3 d1 = end[0].position() - pivot, d2 = end[1].position() - end[0].position();
    const double a1 = std::atan2(d1.x(), -d1.y()), a2 = std::atan2(d2.x(), -d2.y());
    const double error = std::max(std::abs(std::remainder(a1 - exact[0], 2.0 * std::numbers::pi)),
                                  std::abs(std::remainder(a2 - exact[1], 2.0 * std::numbers::pi)));
    return std::vector<double>{error, drift};
  };
  return c;
}

// The heavy symmetric top of tests/physics/joints_test.cpp: a disc on a ball joint 0.1 m below
// its centre, tilted 20°, spinning at 50 rad/s, started on its slow steady precession.
JointCase heavy_top() {
  constexpr double radius = 0.1, thickness = 0.02, mass = 1.0, l = 0.1, spin = 50.0;
  const double tilt = 20.0 * std::numbers::pi / 180.0;
  const Vec3 moments = physics::cylinder_inertia(mass, radius, thickness).diagonal();
  const double i3 = moments.y(), i1 = moments.x() + mass * l * l, mgl = mass * kG * l;
  const double omega =
      (i3 * spin - std::sqrt(i3 * i3 * spin * spin - 4.0 * i1 * mgl * std::cos(tilt))) /
      (2.0 * i1 * std::cos(tilt));
  JointCase c{.name = "heavy_top",
              .summary =
                  "a disc on a ball joint 0.1 m below its centre, tilted 20°, spinning at "
                  "50 rad/s, started on its steady precession, for 5 s",
              .measure_note =
                  "the mean precession rate's relative error against the root of "
                  "I1 Ω² cos θ - I3 ω3 Ω + M g l = 0; the energy's largest relative "
                  "drift",
              .models = {{.constants = physics::constants_from_moments(mass, moments),
                          .forces = {physics::Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                          .shape = physics::cylinder_shape(radius, 0.5 * thickness),
                          .collides = false}},
              .duration = 5.0,
              .measures = {{"precession_error", "precession error (relative)"},
                           {"energy_drift", "energy drift"}}};
  const Vec3 pivot(0.0, 1.0, 0.0);
  const physics::Quat q(Eigen::AngleAxisd(tilt, Vec3::UnitZ()));
  const Vec3 axis = q * Vec3::UnitY();
  const Vec3 w = omega * Vec3::UnitY() + (spin - omega * std::cos(tilt)) * axis;
  c.initial = {
      physics::make_state(c.models[0].constants, pivot + l * axis, w.cross(l * axis), q, w)};
  c.joints = {physics::place_joint(physics::JointKind::ball, 0, physics::kWorldBody, c.initial,
                                   pivot, pivot)};
  const double duration = c.duration;
  c.judge = [omega, mgl, l, duration](const std::vector<std::vector<BodyState>>& states, double) {
    const auto energy = [&](const BodyState& s) {
      return physics::kinetic_energy(s) + mgl / l * s.position().y();
    };
    const double start = energy(states.front()[0]);
    double drift = 0.0, turned = 0.0;
    Vec3 last = states.front()[0].rotation() * Vec3::UnitY();
    for (const auto& s : states) {
      drift = std::max(drift, std::abs(energy(s[0]) - start) / start);
      const Vec3 a = s[0].rotation() * Vec3::UnitY();
      turned +=
          std::atan2(last.z() * a.x() - last.x() * a.z(), last.x() * a.x() + last.z() * a.z());
      last = a;
    }
    return std::vector<double>{std::abs(turned / duration / omega - 1.0), drift};
  };
  return c;
}

}  // namespace

double crossing_in_step(double x0, double d0, double x1, double d1) {
  double s = x0 / (x0 - x1);
  for (int k = 0; k < 20; ++k) {
    const double x = (2 * s * s * s - 3 * s * s + 1) * x0 + (s * s * s - 2 * s * s + s) * d0 +
                     (-2 * s * s * s + 3 * s * s) * x1 + (s * s * s - s * s) * d1;
    const double dx = (6 * s * s - 6 * s) * x0 + (3 * s * s - 4 * s + 1) * d0 +
                      (-6 * s * s + 6 * s) * x1 + (3 * s * s - 2 * s) * d1;
    s -= x / dx;
  }
  return s;
}

std::vector<double> double_pendulum_angles(std::vector<double> y, double t0, double t1,
                                           double tolerance, double g) {
  namespace odeint = boost::numeric::odeint;
  // (m1 + m2) l1 θ̈1 + m2 l2 θ̈2 cos δ = -m2 l2 θ̇2² sin δ - (m1 + m2) g sin θ1
  // l1 θ̈1 cos δ + l2 θ̈2 = l1 θ̇1² sin δ - g sin θ2, with m1 = m2 = 1 kg, l1 = l2 = 1 m.
  const auto rates = [g](const std::vector<double>& s, std::vector<double>& ds, double) {
    const double delta = s[0] - s[1];
    const double a11 = 2.0, a12 = std::cos(delta), a21 = std::cos(delta), a22 = 1.0;
    const double b1 = -s[3] * s[3] * std::sin(delta) - 2.0 * g * std::sin(s[0]);
    const double b2 = s[2] * s[2] * std::sin(delta) - g * std::sin(s[1]);
    const double det = a11 * a22 - a12 * a21;
    ds[0] = s[2];
    ds[1] = s[3];
    ds[2] = (b1 * a22 - a12 * b2) / det;
    ds[3] = (a11 * b2 - a21 * b1) / det;
  };
  odeint::integrate_adaptive(
      odeint::make_controlled(tolerance, tolerance,
                              odeint::runge_kutta_fehlberg78<std::vector<double>>()),
      rates, y, t0, t1, (t1 - t0) / 1000.0);
  return y;
}

const std::vector<JointCase>& joint_cases() {
  static const std::vector<JointCase> cases = {pendulum(), double_pendulum(), heavy_top()};
  return cases;
}

const JointCase* find_joint_case(const std::string& name) {
  for (const JointCase& c : joint_cases()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

sim::Simulation joint_simulation(const JointCase& c, physics::Integrator integrator, double dt) {
  return sim::Simulation(c.models, c.initial, integrator, dt, {}, {}, c.joints);
}

}  // namespace tumble::bench
