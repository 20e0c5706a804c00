#include "cli/plan_command.hpp"

#include <string>
#include <variant>

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

int run_plan(const PlanOptions& options, std::FILE* out, std::FILE* err) {
  if (!options.chunks && !options.chunk_frames) {
    std::fputs("tumble: plan: give --chunks N or --chunk-frames K\n", err);
    return kExitBadInput;
  }
  const Result<scene::Scene> loaded = scene::load_scene_file(options.render.scene_path);
  if (!loaded) {
    std::fprintf(err, "tumble: %s\n", loaded.error().c_str());
    return kExitBadInput;
  }
  // The overrides render takes, so that plan and render count the same frames.
  const Result<scene::Scene> scene = job::scene_as_rendered(*loaded, options.render);
  if (!scene) {
    std::fprintf(err, "tumble: %s\n", scene.error().c_str());
    return kExitBadInput;
  }
  const std::int64_t frame_count = scene::frame_count(*scene);
  Result<std::int64_t> chunks = options.chunks
                                    ? Result<std::int64_t>(*options.chunks)
                                    : job::chunks_of_at_most(frame_count, *options.chunk_frames);
  const Result<std::vector<job::FrameRange>> ranges =
      chunks ? job::plan_chunks(frame_count, *chunks)
             : Result<std::vector<job::FrameRange>>(Error{chunks.error()});
  if (!ranges) {
    std::fprintf(err, "tumble: %s: %s\n", options.render.scene_path.c_str(),
                 ranges.error().c_str());
    return kExitBadInput;
  }
  if (options.json) {
    std::fputs(plan_json(*scene, frame_count, *ranges).c_str(), out);
  } else {
    for (const job::FrameRange& range : *ranges)
      std::fprintf(out, "%s\n", job::range_text(range).c_str());
  }
  return kExitOk;
}

}  // namespace tumble::cli
