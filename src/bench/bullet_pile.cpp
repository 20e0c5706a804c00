#include "bench/bullet_pile.hpp"

#include <btBulletDynamicsCommon.h>

#include <cassert>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>

// CMake defines TUMBLE_BULLET_FLOAT64 when it found bullet-float64.pc, whose flags also define
// BT_USE_DOUBLE_PRECISION; the two disagreeing would mean headers and library of different
// precisions, whose btScalar layouts differ (a crash, not a slow run).
#if defined(TUMBLE_BULLET_FLOAT64) != defined(BT_USE_DOUBLE_PRECISION)
#error "Bullet's headers and the pkg-config module CMake chose disagree on the precision"
#endif

namespace tumble::bench {
namespace {

physics::Material material_of(const btCollisionObject* object) {
  return {.restitution = static_cast<double>(object->getRestitution()),
          .friction = static_cast<double>(object->getFriction())};
}

// Bullet multiplies the two surfaces' friction and restitution (btManifoldResult.cpp), tumble
// takes sqrt(a b) and max(a, b) (physics::combine). Bullet reads these two global hooks for every
// new contact point, so pointing them at tumble's rule gives every pair the values tumble would
// give it, for any materials, not only equal ones. The hooks are process-wide: this guard sets
// them for one run and puts back what was there (the bench runs one world at a time).
btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
  return static_cast<btScalar>(physics::combine(material_of(a), material_of(b)).friction);
}

btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
  return static_cast<btScalar>(physics::combine(material_of(a), material_of(b)).restitution);
}

class TumbleMaterialRule {
 public:
  TumbleMaterialRule()
      : friction_(gCalculateCombinedFrictionCallback),
        restitution_(gCalculateCombinedRestitutionCallback) {
    gCalculateCombinedFrictionCallback = combined_friction;
    gCalculateCombinedRestitutionCallback = combined_restitution;
  }
  ~TumbleMaterialRule() {
    gCalculateCombinedFrictionCallback = friction_;
    gCalculateCombinedRestitutionCallback = restitution_;
  }
  TumbleMaterialRule(const TumbleMaterialRule&) = delete;
  TumbleMaterialRule& operator=(const TumbleMaterialRule&) = delete;

 private:
  CalculateCombinedCallback friction_;
  CalculateCombinedCallback restitution_;
};

btVector3 to_bullet(const physics::Vec3& v) {
  return btVector3(static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()),
                   static_cast<btScalar>(v.z()));
}

physics::Vec3 from_bullet(const btVector3& v) {
  return physics::Vec3(static_cast<double>(v.x()), static_cast<double>(v.y()),
                       static_cast<double>(v.z()));
}

// Bullet's world with every default the issue names: the default collision configuration and
// dispatcher (box-box pairs go to btBoxBoxDetector, ODE's dBoxBox), a dynamic AABB tree broad
// phase, sequential impulses with 10 iterations, split impulse and warm starting on. Box-plane
// pairs go to btConvexPlaneCollisionAlgorithm, which by default finds one new point per step
// (its multipoint perturbation is off until setPlaneConvexMultipointIterations): a box landing
// flat is held by one corner in its first steps and sinks. Kept, as the issue measures Bullet's
// defaults; the sinking shows in the largest penetration.
//
// Members are destroyed in reverse order: the world first (it frees the broad-phase handles of
// the bodies still in it, so the broad phase, the dispatcher and the bodies must outlive it),
// the shapes last (a body points at its shape).
struct BulletWorld {
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> planes;
  std::vector<std::unique_ptr<btRigidBody>> boxes;  // in the pile's order
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
};

// A static plane (mass 0): btStaticPlaneShape is n·x = constant, tumble's Plane n·x = offset.
void add_plane(BulletWorld& bullet, const physics::Plane& plane) {
  auto& shape = bullet.shapes.emplace_back(std::make_unique<btStaticPlaneShape>(
      to_bullet(plane.normal), static_cast<btScalar>(plane.offset)));
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape.get());
  info.m_friction = static_cast<btScalar>(plane.material.friction);
  info.m_restitution = static_cast<btScalar>(plane.material.restitution);
  bullet.world.addRigidBody(bullet.planes.emplace_back(std::make_unique<btRigidBody>(info)).get());
}

// The body's shape in Bullet: a btBoxShape, a btSphereShape for a ball (its radius is all
// margin: it collides as the sphere given), a btCapsuleShape (along y; its height the length
// between its end centres, as tumble's), a btCylinderShape (along y; its margin inside, as a
// box's), or a btConvexHullShape of the hull's corners (body frame). A hull's margin lies outside
// its corners: 5 mm here, where Bullet's default 4 cm would grow a 0.2 m hull by 40 %.
std::unique_ptr<btCollisionShape> bullet_shape(const PileBox& box) {
  switch (box.kind) {
    case PileKind::capsule:
      return std::make_unique<btCapsuleShape>(static_cast<btScalar>(box.radius),
                                              static_cast<btScalar>(box.length));
    case PileKind::ball:
      return std::make_unique<btSphereShape>(static_cast<btScalar>(box.radius));
    case PileKind::cylinder:
      return std::make_unique<btCylinderShape>(to_bullet(0.5 * box.size));
    case PileKind::hull: {
      auto shape = std::make_unique<btConvexHullShape>();
      for (const physics::Vec3& corner : box.hull->hull->vertices) {
        shape->addPoint(to_bullet(corner), false);
      }
      shape->recalcLocalAabb();
      shape->setMargin(static_cast<btScalar>(0.005));
      return shape;
    }
    case PileKind::box:
      break;
  }
  const physics::Vec3 half_size = 0.5 * box.size;  // m
  auto shape = std::make_unique<btBoxShape>(to_bullet(half_size));
  // btBoxShape keeps its 0.04 m margin inside the box: it stores half extents minus the margin
  // and adds the margin back, and box-box (dBoxBox) and box-plane contacts use the extents with
  // margin, so the box collides as the full size given, sharp corners included (no growth).
  assert((from_bullet(shape->getHalfExtentsWithMargin()) - half_size).norm() < 1e-6);
  return shape;
}

void add_box(BulletWorld& bullet, const PileBox& box, const physics::Material& material) {
  std::unique_ptr<btCollisionShape> shape = bullet_shape(box);
  // Tumble's inertia (the same formulas as btBoxShape's and btSphereShape's
  // calculateLocalInertia), so that the two engines start from the same mass properties by
  // construction.
  const physics::Vec3 inertia = constants_of(box).inertia;  // kg m²
  btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(box.mass), nullptr,
                                                shape.get(), to_bullet(inertia));
  info.m_friction = static_cast<btScalar>(material.friction);
  info.m_restitution = static_cast<btScalar>(material.restitution);
  const physics::Quat& q = box.orientation;
  info.m_startWorldTransform =
      btTransform(btQuaternion(static_cast<btScalar>(q.x()), static_cast<btScalar>(q.y()),
                               static_cast<btScalar>(q.z()), static_cast<btScalar>(q.w())),
                  to_bullet(box.position));
  auto body = std::make_unique<btRigidBody>(info);
  body->setLinearVelocity(to_bullet(box.velocity));
  body->setAngularVelocity(to_bullet(box.angular_velocity));  // world frame in both engines
  bullet.world.addRigidBody(body.get());
  bullet.shapes.push_back(std::move(shape));
  bullet.boxes.push_back(std::move(body));
}

// Contact points over all pairs. Bullet also keeps points that are slightly apart (up to the
// manifold's contact-breaking threshold, 0.02 times the shape's bounding radius), so the count is
// of touching-or-nearly pairs' points.
int count_points(btCollisionDispatcher& dispatcher) {
  int points = 0;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    points += dispatcher.getManifoldByIndexInternal(m)->getNumContacts();
  }
  return points;
}

// Box i's pose as PileDepth reads it.
physics::BoxPose pose_of(const btRigidBody& body, const PileBox& box) {
  const btTransform& t = body.getWorldTransform();
  physics::Mat3 rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = static_cast<double>(t.getBasis()[r][c]);
  }
  return {
      .position = from_bullet(t.getOrigin()), .rotation = rotation, .half_size = 0.5 * box.size};
}

double top_speed(const BulletWorld& bullet) {
  double fastest = 0.0;  // m/s
  for (const auto& body : bullet.boxes) {
    fastest = std::max(fastest, static_cast<double>(body->getLinearVelocity().length()));
  }
  return fastest;
}

}  // namespace

std::string bullet_engine_name() {
  const int version = btGetVersion();  // 324 for 3.24
  return "bullet " + std::to_string(version / 100) + "." + std::to_string(version % 100) +
         (btIsDoublePrecision() ? " float64" : " float32");
}

PileRun run_pile_in_bullet(const Pile& pile, const StepObserver& observer) {
  const TumbleMaterialRule rule;
  auto bullet = std::make_unique<BulletWorld>();  // large: on the heap
  bullet->world.setGravity(to_bullet(pile.gravity));
  for (const physics::Plane& plane : pile.planes) add_plane(*bullet, plane);
  for (const PileBox& box : pile.boxes) add_box(*bullet, box, pile.box_material);

  PileDepth depth_of;
  std::vector<physics::BoxPose> poses(pile.boxes.size());
  PileRun run;
  run.engine = bullet_engine_name();
  const auto steps = static_cast<std::size_t>(pile.steps);
  run.step_ms.reserve(steps);
  run.step_cpu_ms.reserve(steps);
  run.contacts.reserve(steps);
  run.depth_m.reserve(steps);
  run.top_speed.reserve(steps);
  for (std::size_t n = 0; n < steps; ++n) {
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    bullet->world.stepSimulation(static_cast<btScalar>(pile.dt), 0);  // no sub-steps
    const auto end = std::chrono::steady_clock::now();
    const std::clock_t cpu_end = std::clock();
    run.step_ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    run.step_cpu_ms.push_back(1000.0 * static_cast<double>(cpu_end - cpu_start) / CLOCKS_PER_SEC);
    for (std::size_t i = 0; i < poses.size(); ++i)
      poses[i] = pose_of(*bullet->boxes[i], pile.boxes[i]);
    const double deepest = depth_of(pile, poses);
    run.contacts.push_back(count_points(bullet->dispatcher));
    run.depth_m.push_back(deepest);
    run.top_speed.push_back(top_speed(*bullet));
    run.largest_penetration_m = std::max(run.largest_penetration_m, deepest);
    if (observer) observer(run);
  }

  run.largest_final_speed = top_speed(*bullet);
  run.final_positions.reserve(bullet->boxes.size());
  for (const auto& body : bullet->boxes) {
    const physics::Vec3 centre = from_bullet(body->getWorldTransform().getOrigin());
    assert(centre.allFinite());
    run.final_positions.push_back(centre);
    if (!inside_bin(pile, centre)) ++run.escaped;
  }
  return run;
}

}  // namespace tumble::bench
