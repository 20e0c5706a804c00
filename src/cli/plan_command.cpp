#include "cli/plan_command.hpp"

#include <CLI/CLI.hpp>
#include <climits>
#include <memory>
#include <string>
#include <variant>

#include "cli/options.hpp"
#include "common/exit_codes.hpp"
#include "io/json_text.hpp"
#include "job/chunk_plan.hpp"
#include "scene/scene_loader.hpp"
#include "scene/video_rules.hpp"

namespace tumble::cli {
namespace {

std::string plan_json(const scene::Scene& scene, std::int64_t frame_count,
                      const std::vector<job::FrameRange>& ranges) {
  std::string text = "{\"scene\": " + io::json_string(scene.name) +
                     ", \"frames\": " + std::to_string(frame_count) + ", \"chunks\": [";
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    text += (i ? ", " : "") + std::string("{\"index\": ") + std::to_string(i + 1) +
            ", \"first\": " + std::to_string(ranges[i].first) +
            ", \"end\": " + std::to_string(ranges[i].end) + "}";
  }
  return text + "]}\n";
}

}  // namespace

CommandResult run_plan(const PlanOptions& options, std::FILE* out) {
  if (!options.chunks && !options.chunk_frames) {
    return Error{"plan: give --chunks N or --chunk-frames K"};
  }
  const Result<scene::Scene> loaded = scene::load_scene_file(options.render.scene_path);
  if (!loaded) return Error{loaded.error()};
  // The overrides render takes, so that plan and render count the same frames.
  const Result<scene::Scene> scene = job::scene_as_rendered(*loaded, options.render);
  if (!scene) return Error{scene.error()};
  // Every chunk of the plan would be refused on the farm: refused here, before it is sent.
  if (const Result<void> joinable =
          job::check_joinable_formats(*scene, "plan: " + options.render.scene_path);
      !joinable) {
    return Error{joinable.error()};
  }
  const std::int64_t frame_count = scene::frame_count(*scene);
  Result<std::int64_t> chunks = options.chunks
                                    ? Result<std::int64_t>(*options.chunks)
                                    : job::chunks_of_at_most(frame_count, *options.chunk_frames);
  const Result<std::vector<job::FrameRange>> ranges =
      chunks ? job::plan_chunks(frame_count, *chunks)
             : Result<std::vector<job::FrameRange>>(Error{chunks.error()});
  if (!ranges) return Error{options.render.scene_path + ": " + ranges.error()};
  if (options.json) {
    std::fputs(plan_json(*scene, frame_count, *ranges).c_str(), out);
  } else {
    for (const job::FrameRange& range : *ranges)
      std::fprintf(out, "%s\n", job::range_text(range).c_str());
  }
  return kExitOk;
}

void add_plan_command(CLI::App& app, Commands& commands) {
  const auto options = std::make_shared<PlanOptions>();
  CLI::App* command = app.add_subcommand(
      "plan", "Print the frame ranges of a render cut into chunks, one A:B per line");
  command->add_option("scene", options->render.scene_path, "Scene file (TOML)")->required();
  CLI::Option* chunks =
      command->add_option("--chunks", options->chunks, "Cut into N chunks, as even as possible")
          ->check(whole_number_in(1, LLONG_MAX, ">= 1"));
  command
      ->add_option("--chunk-frames", options->chunk_frames,
                   "Cut into as few chunks of at most K frames as cover the scene, as even as "
                   "possible")
      ->check(whole_number_in(1, LLONG_MAX, ">= 1"))
      ->excludes(chunks);
  add_setting_option(command, common::render_setting("fps"), options->render.fps,
                     "Frames per second (as render --fps)");
  command->add_option("--quality", options->render.quality,
                      "Size and frame rate preset (as render --quality): the frame count "
                      "follows its rate");
  command->add_flag("--json", options->json, "Print the plan as JSON");
  commands.push_back({command, [options] { return run_plan(*options, stdout); }});
}

}  // namespace tumble::cli
