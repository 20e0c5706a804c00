// The stability advisor (sim/stability.hpp) applied to a whole scene, as lines for people. Used by
// `tumble check`, and printed before a run by `tumble simulate` and `tumble render`.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tumble::app {

// One line per warning, each naming its body: `body "cube": linear damping ...`.
std::vector<std::string> stability_warnings(const scene::Scene& scene);

// Prints each warning as "tumble: warning: <line>".
void print_stability_warnings(const scene::Scene& scene, std::FILE* out);

}  // namespace tumble::app
