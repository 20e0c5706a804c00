#include "cli/diff_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/options.hpp"
#include "diff/diff_command.hpp"

namespace tumble::cli {
namespace {

struct DiffCommandLine {
  diff::DiffCommandOptions diff;
  std::string frames;  // --frames A:B
  ComparisonOptions comparison;
};

CommandResult run_command_line(DiffCommandLine& line) {
  if (!line.frames.empty()) {
    line.diff.frames = parse_range(line.frames);
    if (!line.diff.frames) return Error{frames_error(line.frames)};
  }
  line.comparison.apply_antialiasing(line.diff);
  return diff::run_diff(line.diff, stdout);
}

}  // namespace

void add_diff_command(CLI::App& app, Commands& commands) {
  const auto line = std::make_shared<DiffCommandLine>();
  CLI::App* command = app.add_subcommand(
      "diff",
      "Compare two PNGs, folders of frames, renders or videos: exit 0 if they match within the "
      "tolerance, 1 if not, 2 on error");
  command->add_option("first", line->diff.first_path, "A, the expected: PNG, folder or video")
      ->required();
  command->add_option("second", line->diff.second_path, "B, the actual: PNG, folder or video")
      ->required();
  add_comparison_options(command, line->diff, line->comparison);
  command->add_option("--frames", line->frames, "Compare frames A to B-1 only (A:B)")
      ->check(not_empty());
  command->add_option("--out", line->diff.out, "Two PNGs: write an image of the differences here")
      ->check(not_empty());
  commands.push_back({command, [line] { return run_command_line(*line); }});
}

}  // namespace tumble::cli
