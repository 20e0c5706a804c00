// Contact between bodies (boxes) and static planes: the settings a scene chooses, the contact
// points of a box against a plane, and the manifold that carries them from step to step.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "physics/rigid_body.hpp"
#include "physics/shapes.hpp"

namespace tumble::physics {

enum class ContactMethod {
  // Velocity-level impulses (sequential impulses with accumulated clamping, Catto 2005), impacts
  // at their time of impact, and a position projection that moves no momentum (physics/world.hpp).
  impulse,
  // Fiedler's "Spring Physics": a damped spring at each penetrating corner and a regularised
  // Coulomb friction, evaluated as a force inside the integrator (physics/penalty_contact.hpp).
  penalty,
};

struct ContactSettings {
  ContactMethod method = ContactMethod::impulse;
  // Penalty only. A 1 kg unit cube resting on four corners sinks m g / (4 k) = 0.025 mm at the
  // default stiffness. On four corners k and c both count four times, so a flat landing has
  // ζ = c / sqrt(k m) = 0.47 and bounces back with e ≈ 0.3 (the law's own restitution,
  // exp(−2ζ acos ζ / sqrt(1 − ζ²)), sim/penalty_modes.hpp); 500 N s/m would be overdamped
  // (ζ = 1.6), which also shortens the stable step. The stiff spring needs a small step:
  // about dt <= 4 ms for rk4 with a 1 kg cube (tumble check says so).
  double stiffness = 1.0e5;  // k per penetrating corner (N/m)
  double damping = 150.0;    // c per penetrating corner (N s/m)
  // Impulse only. Impacts slower than this along the normal do not bounce: a resting contact
  // must not chatter. 0.5 m/s lets a bounce test keep bounces at 1.1 m/s (Box2D's 1 m/s would
  // not), and stays above the 0.16 m/s that gravity adds in one 1/60 s step, which PhysX names as
  // the floor for it.
  double restitution_threshold = 0.5;  // m/s
  // Bodies collide with each other (each body's BodyModel::collides too); false: they only
  // touch planes, as before contact between bodies existed.
  bool collide_bodies = true;
  // Impulse only. An island of touching bodies that has stayed still for a while falls asleep:
  // its steps cost nothing, and it keeps its pose exactly, until a body that is awake touches it
  // (physics/world_step.hpp says when). false: every body is stepped at every step.
  bool sleep = true;
};

// The methods in the order they are listed to users.
inline constexpr ContactMethod kAllContactMethods[] = {ContactMethod::impulse,
                                                       ContactMethod::penalty};

// The name of a method in scene files ("impulse", "penalty").
const char* contact_method_name(ContactMethod method);

// What the last solve of a contact point accumulated, kept for warm starting the next step.
struct Impulses {
  double normal = 0.0;  // N s, >= 0
};

// What the last solve of a manifold's friction accumulated (physics/contact_solver.hpp: friction
// acts on a manifold as a whole, at its centre), kept for warm starting the next step.
struct PatchImpulses {
  Vec3 tangent = Vec3::Zero();  // N s, world frame, normal to the contact normal
  double twist = 0.0;           // about the normal (N m s)
};

// A corner of a box touching (or about to touch) a plane.
struct ContactPoint {
  int feature = 0;                 // the corner: bit i set means +half_size on body axis i
  Vec3 body_point = Vec3::Zero();  // the corner relative to the centre, body frame (m)
  double separation = 0.0;         // along the plane normal; negative when inside (m)
  Impulses impulses;
};

// A manifold's twist arm as last computed (physics/contact_rows.cpp), kept with the manifold from
// step to step: a patch of the same points, spread as far about their centre, does not compute
// it again (its exact form takes a sort, eight asinh and as many square roots: a quarter of a
// resting box's step).
struct PatchMemo {
  std::uint64_t points = 0;  // the points' count and features (0: nothing remembered)
  double spread = 0.0;       // Σ |r − c|² over the points' arms r about their centre c (m²)
  double twist_arm = 0.0;    // m
};

// At most four points: the four lowest corners are enough to hold a box still on a face.
inline constexpr int kMaxManifoldPoints = 4;

// The contact between one body and one plane.
struct Manifold {
  int count = 0;
  std::array<ContactPoint, kMaxManifoldPoints> points;
  PatchImpulses friction;
  PatchMemo patch;
};

// The separation from a plane (m, negative inside) of each corner of a box, indexed by corner
// (`corner` below): `rotation` body to world, `position` the centre (m, world), `half_size` half
// the edge lengths along the body axes (m).
using CornerSeparations = std::array<double, 8>;
CornerSeparations corner_separations(const Mat3& rotation, const Vec3& position,
                                     const Vec3& half_size, const Plane& plane);

// The features whose separation is below `margin` (m), the deepest first, at most four (their
// body points left for the caller).
Manifold deepest_features(const CornerSeparations& separations, double margin);

// The corners whose separation is below `margin` (m), the deepest first, at most four.
Manifold box_plane_manifold(const CornerSeparations& separations, const Vec3& half_size,
                            double margin);

// A cylinder's points against a plane lie on the rims of its ends, along two directions across
// its axis (body frame): `down`, towards the plane (where the rim is lowest), and `side`, a quarter
// turn on. Features 0–3 are the −y end's rim at down, side, −down, −side; 4–7 the +y end's. Lying
// on its side a cylinder touches at its two `down` points; standing on an end, at that end's four
// (then fixed in the body: down is body x); tilted, at one. The points move on the rim as it rolls:
// they are found again at each step.
struct RimFrame {
  Vec3 down, side;  // unit, body frame, across the axis
};
RimFrame rim_frame(const Mat3& rotation, const Vec3& normal);
Vec3 rim_point(const Shape& cylinder, const RimFrame& frame, int feature);

// A hull's corners against a plane of unit `normal`, the body at `rotation`: the eight lowest
// (fewer for a hull of fewer corners: −1 past them), lowest first, a tie in index order, and their
// heights along the normal above the centre (m; +∞ past the corners). plane_separations gives a
// hull's features in this order; a manifold's points are named by their corner's index.
struct HullRanks {
  std::array<int, 8> corner;
  std::array<double, 8> height;
};
HullRanks lowest_hull_corners(const ConvexHull& hull, const Mat3& rotation, const Vec3& normal);

// A hull's manifold against a plane from its separations in rank order: those below `margin`, at
// most four (the deepest, then those that widen the patch most).
Manifold hull_plane_manifold(const ConvexHull& hull, const CornerSeparations& separations,
                             const Mat3& rotation, const Vec3& normal, double margin);

// The lowest separation of any corner of the box from the plane (m; negative inside).
double closest_corner_separation(const BodyState& state, const Vec3& half_size, const Plane& plane);

// The same for any shape, indexed by feature: a box's eight corners; a sphere's one point nearest
// the plane (feature 0; the others +∞); a capsule's nearest points at its two ends (features 0 and
// 1, the −y and +y ends); a cylinder's eight rim points (RimFrame); a hull's eight lowest corners
// (HullRanks). `rotation` body to world, `position` the centre (m).
CornerSeparations plane_separations(const Shape& shape, const Mat3& rotation, const Vec3& position,
                                    const Plane& plane);

// The manifold of the shape's points (from plane_separations) below `margin` (m), the body at
// `rotation` against a plane of unit `normal`: a box's corners as box_plane_manifold gives them; a
// cylinder's rim points (RimFrame); a round shape's core points (plane_point: a sphere's centre, a
// capsule's two end centres), whose touching point stands the radius below each along the plane's
// normal and moves on the surface as the body rolls.
Manifold plane_manifold(const Shape& shape, const CornerSeparations& separations,
                        const Mat3& rotation, const Vec3& normal, double margin);

// The lowest separation of the shape at `state` from the plane (m; negative inside).
double closest_separation(const BodyState& state, const Shape& shape, const Plane& plane);

// A shape's point `feature` (of plane_separations, the body at `rotation` against a plane of unit
// `normal`) as a core point fixed in the body (m, body frame) with `radius` (m) of rounding around
// it: the point that touches the plane is core − radius Rᵀn. A box's corners and a cylinder's rim
// points have no rounding; a sphere is its centre and its radius; a capsule's features are its two
// end centres, each with its radius.
struct RoundedPoint {
  Vec3 core = Vec3::Zero();
  double radius = 0.0;
};
RoundedPoint plane_point(const Shape& shape, int feature, const Mat3& rotation, const Vec3& normal);

// The body-frame offset of corner `feature` (bit i: sign along body axis i).
inline Vec3 corner(const Vec3& half_size, int feature) {
  return Vec3((feature & 1) ? half_size.x() : -half_size.x(),
              (feature & 2) ? half_size.y() : -half_size.y(),
              (feature & 4) ? half_size.z() : -half_size.z());
}

}  // namespace tumble::physics
