// libFuzzer target: any bytes as a scene file. The loader must return a scene or an error naming
// the file; it must never crash, hang, throw or read out of bounds. A scene that loads is then
// built, checked by the stability advisor and stepped a little, as every command does with it:
// values the loader accepts must not break the physics (non-finite results are allowed; the
// simulation reports them as a blow-up).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "sim/stability.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tumble;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const Result<scene::Scene> loaded = scene::parse_scene(text, "fuzz.toml");
  if (!loaded) {
    if (loaded.error().rfind("fuzz.toml:", 0) != 0) std::abort();  // every error names the file
    return 0;
  }
  const scene::Scene& scene = *loaded;
  for (const scene::BodySpec& body : scene.bodies) {
    const physics::BodyModel model{.constants = scene::body_constants(body), .forces = body.forces};
    sim::check_step(model, scene::initial_state(body), scene.physics.integrator, scene.physics.dt,
                    scene.duration);
  }
  sim::Simulation simulation = scene::build_simulation(scene);
  // Four steps: enough to reach every stage of a step (contact, islands, sub-steps, sleep),
  // within libFuzzer's 10 s per input in this sanitized, instrumented build. Sixteen were not:
  // tests/fuzz/regressions/scene/offset_tower.toml, a tower with one box set off, pivots its
  // contact block about 1400 times a step and took 14 s (13 ms a step in a release build: a cost of
  // the block solve to bring down, not a hang).
  const std::int64_t steps = std::min<std::int64_t>(scene::step_count(scene), 4);
  for (std::int64_t n = 0; n < steps && !simulation.blow_up(); ++n) simulation.step();
  // Halfway between the last two steps, never before them (states_at's precondition).
  if (steps > 0) simulation.states_at(simulation.time() - 0.5 * simulation.dt());
  return 0;
}
