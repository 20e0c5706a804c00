#include "job/render_golden.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "diff/diff_inputs.hpp"

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

// Whether `path` is `folder` or lies below it, symbolic links and ".." resolved.
bool inside(const fs::path& path, const fs::path& folder) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
  const fs::path container = fs::weakly_canonical(fs::absolute(folder), error);
  auto [end, unused] =
      std::mismatch(container.begin(), container.end(), resolved.begin(), resolved.end());
  return end == container.end();
}

}  // namespace

Result<void> check_golden(const diff::DiffCommandOptions& golden, const RenderJob& job) {
  if (const Result<diff::SequenceOptions> settings = diff::diff_settings(golden); !settings) {
    return Error{settings.error()};
  }
  const Result<diff::DiffInput> resolved = diff::resolve_diff_input(golden.first_path);
  if (!resolved) return Error{"--golden " + resolved.error()};
  const diff::DiffInput& input = *resolved;
  if (input.kind == diff::DiffInputKind::png) {
    return Error{"--golden " + golden.first_path +
                 ": expected a render's folder, a folder of frames or a video, not one PNG"};
  }
  if (inside(golden.first_path, job.directory)) {
    return Error{"--golden " + golden.first_path + " lies in " + job.directory.string() +
                 ", the folder this render replaces: keep goldens elsewhere or render with -o"};
  }
  return {};
}

Result<ExitCode> compare_with_golden(diff::DiffCommandOptions golden, const RenderJob& job,
                                     std::FILE* out) {
  golden.second_path =
      job.scene.output.frames ? job.directory.string() : job.video_path(job.directory);
  // A whole render is compared whole, so that a golden with more frames is a mismatch; a range
  // is compared over the range it rendered.
  if (job.first != 0 || job.end != job.frame_count) golden.frames = {{job.first, job.end}};
  return diff::run_diff(golden, out);
}

}  // namespace tumble::job
