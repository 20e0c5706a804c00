#include "cli/check_command.hpp"

#include <CLI/CLI.hpp>
#include <memory>
#include <variant>

#include "common/printed.hpp"
#include "physics/integrators.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stability_report.hpp"

namespace tumble::cli {

CommandResult run_check(const CheckOptions& options, std::FILE* out) {
  const Result<scene::Scene> loaded = scene::load_scene_file(options.scene_path);
  if (!loaded) return Error{loaded.error()};
  const scene::Scene& scene = *loaded;
  const std::vector<std::string> warnings = scene::stability_warnings(scene);
  for (const std::string& line : warnings) std::fprintf(out, "tumble: warning: %s\n", line.c_str());
  const std::size_t bodies = scene.bodies.size();
  const std::int64_t steps = scene::step_count(scene);
  const std::size_t joints = scene.joints.size();
  const std::string held =
      joints == 0 ? "" : printed(" and %zu joint%s", joints, joints == 1 ? "" : "s");
  std::fprintf(out, "%s: valid: %zu bod%s%s, %lld step%s of %g s with %s; %zu warning%s\n",
               options.scene_path.c_str(), bodies, bodies == 1 ? "y" : "ies", held.c_str(),
               static_cast<long long>(steps), steps == 1 ? "" : "s", scene.physics.dt,
               std::string(physics::integrator_name(scene.physics.integrator)).c_str(),
               warnings.size(), warnings.size() == 1 ? "" : "s");
  return kExitOk;
}

void add_check_command(CLI::App& app, Commands& commands) {
  const auto options = std::make_shared<CheckOptions>();
  CLI::App* command = app.add_subcommand(
      "check", "Validate a scene and warn about its step: exit 0 if valid, 2 if not");
  command->add_option("scene", options->scene_path, "Scene file (TOML)")->required();
  commands.push_back({command, [options] { return run_check(*options, stdout); }});
}

}  // namespace tumble::cli
