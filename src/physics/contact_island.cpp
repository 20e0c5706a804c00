#include "physics/contact_island.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "physics/normal_block.hpp"

namespace tumble::physics {
namespace {

Vec3 arm(const ProjectedPose& pose, const Vec3& anchor) {
  return pose.primary.orientation * anchor;
}

// Pushes a's and b's poses apart along the point's normal until its separation is zero, by a
// position-level impulse through both bodies' masses; returns the separation it had (m), or 0
// when it was not inside.
double project(const PositionPoint& point, ProjectedPose& a, ProjectedPose* b) {
  const Vec3 arm_a = arm(a, point.anchor_a);
  double separation = point.base + point.normal.dot(a.primary.position + arm_a);
  Vec3 arm_b = Vec3::Zero();
  if (b) {
    arm_b = arm(*b, point.anchor_b);
    separation -= point.normal.dot(b->primary.position + arm_b);
  }
  if (separation >= 0.0) return 0.0;
  const Vec3& n = point.normal;
  const Vec3 turn_a = a.solved->turn(arm_a.cross(n));
  double inverse_mass = a.inverse_mass + arm_a.cross(n).dot(turn_a);
  Vec3 turn_b = Vec3::Zero();
  if (b) {
    turn_b = b->solved->turn(arm_b.cross(n));
    inverse_mass += b->inverse_mass + arm_b.cross(n).dot(turn_b);
  }
  const double push = -separation / inverse_mass;  // position-level impulse (kg m)
  a.primary.position += (push * a.inverse_mass) * n;
  a.primary.orientation = rotated(a.primary.orientation, push * turn_a).normalized();
  if (b) {
    b->primary.position -= (push * b->inverse_mass) * n;
    b->primary.orientation = rotated(b->primary.orientation, -push * turn_b).normalized();
  }
  return separation;
}

// One pass of the projection with its points as one block (physics/normal_block.hpp): the
// position-level impulses that bring every point inside to zero separation at once, linearised
// at the poses now, applied together. Returns the deepest separation before the pass (m), or 0.
double project_block(std::span<ProjectedPose> poses, std::span<const PositionPoint> positions) {
  const std::size_t n = positions.size();
  std::vector<ImpulseDirection> directions(n);
  std::vector<BlockRow> rows(n);
  Eigen::VectorXd separations(static_cast<Eigen::Index>(n));
  double deepest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const PositionPoint& point = positions[i];
    const ProjectedPose& a = poses[point.a];
    const Vec3& normal = point.normal;
    const Vec3 arm_a = arm(a, point.anchor_a);
    double separation = point.base + normal.dot(a.primary.position + arm_a);
    ImpulseDirection& d = directions[i];
    d.linear = normal;
    d.moment_a = arm_a.cross(normal);
    d.turn_a = a.solved->turn(d.moment_a);
    d.moment_b = d.turn_b = Vec3::Zero();
    d.mass = 0.0;
    if (point.b != kStatic) {
      const ProjectedPose& b = poses[point.b];
      const Vec3 arm_b = arm(b, point.anchor_b);
      separation -= normal.dot(b.primary.position + arm_b);
      d.moment_b = arm_b.cross(normal);
      d.turn_b = b.solved->turn(d.moment_b);
    }
    rows[i] = {.a = point.a, .b = point.b, .direction = &d};
    separations(static_cast<Eigen::Index>(i)) = separation;
    deepest = std::min(deepest, separation);
  }
  if (deepest == 0.0) return 0.0;
  std::vector<double> inverse_masses;
  for (const ProjectedPose& pose : poses) inverse_masses.push_back(pose.inverse_mass);
  Eigen::MatrixXd matrix;
  block_matrix(rows, inverse_masses, matrix);
  BlockLcp lcp;
  lcp.set_matrix(matrix);
  Eigen::VectorXd push = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  if (!lcp.solve(separations, 1e-3 * std::abs(deepest), push))
    return project_pass(poses, positions);
  std::vector<Vec3> moves(poses.size(), Vec3::Zero()), turns(poses.size(), Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const double p = push(static_cast<Eigen::Index>(i));  // position-level impulse (kg m)
    const PositionPoint& point = positions[i];
    moves[point.a] += (p * poses[point.a].inverse_mass) * point.normal;
    turns[point.a] += p * directions[i].turn_a;
    if (point.b == kStatic) continue;
    moves[point.b] -= (p * poses[point.b].inverse_mass) * point.normal;
    turns[point.b] -= p * directions[i].turn_b;
  }
  for (std::size_t k = 0; k < poses.size(); ++k) {
    poses[k].primary.position += moves[k];
    poses[k].primary.orientation = rotated(poses[k].primary.orientation, turns[k]).normalized();
  }
  return deepest;
}

// The island's states in `out` held to the energy its bodies had at the start (resolve_island
// says why); nothing for an island with a body that is not passive.
void hold_energy(std::span<const IslandBody> bodies, std::span<BodyState> out) {
  double before = 0.0, after = 0.0, scale = 0.0, kinetic = 0.0, pull = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    Vec3 force;  // N
    if (!bodies[i].start || !constant_force(*bodies[i].model, force)) return;
    const double end_kinetic = kinetic_energy(out[i]);
    before += kinetic_energy(*bodies[i].start) - force.dot(bodies[i].start->position());
    after += end_kinetic - force.dot(out[i].position());
    scale += end_kinetic + force.norm() * bodies[i].model->shape.half_size.norm();
    kinetic += end_kinetic;
    pull += force.squaredNorm();
  }
  const double excess = after - before;
  if (!(excess > kEnergySlack * scale)) return;
  // From the kinetic energy what it has; the rest (a body lifted from rest) from the potential,
  // each body moved along its constant force by its share: -ΔU = Σ F·d = the rest.
  const double taken = std::min(excess, kinetic);
  const double factor = kinetic > 0.0 ? std::sqrt(std::max(0.0, 1.0 - taken / kinetic)) : 1.0;
  const double rest = pull > 0.0 ? (excess - taken) / pull : 0.0;  // m/N
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    Vec3 force;
    constant_force(*bodies[i].model, force);
    PrimaryState primary = out[i].primary();
    primary.momentum *= factor;
    primary.angular_momentum *= factor;
    primary.position += rest * force;
    out[i] = BodyState(primary, bodies[i].model->constants);
  }
}

}  // namespace

bool constant_force(const BodyModel& model, Vec3& force) {
  force = Vec3::Zero();
  for (const ForceLaw& law : model.forces) {
    if (const auto* gravity = std::get_if<Gravity>(&law)) {
      force += model.constants.mass * gravity->acceleration;
    } else if (const auto* constant = std::get_if<ConstantForce>(&law)) {
      force += constant->force;
    } else if (!std::holds_alternative<LinearDamping>(law) &&
               !std::holds_alternative<AngularDamping>(law)) {
      return false;
    }
  }
  return true;
}

bool passive(const BodyModel& model) {
  Vec3 force;
  return constant_force(model, force);
}

Vec3 without_residue(Vec3 momentum) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(momentum[i]) < kNegligibleMomentum) momentum[i] = 0.0;
  }
  return momentum;
}

double project_pass(std::span<ProjectedPose> poses, std::span<const PositionPoint> positions) {
  double deepest = 0.0;
  for (const PositionPoint& point : positions) {
    deepest = std::min(
        deepest, project(point, poses[point.a], point.b == kStatic ? nullptr : &poses[point.b]));
  }
  return deepest;
}

Quat rotated(const Quat& q, const Vec3& angle) {
  const double squared = angle.squaredNorm();
  // exp(angle / 2) = (cos(θ/2), sin(θ/2)/θ angle); below 1e-4 rad the Taylor terms kept are exact
  // to rounding (the next ones are below θ⁴/384 < 3e-19), and a resting body turns by ~1e-17.
  if (squared < 1e-8) {
    Quat turn(1.0 - squared / 8.0, 0.0, 0.0, 0.0);
    turn.vec() = (0.5 - squared / 48.0) * angle;
    return turn * q;
  }
  const double size = std::sqrt(squared);
  return Quat(Eigen::AngleAxisd(size, angle / size)) * q;
}

int solver_passes(std::size_t points) {
  const std::size_t budget =
      static_cast<std::size_t>(kPointPassBudget) / std::max<std::size_t>(points, 1);
  return static_cast<int>(std::clamp<std::size_t>(budget, kFewestPasses, kMostPasses));
}

Vec3 mean_arm(std::span<const Vec3> arms) {
  Vec3 centre = Vec3::Zero();
  if (arms.empty()) return centre;
  for (const Vec3& arm : arms) centre += arm;
  return centre / static_cast<double>(arms.size());
}

void resolve_island(std::span<const IslandBody> bodies, ContactRows& rows,
                    const ContactSettings& settings, std::span<BodyState> out) {
  const std::span<const SolverBody> solver = rows.bodies;
  std::vector<ProjectedPose>& poses = rows.poses;
  solve_contacts(rows.bodies, rows.points, rows.patches,
                 {.iterations = solver_passes(rows.points.size()),
                  .tolerance = kRestingTolerance,
                  .restitution_threshold = settings.restitution_threshold,
                  .warm_start = true,
                  // Two bodies or more: their mass ratio and their symmetric contacts want the
                  // normal rows as one block (physics/normal_block.hpp); one body alone on planes
                  // converges one row at a time in a pass or two.
                  .block = bodies.size() > 1},
                 rows.joints);
  poses.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const IslandBody& body = bodies[i];
    const SolverBody& solved = solver[i];
    PrimaryState primary = body.end.primary();
    primary.momentum =
        without_residue(primary.momentum + solved.linear_impulse(body.end.velocity()));
    primary.angular_momentum = without_residue(primary.angular_momentum +
                                               solved.angular_impulse(body.end.angular_velocity()));
    primary.position += body.weight * (solved.velocity - body.end.velocity());
    primary.orientation = rotated(
        primary.orientation, body.weight * (solved.angular_velocity - body.end.angular_velocity()));
    poses[i] = {
        .primary = primary, .inverse_mass = body.model->constants.inverse_mass, .solved = &solved};
  }
  // Two bodies or more project their points as one block, as they solved them (above).
  const bool by_block = bodies.size() > 1 && rows.positions.size() <= kMostBlockRows;
  for (int iteration = 0; iteration < kProjectionIterations; ++iteration) {
    const double deepest =
        by_block ? project_block(poses, rows.positions) : project_pass(poses, rows.positions);
    if (deepest == 0.0) break;
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    out[i] = BodyState(poses[i].primary, bodies[i].model->constants);
  }
  hold_energy(bodies, out);
}

}  // namespace tumble::physics
