#include "physics/free_rigid_body.hpp"

#include <algorithm>
#include <array>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

// The orientation is split as R(t) = A Rz(ψ(t)) P(l(t)) (as in Celledoni, Fassò, Säfström & Zanna
// 2008): l = body-frame L / |L|, P(l) a rotation taking l to the circulation axis e_c (see
// make_elliptic), A a constant rotation taking e_c to the world L̂, ψ the angle about L. Then
// R(t₁) = Rot(L̂, ψ₁ − ψ₀) R(t₀) P(l₀)ᵀ P(l₁), and only l(t) and ψ(t) are needed. Our P is the
// minimal rotation l → e_c, regular away from l = −e_c, which the motion never nears (l_c > 0).
// Differentiating R and dotting with l gives
//     ψ' = 2T/|L| − (l_a l_b' − l_b l_a')/(1 + l_c),
// and with Euler's equations l_a l_b' − l_b l_a' = |L| l_c (e − 1/I_c), e = 2T/|L|²:
//     ψ' = |L|/I_c + |L| (e − 1/I_c) / (1 + l_c).
// 1/(1 + l_c) = 1/(1 − l_c²) − l_c/(1 − l_c²); the first part integrates to Legendre's Π (the
// Euler-angle precession rate of Landau & Lifshitz §37 and van Zon & Schofield 2007), the second
// is the rate of the azimuth of (l_a, l_b), which we take in closed form. The split avoids the
// cancellation of ∫ dt/(1 + l_c) near a steady spin and the azimuth singularity of the
// Euler-angle frame there. Near the separatrix the phase τ of the elliptic functions is
// ill-conditioned, so it is never formed: l(t₁) comes from l(t₀) by the addition theorem of sn,
// cn, dn and ∫ dτ/(1 − n sn²τ) by the addition theorem of the third kind.

namespace tumble::physics {
namespace {

constexpr double kPi = std::numbers::pi;
// Boost.Math would otherwise evaluate double arguments in long double (x87), four times slower,
// and throw on arguments it cannot take; a non-finite state should come back non-finite instead.
using DoublePrecision = boost::math::policies::policy<
    boost::math::policies::promote_double<false>,
    boost::math::policies::domain_error<boost::math::policies::ignore_error>,
    boost::math::policies::evaluation_error<boost::math::policies::ignore_error>>;
// Smallest k'² we let through: exactly on the separatrix (k'² = 0) the period is infinite and the
// arithmetic-geometric mean below would not converge. The orbit with k'² = 2⁻¹⁰⁰⁰ passes within
// 2⁻⁵⁰⁰ |L| of the saddle: the same orbit to every digit we hold.
constexpr double kSmallestComplement = 0x1p-1000;

double squared(double x) {
  return x * x;
}

// Rotation by `angle` (rad) about the unit `axis`.
Quat rotation_about(const Vec3& axis, double angle) {
  const double half = 0.5 * angle;
  const double s = std::sin(half);
  return Quat(std::cos(half), s * axis.x(), s * axis.y(), s * axis.z());
}

// The minimal rotation taking the direction of v to +z: about v × z by the angle θ between them.
// (1 + cos θ, sin θ û) normalised is (cos θ/2, sin θ/2 û); regular unless v points along −z.
Quat align_with_z(const Vec3& v) {
  const Vec3 l = v.normalized();
  return Quat(1.0 + l.z(), l.y(), -l.x(), 0.0).normalized();
}

// The Jacobi amplitude am(u | k) by the arithmetic-geometric mean (Abramowitz & Stegun 16.4.2-3),
// seeded with k' itself so that nothing is lost as k → 1. Continuous in u: not reduced mod 2π.
// A&S's step φₙ₋₁ = (φₙ + asin(cₙ/aₙ sin φₙ))/2 is taken as an atan2 whose cosine,
// sqrt(cos²φₙ + (bₙ/aₙ)² sin²φₙ), keeps its digits where the arcsine's argument nears ±1.
double jacobi_amplitude(double u, double modulus_squared, double complement_squared) {
  // Converges quadratically once a ≈ b; k'² = 2⁻¹⁰⁰⁰ needs 13 steps, k'² = 0.5 needs 4.
  constexpr int kMaxSteps = 24;
  std::array<double, kMaxSteps + 1> a{};
  std::array<double, kMaxSteps + 1> b{};
  std::array<double, kMaxSteps + 1> c{};
  a[0] = 1.0;
  b[0] = std::sqrt(complement_squared);
  c[0] = std::sqrt(modulus_squared);
  int steps = 0;
  while (steps < kMaxSteps && c[steps] > 0x1p-53 * a[steps]) {
    a[steps + 1] = 0.5 * (a[steps] + b[steps]);
    b[steps + 1] = std::sqrt(a[steps] * b[steps]);
    c[steps + 1] = squared(c[steps]) / (4.0 * a[steps + 1]);  // (a − b)/2 without cancellation
    ++steps;
  }
  double amplitude = std::ldexp(a[steps] * u, steps);
  for (; steps > 0; --steps) {
    const double s = std::sin(amplitude);
    const double ratio = b[steps] / a[steps];  // sqrt(1 − (cₙ/aₙ)²), as aₙ² − cₙ² = bₙ²
    const double defect = std::atan2(c[steps] / a[steps] * s,
                                     std::sqrt(squared(std::cos(amplitude)) + squared(ratio * s)));
    amplitude = 0.5 * (amplitude + defect);
  }
  return amplitude;
}

// Legendre's Π(n; φ | k) for |φ| ≤ π/2 from sin φ, cos φ ≥ 0 and Δ = sqrt(1 − k² sin² φ) given
// separately, so that Δ keeps its digits near the separatrix: Carlson's form
// Π = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, 1 − n s²) (DLMF §19.25).
double third_kind_reduced(double characteristic, double sin_phi, double cos_phi, double delta) {
  const double c2 = squared(cos_phi);
  const double d2 = squared(delta);
  const double s2 = squared(sin_phi);
  return sin_phi * boost::math::ellint_rf(c2, d2, 1.0, DoublePrecision()) +
         characteristic / 3.0 * sin_phi * s2 *
             boost::math::ellint_rj(c2, d2, 1.0, 1.0 - characteristic * s2, DoublePrecision());
}

// Π(n; φ | k) for any φ: Π(jπ + r) = 2j Π(n | k) + Π(r), |r| ≤ π/2.
double third_kind(double characteristic, double amplitude, double sin_phi, double cos_phi,
                  double delta, double complement_squared) {
  const double turns = std::round(amplitude / kPi);
  const double sign = std::fmod(turns, 2.0) == 0.0 ? 1.0 : -1.0;
  const double reduced =
      third_kind_reduced(characteristic, sign * sin_phi, std::abs(cos_phi), delta);
  if (turns == 0.0) return reduced;
  const double complete = boost::math::ellint_rf(0.0, complement_squared, 1.0, DoublePrecision()) +
                          characteristic / 3.0 *
                              boost::math::ellint_rj(0.0, complement_squared, 1.0,
                                                     1.0 - characteristic, DoublePrecision());
  return 2.0 * turns * complete + reduced;
}

// The azimuth of (A_a cos φ, A_b sin φ) minus φ: the angle from (cos φ, sin φ) to that point,
// always within (−π/2, π/2) because both lie in the same quadrant.
double azimuth_offset(const Vec3& amplitude, double sin_phi, double cos_phi) {
  return std::atan2((amplitude.y() - amplitude.x()) * sin_phi * cos_phi,
                    amplitude.x() * squared(cos_phi) + amplitude.y() * squared(sin_phi));
}

// Three different moments: Jacobi's solution of Euler's equations (Landau & Lifshitz §37; van Zon
// & Schofield 2007) written in an elliptic frame (a, b, c): b the intermediate axis, c the axis L
// circulates about (the largest moment when |L|² > 2E I_b, the smallest when |L|² < 2E I_b), and
// L_c > 0. Then L_a = A_a cn τ, L_b = ±A_b sn τ, L_c = A_c dn τ (in units of |L|), τ = ω_p t + τ₀.
// Every invariant is a sum of terms of one sign, so none loses digits near a steady spin; only
// |L|² − 2E I_b (the distance from the separatrix) is a true difference. τ₀ itself is never
// formed: near the separatrix it is ill-conditioned, and the addition theorems need only sn, cn
// and dn of τ₀, which are L_a / A_a, ±L_b / A_b and L_c / A_c.
FreeRigidBodyFlow::Elliptic make_elliptic(const Vec3& inertia, const Vec3& body_momentum,
                                          double norm) {
  int largest = 0;
  int smallest = 0;
  for (int i = 1; i < 3; ++i) {
    if (inertia[i] > inertia[largest]) largest = i;
    if (inertia[i] < inertia[smallest]) smallest = i;
  }
  const int b = 3 - largest - smallest;
  // L / |L|: everything below but ω_p is scale-free, and a huge |L| cannot overflow the squares.
  const Vec3 l = body_momentum / norm;
  // (|L|² − 2E I_b)/|L|² = Σ l_i² (I_i − I_b)/I_i.
  const double separatrix =
      squared(l[largest]) * (inertia[largest] - inertia[b]) / inertia[largest] +
      squared(l[smallest]) * (inertia[smallest] - inertia[b]) / inertia[smallest];
  const int c = separatrix >= 0.0 ? largest : smallest;
  const int a = separatrix >= 0.0 ? smallest : largest;

  FreeRigidBodyFlow::Elliptic e;
  // A signed permutation with determinant +1: rows a, b, c, with L_c ≥ 0.
  const Vec3 row_b = Vec3::Unit(b);
  const Vec3 row_c = (l[c] >= 0.0 ? 1.0 : -1.0) * Vec3::Unit(c);
  e.to_elliptic.row(0) = row_b.cross(row_c).transpose();
  e.to_elliptic.row(1) = row_b.transpose();
  e.to_elliptic.row(2) = row_c.transpose();
  const Vec3 m = e.to_elliptic * l;  // exact: a signed permutation
  const double ia = inertia[a];
  const double ib = inertia[b];
  const double ic = inertia[c];
  e.inertia = Vec3(ia, ib, ic);
  const double ma2 = squared(m.x());
  const double mb2 = squared(m.y());
  const double mc2 = squared(m.z());
  // X = (2E I_c − |L|²)/|L|² and Y = (|L|² − 2E I_a)/|L|², both of the sign of I_c − I_a.
  const double x = ma2 * (ic - ia) / ia + mb2 * (ic - ib) / ib;
  const double y = mb2 * (ib - ia) / ib + mc2 * (ic - ia) / ic;
  // A_a² = X I_a/(I_c − I_a), A_b² = X I_b/(I_c − I_b), A_c² = Y I_c/(I_c − I_a) (L&L §37), each
  // written as a sum of non-negative terms.
  e.amplitude = Vec3(std::sqrt(ma2 + mb2 * ia * (ic - ib) / (ib * (ic - ia))),
                     std::sqrt(ma2 * ib * (ic - ia) / (ia * (ic - ib)) + mb2),
                     std::sqrt(mc2 + mb2 * ic * (ib - ia) / (ib * (ic - ia))));
  e.norm = norm;
  e.sign_b = ic > ib ? 1.0 : -1.0;
  // k² = (I_b − I_a) X / ((I_c − I_b) Y); k'² = (I_c − I_a)(|L|² − 2E I_b) / ((I_c − I_b) Y |L|²).
  double k2 = (ib - ia) * x / ((ic - ib) * y);
  double kp2 = (ic - ia) * separatrix / ((ic - ib) * y);
  if (kp2 < 0.5) {
    kp2 = std::max(kp2, kSmallestComplement);
    k2 = 1.0 - kp2;
  } else {
    kp2 = 1.0 - k2;
  }
  e.modulus = std::sqrt(k2);
  e.complement_squared = kp2;
  // ω_p = |L| sqrt((I_c − I_b) Y / (I_a I_b I_c)) (L&L §37).
  e.frequency = norm * std::sqrt((ic - ib) * y / (ia * ib * ic));
  // 1 − l_c² = (A_a²/|L|²)(1 − n sn² τ) with n = −I_c (I_b − I_a) / (I_a (I_c − I_b)) < 0, which
  // depends on the moments only (as in van Zon & Schofield 2007).
  e.characteristic = -ic * (ib - ia) / (ia * (ic - ib));
  // (sn τ₀, cn τ₀) = (±L_b / A_b, L_a / A_a): a unit vector up to round-off, made exactly one.
  const double sn0 = e.sign_b * m.y() / e.amplitude.y();
  const double cn0 = m.x() / e.amplitude.x();
  const double unit = std::hypot(sn0, cn0);
  e.start = Vec3(sn0 / unit, cn0 / unit, m.z() / e.amplitude.z());
  e.start_offset = azimuth_offset(e.amplitude, e.start.x(), e.start.y());
  e.start_alignment = align_with_z(m);
  return e;
}

// Orientation after `elapsed` for three different moments; see the file comment.
Quat elliptic_orientation(const FreeRigidBodyFlow::Elliptic& e, const Quat& start, const Vec3& axis,
                          double elapsed) {
  const double k2 = squared(e.modulus);
  const double kp2 = e.complement_squared;
  const double n = e.characteristic;
  // sn, cn, dn of u = τ₁ − τ₀; dn² = k'² + k² cn² has no cancellation near the separatrix.
  const double u = e.frequency * elapsed;
  const double am_u = jacobi_amplitude(u, k2, kp2);
  const double su = std::sin(am_u);
  const double cu = std::cos(am_u);
  const double du = std::sqrt(kp2 + k2 * squared(cu));
  // sn, cn, dn of τ₁ = τ₀ + u by the addition theorem (DLMF 22.8.1-2), with the denominator
  // 1 − k² sn²τ₀ sn²u written as cn²τ₀ + sn²τ₀ dn²u.
  const double s0 = e.start.x();
  const double c0 = e.start.y();
  const double d0 = e.start.z();
  const double denominator = squared(c0) + squared(s0 * du);
  const double s1 = (s0 * cu * du + su * c0 * d0) / denominator;
  const double c1 = (c0 * cu - s0 * su * d0 * du) / denominator;
  const double d1 = std::sqrt(kp2 + k2 * squared(c1));

  // ∫ dτ / (1 − n sn²τ) from τ₀ to τ₁ = P(u) − C(τ₀, u), P(u) = Π(n; am u | k), by Jacobi's
  // addition theorem for integrals of the third kind (Whittaker & Watson, ch. XXII) with
  // n = k² sn² α; for n < 0, α is imaginary and its logarithm becomes an arctangent:
  //   C = sqrt(−n / ((k² − n)(1 − n))) atan(sqrt(−n (k² − n)(1 − n)) s₀ s_u s₁
  //                                         / (1 − n s₁² + n s₀ s_u c₁ d₁)).
  // (Checked against quadrature; the denominator stays ≥ 1, so no branch is crossed.) C is
  // bounded and smooth, unlike Π at either end near the separatrix.
  const double scale = std::sqrt(-n * (k2 - n) * (1.0 - n));
  const double correction =
      (-n / scale) *
      std::atan2(scale * s0 * su * s1, 1.0 - n * squared(s1) + n * s0 * su * c1 * d1);
  const double third = third_kind(n, am_u, su, cu, du, kp2) - correction;
  // am τ₁ − am τ₀ = am u + arg((cn τ₁ + i sn τ₁)(cn τ₀ − i sn τ₀)(cn u − i sn u)), the last term
  // being the bounded defect of the amplitude's addition.
  const std::complex<double> defect =
      std::complex<double>(c1, s1) * std::complex<double>(c0, -s0) * std::complex<double>(cu, -su);
  const double amplitude_change = am_u + std::arg(defect);

  const double ia = e.inertia.x();
  const double ic = e.inertia.z();
  // ψ₁ − ψ₀ = |L| t / I_c + |L| (1/I_a − 1/I_c) ∫ dτ/(1 − n sn²τ) / ω_p − Δ(azimuth of L_a, L_b),
  // using |L| (e − 1/I_c) / (1 − l_c²) = |L| (1/I_a − 1/I_c) / (1 − n sn² τ).
  const double azimuth_change =
      e.sign_b * (amplitude_change + azimuth_offset(e.amplitude, s1, c1) - e.start_offset);
  const double turn_about_momentum =
      e.norm * elapsed / ic + e.norm * (1.0 / ia - 1.0 / ic) * third / e.frequency - azimuth_change;

  const Vec3 momentum(e.amplitude.x() * c1, e.sign_b * e.amplitude.y() * s1, e.amplitude.z() * d1);
  // P(l₀)ᵀ P(l₁) in the elliptic frame, then carried to the body frame by the signed permutation.
  const Quat relative = e.start_alignment.conjugate() * align_with_z(momentum);
  const Vec3 body_axis = e.to_elliptic.transpose() * relative.vec();
  const Quat body_turn(relative.w(), body_axis.x(), body_axis.y(), body_axis.z());
  return rotation_about(axis, turn_about_momentum) * start * body_turn;
}

}  // namespace

FreeRigidBodyFlow::FreeRigidBodyFlow(const BodyConstants& constants, const Quat& orientation,
                                     const Vec3& angular_momentum)
    : start_(orientation.normalized()) {
  const double norm = angular_momentum.norm();
  if (norm == 0.0) return;
  axis_ = angular_momentum / norm;
  const Vec3 body_momentum = start_.conjugate() * angular_momentum;  // kg m²/s
  const Vec3& inertia = constants.inertia;
  // A state that has already blown up stays not-a-number (for the caller's finiteness checks)
  // rather than reaching the elliptic integrals.
  if (!body_momentum.allFinite()) {
    kind_ = Kind::steady;
    rate_about_momentum_ = std::numeric_limits<double>::quiet_NaN();
    return;
  }

  // A cube, or L along a principal axis: steady rotation about L at |L| / I.
  if (constants.isotropic) {
    kind_ = Kind::steady;
    rate_about_momentum_ = norm * constants.inverse_inertia.x();
    return;
  }
  for (int i = 0; i < 3; ++i) {
    if (body_momentum[(i + 1) % 3] == 0.0 && body_momentum[(i + 2) % 3] == 0.0) {
      kind_ = Kind::steady;
      rate_about_momentum_ = norm / inertia[i];
      return;
    }
  }
  // Symmetric top, I₁ = I₂ ≠ I₃: R(t) = Rot(L̂, |L| t / I₁) R₀ Rot(e₃, (1/I₃ − 1/I₁) L₃ t), so the
  // body-frame L precesses about e₃ at (1/I₁ − 1/I₃) L₃ (Landau & Lifshitz §33; Celledoni et al.
  // 2008).
  for (int s = 0; s < 3; ++s) {
    const double equal = inertia[(s + 1) % 3];
    if (equal == inertia[(s + 2) % 3]) {
      kind_ = Kind::symmetric;
      rate_about_momentum_ = norm / equal;
      symmetry_axis_ = Vec3::Unit(s);
      rate_about_symmetry_axis_ = (1.0 / inertia[s] - 1.0 / equal) * body_momentum[s];
      return;
    }
  }
  kind_ = Kind::elliptic;
  elliptic_ = make_elliptic(inertia, body_momentum, norm);
  // Amplitudes that underflow leave a spin that is steady to every digit we hold.
  if (elliptic_.amplitude.x() == 0.0 || elliptic_.amplitude.y() == 0.0) {
    kind_ = Kind::steady;
    rate_about_momentum_ = norm / elliptic_.inertia.z();
  }
}

Quat FreeRigidBodyFlow::orientation_after(double elapsed) const {
  switch (kind_) {
    case Kind::still:
      return start_;
    case Kind::steady:
      return rotation_about(axis_, rate_about_momentum_ * elapsed) * start_;
    case Kind::symmetric:
      return rotation_about(axis_, rate_about_momentum_ * elapsed) * start_ *
             rotation_about(symmetry_axis_, rate_about_symmetry_axis_ * elapsed);
    case Kind::elliptic:
      return elliptic_orientation(elliptic_, start_, axis_, elapsed);
  }
  return start_;
}

Quat free_rigid_body(const BodyConstants& constants, const Quat& orientation,
                     const Vec3& angular_momentum, double h) {
  return FreeRigidBodyFlow(constants, orientation, angular_momentum).orientation_after(h);
}

}  // namespace tumble::physics
