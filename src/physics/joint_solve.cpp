#include "physics/joint_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/contact_island.hpp"
#include "physics/plane_contact_step.hpp"

namespace tumble::physics {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// K is regularised by this fraction of its largest diagonal entry, so that redundant rows (two
// hinges on one axis) factorise: it changes λ by about as much relative, far below what shows.
constexpr double kRegularisation = 1e-10;

const JointBody& world_body() {
  static const JointBody world;
  return world;
}

// The joint's two bodies at `states`, the world's for body b kWorldBody.
struct JointBodies {
  JointBody a, b;
};
JointBodies bodies_of(const Joint& joint, std::span<const BodyState> states) {
  return {JointBody::of(states[joint.a]),
          joint.b == kWorldBody ? world_body() : JointBody::of(states[joint.b])};
}

double row_rate(const JointRow& row, std::span<const BodyState> states) {
  double rate = row.linear_a.dot(states[row.a].velocity()) +
                row.angular_a.dot(states[row.a].angular_velocity());
  if (row.b != kWorldBody) {
    rate += row.linear_b.dot(states[row.b].velocity()) +
            row.angular_b.dot(states[row.b].angular_velocity());
  }
  return rate;
}

// A row of step 2: its impulse accumulated within [lowest, highest], driving its rate to
// at least `target` (one-sided) or to `target` (a motor, an equality).
struct BoundedRow {
  JointRow row;
  double lowest = -kInfinity, highest = kInfinity;  // N s (or N m s)
  double target = 0.0;                              // m/s or rad/s
  double impulse = 0.0;                             // accumulated
  double mass = 0.0;                                // 1 / (J M⁻¹ Jᵀ)
  std::uint32_t joint = 0;
  double JointImpulses::*memory = nullptr;  // where it warm-starts from, if anywhere
};

// The joint's one-sided rows: each with its gap C >= 0 in `error` (m or rad), direction so that
// a positive impulse opens the gap.
struct OneSided {
  JointRow row;
  double JointImpulses::*memory = nullptr;
};
void one_sided_rows(const Joint& joint, const JointBody& a, const JointBody& b,
                    std::vector<OneSided>& out) {
  double lower = -kInfinity, upper = kInfinity;
  if (joint.kind == JointKind::distance && !is_rigid_distance(joint)) {
    if (joint.min_length > 0.0) lower = joint.min_length;
    if (std::isfinite(joint.max_length)) upper = joint.max_length;
  } else if (joint.limits) {
    lower = joint.limits->lower;
    upper = joint.limits->upper;
  } else {
    return;
  }
  const std::optional<JointCoordinate> at = joint_coordinate(joint, a, b);
  if (!at) return;
  const JointRow along = coordinate_row(joint, a, b);
  if (std::isfinite(lower)) {
    OneSided side{.row = along, .memory = &JointImpulses::lower};
    side.row.error = at->value - lower;
    out.push_back(side);
  }
  if (std::isfinite(upper)) {
    OneSided side{.row = along, .memory = &JointImpulses::upper};
    side.row.linear_a = -side.row.linear_a;
    side.row.angular_a = -side.row.angular_a;
    side.row.linear_b = -side.row.linear_b;
    side.row.angular_b = -side.row.angular_b;
    side.row.error = upper - at->value;
    out.push_back(side);
  }
}

// A body's accelerations (m/s², rad/s²).
struct Accelerations {
  Vec3 linear = Vec3::Zero();
  Vec3 angular = Vec3::Zero();
};

}  // namespace

void JointSystem::masses(std::span<const BodyModel> models, std::span<const BodyState> states) {
  inverse_masses_.resize(models.size());
  inverse_inertias_.resize(models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    const BodyConstants& c = models[i].constants;
    inverse_masses_[i] = c.inverse_mass;
    const Mat3 r = states[i].rotation();
    inverse_inertias_[i] = r * c.inverse_inertia.asDiagonal() * r.transpose();
  }
}

void JointSystem::build(std::span<const Joint> joints, std::span<const BodyModel> models,
                        std::span<const BodyState> states) {
  masses(models, states);
  rows_.clear();
  for (std::uint32_t j = 0; j < joints.size(); ++j) {
    const std::size_t first = rows_.size();
    const JointBodies at = bodies_of(joints[j], states);
    equality_rows(joints[j], at.a, at.b, rows_);
    for (std::size_t r = first; r < rows_.size(); ++r) rows_[r].joint = j;
  }
}

void JointSystem::build_with_passed_limits(std::span<const Joint> joints,
                                           std::span<const BodyModel> models,
                                           std::span<const BodyState> states) {
  build(joints, models, states);
  std::vector<OneSided> sides;
  for (const Joint& joint : joints) {
    const JointBodies at = bodies_of(joint, states);
    sides.clear();
    one_sided_rows(joint, at.a, at.b, sides);
    for (const OneSided& side : sides) {
      if (side.row.error < 0.0) rows_.push_back(side.row);
    }
  }
}

void JointSystem::plan() {
  // K_rs = Σ over the bodies rows r and s share: m⁻¹ l_r·l_s + w_r·I⁻¹ w_s, lower triangle; a
  // static body (no inverse mass or inertia) adds nothing.
  const auto n = static_cast<Eigen::Index>(rows_.size());
  std::vector<std::vector<std::pair<std::uint32_t, bool>>> by_body(inverse_masses_.size());
  for (std::uint32_t r = 0; r < rows_.size(); ++r) {
    by_body[rows_[r].a].push_back({r, false});
    if (rows_[r].b != kWorldBody) by_body[rows_[r].b].push_back({r, true});
  }
  terms_.clear();
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::uint32_t i = 0; i < by_body.size(); ++i) {
    if (inverse_masses_[i] == 0.0 && inverse_inertias_[i].isZero()) continue;
    for (const auto& [r, r_on_b] : by_body[i]) {
      for (const auto& [s, s_on_b] : by_body[i]) {
        if (s > r) continue;
        terms_.push_back({.r = r, .s = s, .body = i, .r_on_b = r_on_b, .s_on_b = s_on_b});
        triplets.emplace_back(r, s, 0.0);
      }
    }
  }
  for (Eigen::Index r = 0; r < n; ++r) triplets.emplace_back(r, r, 0.0);
  k_.resize(n, n);
  k_.setFromTriplets(triplets.begin(), triplets.end());
  k_.makeCompressed();
  const double* values = k_.valuePtr();
  for (Term& term : terms_) term.slot = &k_.coeffRef(term.r, term.s) - values;
  diagonal_slots_.resize(rows_.size());
  for (Eigen::Index r = 0; r < n; ++r) diagonal_slots_[r] = &k_.coeffRef(r, r) - values;
  pattern_.clear();
  for (const JointRow& row : rows_) pattern_.emplace_back(row.a, row.b);
  if (!factor_) factor_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
  factor_->analyzePattern(k_);
  analysed_ = true;
}

bool JointSystem::factorise() {
  const std::size_t n = rows_.size();
  if (n == 0) return true;
  bool same = analysed_ && pattern_.size() == n;
  for (std::size_t r = 0; same && r < n; ++r) {
    same = pattern_[r].first == rows_[r].a && pattern_[r].second == rows_[r].b;
  }
  if (!same) plan();
  // Each row's image through each of its bodies' inverse inertias, once.
  turns_.resize(2 * n);
  for (std::size_t r = 0; r < n; ++r) {
    const JointRow& row = rows_[r];
    turns_[2 * r] = inverse_inertias_[row.a] * row.angular_a;
    turns_[2 * r + 1] =
        row.b == kWorldBody ? Vec3::Zero() : Vec3(inverse_inertias_[row.b] * row.angular_b);
  }
  double* values = k_.valuePtr();
  std::fill(values, values + k_.nonZeros(), 0.0);
  for (const Term& term : terms_) {
    const JointRow& row_r = rows_[term.r];
    const JointRow& row_s = rows_[term.s];
    const Vec3& l_r = term.r_on_b ? row_r.linear_b : row_r.linear_a;
    const Vec3& turn_r = turns_[2 * term.r + (term.r_on_b ? 1 : 0)];
    const Vec3& l_s = term.s_on_b ? row_s.linear_b : row_s.linear_a;
    const Vec3& w_s = term.s_on_b ? row_s.angular_b : row_s.angular_a;
    values[term.slot] += inverse_masses_[term.body] * l_r.dot(l_s) + turn_r.dot(w_s);
  }
  double largest = 0.0;
  for (const std::ptrdiff_t slot : diagonal_slots_) largest = std::max(largest, values[slot]);
  for (const std::ptrdiff_t slot : diagonal_slots_) values[slot] += kRegularisation * largest;
  factor_->factorize(k_);
  return factor_->info() == Eigen::Success;
}

Eigen::VectorXd JointSystem::solve(const Eigen::VectorXd& rhs) const {
  if (rhs.size() == 0) return rhs;
  return factor_->solve(rhs);
}

namespace {

// The force and torque of a sprung distance joint on its two bodies (N, N m, world).
void add_spring(const Joint& joint, std::span<const BodyState> states, std::span<Wrench> wrenches) {
  const JointBodies at = bodies_of(joint, states);
  const Vec3 arm_a = at.a.rotation * joint.anchor_a;
  const Vec3 arm_b = at.b.rotation * joint.anchor_b;
  const Vec3 apart = at.a.position + arm_a - at.b.position - arm_b;
  const double length = apart.norm();
  if (!(length > 0.0)) return;
  const Vec3 u = apart / length;
  const Vec3 closing = at.a.velocity + at.a.angular_velocity.cross(arm_a) - at.b.velocity -
                       at.b.angular_velocity.cross(arm_b);
  const Vec3 force =
      -(joint.stiffness * (length - joint.rest_length) + joint.damping * u.dot(closing)) * u;
  wrenches[joint.a].force += force;
  wrenches[joint.a].torque += arm_a.cross(force);
  if (joint.b != kWorldBody) {
    wrenches[joint.b].force -= force;
    wrenches[joint.b].torque -= arm_b.cross(force);
  }
}

// Adds to `wrenches` λ along each row (N or N m per unit).
void add_row_forces(const std::vector<JointRow>& rows, const Eigen::VectorXd& lambda,
                    std::span<const BodyModel> models, std::span<Wrench> wrenches) {
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    const double l = lambda[static_cast<Eigen::Index>(r)];
    if (!models[row.a].is_static) {
      wrenches[row.a].force += l * row.linear_a;
      wrenches[row.a].torque += l * row.angular_a;
    }
    if (row.b != kWorldBody && !models[row.b].is_static) {
      wrenches[row.b].force += l * row.linear_b;
      wrenches[row.b].torque += l * row.angular_b;
    }
  }
}

// The joints' equality forces at `states` (the sprung joints' forces already in `wrenches`),
// with each row's λ into `lambda`.
void solve_forces(std::span<const Joint> joints, std::span<const BodyModel> models,
                  std::span<const BodyState> states, double t, JointSystem& system,
                  std::span<Wrench> wrenches, Eigen::VectorXd& lambda) {
  system.build(joints, models, states);
  const std::vector<JointRow>& rows = system.rows();
  lambda.resize(static_cast<Eigen::Index>(rows.size()));
  if (rows.empty() || !system.factorise()) {
    lambda.setZero();
    return;
  }
  // Each body's accelerations under its own laws and what is in `wrenches` so far.
  std::vector<Accelerations> free(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (models[i].is_static) continue;
    const Wrench own = total_wrench(models[i].forces, models[i].constants, states[i], t);
    const Vec3 force = own.force + wrenches[i].force;
    const Vec3 torque = own.torque + wrenches[i].torque;
    const Vec3& omega = states[i].angular_velocity();
    free[i].linear = models[i].constants.inverse_mass * force;
    free[i].angular = system.inverse_inertia(static_cast<std::uint32_t>(i)) *
                      (torque - omega.cross(states[i].angular_momentum()));
  }
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    double acceleration =
        row.linear_a.dot(free[row.a].linear) + row.angular_a.dot(free[row.a].angular);
    if (row.b != kWorldBody) {
      acceleration += row.linear_b.dot(free[row.b].linear) + row.angular_b.dot(free[row.b].angular);
    }
    rhs[static_cast<Eigen::Index>(r)] = -(acceleration + row.curvature);
  }
  lambda = system.solve(rhs);
  add_row_forces(rows, lambda, models, wrenches);
}

// Moves the states by the impulses (N s, N m s) per body: momenta by them, poses by `weight`
// (s) times the velocity change they make (0: poses unmoved).
void apply_impulses(std::span<const BodyModel> models, const JointSystem& system,
                    std::span<const Vec3> linear, std::span<const Vec3> angular, double weight,
                    bool momenta, std::span<BodyState> states) {
  for (std::uint32_t i = 0; i < states.size(); ++i) {
    if (models[i].is_static) continue;
    if (linear[i].isZero() && angular[i].isZero()) continue;
    PrimaryState primary = states[i].primary();
    if (momenta) {
      primary.momentum += linear[i];
      primary.angular_momentum += angular[i];
    }
    if (weight != 0.0) {
      primary.position += weight * system.inverse_mass(i) * linear[i];
      primary.orientation =
          rotated(primary.orientation, weight * (system.inverse_inertia(i) * angular[i]))
              .normalized();
    }
    states[i] = BodyState(primary, models[i].constants);
  }
}

// Sums λ along each row into per-body impulses.
void gather(const std::vector<JointRow>& rows, const Eigen::VectorXd& lambda,
            std::vector<Vec3>& linear, std::vector<Vec3>& angular) {
  std::fill(linear.begin(), linear.end(), Vec3::Zero());
  std::fill(angular.begin(), angular.end(), Vec3::Zero());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    const double l = lambda[static_cast<Eigen::Index>(r)];
    linear[row.a] += l * row.linear_a;
    angular[row.a] += l * row.angular_a;
    if (row.b != kWorldBody) {
      linear[row.b] += l * row.linear_b;
      angular[row.b] += l * row.angular_b;
    }
  }
}

// Step 2: limits, motors and ranges by sequential impulses with the equality rows, at `states`;
// momenta changed, poses moved by weight × the velocity change.
void solve_bounded(double dt, double weight, JointWorld& world, std::span<BodyState> states) {
  const std::span<const BodyModel> models = world.models;
  std::vector<BoundedRow> rows;
  std::vector<OneSided> sides;
  for (std::uint32_t j = 0; j < world.local.size(); ++j) {
    const Joint& joint = world.local[j];
    const JointBodies at = bodies_of(joint, states);
    sides.clear();
    one_sided_rows(joint, at.a, at.b, sides);
    for (const OneSided& side : sides) {
      // Speculative while apart: the gap may close within the step, and no further.
      rows.push_back({.row = side.row,
                      .lowest = 0.0,
                      .target = -std::max(side.row.error, 0.0) / dt,
                      .joint = j,
                      .memory = side.memory});
    }
    if (joint.motor) {
      const double most = joint.motor->max_effort * dt;
      rows.push_back({.row = coordinate_row(joint, at.a, at.b),
                      .lowest = -most,
                      .highest = most,
                      .target = joint.motor->speed,
                      .joint = j,
                      .memory = &JointImpulses::motor});
    }
  }
  if (rows.empty()) return;
  world.system.build(world.local, models, states);
  for (const JointRow& row : world.system.rows()) rows.push_back({.row = row});
  const JointSystem& system = world.system;
  // Velocities while solving.
  std::vector<Vec3> v(states.size()), w(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    v[i] = states[i].velocity();
    w[i] = states[i].angular_velocity();
  }
  const auto push = [&](const BoundedRow& r, double impulse) {
    const JointRow& row = r.row;
    v[row.a] += system.inverse_mass(row.a) * impulse * row.linear_a;
    w[row.a] += system.inverse_inertia(row.a) * (impulse * row.angular_a);
    if (row.b != kWorldBody) {
      v[row.b] += system.inverse_mass(row.b) * impulse * row.linear_b;
      w[row.b] += system.inverse_inertia(row.b) * (impulse * row.angular_b);
    }
  };
  for (BoundedRow& r : rows) {
    const JointRow& row = r.row;
    double inverse = system.inverse_mass(row.a) * row.linear_a.squaredNorm() +
                     row.angular_a.dot(system.inverse_inertia(row.a) * row.angular_a);
    if (row.b != kWorldBody) {
      inverse += system.inverse_mass(row.b) * row.linear_b.squaredNorm() +
                 row.angular_b.dot(system.inverse_inertia(row.b) * row.angular_b);
    }
    r.mass = inverse > 0.0 ? 1.0 / inverse : 0.0;
    if (r.memory) {
      r.impulse = std::clamp(world.impulses[r.joint].*r.memory, r.lowest, r.highest);
      push(r, r.impulse);
    }
  }
  for (int pass = 0; pass < kJointPasses; ++pass) {
    double largest = 0.0, change = 0.0;
    for (BoundedRow& r : rows) {
      const JointRow& row = r.row;
      double rate = row.linear_a.dot(v[row.a]) + row.angular_a.dot(w[row.a]);
      if (row.b != kWorldBody) rate += row.linear_b.dot(v[row.b]) + row.angular_b.dot(w[row.b]);
      const double wanted = r.impulse + r.mass * (r.target - rate);
      // A one-sided row only stops the approach past its target; others reach it.
      const double next = std::clamp(wanted, r.lowest, r.highest);
      const double delta = next - r.impulse;
      r.impulse = next;
      push(r, delta);
      largest = std::max(largest, std::abs(next));
      change = std::max(change, std::abs(delta));
    }
    if (change <= kJointTolerance * largest) break;
  }
  for (JointImpulses& memory : world.impulses) memory = {};
  std::vector<Vec3> linear(states.size(), Vec3::Zero()), angular(states.size(), Vec3::Zero());
  for (const BoundedRow& r : rows) {
    if (r.memory) world.impulses[r.joint].*r.memory = r.impulse;
    const JointRow& row = r.row;
    linear[row.a] += r.impulse * row.linear_a;
    angular[row.a] += r.impulse * row.angular_a;
    if (row.b != kWorldBody) {
      linear[row.b] += r.impulse * row.linear_b;
      angular[row.b] += r.impulse * row.angular_b;
    }
  }
  apply_impulses(models, system, linear, angular, weight, true, states);
}

// Step 3: the poses onto the equality rows and off the passed limits, then the velocities onto
// the equality rows.
void project(JointWorld& world, std::span<BodyState> states) {
  const std::span<const BodyModel> models = world.models;
  JointSystem& system = world.system;
  std::vector<Vec3> linear(states.size()), angular(states.size());
  for (int iteration = 0; iteration < kJointProjectionIterations; ++iteration) {
    system.build_with_passed_limits(world.local, models, states);
    const std::vector<JointRow>& rows = system.rows();
    double worst = 0.0;
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      worst = std::max(worst, std::abs(rows[r].error));
      rhs[static_cast<Eigen::Index>(r)] = -rows[r].error;
    }
    if (worst <= kJointProjectionTolerance || !system.factorise()) break;
    gather(rows, system.solve(rhs), linear, angular);
    apply_impulses(models, system, linear, angular, 1.0, false, states);
  }
  system.build(world.local, models, states);
  const std::vector<JointRow>& rows = system.rows();
  if (rows.empty() || !system.factorise()) return;
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    rhs[static_cast<Eigen::Index>(r)] = -row_rate(rows[r], states);
  }
  gather(rows, system.solve(rhs), linear, angular);
  apply_impulses(models, system, linear, angular, 0.0, true, states);
}

// The smallest moment of inertia (kg m²) of `inertia` (world) about the axes normal to the unit
// `direction`.
double least_moment_across(const Mat3& inertia, const Vec3& direction) {
  Eigen::Index least = 0;
  direction.cwiseAbs().minCoeff(&least);
  const Vec3 u = direction.cross(Vec3::Unit(least)).normalized();
  const Vec3 v = direction.cross(u);
  const double a = u.dot(inertia * u), d = v.dot(inertia * v), b = u.dot(inertia * v);
  return 0.5 * (a + d) - std::hypot(0.5 * (a - d), b);
}

}  // namespace

double fastest_joint_mode(std::span<const Joint> joints, std::span<const BodyModel> models,
                          std::span<const BodyState> states, double t, JointSystem& system) {
  std::vector<Wrench> wrenches(states.size());
  for (const Joint& joint : joints) {
    if (joint.kind == JointKind::distance && joint.stiffness > 0.0) {
      add_spring(joint, states, wrenches);
    }
  }
  Eigen::VectorXd lambda;
  solve_forces(joints, models, states, t, system, wrenches, lambda);
  // Each joint's force and moment (about the body's centre) on its two bodies.
  std::vector<Wrench> on_a(joints.size()), on_b(joints.size());
  const std::vector<JointRow>& rows = system.rows();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    const double l = lambda[static_cast<Eigen::Index>(r)];
    on_a[row.joint].force += l * row.linear_a;
    on_a[row.joint].torque += l * row.angular_a;
    on_b[row.joint].force += l * row.linear_b;
    on_b[row.joint].torque += l * row.angular_b;
  }
  // ω² of body i: Σ over its joints of the geometric stiffness of the force F at arm r, |F||r|
  // over the moment across r, of a pure moment over the least moment, of a rod's pull F over
  // m ℓ, and of a spring k over m.
  std::vector<double> squared(states.size(), 0.0);
  const auto add = [&](const Joint& joint, std::uint32_t i, const Vec3& anchor,
                       const Wrench& wrench) {
    if (i == kWorldBody || models[i].is_static) return;
    const BodyConstants& c = models[i].constants;
    const Mat3 rotation = states[i].rotation();
    const Vec3 arm = rotation * anchor;
    const Mat3 inertia = rotation * c.inertia.asDiagonal() * rotation.transpose();
    const double force = wrench.force.norm();
    double sum = (wrench.torque - arm.cross(wrench.force)).norm() / c.inertia.minCoeff();
    if (arm.norm() > 0.0)
      sum += force * arm.norm() / least_moment_across(inertia, arm.normalized());
    if (joint.kind == JointKind::distance) {
      const double length = std::max(joint.max_length, joint.min_length);
      if (length > 0.0) sum += force * c.inverse_mass / length;
      sum += joint.stiffness * c.inverse_mass;
    }
    squared[i] += sum;
  };
  for (std::size_t j = 0; j < joints.size(); ++j) {
    add(joints[j], joints[j].a, joints[j].anchor_a, on_a[j]);
    add(joints[j], joints[j].b, joints[j].anchor_b, on_b[j]);
  }
  double most = 0.0;
  for (const double w2 : squared) most = std::max(most, w2);
  return std::sqrt(most);
}

void JointForces::add(std::span<const BodyState> states, double t,
                      std::span<Wrench> wrenches) const {
  for (const Joint& joint : joints_) {
    if (joint.kind == JointKind::distance && joint.stiffness > 0.0) {
      add_spring(joint, states, wrenches);
    }
  }
  Eigen::VectorXd lambda;
  solve_forces(joints_, models_, states, t, system_, wrenches, lambda);
}

std::vector<Wrench> joint_wrenches(const JointWorld& world, std::span<const BodyState> states,
                                   double t) {
  std::vector<BodyState> local;
  for (const std::uint32_t i : world.members) local.push_back(states[i]);
  const std::span<const BodyModel> models = world.models;
  JointSystem system;
  std::vector<Wrench> body_wrenches(local.size());
  for (const Joint& joint : world.local) {
    if (joint.kind == JointKind::distance && joint.stiffness > 0.0) {
      add_spring(joint, local, body_wrenches);
    }
  }
  Eigen::VectorXd lambda;
  solve_forces(world.local, models, local, t, system, body_wrenches, lambda);
  std::vector<Wrench> out(world.local.size());
  const std::vector<JointRow>& rows = system.rows();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double l = lambda[static_cast<Eigen::Index>(r)];
    out[rows[r].joint].force += l * rows[r].linear_a;
    out[rows[r].joint].torque += l * rows[r].angular_a;
  }
  for (std::size_t j = 0; j < world.local.size(); ++j) {
    const Joint& joint = world.local[j];
    if (joint.kind == JointKind::distance && joint.stiffness > 0.0) {
      std::vector<Wrench> one(local.size());
      add_spring(joint, local, one);
      out[j].force += one[joint.a].force;
      out[j].torque += one[joint.a].torque;
    }
    if (j < world.impulses.size() && world.substep > 0.0) {
      const JointBodies at = bodies_of(joint, local);
      const JointRow along = coordinate_row(joint, at.a, at.b);
      const JointImpulses& i = world.impulses[j];
      const double net = i.lower - i.upper + i.motor;
      out[j].force += net / world.substep * along.linear_a;
      out[j].torque += net / world.substep * along.angular_a;
    }
  }
  return out;
}

JointWorld make_joint_world(std::vector<Joint> joints, std::span<const BodyModel> models) {
  JointWorld world;
  std::vector<std::uint32_t> local_of(models.size(), kWorldBody);
  for (const Joint& joint : joints) {
    local_of[joint.a] = 0;
    if (joint.b != kWorldBody) local_of[joint.b] = 0;
  }
  for (std::uint32_t i = 0; i < models.size(); ++i) {
    if (local_of[i] == kWorldBody) continue;
    local_of[i] = static_cast<std::uint32_t>(world.members.size());
    world.members.push_back(i);
    world.models.push_back(models[i]);
  }
  world.held.assign(models.size(), 0);
  for (const std::uint32_t i : world.members) world.held[i] = 1;
  for (const Joint& joint : joints) {
    if (joint.collide_connected || joint.b == kWorldBody) continue;
    world.unpaired.push_back({std::min(joint.a, joint.b), std::max(joint.a, joint.b)});
  }
  std::sort(world.unpaired.begin(), world.unpaired.end());
  world.local = joints;
  for (Joint& joint : world.local) {
    joint.a = local_of[joint.a];
    if (joint.b != kWorldBody) joint.b = local_of[joint.b];
  }
  world.joints = std::move(joints);
  world.impulses.resize(world.joints.size());
  return world;
}

int joint_substeps(double fastest, double dt) {
  const double wanted = std::ceil(fastest * dt / kStableTurn);
  return static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(kMostJointSubsteps)));
}

namespace {

// Symplectic Euler with the joints at the velocity level, from world.start to world.end over h
// (s): each body's kick by its own laws (and the springs'), the velocities onto J v = 0 at the
// start pose (one solve with K: the joints' impulses over the step, implicit in the velocities),
// the limits and motors, the drift with the new velocities, then the projection.
void symplectic_joint_step(double t, double h, JointWorld& world) {
  const std::span<const BodyModel> models = world.models;
  const std::size_t n = world.members.size();
  std::vector<Wrench> springs(n);
  for (const Joint& joint : world.local) {
    if (joint.kind == JointKind::distance && joint.stiffness > 0.0) {
      add_spring(joint, world.start, springs);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (models[i].is_static) {
      world.end[i] = world.start[i];
      continue;
    }
    const Wrench own = total_wrench(models[i].forces, models[i].constants, world.start[i], t);
    PrimaryState kicked = world.start[i].primary();
    kicked.momentum += h * (own.force + springs[i].force);
    kicked.angular_momentum += h * (own.torque + springs[i].torque);
    world.end[i] = BodyState(kicked, models[i].constants);
  }
  JointSystem& system = world.system;
  system.build(world.local, models, world.end);
  const std::vector<JointRow>& rows = system.rows();
  if (!rows.empty() && system.factorise()) {
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      rhs[static_cast<Eigen::Index>(r)] = -row_rate(rows[r], world.end);
    }
    std::vector<Vec3> linear(n), angular(n);
    gather(rows, system.solve(rhs), linear, angular);
    apply_impulses(models, system, linear, angular, 0.0, true, world.end);
  }
  solve_bounded(h, 0.0, world, world.end);
  for (std::size_t i = 0; i < n; ++i) {
    if (models[i].is_static) continue;
    PrimaryState moved = world.end[i].primary();
    moved.position += h * world.end[i].velocity();
    moved.orientation.coeffs() += h * world.end[i].spin().coeffs();
    world.end[i] = BodyState(moved, models[i].constants);
  }
  project(world, world.end);
}

}  // namespace

void advance_joint_members(Integrator integrator, std::span<const BodyState> in, double t,
                           double dt, JointWorld& world, std::span<BodyState> out) {
  const std::size_t n = world.members.size();
  world.start.resize(n);
  world.end.resize(n);
  for (std::size_t k = 0; k < n; ++k) world.start[k] = in[world.members[k]];
  const std::span<const BodyModel> models = world.models;
  const int substeps =
      joint_substeps(fastest_joint_mode(world.local, models, world.start, t, world.system), dt);
  const double h = dt / substeps;
  world.substep = h;
  if (integrator == Integrator::symplectic_euler) {
    for (int k = 0; k < substeps; ++k) {
      symplectic_joint_step(t + k * h, h, world);
      world.start.swap(world.end);
    }
    for (std::size_t k = 0; k < n; ++k) out[world.members[k]] = world.start[k];
    return;
  }
  const JointForces forces(world.local, models, world.system);
  for (int k = 0; k < substeps; ++k) {
    step_coupled(integrator, models, world.start, t + k * h, h, forces, world.end);
    for (std::size_t i = 0; i < n; ++i) {
      if (models[i].is_static) world.end[i] = world.start[i];
    }
    solve_bounded(h, impulse_position_weight(integrator, h), world, world.end);
    project(world, world.end);
    world.start.swap(world.end);
  }
  for (std::size_t k = 0; k < n; ++k) out[world.members[k]] = world.start[k];
}

void hold_joint_members(Integrator integrator, double dt, JointWorld& world,
                        std::span<BodyState> states) {
  const std::size_t n = world.members.size();
  world.end.resize(n);
  for (std::size_t k = 0; k < n; ++k) world.end[k] = states[world.members[k]];
  world.substep = dt;
  solve_bounded(dt, impulse_position_weight(integrator, dt), world, world.end);
  project(world, world.end);
  for (std::size_t k = 0; k < n; ++k) states[world.members[k]] = world.end[k];
}

void project_joint_members(JointWorld& world, std::span<BodyState> states) {
  const std::size_t n = world.members.size();
  world.end.resize(n);
  for (std::size_t k = 0; k < n; ++k) world.end[k] = states[world.members[k]];
  project(world, world.end);
  for (std::size_t k = 0; k < n; ++k) states[world.members[k]] = world.end[k];
}

void step_joints(Integrator integrator, std::span<const BodyModel> models,
                 std::span<const BodyState> in, double t, double dt, JointWorld& world,
                 std::span<BodyState> out) {
  std::size_t next = 0;  // the next member
  for (std::uint32_t i = 0; i < models.size(); ++i) {
    if (next < world.members.size() && world.members[next] == i) {
      ++next;
      continue;
    }
    out[i] = models[i].is_static ? in[i] : step(integrator, models[i], in[i], t, dt);
  }
  advance_joint_members(integrator, in, t, dt, world, out);
}

}  // namespace tumble::physics
