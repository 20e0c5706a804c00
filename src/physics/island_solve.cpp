#include "physics/island_solve.hpp"

#include <algorithm>
#include <functional>

#include "physics/contact_rows.hpp"

namespace tumble::physics {
namespace {

// Body i's state in a sub-stepped island now: a member's as its sub-steps moved it, a static
// body's where it stands.
const BodyState& substep_state(const StepContext& context, std::uint32_t i) {
  return context.models[i].is_static
             ? context.in[i]
             : context.scratch.substep_bodies[context.scratch.local[i]].state;
}

// The rows of the pair rows.pair, from its manifold, with its bodies at the poses in the
// sub-stepped island's bodies: their start, or a sub-step's.
PairManifoldRows substep_pair_rows(const StepContext& context, const PairRows& rows,
                                   const Material& material, const Mat3& a_rotation,
                                   const Mat3& b_rotation) {
  const PairContact& pair = context.scratch.found[rows.pair];
  const auto [a, b] = pair.bodies;
  const BodyState& a_state = substep_state(context, a);
  const BodyState& b_state = substep_state(context, b);
  return {.manifold = pair.manifold,
          .material = material,
          .a = context.scratch.local[a],
          .b = context.scratch.local[b],
          .a_rotation = a_rotation,
          .b_rotation = b_rotation,
          .a_base = {a_state.position(), a_rotation},
          .b_base = {b_state.position(), b_rotation},
          .speculative_step = 0.0,
          .source = {.owner = rows.pair},
          .keeps_friction = true,
          .a_shape = context.models[a].shape,
          .b_shape = context.models[b].shape};
}

RowSlots slots_of(const PairRows& rows) {
  return {.first = rows.first, .slots = rows.slots, .patch = rows.patch};
}
RowSlots slots_of(const PlaneRows& rows) {
  return {.first = rows.first, .slots = kMaxManifoldPoints, .patch = rows.patch};
}

// Finds a fast pair's manifold again at the bodies' poses now, within the part `left` of the
// step still to come, and rewrites its rows, keeping the sub-step impulses of the features it
// still has (and of its friction, turned to the new tangents).
void refind_pair(const StepContext& context, const PairRows& rows, double left) {
  PairContact& pair = context.scratch.found[rows.pair];
  const auto [a, b] = pair.bodies;
  const BodyModel& model_a = context.models[a];
  const BodyModel& model_b = context.models[b];
  const BodyState& a_state = substep_state(context, a);
  const BodyState& b_state = substep_state(context, b);
  const Mat3 a_rotation = a_state.rotation(), b_rotation = b_state.rotation();
  PairManifold found = pair_manifold(pose_of(a_state, a_rotation, model_a.shape),
                                     pose_of(b_state, b_rotation, model_b.shape),
                                     kTouchingDistance + left * rows.reach, pair.manifold.normal);
  // A point found again keeps its impulse.
  ContactRows& solve = context.scratch.rows;
  const RowSlots at = slots_of(rows);
  CarriedImpulses carried;
  carry_by_feature(found, pair.manifold, at, solve, carried);
  carried.friction = patch_impulses(solve.patches[rows.patch]);
  found.friction = pair.manifold.friction;
  found.patch = pair.manifold.patch;
  pair.manifold = found;
  pair.stamp.valid = false;  // found at a sub-step's poses: not the start's
  const Material material = combine(model_a.material, model_b.material);
  write_rows(substep_pair_rows(context, rows, material, a_rotation, b_rotation), at, solve);
  restore(carried, at, solve);
}

// The rows of a fast island's body against one plane, from its corners within `margin` (m) of it
// at `pose`, into its slots: the body's manifold with that plane becomes the one found here. A
// corner found before keeps its impulses (of the last step; within the step, `within_step`, also
// its sub-step impulse, approach speed and largest push), and the patch its friction.
void write_plane_rows(const StepContext& context, const PlaneRows& rows, const PoseRef& pose,
                      double margin, bool within_step) {
  const Plane& plane = context.planes[rows.plane];
  const BodyModel& model = context.models[rows.body];
  Manifold& manifold = context.memory.planes[rows.body][rows.plane];
  ContactRows& solve = context.scratch.rows;
  const RowSlots at = slots_of(rows);
  Manifold found = plane_manifold(
      model.shape, plane_separations(model.shape, pose.rotation, pose.position, plane),
      pose.rotation, plane.normal, margin);
  found.friction = manifold.friction;
  found.patch = manifold.patch;
  CarriedImpulses carried;
  carry_by_feature(found, manifold, at, solve, carried);
  const FrictionPatch& before = solve.patches[rows.patch];
  if (before.count > 0) carried.friction = patch_impulses(before);
  manifold = found;
  write_rows({.manifold = manifold,
              .plane = plane,
              .material = combine(model.material, plane.material),
              .body = context.scratch.local[rows.body],
              .rotation = pose.rotation,
              .source = {.owner = rows.body, .plane = rows.plane},
              .keeps_friction = true,
              .rounding = rounding(model.shape)},
             at, solve);
  if (within_step) restore(carried, at, solve);
}

// The island's bodies, with the rows its solve fills emptied, and the static bodies its pairs
// touch at kStatic among the rows' bodies (they are none of them: rows against them are one-sided,
// as against a plane).
std::span<const std::uint32_t> start_island(const StepContext& context, std::uint32_t island) {
  StepScratch& scratch = context.scratch;
  scratch.rows.clear();
  scratch.local.resize(scratch.island_of.size());
  for (std::uint32_t k = scratch.pair_offsets[island]; k < scratch.pair_offsets[island + 1]; ++k) {
    for (const std::uint32_t i : {scratch.found[scratch.pair_order[k]].bodies.first,
                                  scratch.found[scratch.pair_order[k]].bodies.second}) {
      if (context.models[i].is_static) scratch.local[i] = kStatic;
    }
  }
  return members_of(island, scratch);
}

// Body i's rotation as a converged island's rows take it: a member's at the end of its free step,
// a static body's where it stands.
const Mat3& rows_rotation(const StepContext& context, std::uint32_t i) {
  return context.models[i].is_static
             ? context.scratch.start_rotations[i]
             : context.scratch.island_bodies[context.scratch.local[i]].rotation;
}

// How far body i's corners can swing about its centre in the step (m).
double swing(const StepContext& context, std::uint32_t i) {
  return corner_swing(context.in[i], context.scratch.advances[i].end, context.models[i].shape,
                      context.dt);
}

// How far the bodies of a pair can close on each other in the step (m): as `reach` in
// world_step.cpp, but of B's centre relative to A's (a clump of boxes falling together closes by
// nothing), plus both corners' swings.
double pair_closing(const StepContext& context, std::uint32_t a, std::uint32_t b) {
  const BodyState& a_start = context.in[a];
  const BodyState& b_start = context.in[b];
  const BodyState& a_end = context.scratch.advances[a].end;
  const BodyState& b_end = context.scratch.advances[b].end;
  const double travel = std::max(
      ((b_end.position() - a_end.position()) - (b_start.position() - a_start.position())).norm(),
      context.dt * std::max((b_start.velocity() - a_start.velocity()).norm(),
                            (b_end.velocity() - a_end.velocity()).norm()));
  return travel + swing(context, a) + swing(context, b);
}

// How far a body can close on the planes within its reach in the step (m): its centre's travel
// along each such plane's normal towards it, plus its corners' swing.
double plane_closing(const StepContext& context, std::uint32_t i) {
  const BodyState& start = context.in[i];
  const BodyState& end = context.scratch.advances[i].end;
  const double near =
      context.models[i].shape.half_size.norm() + context.scratch.reaches[i] + kTouchingDistance;
  double closing = -1.0;  // no plane within reach
  for (const Plane& plane : context.planes) {
    if (separation(plane, start.position()) > near) continue;
    const Vec3& n = plane.normal;
    closing =
        std::max({closing, 0.0, -n.dot(end.position() - start.position()),
                  -context.dt * n.dot(start.velocity()), -context.dt * n.dot(end.velocity())});
  }
  return closing < 0.0 ? 0.0 : closing + swing(context, i);
}

// The fastest closing in the island: of a pair on each other, or of a body on the planes near it
// (m in the step). Closing, not moving: clumps of boxes poured together move far in a step but
// close on nothing until they land. On the 1000-box pour (contact_bench, seeds 1-3, one run
// each) the mean step went from 1.95-2.07 to 1.66-1.92 x Bullet's (docs/performance.md; the
// deepest point, one rare landing, moves either way with the run).
double fastest_closing(const StepContext& context, std::uint32_t island,
                       std::span<const std::uint32_t> members) {
  const StepScratch& scratch = context.scratch;
  double fastest = 0.0;
  for (std::uint32_t k = scratch.pair_offsets[island]; k < scratch.pair_offsets[island + 1]; ++k) {
    const auto [a, b] = scratch.found[scratch.pair_order[k]].bodies;
    fastest = std::max(fastest, pair_closing(context, a, b));
  }
  for (const std::uint32_t i : members) fastest = std::max(fastest, plane_closing(context, i));
  return fastest;
}

// The rows of a sub-stepped island's bodies against the planes: speculative, or (`fast`) in
// slots found again before each sub-step (an impact within the step turns a box onto corners
// its start knew nothing of: on the pile, bottom boxes hit from above went 3.9 cm into the floor
// so).
void add_substep_plane_rows(const StepContext& context, std::span<const std::uint32_t> members,
                            bool fast) {
  StepScratch& scratch = context.scratch;
  scratch.plane_rows.clear();
  if (context.planes.empty()) return;
  for (const std::uint32_t i : members) {
    const double margin = kTouchingDistance + scratch.reaches[i];
    const Mat3& rotation = scratch.start_rotations[i];
    if (!fast) {
      append_speculative_plane_rows(
          context, {.body = i, .solver = scratch.local[i], .rotation = rotation}, margin);
      continue;
    }
    std::vector<Manifold>& manifolds = context.memory.planes[i];
    manifolds.resize(context.planes.size());
    const BodyState& start = context.in[i];
    const double near = context.models[i].shape.half_size.norm() + margin + kRefindReach;
    for (std::uint32_t p = 0; p < context.planes.size(); ++p) {
      if (separation(context.planes[p], start.position()) > near) {
        manifolds[p].count = 0;
        continue;
      }
      const RowSlots at = add_slots(scratch.rows, kMaxManifoldPoints);
      const PlaneRows rows{.body = i, .plane = p, .first = at.first, .patch = at.patch};
      write_plane_rows(context, rows, {start.position(), rotation}, margin, false);
      scratch.plane_rows.push_back(rows);
    }
  }
}

// The rows of a sub-stepped island's pairs at the start pose; a pair that can close by more than
// kRefindReach gets slots for a whole manifold, found again before each sub-step.
void add_substep_pair_rows(const StepContext& context, std::uint32_t island) {
  StepScratch& scratch = context.scratch;
  scratch.pair_rows.clear();
  for (std::uint32_t k = scratch.pair_offsets[island]; k < scratch.pair_offsets[island + 1]; ++k) {
    const std::uint32_t p = scratch.pair_order[k];
    const auto [a, b] = scratch.found[p].bodies;
    const double reach = pair_closing(context, a, b);
    const RowSlots at =
        add_slots(scratch.rows, reach > kRefindReach
                                    ? kMaxManifoldPoints
                                    : static_cast<std::uint32_t>(scratch.found[p].manifold.count));
    const PairRows rows{
        .pair = p, .first = at.first, .slots = at.slots, .patch = at.patch, .reach = reach};
    const Material material = combine(context.models[a].material, context.models[b].material);
    write_rows(substep_pair_rows(context, rows, material, scratch.start_rotations[a],
                                 scratch.start_rotations[b]),
               at, scratch.rows);
    if (reach > kRefindReach) scratch.pair_rows.push_back(rows);
  }
}

// Before sub-step `substep` of `substeps`: the fast pairs' and planes' rows found again.
void refind(const StepContext& context, int substep, int substeps) {
  const double left = static_cast<double>(substeps - substep) / substeps;
  for (const PairRows& rows : context.scratch.pair_rows) refind_pair(context, rows, left);
  for (const PlaneRows& rows : context.scratch.plane_rows) {
    const BodyState& now = context.scratch.substep_bodies[context.scratch.local[rows.body]].state;
    const BodyModel& model = context.models[rows.body];
    // As far as it can go in what is left of the step, at its speeds now or the start's, and
    // as far again as the projection may push it (a box wedged under another is pushed down).
    const double going = context.dt * (now.velocity().norm() + now.angular_velocity().norm() *
                                                                   model.shape.half_size.norm());
    const double margin = kTouchingDistance +
                          left * std::max(context.scratch.reaches[rows.body], going) + kRefindReach;
    const Mat3 rotation = now.rotation();
    write_plane_rows(context, rows, {now.position(), rotation}, margin, true);
  }
}

// The equality rows of every joint with a body in the island (both its bodies are: joints join
// islands), at the bodies' free-step ends, into rows.joints.
void append_joint_rows(const StepContext& context, std::uint32_t island, ContactRows& rows) {
  const StepScratch& scratch = context.scratch;
  const JointWorld& world = *context.joints;
  std::vector<JointRow> found;
  const auto solver_index = [&](std::uint32_t i) {
    return i == kWorldBody || context.models[i].is_static ? kStatic : scratch.local[i];
  };
  const auto body_at = [&](std::uint32_t i) {
    return i == kWorldBody ? JointBody{} : JointBody::of(scratch.advances[i].end);
  };
  for (const Joint& joint : world.joints) {
    if (scratch.island_of[joint.a] != island &&
        (joint.b == kWorldBody || scratch.island_of[joint.b] != island)) {
      continue;
    }
    found.clear();
    equality_rows(joint, body_at(joint.a), body_at(joint.b), found);
    for (const JointRow& row : found) {
      JointConstraint out;
      out.a = solver_index(row.a);
      out.b = solver_index(row.b);
      SolverBody* a = out.a == kStatic ? nullptr : &rows.bodies[out.a];
      SolverBody* b = out.b == kStatic ? nullptr : &rows.bodies[out.b];
      if (!a) {  // the joint's a is static: the row seen from b
        std::swap(a, b);
        std::swap(out.a, out.b);
        out.direction = {.linear = row.linear_b,
                         .moment_a = row.angular_b,
                         .turn_a = a->turn(row.angular_b),
                         .moment_b = -row.angular_a,
                         .turn_b = Vec3::Zero(),
                         .mass = 0.0};
      } else {
        out.direction = {.linear = row.linear_a,
                         .moment_a = row.angular_a,
                         .turn_a = a->turn(row.angular_a),
                         .moment_b = -row.angular_b,
                         .turn_b = b ? b->turn(-row.angular_b) : Vec3::Zero(),
                         .mass = 0.0};
      }
      const ImpulseDirection& d = out.direction;
      double inverse = a->inverse_mass * d.linear.squaredNorm() + d.moment_a.dot(d.turn_a);
      if (b) inverse += b->inverse_mass * d.linear.squaredNorm() + d.moment_b.dot(d.turn_b);
      out.direction.mass = inverse > 0.0 ? 1.0 / inverse : 0.0;
      rows.joints.push_back(out);
    }
  }
}

}  // namespace

void solve_converged(const StepContext& context, std::uint32_t island) {
  StepScratch& scratch = context.scratch;
  ContactRows& rows = scratch.rows;
  const std::span<const std::uint32_t> members = start_island(context, island);
  scratch.island_bodies.clear();
  for (const std::uint32_t i : members) {
    const PlaneAdvance& advance = scratch.advances[i];
    const Mat3 rotation = advance.touching ? advance.rotation : advance.end.rotation();
    scratch.local[i] = static_cast<std::uint32_t>(scratch.island_bodies.size());
    scratch.island_bodies.push_back(
        {.model = &context.models[i],
         .start = holds_energy(context.integrator) && !held_by_joints(context, i) ? &context.in[i]
                                                                                  : nullptr,
         .end = advance.end,
         .rotation = rotation,
         .weight = impulse_position_weight(context.integrator, advance.remaining)});
    rows.bodies.push_back(SolverBody::from(advance.end, context.models[i].constants, rotation));
  }
  for (const std::uint32_t i : members) {
    if (!scratch.advances[i].touching) continue;
    const std::uint32_t local = scratch.local[i];
    append_plane_rows(
        context, {.body = i, .solver = local, .rotation = scratch.island_bodies[local].rotation},
        kTouchingDistance);
  }
  for (std::uint32_t k = scratch.pair_offsets[island]; k < scratch.pair_offsets[island + 1]; ++k) {
    const std::uint32_t p = scratch.pair_order[k];
    PairContact& pair = scratch.found[p];
    const auto [a, b] = pair.bodies;
    // Friction between bodies is not warm-started here (contact_solver.hpp says why): nothing
    // stale is left for a sub-stepped solve to start from.
    pair.manifold.friction = {};
    const Material material = combine(context.models[a].material, context.models[b].material);
    append_rows({.manifold = pair.manifold,
                 .material = material,
                 .a = scratch.local[a],
                 .b = scratch.local[b],
                 .a_rotation = rows_rotation(context, a),
                 .b_rotation = rows_rotation(context, b),
                 .a_base = {context.in[a].position(), scratch.start_rotations[a]},
                 .b_base = {context.in[b].position(), scratch.start_rotations[b]},
                 .speculative_step = context.dt,
                 .source = {.owner = p},
                 .keeps_friction = false,
                 .a_shape = context.models[a].shape,
                 .b_shape = context.models[b].shape},
                rows);
  }
  if (context.joints) append_joint_rows(context, island, rows);
  scratch.island_out.resize(members.size());
  resolve_island(scratch.island_bodies, rows, context.settings, scratch.island_out);
  store_impulses(rows, context.memory.planes, scratch.found);
  for (std::size_t k = 0; k < members.size(); ++k) {
    context.out[members[k]] = std::move(scratch.island_out[k]);
  }
}

void solve_substepped(const StepContext& context, std::uint32_t island) {
  StepScratch& scratch = context.scratch;
  const std::span<const std::uint32_t> members = start_island(context, island);
  scratch.substep_bodies.clear();
  for (const std::uint32_t i : members) {
    scratch.local[i] = static_cast<std::uint32_t>(scratch.substep_bodies.size());
    scratch.substep_bodies.push_back({.model = &context.models[i], .state = context.in[i]});
    scratch.rows.bodies.push_back(
        SolverBody::from(context.in[i], context.models[i].constants, scratch.start_rotations[i]));
  }
  const int substeps = substeps_for(fastest_closing(context, island, members));
  // In a fast island a body's corners near a plane are found again before each sub-step, as fast
  // pairs' points are.
  add_substep_plane_rows(context, members, substeps > kSubsteps);
  add_substep_pair_rows(context, island);
  const auto refresh = [&](int substep) { refind(context, substep, substeps); };
  substep_island(context, substeps,
                 scratch.pair_rows.empty() ? std::function<void(int)>{} : refresh);
  store_impulses(scratch.rows, context.memory.planes, scratch.found);
  for (std::size_t k = 0; k < members.size(); ++k) {
    context.out[members[k]] = std::move(scratch.substep_bodies[k].state);
  }
}

}  // namespace tumble::physics
