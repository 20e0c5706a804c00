// The largest scene tumble will attempt. Beyond these a value is almost surely a typo, and an
// attempt would run for days or fill the disk, so the loader refuses it with a message instead.
// docs/errors.md lists them; change both together. scene/video_rules.hpp holds
// a scene to the image and frame limits.
#pragma once

#include <cstdint>

#include "common/render_setting_table.hpp"

namespace tumble::scene {

// [render] width and height, and --width and --height: their rows of the settings table.
inline constexpr std::int64_t kMinImageSide = common::render_setting("width").min;
inline constexpr std::int64_t kMaxImageSide = common::render_setting("width").max;
static_assert(common::render_setting("height").min == kMinImageSide &&
              common::render_setting("height").max == kMaxImageSide);
// width × height: 8192 × 4320, the largest frame of H.264's highest level (6.2: 139 264
// macroblocks of 16 × 16), about 142 MB per RGBA frame.
inline constexpr std::int64_t kMaxPixels = 8192 * 4320;
// duration × fps: 1 000 000 frames is 4.6 hours at 60 fps.
inline constexpr std::int64_t kMaxFrames = 1'000'000;
// duration / dt: a typo must not start a run of days.
inline constexpr std::int64_t kMaxSteps = 100'000'000;
inline constexpr std::int64_t kMaxBodies = 1000;
// bodies × steps: each limit alone still allows 10^11 body steps (days of work); 10^9 is about
// five minutes of RK4 on boxes here (285 ns a step, physics_bench).
inline constexpr std::int64_t kMaxBodySteps = 1'000'000'000;
inline constexpr std::int64_t kMaxForcesPerBody = 100;
// Two joints a body: a chain of every body, a ladder, a bridge.
inline constexpr std::int64_t kMaxJoints = 2 * kMaxBodies;
// Every body is tested against every plane at each step: a room and a few ramps need a dozen.
inline constexpr std::int64_t kMaxPlanes = 64;
// Points written for one hull (a mesh may have any number of vertices: its hull is reduced).
inline constexpr std::size_t kMostHullPoints = 10'000;
// Scene files are read whole.
inline constexpr std::int64_t kMaxSceneFileBytes = 16 * 1024 * 1024;

}  // namespace tumble::scene
