// Body arrays: `count` and `spacing` (and `colors`) on a [[bodies]] table make that body many
// times over, in a line or a grid, as if each were written out. Internal to src/scene/.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// How one [[bodies]] table is repeated: counts[0] × counts[1] × counts[2] bodies, body (i, j, k)
// at the table's position + i steps[0] + j steps[1] + k steps[2].
struct BodyArray {
  std::array<std::int64_t, 3> counts = {1, 1, 1};
  std::array<physics::Vec3, 3> steps = {physics::Vec3::Zero(), physics::Vec3::Zero(),
                                        physics::Vec3::Zero()};  // world frame (m)
  std::vector<common::Color> colors;  // sRGB, given body by body in turn; empty: not written
  bool written = false;               // `count` was written: the bodies are named NAME_0, ...

  std::int64_t size() const { return counts[0] * counts[1] * counts[2]; }
};

// The colour of the body at `index` in the scene when its table gives none (sRGB).
common::Color default_body_color(std::size_t index);

// `count` (a whole number: a line along `spacing`; or [nx, ny, nz]: a grid, `spacing` then the
// step along the world's x, y and z), `spacing` ([x, y, z] m) and `colors` (colours, one after
// the other) of the body table `in`. Without `count`, one body and neither other key. A count
// below 1 or past kMaxBodies, a spacing that puts two bodies in one place or the last body past
// the position limit, `colors` empty or beside `color`, is an error at that key.
BodyArray read_body_array(TableReader& in, const physics::Vec3& position);

// The bodies `array` makes of `body` (read from `in`, the `index`-th body of the scene): itself
// when not an array; else copies named NAME_0, NAME_1, ... (x fastest, then y, then z), placed
// along the steps, coloured by `colors` in turn, or, when the table gives no colour, by the
// default of their own index in the scene, as bodies written one by one would be.
std::vector<BodySpec> expand_body_array(TableReader& in, const BodySpec& body,
                                        const BodyArray& array, std::size_t index);

}  // namespace tumble::scene::detail
