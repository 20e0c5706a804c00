// The keys that move the camera: [[camera.keys]] and [camera] orbit_period. Internal to
// src/scene/.
#pragma once

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// Reads [[camera.keys]] and orbit_period from the [camera] table `in` into scene.camera; needs
// scene.duration and scene.camera.fov_degrees already read. A key time before 0, after the
// duration, or not after the key before it is an error at that key's time.
void read_camera_moves(TableReader& in, Scene& scene);

}  // namespace tumble::scene::detail
