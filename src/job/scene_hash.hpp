// The name of a scene as rendered, which `tumble join` compares across chunks: two renders with
// the same hash drew the same pictures (on the same OpenGL, which report.json records apart).
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace tumble::job {

// SHA-256 (hex) of the scene file's bytes followed by a line of the values, as rendered, that
// the command line can override and that change the pictures: "\n# as rendered: width=W
// height=H fps=F msaa=M duration=D\n". The values go in whether overridden or not: a file
// that says width = 64 and one given --width 64 still differ in their bytes, so nothing is
// lost, and one rule covers every override. The output switches and the encoder's settings
// do not change the pictures; join checks them as settings.
std::string scene_hash(std::string_view file_bytes, const scene::Scene& rendered);

}  // namespace tumble::job
