// The files of the html replay that come with tumble, not from the render: web/replay.html (the
// markup), web/replay.js (the player) and web/dist/three.bundle.js (three.js r187 with its glTF
// loader and orbit controls as one script, which scripts/install-deps makes with npm from the
// versions web/package-lock.json pins). Found at render time as the shaders are.
#pragma once

#include <string>

#include "common/result.hpp"

namespace tumble::job {

struct ReplayAssets {
  std::string directory;  // where they were found
  std::string markup;     // replay.html
  std::string replay_js;  // replay.js
  std::string three_js;   // dist/three.bundle.js
};

// web/ beside an installed binary (share/tumble/web), else in the source tree this binary was
// built from; TUMBLE_WEB_DIR overrides both. "" if none holds replay.html.
std::string find_web_directory();

// The three files, read from `directory`, or from find_web_directory() when it is "" (the
// Python module gives the one installed beside it). Without three.js the error says what to run:
// scripts/install-deps, or npm ci and npm run bundle in the folder.
Result<ReplayAssets> load_replay_assets(const std::string& directory = "");

}  // namespace tumble::job
