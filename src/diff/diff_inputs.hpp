// What each side of `tumble diff` names: a PNG, a folder of PNG frames (a render's output folder
// counts: its frames/ are used), or a video file that libavformat reads.
#pragma once

#include <string>
#include <vector>

#include "common/result.hpp"

namespace tumble::diff {

enum class DiffInputKind { png, folder, video };

struct DiffInput {
  DiffInputKind kind = DiffInputKind::png;
  std::string path;                 // as given
  std::string folder;               // folder: where its PNGs are (path, or path/frames)
  std::vector<std::string> frames;  // folder: the PNG file names in it, sorted by name
};

// A path names a PNG when its name ends in ".png" (any case) or the file starts with the PNG
// signature; either side being one makes `tumble diff` compare two images.
bool names_png(const std::string& path);

// Finds what `path` holds. An error names the path: a missing path, a folder with no PNG frames.
Result<DiffInput> resolve_diff_input(const std::string& path);

}  // namespace tumble::diff
