#include "physics/plane_contact_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/contact_rows.hpp"

namespace tumble::physics {
namespace {

// Whether the shape's bounding sphere at `position` (m, world) comes within `margin` (m) of any
// plane: one dot product per plane, and the whole test for a body that touches nothing.
bool near_any(const Vec3& position, const Shape& shape, std::span<const Plane> planes,
              double margin) {
  const double reach = bounding_radius(shape) + margin;
  return std::any_of(planes.begin(), planes.end(),
                     [&](const Plane& plane) { return separation(plane, position) <= reach; });
}

// Into `out`, one per plane: the separations of the shape's points at `pose`, or +∞ for every
// point of a plane that the shape's bounding sphere is further from than `margin` (m). Returns the
// lowest separation.
double plane_separations(const PoseRef& pose, const Shape& shape, std::span<const Plane> planes,
                         double margin, std::vector<CornerSeparations>& out) {
  const Vec3& position = pose.position;
  out.resize(planes.size());
  const double reach = bounding_radius(shape) + margin;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (separation(planes[p], position) > reach) {
      out[p].fill(std::numeric_limits<double>::infinity());
      continue;
    }
    out[p] = plane_separations(shape, pose.rotation, position, planes[p]);
    lowest = std::min(lowest, *std::min_element(out[p].begin(), out[p].end()));
  }
  return lowest;
}

double lowest_separation(const BodyState& state, std::span<const Plane> planes,
                         const std::vector<ImpactCorner>& corners) {
  const Mat3 rotation = state.rotation();
  double lowest = std::numeric_limits<double>::infinity();
  for (const ImpactCorner& c : corners) {
    lowest = std::min(
        lowest, separation(planes[c.plane], rotation * c.body_point + state.position()) - c.radius);
  }
  return lowest;
}

// Into `out`: the shape's points inside a plane at the end of the step (`end`, the separations
// there) that were apart from it at `start` (by more than kTouchingDistance).
void find_impact_corners(const BodyState& start, const std::vector<CornerSeparations>& end,
                         const Shape& shape, std::span<const Plane> planes,
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
        plane_separations(shape, start_rotation, start.position(), planes[p]);
    for (int feature = 0; feature < 8; ++feature) {
      const auto f = static_cast<std::size_t>(feature);
      if (end[p][f] < 0.0 && before[f] > kTouchingDistance) {
        const RoundedPoint point = plane_point(shape, feature, start_rotation, planes[p].normal);
        out.push_back({.plane = p, .body_point = point.core, .radius = point.radius});
      }
    }
  }
}

// The time (s, in (0, h]) at which the first candidate corner reaches its plane along the
// integrator's motion from `start`, approached from the outside: Illinois regula falsi on the
// lowest separation, which is positive at 0 and negative at h. The answer is a time at which the
// corners are still outside, by at most a small fraction of kTouchingDistance.
double time_of_impact(const StepContext& context, const BodyModel& model, const BodyState& start,
                      double t, double h) {
  const Integrator integrator = context.integrator;
  const std::span<const Plane> planes = context.planes;
  const std::vector<ImpactCorner>& corners = context.scratch.impact_corners;
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

// Whether the body at `at`, where a corner reaches a plane, is already more than half its
// thinnest side deep in that plane: then the corner came through the body, not from outside,
// and is no impact. A load too heavy for one free step does this: a 1 kg unit cube resting on
// the floor and pushed down by 1e4 N falls 1.4 m through it in a free step of 1/60 s, and its
// top corners reach the floor from below 1 m into it. The resting solve at the step's end takes
// such a step back whole (its impulse balances the step's load, impulse_position_weight); an
// impact there found corners at both faces and left the cube 0.3 m inside. A box tipping onto a
// face still has its pivot within a free fall's step of the surface (1.4 mm at 1/60 s).
bool passed_through(const BodyState& at, const Shape& shape, std::span<const Plane> planes,
                    const std::vector<ImpactCorner>& corners) {
  const Mat3 rotation = at.rotation();
  const double thinnest = shape.half_size.minCoeff();
  for (const ImpactCorner& c : corners) {
    const CornerSeparations there =
        plane_separations(shape, rotation, at.position(), planes[c.plane]);
    if (*std::min_element(there.begin(), there.end()) < -thinnest) return true;
  }
  return false;
}

// The state with the solver's impulses added to its momenta (an instant impulse: pose unchanged).
BodyState with_impulses(const BodyState& state, const SolverBody& body,
                        const BodyConstants& constants) {
  PrimaryState primary = state.primary();
  primary.momentum += body.linear_impulse(state.velocity());
  primary.angular_momentum += body.angular_impulse(state.angular_velocity());
  return BodyState(primary, constants);
}

// Below this approach speed (m/s) an impact on a plane is a resting contact made again, not a
// landing (SlowImpacts): twice what the body's constant load adds in a step (a corner of a rod
// set rocking falls back at 0.07 m/s; a box landing in a pour comes at metres a second), and
// never one that bounces. 0 for a body that is not passive (nothing is deferred).
double slow_impact_speed(const StepContext& context, const BodyModel& model) {
  Vec3 force;
  if (!constant_force(model, force)) return 0.0;
  return std::min(context.settings.restitution_threshold,
                  2.0 * force.norm() * model.constants.inverse_mass * context.dt);
}

// The fastest any of the corners reaches its plane at `at` (m/s).
double fastest_approach(const BodyState& at, std::span<const Plane> planes,
                        const std::vector<ImpactCorner>& corners) {
  const Mat3 rotation = at.rotation();
  double fastest = 0.0;  // m/s
  for (const ImpactCorner& c : corners) {
    const Vec3& n = planes[c.plane].normal;
    const Vec3 point = rotation * c.body_point + at.position() - c.radius * n;
    fastest = std::max(fastest, -n.dot(point_velocity(at, point)));
  }
  return fastest;
}

// The impact of the body at `at` with the planes it touches there, as an instant impulse.
BodyState resolve_impact(const StepContext& context, std::uint32_t body, const BodyState& at) {
  const BodyModel& model = context.models[body];
  const Mat3 rotation = at.rotation();
  std::vector<CornerSeparations>& separations = context.scratch.separations[body];
  plane_separations({at.position(), rotation}, model.shape, context.planes, kTouchingDistance,
                    separations);
  ContactRows& rows = context.scratch.rows;
  rows.clear();
  rows.bodies.push_back(SolverBody::from(at, model.constants, rotation));
  for (std::uint32_t p = 0; p < context.planes.size(); ++p) {
    const Plane& plane = context.planes[p];
    const Manifold found =
        plane_manifold(model.shape, separations[p], rotation, plane.normal, kTouchingDistance);
    if (found.count == 0) continue;
    append_rows({.manifold = found,
                 .plane = plane,
                 .material = combine(model.material, plane.material),
                 .body = 0,
                 .rotation = rotation,
                 .source = {.owner = body, .plane = p},
                 .keeps_friction = false,
                 .rounding = rounding(model.shape)},
                rows);
  }
  // An impact is solved to convergence: its bounce decides the energy of everything after it.
  // Its impulses go nowhere: the rest of the step finds its own.
  solve_contacts(rows.bodies, rows.points, rows.patches,
                 {.iterations = 100,
                  .restitution_threshold = context.settings.restitution_threshold,
                  .warm_start = false});
  return with_impulses(at, rows.bodies[0], model.constants);
}

// Whether a point of the shape at `state` is within kTouchingDistance of a plane; if so, into
// `separations` its points' separations and into `rotation` its rotation matrix.
bool touching(const BodyState& state, const Shape& shape, std::span<const Plane> planes,
              std::vector<CornerSeparations>& separations, Mat3& rotation) {
  if (!near_any(state.position(), shape, planes, kTouchingDistance)) return false;
  rotation = state.rotation();
  return plane_separations({state.position(), rotation}, shape, planes, kTouchingDistance,
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

void take_free_step(const StepContext& context, std::uint32_t body, BodyState end) {
  PlaneAdvance& out = context.scratch.advances[body];
  std::vector<Manifold>& manifolds = context.memory.planes[body];
  manifolds.resize(context.planes.size());
  out.end = std::move(end);
  out.remaining = context.dt;
  out.slow_impact = false;
  out.touching =
      !context.planes.empty() && touching(out.end, context.models[body].shape, context.planes,
                                          context.scratch.separations[body], out.rotation);
  if (out.touching) return;
  for (Manifold& m : manifolds) m.count = 0;  // nothing to warm start from
}

void advance_among_planes(const StepContext& context, std::uint32_t body, SlowImpacts slow) {
  const Integrator integrator = context.integrator;
  const BodyModel& model = context.models[body];
  const std::span<const Plane> planes = context.planes;
  std::vector<Manifold>& manifolds = context.memory.planes[body];
  std::vector<CornerSeparations>& separations = context.scratch.separations[body];
  manifolds.resize(planes.size());
  PlaneAdvance& out = context.scratch.advances[body];
  out.end = step(integrator, model, context.in[body], context.t, context.dt);
  out.remaining = context.dt;
  out.slow_impact = false;
  out.touching = touching(out.end, model.shape, planes, separations, out.rotation);
  if (!out.touching) {
    for (Manifold& m : manifolds) m.count = 0;  // nothing to warm start from
    return;
  }
  BodyState state = context.in[body];
  double time = context.t;
  double slow_speed = -1.0;  // m/s, found at the first impact (a resting body has none)
  for (int impacts = 0; impacts < kMaxImpactsPerStep; ++impacts) {
    find_impact_corners(state, separations, model.shape, planes, context.scratch.impact_corners);
    if (context.scratch.impact_corners.empty()) break;
    const double until = time_of_impact(context, model, state, time, out.remaining);
    const BodyState at = until > 0.0 ? step(integrator, model, state, time, until) : state;
    if (passed_through(at, model.shape, planes, context.scratch.impact_corners)) break;
    if (slow_speed < 0.0) slow_speed = slow_impact_speed(context, model);
    if (fastest_approach(at, planes, context.scratch.impact_corners) < slow_speed) {
      // In the solve: the end of the free step stands, touching, and the island takes it.
      if (slow == SlowImpacts::in_the_solve) break;
      out.slow_impact = true;
    }
    state = resolve_impact(context, body, at);
    time += until;
    out.remaining -= until;
    out.end = step(integrator, model, state, time, out.remaining);
    out.touching = touching(out.end, model.shape, planes, separations, out.rotation);
    if (!out.touching) {
      for (Manifold& m : manifolds) m.count = 0;
      return;
    }
  }
}

void append_plane_rows(const StepContext& context, const BodyInRows& body, double margin) {
  const BodyModel& model = context.models[body.body];
  std::vector<Manifold>& manifolds = context.memory.planes[body.body];
  const std::vector<CornerSeparations>& separations = context.scratch.separations[body.body];
  for (std::uint32_t p = 0; p < context.planes.size(); ++p) {
    const Plane& plane = context.planes[p];
    Manifold& manifold = manifolds[p];
    Manifold found =
        plane_manifold(model.shape, separations[p], body.rotation, plane.normal, margin);
    // Warm start from the last step's impulses of the same corners, and of the same plane's
    // friction.
    if (found.count > 0 && manifold.count > 0) {
      found.friction = manifold.friction;
      found.patch = manifold.patch;
    }
    keep_impulses(found, manifold);
    manifold = found;
    if (manifold.count == 0) continue;
    append_rows({.manifold = manifold,
                 .plane = plane,
                 .material = combine(model.material, plane.material),
                 .body = body.solver,
                 .rotation = body.rotation,
                 .source = {.owner = body.body, .plane = p},
                 .keeps_friction = true,
                 .rounding = rounding(model.shape)},
                context.scratch.rows);
  }
}

void append_speculative_plane_rows(const StepContext& context, const BodyInRows& body,
                                   double margin) {
  const BodyModel& model = context.models[body.body];
  const BodyState& start = context.in[body.body];
  std::vector<Manifold>& manifolds = context.memory.planes[body.body];
  manifolds.resize(context.planes.size());
  if (!near_any(start.position(), model.shape, context.planes, margin)) {
    for (Manifold& m : manifolds) m.count = 0;
    return;
  }
  plane_separations({start.position(), body.rotation}, model.shape, context.planes, margin,
                    context.scratch.separations[body.body]);
  append_plane_rows(context, body, margin);
}

BodyState rest_on_planes(const StepContext& context, std::uint32_t body) {
  const PlaneAdvance& advance = context.scratch.advances[body];
  const BodyModel& model = context.models[body];
  const IslandBody island{
      .model = &model,
      .start = holds_energy(context.integrator) && !held_by_joints(context, body)
                   ? &context.in[body]
                   : nullptr,
      .end = advance.end,
      .rotation = advance.rotation,
      .weight = impulse_position_weight(context.integrator, advance.remaining)};
  ContactRows& rows = context.scratch.rows;
  rows.clear();
  rows.bodies.push_back(SolverBody::from(island.end, model.constants, island.rotation));
  append_plane_rows(context, {.body = body, .solver = 0, .rotation = island.rotation},
                    kTouchingDistance);
  BodyState out;
  resolve_island({&island, 1}, rows, context.settings, {&out, 1});
  store_impulses(rows, context.memory.planes, {});
  return out;
}

bool step_among_planes(const StepContext& context, std::uint32_t body) {
  advance_among_planes(context, body, SlowImpacts::at_their_time);
  PlaneAdvance& advance = context.scratch.advances[body];
  context.out[body] = advance.touching ? rest_on_planes(context, body) : std::move(advance.end);
  return advance.touching;
}

}  // namespace tumble::physics
