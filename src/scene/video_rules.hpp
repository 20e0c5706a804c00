// The rules of the video a scene describes, in one place: the loader holds a scene file to them,
// and `tumble render` and `tumble bench pipeline` hold the scene to them again once the command
// line has changed it. Also the one home of the frame count.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tumble::scene {

// A rule the scene breaks: what is wrong, and where in a scene file to say so.
struct BrokenRule {
  std::vector<std::string> keys;  // dotted ("render.width"); the first one a file has is blamed
  std::string fallback;           // the top-level key blamed when a file has none of them
  std::string problem;            // what is wrong, as a clause
};

// The first rule no render of `scene` could keep (a frame within kMaxPixels, 1 to kMaxFrames
// frames, an even size for H.264 and VP9 video, alpha in every video of a transparent render, a
// poster time within the scene, something to write), or nothing.
std::optional<BrokenRule> broken_video_rule(const Scene& scene);

// The scene's frames: duration × fps, rounded to the nearest. Frame k shows t = k / fps (s).
// Only for a scene with no broken video rule (which bounds it by kMaxFrames).
std::int64_t frame_count(const Scene& scene);

// The frame poster.png shows: the one nearest [output] poster_time (the last for a time past the
// last frame's), else the middle one, frame_count / 2. Same precondition as frame_count.
std::int64_t poster_frame(const Scene& scene);

}  // namespace tumble::scene
