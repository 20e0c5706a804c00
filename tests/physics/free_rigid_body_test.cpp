#include "physics/free_rigid_body.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

namespace tumble::physics {
namespace {

// Independent reference: Euler's equations dL_b/dt = L_b × ω_b and q' = ½ q (0, ω_b), ω_b = I⁻¹
// L_b, integrated in long double by Runge-Kutta-Fehlberg 7(8) at a 1e-19 tolerance.
Quat reference_orientation(const BodyConstants& constants, const Quat& start,
                           const Vec3& angular_momentum, double duration) {
  using State = std::array<long double, 7>;  // body-frame L, then q as (w, x, y, z)
  const std::array<long double, 3> inverse{
      1.0L / constants.inertia.x(), 1.0L / constants.inertia.y(), 1.0L / constants.inertia.z()};
  const auto rates = [&](const State& s, State& d, long double) {
    const long double wx = s[0] * inverse[0];
    const long double wy = s[1] * inverse[1];
    const long double wz = s[2] * inverse[2];
    d[0] = s[1] * wz - s[2] * wy;
    d[1] = s[2] * wx - s[0] * wz;
    d[2] = s[0] * wy - s[1] * wx;
    d[3] = 0.5L * (-s[4] * wx - s[5] * wy - s[6] * wz);
    d[4] = 0.5L * (s[3] * wx + s[5] * wz - s[6] * wy);
    d[5] = 0.5L * (s[3] * wy + s[6] * wx - s[4] * wz);
    d[6] = 0.5L * (s[3] * wz + s[4] * wy - s[5] * wx);
  };
  const Vec3 body = start.conjugate() * angular_momentum;
  State state{body.x(), body.y(), body.z(), start.w(), start.x(), start.y(), start.z()};
  namespace odeint = boost::numeric::odeint;
  odeint::integrate_adaptive(
      odeint::make_controlled(1e-19L, 1e-19L, odeint::runge_kutta_fehlberg78<State, long double>()),
      rates, state, 0.0L, static_cast<long double>(duration), 1e-4L);
  return Quat(static_cast<double>(state[3]), static_cast<double>(state[4]),
              static_cast<double>(state[5]), static_cast<double>(state[6]))
      .normalized();
}

const Quat kTilted(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));

// The box of scenes/intermediate_axis.toml: I_x = 0.417 > I_y = 0.341 > I_z = 0.091 kg m².
BodyConstants racket() {
  return box_constants(1.0, Vec3(0.3, 1.0, 2.0));
}

Vec3 world_momentum(const BodyConstants& constants, const Quat& q, const Vec3& w /* world */) {
  return apply_inertia_world(constants, q, w);
}

TEST(FreeRigidBody, CubeTurnsAboutLAtItsAngularSpeed) {
  const BodyConstants cube = cube_constants(2.0, 0.5);
  const Vec3 w(3.0, -40.0, 7.0);
  const Vec3 momentum = world_momentum(cube, kTilted, w);
  for (const double h : {1e-3, 1.0 / 60.0, 0.7, 25.0}) {
    const Quat exact = Quat(Eigen::AngleAxisd(w.norm() * h, w.normalized())) * kTilted;
    EXPECT_LT(angle_between(free_rigid_body(cube, kTilted, momentum, h), exact),
              1e-15 * std::max(1.0, w.norm() * h))
        << h;
  }
}

// A symmetric top (I₁ = I₂ ≠ I₃) for each choice of symmetry axis: the body-frame L precesses
// about the symmetry axis at (1/I₃ − 1/I₁) L₃ (backwards, seen from the body), and the symmetry
// axis precesses about the world L at |L|/I₁. Together the two fix the orientation.
TEST(FreeRigidBody, SymmetricTopFollowsTheClosedForm) {
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 size = Vec3::Constant(0.4);
    size[axis] = 1.5;  // a rod: the odd moment is the smallest
    const BodyConstants top = box_constants(1.0, size);
    ASSERT_FALSE(top.isotropic);
    const double equal = top.inertia[(axis + 1) % 3];
    const double odd = top.inertia[axis];
    const Vec3 momentum = world_momentum(top, kTilted, Vec3(2.0, -1.0, 4.0));
    const Vec3 body_start = kTilted.conjugate() * momentum;
    const Vec3 symmetry_axis = Vec3::Unit(axis);
    for (const double h : {1.0 / 60.0, 0.9, 12.0}) {
      const Quat end = free_rigid_body(top, kTilted, momentum, h);
      const Vec3 body_expected =
          Eigen::AngleAxisd(-(1.0 / odd - 1.0 / equal) * body_start[axis] * h, symmetry_axis) *
          body_start;
      const Vec3 axis_expected =
          Eigen::AngleAxisd(momentum.norm() / equal * h, momentum.normalized()) *
          (kTilted * symmetry_axis);
      EXPECT_LT((end.conjugate() * momentum - body_expected).norm(), 1e-14 * momentum.norm())
          << axis << ' ' << h;
      EXPECT_LT((end * symmetry_axis - axis_expected).norm(), 1e-14 * std::max(1.0, h))
          << axis << ' ' << h;
    }
  }
}

TEST(FreeRigidBody, SpinAboutAPrincipalAxisIsSteady) {
  const BodyConstants box = racket();
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 momentum = 3.0 * Vec3::Unit(axis);  // body = world at the identity
    const double h = 0.37;
    const Quat expected(Eigen::AngleAxisd(3.0 / box.inertia[axis] * h, Vec3::Unit(axis)));
    EXPECT_LT(angle_between(free_rigid_body(box, Quat::Identity(), momentum, h), expected), 1e-15)
        << axis;
  }
}

// The energy ½ L·I_world⁻¹ L depends on the orientation only, so it measures the flow's
// round-off; |L| is the constant input itself.
TEST(FreeRigidBody, KeepsTheEnergyToRoundOff) {
  const BodyConstants box = racket();
  const Vec3 momentum = world_momentum(box, kTilted, Vec3(0.8, 3.0, -0.5));
  const auto energy = [&](const Quat& q) {
    return 0.5 * momentum.dot(apply_inverse_inertia_world(box, q, momentum));
  };
  const double start = energy(kTilted);
  Quat q = kTilted;
  double worst_step = 0.0;
  for (int n = 0; n < 100000; ++n) {
    const double before = energy(q);
    q = free_rigid_body(box, q, momentum, 1.0 / 60.0).normalized();
    worst_step = std::max(worst_step, std::abs(energy(q) - before) / start);
  }
  const double drift = std::abs(energy(q) - start) / start;
  std::cout << "[ measured ] free flow energy: worst step " << worst_step << ", drift after 1e5 "
            << drift << '\n';
  EXPECT_LT(worst_step, 1e-14);
  EXPECT_LT(drift, 1e-12);
}

TEST(FreeRigidBody, FlowsCompose) {
  const BodyConstants box = racket();
  double worst = 0.0;
  for (const Vec3& w : {Vec3(0.01, 3.0, 0.01), Vec3(3.0, 0.4, 0.3), Vec3(0.3, 0.4, 3.0)}) {
    const Vec3 momentum = world_momentum(box, kTilted, w);
    for (const double first : {0.013, 0.3, 1.7, 7.0}) {
      for (const double second : {-0.02, 0.5, 2.9}) {
        const Quat twice =
            free_rigid_body(box, free_rigid_body(box, kTilted, momentum, first), momentum, second);
        worst = std::max(
            worst, angle_between(twice, free_rigid_body(box, kTilted, momentum, first + second)));
      }
    }
  }
  std::cout << "[ measured ] flow(h1) then flow(h2) vs flow(h1 + h2): " << worst << " rad\n";
  EXPECT_LT(worst, 1e-13);
}

struct ReferenceCase {
  std::string name;
  Vec3 size;              // box edges (m)
  Vec3 angular_velocity;  // body frame (rad/s)
  int regime;  // sign of |L|² − 2E I_intermediate: +1 about the major axis, −1 minor
};

// Names the case in test listings (GoogleTest would print its bytes, pointers included).
std::ostream& operator<<(std::ostream& out, const ReferenceCase& c) {
  return out << c.name;
}

class AgainstReference : public ::testing::TestWithParam<ReferenceCase> {};

// Both circulation regimes, each ordering of the moments, and the tennis-racket case close to
// (not on) the separatrix; times from a fraction of a turn to many turns.
TEST_P(AgainstReference, MatchesEulersEquationsToRoundOff) {
  const BodyConstants box = box_constants(1.0, GetParam().size);
  const Vec3 body = box.inertia.cwiseProduct(GetParam().angular_velocity);
  const Vec3 momentum = kTilted * body;
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(),
            [&](int i, int j) { return box.inertia[i] < box.inertia[j]; });
  const double intermediate = box.inertia[order[1]];
  const double separatrix =
      body.squaredNorm() - intermediate * body.dot(box.inverse_inertia.cwiseProduct(body));
  ASSERT_EQ(separatrix > 0.0 ? 1 : -1, GetParam().regime);
  double worst = 0.0;
  for (const double duration : {0.01, 0.1, 1.0, 5.0}) {
    const double error = angle_between(free_rigid_body(box, kTilted, momentum, duration),
                                       reference_orientation(box, kTilted, momentum, duration));
    worst = std::max(worst, error);
    EXPECT_LT(error, 1e-13) << duration;
  }
  std::cout << "[ measured ] " << GetParam().name << ": worst " << worst << " rad\n";
}

INSTANTIATE_TEST_SUITE_P(
    FreeRigidBody, AgainstReference,
    ::testing::Values(
        ReferenceCase{"NearMajorAxis", Vec3(0.3, 1.0, 2.0), Vec3(3.0, 0.4, 0.3), 1},
        ReferenceCase{"NearMinorAxis", Vec3(0.3, 1.0, 2.0), Vec3(0.3, 0.4, 3.0), -1},
        ReferenceCase{"NearMajorAxisOtherOrder", Vec3(2.0, 0.3, 1.0), Vec3(-0.5, 2.0, -0.3), 1},
        ReferenceCase{"NearMinorAxisOtherOrder", Vec3(2.0, 0.3, 1.0), Vec3(2.5, -0.2, 0.6), -1},
        ReferenceCase{"IntermediateAxisMajorSide", Vec3(0.3, 1.0, 2.0), Vec3(0.01, 3.0, 0.002), 1},
        ReferenceCase{"IntermediateAxisMinorSide", Vec3(0.3, 1.0, 2.0), Vec3(0.002, 3.0, 0.01), -1},
        ReferenceCase{"NearlySymmetric", Vec3(1.0, 1.0 + 1e-9, 2.0), Vec3(1.0, 2.0, 3.0), -1}),
    [](const auto& info) { return info.param.name; });

// Within 1e-12 |L| of the saddle (the intermediate axis) and exactly on the separatrix the flow
// must stay accurate for as long as the motion itself is well conditioned (a few 1/λ).
TEST(FreeRigidBody, StaysAccurateAtTheSeparatrix) {
  const BodyConstants box = racket();
  const Vec3& inertia = box.inertia;
  // |L|² = 2E I_y exactly for L_y = 0: L_x² (I_x − I_y)/I_x = L_z² (I_y − I_z)/I_z.
  const double on_x = std::sqrt((inertia.y() - inertia.z()) / inertia.z() * inertia.x() /
                                (inertia.x() - inertia.y()));
  for (const Vec3& body : {Vec3(1e-12, 2.0, -1e-12), Vec3(on_x, 0.0, 1.0), Vec3(on_x, 1.0, 1.0)}) {
    for (const double duration : {0.1, 0.5}) {
      const Quat end = free_rigid_body(box, Quat::Identity(), body, duration);
      EXPECT_LT(angle_between(end, reference_orientation(box, Quat::Identity(), body, duration)),
                1e-13)
          << body.transpose() << ' ' << duration;
    }
  }
}

// The references of tests/physics/splitting_test.cpp (one evaluation over the whole run) against
// Euler's equations: a box at 208 rad/s for 10 s and 100 s, and the tennis racket for 100 s.
TEST(FreeRigidBody, LongFlowsMatchTheReference) {
  struct Long {
    BodyConstants constants;
    Quat orientation;
    Vec3 angular_velocity;  // world (rad/s)
    double duration;        // s
    double tolerance;       // rad
  };
  const BodyConstants box = box_constants(1.0, Vec3(0.5, 1.0, 1.5));
  for (const Long& c : {Long{box, kTilted, Vec3(120.0, 150.0, 80.0), 10.0, 1e-11},
                        Long{box, kTilted, Vec3(120.0, 150.0, 80.0), 100.0, 1e-10},
                        Long{racket(), Quat::Identity(), Vec3(0.01, 3.0, 0.01), 100.0, 1e-11}}) {
    const Vec3 momentum = world_momentum(c.constants, c.orientation, c.angular_velocity);
    const double error =
        angle_between(free_rigid_body(c.constants, c.orientation, momentum, c.duration),
                      reference_orientation(c.constants, c.orientation, momentum, c.duration));
    std::cout << "[ measured ] one-shot flow over " << c.duration << " s at "
              << c.angular_velocity.norm() << " rad/s: " << error << " rad from the reference\n";
    EXPECT_LT(error, c.tolerance);
  }
}

TEST(FreeRigidBody, CostPerStep) {
  const BodyConstants box = racket();
  const Vec3 momentum = world_momentum(box, kTilted, Vec3(120.0, 150.0, 80.0));
  Quat q = kTilted;
  constexpr int kSteps = 100000;
  const auto start = std::chrono::steady_clock::now();
  for (int n = 0; n < kSteps; ++n) q = free_rigid_body(box, q, momentum, 1.0 / 60.0);
  const std::chrono::duration<double, std::micro> elapsed =
      std::chrono::steady_clock::now() - start;
  std::cout << "[ measured ] free_rigid_body, three different moments: " << elapsed.count() / kSteps
            << " us per step\n";
  EXPECT_TRUE(q.coeffs().allFinite());
}

}  // namespace
}  // namespace tumble::physics
