// Reading and validating scene files (TOML). Every error names the file, line, column and key.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace tumble::scene {

// Loads a scene from a file; the file's stem is the default scene name. An error's message is
// complete and ready to print, in the form "path:line:column: key: what is wrong".
Result<Scene> load_scene_file(const std::string& path);

// A scene file's bytes, as load_scene_file reads them (up to kMaxSceneFileBytes), for a caller
// that keeps them (a render hashes the scene it drew); errors name the path.
Result<std::string> read_scene_text(const std::string& path);

// Loads a scene from text; `path` names it in messages and gives the default name.
Result<Scene> parse_scene(std::string_view text, const std::string& path);

}  // namespace tumble::scene
