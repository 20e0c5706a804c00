#include "sim/stability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>
#include <variant>

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

// N of a step of h (s) on a decaying momentum, p' = -k p: the map's factor minus one.
double decay_change(Method method, double k, double h) {
  const double z = -k * h;
  switch (method) {
    case Method::euler:
    case Method::symplectic_euler:  // the kick is an explicit Euler step of the momentum
      return z;
    case Method::rk4:
      return z * (1.0 + z / 2.0 * (1.0 + z / 3.0 * (1.0 + z / 4.0)));
    case Method::splitting:  // damping applied exactly
    case Method::splitting4:
      return std::expm1(z);
  }
  return 0.0;
}

// N of (I + second)(I + first): first, then second.
Mat2 then(const Mat2& first, const Mat2& second) {
  return first + second + second * first;
}

// N of Strang splitting over h (s): half a kick, a drift, half a kick, each kick the exact flow
// of y'' = -ω² y - k y' with y frozen (physics/integrators.cpp): v -> e^{-kh/2} v - φ ω² y.
Mat2 strang_change(const LinearMode& mode, double h) {
  const double k = mode.damping_rate;
  const double half = 0.5 * h;
  const double impulse_time = k == 0.0 ? half : -std::expm1(-k * half) / k;  // φ (s)
  Mat2 half_kick, drift;
  half_kick << 0.0, 0.0, -impulse_time * mode.frequency * mode.frequency, std::expm1(-k * half);
  drift << 0.0, h, 0.0, 0.0;
  return then(then(half_kick, drift), half_kick);
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
      change = strang_change(mode, h);
      break;
    case Method::splitting4: {
      // Yoshida's triple jump: Strang steps of γ₁h, γ₂h, γ₁h with γ₁ = 1 / (2 - ∛2), γ₂ = 1 - 2γ₁.
      const double outer = 1.0 / (2.0 - std::cbrt(2.0));
      const Mat2 outer_step = strang_change(mode, outer * h);
      change = then(then(outer_step, strang_change(mode, (1.0 - 2.0 * outer) * h)), outer_step);
      break;
    }
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
  if (mode.frequency == 0.0) return bounded(decay_change(method, mode.damping_rate, h), kRounding);
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

std::string printed(const char* format, auto... values) {
  const int size = std::snprintf(nullptr, 0, format, values...);
  std::string text(static_cast<std::size_t>(std::max(size, 0)), '\0');
  std::snprintf(text.data(), text.size() + 1, format, values...);
  return text;
}

struct BodyRates {
  double linear_damping = 0.0;                   // Σ c (N s/m)
  double angular_damping = 0.0;                  // Σ c (N m s)
  physics::Vec3 torque = physics::Vec3::Zero();  // Σ constant torques, world (N m)
  std::vector<physics::Spring> springs;
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
  if (warning.suggested_integrator) {
    out += out.empty() ? "use " : " or ";
    out += printed("integrator = \"%s\"",
                   std::string(physics::integrator_name(*warning.suggested_integrator)).c_str());
  }
  return out.empty() ? out : "; " + out;
}

// A warning when `dt` is beyond the stability limit of `integrator` on `mode`.
std::optional<StepWarning> check_mode(Integrator integrator, const LinearMode& mode,
                                      const std::string& cause, double dt) {
  const std::optional<double> limit = stability_limit(integrator, mode);
  if (!limit || dt <= *limit) return std::nullopt;
  const std::string name(physics::integrator_name(integrator));
  StepWarning warning;
  const bool oscillates = mode.frequency > 0.0;
  const double rate = oscillates ? mode.frequency : mode.damping_rate;
  const char* symbol = oscillates ? "ω_n" : "k";
  if (*limit == 0.0) {
    warning.message = printed("%s: %s is unstable on it at any dt (it gains energy every step)",
                              cause.c_str(), name.c_str());
  } else {
    warning.message = printed(
        "%s: %s·dt = %.3g is beyond %s's stability limit %s·dt <= %.4g%s, "
        "so the motion will blow up",
        cause.c_str(), symbol, rate * dt, name.c_str(), symbol, rate * *limit,
        oscillates && mode.damping_rate > 0.0 ? " with this damping" : "");
    warning.suggested_dt = kSuggestedFractionOfLimit * *limit;
  }
  warning.suggested_integrator = alternative(integrator, [&](Integrator candidate) {
    const std::optional<double> other = stability_limit(candidate, mode);
    return other && dt <= *other;
  });
  warning.message += advice(warning);
  return warning;
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
    if (auto warning = check_mode(integrator, mode, cause, dt)) {
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
