#include "cli/check_command.hpp"

#include <variant>

#include "physics/integrators.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stability_report.hpp"

namespace tumble::cli {

int run_check(const CheckOptions& options, std::FILE* out, std::FILE* err) {
  const Result<scene::Scene> loaded = scene::load_scene_file(options.scene_path);
  if (!loaded) {
    std::fprintf(err, "tumble: %s\n", loaded.error().c_str());
    return kExitBadInput;
  }
  const scene::Scene& scene = *loaded;
  const std::vector<std::string> warnings = scene::stability_warnings(scene);
  for (const std::string& line : warnings) std::fprintf(out, "tumble: warning: %s\n", line.c_str());
  const std::size_t bodies = scene.bodies.size();
  const std::int64_t steps = scene::step_count(scene);
  std::fprintf(out, "%s: valid: %zu bod%s, %lld step%s of %g s with %s; %zu warning%s\n",
               options.scene_path.c_str(), bodies, bodies == 1 ? "y" : "ies",
               static_cast<long long>(steps), steps == 1 ? "" : "s", scene.physics.dt,
               std::string(physics::integrator_name(scene.physics.integrator)).c_str(),
               warnings.size(), warnings.size() == 1 ? "" : "s");
  return kExitOk;
}

}  // namespace tumble::cli
