#include "scene/orientation_keys.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace tumble::scene::detail {
namespace {

using physics::Quat;
using physics::Vec3;

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// rotation = { axis = [x, y, z], degrees = θ }: both keys required, nothing else.
Quat read_rotation(TableReader& in) {
  const toml::table* table = in.table().get("rotation")->as_table();
  if (!table) in.fail("rotation", "expected a table { axis = [x, y, z], degrees = angle }");
  TableReader rotation(*table, in.qualified("rotation"), in.file());
  const Vec3 axis = rotation.required_vector("axis");
  const double degrees = rotation.required_number("degrees");
  rotation.reject_unknown_keys();
  if (!(axis.stableNorm() > 0.0)) {
    rotation.fail("axis", "a rotation's axis must not be [0, 0, 0]");
  }
  return axis_angle_quaternion(axis, degrees);
}

}  // namespace

Quat axis_angle_quaternion(const Vec3& axis, double degrees) {
  const double half = 0.5 * degrees * kRadiansPerDegree;  // rad
  const Vec3 unit = axis / axis.stableNorm();  // stableNorm: an axis of 1e200 is still an axis
  const Vec3 v = std::sin(half) * unit;
  return Quat(std::cos(half), v.x(), v.y(), v.z());
}

Quat euler_quaternion(const Vec3& degrees) {
  const Quat qx = axis_angle_quaternion(Vec3::UnitX(), degrees.x());
  const Quat qy = axis_angle_quaternion(Vec3::UnitY(), degrees.y());
  const Quat qz = axis_angle_quaternion(Vec3::UnitZ(), degrees.z());
  return (qz * qy * qx).normalized();
}

Quat read_orientation(TableReader& in) {
  constexpr std::array<const char*, 3> kKeys = {"orientation", "rotation", "euler_degrees"};
  const char* given = nullptr;
  for (const char* key : kKeys) {
    if (!in.has(key)) continue;
    if (given) {
      in.fail(key, std::string("give one of orientation, rotation and euler_degrees (") + given +
                       " is given too)");
    }
    given = key;
  }
  if (!given || std::string(given) == "orientation") return in.optional_quaternion("orientation");
  if (std::string(given) == "rotation") return read_rotation(in);
  return euler_quaternion(in.required_vector("euler_degrees"));
}

}  // namespace tumble::scene::detail
