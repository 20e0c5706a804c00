// Which folders a render may replace. A render replaces its scene's folder as a whole (see
// io::StagedDirectory), so it must only ever replace one of its own: empty, or holding a
// report.json as tumble writes them and nothing but what a render writes (report.json, *.mp4,
// frames/frame_*.png). Nor may it write inside another render's folder, or through a symbolic
// link below the output root out of it.
#pragma once

#include <filesystem>
#include <string>

namespace tumble::job {

// Why the scene's folder `relative` below the output folder `root` must not be replaced by a
// render, as a sentence for people; "" when it may (also when it does not exist yet).
std::string replace_problem(const std::filesystem::path& root,
                            const std::filesystem::path& relative);

}  // namespace tumble::job
