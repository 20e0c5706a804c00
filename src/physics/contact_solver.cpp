#include "physics/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "physics/normal_block.hpp"

namespace tumble::physics {
namespace {

constexpr int kBounceIterations = 100;
constexpr double kBounceTolerance = 1e-13;

SolverBody* second(std::span<SolverBody> bodies, const ContactConstraint& c) {
  return c.b == kStatic ? nullptr : &bodies[c.b];
}

// The normal row of one point; returns the change of its impulse (N s).
[[gnu::always_inline]] inline double solve_normal(std::span<SolverBody> bodies,
                                                  ContactConstraint& c) {
  SolverBody& a = bodies[c.a];
  SolverBody* b = second(bodies, c);
  const double accumulated =
      std::max(0.0, c.normal_impulse -
                        c.normal.mass * (relative_speed(c.normal, a, b) + c.speculative_speed));
  const double change = accumulated - c.normal_impulse;
  c.normal_impulse = accumulated;
  push(c.normal, a, b, change);
  return change;
}

// Two rows solved together within a circle: both accumulated impulses within `limit`, so that no
// direction between them is favoured (the tangents' circular cone; the rolling rows' circle).
// Returns the larger change.
[[gnu::always_inline]] inline double solve_in_circle(const ImpulseDirection (&rows)[2],
                                                     double (&accumulated)[2], double limit,
                                                     SolverBody& a, SolverBody* b) {
  double wanted[2];
  for (int k = 0; k < 2; ++k) {
    wanted[k] = accumulated[k] - rows[k].mass * relative_speed(rows[k], a, b);
  }
  const double size_squared = wanted[0] * wanted[0] + wanted[1] * wanted[1];
  const double scale = size_squared > limit * limit ? limit / std::sqrt(size_squared) : 1.0;
  double largest = 0.0;
  for (int k = 0; k < 2; ++k) {
    const double change = wanted[k] * scale - accumulated[k];
    push(rows[k], a, b, change);
    accumulated[k] += change;
    largest = std::max(largest, std::abs(change));
  }
  return largest;
}

// The friction rows of one patch, within μ times its points' normal impulse; returns the largest
// change (N s, or N m s for the twist).
double solve_friction(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
                      FrictionPatch& f) {
  SolverBody& a = bodies[f.a];
  SolverBody* b = f.b == kStatic ? nullptr : &bodies[f.b];
  double normal = 0.0;
  for (std::uint32_t i = f.first; i < f.first + f.count; ++i) {
    normal += points[i].normal_impulse + points[i].impact_impulse;
  }
  // Circular cone: both tangent impulses together within μ λ_n.
  const double limit = f.friction * normal;
  double largest = solve_in_circle(f.tangent, f.tangent_impulse, limit, a, b);
  const double twist_limit = limit * f.shape.twist_arm;
  const double twist = std::clamp(f.twist_impulse - f.twist.mass * relative_speed(f.twist, a, b),
                                  -twist_limit, twist_limit);
  const double change = twist - f.twist_impulse;
  push(f.twist, a, b, change);
  f.twist_impulse = twist;
  largest = std::max(largest, std::abs(change));
  if (f.rolling_arm > 0.0) {
    const ImpulseDirection rolling[2] = {turning_direction(f.tangent[0].linear, a, b),
                                         turning_direction(f.tangent[1].linear, a, b)};
    largest = std::max(largest,
                       solve_in_circle(rolling, f.rolling_impulse, f.rolling_arm * normal, a, b));
  }
  return largest;
}

// One pass over every patch: its points' normal rows, then its friction. Returns the largest
// change of an accumulated impulse.
double inelastic_pass(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                      std::span<FrictionPatch> patches) {
  double largest_change = 0.0;
  for (FrictionPatch& f : patches) {
    for (std::uint32_t i = f.first; i < f.first + f.count; ++i) {
      largest_change = std::max(largest_change, std::abs(solve_normal(bodies, points[i])));
    }
    largest_change = std::max(largest_change, solve_friction(bodies, points, f));
  }
  return largest_change;
}

// The normal rows of the points in the patches solved as one block, with what it needs of them.
struct BlockRows {
  NormalBlock block;
  std::vector<double> least, impulses;

  // The rows of the points in `patches`, which must be at most kMostBlockRows; false if more.
  bool build(std::span<const SolverBody> bodies, std::span<const ContactConstraint> points,
             std::span<const FrictionPatch> patches) {
    std::vector<std::uint32_t> rows;
    for (const FrictionPatch& f : patches) {
      for (std::uint32_t i = f.first; i < f.first + f.count; ++i) rows.push_back(i);
    }
    if (rows.size() > kMostBlockRows) return false;
    block.build(bodies, points, rows);
    least.resize(rows.size());
    impulses.resize(rows.size());
    return true;
  }

  // Solves the rows, point i's normal speed at least least_of(i) (m/s), and writes the impulses
  // back to the points; returns the largest change of one (N s), or -1 when the block did not
  // solve (and nothing changed).
  template <class Least>
  double solve(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
               std::span<const FrictionPatch> patches, Least least_of) {
    std::size_t k = 0;
    for (const FrictionPatch& f : patches) {
      for (std::uint32_t i = f.first; i < f.first + f.count; ++i, ++k) {
        least[k] = least_of(i);
        impulses[k] = points[i].normal_impulse;
      }
    }
    if (!block.solve(bodies, points, least, impulses)) return -1.0;
    double largest_change = 0.0;
    k = 0;
    for (const FrictionPatch& f : patches) {
      for (std::uint32_t i = f.first; i < f.first + f.count; ++i, ++k) {
        largest_change = std::max(largest_change, std::abs(impulses[k] - points[i].normal_impulse));
        points[i].normal_impulse = impulses[k];
      }
    }
    return largest_change;
  }
};

// One pass of the inelastic solve with the normal rows as one block (each point's speed at
// least the speculative speed it may still approach at), then each patch's friction. A block
// that does not solve leaves this pass to the rows one by one. Returns the largest change of an
// accumulated impulse.
double block_pass(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                  std::span<FrictionPatch> patches, BlockRows& rows) {
  double largest_change = rows.solve(bodies, points, patches,
                                     [&](std::uint32_t i) { return -points[i].speculative_speed; });
  if (largest_change < 0.0) return inelastic_pass(bodies, points, patches);
  for (FrictionPatch& f : patches) {
    largest_change = std::max(largest_change, solve_friction(bodies, points, f));
  }
  return largest_change;
}

// One pass driving each bouncing point's normal speed up to -e × its approach speed, adding to
// (never taking from below zero) the impulse it already has.
double bounce_pass(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
                   const std::vector<double>& bounce_impulse, std::vector<double>& accumulated) {
  double largest_change = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ContactConstraint& c = points[i];
    if (bounce_impulse[i] == 0.0) continue;  // marks a point that does not bounce
    SolverBody& a = bodies[c.a];
    SolverBody* b = second(bodies, c);
    const double target = -c.restitution * c.approach_speed;
    const double total =
        std::max(0.0, accumulated[i] - c.normal.mass * (relative_speed(c.normal, a, b) - target));
    const double change = total - accumulated[i];
    accumulated[i] = total;
    push(c.normal, a, b, change);
    largest_change = std::max(largest_change, std::abs(change));
  }
  return largest_change;
}

double largest_normal_impulse(std::span<const ContactConstraint> points) {
  double largest = 0.0;
  for (const ContactConstraint& c : points) largest = std::max(largest, c.normal_impulse);
  return largest;
}

// The kinetic energy of a body at (v + s dv, ω + s dω) as c₀ + c₁ s + c₂ s² (J), dv and dω
// taking it from `at_zero` to `at_one`.
struct EnergyInStep {
  double c0 = 0.0, c1 = 0.0, c2 = 0.0;
};
EnergyInStep energy_in_step(const SolverBody& at_zero, const SolverBody& at_one) {
  const Vec3 dv = at_one.velocity - at_zero.velocity;
  const Vec3 dw = at_one.angular_velocity - at_zero.angular_velocity;
  const Mat3& inertia = at_zero.inertia;
  const double mass = at_zero.inverse_mass > 0.0 ? 1.0 / at_zero.inverse_mass : 0.0;
  return {.c0 = at_zero.kinetic_energy(),
          .c1 = mass * at_zero.velocity.dot(dv) + at_zero.angular_velocity.dot(inertia * dw),
          .c2 = 0.5 * (mass * dv.squaredNorm() + dw.dot(inertia * dw))};
}

// The largest s in [0, 1] at which an energy c₀ + c₁ s + c₂ s² is at most `bound`, given that
// it is at s = 0.
double largest_step_within(const EnergyInStep& e, double bound) {
  const double a = e.c0 - bound;  // <= 0
  if (e.c2 <= 0.0) return 0.0;
  // The positive root of c₂ s² + c₁ s + a = 0 (a <= 0 so it exists), without cancellation.
  const double root = std::sqrt(std::max(0.0, e.c1 * e.c1 - 4.0 * e.c2 * a));
  const double s = e.c1 >= 0.0 ? (-2.0 * a) / (e.c1 + root) : (root - e.c1) / (2.0 * e.c2);
  return std::clamp(s, 0.0, 1.0);
}

// The bounce of the points whose `bouncing` entry is not 0 (solve_contacts and bounce say when),
// from the bodies' velocities now, then held to `energy_before` (J).
void bounce_points(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
                   const std::vector<double>& bouncing, int iterations, double energy_before) {
  const std::vector<SolverBody> inelastic(bodies.begin(), bodies.end());
  std::vector<double> accumulated(points.size(), 0.0);
  // A bounce is solved to round-off whatever the settings say: it happens once per impact, and
  // its velocities decide everything after it (an elastic exchange of velocities, say).
  for (int pass = 0; pass < std::max(iterations, kBounceIterations); ++pass) {
    const double change = bounce_pass(bodies, points, bouncing, accumulated);
    double largest = 0.0;
    for (const double a : accumulated) largest = std::max(largest, a);
    if (change <= kBounceTolerance * largest) break;
  }
  if (total_kinetic_energy(bodies) <= energy_before) return;
  // One scale for the whole group: energy a bounce moves from one body to another is kept.
  EnergyInStep energy;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const EnergyInStep e = energy_in_step(inelastic[b], bodies[b]);
    energy.c0 += e.c0;
    energy.c1 += e.c1;
    energy.c2 += e.c2;
  }
  const double s = largest_step_within(energy, energy_before);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    SolverBody& body = bodies[b];
    const SolverBody& from = inelastic[b];
    body.velocity = from.velocity + s * (body.velocity - from.velocity);
    body.angular_velocity =
        from.angular_velocity + s * (body.angular_velocity - from.angular_velocity);
  }
}

// The normal row of one point of a sub-step of h (s), apart by `separation` (m).
void solve_substep_normal(std::span<SolverBody> bodies, ContactConstraint& c, double separation,
                          double h) {
  SolverBody& a = bodies[c.a];
  SolverBody* b = second(bodies, c);
  const double allowed = separation > 0.0 ? separation / h : 0.0;  // approach speed (m/s)
  const double accumulated =
      std::max(0.0, c.normal_impulse - c.normal.mass * (relative_speed(c.normal, a, b) + allowed));
  const double change = accumulated - c.normal_impulse;
  c.normal_impulse = accumulated;
  push(c.normal, a, b, change);
}

}  // namespace

double total_kinetic_energy(std::span<const SolverBody> bodies) {
  double total = 0.0;
  for (const SolverBody& body : bodies) total += body.kinetic_energy();
  return total;
}

void warm_start(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
                std::span<const FrictionPatch> patches) {
  for (const ContactConstraint& c : points) {
    push(c.normal, bodies[c.a], second(bodies, c), c.normal_impulse);
  }
  for (const FrictionPatch& f : patches) {
    SolverBody& a = bodies[f.a];
    SolverBody* b = f.b == kStatic ? nullptr : &bodies[f.b];
    for (int k = 0; k < 2; ++k) push(f.tangent[k], a, b, f.tangent_impulse[k]);
    push(f.twist, a, b, f.twist_impulse);
  }
}

void substep_pass(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                  std::span<const double> separations, std::span<FrictionPatch> patches, double h,
                  bool by_block) {
  BlockRows block;
  if (by_block && block.build(bodies, points, patches) &&
      block.solve(bodies, points, patches, [&](std::uint32_t i) {
        return separations[i] > 0.0 ? -separations[i] / h : 0.0;
      }) >= 0.0) {
    for (FrictionPatch& f : patches) solve_friction(bodies, points, f);
    return;
  }
  for (FrictionPatch& f : patches) {
    for (std::uint32_t i = f.first; i < f.first + f.count; ++i) {
      solve_substep_normal(bodies, points[i], separations[i], h);
    }
    solve_friction(bodies, points, f);
  }
}

void resolve_impacts(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                     std::span<const FrictionPatch> patches, std::span<const double> allowed,
                     double threshold) {
  NormalBlock block;
  std::vector<std::uint32_t> rows;
  std::vector<double> least, impulses;
  // The bodies an impact moved in the last round (every body before the first): only their
  // manifolds can approach anew.
  std::vector<char> moved(bodies.size(), 1), moving(bodies.size(), 0);
  const int most_rounds = kImpactRounds + 2 * static_cast<int>(patches.size());
  for (int round = 0; round < most_rounds; ++round) {
    bool any = false;
    for (const FrictionPatch& f : patches) {
      if (f.count == 0 || points[f.first].restitution <= 0.0) continue;
      if (!moved[f.a] && (f.b == kStatic || !moved[f.b])) continue;
      rows.clear();
      least.clear();
      bool impact = false;
      for (std::uint32_t i = f.first; i < f.first + f.count; ++i) {
        const ContactConstraint& c = points[i];
        const double speed = relative_speed(c.normal, bodies[c.a], second(bodies, c));
        if (speed + allowed[i] >= 0.0) continue;  // apart at the (sub-)step's end, or leaving
        rows.push_back(i);
        least.push_back(-c.restitution * speed);
        impact = impact || speed < -threshold;
      }
      if (!impact) continue;
      block.build(bodies, points, rows);
      impulses.assign(rows.size(), 0.0);
      if (!block.solve(bodies, points, least, impulses)) continue;
      for (std::size_t k = 0; k < rows.size(); ++k) points[rows[k]].impact_impulse += impulses[k];
      moving[f.a] = 1;
      if (f.b != kStatic) moving[f.b] = 1;
      any = true;
    }
    if (!any) return;
    moved.swap(moving);
    std::fill(moving.begin(), moving.end(), 0);
  }
}

SolverBody SolverBody::from(const BodyState& state, const BodyConstants& constants,
                            const Mat3& rotation) {
  SolverBody out{.velocity = state.velocity(),
                 .angular_velocity = state.angular_velocity(),
                 .inverse_mass = constants.inverse_mass};
  if (constants.isotropic) {  // a scalar tensor in every frame
    out.isotropic = true;
    out.inverse_inertia = Mat3::Identity() * constants.inverse_inertia.x();
    out.inertia = Mat3::Identity() * constants.inertia.x();
  } else {
    out.inverse_inertia = rotation * constants.inverse_inertia.asDiagonal() * rotation.transpose();
    out.inertia = rotation * constants.inertia.asDiagonal() * rotation.transpose();
  }
  return out;
}

Vec3 SolverBody::linear_impulse(const Vec3& velocity_before) const {
  const double mass = inverse_mass > 0.0 ? 1.0 / inverse_mass : 0.0;
  return mass * (velocity - velocity_before);
}

Vec3 SolverBody::angular_impulse(const Vec3& angular_velocity_before) const {
  return inertia * (angular_velocity - angular_velocity_before);
}

double SolverBody::kinetic_energy() const {
  const double mass = inverse_mass > 0.0 ? 1.0 / inverse_mass : 0.0;
  return 0.5 * mass * velocity.squaredNorm() +
         0.5 * angular_velocity.dot(inertia * angular_velocity);
}

void tangent_basis(const Vec3& normal, Vec3 (&out)[2]) {
  int least = 0;
  for (int axis = 1; axis < 3; ++axis) {
    if (std::abs(normal[axis]) < std::abs(normal[least])) least = axis;
  }
  out[0] = normal.cross(Vec3::Unit(least)).normalized();
  out[1] = normal.cross(out[0]);
}

namespace {

// One pass over the joints' rows: each row's rate to 0. Returns the largest change of an
// impulse (N s).
double joint_pass(std::span<SolverBody> bodies, std::span<JointConstraint> joints) {
  double change = 0.0;
  for (JointConstraint& row : joints) {
    SolverBody* b = row.b == kStatic ? nullptr : &bodies[row.b];
    const double delta = -row.direction.mass * relative_speed(row.direction, bodies[row.a], b);
    row.impulse += delta;
    push(row.direction, bodies[row.a], b, delta);
    change = std::max(change, std::abs(delta));
  }
  return change;
}

}  // namespace

void solve_contacts(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                    std::span<FrictionPatch> patches, const SolveSettings& settings,
                    std::span<JointConstraint> joints) {
  // Which points may bounce is known before the solve; the energy guard needs the energy then.
  // With the normal rows as one block the impacts come first, at once (resolve_impacts).
  const auto may_bounce = [&](const ContactConstraint& c) {
    return c.restitution > 0.0 && c.approach_speed < -settings.restitution_threshold;
  };
  const bool some_may_bounce =
      !settings.block && std::any_of(points.begin(), points.end(), may_bounce);
  const double energy_before = some_may_bounce ? total_kinetic_energy(bodies) : 0.0;

  if (settings.block) {  // the impacts, from the velocities before the warm start's guess
    std::vector<double> allowed(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) allowed[i] = points[i].speculative_speed;
    resolve_impacts(bodies, points, patches, allowed, settings.restitution_threshold);
  }
  if (settings.warm_start) {
    for (const ContactConstraint& c : points) {
      push(c.normal, bodies[c.a], second(bodies, c), c.normal_impulse);
    }
    for (const FrictionPatch& f : patches) {
      if (!f.keeps_friction) continue;
      SolverBody& a = bodies[f.a];
      SolverBody* b = f.b == kStatic ? nullptr : &bodies[f.b];
      for (int k = 0; k < 2; ++k) push(f.tangent[k], a, b, f.tangent_impulse[k]);
      push(f.twist, a, b, f.twist_impulse);
    }
  }
  std::optional<BlockRows> block;  // made only where it is used: a body alone pays nothing
  if (settings.block) {
    block.emplace();
    if (!block->build(bodies, points, patches)) block.reset();
  }
  for (int pass = 0; pass < settings.iterations; ++pass) {
    double joint_change = 0.0, largest_joint = 0.0;
    if (!joints.empty()) {
      joint_change = joint_pass(bodies, joints);
      for (const JointConstraint& row : joints) {
        largest_joint = std::max(largest_joint, std::abs(row.impulse));
      }
    }
    const double change = block ? block_pass(bodies, points, patches, *block)
                                : inelastic_pass(bodies, points, patches);
    if (std::max(change, joint_change) <=
        settings.tolerance * std::max(largest_normal_impulse(points), largest_joint)) {
      break;
    }
  }

  // The bounce, from the velocities the inelastic solve left (Poisson-like: compression first,
  // then restitution), only where the point approached fast enough and was pushed.
  if (!some_may_bounce) return;
  std::vector<double> bouncing(points.size(), 0.0);
  bool any = false;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (may_bounce(points[i]) && points[i].normal_impulse > 0.0) {
      bouncing[i] = 1.0;
      any = true;
    }
  }
  if (any) bounce_points(bodies, points, bouncing, settings.iterations, energy_before);
}

}  // namespace tumble::physics
