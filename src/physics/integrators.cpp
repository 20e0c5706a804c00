#include "physics/integrators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <variant>
#include <vector>

#include "physics/free_rigid_body.hpp"

namespace tumble::physics {
namespace {

// Time derivative of the primary state: (dx/dt, dp/dt, dq/dt, dL/dt).
struct Derivative {
  Vec3 velocity = Vec3::Zero();  // m/s
  Vec3 force = Vec3::Zero();     // N
  Quat spin = Quat(0, 0, 0, 0);  // 1/s
  Vec3 torque = Vec3::Zero();    // N m
};

void add_to(Wrench& sum, const Wrench& more) {
  sum.force += more.force;
  sum.torque += more.torque;
}

// primary + derivative * h, as a raw (not yet normalised) primary state.
PrimaryState advanced(const PrimaryState& in, const Derivative& rate, double h) {
  PrimaryState out = in;
  out.position += h * rate.velocity;
  out.momentum += h * rate.force;
  out.orientation.coeffs() += h * rate.spin.coeffs();
  out.angular_momentum += h * rate.torque;
  return out;
}

Derivative derivative_at(const BodyModel& model, const BodyState& state, double t) {
  const Wrench wrench = total_wrench(model.forces, model.constants, state, t);
  return {.velocity = state.velocity(),
          .force = wrench.force,
          .spin = state.spin(),
          .torque = wrench.torque};
}

// With `extra`, a wrench from outside the body's own laws (Coupling), added to theirs.
Derivative derivative_at(const BodyModel& model, const BodyState& state, double t,
                         const Wrench& extra) {
  Derivative out = derivative_at(model, state, t);
  out.force += extra.force;
  out.torque += extra.torque;
  return out;
}

BodyState euler_step(const BodyModel& model, const BodyState& in, double t, double dt) {
  return BodyState(advanced(in.primary(), derivative_at(model, in, t), dt), model.constants);
}

// Kick the momenta with forces from the start of the step, then drift the pose with the new
// velocities (semi-implicit Euler).
BodyState symplectic_euler_step(const BodyModel& model, const BodyState& in, double t, double dt,
                                const Wrench* extra = nullptr) {
  Wrench wrench = total_wrench(model.forces, model.constants, in, t);
  if (extra) add_to(wrench, *extra);
  PrimaryState kicked = in.primary();
  kicked.momentum += dt * wrench.force;
  kicked.angular_momentum += dt * wrench.torque;
  const BodyState mid(kicked, model.constants);
  return BodyState(advanced(kicked, {.velocity = mid.velocity(), .spin = mid.spin()}, dt),
                   model.constants);
}

// RK4's weighted mean of its four stages' derivatives.
[[gnu::always_inline]] inline Derivative rk4_combined(const Derivative& a, const Derivative& b,
                                                      const Derivative& c, const Derivative& d) {
  Derivative out;
  out.velocity = (a.velocity + 2.0 * (b.velocity + c.velocity) + d.velocity) / 6.0;
  out.force = (a.force + 2.0 * (b.force + c.force) + d.force) / 6.0;
  out.spin.coeffs() =
      (a.spin.coeffs() + 2.0 * (b.spin.coeffs() + c.spin.coeffs()) + d.spin.coeffs()) / 6.0;
  out.torque = (a.torque + 2.0 * (b.torque + c.torque) + d.torque) / 6.0;
  return out;
}

// Fiedler's RK4: each stage state is recalculated (and so its quaternion normalised) before
// its derivative is taken; measured still fourth order (tests/physics/integrators_test.cpp).
BodyState rk4_step(const BodyModel& model, const BodyState& in, double t, double dt) {
  const auto stage = [&](const Derivative& rate, double h) {
    const BodyState state(advanced(in.primary(), rate, h), model.constants);
    return derivative_at(model, state, t + h);
  };
  const Derivative a = derivative_at(model, in, t);
  const Derivative b = stage(a, 0.5 * dt);
  const Derivative c = stage(b, 0.5 * dt);
  const Derivative d = stage(c, dt);
  return BodyState(advanced(in.primary(), rk4_combined(a, b, c, d), dt), model.constants);
}

// ---- Splitting: symmetric compositions of exact sub-flows ----------------------------------

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix7 = Eigen::Matrix<double, 7, 7>;

// x(h) for dx/dt = f − k x with f constant: e^{−kh} x + (1 − e^{−kh})/k f, the second factor
// written −expm1(−kh)/k so that it tends to h without cancellation as k → 0.
template <typename Value>
Value decay(double rate /* 1/s */, double h /* s */, const Value& x, const Value& f) {
  if (rate == 0.0) return x + h * f;
  return std::exp(-rate * h) * x - std::expm1(-rate * h) / rate * f;
}

Vector6 as_vector(const Vec3& linear, const Vec3& angular) {
  Vector6 out;
  out << linear, angular;
  return out;
}

// φ₁(Z) w = Σ Zᵏ w / (k+1)!, the change over one kick of the affine flow below (Z = J h,
// w = W(y₀) h). For ‖Z‖₁ ≤ 1/2 (the usual case: ‖Z‖ is a damping rate times dt) Horner's scheme on
// the vector, truncated after degree 14 (remainder below 0.5¹⁵/16! ≈ 1.5e-18 ‖w‖); for stiffer
// kicks the exponential of [[Z, ŵ], [0, 0]], ŵ = w/‖w‖, whose last column is (φ₁(Z) ŵ, 1), by the
// same series after scaling by 2⁻ˢ to norm ≤ 1/2, then s squarings (Moler & Van Loan 2003,
// "method 3"). Costs 15 6×6 matrix-vector products, or about 15 + s 7×7 matrix products.
Vector6 phi1_times(const Matrix6& z, const Vector6& w) {
  constexpr int kDegree = 14;
  const double norm = z.cwiseAbs().colwise().sum().maxCoeff();
  if (norm <= 0.5) {
    Vector6 sum = w;
    for (int k = kDegree + 1; k >= 2; --k) sum = w + z * sum / k;
    return sum;
  }
  const double size = w.lpNorm<1>();
  if (size == 0.0) return Vector6::Zero();
  const int squarings = static_cast<int>(std::ceil(std::log2(2.0 * norm)));
  Matrix7 augmented = Matrix7::Zero();
  augmented.topLeftCorner<6, 6>() = z;
  augmented.topRightCorner<6, 1>() = w / size;
  augmented *= std::ldexp(1.0, -squarings);
  Matrix7 exponential = Matrix7::Identity();
  for (int k = kDegree; k >= 1; --k) {
    exponential = Matrix7::Identity() + augmented * exponential / k;
  }
  for (int i = 0; i < squarings; ++i) exponential = exponential * exponential;
  return size * exponential.topRightCorner<6, 1>();
}

// A damped spring's force follows the attachment point's velocity v + ω × r, which couples the
// two momenta; a moving anchor's velocity, frozen with the time, only offsets it. The exact flow
// of dy/dt = W(y), y = (p, L), W affine with pose and time frozen, is
// y(h) = y₀ + ∫₀ʰ e^{J s} ds W(y₀) = y₀ + φ₁(J h) W(y₀) h. J is read off the laws themselves by
// six probes: their differences are exact for an affine W.
PrimaryState coupled_kick(const BodyModel& model, const BodyState& in, double t, double h,
                          const Wrench* extra) {
  const auto wrench_vector = [&](const BodyState& state) {
    const Wrench w = total_wrench(model.forces, model.constants, state, t);
    return as_vector(w.force, w.torque);
  };
  const Vector6 start = as_vector(in.momentum(), in.angular_momentum());
  const Vector6 base = wrench_vector(in);
  // Any probe size is exact in exact arithmetic; this one keeps the differences far above the
  // round-off of W(y₀).
  const double probe = 1.0 + start.cwiseAbs().maxCoeff();
  Matrix6 jacobian_step;  // J h
  for (int i = 0; i < 6; ++i) {
    PrimaryState shifted = in.primary();
    if (i < 3) {
      shifted.momentum[i] += probe;
    } else {
      shifted.angular_momentum[i - 3] += probe;
    }
    jacobian_step.col(i) =
        (wrench_vector(BodyState(shifted, model.constants)) - base) * (h / probe);
  }
  // A wrench from outside (Coupling) is held over the kick: it adds to W(y₀), not to J.
  const Vector6 held = extra ? base + as_vector(extra->force, extra->torque) : base;
  const Vector6 change = phi1_times(jacobian_step, held * h);
  PrimaryState out = in.primary();
  out.momentum += change.head<3>();
  out.angular_momentum += change.tail<3>();
  return out;
}

// The kick: the exact flow over h of dp/dt = F, dL/dt = τ with position, orientation and time
// frozen. Every law in forces.hpp but PenaltyContact is then affine in (p, L): laws that ignore
// the momenta give a constant wrench; linear damping −(c/m) p decays p exponentially; angular
// damping −c I_world⁻¹ L is diagonal in the body frame (I_world is frozen with q), so each body
// component of L decays at its own rate c/I_i. Both are exact for any h, hence stable however
// stiff. Only a damped spring couples p and L, and takes the φ₁ series above, while it acts. Time
// is frozen too: a moving anchor and a law's start and end are read at the kick's time, which the
// drifts advance (time as one more coordinate of the drift), so a spring whose anchor moves needs
// nothing more here. PenaltyContact is not affine (it pushes only, and its friction is
// regularised): it is evaluated once at the kick's start and held, so its damping is explicit and
// the method is first order on penalty contact (measured 1.0 for splitting and splitting4 on a
// resting cube's bounce, against 4.0 for rk4); sim/penalty_modes models that kick for the stability
// advisor.
// A wrench from outside the body's laws (`extra`, Coupling) is held over the kick likewise.
PrimaryState kick(const BodyModel& model, const BodyState& in, double t, double h,
                  const Wrench* extra = nullptr) {
  const BodyConstants& constants = model.constants;
  Wrench fixed;  // the laws that ignore the momenta (N, N m)
  if (extra) fixed = *extra;
  double linear_damping = 0.0;   // Σ c over LinearDamping (N s/m)
  double angular_damping = 0.0;  // Σ c over AngularDamping (N m s)
  for (const ForceLaw& law : model.forces) {
    if (const auto* damping = std::get_if<LinearDamping>(&law)) {
      linear_damping += damping->coefficient;
    } else if (const auto* damping = std::get_if<AngularDamping>(&law)) {
      angular_damping += damping->coefficient;
    } else if (const auto* spring = std::get_if<Spring>(&law);
               spring && spring->damping != 0.0 && acts_at(*spring, t)) {
      return coupled_kick(model, in, t, h, extra);
    } else {
      const Wrench w = evaluate(law, constants, in, t);
      fixed.force += w.force;
      fixed.torque += w.torque;
    }
  }
  PrimaryState out = in.primary();
  out.momentum = decay(linear_damping * constants.inverse_mass, h, out.momentum, fixed.force);
  if (angular_damping == 0.0) {
    out.angular_momentum += h * fixed.torque;
  } else if (constants.isotropic) {
    out.angular_momentum = decay(angular_damping * constants.inverse_inertia.x(), h,
                                 out.angular_momentum, fixed.torque);
  } else {
    const Mat3 rotation = in.orientation().toRotationMatrix();
    Vec3 body_momentum = rotation.transpose() * out.angular_momentum;
    const Vec3 body_torque = rotation.transpose() * fixed.torque;
    for (int i = 0; i < 3; ++i) {
      body_momentum[i] = decay(angular_damping * constants.inverse_inertia[i], h, body_momentum[i],
                               body_torque[i]);
    }
    out.angular_momentum = rotation * body_momentum;
  }
  return out;
}

// The drift: the exact flow of the kinetic energy alone, x += (p/m) h and the torque-free rotation.
PrimaryState drift(const BodyModel& model, PrimaryState state, double h) {
  state.position += (h * model.constants.inverse_mass) * state.momentum;
  state.orientation =
      free_rigid_body(model.constants, state.orientation, state.angular_momentum, h);
  return state;
}

// A symmetric composition kick(k₀ dt) drift(d₀ dt) kick(k₁ dt) … drift(d_{n−1} dt) kick(k_n dt).
struct Composition {
  int drifts = 1;
  std::array<double, 4> kicks = {};
  std::array<double, 3> drifts_by = {};
};

// Strang's kick(dt/2) drift(dt) kick(dt/2) for splitting; for splitting4, Yoshida 1990's triple
// jump S(γ₁h) S(γ₂h) S(γ₁h) with 2γ₁³ + γ₂³ = 0, 2γ₁ + γ₂ = 1, the kicks that meet between two
// Strang steps merged (both are exact flows of the same frozen field).
Composition composition(Integrator integrator) {
  if (integrator == Integrator::splitting)
    return {.drifts = 1, .kicks = {0.5, 0.5}, .drifts_by = {1.0}};
  const double outer = 1.0 / (2.0 - std::cbrt(2.0));
  const double inner = 1.0 - 2.0 * outer;
  return {.drifts = 3,
          .kicks = {0.5 * outer, 0.5 * (outer + inner), 0.5 * (outer + inner), 0.5 * outer},
          .drifts_by = {outer, inner, outer}};
}

// The composition over every body of `states` together, in place; forces are evaluated at the
// time the drifts have reached. `outside(states, time)` gives each body's wrench from outside
// its laws at the start of each kick (held over it), or nullptr for none.
template <typename Outside>
void compose(const Composition& c, std::span<const BodyModel> models, std::span<BodyState> states,
             double t, double dt, const Outside& outside) {
  double elapsed = 0.0;  // fraction of dt
  for (int i = 0; i <= c.drifts; ++i) {
    const double time = i == c.drifts ? t + dt : t + elapsed * dt;
    const Wrench* extra = outside(std::span<const BodyState>(states), time);
    for (std::size_t j = 0; j < states.size(); ++j) {
      const BodyModel& model = models[j];
      const PrimaryState kicked =
          kick(model, states[j], time, c.kicks[i] * dt, extra ? &extra[j] : nullptr);
      states[j] = i == c.drifts
                      ? BodyState(kicked, model.constants)
                      : BodyState(drift(model, kicked, c.drifts_by[i] * dt), model.constants);
    }
    if (i < c.drifts) elapsed += c.drifts_by[i];
  }
}

BodyState splitting_step(Integrator integrator, const BodyModel& model, const BodyState& in,
                         double t, double dt) {
  BodyState state = in;
  compose(composition(integrator), std::span<const BodyModel>(&model, 1),
          std::span<BodyState>(&state, 1), t, dt,
          [](std::span<const BodyState>, double) -> const Wrench* { return nullptr; });
  return state;
}

}  // namespace

std::string_view integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::euler:
      return "euler";
    case Integrator::symplectic_euler:
      return "symplectic_euler";
    case Integrator::rk4:
      return "rk4";
    case Integrator::splitting:
      return "splitting";
    case Integrator::splitting4:
      return "splitting4";
  }
  return "unknown";
}

std::optional<Integrator> integrator_from_name(std::string_view name) {
  for (const Integrator integrator : kAllIntegrators) {
    if (integrator_name(integrator) == name) return integrator;
  }
  return std::nullopt;
}

BodyState step(Integrator integrator, const BodyModel& model, const BodyState& state, double t,
               double dt) {
  switch (integrator) {
    case Integrator::euler:
      return euler_step(model, state, t, dt);
    case Integrator::symplectic_euler:
      return symplectic_euler_step(model, state, t, dt);
    case Integrator::rk4:
      return rk4_step(model, state, t, dt);
    case Integrator::splitting:
    case Integrator::splitting4:
      return splitting_step(integrator, model, state, t, dt);
  }
  return state;
}

void step_coupled(Integrator integrator, std::span<const BodyModel> models,
                  std::span<const BodyState> in, double t, double dt, const Coupling& coupling,
                  std::span<BodyState> out) {
  const std::size_t count = models.size();
  std::vector<Wrench> extra(count);
  const auto outside = [&](std::span<const BodyState> states, double time) -> const Wrench* {
    std::fill(extra.begin(), extra.end(), Wrench{});
    coupling.add(states, time, extra);
    return extra.data();
  };
  switch (integrator) {
    case Integrator::euler:
      outside(in, t);
      for (std::size_t i = 0; i < count; ++i) {
        out[i] =
            BodyState(advanced(in[i].primary(), derivative_at(models[i], in[i], t, extra[i]), dt),
                      models[i].constants);
      }
      return;
    case Integrator::symplectic_euler:
      outside(in, t);
      for (std::size_t i = 0; i < count; ++i) {
        out[i] = symplectic_euler_step(models[i], in[i], t, dt, &extra[i]);
      }
      return;
    case Integrator::rk4: {
      // Each stage over every body before the next, the outside wrenches from the stage's states.
      std::array<std::vector<Derivative>, 4> rates;
      const auto rates_at = [&](std::span<const BodyState> states, double time,
                                std::vector<Derivative>& into) {
        outside(states, time);
        into.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
          into[i] = derivative_at(models[i], states[i], time, extra[i]);
        }
      };
      rates_at(in, t, rates[0]);
      for (int stage = 1; stage < 4; ++stage) {
        const double h = stage == 3 ? dt : 0.5 * dt;
        for (std::size_t i = 0; i < count; ++i) {
          out[i] =
              BodyState(advanced(in[i].primary(), rates[stage - 1][i], h), models[i].constants);
        }
        rates_at(out, t + h, rates[stage]);
      }
      for (std::size_t i = 0; i < count; ++i) {
        const Derivative combined =
            rk4_combined(rates[0][i], rates[1][i], rates[2][i], rates[3][i]);
        out[i] = BodyState(advanced(in[i].primary(), combined, dt), models[i].constants);
      }
      return;
    }
    case Integrator::splitting:
    case Integrator::splitting4:
      std::copy(in.begin(), in.end(), out.begin());
      compose(composition(integrator), models, out, t, dt, outside);
      return;
  }
}

}  // namespace tumble::physics
