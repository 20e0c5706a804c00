// The [[overlays]] tables of a scene file (scene/overlays.hpp): each key checked, an error at
// its file:line:col with the key. Internal to src/scene/.
#pragma once

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// Reads the [[overlays]] of `root` into scene.overlays, in the order written. Needs
// scene.bodies read (overlays name bodies, and placeholders their quantities).
void read_overlays(TableReader& root, Scene& scene);

}  // namespace tumble::scene::detail
