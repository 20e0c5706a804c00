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

// Whether the box's bounding sphere at `position` (m, world) comes within `margin` (m) of any
// plane: one dot product per plane, and the whole test for a body that touches nothing.
bool near_any(const Vec3& position, const Vec3& half_size, const std::vector<Plane>& planes,
              double margin) {
  const double reach = half_size.norm() + margin;
  return std::any_of(planes.begin(), planes.end(),
                     [&](const Plane& plane) { return separation(plane, position) <= reach; });
}

// Into `out`, one per plane: the corner separations of the box at (rotation, position), or +∞
// for every corner of a plane that the box's bounding sphere is further from than `margin` (m).
// Returns the lowest separation.
double corner_separations(const Mat3& rotation, const Vec3& position, const Vec3& half_size,
                          const std::vector<Plane>& planes, double margin,
                          std::vector<CornerSeparations>& out) {
  out.resize(planes.size());
  const double reach = half_size.norm() + margin;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (separation(planes[p], position) > reach) {
      out[p].fill(std::numeric_limits<double>::infinity());
      continue;
    }
    out[p] = corner_separations(rotation, position, half_size, planes[p]);
    lowest = std::min(lowest, *std::min_element(out[p].begin(), out[p].end()));
  }
  return lowest;
}

double lowest_separation(const BodyState& state, const std::vector<Plane>& planes,
                         const std::vector<ImpactCorner>& corners) {
  const Mat3 rotation = state.rotation();
  double lowest = std::numeric_limits<double>::infinity();
  for (const ImpactCorner& c : corners) {
    lowest =
        std::min(lowest, separation(planes[c.plane], rotation * c.body_point + state.position()));
  }
  return lowest;
}

// Into `out`: the corners inside a plane at the end of the step (`end`, the separations there)
// that were apart from it at `start` (by more than kTouchingDistance).
void find_impact_corners(const BodyState& start, const std::vector<CornerSeparations>& end,
                         const Vec3& half_size, const std::vector<Plane>& planes,
                         std::vector<ImpactCorner>& out) {
  out.clear();
  Mat3 start_rotation;
  bool rotated = false;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (!(*std::min_element(end[p].begin(), end[p].end()) < 0.0)) continue;
    if (!rotated) {
      start_rotation = start.rotation();
      rotated = true;
    }
    const CornerSeparations before =
        corner_separations(start_rotation, start.position(), half_size, planes[p]);
    for (int feature = 0; feature < 8; ++feature) {
      const auto f = static_cast<std::size_t>(feature);
      if (end[p][f] < 0.0 && before[f] > kTouchingDistance) {
        out.push_back({p, corner(half_size, feature)});
      }
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
// `margin`, m, from the state's corner separations) and a constraint for each of its points,
// pointing back at it for the impulses.
void find_constraints(const BodyModel& model, const Mat3& rotation, const SolverBody& body,
                      const std::vector<Plane>& planes,
                      const std::vector<CornerSeparations>& separations, double margin,
                      PlaneContacts& contacts) {
  contacts.found.resize(planes.size());
  contacts.points.clear();
  for (std::size_t p = 0; p < planes.size(); ++p) {
    Manifold& manifold = contacts.found[p];
    manifold = box_plane_manifold(separations[p], model.half_size, margin);
    if (manifold.count == 0) continue;
    const Plane& plane = planes[p];
    const Material material = combine(model.material, plane.material);
    Vec3 tangents[2];
    tangent_basis(plane.normal, tangents);
    for (int i = 0; i < manifold.count; ++i) {
      ContactPoint& point = manifold.points[static_cast<std::size_t>(i)];
      contacts.points.push_back(
          make_constraint(0, body, rotation * point.body_point, plane.normal, tangents, material));
      contacts.points.back().source = &point.impulses;
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
  const Mat3 rotation = at.rotation();
  corner_separations(rotation, at.position(), model.half_size, planes, kTouchingDistance,
                     contacts.separations);
  SolverBody bodies[1] = {SolverBody::from(at, model.constants, rotation)};
  find_constraints(model, rotation, bodies[0], planes, contacts.separations, kTouchingDistance,
                   contacts);
  // An impact is solved to convergence: its bounce decides the energy of everything after it.
  solve_contacts(bodies, contacts.points,
                 {.iterations = 100,
                  .restitution_threshold = settings.restitution_threshold,
                  .warm_start = false});
  return with_impulses(at, bodies[0], model.constants);
}

// Rotates q by the rotation vector `angle` (rad, world frame): exp(angle / 2) q.
Quat rotated(const Quat& q, const Vec3& angle) {
  const double squared = angle.squaredNorm();
  // exp(angle / 2) = (cos(θ/2), sin(θ/2)/θ angle); below 1e-4 rad the Taylor terms kept are exact
  // to rounding (the next ones are below θ⁴/384 < 3e-19), and a resting body turns by ~1e-17.
  if (squared < 1e-8) {
    const Quat turn(1.0 - squared / 8.0, 0.0, 0.0, 0.0);
    Quat out = turn;
    out.vec() = (0.5 - squared / 48.0) * angle;
    return out * q;
  }
  const double size = std::sqrt(squared);
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

// The free step's end `free`, whose rotation is `rotation` and corner separations are
// contacts.separations, with its resting and sliding contacts solved.
BodyState resolve_resting(Integrator integrator, const BodyModel& model, const BodyState& free,
                          const Mat3& rotation, double h, const std::vector<Plane>& planes,
                          const ContactSettings& settings, PlaneContacts& contacts) {
  SolverBody bodies[1] = {SolverBody::from(free, model.constants, rotation)};
  find_constraints(model, rotation, bodies[0], planes, contacts.separations, kTouchingDistance,
                   contacts);
  // Warm start from the last step's impulses of the same corners.
  for (std::size_t p = 0; p < planes.size(); ++p) {
    for (int i = 0; i < contacts.found[p].count; ++i) {
      ContactPoint& now = contacts.found[p].points[static_cast<std::size_t>(i)];
      for (int j = 0; j < contacts.manifolds[p].count; ++j) {
        const ContactPoint& before = contacts.manifolds[p].points[static_cast<std::size_t>(j)];
        if (before.feature != now.feature) continue;
        now.impulses = before.impulses;
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

// Whether a corner of the box at `state` is within kTouchingDistance of a plane; if so, into
// `separations` its corner separations and into `rotation` its rotation matrix.
bool touching(const BodyState& state, const Vec3& half_size, const std::vector<Plane>& planes,
              std::vector<CornerSeparations>& separations, Mat3& rotation) {
  if (!near_any(state.position(), half_size, planes, kTouchingDistance)) return false;
  rotation = state.rotation();
  return corner_separations(rotation, state.position(), half_size, planes, kTouchingDistance,
                            separations) < kTouchingDistance;
}

// The step from `in` at t whose free step `free` (rotation `rotation`, separations in
// contacts.separations) touches a plane: its impacts at their times, then what rests.
BodyState step_in_contact(Integrator integrator, const BodyModel& model, const BodyState& in,
                          double t, double dt, BodyState free, Mat3 rotation,
                          const std::vector<Plane>& planes, const ContactSettings& settings,
                          PlaneContacts& contacts) {
  BodyState state = in;
  double time = t, remaining = dt;
  for (int impacts = 0; impacts < kMaxImpactsPerStep; ++impacts) {
    find_impact_corners(state, contacts.separations, model.half_size, planes,
                        contacts.impact_corners);
    if (contacts.impact_corners.empty()) break;
    const double until =
        time_of_impact(integrator, model, state, time, remaining, planes, contacts.impact_corners);
    const BodyState at = until > 0.0 ? step(integrator, model, state, time, until) : state;
    state = resolve_impact(model, at, planes, settings, contacts);
    time += until;
    remaining -= until;
    free = step(integrator, model, state, time, remaining);
    if (!touching(free, model.half_size, planes, contacts.separations, rotation)) {
      for (Manifold& m : contacts.manifolds) m.count = 0;
      return free;
    }
  }
  return resolve_resting(integrator, model, free, rotation, remaining, planes, settings, contacts);
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
  BodyState out = step(integrator, model, in, t, dt);
  Mat3 rotation;
  if (touching(out, model.half_size, planes, contacts.separations, rotation)) {
    out = step_in_contact(integrator, model, in, t, dt, out, rotation, planes, settings, contacts);
  } else {
    for (Manifold& m : contacts.manifolds) m.count = 0;  // nothing to warm start from
  }
  return out;
}

}  // namespace tumble::physics
