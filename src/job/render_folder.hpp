// A render of a scene file's text into its folder, as `tumble render` and the Python module's
// Scene.render do it, without a word printed: the job decided and checked (prepare_render), then
// the frames and videos written into a staged folder beside the final one, the files of an
// earlier render of the same scene kept, report.json written and the folder swapped in
// (render_to_folder). A failed or stopped render leaves the earlier folder as it was.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "job/kept_files.hpp"
#include "job/render_job.hpp"

namespace tumble::job {

struct PreparedRender {
  RenderJob job;          // with the scene's hash set
  EarlierRender earlier;  // what the folder holds now: told before the render (another scene's)
  std::string scene_text;
  std::chrono::steady_clock::time_point start;  // when the render was asked for: report's total
};

// The scene in `scene_text` (read from options.scene_path, which names it in errors) as the
// options render it, its folder checked to be one a render may replace.
Result<PreparedRender> prepare_render(std::string scene_text, const RenderOptions& options,
                                      std::chrono::steady_clock::time_point start);

// What a render did, as far as it got.
struct RenderOutcome {
  RenderResult result;               // also when it failed or stopped
  std::vector<std::string> written;  // job::render_files of the new render
  std::vector<RenderedFile> kept;    // of the earlier render of this scene
  std::string leftover;              // io::StagedDirectory::leftover, a warning when not ""
  double total_seconds = 0.0;
  bool stopped = false;  // stop_requested() said so: nothing was written
};

// Renders `prepared` into its folder. Fails (the folder left as it was) with the reason and a
// second line "render failed after K of N frames; FOLDER was left as it was", or, when
// stop_requested() turned true, with outcome.stopped set and stopped_message's words.
Result<void> render_to_folder(const PreparedRender& prepared,
                              const std::function<bool()>& stop_requested,
                              const std::function<void(std::int64_t done)>& on_frame_done,
                              RenderOutcome& outcome);

// "<why> after K of N frames; <folder> was left as it was".
std::string stopped_message(const RenderJob& job, const RenderResult& result,
                            const std::string& why);

}  // namespace tumble::job
