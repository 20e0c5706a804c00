#include "physics/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

namespace tumble::physics {

Mat3 sphere_inertia(double mass, double radius) {
  return Mat3::Identity() * (0.4 * mass * radius * radius);
}

BodyConstants sphere_constants(double mass, double radius) {
  return constants_from_moments(mass, sphere_inertia(mass, radius).diagonal());
}

Mat3 cylinder_inertia(double mass, double radius, double length) {
  const double r2 = radius * radius, h2 = length * length;
  const double across = mass * (3.0 * r2 + h2) / 12.0;
  return Vec3(across, 0.5 * mass * r2, across).asDiagonal();
}

Mat3 capsule_inertia(double mass, double radius, double length) {
  const double r = radius, h = length;
  const double cylinder_volume = std::numbers::pi * r * r * h;
  const double caps_volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double density = mass / (cylinder_volume + caps_volume);
  const double mc = density * cylinder_volume, ms = density * caps_volume;
  const double across =
      mc * (3.0 * r * r + h * h) / 12.0 + 0.4 * ms * r * r + ms * h * (3.0 * r + 2.0 * h) / 8.0;
  const double along = 0.5 * mc * r * r + 0.4 * ms * r * r;
  return Vec3(across, along, across).asDiagonal();
}

MassProperties polyhedron_mass_properties(std::span<const Vec3> vertices,
                                          std::span<const std::array<std::uint32_t, 3>> triangles,
                                          double density) {
  // About the vertices' mean (inside a convex solid), for round-off: the tetrahedra are small
  // there and their determinants well conditioned.
  Vec3 apex = Vec3::Zero();
  for (const Vec3& v : vertices) apex += v;
  apex /= static_cast<double>(vertices.size());
  double six_volume = 0.0;     // Σ det = 6 V
  Vec3 first = Vec3::Zero();   // Σ det (a + b + c) / 4 = 6 ∫ x dV
  Mat3 second = Mat3::Zero();  // Σ det (a aᵀ + b bᵀ + c cᵀ + s sᵀ) / 20 = 6 ∫ x xᵀ dV
  for (const auto& t : triangles) {
    const Vec3 a = vertices[t[0]] - apex, b = vertices[t[1]] - apex, c = vertices[t[2]] - apex;
    const double det = a.dot(b.cross(c));
    const Vec3 sum = a + b + c;
    six_volume += det;
    first += det * sum / 4.0;
    second += det / 20.0 *
              (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  const double volume = six_volume / 6.0;
  MassProperties out;
  out.mass = density * volume;
  const Vec3 centre = first / six_volume;  // about the apex
  // The covariance ρ ∫ x xᵀ dV about the centre of mass, then I = tr(C) E − C.
  const Mat3 covariance = density * second / 6.0 - out.mass * centre * centre.transpose();
  out.inertia = Mat3::Identity() * covariance.trace() - covariance;
  out.inertia = 0.5 * (out.inertia + out.inertia.transpose()).eval();
  out.centre = apex + centre;
  return out;
}

PrincipalAxes principal_axes(const Mat3& inertia) {
  const double off = std::abs(inertia(0, 1)) + std::abs(inertia(0, 2)) + std::abs(inertia(1, 2));
  if (off <= 1e-13 * inertia.trace()) return {.moments = inertia.diagonal()};
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia);
  PrincipalAxes out{.moments = solver.eigenvalues(), .rotation = solver.eigenvectors()};
  // Each axis pointing into the positive half of the given frame's axis it lies nearest, then
  // right-handed: the same tensor gives the same axes on every run and compiler.
  for (int k = 0; k < 3; ++k) {
    Eigen::Index largest = 0;
    out.rotation.col(k).cwiseAbs().maxCoeff(&largest);
    if (out.rotation(largest, k) < 0.0) out.rotation.col(k) *= -1.0;
  }
  if (out.rotation.determinant() < 0.0) out.rotation.col(2) *= -1.0;
  return out;
}

}  // namespace tumble::physics
