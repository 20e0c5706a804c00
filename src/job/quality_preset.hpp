// --quality: named sizes and frame rates, the ones Manim users know (its constants.py QUALITIES).
#pragma once

#include <optional>
#include <string_view>

namespace tumble::job {

struct QualityPreset {
  const char* name;
  int width;   // pixels
  int height;  // pixels
  int fps;     // frames per second
};

inline constexpr QualityPreset kQualityPresets[] = {{"low", 854, 480, 15},
                                                    {"medium", 1280, 720, 30},
                                                    {"high", 1920, 1080, 60},
                                                    {"production", 2560, 1440, 60},
                                                    {"4k", 3840, 2160, 60}};

// The preset named `name`, or nothing.
std::optional<QualityPreset> quality_preset(std::string_view name);

// "low, medium, high, production, 4k", for messages and --help.
const char* quality_preset_names();

}  // namespace tumble::job
