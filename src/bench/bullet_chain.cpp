// The chain of bench/chain.hpp in Bullet 3.24: btRigidBody links (btBoxShape, the same mass and
// inertia as tumble's box), btPoint2PointConstraint between them and to the world, Bullet's
// defaults otherwise (sequential impulses, 10 iterations, ERP 0.2), no collisions (as tumble's
// links, which do not collide).
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include "bench/bullet_chain.hpp"
#include "bench/bullet_pile.hpp"

namespace tumble::bench {

ChainRun run_chain_in_bullet(int links, double seconds, double dt) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, static_cast<btScalar>(-9.81), 0));
  btBoxShape shape(btVector3(0.01, static_cast<btScalar>(0.5 * kChainLinkLength), 0.01));
  btVector3 inertia;
  shape.calculateLocalInertia(static_cast<btScalar>(kChainLinkMass), inertia);
  std::vector<std::unique_ptr<btDefaultMotionState>> motions;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  std::vector<std::unique_ptr<btPoint2PointConstraint>> joints;
  const btQuaternion along_x(btVector3(0, 0, 1), static_cast<btScalar>(-M_PI / 2.0));
  // A link's ends, body frame: its -y end is pinned to the link before it (or the world), its +y
  // end (towards +x, where the next link starts) to the next.
  const btVector3 top(0, static_cast<btScalar>(0.5 * kChainLinkLength), 0);
  for (int k = 0; k < links; ++k) {
    btTransform start(along_x,
                      btVector3(static_cast<btScalar>((k + 0.5) * kChainLinkLength), 0, 0));
    motions.push_back(std::make_unique<btDefaultMotionState>(start));
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(kChainLinkMass),
                                                  motions.back().get(), &shape, inertia);
    bodies.push_back(std::make_unique<btRigidBody>(info));
    bodies.back()->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(bodies.back().get(), 2, 0);  // collides with nothing
    if (k == 0) {
      joints.push_back(std::make_unique<btPoint2PointConstraint>(*bodies[0], -top));
    } else {
      joints.push_back(
          std::make_unique<btPoint2PointConstraint>(*bodies[k], *bodies[k - 1], -top, top));
    }
    world.addConstraint(joints.back().get(), true);
  }
  const auto widest = [&] {
    double out = 0.0;
    for (int k = 0; k < links; ++k) {
      const btVector3 a = bodies[k]->getCenterOfMassTransform() * -top;
      const btVector3 b =
          k == 0 ? btVector3(0, 0, 0) : bodies[k - 1]->getCenterOfMassTransform() * top;
      out = std::max(out, static_cast<double>((a - b).length()));
    }
    return out;
  };
  ChainRun run{.engine = bullet_engine_name(), .steps = std::llround(seconds / dt)};
  double stepping = 0.0;
  for (std::int64_t n = 0; n < run.steps; ++n) {
    const auto start = std::chrono::steady_clock::now();
    world.stepSimulation(static_cast<btScalar>(dt), 0);
    stepping += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.final_widest_gap = widest();
    run.widest_gap = std::max(run.widest_gap, run.final_widest_gap);
    if (!std::isfinite(run.final_widest_gap)) {
      run.blew_up = true;
      run.steps = n + 1;
      break;
    }
  }
  run.ms_per_step = 1e3 * stepping / static_cast<double>(std::max<std::int64_t>(run.steps, 1));
  for (auto& joint : joints) world.removeConstraint(joint.get());
  for (auto& body : bodies) world.removeRigidBody(body.get());
  return run;
}

}  // namespace tumble::bench
