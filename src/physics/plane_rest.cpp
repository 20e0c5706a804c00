#include "physics/plane_rest.hpp"

#include <algorithm>
#include <cmath>

#include "physics/contact_island.hpp"
#include "physics/contact_solver.hpp"
#include "physics/plane_contact_step.hpp"

namespace tumble::physics {
namespace {

constexpr int kMostPoints = kMostRestingPlanes * kMaxManifoldPoints;

// The body through the solve: the island solve's SolverBody (velocities, mass, world tensors),
// and for a cube (constants.isotropic) its inverse inertia as the scalar it is in every frame.
struct Body : SolverBody {
  bool isotropic;
  double scalar_inverse_inertia;

  Vec3 turn(const Vec3& moment) const {
    return isotropic ? Vec3(scalar_inverse_inertia * moment) : Vec3(inverse_inertia * moment);
  }
  // An impulse λ along a row, given its d and I⁻¹(r × d): ImpulseDirection's rule with no
  // second body.
  void push(const Vec3& linear, const Vec3& turn, double impulse) {
    velocity += inverse_mass * (impulse * linear);
    angular_velocity += impulse * turn;
  }
};

// A direction the contact pushes the body in, at an arm r from its centre: d, r × d, I⁻¹(r × d)
// and the effective mass 1 / (1/m + (r × d)·I⁻¹(r × d)).
struct Row {
  Vec3 linear;
  Vec3 moment;
  Vec3 turn;
  double mass;

  Row() = default;
  Row(const Body& body, const Vec3& arm, const Vec3& along)
      : linear(along), moment(arm.cross(along)), turn(body.turn(moment)) {
    const double inverse = body.inverse_mass + moment.dot(turn);
    mass = inverse > 0.0 ? 1.0 / inverse : 0.0;
  }
  double speed(const Body& body) const {
    return body.velocity.dot(linear) + body.angular_velocity.dot(moment);
  }
};

// The friction of one plane's points [first, first + count): two tangents at their centre and a
// twist about the normal, as contact_solver.hpp's FrictionPatch.
struct Patch {
  std::size_t plane;
  int first, count;
  double friction, twist_arm;
  Row tangent[2];
  Vec3 twist_axis, twist_turn;
  double twist_mass;
  double tangent_impulse[2];
  double twist_impulse;
};

// Everything one step builds: the normal rows and their impulses, the patches.
struct Rows {
  int points = 0, patches = 0;
  Row normal[kMostPoints];
  double impulse[kMostPoints];
  Patch patch[kMostRestingPlanes];
};

// One pass over the patches, as contact_solver.cpp's inelastic_pass; returns the largest change
// of an accumulated impulse.
double pass(Body& body, Rows& rows) {
  double largest = 0.0;
  for (int p = 0; p < rows.patches; ++p) {
    Patch& f = rows.patch[p];
    double normal = 0.0;
    for (int i = f.first; i < f.first + f.count; ++i) {
      const Row& row = rows.normal[i];
      const double accumulated = std::max(0.0, rows.impulse[i] - row.mass * row.speed(body));
      const double change = accumulated - rows.impulse[i];
      rows.impulse[i] = accumulated;
      body.push(row.linear, row.turn, change);
      largest = std::max(largest, std::abs(change));
      normal += accumulated;
    }
    // Circular cone: both tangent impulses together within μ λ_n.
    double wanted[2];
    for (int k = 0; k < 2; ++k) {
      wanted[k] = f.tangent_impulse[k] - f.tangent[k].mass * f.tangent[k].speed(body);
    }
    const double limit = f.friction * normal;
    const double size_squared = wanted[0] * wanted[0] + wanted[1] * wanted[1];
    const double scale = size_squared > limit * limit ? limit / std::sqrt(size_squared) : 1.0;
    for (int k = 0; k < 2; ++k) {
      const double change = wanted[k] * scale - f.tangent_impulse[k];
      body.push(f.tangent[k].linear, f.tangent[k].turn, change);
      f.tangent_impulse[k] += change;
      largest = std::max(largest, std::abs(change));
    }
    const double twist_limit = limit * f.twist_arm;
    const double twist =
        std::clamp(f.twist_impulse - f.twist_mass * body.angular_velocity.dot(f.twist_axis),
                   -twist_limit, twist_limit);
    const double change = twist - f.twist_impulse;
    body.angular_velocity += change * f.twist_turn;
    f.twist_impulse = twist;
    largest = std::max(largest, std::abs(change));
  }
  return largest;
}

}  // namespace

bool rest_alone_on_planes(const BodyModel& model, const BodyState& end, const Mat3& rotation,
                          double weight, const std::vector<Plane>& planes,
                          const ContactSettings& settings, PlaneContacts& contacts,
                          BodyState& out) {
  const BodyConstants& constants = model.constants;
  Body body{SolverBody::from(end, constants, rotation), constants.isotropic,
            constants.inverse_inertia.x()};

  // The rows, warm-started from the last step's manifolds (the same corners, the same plane's
  // friction); nothing is written until the step is known to be one this function takes.
  contacts.found.resize(planes.size());
  Rows rows;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    Manifold& found = contacts.found[p];
    found = box_plane_manifold(contacts.separations[p], model.half_size, kTouchingDistance);
    if (found.count == 0) continue;
    if (rows.patches == kMostRestingPlanes) return false;
    const Plane& plane = planes[p];
    const Material material = combine(model.material, plane.material);
    const Manifold& last = contacts.manifolds[p];
    Vec3 arms[kMaxManifoldPoints];
    for (int k = 0; k < found.count; ++k) {
      ContactPoint& point = found.points[static_cast<std::size_t>(k)];
      arms[k] = rotation * point.body_point;
      const Row& row = rows.normal[rows.points + k] = Row(body, arms[k], plane.normal);
      if (material.restitution > 0.0 && row.speed(body) < -settings.restitution_threshold) {
        return false;  // a bounce: the island solve's, with its energy guard
      }
      double impulse = 0.0;
      for (int j = 0; j < last.count; ++j) {
        if (last.points[static_cast<std::size_t>(j)].feature == point.feature) {
          impulse = last.points[static_cast<std::size_t>(j)].impulses.normal;
        }
      }
      rows.impulse[rows.points + k] = impulse;
    }
    const PatchShape shape =
        patch_shape({arms, static_cast<std::size_t>(found.count)}, plane.normal);
    Vec3 tangents[2];
    tangent_basis(plane.normal, tangents);
    const PatchImpulses warm = last.count > 0 ? last.friction : PatchImpulses{};
    Patch& patch = rows.patch[rows.patches++];
    patch = {.plane = p,
             .first = rows.points,
             .count = found.count,
             .friction = material.friction,
             .twist_arm = shape.twist_arm,
             .tangent = {Row(body, shape.centre_arm, tangents[0]),
                         Row(body, shape.centre_arm, tangents[1])},
             .twist_axis = plane.normal,
             .twist_turn = body.turn(plane.normal),
             .twist_mass = 0.0,
             .tangent_impulse = {warm.tangent.dot(tangents[0]), warm.tangent.dot(tangents[1])},
             .twist_impulse = warm.twist};
    const double twist_inverse = plane.normal.dot(patch.twist_turn);
    patch.twist_mass = twist_inverse > 0.0 ? 1.0 / twist_inverse : 0.0;
    rows.points += found.count;
  }

  // The solve, warm-started: the last step's impulses first, then passes until one changes no
  // impulse by more than kRestingTolerance of the largest.
  for (int i = 0; i < rows.points; ++i) {
    body.push(rows.normal[i].linear, rows.normal[i].turn, rows.impulse[i]);
  }
  for (int p = 0; p < rows.patches; ++p) {
    Patch& f = rows.patch[p];
    for (int k = 0; k < 2; ++k)
      body.push(f.tangent[k].linear, f.tangent[k].turn, f.tangent_impulse[k]);
    body.angular_velocity += f.twist_impulse * f.twist_turn;
  }
  const int passes = solver_passes(static_cast<std::size_t>(rows.points));
  for (int n = 0; n < passes; ++n) {
    const double change = pass(body, rows);
    double largest = 0.0;
    for (int i = 0; i < rows.points; ++i) largest = std::max(largest, rows.impulse[i]);
    if (change <= kRestingTolerance * largest) break;
  }

  // This step's manifolds, with their impulses, for the next step to start from.
  contacts.manifolds.swap(contacts.found);
  for (int p = 0; p < rows.patches; ++p) {
    const Patch& f = rows.patch[p];
    Manifold& manifold = contacts.manifolds[f.plane];
    for (int k = 0; k < f.count; ++k) {
      manifold.points[static_cast<std::size_t>(k)].impulses.normal = rows.impulse[f.first + k];
    }
    manifold.friction = {.tangent = f.tangent_impulse[0] * f.tangent[0].linear +
                                    f.tangent_impulse[1] * f.tangent[1].linear,
                         .twist = f.twist_impulse};
  }

  // The pose moved by what the impulses did over the step, its momenta by the impulses.
  const Vec3 dv = body.velocity - end.velocity();
  const Vec3 dw = body.angular_velocity - end.angular_velocity();
  PrimaryState primary = end.primary();
  primary.momentum = without_residue(primary.momentum + body.linear_impulse(end.velocity()));
  primary.angular_momentum =
      without_residue(primary.angular_momentum + body.angular_impulse(end.angular_velocity()));
  primary.position += weight * dv;
  primary.orientation = rotated(primary.orientation, weight * dw);

  // The projection: each point still inside pushed out along its normal by a position-level
  // impulse (contact_island.hpp's project_pass, with the inverse inertia the rows had).
  for (int iteration = 0; iteration < kProjectionIterations; ++iteration) {
    bool inside = false;
    for (int p = 0; p < rows.patches; ++p) {
      const Patch& f = rows.patch[p];
      const Plane& plane = planes[f.plane];
      const Manifold& manifold = contacts.manifolds[f.plane];
      for (int k = 0; k < f.count; ++k) {
        const Vec3 arm =
            primary.orientation * manifold.points[static_cast<std::size_t>(k)].body_point;
        const double separation = plane.normal.dot(primary.position + arm) - plane.offset;
        if (separation >= 0.0) continue;
        inside = true;
        const Vec3 moment = arm.cross(plane.normal);
        const Vec3 turn = body.turn(moment);
        const double push = -separation / (constants.inverse_mass + moment.dot(turn));  // kg m
        primary.position += (push * constants.inverse_mass) * plane.normal;
        primary.orientation = rotated(primary.orientation, push * turn).normalized();
      }
    }
    if (!inside) break;
  }
  out = BodyState(primary, constants);
  return true;
}

}  // namespace tumble::physics
