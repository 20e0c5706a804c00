#include "sim/contact_advice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include "physics/box_box.hpp"
#include "physics/contact_island.hpp"
#include "physics/normal_block.hpp"

namespace tumble::sim {

std::vector<std::string> check_contact(const physics::BodyModel& model,
                                       const std::vector<physics::Plane>& planes,
                                       const physics::ContactSettings& settings,
                                       physics::Integrator integrator, double dt) {
  std::vector<std::string> out;
  if (settings.method != physics::ContactMethod::impulse) return out;
  physics::Vec3 gravity = physics::Vec3::Zero();  // m/s²
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* g = std::get_if<physics::Gravity>(&law)) gravity += g->acceleration;
  }
  const double step_speed = gravity.norm() * dt;  // m/s gained in one step of free fall
  if (step_speed == 0.0 && settings.restitution_threshold > 0.0 &&
      model.material.restitution > 0.0) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "it bounces (restitution %.3g) with no gravity, so nothing rests, but its "
                  "impacts slower than restitution_threshold = %.3g m/s lose their bounce; use "
                  "restitution_threshold = 0",
                  model.material.restitution, settings.restitution_threshold);
    out.push_back(text);
    return out;
  }
  const double wanted = kThresholdOverStepSpeed * step_speed;
  if (settings.restitution_threshold >= wanted) return out;
  if (physics::holds_energy(integrator) && physics::passive(model)) return out;  // it rests
  for (const physics::Plane& plane : planes) {
    if (physics::combine(model.material, plane.material).restitution <= 0.0) continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  "restitution_threshold = %.3g m/s is below %.2g × the %.3g m/s that gravity adds "
                  "in one step (|g| dt), so resting on a plane it bounces off (restitution > 0) it "
                  "will bounce on every step and chatter; use restitution_threshold >= %.3g m/s "
                  "or a smaller dt",
                  settings.restitution_threshold, kThresholdOverStepSpeed, step_speed, wanted);
    out.push_back(text);
    break;
  }
  return out;
}

namespace {

// Closer than this at the start counts as touching (m).
constexpr double kTouching = 1e-3;

physics::Vec3 constant_acceleration(const physics::BodyModel& model) {
  physics::Vec3 total = physics::Vec3::Zero();  // m/s²
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* g = std::get_if<physics::Gravity>(&law)) total += g->acceleration;
    if (const auto* f = std::get_if<physics::ConstantForce>(&law)) {
      total += f->force * model.constants.inverse_mass;
    }
  }
  return total;
}

double gravity_of(const physics::BodyModel& model) {
  physics::Vec3 total = physics::Vec3::Zero();
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* g = std::get_if<physics::Gravity>(&law)) total += g->acceleration;
  }
  return total.norm();
}

// The root of `i` in a union-find forest, with path halving.
std::size_t root_of(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

std::string formatted(const char* format, auto... values) {
  char text[400];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

}  // namespace

std::vector<BodiesAdvice> check_contact_world(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings, double dt) {
  std::vector<BodiesAdvice> out;
  if (settings.method != physics::ContactMethod::impulse) return out;
  const std::size_t count = models.size();
  std::vector<bool> on_plane(count, false), touches(count, false);
  std::vector<std::size_t> parent(count);
  for (std::size_t i = 0; i < count; ++i) {
    parent[i] = i;
    for (const physics::Plane& plane : planes) {
      if (physics::closest_corner_separation(initial[i], models[i].half_size, plane) < kTouching) {
        on_plane[i] = touches[i] = true;
      }
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // touching at the start
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count && settings.collide_bodies; ++j) {
      if (!models[i].collides || !models[j].collides) continue;
      const physics::BoxPose a{initial[i].position(), initial[i].rotation(), models[i].half_size};
      const physics::BoxPose b{initial[j].position(), initial[j].rotation(), models[j].half_size};
      if (physics::box_box_axis(a, b).separation >= kTouching) continue;
      touches[i] = touches[j] = true;
      parent[root_of(parent, i)] = root_of(parent, j);
      pairs.emplace_back(i, j);
    }
  }
  // The contact points of each group (by its root): whether the block solve takes it.
  std::vector<std::size_t> points(count, 0);
  for (const auto& [i, j] : pairs)
    points[root_of(parent, i)] += static_cast<std::size_t>(physics::kMaxManifoldPoints);
  for (std::size_t i = 0; i < count; ++i) {
    if (on_plane[i])
      points[root_of(parent, i)] += static_cast<std::size_t>(physics::kMaxManifoldPoints);
  }
  const auto by_rows = [&](std::size_t i) {
    return points[root_of(parent, i)] > physics::kMostBlockRows;
  };
  const std::string why = formatted(
      "in a group of touching bodies with more than %zu contact points, which the contact solver "
      "solves one point at a time",
      physics::kMostBlockRows);
  for (const auto& [i, j] : pairs) {
    if (!by_rows(i)) continue;
    const double heavy = std::max(models[i].constants.mass, models[j].constants.mass);
    const double light = std::min(models[i].constants.mass, models[j].constants.mass);
    if (heavy > kMostMassRatio * light) {
      out.push_back(
          {{i, j},
           formatted("touch with a mass ratio of %.3g (%.3g kg on %.3g kg) %s, beyond "
                     "the %.0f it holds there: the lighter body is pressed into what "
                     "holds it or squeezed out (a column of 14 cubes with a top 50 "
                     "times as heavy collapses); bring the masses within %.0fx of each "
                     "other or split the group",
                     heavy / light, heavy, light, why.c_str(), kMostMassRatio, kMostMassRatio)});
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (!touches[i] || !by_rows(i)) continue;
    const double acceleration = constant_acceleration(models[i]).norm();  // m/s²
    const double edge = 2.0 * models[i].half_size.minCoeff();             // m
    const double per_step = 0.5 * acceleration * dt * dt;                 // m
    if (per_step > edge) {
      out.push_back({{i},
                     formatted("its constant load (%.3g m/s²) moves it %.3g m in one step of "
                               "%.3g s, more than its smallest edge (%.3g m), %s: one step's "
                               "contact cannot carry it and it ends its steps inside what holds "
                               "it; use dt <= %.3g s",
                               acceleration, per_step, dt, edge, why.c_str(),
                               std::sqrt(2.0 * edge / acceleration))});
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (root_of(parent, i) != i || !by_rows(i)) continue;
    std::vector<std::size_t> stack;
    bool grounded = false;
    double gravity = 0.0;  // m/s²
    for (std::size_t j = 0; j < count; ++j) {
      if (root_of(parent, j) != i) continue;
      stack.push_back(j);
      grounded = grounded || on_plane[j];
      gravity = std::max(gravity, gravity_of(models[j]));
    }
    const double sink = gravity * dt * dt;  // m
    if (stack.size() < 3 || !grounded || sink <= kMostStackSink) continue;
    out.push_back({stack, formatted("a stack of %zu bodies with %zu contact points stepped at "
                                    "dt = %.3g s sinks |g| dt² = %.3g m a step under gravity, "
                                    "beyond the %.0f mm at which the contact solver settles a "
                                    "stack it solves one point at a time (a column of 14 cubes "
                                    "at dt = 1/30 s collapses); use dt <= %.3g s",
                                    stack.size(), points[i], dt, sink, kMostStackSink * 1e3,
                                    std::sqrt(kMostStackSink / gravity))});
  }
  return out;
}

}  // namespace tumble::sim
