// Scenes written as text in the tests, and what the loader makes of them: one home for the
// small scenes many tests start from and for reading a parse's result.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "scene/scene_loader.hpp"

namespace tumble::testing {

// A unit cube of 1 kg that lasts `duration` s, with nothing else: tests append the tables they
// are about.
inline std::string cube_scene(double duration) {
  return "duration = " + std::to_string(duration) +
         "\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n";
}

// The command tests' spinning cube: 0.5 s of a unit cube turning at (0, 2, 1) rad/s, stepped
// every 0.01 s and drawn at `width` × `height` and 30 frames/s. `body` adds keys to the cube's
// table (an orientation, a [[bodies.forces]] table); `tables` follow [render].
inline std::string spin_scene(int width, int height, const std::string& body = "",
                              const std::string& tables = "") {
  return "name = \"spin\"\nduration = 0.5\n[physics]\ndt = 0.01\n[[bodies]]\nshape = \"cube\"\n"
         "size = 1.0\nmass = 1.0\nangular_velocity = [0.0, 2.0, 1.0]\n" +
         body + "[render]\nwidth = " + std::to_string(width) +
         "\nheight = " + std::to_string(height) + "\nfps = 30\n" + tables;
}

// A constant torque of (1, 0, 0) N·m on the body whose table it ends.
inline constexpr const char* kTorqueX =
    "[[bodies.forces]]\nkind = \"torque\"\ntorque = [1.0, 0.0, 0.0]\n";

// The scene parsed from `text` (named test.toml in messages), or a test failure carrying the
// loader's message and a default scene.
inline scene::Scene parse_valid(const std::string& text) {
  Result<scene::Scene> result = scene::parse_scene(text, "test.toml");
  if (!result) {
    ADD_FAILURE() << "unexpected error: " << result.error();
    return {};
  }
  return std::move(result).value();
}

// The loader's message for `text`, or "(no error)".
inline std::string error_of(const std::string& text) {
  const Result<scene::Scene> result = scene::parse_scene(text, "test.toml");
  return result ? "(no error)" : result.error();
}

}  // namespace tumble::testing
