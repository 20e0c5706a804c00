#include "physics/plane_contact_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/contact_island.hpp"
#include "physics/contact_solver.hpp"

namespace tumble::physics {
namespace {

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

// Into `found` (one per plane) the manifold of each plane (its corners closer than `margin`, m,
// from the corner separations), and onto `points` a constraint for each of its points and onto
// `patches` its friction, pointing back at it for the impulses; `body` is the body's index among
// the solver's bodies.
void find_constraints(const BodyModel& model, std::uint32_t body, const Mat3& rotation,
                      const SolverBody& solver_body, const std::vector<Plane>& planes,
                      const std::vector<CornerSeparations>& separations, double margin,
                      std::vector<Manifold>& found, std::vector<ContactConstraint>& points,
                      std::vector<FrictionPatch>& patches) {
  found.resize(planes.size());
  for (std::size_t p = 0; p < planes.size(); ++p) {
    Manifold& manifold = found[p];
    manifold = box_plane_manifold(separations[p], model.half_size, margin);
    if (manifold.count == 0) continue;
    const Plane& plane = planes[p];
    const Material material = combine(model.material, plane.material);
    Vec3 arms[kMaxManifoldPoints];
    const auto first = static_cast<std::uint32_t>(points.size());
    for (int i = 0; i < manifold.count; ++i) {
      ContactPoint& point = manifold.points[static_cast<std::size_t>(i)];
      arms[i] = rotation * point.body_point;
      points.push_back(make_constraint(body, solver_body, arms[i], plane.normal, material));
      points.back().source = &point.impulses;
    }
    const PatchShape shape =
        patch_shape({arms, static_cast<std::size_t>(manifold.count)}, plane.normal);
    patches.push_back(make_patch(body, solver_body, shape.centre_arm, kStatic, nullptr,
                                 Vec3::Zero(), plane.normal, material.friction, shape.twist_arm,
                                 first, static_cast<std::uint32_t>(manifold.count)));
    patches.back().source = &manifold.friction;
  }
}

// The state with the solver's impulses added to its momenta (an instant impulse: pose unchanged).
BodyState with_impulses(const BodyState& state, const SolverBody& body,
                        const BodyConstants& constants) {
  PrimaryState primary = state.primary();
  primary.momentum += body.linear_impulse(state.velocity());
  primary.angular_momentum += body.angular_impulse(state.angular_velocity());
  return BodyState(primary, constants);
}

BodyState resolve_impact(const BodyModel& model, const BodyState& at,
                         const std::vector<Plane>& planes, const ContactSettings& settings,
                         PlaneContacts& contacts) {
  const Mat3 rotation = at.rotation();
  corner_separations(rotation, at.position(), model.half_size, planes, kTouchingDistance,
                     contacts.separations);
  SolverBody bodies[1] = {SolverBody::from(at, model.constants, rotation)};
  contacts.points.clear();
  contacts.patches.clear();
  find_constraints(model, 0, rotation, bodies[0], planes, contacts.separations, kTouchingDistance,
                   contacts.found, contacts.points, contacts.patches);
  // An impact is solved to convergence: its bounce decides the energy of everything after it.
  solve_contacts(bodies, contacts.points, contacts.patches,
                 {.iterations = 100,
                  .restitution_threshold = settings.restitution_threshold,
                  .warm_start = false});
  return with_impulses(at, bodies[0], model.constants);
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

PlaneAdvance advance_among_planes(Integrator integrator, const BodyModel& model,
                                  const BodyState& in, double t, double dt,
                                  const std::vector<Plane>& planes, const ContactSettings& settings,
                                  PlaneContacts& contacts) {
  contacts.manifolds.resize(planes.size());
  PlaneAdvance out{.end = step(integrator, model, in, t, dt), .remaining = dt};
  out.touching = touching(out.end, model.half_size, planes, contacts.separations, out.rotation);
  if (!out.touching) {
    for (Manifold& m : contacts.manifolds) m.count = 0;  // nothing to warm start from
    return out;
  }
  BodyState state = in;
  double time = t;
  for (int impacts = 0; impacts < kMaxImpactsPerStep; ++impacts) {
    find_impact_corners(state, contacts.separations, model.half_size, planes,
                        contacts.impact_corners);
    if (contacts.impact_corners.empty()) break;
    const double until = time_of_impact(integrator, model, state, time, out.remaining, planes,
                                        contacts.impact_corners);
    const BodyState at = until > 0.0 ? step(integrator, model, state, time, until) : state;
    state = resolve_impact(model, at, planes, settings, contacts);
    time += until;
    out.remaining -= until;
    out.end = step(integrator, model, state, time, out.remaining);
    out.touching = touching(out.end, model.half_size, planes, contacts.separations, out.rotation);
    if (!out.touching) {
      for (Manifold& m : contacts.manifolds) m.count = 0;
      return out;
    }
  }
  return out;
}

namespace {

// add_plane_points with the corners closer than `margin` (m) from contacts.separations.
void add_plane_points_within(const BodyModel& model, std::uint32_t body, const Mat3& rotation,
                             const SolverBody& solver_body, const std::vector<Plane>& planes,
                             double margin, PlaneContacts& contacts,
                             std::vector<ContactConstraint>& points,
                             std::vector<FrictionPatch>& patches,
                             std::vector<PositionPoint>& positions) {
  find_constraints(model, body, rotation, solver_body, planes, contacts.separations, margin,
                   contacts.found, points, patches);
  // Warm start from the last step's impulses of the same corners, and of the same plane's
  // friction.
  // (Through local references: the pushes onto `positions` would otherwise have every access to
  // the two manifolds reload them.)
  for (std::size_t p = 0; p < planes.size(); ++p) {
    Manifold& found = contacts.found[p];
    const Manifold& last = contacts.manifolds[p];
    if (found.count > 0 && last.count > 0) found.friction = last.friction;
    const Plane& plane = planes[p];
    for (int i = 0; i < found.count; ++i) {
      ContactPoint& now = found.points[static_cast<std::size_t>(i)];
      for (int j = 0; j < last.count; ++j) {
        const ContactPoint& before = last.points[static_cast<std::size_t>(j)];
        if (before.feature == now.feature) now.impulses = before.impulses;
      }
      positions.push_back(
          {.a = body, .anchor_a = now.body_point, .normal = plane.normal, .base = -plane.offset});
    }
  }
  // The points' sources stay where they are: swapping vectors keeps their buffers.
  contacts.manifolds.swap(contacts.found);
}

}  // namespace

void add_plane_points(const BodyModel& model, std::uint32_t body, const Mat3& rotation,
                      const SolverBody& solver_body, const std::vector<Plane>& planes,
                      PlaneContacts& contacts, std::vector<ContactConstraint>& points,
                      std::vector<FrictionPatch>& patches, std::vector<PositionPoint>& positions) {
  add_plane_points_within(model, body, rotation, solver_body, planes, kTouchingDistance, contacts,
                          points, patches, positions);
}

void add_speculative_plane_points(const BodyModel& model, std::uint32_t body,
                                  const BodyState& start, const Mat3& rotation, double margin,
                                  const SolverBody& solver_body, const std::vector<Plane>& planes,
                                  PlaneContacts& contacts, std::vector<ContactConstraint>& points,
                                  std::vector<FrictionPatch>& patches,
                                  std::vector<PositionPoint>& positions) {
  contacts.manifolds.resize(planes.size());
  if (!near_any(start.position(), model.half_size, planes, margin)) {
    for (Manifold& m : contacts.manifolds) m.count = 0;
    return;
  }
  corner_separations(rotation, start.position(), model.half_size, planes, margin,
                     contacts.separations);
  add_plane_points_within(model, body, rotation, solver_body, planes, margin, contacts, points,
                          patches, positions);
}

BodyState rest_on_planes(Integrator integrator, const BodyModel& model, const PlaneAdvance& advance,
                         const std::vector<Plane>& planes, const ContactSettings& settings,
                         PlaneContacts& contacts) {
  const IslandBody body{.model = &model,
                        .end = advance.end,
                        .rotation = advance.rotation,
                        .weight = impulse_position_weight(integrator, advance.remaining)};
  SolverBody solver[1] = {SolverBody::from(body.end, model.constants, body.rotation)};
  contacts.points.clear();
  contacts.patches.clear();
  contacts.positions.clear();
  add_plane_points(model, 0, body.rotation, solver[0], planes, contacts, contacts.points,
                   contacts.patches, contacts.positions);
  BodyState out;
  resolve_island({&body, 1}, solver, contacts.points, contacts.patches, contacts.positions,
                 settings, contacts.poses, {&out, 1});
  return out;
}

BodyState step_with_planes(Integrator integrator, const BodyModel& model, const BodyState& in,
                           double t, double dt, const std::vector<Plane>& planes,
                           const ContactSettings& settings, PlaneContacts& contacts) {
  PlaneAdvance advance =
      advance_among_planes(integrator, model, in, t, dt, planes, settings, contacts);
  if (!advance.touching) return std::move(advance.end);
  return rest_on_planes(integrator, model, advance, planes, settings, contacts);
}

}  // namespace tumble::physics
