#include "sim/contact_advice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <variant>

#include "common/printed.hpp"
#include "physics/contact_island.hpp"
#include "physics/normal_block.hpp"
#include "physics/pair_contact.hpp"
#include "physics/world_step.hpp"
#include "sim/stability.hpp"

namespace tumble::sim {

std::vector<std::string> check_contact(const physics::BodyModel& model,
                                       const std::vector<physics::Plane>& planes,
                                       const physics::ContactSettings& settings,
                                       physics::Integrator integrator, double dt) {
  std::vector<std::string> out;
  // A static body neither falls nor bounces. (What rests on a bouncy static body is not advised
  // on: only planes are looked at here.)
  if (settings.method != physics::ContactMethod::impulse || model.is_static) return out;
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

physics::Vec3 constant_gravity(const physics::BodyModel& model) {
  physics::Vec3 total = physics::Vec3::Zero();  // m/s²
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* g = std::get_if<physics::Gravity>(&law)) total += g->acceleration;
  }
  return total;
}

double gravity_of(const physics::BodyModel& model) {
  return constant_gravity(model).norm();
}

// The root of `i` in a union-find forest, with path halving.
std::size_t root_of(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Whether two bodies touch (within kTouching).
bool touch(const physics::BodyModel& a, const physics::BodyState& sa, const physics::BodyModel& b,
           const physics::BodyState& sb) {
  return physics::pair_separation({sa.position(), sa.rotation(), &a.shape},
                                  {sb.position(), sb.rotation(), &b.shape}, kTouching) < kTouching;
}

}  // namespace

std::vector<std::size_t> weightless_above_floor(const std::vector<physics::BodyModel>& models,
                                                const std::vector<physics::BodyState>& initial,
                                                const std::vector<physics::Plane>& planes) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i].is_static || !constant_gravity(models[i]).isZero(0.0)) continue;
    const physics::Vec3& centre = initial[i].position();  // world frame (m)
    const auto floor_below = [&](const physics::Plane& plane) {
      return plane.normal.y() > 0.0 && plane.normal.dot(centre) > plane.offset;
    };
    if (std::any_of(planes.begin(), planes.end(), floor_below)) out.push_back(i);
  }
  return out;
}

TouchingAtStart touching_at_start(const std::vector<physics::BodyModel>& models,
                                  const std::vector<physics::BodyState>& initial,
                                  const std::vector<physics::Plane>& planes,
                                  const physics::ContactSettings& settings) {
  const std::size_t count = models.size();
  TouchingAtStart out;
  out.on_plane.assign(count, false);
  out.touches.assign(count, false);
  out.group.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    out.group[i] = i;
    if (models[i].is_static) continue;
    for (const physics::Plane& plane : planes) {
      if (physics::closest_separation(initial[i], models[i].shape, plane) < kTouching) {
        out.on_plane[i] = out.touches[i] = true;
      }
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count && settings.collide_bodies; ++j) {
      if (!models[i].collides || !models[j].collides) continue;
      if (models[i].is_static && models[j].is_static) continue;
      if (!touch(models[i], initial[i], models[j], initial[j])) continue;
      // A static body holds what rests on it as a plane does.
      if (models[i].is_static || models[j].is_static) {
        const std::size_t moving = models[i].is_static ? j : i;
        out.on_plane[moving] = out.touches[moving] = true;
        continue;
      }
      out.touches[i] = out.touches[j] = true;
      out.group[root_of(out.group, i)] = root_of(out.group, j);
      out.pairs.emplace_back(i, j);
    }
  }
  for (std::size_t i = 0; i < count; ++i) out.group[i] = root_of(out.group, i);
  return out;
}

std::vector<BodiesAdvice> check_contact_world(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings,
                                              physics::Integrator integrator, double dt) {
  if (settings.method == physics::ContactMethod::penalty) {
    return check_penalty_pairs(models, initial, planes, settings, integrator, dt);
  }
  std::vector<BodiesAdvice> out;
  const std::size_t count = models.size();
  const TouchingAtStart touching = touching_at_start(models, initial, planes, settings);
  const std::vector<bool>& on_plane = touching.on_plane;
  const std::vector<bool>& touches = touching.touches;
  const std::vector<std::pair<std::size_t, std::size_t>>& pairs = touching.pairs;
  const std::vector<std::size_t>& group = touching.group;
  // The contact points of each group (by its root): whether the block solve takes it.
  std::vector<std::size_t> points(count, 0);
  for (const auto& [i, j] : pairs)
    points[group[i]] += static_cast<std::size_t>(physics::kMaxManifoldPoints);
  for (std::size_t i = 0; i < count; ++i) {
    if (on_plane[i]) points[group[i]] += static_cast<std::size_t>(physics::kMaxManifoldPoints);
  }
  const auto by_rows = [&](std::size_t i) { return points[group[i]] > physics::kMostBlockRows; };
  const std::string why = printed(
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
           printed("touch with a mass ratio of %.3g (%.3g kg on %.3g kg) %s, beyond "
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
    const double edge = 2.0 * models[i].shape.half_size.minCoeff();       // m
    const double per_step = 0.5 * acceleration * dt * dt;                 // m
    if (per_step > edge) {
      out.push_back({{i},
                     printed("its constant load (%.3g m/s²) moves it %.3g m in one step of "
                             "%.3g s, more than its smallest edge (%.3g m), %s: one step's "
                             "contact cannot carry it and it ends its steps inside what holds "
                             "it; use dt <= %.3g s",
                             acceleration, per_step, dt, edge, why.c_str(),
                             std::sqrt(2.0 * edge / acceleration))});
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (group[i] != i || !by_rows(i)) continue;
    std::vector<std::size_t> stack;
    bool grounded = false;
    double gravity = 0.0;  // m/s²
    for (std::size_t j = 0; j < count; ++j) {
      if (group[j] != i) continue;
      stack.push_back(j);
      grounded = grounded || on_plane[j];
      gravity = std::max(gravity, gravity_of(models[j]));
    }
    const double sink = gravity * dt * dt;  // m
    if (stack.size() < 3 || !grounded || sink <= kMostStackSink) continue;
    out.push_back({stack, printed("a stack of %zu bodies with %zu contact points stepped at "
                                  "dt = %.3g s sinks |g| dt² = %.3g m a step under gravity, "
                                  "beyond the %.0f mm at which the contact solver settles a "
                                  "stack it solves one point at a time (a column of 14 cubes "
                                  "at dt = 1/30 s collapses); use dt <= %.3g s",
                                  stack.size(), points[i], dt, sink, kMostStackSink * 1e3,
                                  std::sqrt(kMostStackSink / gravity))});
  }
  return out;
}

std::vector<BodiesAdvice> check_penalty_pairs(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings,
                                              physics::Integrator integrator, double dt) {
  std::vector<BodiesAdvice> out;
  if (!physics::pairs_possible(models, settings) || settings.stiffness <= 0.0) return out;
  const std::size_t count = models.size();
  const TouchingAtStart touching = touching_at_start(models, initial, planes, settings);
  const double face = settings.stiffness * physics::kMaxManifoldPoints;  // 4k (N/m)
  const auto mass = [&](std::size_t i) { return models[i].constants.mass; };
  // Gershgorin's bound on M⁻¹K by body, and each group's largest.
  std::vector<double> bound(count, 0.0), group_bound(count, 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    if (touching.on_plane[i]) bound[i] += face / mass(i);
  }
  for (const auto& [i, j] : touching.pairs) {
    const double across = face / std::sqrt(mass(i) * mass(j));
    bound[i] += face / mass(i) + across;
    bound[j] += face / mass(j) + across;
  }
  for (const auto& [i, j] : touching.pairs) {
    for (const std::size_t b : {i, j}) {
      group_bound[touching.group[b]] = std::max(group_bound[touching.group[b]], bound[b]);
    }
  }
  const double ratio = settings.damping / settings.stiffness;  // c/k (s)
  const auto mode_of = [&](double lambda) {
    return LinearMode{.damping_rate = ratio * lambda,
                      .frequency = std::sqrt(lambda),
                      .kick_damping = KickDamping::frozen};
  };
  // Each group's bodies, and how far a grounded one sinks under its weight (m).
  const auto members = [&](std::size_t root) {
    std::vector<std::size_t> in_group;
    for (std::size_t i = 0; i < count; ++i) {
      if (touching.group[i] == root) in_group.push_back(i);
    }
    return in_group;
  };
  const auto sink_of = [&](const std::vector<std::size_t>& group) {
    bool grounded = false;
    physics::Vec3 gravity = physics::Vec3::Zero();
    for (const std::size_t i : group) {
      grounded = grounded || touching.on_plane[i];
      if (gravity_of(models[i]) > gravity.norm()) gravity = constant_gravity(models[i]);
    }
    if (!grounded || gravity.isZero()) return 0.0;
    const physics::Vec3 up = -gravity.normalized();
    double sink = 0.0;
    for (const std::size_t i : group) {
      double above = 0.0;  // the weight at or above body i (N)
      for (const std::size_t j : group) {
        if (up.dot(initial[j].position()) >= up.dot(initial[i].position())) {
          above += mass(j) * gravity.norm();
        }
      }
      sink += above / face;
    }
    return sink;
  };
  const auto tolerance_of = [&](const std::vector<std::size_t>& group) {
    double edge = std::numeric_limits<double>::infinity();
    for (const std::size_t i : group)
      edge = std::min(edge, 2.0 * models[i].shape.half_size.minCoeff());
    return kMostPenaltySink * edge;  // m
  };
  const std::string springs = printed(
      "penalty contact between bodies (k = %.4g N/m, c = %.4g N s/m per point, four points to a "
      "face)",
      settings.stiffness, settings.damping);
  // The warning on one bound, with the stiffness that is stable at this dt when it holds.
  const auto warn = [&](std::vector<std::size_t> bodies, double lambda, const std::string& what,
                        double sink, double tolerance) {
    NamedMode named{
        .mode = mode_of(lambda),
        .cause = printed("%s makes %s at up to ω_n = %.4g rad/s, damped at %.4g /s",
                         springs.c_str(), what.c_str(), std::sqrt(lambda), ratio * lambda),
        .penalty_contact = true};
    std::optional<StepWarning> warning = check_mode(integrator, named, dt);
    if (!warning) return false;
    BodiesAdvice advice{.bodies = std::move(bodies), .suggested_dt = warning->suggested_dt};
    // k → α k with c → √α c keeps ζ and scales every rate of the mode by √α.
    const std::optional<double> limit = stability_limit(integrator, named.mode);
    if (limit && *limit > 0.0) {
      const double alpha = std::pow(kSuggestedFractionOfLimit * *limit / dt, 2.0);
      const double softer_sink = sink / alpha;
      if (softer_sink <= tolerance) {
        advice.suggested_stiffness = alpha * settings.stiffness;
        advice.suggested_damping = std::sqrt(alpha) * settings.damping;
        warning->message += printed(
            "; at this dt, contact_stiffness = %.3g and contact_damping = %.3g hold (ζ kept%s)",
            *advice.suggested_stiffness, *advice.suggested_damping,
            sink > 0.0 ? printed(", the stack sinking %.3g mm", softer_sink * 1e3).c_str() : "");
      }
    }
    advice.message = std::move(warning->message);
    out.push_back(std::move(advice));
    return true;
  };
  bool warned = false;
  for (std::size_t root = 0; root < count; ++root) {
    if (group_bound[root] <= 0.0) continue;
    const std::vector<std::size_t> group = members(root);
    const double sink = sink_of(group), tolerance = tolerance_of(group);
    warned = warn(group, group_bound[root], "them bounce on each other", sink, tolerance) || warned;
    if (sink > tolerance) {
      out.push_back({.bodies = group,
                     .message = printed(
                         "%s makes the stack of %zu bodies sink about %.3g mm into its springs "
                         "under its weight (more than %.3g mm, %.0f%% of its smallest edge); "
                         "use contact_stiffness >= %.3g (and a dt that is stable with it: "
                         "tumble check tells)",
                         springs.c_str(), group.size(), sink * 1e3, tolerance * 1e3,
                         kMostPenaltySink * 100.0, settings.stiffness * sink / tolerance),
                     .suggested_stiffness = settings.stiffness * sink / tolerance});
    }
  }
  if (warned) return out;
  // Bodies that do not touch at the start may meet: the two lightest colliding ones.
  std::vector<std::size_t> colliders;
  for (std::size_t i = 0; i < count; ++i) {
    if (models[i].collides) colliders.push_back(i);
  }
  std::partial_sort(colliders.begin(), colliders.begin() + 2, colliders.end(),
                    [&](std::size_t a, std::size_t b) {
                      return mass(a) < mass(b) || (mass(a) == mass(b) && a < b);
                    });
  const std::size_t first = std::min(colliders[0], colliders[1]);
  const std::size_t second = std::max(colliders[0], colliders[1]);
  warn({first, second}, face * (1.0 / mass(first) + 1.0 / mass(second)),
       "them bounce off each other where they meet face to face", 0.0, 0.0);
  return out;
}

}  // namespace tumble::sim
