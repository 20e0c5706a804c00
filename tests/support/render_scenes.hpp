// Small scenes for the end-to-end tests of render outputs (formats, poster, contact sheet): a
// spinning cube seen from a fixed camera, a few frames at a small size.
#pragma once

#include <string>

namespace tumble::testing {

// 96 × 64 pixels at 20 frames/s; `duration` s; `output` is appended (such as an [output]
// table) and `render` goes into [render] (such as "background = \"transparent\"\n").
inline std::string spinning_cube_scene(double duration, const std::string& output = "",
                                       const std::string& render = "") {
  return "name = \"spin\"\nduration = " + std::to_string(duration) +
         "\n[physics]\ndt = 0.01\n"
         "[[bodies]]\nname = \"cube\"\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n"
         "angular_velocity = [0.4, 2.0, 0.0]\n"
         "[render]\nwidth = 96\nheight = 64\nfps = 20\n" +
         render +
         "[camera]\nposition = [0.0, 1.5, 4.0]\nlook_at = [0.0, 0.0, 0.0]\n"
         "[ground]\nheight = -1.0\n" +
         output;
}

}  // namespace tumble::testing
