// The rendering tables of a scene file: [render], [camera], [light], [ground], [output].
#pragma once

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// Reads whichever of the tables are present in `root` into `scene`; needs scene.bodies,
// scene.planes and scene.name already read (for `follow`, [ground] and the default output
// directory).
void read_render_tables(TableReader& root, Scene& scene);

}  // namespace tumble::scene::detail
