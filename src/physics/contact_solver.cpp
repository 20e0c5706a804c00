#include "physics/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tumble::physics {
namespace {

// Two unit vectors spanning the plane normal to n, from the world axis least along n (so the
// same normal always gives the same basis).
void tangent_basis(const Vec3& n, Vec3 (&out)[2]) {
  int least = 0;
  for (int axis = 1; axis < 3; ++axis) {
    if (std::abs(n[axis]) < std::abs(n[least])) least = axis;
  }
  out[0] = n.cross(Vec3::Unit(least)).normalized();
  out[1] = n.cross(out[0]);
}

// The direction `along` (unit, world) of a point at `arm` (m, world, from the centre) of the body.
ImpulseDirection direction(const SolverBody& body, const Vec3& arm, const Vec3& along) {
  ImpulseDirection out{.linear = along, .moment = arm.cross(along)};
  out.turn = body.inverse_inertia * out.moment;
  const double inverse = body.inverse_mass + out.moment.dot(out.turn);
  out.mass = inverse > 0.0 ? 1.0 / inverse : 0.0;
  return out;
}

// One pass of friction then normal impulses over every point (normal last: it matters most).
// Returns the largest change of an accumulated impulse (N s).
double inelastic_pass(std::span<SolverBody> bodies, std::span<ContactConstraint> points) {
  double largest_change = 0.0;
  for (ContactConstraint& c : points) {
    SolverBody& body = bodies[c.body];
    // Circular cone: both tangent impulses together within μ λ_n, so no direction is favoured.
    double wanted[2];
    for (int k = 0; k < 2; ++k) {
      wanted[k] = c.tangent_impulse[k] - c.tangent[k].mass * c.tangent[k].speed(body);
    }
    const double limit = c.friction * c.normal_impulse;
    const double size_squared = wanted[0] * wanted[0] + wanted[1] * wanted[1];
    const double scale = size_squared > limit * limit ? limit / std::sqrt(size_squared) : 1.0;
    for (int k = 0; k < 2; ++k) {
      const double change = wanted[k] * scale - c.tangent_impulse[k];
      c.tangent[k].push(body, change);
      c.tangent_impulse[k] += change;
      largest_change = std::max(largest_change, std::abs(change));
    }
    const double accumulated =
        std::max(0.0, c.normal_impulse - c.normal.mass * c.normal.speed(body));
    const double change = accumulated - c.normal_impulse;
    c.normal_impulse = accumulated;
    c.normal.push(body, change);
    largest_change = std::max(largest_change, std::abs(change));
  }
  return largest_change;
}

// One pass driving each bouncing point's normal speed up to -e × its approach speed, adding to
// (never taking from below zero) the impulse it already has.
double bounce_pass(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                   const std::vector<double>& bounce_impulse, std::vector<double>& accumulated) {
  double largest_change = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ContactConstraint& c = points[i];
    if (bounce_impulse[i] == 0.0) continue;  // marks a point that does not bounce
    SolverBody& body = bodies[c.body];
    const double target = -c.restitution * c.approach_speed;
    const double total =
        std::max(0.0, accumulated[i] - c.normal.mass * (c.normal.speed(body) - target));
    const double change = total - accumulated[i];
    accumulated[i] = total;
    c.normal.push(body, change);
    largest_change = std::max(largest_change, std::abs(change));
  }
  return largest_change;
}

double largest_normal_impulse(std::span<const ContactConstraint> points) {
  double largest = 0.0;
  for (const ContactConstraint& c : points) largest = std::max(largest, c.normal_impulse);
  return largest;
}

// Kinetic energy of (v + s dv, ω + s dω) is a + b s + c s²: the largest s in [0, 1] at which it is
// at most `bound`, given that it is at s = 0.
double largest_step_within(const SolverBody& at_zero, const SolverBody& at_one, double bound) {
  const Vec3 dv = at_one.velocity - at_zero.velocity;
  const Vec3 dw = at_one.angular_velocity - at_zero.angular_velocity;
  const Mat3& inertia = at_zero.inertia;
  const double mass = at_zero.inverse_mass > 0.0 ? 1.0 / at_zero.inverse_mass : 0.0;
  const double a = at_zero.kinetic_energy() - bound;  // <= 0
  const double b = mass * at_zero.velocity.dot(dv) + at_zero.angular_velocity.dot(inertia * dw);
  const double c = 0.5 * (mass * dv.squaredNorm() + dw.dot(inertia * dw));
  if (c <= 0.0) return 0.0;
  // The positive root of c s² + b s + a = 0 (a <= 0 so it exists), written without cancellation.
  const double root = std::sqrt(std::max(0.0, b * b - 4.0 * c * a));
  const double s = b >= 0.0 ? (-2.0 * a) / (b + root) : (root - b) / (2.0 * c);
  return std::clamp(s, 0.0, 1.0);
}

}  // namespace

SolverBody SolverBody::from(const BodyState& state, const BodyConstants& constants) {
  const Mat3 rotation = state.orientation().toRotationMatrix();
  return {
      .velocity = state.velocity(),
      .angular_velocity = state.angular_velocity(),
      .inverse_mass = constants.inverse_mass,
      .inverse_inertia = rotation * constants.inverse_inertia.asDiagonal() * rotation.transpose(),
      .inertia = rotation * constants.inertia.asDiagonal() * rotation.transpose()};
}

double SolverBody::kinetic_energy() const {
  const double mass = inverse_mass > 0.0 ? 1.0 / inverse_mass : 0.0;
  return 0.5 * mass * velocity.squaredNorm() +
         0.5 * angular_velocity.dot(inertia * angular_velocity);
}

ContactConstraint make_constraint(std::size_t body_index, const SolverBody& body, const Vec3& arm,
                                  const Vec3& normal, const Material& material) {
  ContactConstraint c;
  c.body = body_index;
  c.normal = direction(body, arm, normal);
  Vec3 tangents[2];
  tangent_basis(normal, tangents);
  for (int k = 0; k < 2; ++k) c.tangent[k] = direction(body, arm, tangents[k]);
  c.friction = material.friction;
  c.restitution = material.restitution;
  c.approach_speed = c.normal.speed(body);
  return c;
}

void solve_contacts(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                    const SolveSettings& settings) {
  // Which points may bounce is known before the solve; the energy guard needs the energies then.
  const auto may_bounce = [&](const ContactConstraint& c) {
    return c.restitution > 0.0 && c.approach_speed < -settings.restitution_threshold;
  };
  std::vector<double> energy_before;
  if (std::any_of(points.begin(), points.end(), may_bounce)) {
    for (const SolverBody& body : bodies) energy_before.push_back(body.kinetic_energy());
  }

  if (settings.warm_start) {
    for (ContactConstraint& c : points) {
      if (!c.source) continue;
      c.normal_impulse = c.source->normal_impulse;
      c.normal.push(bodies[c.body], c.normal_impulse);
      for (int k = 0; k < 2; ++k) {
        c.tangent_impulse[k] = c.source->tangent_impulse.dot(c.tangent[k].linear);
        c.tangent[k].push(bodies[c.body], c.tangent_impulse[k]);
      }
    }
  }
  for (int pass = 0; pass < settings.iterations; ++pass) {
    const double change = inelastic_pass(bodies, points);
    if (change <= settings.tolerance * largest_normal_impulse(points)) break;
  }
  for (ContactConstraint& c : points) {
    if (!c.source) continue;
    c.source->normal_impulse = c.normal_impulse;
    c.source->tangent_impulse =
        c.tangent_impulse[0] * c.tangent[0].linear + c.tangent_impulse[1] * c.tangent[1].linear;
  }

  // The bounce, from the velocities the inelastic solve left (Poisson-like: compression first,
  // then restitution), only where the point approached fast enough and was pushed.
  if (energy_before.empty()) return;
  std::vector<double> bouncing(points.size(), 0.0);
  bool any = false;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (may_bounce(points[i]) && points[i].normal_impulse > 0.0) {
      bouncing[i] = 1.0;
      any = true;
    }
  }
  if (!any) return;
  const std::vector<SolverBody> inelastic(bodies.begin(), bodies.end());
  std::vector<double> accumulated(points.size(), 0.0);
  for (int pass = 0; pass < settings.iterations; ++pass) {
    const double change = bounce_pass(bodies, points, bouncing, accumulated);
    double largest = 0.0;
    for (const double a : accumulated) largest = std::max(largest, a);
    if (change <= settings.tolerance * largest) break;
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].kinetic_energy() <= energy_before[b]) continue;
    const double s = largest_step_within(inelastic[b], bodies[b], energy_before[b]);
    SolverBody& body = bodies[b];
    body.velocity = inelastic[b].velocity + s * (body.velocity - inelastic[b].velocity);
    body.angular_velocity =
        inelastic[b].angular_velocity + s * (body.angular_velocity - inelastic[b].angular_velocity);
    body.linear_impulse =
        inelastic[b].linear_impulse + s * (body.linear_impulse - inelastic[b].linear_impulse);
    body.angular_impulse =
        inelastic[b].angular_impulse + s * (body.angular_impulse - inelastic[b].angular_impulse);
  }
}

}  // namespace tumble::physics
