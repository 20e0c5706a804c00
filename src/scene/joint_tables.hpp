// The [[joints]] tables of a scene file. Internal to src/scene/.
#pragma once

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// The [[joints]] tables of `root` into scene.joints, each checked against the bodies (read
// before): a known body_a, a body_b that is another body or the world, the keys its kind takes,
// limits in order, a motor with its maximum, not static at both ends; then refuses a weld that
// closes a loop of welds (over-constrained). Errors name the joint, file, line and key.
void read_joints(TableReader& root, Scene& scene);

// Whether a joint between bodies a and b (indices) keeps them from colliding with each other
// (its collide_connected is false).
bool kept_from_colliding(const Scene& scene, std::size_t a, std::size_t b);

}  // namespace tumble::scene::detail
