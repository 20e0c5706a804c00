// The stability advisor (sim/stability.hpp) applied to a whole scene, as lines for people. Used by
// `tumble check`, printed before a run by `tumble simulate` and `tumble render`, and given as the
// likely cause when a run blows up.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "sim/simulation.hpp"

namespace tumble::scene {

// One line per warning, each naming its body: `body "cube": linear damping ...`.
std::vector<std::string> stability_warnings(const scene::Scene& scene);

// Prints each warning as "tumble: warning: <line>".
void print_stability_warnings(const scene::Scene& scene, std::FILE* out);

// What blew up, when, and the likely cause: the advisor's warnings for that body, with the
// stable step where one is known, or else what to try.
std::string blow_up_message(const scene::Scene& scene, const sim::BlowUp& blow_up);

}  // namespace tumble::scene
