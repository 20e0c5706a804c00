// A body's start orientation, written one of three ways: `orientation` (a unit quaternion),
// `rotation` (an axis and an angle) or `euler_degrees` (three angles). Internal to src/scene/.
#pragma once

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// The rotation of `degrees` about `axis` (any length but 0, world frame):
// q = (cos(θ/2), sin(θ/2) a/|a|), θ in radians.
physics::Quat axis_angle_quaternion(const physics::Vec3& axis, double degrees);

// euler_degrees = [x, y, z]: turns about the world's x axis by x, then about the world's y axis
// by y, then about the world's z axis by z (extrinsic x-y-z, the same as intrinsic z-y'-x''):
// q = q_z q_y q_x.
physics::Quat euler_quaternion(const physics::Vec3& degrees);

// The body table's `orientation`, `rotation = { axis = [x, y, z], degrees = θ }` or
// `euler_degrees = [x, y, z]` (the identity when none is written): more than one of them, a
// rotation's zero axis or unknown key, is an error at that key.
physics::Quat read_orientation(TableReader& in);

}  // namespace tumble::scene::detail
