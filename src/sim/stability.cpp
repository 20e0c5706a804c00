#include "sim/stability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>
#include <variant>

#include "common/printed.hpp"
#include "sim/penalty_modes.hpp"

namespace tumble::sim {
namespace {

using physics::Integrator;
using Mat2 = Eigen::Matrix2d;

// The integrators whose one-step map on a linear mode is modelled here. The splitting methods
// are named rather than enumerated so that this file does not depend on their being built.
enum class Method { euler, symplectic_euler, rk4, splitting, splitting4 };

std::optional<Method> method_of(Integrator integrator) {
  if (integrator == Integrator::euler) return Method::euler;
  if (integrator == Integrator::symplectic_euler) return Method::symplectic_euler;
  if (integrator == Integrator::rk4) return Method::rk4;
  const std::string_view name = physics::integrator_name(integrator);
  if (name == "splitting") return Method::splitting;
  if (name == "splitting4") return Method::splitting4;
  return std::nullopt;
}

bool is_splitting(Method method) {
  return method == Method::splitting || method == Method::splitting4;
}

// Every one-step map below is written I + N and only N is computed: for a small step the map is
// close to the identity, and its eigenvalues, 1 + those of N, would lose their digits to the 1.

// N of (I + second)(I + first): first, then second.
Mat2 then(const Mat2& first, const Mat2& second) {
  return first + second + second * first;
}

// N of a kick of τ (s) on (y, y') with y'' = -ω² y - k y': y' moves, y is frozen. The exact flow
// is y' -> e^{-kτ} y' - φ ω² y with φ = (1 - e^{-kτ})/k; the frozen force held over τ gives
// y' -> (1 - kτ) y' - τ ω² y.
Mat2 kick_change(const LinearMode& mode, double tau) {
  const double k = mode.damping_rate;
  const double w2 = mode.frequency * mode.frequency;
  Mat2 change;
  if (mode.kick_damping == KickDamping::frozen) {
    change << 0.0, 0.0, -tau * w2, -tau * k;
  } else {
    const double impulse_time = k == 0.0 ? tau : -std::expm1(-k * tau) / k;  // φ (s)
    change << 0.0, 0.0, -impulse_time * w2, std::expm1(-k * tau);
  }
  return change;
}

// N of kick(k₀h) drift(d₀h) kick(k₁h) … drift(d_{n-1}h) kick(k_n h), the splitting methods'
// composition (physics/integrators.cpp, compose); a drift moves y by τ y'.
template <std::size_t Drifts>
Mat2 composition_change(const LinearMode& mode, double h,
                        const std::array<double, Drifts + 1>& kicks,
                        const std::array<double, Drifts>& drifts) {
  Mat2 change = kick_change(mode, kicks[0] * h);
  for (std::size_t i = 0; i < Drifts; ++i) {
    Mat2 drift;
    drift << 0.0, drifts[i] * h, 0.0, 0.0;
    change = then(then(change, drift), kick_change(mode, kicks[i + 1] * h));
  }
  return change;
}

// N of one splitting step of h (s), with the coefficients of physics/integrators.cpp: Strang's
// half kick, drift, half kick; and Yoshida's triple jump of it, Strang steps of γ₁h, γ₂h, γ₁h
// with γ₁ = 1 / (2 - ∛2), γ₂ = 1 - 2γ₁, whose touching half kicks are merged into one kick. (For
// exact kicks merging changes nothing; for frozen ones it is what the integrator does.)
Mat2 splitting_change(Method method, const LinearMode& mode, double h) {
  if (method == Method::splitting) return composition_change<1>(mode, h, {0.5, 0.5}, {1.0});
  const double outer = 1.0 / (2.0 - std::cbrt(2.0));
  const double inner = 1.0 - 2.0 * outer;
  return composition_change<3>(
      mode, h, {0.5 * outer, 0.5 * (outer + inner), 0.5 * (outer + inner), 0.5 * outer},
      {outer, inner, outer});
}

// N of a step of h (s) on a decaying momentum, p' = -k p: the map's factor minus one.
double decay_change(Method method, const LinearMode& mode, double h) {
  const double z = -mode.damping_rate * h;
  switch (method) {
    case Method::euler:
    case Method::symplectic_euler:  // the kick is an explicit Euler step of the momentum
      return z;
    case Method::rk4:
      return z * (1.0 + z / 2.0 * (1.0 + z / 3.0 * (1.0 + z / 4.0)));
    case Method::splitting:  // the momentum's part of the kicks; drifts do not touch it
    case Method::splitting4:
      return splitting_change(method, mode, h)(1, 1);
  }
  return 0.0;
}

// N of one step of h (s) of the method on (y, y') with y'' = -ω² y - k y'.
Mat2 oscillator_change(Method method, const LinearMode& mode, double h) {
  const double k = mode.damping_rate;
  const double w2 = mode.frequency * mode.frequency;
  Mat2 rate;
  rate << 0.0, 1.0, -w2, -k;
  const Mat2 identity = Mat2::Identity();
  Mat2 change;
  switch (method) {
    case Method::euler:
      change = h * rate;
      break;
    case Method::rk4: {
      // Σ (hA)^j / j! for 1 <= j <= 4: the classical RK4 stability function minus one.
      const Mat2 z = h * rate;
      change = z * (identity + z / 2.0 * (identity + z / 3.0 * (identity + z / 4.0)));
      break;
    }
    case Method::symplectic_euler:
      // Kick y' with the forces of the start of the step, then drift y with the new y'.
      change << -h * h * w2, h * (1.0 - h * k), -h * w2, -h * k;
      break;
    case Method::splitting:
    case Method::splitting4:
      change = splitting_change(method, mode, h);
      break;
  }
  return change;
}

// |1 + μ| <= 1 up to rounding for a real μ.
bool bounded(double mu, double tolerance) {
  return mu <= tolerance && mu >= -2.0 - tolerance;
}

// The map I + N does not grow the mode: every eigenvalue 1 + μ of it has |1 + μ| <= 1 up to
// rounding. (Explicit Euler on an undamped oscillator grows by sqrt(1 + (ω h)²), which this
// still tells from 1 at ω h = 1e-6.) A pure decay is the scalar p' = -k p; the position it
// drives is only its running sum.
bool stable(Method method, const LinearMode& mode, double h) {
  constexpr double kRounding = 1e-14;
  if (mode.frequency == 0.0) return bounded(decay_change(method, mode, h), kRounding);
  const Mat2 change = oscillator_change(method, mode, h);
  const double half_trace = 0.5 * change.trace();
  const double determinant = change.determinant();
  const double discriminant = half_trace * half_trace - determinant;
  if (discriminant < 0.0) {
    // μ = a ± i b: |1 + μ|² - 1 = 2a + a² + b² = 2a + det N.
    return 2.0 * half_trace + determinant <= 2.0 * kRounding;
  }
  // Two real μ, the larger in magnitude without cancellation and the other as det / it.
  const double larger = half_trace + std::copysign(std::sqrt(discriminant), half_trace);
  if (larger == 0.0) return true;
  return bounded(larger, kRounding) && bounded(determinant / larger, kRounding);
}

struct BodyRates {
  double linear_damping = 0.0;                    // Σ c (N s/m)
  double angular_damping = 0.0;                   // Σ c (N m s)
  physics::Vec3 torque = physics::Vec3::Zero();   // Σ constant torques, world (N m)
  physics::Vec3 gravity = physics::Vec3::Zero();  // Σ gravitational fields, world (m/s²)
  std::vector<physics::Spring> springs;
  std::vector<const physics::PenaltyContact*> penalty_contacts;
};

BodyRates rates_of(const physics::BodyModel& model) {
  BodyRates out;
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* d = std::get_if<physics::LinearDamping>(&law)) {
      out.linear_damping += d->coefficient;
    } else if (const auto* a = std::get_if<physics::AngularDamping>(&law)) {
      out.angular_damping += a->coefficient;
    } else if (const auto* t = std::get_if<physics::ConstantTorque>(&law)) {
      out.torque += t->torque;
    } else if (const auto* s = std::get_if<physics::Spring>(&law)) {
      out.springs.push_back(*s);
    } else if (const auto* g = std::get_if<physics::Gravity>(&law)) {
      out.gravity += g->acceleration;
    } else if (const auto* p = std::get_if<physics::PenaltyContact>(&law)) {
      out.penalty_contacts.push_back(p);
    }
  }
  return out;
}

// The fastest the body is expected to turn (rad/s). Torque-free, |ω|² <= 2E / I_min and
// |ω| <= |L| / I_min; a constant torque τ against angular damping c tends to τ / c, and without
// damping adds at most τ T / I_min.
double fastest_spin(const physics::BodyModel& model, const physics::BodyState& initial,
                    const BodyRates& rates, double duration) {
  const double smallest_inertia = model.constants.inertia.minCoeff();
  const double spin = initial.angular_velocity().norm();
  const double twice_energy = initial.angular_momentum().dot(initial.angular_velocity());
  const double free = std::max(spin, std::min(initial.angular_momentum().norm() / smallest_inertia,
                                              std::sqrt(twice_energy / smallest_inertia)));
  const double torque = rates.torque.norm();
  if (torque == 0.0) return free;
  const double driven = rates.angular_damping > 0.0 ? torque / rates.angular_damping
                                                    : free + torque * duration / smallest_inertia;
  return std::max(free, driven);
}

// The integrator to suggest instead of `current`: the first, in order of preference, that passes
// `ok` — the second-order splitting (exact damping and free rotation), then RK4, then the rest.
std::optional<Integrator> alternative(Integrator current, const auto& ok) {
  constexpr Method kPreference[] = {Method::splitting, Method::rk4, Method::splitting4,
                                    Method::symplectic_euler, Method::euler};
  for (const Method preferred : kPreference) {
    for (const Integrator candidate : physics::kAllIntegrators) {
      if (candidate != current && method_of(candidate) == preferred && ok(candidate)) {
        return candidate;
      }
    }
  }
  return std::nullopt;
}

std::string advice(const StepWarning& warning) {
  std::string out;
  if (warning.suggested_dt) out += printed("use dt <= %.3g s", *warning.suggested_dt);
  const auto suggest = [&](const std::string& setting) {
    out += (out.empty() ? "use " : " or ") + setting;
  };
  if (warning.suggested_integrator) {
    suggest(printed("integrator = \"%s\"",
                    std::string(physics::integrator_name(*warning.suggested_integrator)).c_str()));
  }
  if (warning.suggests_impulse_contact) suggest("contact = \"impulse\"");
  return out.empty() ? out : "; " + out;
}

}  // namespace

std::optional<StepWarning> check_mode(Integrator integrator, const NamedMode& named, double dt) {
  const LinearMode& mode = named.mode;
  const std::optional<double> limit = stability_limit(integrator, mode);
  if (!limit || dt <= *limit) return std::nullopt;
  const std::string name(physics::integrator_name(integrator));
  StepWarning warning;
  const bool oscillates = mode.frequency > 0.0;
  const double rate = oscillates ? mode.frequency : mode.damping_rate;
  const char* symbol = oscillates ? "ω_n" : "k";
  if (*limit == 0.0) {
    warning.message = printed("%s: %s is unstable on it at any dt (it gains energy every step)",
                              named.cause.c_str(), name.c_str());
  } else {
    warning.message = printed(
        "%s: %s·dt = %.3g is beyond %s's stability limit %s·dt <= %.4g%s, so %s",
        named.cause.c_str(), symbol, rate * dt, name.c_str(), symbol, rate * *limit,
        oscillates && mode.damping_rate > 0.0 ? " with this damping" : "", named.outcome.c_str());
    warning.suggested_dt = kSuggestedFractionOfLimit * *limit;
  }
  warning.suggested_integrator = alternative(integrator, [&](Integrator candidate) {
    const std::optional<double> other = stability_limit(candidate, mode);
    return other && dt <= *other;
  });
  warning.suggests_impulse_contact = named.penalty_contact;
  warning.message += advice(warning);
  return warning;
}

namespace {

// Of several modes of one kind (a box rocking about each of its axes), the one `integrator`
// is least stable on: the smallest limit.
const PenaltyMode* least_stable(Integrator integrator, const std::vector<PenaltyMode>& modes) {
  const PenaltyMode* out = nullptr;
  double smallest = std::numeric_limits<double>::infinity();
  for (const PenaltyMode& candidate : modes) {
    const std::optional<double> limit = stability_limit(integrator, candidate.mode);
    if (limit && (!out || *limit < smallest)) {
      out = &candidate;
      smallest = *limit;
    }
  }
  return out;
}

// The words of a penalty contact mode (sim/penalty_modes.hpp).
NamedMode described(const PenaltyMode& mode, const physics::PenaltyContact& law, double friction) {
  constexpr const char* kAxes[] = {"x", "y", "z"};
  const double rate = mode.mode.damping_rate, frequency = mode.mode.frequency;
  NamedMode out;
  out.mode = mode.mode;
  out.penalty_contact = true;
  switch (mode.kind) {
    case PenaltyMode::Kind::bounce:
      out.cause = printed(
          "penalty contact (k = %.4g N/m, c = %.4g N s/m per corner) makes the box bounce on "
          "four corners at ω_n = sqrt(4k/m) = %.4g rad/s, damped at 4c/m = %.4g /s",
          law.stiffness, law.damping, frequency, rate);
      break;
    case PenaltyMode::Kind::rock:
      out.cause = printed(
          "penalty contact makes the box rock on four corners about its %s axis at "
          "ω_n = sqrt(4k a²/I) = %.4g rad/s (lever a = %.3g m), damped at 4c a²/I = %.4g /s",
          kAxes[mode.axis], frequency, mode.lever, rate);
      break;
    case PenaltyMode::Kind::slide:
    case PenaltyMode::Kind::twist:
      out.cause = printed(
          "penalty contact's friction (μ = %.3g, slip speed %.3g m/s) makes a resting box's "
          "%s decay at k = %.4g /s",
          friction, law.slip_speed,
          mode.kind == PenaltyMode::Kind::slide ? "slip (with its rocking)" : "twist", rate);
      // The friction force is at most μ F_n: a slip that overshoots stays bounded.
      out.outcome = "the box will jitter on the plane instead of resting";
      break;
  }
  return out;
}

}  // namespace

std::optional<double> stability_limit(Integrator integrator, const LinearMode& mode) {
  const std::optional<Method> method = method_of(integrator);
  if (!method) return std::nullopt;
  const double scale = std::max(mode.damping_rate, mode.frequency);  // 1/s
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (scale <= 0.0) return kInfinity;
  if (!std::isfinite(scale)) return std::nullopt;  // a rate past double range: nothing to say
  // Walk up in steps of 1% of h until the map first grows, then bisect: the first crossing.
  constexpr double kSmallest = 1e-6, kLargest = 100.0;  // h · scale
  if (!stable(*method, mode, kSmallest / scale)) return 0.0;
  double stable_h = kSmallest / scale;
  double unstable_h = 0.0;
  for (double h = stable_h * 1.01; h <= kLargest / scale; h *= 1.01) {
    if (!stable(*method, mode, h)) {
      unstable_h = h;
      break;
    }
    stable_h = h;
  }
  if (unstable_h == 0.0) return kInfinity;
  for (int i = 0; i < 100 && unstable_h - stable_h > 1e-15 * stable_h; ++i) {
    const double middle = 0.5 * (stable_h + unstable_h);
    (stable(*method, mode, middle) ? stable_h : unstable_h) = middle;
  }
  return stable_h;
}

std::vector<StepWarning> check_step(const physics::BodyModel& model,
                                    const physics::BodyState& initial, Integrator integrator,
                                    double dt, double duration) {
  std::vector<StepWarning> warnings;
  const std::optional<Method> method = method_of(integrator);
  if (!method) return warnings;
  const physics::BodyConstants& constants = model.constants;
  const double smallest_inertia = constants.inertia.minCoeff();
  const BodyRates rates = rates_of(model);
  const double linear_rate = rates.linear_damping * constants.inverse_mass;

  const auto add = [&](const LinearMode& mode, const std::string& cause) {
    if (auto warning = check_mode(integrator, {.mode = mode, .cause = cause}, dt)) {
      warnings.push_back(std::move(*warning));
    }
  };
  if (linear_rate > 0.0) {
    add({.damping_rate = linear_rate},
        printed("linear damping makes the momentum decay at k = c/m = %.4g /s", linear_rate));
  }
  if (rates.angular_damping > 0.0) {
    const double rate = rates.angular_damping / smallest_inertia;
    add({.damping_rate = rate},
        printed("angular damping makes the spin decay at k = c/I_min = %.4g /s", rate));
  }
  for (const physics::Spring& spring : rates.springs) {
    // The spring pulls on its attachment; turning about the centre makes the body seem lighter
    // there, at most 1/m + |r|²/I_min in inverse mass.
    const double inverse_mass =
        constants.inverse_mass + spring.attachment.squaredNorm() / smallest_inertia;
    const LinearMode mode{.damping_rate = spring.damping * inverse_mass + linear_rate,
                          .frequency = std::sqrt(spring.stiffness * inverse_mass)};
    if (mode.frequency > 0.0) {
      add(mode, printed("the spring (stiffness %.4g N/m) makes the body oscillate at up to "
                        "ω_n = %.4g rad/s, damped at %.4g /s",
                        spring.stiffness, mode.frequency, mode.damping_rate));
    } else if (spring.damping > 0.0) {
      add(mode, printed("the spring's damping makes the attachment's speed decay at up to "
                        "k = %.4g /s",
                        mode.damping_rate));
    }
  }

  for (const physics::PenaltyContact* law : rates.penalty_contacts) {
    const PenaltyModes modes = penalty_modes(constants, *law, rates.gravity);
    for (const PenaltyMode* mode : {&modes.bounce, least_stable(integrator, modes.rocking),
                                    least_stable(integrator, modes.slipping)}) {
      if (!mode) continue;
      if (auto warning = check_mode(integrator, described(*mode, *law, modes.friction), dt)) {
        warnings.push_back(std::move(*warning));
      }
    }
  }

  if (!is_splitting(*method)) {
    const double spin = fastest_spin(model, initial, rates, duration);
    if (spin * dt > kMaxRotationPerStep) {
      StepWarning warning;
      // No step to suggest when the spin is beyond double range (a torque of 1e308 N m).
      if (std::isfinite(spin)) {
        warning.suggested_dt = kSuggestedFractionOfLimit * kMaxRotationPerStep / spin;
      }
      warning.suggested_integrator = alternative(integrator, [](Integrator candidate) {
        const std::optional<Method> other = method_of(candidate);
        return other && is_splitting(*other);
      });
      warning.message = printed(
          "it spins at up to %.4g rad/s, %.3g rad per step (more than %.2g), so %s will "
          "follow the orientation inaccurately",
          spin, spin * dt, kMaxRotationPerStep,
          std::string(physics::integrator_name(integrator)).c_str());
      warning.message += advice(warning);
      warnings.push_back(std::move(warning));
    }
  }
  return warnings;
}

}  // namespace tumble::sim
