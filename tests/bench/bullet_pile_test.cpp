// Bullet as the peer of `contact_bench`: a small pile run through it settles in the bin, the same
// way every time, with tumble's material rule in force for the run and only for the run.
#include "bench/bullet_pile.hpp"

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <vector>

namespace tumble::bench {
namespace {

using physics::Vec3;

// 60 boxes (the bottom 2.4 layers of the benchmark's pile) for 4 s: the top layer lands at about
// 7 m/s near t = 0.8 s and the pile is quiet by t = 2.5 s (measured: 0.10 m/s at the end, 246
// contact points, the deepest 1.5 mm after the deepest 0.27 m of the landings).
class BulletPile : public testing::Test {
 protected:
  static void SetUpTestSuite() { run_ = new PileRun(run_pile_in_bullet(make_pile(60, 1, 4.0))); }
  static void TearDownTestSuite() { delete run_; }
  static PileRun* run_;
};
PileRun* BulletPile::run_ = nullptr;

TEST_F(BulletPile, NamesItsVersionAndPrecision) {
  EXPECT_EQ(run_->engine.rfind("bullet 3.24 float", 0), 0u) << run_->engine;
  EXPECT_EQ(run_->engine, bullet_engine_name());
}

TEST_F(BulletPile, MeasuresEveryStep) {
  EXPECT_EQ(run_->step_ms.size(), 240u);
  EXPECT_EQ(run_->step_cpu_ms.size(), 240u);
  EXPECT_EQ(run_->contacts.size(), 240u);
  EXPECT_EQ(run_->depth_m.size(), 240u);
  EXPECT_EQ(run_->top_speed.size(), 240u);
  EXPECT_EQ(run_->final_positions.size(), 60u);
  for (const double ms : run_->step_ms) EXPECT_GT(ms, 0.0);
}

TEST_F(BulletPile, NoBoxLeavesTheBin) {
  EXPECT_EQ(run_->escaped, 0);
}

// A still-falling or thrown box would move at metres per second; 0.25 m/s is 2.5 times the
// measured 0.10 m/s of boxes still shuffling in the settled pile (Bullet's sleeping needs 2 s
// below 0.8 m/s, which the last landings have not all had yet).
TEST_F(BulletPile, ThePileSettles) {
  EXPECT_LT(run_->largest_final_speed, 0.25);
  EXPECT_GT(run_->contacts.back(), 60);   // every box rests on something, most on several points
  EXPECT_LT(run_->depth_m.back(), 0.01);  // m: the landings' sinking recovered (1.5 mm measured)
  for (const Vec3& centre : run_->final_positions) EXPECT_GT(centre.y(), 0.1 - 0.01);  // m
}

// Bullet is deterministic for one binary: the same pile twice gives the same bits.
TEST_F(BulletPile, TwoRunsGiveIdenticalPositions) {
  const PileRun again = run_pile_in_bullet(make_pile(60, 1, 4.0));
  ASSERT_EQ(again.final_positions.size(), run_->final_positions.size());
  for (std::size_t n = 0; n < again.final_positions.size(); ++n) {
    EXPECT_EQ(again.final_positions[n], run_->final_positions[n]) << "box " << n;
  }
  EXPECT_EQ(again.contacts, run_->contacts);
}

// The observer sees each step once, as it is done, with the figures the run returns.
TEST_F(BulletPile, TheObserverSeesEveryStepAsItIsDone) {
  std::vector<int> contacts_seen;
  const PileRun again = run_pile_in_bullet(make_pile(60, 1, 4.0), [&](const PileRun& so_far) {
    EXPECT_EQ(so_far.step_ms.size(), contacts_seen.size() + 1);
    EXPECT_EQ(so_far.top_speed.size(), so_far.step_ms.size());
    contacts_seen.push_back(so_far.contacts.back());
  });
  EXPECT_EQ(contacts_seen, again.contacts);
  EXPECT_EQ(contacts_seen, run_->contacts);
}

// A 0.4 m cube sliding at 2 m/s on the floor stops after v²/(2 μ g) = 0.41 m with tumble's
// sqrt(0.5 · 0.5) = 0.5, but 0.82 m with Bullet's own product 0.25. Bullet's slide is 11% longer
// than the closed form (measured 0.452 m): its first steps hold the box on fewer contact points,
// whose friction bound lags the weight.
TEST(BulletPeer, PairsGetTumblesFrictionRule) {
  Pile pile = make_pile(1, 1, 2.0);
  PileBox& box = pile.boxes[0];
  box.size = Vec3::Constant(0.4);
  box.mass = 32.0;
  box.position = Vec3(-1.0, 0.2, 0.0);  // resting on the floor
  box.orientation = physics::Quat::Identity();
  box.velocity = Vec3(2.0, 0.0, 0.0);
  box.angular_velocity = Vec3::Zero();
  const PileRun run = run_pile_in_bullet(pile);
  const double slide = run.final_positions[0].x() - box.position.x();  // m
  const double expected = 2.0 * 2.0 / (2.0 * 0.5 * 9.81);              // m
  EXPECT_GT(slide, expected);
  EXPECT_LT(slide, 1.15 * expected);
  EXPECT_LT(run.largest_final_speed, 1e-3);
  // Resting at its half size: btBoxShape's margin lies inside the box, it neither grows nor
  // shrinks it.
  EXPECT_NEAR(run.final_positions[0].y(), 0.2, 1e-3);
}

TEST(BulletPeer, TheMaterialHooksAreRestoredAfterARun) {
  const CalculateCombinedCallback friction = gCalculateCombinedFrictionCallback;
  const CalculateCombinedCallback restitution = gCalculateCombinedRestitutionCallback;
  run_pile_in_bullet(make_pile(1, 1, 0.1));
  EXPECT_EQ(gCalculateCombinedFrictionCallback, friction);
  EXPECT_EQ(gCalculateCombinedRestitutionCallback, restitution);
}

}  // namespace
}  // namespace tumble::bench
