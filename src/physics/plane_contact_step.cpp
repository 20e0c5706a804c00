#include "physics/plane_contact_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/contact_solver.hpp"

namespace tumble::physics {
namespace {

// Passes of the position projection; each moves the body by what is left inside.
constexpr int kProjectionIterations = 4;
// A resting solve ends when a pass changes no impulse by more than this fraction of the largest:
// the velocity left is then about 1e-7 of what gravity adds in a step, far below what shows.
constexpr double kRestingTolerance = 1e-6;

// A body point in the world through the state's rotation matrix: cheaper than rotating by q.
Vec3 world_point(const BodyState& state, const Vec3& body_point) {
  const Mat4& m = state.derived().body_to_world;
  return m.topLeftCorner<3, 3>() * body_point + m.topRightCorner<3, 1>();
}

// Whether any corner of the box touches (is within kTouchingDistance of, or inside) any plane: a
// bounding-sphere test first, so a body far from every plane costs one dot product per plane.
bool touches_any(const BodyState& state, const Vec3& half_size, const std::vector<Plane>& planes) {
  const double radius = half_size.norm();
  for (const Plane& plane : planes) {
    if (separation(plane, state.position()) > radius + kTouchingDistance) continue;
    if (closest_corner_separation(state, half_size, plane) < kTouchingDistance) return true;
  }
  return false;
}

double lowest_separation(const BodyState& state, const std::vector<Plane>& planes,
                         const std::vector<ImpactCorner>& corners) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const ImpactCorner& c : corners) {
    lowest = std::min(lowest, separation(planes[c.plane], world_point(state, c.body_point)));
  }
  return lowest;
}

// Into `out`: the corners apart from a plane at `start` (by more than kTouchingDistance) and
// inside it at `end`.
void find_impact_corners(const BodyState& start, const BodyState& end, const Vec3& half_size,
                         const std::vector<Plane>& planes, std::vector<ImpactCorner>& out) {
  out.clear();
  const double radius = half_size.norm();
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (separation(planes[p], end.position()) > radius) continue;
    for (int feature = 0; feature < 8; ++feature) {
      const Vec3 body_point = corner(half_size, feature);
      if (separation(planes[p], world_point(end, body_point)) >= 0.0) continue;
      if (separation(planes[p], world_point(start, body_point)) <= kTouchingDistance) continue;
      out.push_back({p, body_point});
    }
  }
}

// The time (s, in (0, h]) at which the first candidate corner reaches its plane along the
// integrator's motion from `start`, approached from the outside: Illinois regula falsi on the
// lowest separation, which is positive at 0 and negative at h. The answer is a time at which the
// corners are still outside, by at most a small fraction of kTouchingDistance.
double time_of_impact(Integrator integrator, const BodyModel& model, const BodyState& start,
                      double t, double h, const std::vector<Plane>& planes,
                      const std::vector<ImpactCorner>& corners) {
  double outside = 0.0, inside = h;
  double outside_gap = lowest_separation(start, planes, corners);
  double inside_gap = lowest_separation(step(integrator, model, start, t, h), planes, corners);
  int kept_side = 0;  // +1 / -1 when the same end moved twice running (Illinois halving)
  for (int iteration = 0; iteration < 60; ++iteration) {
    if (outside_gap <= 0.01 * kTouchingDistance || inside - outside <= 1e-12 * h) break;
    double guess = outside + (inside - outside) * outside_gap / (outside_gap - inside_gap);
    guess =
        std::clamp(guess, outside + 1e-3 * (inside - outside), inside - 1e-3 * (inside - outside));
    const double gap = lowest_separation(step(integrator, model, start, t, guess), planes, corners);
    if (gap >= 0.0) {
      outside = guess;
      outside_gap = gap;
      if (kept_side == 1) inside_gap *= 0.5;
      kept_side = 1;
    } else {
      inside = guess;
      inside_gap = gap;
      if (kept_side == -1) outside_gap *= 0.5;
      kept_side = -1;
    }
  }
  return outside;
}

// Into contacts.found and contacts.points: the manifold of each plane (its corners closer than
// `margin`, m) and a constraint for each of its points, pointing back at it for the impulses.
void find_constraints(const BodyModel& model, const BodyState& state, const SolverBody& body,
                      const std::vector<Plane>& planes, double margin, PlaneContacts& contacts) {
  contacts.found.assign(planes.size(), Manifold{});
  contacts.points.clear();
  const double radius = model.half_size.norm();
  const Mat3 rotation = state.derived().body_to_world.topLeftCorner<3, 3>();
  for (std::size_t p = 0; p < planes.size(); ++p) {
    const Plane& plane = planes[p];
    if (separation(plane, state.position()) > radius + margin) continue;
    Manifold& manifold = contacts.found[p];
    manifold = box_plane_manifold(state, model.half_size, plane, margin);
    const Material material = combine(model.material, plane.material);
    for (int i = 0; i < manifold.count; ++i) {
      ContactPoint& point = manifold.points[static_cast<std::size_t>(i)];
      contacts.points.push_back(
          make_constraint(0, body, rotation * point.body_point, plane.normal, material));
      contacts.points.back().source = &point;
    }
  }
}

// The state with the solver's impulses added to its momenta (an instant impulse: pose unchanged).
BodyState with_impulses(const BodyState& state, const SolverBody& body,
                        const BodyConstants& constants) {
  PrimaryState primary = state.primary();
  primary.momentum += body.linear_impulse;
  primary.angular_momentum += body.angular_impulse;
  return BodyState(primary, constants);
}

BodyState resolve_impact(const BodyModel& model, const BodyState& at,
                         const std::vector<Plane>& planes, const ContactSettings& settings,
                         PlaneContacts& contacts) {
  SolverBody bodies[1] = {SolverBody::from(at, model.constants)};
  find_constraints(model, at, bodies[0], planes, kTouchingDistance, contacts);
  // An impact is solved to convergence: its bounce decides the energy of everything after it.
  solve_contacts(bodies, contacts.points,
                 {.iterations = 100,
                  .restitution_threshold = settings.restitution_threshold,
                  .warm_start = false});
  return with_impulses(at, bodies[0], model.constants);
}

// Rotates q by the rotation vector `angle` (rad, world frame): exp(angle / 2) q.
Quat rotated(const Quat& q, const Vec3& angle) {
  const double size = angle.norm();
  if (size == 0.0) return q;
  return Quat(Eigen::AngleAxisd(size, angle / size)) * q;
}

// Non-linear Gauss-Seidel on the pose: each manifold corner still inside is pushed out to the
// surface along the normal by a position-level impulse through the body's mass and inertia.
// The inverse inertia is the one at the start of the projection: the pose turns by little.
PrimaryState project_out(const BodyModel& model, const Mat3& inverse_inertia, PrimaryState pose,
                         const std::vector<Plane>& planes, const std::vector<Manifold>& manifolds) {
  for (int iteration = 0; iteration < kProjectionIterations; ++iteration) {
    bool moved = false;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      for (int i = 0; i < manifolds[p].count; ++i) {
        const Vec3 arm =
            pose.orientation * manifolds[p].points[static_cast<std::size_t>(i)].body_point;
        const double depth = -separation(planes[p], pose.position + arm);
        if (depth <= 0.0) continue;
        const Vec3& n = planes[p].normal;
        const Vec3 moment = arm.cross(n);
        const Vec3 turn_per_unit = inverse_inertia * moment;
        const double inverse_mass = model.constants.inverse_mass + moment.dot(turn_per_unit);
        const double push = depth / inverse_mass;  // position-level impulse (kg m)
        pose.position += (push * model.constants.inverse_mass) * n;
        pose.orientation = rotated(pose.orientation, push * turn_per_unit).normalized();
        moved = true;
      }
    }
    if (!moved) break;
  }
  return pose;
}

BodyState resolve_resting(Integrator integrator, const BodyModel& model, const BodyState& free,
                          double h, const std::vector<Plane>& planes,
                          const ContactSettings& settings, PlaneContacts& contacts) {
  SolverBody bodies[1] = {SolverBody::from(free, model.constants)};
  find_constraints(model, free, bodies[0], planes, kTouchingDistance, contacts);
  // Warm start from the last step's impulses of the same corners.
  for (std::size_t p = 0; p < planes.size(); ++p) {
    for (int i = 0; i < contacts.found[p].count; ++i) {
      ContactPoint& now = contacts.found[p].points[static_cast<std::size_t>(i)];
      for (int j = 0; j < contacts.manifolds[p].count; ++j) {
        const ContactPoint& before = contacts.manifolds[p].points[static_cast<std::size_t>(j)];
        if (before.feature != now.feature) continue;
        now.normal_impulse = before.normal_impulse;
        now.tangent_impulse = before.tangent_impulse;
      }
    }
  }
  solve_contacts(bodies, contacts.points,
                 {.iterations = kContactIterations,
                  .tolerance = kRestingTolerance,
                  .restitution_threshold = settings.restitution_threshold,
                  .warm_start = true});
  contacts.manifolds.swap(contacts.found);

  const SolverBody& solved = bodies[0];
  const double weight = impulse_position_weight(integrator, h);
  PrimaryState primary = free.primary();
  primary.momentum += solved.linear_impulse;
  primary.angular_momentum += solved.angular_impulse;
  primary.position += weight * (solved.velocity - free.velocity());
  primary.orientation =
      rotated(primary.orientation, weight * (solved.angular_velocity - free.angular_velocity()));
  return BodyState(project_out(model, solved.inverse_inertia, primary, planes, contacts.manifolds),
                   model.constants);
}

}  // namespace

double impulse_position_weight(Integrator integrator, double h) {
  switch (integrator) {
    case Integrator::euler:
      return 0.0;
    case Integrator::symplectic_euler:
      return h;
    case Integrator::rk4:
    case Integrator::splitting:
    case Integrator::splitting4:
      return 0.5 * h;
  }
  return 0.5 * h;
}

BodyState step_with_planes(Integrator integrator, const BodyModel& model, const BodyState& in,
                           double t, double dt, const std::vector<Plane>& planes,
                           const ContactSettings& settings, PlaneContacts& contacts) {
  contacts.manifolds.resize(planes.size());
  BodyState state = in;
  double time = t, remaining = dt;
  for (int impacts = 0;; ++impacts) {
    const BodyState free = step(integrator, model, state, time, remaining);
    if (!touches_any(free, model.half_size, planes)) {
      for (Manifold& m : contacts.manifolds) m.count = 0;  // nothing to warm start from
      return free;
    }
    if (impacts < kMaxImpactsPerStep) {
      find_impact_corners(state, free, model.half_size, planes, contacts.impact_corners);
      if (!contacts.impact_corners.empty()) {
        const double until = time_of_impact(integrator, model, state, time, remaining, planes,
                                            contacts.impact_corners);
        const BodyState at = until > 0.0 ? step(integrator, model, state, time, until) : state;
        state = resolve_impact(model, at, planes, settings, contacts);
        time += until;
        remaining -= until;
        continue;
      }
    }
    return resolve_resting(integrator, model, free, remaining, planes, settings, contacts);
  }
}

}  // namespace tumble::physics
