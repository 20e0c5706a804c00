// Mass properties of solids of uniform density: closed forms for the sphere, the cylinder and the
// capsule, and the exact integrals over a closed polyhedron (a convex hull's surface), with the
// tensor's principal axes, which become a body's frame (BodyConstants keeps principal moments).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "physics/rigid_body.hpp"

namespace tumble::physics {

// A solid's mass (kg), centre of mass (m) and inertia tensor about that centre (kg m²), in the
// frame its geometry was given in.
struct MassProperties {
  double mass = 0.0;
  Vec3 centre = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};

// A uniform ball of `radius` (m): I = 2/5 m r² about every axis.
Mat3 sphere_inertia(double mass, double radius);
// The constants of a uniform ball of `mass` (kg) and `radius` (m).
BodyConstants sphere_constants(double mass, double radius);
// A uniform solid cylinder of `radius` and `length` (m) along its y axis: I_y = m r²/2,
// I_x = I_z = m (3 r² + h²)/12.
Mat3 cylinder_inertia(double mass, double radius, double length);
// A uniform capsule: a cylinder of `radius` and `length` (m) along y, closed by two hemispheres of
// the same radius. The mass splits by volume between the cylinder (m_c) and the caps (m_s, both
// together); each cap's centroid lies 3r/8 beyond the cylinder's end, its own perpendicular moment
// about that centroid is 83/320 of its mass times r², so that about the centre
// I_x = m_c (3r² + h²)/12 + 2/5 m_s r² + m_s h (3r + 2h)/8 and I_y = m_c r²/2 + 2/5 m_s r² (the
// same as Box3D's b3ComputeCapsuleMass).
Mat3 capsule_inertia(double mass, double radius, double length);

// The solid bounded by a closed triangle surface of density `density` (kg/m³): the triangles index
// `vertices` and wind counter-clockwise seen from outside. Exact up to round-off: the solid is cut
// into tetrahedra, one per triangle, with an apex at the vertices' mean, and each tetrahedron's
// volume, first and second moments summed (the canonical tetrahedron's covariance, as in Kallay,
// "Computing the Moment of Inertia of a Solid Defined by a Triangle Mesh", JGT 11(2), 2006, and
// Blow & Binstock, 2004); the tensor is then moved to the centre of mass (parallel axes).
MassProperties polyhedron_mass_properties(std::span<const Vec3> vertices,
                                          std::span<const std::array<std::uint32_t, 3>> triangles,
                                          double density);

// A tensor's principal moments (kg m²) and the rotation whose columns are its principal axes
// (right-handed, in the tensor's frame): inertia = rotation * diag(moments) * rotationᵀ. A tensor
// that is already diagonal (off-diagonal terms below 1e-13 of its trace) keeps its axes and order,
// so a box's hull spins as the box does, bit for bit in its frame.
struct PrincipalAxes {
  Vec3 moments = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
};
PrincipalAxes principal_axes(const Mat3& inertia);

}  // namespace tumble::physics
