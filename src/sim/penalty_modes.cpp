// The modes, derived. Take the face the box lies on as body axis n = y up, the in-face axes x and
// z, corners r = (±a_x, -a_y, ±a_z) (a the half sizes). A small rise z of the centre and a small
// turn θ move a corner up by δ = z + (θ × r)·y = z + θ_z r_x - θ_x r_z, and the law (forces.hpp)
// changes its normal force by -k δ - c δ'. Summed over the four corners, with Σ r_x = Σ r_z =
// Σ r_x r_z = 0:
//   F_y = -4k z - 4c z'                          bounce: ω_n² = 4k/m,           rate 4c/m
//   τ_x = -Σ r_z ΔF = -4k a_z² θ_x - 4c a_z² θ_x'  rock:   ω_n² = 4k a_z² / I_x,  rate 4c a_z² /
//   I_x
// and τ_z likewise with a_x: three uncoupled modes; sliding and twisting about y have no
// stiffness. The static load m g / 4 per corner adds m g a_y θ_x to τ_x (the centre stands over
// its support like an inverted pendulum): a relative change of m g a_y / (4k a_z²) in ω_n², 5e-5
// for a 1 kg unit cube at k = 1e5 N/m, left out. A body axis i is a rocking axis of the two faces
// it lies in, with the lever of the other in-face axis: the longer of the two is the stiffer.
//
// Friction, below the slip speed: -μ F_n v_t / sqrt(|v_t|² + v_s²) ≈ -(μ F_n / v_s) v_t, a
// viscous drag at each corner, ΣF_n = m g. Sliding along z, the corners slip at w = v_z - a_y ω_x
// (the twist terms cancel over the corners), and the drag F_z at the face's height turns the box,
// τ_x = -a_y F_z, so w' = F_z (1/m + a_y² / I_x): w decays at μ g (1 + m a_y² / I_x) / v_s. That is
// the fastest: it holds while the rocking springs do not yet resist the tilt, and they only slow
// it. Twisting about y, a corner at ρ = sqrt(a_x² + a_z²) slips at ω_y ρ, so ω_y decays at
// μ g m ρ² / (I_y v_s) (3 μ g / v_s for any uniform box). The modes are those of the linearised
// law: a slip of a few v_s saturates the friction at μ F_n, so growing slip stays bounded.
#include "sim/penalty_modes.hpp"

#include <algorithm>
#include <cmath>

#include "physics/shapes.hpp"

namespace tumble::sim {

PenaltyModes penalty_modes(const physics::BodyConstants& constants,
                           const physics::PenaltyContact& law, const physics::Vec3& gravity) {
  using Kind = PenaltyMode::Kind;
  const double m = constants.mass;
  const double k = law.stiffness, c = law.damping;
  const physics::Vec3& a = law.half_size;
  PenaltyModes out;
  // Splitting kicks evaluate the law once per kick (physics/integrators.cpp): frozen damping.
  const auto mode = [](double rate, double frequency_squared) {
    return LinearMode{.damping_rate = rate,
                      .frequency = std::sqrt(frequency_squared),
                      .kick_damping = KickDamping::frozen};
  };
  out.bounce = {.kind = Kind::bounce, .mode = mode(4.0 * c / m, 4.0 * k / m)};
  for (int i = 0; i < 3; ++i) {
    const double lever = std::max(a[(i + 1) % 3], a[(i + 2) % 3]);  // m
    const double share = lever * lever / constants.inertia[i];      // 1/kg
    out.rocking.push_back({.kind = Kind::rock,
                           .mode = mode(4.0 * c * share, 4.0 * k * share),
                           .axis = i,
                           .lever = lever});
  }

  for (const physics::Plane& plane : law.planes) {
    out.friction = std::max(out.friction, physics::combine(law.material, plane.material).friction);
  }
  // The drag coefficient of all four corners together, μ m g / v_s (N s/m).
  const double drag = out.friction * m * gravity.norm() / law.slip_speed;
  if (!(drag > 0.0)) return out;
  for (int i = 0; i < 3; ++i) {
    const double height = std::max(a[(i + 1) % 3], a[(i + 2) % 3]);  // m, over the face
    const double rate = drag * (1.0 / m + height * height / constants.inertia[i]);
    out.slipping.push_back(
        {.kind = Kind::slide, .mode = mode(rate, 0.0), .axis = i, .lever = height});
  }
  for (int n = 0; n < 3; ++n) {
    const double radius_squared = a.squaredNorm() - a[n] * a[n];  // ρ² (m²)
    out.slipping.push_back({.kind = Kind::twist,
                            .mode = mode(drag * radius_squared / constants.inertia[n], 0.0),
                            .axis = n,
                            .lever = std::sqrt(radius_squared)});
  }
  return out;
}

// With ω_n² = 4k/m and ζ = c / sqrt(k m), a landing at speed v₀ sinks d(t) = (v₀/ω_d) e^{-ζω_n t}
// sin(ω_d t), ω_d = ω_n sqrt(1 - ζ²). The force, ∝ ω_n² d + 2ζω_n d', reaches zero where
// tan(ω_d t) = -2ζ sqrt(1 - ζ²) / (1 - 2ζ²), i.e. ω_d t* = π - 2 asin ζ = 2 acos ζ; from there
// the box flies free, at d'(t*) = -v₀ e^{-ζω_n t*} (the bracket cos(2 acos ζ) - ζ/sqrt(1 - ζ²)
// sin(2 acos ζ) is -1). For ζ > 1 the same steps with sinh give ω' t* = 2 acosh ζ,
// ω' = ω_n sqrt(ζ² - 1); both tend to e^{-2} at ζ = 1.
double penalty_restitution(double damping_ratio) {
  const double zeta = damping_ratio;
  if (zeta == 1.0) return std::exp(-2.0);
  if (zeta < 1.0) return std::exp(-2.0 * zeta * std::acos(zeta) / std::sqrt(1.0 - zeta * zeta));
  return std::exp(-2.0 * zeta * std::acosh(zeta) / std::sqrt(zeta * zeta - 1.0));
}

double penalty_damping_for_restitution(double restitution, double stiffness, double mass) {
  // e(ζ) falls from 1 at ζ = 0 towards 0 (as 1/(4ζ²)): bracket, then bisect.
  double low = 0.0, high = 1.0;
  while (penalty_restitution(high) > restitution && high < 1e12) high *= 2.0;
  for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i) {
    const double middle = 0.5 * (low + high);
    (penalty_restitution(middle) > restitution ? low : high) = middle;
  }
  return 0.5 * (low + high) * std::sqrt(stiffness * mass);
}

}  // namespace tumble::sim
