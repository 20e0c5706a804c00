#include "physics/world_step.hpp"

#include <algorithm>
#include <limits>

#include "physics/contact_rows.hpp"
#include "physics/island_solve.hpp"

namespace tumble::physics {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// How far a box can move towards anything in a step of h (s): its centre's travel (the free
// step's, or its speed times h, whichever is more: an impact with a plane within the step can
// bring the end back near the start) plus its corners' swing (its fastest turn times its half
// diagonal).
double reach(const BodyState& start, const BodyState& end, const Shape& shape, double h) {
  const double travel = std::max((end.position() - start.position()).norm(),
                                 h * std::max(start.velocity().norm(), end.velocity().norm()));
  return travel + corner_swing(start, end, shape, h);
}

std::uint32_t find_root(std::vector<std::uint32_t>& root, std::uint32_t i) {
  while (root[i] != i) {
    root[i] = root[root[i]];  // path halving
    i = root[i];
  }
  return i;
}

// The free steps, each with its impacts on planes.
void advance_bodies(const StepContext& context) {
  for (std::uint32_t i = 0; i < context.in.size(); ++i) {
    PlaneAdvance& advance = context.scratch.advances[i];
    const BodyState& in = context.in[i];
    if (context.models[i].is_static) {  // where it stands, touching no plane
      advance = {.end = in, .rotation = in.rotation(), .remaining = context.dt};
    } else if (held_by_joints(context, i)) {
      continue;  // below, with the joints' other members
    } else if (context.memory.asleep[i]) {
      // Unmoved, and still in its island: its manifolds keep the impulses it fell asleep with.
      advance = {.end = in, .rotation = in.rotation(), .remaining = context.dt, .touching = true};
    } else if (context.planes.empty()) {
      advance = {.end = step(context.integrator, context.models[i], in, context.t, context.dt),
                 .remaining = context.dt};
    } else {
      advance_among_planes(context, i, SlowImpacts::at_their_time);
    }
  }
  if (!context.joints) return;
  // The joints' members together, under their joints, their plane contacts left to the solve.
  advance_joint_members(context.integrator, context.in, context.t, context.dt, *context.joints,
                        context.out);
  for (const std::uint32_t i : context.joints->members) {
    if (!context.models[i].is_static) take_free_step(context, i, context.out[i]);
  }
}

// Notes in pair.stamp where its bodies stand at the start as its manifold is found with `margin`
// (m).
void stamp(const StepContext& context, double margin, PairContact& pair) {
  const BodyState& a = context.in[pair.bodies.first];
  const BodyState& b = context.in[pair.bodies.second];
  const Mat3& a_rotation = context.scratch.start_rotations[pair.bodies.first];
  PairStamp& out = pair.stamp;
  out.valid = true;
  out.offset = a_rotation.transpose() * (b.position() - a.position());
  out.turn = a.orientation().conjugate() * b.orientation();
  out.normal = a_rotation.transpose() * pair.manifold.normal;
  out.margin = margin;
  for (int k = 0; k < pair.manifold.count; ++k) {
    out.separation[static_cast<std::size_t>(k)] =
        pair.manifold.points[static_cast<std::size_t>(k)].separation;
  }
}

// Whether the pair `before` keeps its manifold at the bodies' poses at the start, needing
// `margin` (m); if so, `pair` gets it, with its normal turned with A and its separations
// measured now.
bool reuse(const StepContext& context, const PairContact& before, double margin,
           PairContact& pair) {
  const BodyState& a = context.in[pair.bodies.first];
  const BodyState& b = context.in[pair.bodies.second];
  const Mat3& a_rotation = context.scratch.start_rotations[pair.bodies.first];
  const Mat3& b_rotation = context.scratch.start_rotations[pair.bodies.second];
  const Vec3& b_half_size = context.models[pair.bodies.second].shape.half_size;
  const PairStamp& then = before.stamp;
  if (!then.valid) return false;
  // A ball's point turns away with the ball: its closed-form contact is found afresh, and costs
  // no more than this test.
  if (rounding(context.models[pair.bodies.first].shape) > 0.0 ||
      rounding(context.models[pair.bodies.second].shape) > 0.0) {
    return false;
  }
  const Vec3 moved = a_rotation.transpose() * (b.position() - a.position()) - then.offset;
  const Quat turned = then.turn.conjugate() * (a.orientation().conjugate() * b.orientation());
  const double angle = 2.0 * std::asin(std::min(1.0, turned.vec().norm()));  // rad
  const double distance = moved.norm() + angle * b_half_size.norm();
  if (!(distance + margin <= then.margin && distance < kReuseDistance)) return false;
  pair.manifold = before.manifold;
  pair.stamp = then;
  const Vec3 n = a_rotation * then.normal;
  pair.manifold.normal = n;
  for (int k = 0; k < pair.manifold.count; ++k) {
    PairPoint& point = pair.manifold.points[static_cast<std::size_t>(k)];
    // The two anchors were one point when the manifold was found.
    const Vec3 apart = world_point({b.position(), b_rotation}, point.point_b) -
                       world_point({a.position(), a_rotation}, point.point_a);
    point.separation = then.separation[static_cast<std::size_t>(k)] + n.dot(apart);
  }
  return true;
}

// Into scratch.found: the touching pairs of colliding bodies, with their manifolds at the start
// of the step and the last step's impulses of the same features.
void find_pairs(const StepContext& context) {
  StepScratch& scratch = context.scratch;
  const std::span<const BodyModel> models = context.models;
  const std::span<const BodyState> in = context.in;
  scratch.found.clear();
  scratch.colliders.clear();
  for (std::uint32_t i = 0; i < in.size(); ++i) {
    if (models[i].collides) scratch.colliders.push_back(i);
  }
  if (scratch.colliders.size() < 2) return;
  scratch.start_rotations.resize(in.size());
  scratch.bounds.clear();
  for (const std::uint32_t i : scratch.colliders) {
    scratch.start_rotations[i] = in[i].rotation();
    const PlaneAdvance& advance = scratch.advances[i];
    const Mat3 end_rotation = advance.touching ? advance.rotation : advance.end.rotation();
    scratch.bounds.push_back(merged(box_bounds(in[i].position(), scratch.start_rotations[i],
                                               models[i].shape.half_size, kTouchingDistance),
                                    box_bounds(advance.end.position(), end_rotation,
                                               models[i].shape.half_size, kTouchingDistance)));
  }
  overlapping_pairs(scratch.bounds, scratch.order, scratch.candidates);
  const std::vector<PairContact>& last = context.memory.pairs;
  std::size_t previous = 0;  // the last step's pairs are sorted as the candidates are: merge
  for (const BodyPair& candidate : scratch.candidates) {
    const std::uint32_t a = scratch.colliders[candidate.first];
    const std::uint32_t b = scratch.colliders[candidate.second];
    if (models[a].is_static && models[b].is_static) continue;
    const BodyPair bodies{a, b};
    if (context.joints && context.joints->keeps_apart(bodies)) continue;
    while (previous < last.size() && last[previous].bodies < bodies) ++previous;
    const PairContact* before =
        previous < last.size() && last[previous].bodies == bodies ? &last[previous] : nullptr;
    // Speculative points as far as the two can close on each other in the step.
    const double margin = kTouchingDistance + scratch.reaches[a] + scratch.reaches[b];
    PairContact pair;
    pair.bodies = bodies;
    if (before && reuse(context, *before, margin, pair)) {
      scratch.found.push_back(pair);
      continue;
    }
    pair.manifold =
        pair_manifold(pose_of(in[a], scratch.start_rotations[a], models[a].shape),
                      pose_of(in[b], scratch.start_rotations[b], models[b].shape),
                      margin + kReuseDistance, before ? before->manifold.normal : Vec3::Zero());
    if (pair.manifold.count == 0) continue;
    stamp(context, margin + kReuseDistance, pair);
    if (before) {
      pair.manifold.friction = before->manifold.friction;
      pair.manifold.patch = before->manifold.patch;
      keep_impulses(pair.manifold, before->manifold);
    }
    scratch.found.push_back(pair);
  }
}

// Into scratch.island_of: each body's island (kNone for a body touching nothing), numbered in
// the order of their lowest bodies, so the solve's order depends on body order alone.
int group_islands(const StepContext& context) {
  const std::size_t body_count = context.in.size();
  StepScratch& scratch = context.scratch;
  scratch.root.resize(body_count);
  for (std::uint32_t i = 0; i < body_count; ++i) scratch.root[i] = i;
  // A static body joins no island: two balls resting on one peg are two islands, each with its
  // rows against the peg, as against a plane.
  const auto is_static = [&](std::uint32_t i) { return context.models[i].is_static; };
  const auto join = [&](std::uint32_t first, std::uint32_t second) {
    const std::uint32_t a = find_root(scratch.root, first);
    const std::uint32_t b = find_root(scratch.root, second);
    if (a != b) scratch.root[std::max(a, b)] = std::min(a, b);
  };
  for (const PairContact& pair : scratch.found) {
    if (is_static(pair.bodies.first) || is_static(pair.bodies.second)) continue;
    join(pair.bodies.first, pair.bodies.second);
  }
  // A joint's two bodies are one island, whatever touches them (held_by_joints).
  if (context.joints) {
    for (const Joint& joint : context.joints->joints) {
      if (joint.b == kWorldBody || is_static(joint.a) || is_static(joint.b)) continue;
      join(joint.a, joint.b);
    }
  }
  scratch.island_of.assign(body_count, kNone);
  std::vector<std::uint32_t>& number_of_root = scratch.local;  // reused as scratch here
  number_of_root.assign(body_count, kNone);
  int islands = 0;
  std::vector<char>& paired = scratch.paired;
  paired.assign(body_count, 0);
  for (const PairContact& pair : scratch.found) {
    for (const std::uint32_t i : {pair.bodies.first, pair.bodies.second}) {
      if (!is_static(i)) paired[i] = 1;
    }
  }
  if (context.joints) {
    for (const std::uint32_t i : context.joints->members) {
      if (!is_static(i)) paired[i] = 1;
    }
  }
  for (std::uint32_t i = 0; i < body_count; ++i) {
    if (!scratch.advances[i].touching && !paired[i]) continue;
    const std::uint32_t r = find_root(scratch.root, i);
    if (number_of_root[r] == kNone) number_of_root[r] = static_cast<std::uint32_t>(islands++);
    scratch.island_of[i] = number_of_root[r];
  }
  // Bodies and pairs by island, each in its own order (a counting sort, which is stable).
  std::vector<std::uint32_t>& next = scratch.next_slot;
  const auto bucket = [islands, &next](std::size_t count, auto island_of_item,
                                       std::vector<std::uint32_t>& offsets,
                                       std::vector<std::uint32_t>& items) {
    offsets.assign(static_cast<std::size_t>(islands) + 1, 0);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (const std::uint32_t i = island_of_item(k); i != kNone) ++offsets[i + 1];
    }
    for (int i = 0; i < islands; ++i) offsets[i + 1] += offsets[i];
    items.resize(offsets.back());
    next.assign(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (const std::uint32_t i = island_of_item(k); i != kNone) items[next[i]++] = k;
    }
  };
  bucket(
      body_count, [&](std::uint32_t k) { return scratch.island_of[k]; }, scratch.member_offsets,
      scratch.members);
  bucket(
      scratch.found.size(),
      [&](std::uint32_t k) {
        const BodyPair& bodies = scratch.found[k].bodies;
        return scratch.island_of[is_static(bodies.first) ? bodies.second : bodies.first];
      },
      scratch.pair_offsets, scratch.pair_order);
  return islands;
}

// Whether the island suits solve_converged: small, and slow. Small: its pass budget
// (contact_island.hpp) still gives it kConvergedPasses. A pyramid of 55 cubes (400 points, 100
// passes) stands within 3 mm for 30 s so (0.33 mm with kept manifolds), and a tower of ten cubes
// within 3 mm for 60 s (1.3 mm), where the sub-steps let the tower rock 14 cm; but with 30 passes
// the pyramid moved 1.1 cm, and a pile of 1000 boxes solved so went 39 cm into itself, where the
// sub-steps (as many as it closes fast) keep it within 0.84 cm while the boxes land and 1.6 mm
// once it settles (contact_bench). Slow: no pair can close by more
// than kRefindReach in the step, for only the sub-steps find fast pairs' points again. Its points
// are counted as its pairs' and four for each body touching a plane.
constexpr int kConvergedPasses = 100;
bool converges(const StepContext& context, std::uint32_t island) {
  const StepScratch& scratch = context.scratch;
  std::size_t points = 0;
  for (std::uint32_t k = scratch.pair_offsets[island]; k < scratch.pair_offsets[island + 1]; ++k) {
    const PairContact& pair = scratch.found[scratch.pair_order[k]];
    const auto [a, b] = pair.bodies;
    if (scratch.reaches[a] + scratch.reaches[b] > kRefindReach) return false;
    points += static_cast<std::size_t>(pair.manifold.count);
  }
  for (std::uint32_t k = scratch.member_offsets[island]; k < scratch.member_offsets[island + 1];
       ++k) {
    if (scratch.advances[scratch.members[k]].touching) points += kMaxManifoldPoints;
  }
  return solver_passes(points) >= kConvergedPasses;
}

// Whether nothing but the body's state and the planes decides its laws: no law that switches
// on or off or moves in time, which a sleeping body would miss.
bool can_sleep(const BodyModel& model) {
  constexpr double kForever = std::numeric_limits<double>::infinity();
  return std::none_of(model.forces.begin(), model.forces.end(), [](const ForceLaw& law) {
    if (const auto* push = std::get_if<ForceAtPoint>(&law)) {
      return push->start != -kForever || push->end != kForever;
    }
    if (const auto* spring = std::get_if<Spring>(&law)) {
      return spring->start != -kForever || spring->end != kForever ||
             spring->anchor_keys.size() > 1;
    }
    return false;
  });
}

bool holds_joint_members(const StepContext& context, std::uint32_t island) {
  if (!context.joints) return false;
  const auto members = members_of(island, context.scratch);
  return std::any_of(members.begin(), members.end(),
                     [&](std::uint32_t i) { return context.joints->holds(i); });
}

bool touches_a_plane(const StepContext& context, std::uint32_t island) {
  const auto members = members_of(island, context.scratch);
  return std::any_of(members.begin(), members.end(),
                     [&](std::uint32_t i) { return context.scratch.advances[i].touching; });
}

bool island_asleep(const StepContext& context, std::uint32_t island) {
  const auto members = members_of(island, context.scratch);
  return std::all_of(members.begin(), members.end(),
                     [&](std::uint32_t i) { return context.memory.asleep[i] != 0; });
}

// Wakes the sleeping bodies of every island that has a body awake in it, each with its free step
// and its reach now; returns whether any woke.
bool wake_touched(const StepContext& context, int islands) {
  ContactMemory& memory = context.memory;
  StepScratch& scratch = context.scratch;
  bool woke = false;
  for (std::uint32_t island = 0; island < static_cast<std::uint32_t>(islands); ++island) {
    const auto members = members_of(island, scratch);
    const bool some_awake = std::any_of(members.begin(), members.end(),
                                        [&](std::uint32_t i) { return !memory.asleep[i]; });
    if (!some_awake || island_asleep(context, island)) continue;
    for (const std::uint32_t i : members) {
      if (!memory.asleep[i]) continue;
      memory.asleep[i] = 0;
      memory.still_for[i] = 0.0;
      advance_among_planes(context, i, SlowImpacts::at_their_time);
      scratch.reaches[i] =
          reach(context.in[i], scratch.advances[i].end, context.models[i].shape, context.dt);
      woke = true;
    }
  }
  return woke;
}

// How fast the body's fastest point can move (m/s): a bound, |v| + |ω| × its half diagonal.
double point_speed_bound(const BodyState& state, const Vec3& half_size) {
  return state.velocity().norm() + state.angular_velocity().norm() * half_size.norm();
}

// Adds dt (s) to the body's time still if it ended the step still, else restarts it; returns
// whether it has been still for kTimeToSleep and may sleep.
bool still_long_enough(const BodyModel& model, const BodyState& end, double dt, double& still_for) {
  const bool still = point_speed_bound(end, model.shape.half_size) < kSleepSpeed;
  still_for = still ? still_for + dt : 0.0;
  return still_for >= kTimeToSleep && can_sleep(model);
}

// Puts body i to sleep at rest where it stands.
void fall_asleep(const StepContext& context, std::uint32_t i) {
  PrimaryState rest = context.out[i].primary();
  rest.momentum.setZero();
  rest.angular_momentum.setZero();
  context.out[i] = BodyState(rest, context.models[i].constants);
  context.memory.asleep[i] = 1;
}

// After the islands' solves: each awake body's time still, and an island whose bodies have all
// been still for kTimeToSleep (and may sleep) put to sleep at rest where it stands.
void settle(const StepContext& context, int islands) {
  std::vector<double>& still_for = context.memory.still_for;
  for (std::size_t i = 0; i < context.out.size(); ++i) {
    if (context.scratch.island_of[i] == kNone) still_for[i] = 0.0;
  }
  for (std::uint32_t island = 0; island < static_cast<std::uint32_t>(islands); ++island) {
    // A joint's members do not sleep: what holds them reaches past the island.
    if (island_asleep(context, island) || holds_joint_members(context, island)) continue;
    const auto members = members_of(island, context.scratch);
    bool sleeps = true;
    for (const std::uint32_t i : members) {
      sleeps =
          still_long_enough(context.models[i], context.out[i], context.dt, still_for[i]) && sleeps;
    }
    if (!sleeps) continue;
    for (const std::uint32_t i : members) fall_asleep(context, i);
  }
}

// step_world for a world in which no two bodies can touch: each body's step among the planes
// (step_among_planes), and its sleep, exactly as its island of one would have them.
void step_bodies_alone(const StepContext& context) {
  ContactMemory& memory = context.memory;
  memory.pairs.clear();
  if (context.joints) {
    advance_joint_members(context.integrator, context.in, context.t, context.dt, *context.joints,
                          context.out);
  }
  bool moved_members = false;
  for (std::uint32_t i = 0; i < context.in.size(); ++i) {
    if (held_by_joints(context, i)) {  // its free step is the joints'; planes may stop it
      if (context.models[i].is_static || context.planes.empty()) continue;
      take_free_step(context, i, context.out[i]);
      if (!context.scratch.advances[i].touching) continue;
      context.out[i] = rest_on_planes(context, i);
      moved_members = true;
      continue;
    }
    if (memory.asleep[i] || context.models[i].is_static) {  // nothing can move it
      context.out[i] = context.in[i];
      continue;
    }
    bool touching = false;
    if (context.planes.empty()) {
      context.out[i] =
          step(context.integrator, context.models[i], context.in[i], context.t, context.dt);
    } else {
      touching = step_among_planes(context, i);
    }
    if (!context.settings.sleep) continue;
    if (!touching) {
      memory.still_for[i] = 0.0;
    } else if (still_long_enough(context.models[i], context.out[i], context.dt,
                                 memory.still_for[i])) {
      fall_asleep(context, i);
    }
  }
  // Planes moved members apart from each other: onto the joints again.
  if (moved_members) project_joint_members(*context.joints, context.out);
}

// Every per-body list of the memory and the scratch sized to the world's bodies.
void size_for(std::size_t bodies, WorldContacts& contacts) {
  contacts.memory.asleep.resize(bodies, 0);
  contacts.memory.still_for.resize(bodies, 0.0);
  contacts.memory.planes.resize(bodies);
  contacts.scratch.advances.resize(bodies);
  contacts.scratch.separations.resize(bodies);
  contacts.scratch.reaches.resize(bodies);
}

// A body of an island of several, solved to convergence, that resolved an impact with a plane
// at its time, for itself alone, though it did not bounce, takes its free step again leaving it
// to the island's solve (SlowImpacts, plane_contact_step.hpp). A body touching only planes keeps
// it, and steps as alone; so does a sub-stepped island's (a pour), whose sub-steps find the
// planes' corners again (deferred there too, the 1000-box pour went 19 and 38 mm deep on seeds 1
// and 3, against 15 and 12 kept).
void leave_slow_impacts_to_the_solve(const StepContext& context, int islands) {
  StepScratch& scratch = context.scratch;
  for (std::uint32_t island = 0; island < static_cast<std::uint32_t>(islands); ++island) {
    const std::span<const std::uint32_t> members = members_of(island, scratch);
    if (members.size() < 2 || island_asleep(context, island) || !converges(context, island)) {
      continue;
    }
    for (const std::uint32_t i : members) {
      if (!scratch.advances[i].slow_impact) continue;
      advance_among_planes(context, i, SlowImpacts::in_the_solve);
    }
  }
}

// The islands' solves: asleep, a body alone on planes, converged or sub-stepped.
void solve_islands(const StepContext& context, int islands) {
  const StepScratch& scratch = context.scratch;
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(islands); ++k) {
    if (island_asleep(context, k)) {
      for (const std::uint32_t i : members_of(k, scratch)) context.out[i] = context.in[i];
    } else if (scratch.pair_offsets[k] == scratch.pair_offsets[k + 1] &&
               holds_joint_members(context, k) && !touches_a_plane(context, k)) {
      // Bodies held by joints alone, touching nothing: their free step was their joints' solve.
      for (const std::uint32_t i : members_of(k, scratch)) context.out[i] = scratch.advances[i].end;
    } else if (holds_joint_members(context, k)) {
      // From the joints' free step, their rows among the contacts': solved to convergence.
      solve_converged(context, k);
    } else if (scratch.pair_offsets[k] == scratch.pair_offsets[k + 1]) {
      // One body touching planes alone: its impacts were at their times; it rests as it would
      // with no other body in the world.
      const std::uint32_t i = scratch.members[scratch.member_offsets[k]];
      context.out[i] = rest_on_planes(context, i);
    } else if (converges(context, k)) {
      solve_converged(context, k);
    } else {
      solve_substepped(context, k);
    }
  }
}

// Whether a joint's member was in an island: its contacts may have moved it off its joints.
bool contacts_moved_members(const StepContext& context) {
  if (!context.joints) return false;
  const std::vector<std::uint32_t>& members = context.joints->members;
  return std::any_of(members.begin(), members.end(),
                     [&](std::uint32_t i) { return context.scratch.island_of[i] != kNone; });
}

}  // namespace

bool pairs_possible(std::span<const BodyModel> models, const ContactSettings& settings) {
  if (!settings.collide_bodies) return false;
  return std::count_if(models.begin(), models.end(),
                       [](const BodyModel& model) { return model.collides; }) >= 2;
}

void step_world(Integrator integrator, std::span<const BodyModel> models,
                std::span<const BodyState> in, double t, double dt,
                const std::vector<Plane>& planes, const ContactSettings& settings,
                WorldContacts& contacts, std::span<BodyState> out, JointWorld* joints) {
  size_for(in.size(), contacts);
  const StepContext context{.integrator = integrator,
                            .models = models,
                            .in = in,
                            .t = t,
                            .dt = dt,
                            .planes = planes,
                            .settings = settings,
                            .memory = contacts.memory,
                            .scratch = contacts.scratch,
                            .out = out,
                            .joints = joints && !joints->joints.empty() ? joints : nullptr};
  if (!pairs_possible(models, settings) && !context.joints) {
    step_bodies_alone(context);
    return;
  }
  advance_bodies(context);
  StepScratch& scratch = contacts.scratch;
  for (std::size_t i = 0; i < in.size(); ++i) {
    scratch.reaches[i] = reach(in[i], scratch.advances[i].end, models[i].shape, dt);
  }
  int islands = 0;
  do {  // again while bodies woke: what they touch now may be asleep too
    scratch.found.clear();
    if (settings.collide_bodies) find_pairs(context);
    islands = group_islands(context);
  } while (settings.sleep && wake_touched(context, islands));
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (scratch.island_of[i] == kNone) out[i] = std::move(scratch.advances[i].end);
  }
  leave_slow_impacts_to_the_solve(context, islands);
  solve_islands(context, islands);
  if (contacts_moved_members(context)) project_joint_members(*context.joints, out);
  if (settings.sleep) settle(context, islands);
  contacts.memory.pairs.swap(scratch.found);
}

BodyState step_with_planes(Integrator integrator, const BodyModel& model, const BodyState& in,
                           double t, double dt, const std::vector<Plane>& planes,
                           const ContactSettings& settings, WorldContacts& contacts) {
  // A world of this body alone, which does not sleep.
  ContactSettings alone = settings;
  alone.collide_bodies = false;
  alone.sleep = false;
  BodyState out;
  step_world(integrator, {&model, 1}, {&in, 1}, t, dt, planes, alone, contacts, {&out, 1});
  return out;
}

}  // namespace tumble::physics
