// Which folders a render may replace. A render replaces its scene's folder as a whole (see
// io::StagedDirectory), so it must only ever replace one of its own: empty, or holding a
// report.json as tumble writes them and nothing but what a render writes (report.json, *.mp4,
// frames/frame_*.png). Nor may it write inside another render's folder, or through a symbolic
// link below the output root out of it.
#pragma once

#include <filesystem>

#include "common/result.hpp"

namespace tumble::job {

// Succeeds when a render may replace the scene's folder `relative` below the output folder `root`
// (also when it does not exist yet); else why not, as a sentence for people.
Result<void> check_replaceable(const std::filesystem::path& root,
                               const std::filesystem::path& relative);

}  // namespace tumble::job
