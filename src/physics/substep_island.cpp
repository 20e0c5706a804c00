#include "physics/substep_island.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "physics/step_context.hpp"

namespace tumble::physics {
namespace {

// The projection of a sub-step passes again while a point was deeper than the tolerance when a
// pass reached it, up to the most passes: a settled pile, 0.6 mm inside, takes one; a box landing
// at 20 m/s drives the one it hits centimetres into the next within a sub-step, and a pass moves
// that push one contact along (m).
constexpr double kProjectionTolerance = 0.002;
constexpr int kMostProjectionPasses = 8;

// Into `out`, each point's separation (m) at the bodies' poses: their centres and the rotations
// in `rotations`.
const Vec3& centre(const SubstepBody& body) {
  return body.state.position();
}
const Vec3& centre(const ProjectedPose& pose) {
  return pose.primary.position;
}

template <class Body>
void measure(std::span<const Body> bodies, std::span<const Mat3> rotations,
             std::span<const PositionPoint> positions, std::vector<double>& out) {
  out.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const PositionPoint& p = positions[i];
    double s = p.base + p.normal.dot(centre(bodies[p.a]) + rotations[p.a] * p.anchor_a);
    if (p.b != kStatic) s -= p.normal.dot(centre(bodies[p.b]) + rotations[p.b] * p.anchor_b);
    out[i] = s;
  }
}

// Scales every accumulated impulse of the points and patches by `factor`.
void scale_impulses(std::span<ContactConstraint> points, std::span<FrictionPatch> patches,
                    double factor) {
  for (ContactConstraint& c : points) c.normal_impulse *= factor;
  for (FrictionPatch& f : patches) {
    f.tangent_impulse[0] *= factor;
    f.tangent_impulse[1] *= factor;
    f.twist_impulse *= factor;
  }
}

// Whether the body's only forces are gravity, with their sum into `g` (m/s²): its free
// momentum over a sub-step of h is then p + m g h and its angular momentum stays, exactly what
// every integrator gives for a constant force through the centre, without running one.
bool gravity_only(const BodyModel& model, Vec3& g) {
  g = Vec3::Zero();
  for (const ForceLaw& law : model.forces) {
    const auto* gravity = std::get_if<Gravity>(&law);
    if (!gravity) return false;
    g += gravity->acceleration;
  }
  return true;
}

// resolve_impacts for the points at `separations` (m), each apart point allowed to approach at
// its separation over `within` (s).
void impacts(std::span<SolverBody> solver, std::span<ContactConstraint> points,
             std::span<const FrictionPatch> patches, std::span<const double> separations,
             double within, const ContactSettings& settings, std::vector<double>& allowed) {
  allowed.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    allowed[i] = std::max(separations[i], 0.0) / within;
  }
  resolve_impacts(solver, points, patches, allowed, settings.restitution_threshold);
}

}  // namespace

int substeps_for(double reach) {
  const double wanted = std::ceil(reach / kSubstepReach);
  return static_cast<int>(
      std::clamp(wanted, static_cast<double>(kSubsteps), static_cast<double>(kMostSubsteps)));
}

void substep_island(const StepContext& context, int substeps,
                    const std::function<void(int)>& refresh) {
  const Integrator integrator = context.integrator;
  const double t = context.t, dt = context.dt;
  const ContactSettings& settings = context.settings;
  const std::span<SubstepBody> bodies = context.scratch.substep_bodies;
  ContactRows& rows = context.scratch.rows;
  const std::span<SolverBody> solver = rows.bodies;
  const std::span<ContactConstraint> points = rows.points;
  const std::span<const PositionPoint> positions = rows.positions;
  const std::span<FrictionPatch> patches = rows.patches;
  SubstepScratch& scratch = context.scratch.substep;
  const double h = dt / substeps;

  // Warm start: a sub-step's share of the last step's impulses (the rows start from them).
  scale_impulses(points, patches, 1.0 / substeps);

  const std::size_t n = bodies.size();
  // An island of two bodies or more has its normal rows solved as one block where it is small
  // (physics/normal_block.hpp): mass ratios and symmetric impacts.
  const bool by_block = n > 1;
  scratch.size_for(n);
  for (std::size_t i = 0; i < n; ++i) {
    scratch.falls_freely[i] = gravity_only(*bodies[i].model, scratch.gravity[i]);
  }
  for (int substep = 0; substep < substeps; ++substep) {
    if (substep > 0 && refresh) refresh(substep);
    // The forces over the sub-step, by the scene's integrator (or exactly, for gravity alone);
    // its positions are not used: the poses move with the solved velocities below (symplectic
    // Euler, as Box2D's sub-steps do), so a body held still by its contacts stays exactly where
    // it is.
    for (std::size_t i = 0; i < n; ++i) {
      const BodyState& now = bodies[i].state;
      if (scratch.falls_freely[i]) {
        scratch.free_velocity[i] = now.velocity() + h * scratch.gravity[i];
        scratch.free_angular_velocity[i] = now.angular_velocity();
        scratch.free_angular_momentum[i] = now.angular_momentum();
      } else {
        const BodyState free = step(integrator, *bodies[i].model, now, t + substep * h, h);
        scratch.free_velocity[i] = free.velocity();
        scratch.free_angular_velocity[i] = free.angular_velocity();
        scratch.free_angular_momentum[i] = free.primary().angular_momentum;
      }
      solver[i].velocity = scratch.free_velocity[i];
      solver[i].angular_velocity = scratch.free_angular_velocity[i];
      scratch.rotations[i] = now.orientation().toRotationMatrix();
    }
    measure<SubstepBody>(bodies, scratch.rotations, positions, scratch.separations);
    // The impacts of points that close within this sub-step or by the solve after its move (whose
    // speculative rows would take their approach as a contact without restitution), at once
    // (resolve_impacts), from the velocities before the warm start: the warm start's impulses
    // are a guess that the passes may take back, and an approach they make is no impact (taken
    // as one, its bounce stayed when the guess was taken back, and a settling pile of 1000 boxes
    // still moved at 1 m/s after 10 s).
    for (ContactConstraint& c : points) c.impact_impulse = 0.0;
    for (FrictionPatch& f : patches) f.rolling_impulse[0] = f.rolling_impulse[1] = 0.0;
    impacts(solver, points, patches, scratch.separations, 2.0 * h, settings, scratch.allowed);
    warm_start(solver, points, patches);
    substep_pass(solver, points, scratch.separations, patches, h, by_block);

    scratch.poses.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      PrimaryState primary = bodies[i].state.primary();
      primary.position += h * solver[i].velocity;
      primary.orientation =
          rotated(primary.orientation, h * solver[i].angular_velocity).normalized();
      scratch.poses[i] = {.primary = primary,
                          .inverse_mass = bodies[i].model->constants.inverse_mass,
                          .solved = &solver[i]};
    }
    for (int pass = 0; pass < kMostProjectionPasses; ++pass) {
      if (project_pass(scratch.poses, positions) > -kProjectionTolerance) break;
    }
    for (std::size_t i = 0; i < n; ++i) {
      scratch.rotations[i] = scratch.poses[i].primary.orientation.toRotationMatrix();
    }
    measure<ProjectedPose>(scratch.poses, scratch.rotations, positions, scratch.separations);
    substep_pass(solver, points, scratch.separations, patches, h, by_block);

    for (std::size_t i = 0; i < n; ++i) {
      PrimaryState& primary = scratch.poses[i].primary;
      primary.momentum = solver[i].linear_impulse(Vec3::Zero());  // m v
      primary.angular_momentum = scratch.free_angular_momentum[i] +
                                 solver[i].angular_impulse(scratch.free_angular_velocity[i]);
      bodies[i].state = BodyState(primary, bodies[i].model->constants);
    }
  }

  scale_impulses(points, patches, substeps);
}

}  // namespace tumble::physics
