#include "physics/interpolation.hpp"

#include <cmath>

namespace tumble::physics {

Quat slerp_shortest(const Quat& a, const Quat& b, double alpha) {
  double cosine = a.dot(b);
  Eigen::Vector4d target = b.coeffs();
  if (cosine < 0.0) {
    cosine = -cosine;
    target = -target;
  }
  double weight_a = 1.0 - alpha;
  double weight_b = alpha;
  // Nearly parallel: sin(θ) → 0 makes the slerp weights 0/0; lerp is exact to round-off there.
  if (cosine < 1.0 - 1e-9) {
    const double angle = std::acos(cosine);
    const double inverse_sine = 1.0 / std::sin(angle);
    weight_a = std::sin((1.0 - alpha) * angle) * inverse_sine;
    weight_b = std::sin(alpha * angle) * inverse_sine;
  }
  Quat out;
  out.coeffs() = weight_a * a.coeffs() + weight_b * target;
  return out.normalized();
}

BodyState interpolate(const BodyState& previous, const BodyState& current, double alpha,
                      const BodyConstants& constants) {
  // The bracketing states themselves, bit for bit, at the ends.
  if (alpha <= 0.0) return previous;
  if (alpha >= 1.0) return current;
  const PrimaryState& a = previous.primary();
  const PrimaryState& b = current.primary();
  const auto lerp = [alpha](const Vec3& from, const Vec3& to) -> Vec3 {
    return (1.0 - alpha) * from + alpha * to;
  };
  return BodyState(PrimaryState{.position = lerp(a.position, b.position),
                                .momentum = lerp(a.momentum, b.momentum),
                                .orientation = slerp_shortest(a.orientation, b.orientation, alpha),
                                .angular_momentum = lerp(a.angular_momentum, b.angular_momentum)},
                   constants);
}

}  // namespace tumble::physics
