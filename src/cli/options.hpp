// Option checks and option groups more than one command registers.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <utility>

#include "common/render_setting_table.hpp"
#include "diff/diff_command.hpp"  // DiffCommandOptions

namespace tumble::cli {

// A whole number from `min` to `max`, with a message a person can read (CLI11's own ranges print
// DBL_MAX); `range` says which in words.
CLI::Validator whole_number_in(long long min, long long max, const std::string& range);

// A file or folder name given on the command line: "" would mean the current folder or nothing.
CLI::Validator not_empty();

// "A:B" as two whole numbers, each within long long; nothing else.
std::optional<std::pair<long long, long long>> parse_range(const std::string& text);

// The error of a --frames A:B that is not one.
std::string frames_error(const std::string& text);

// The option of a row of the settings table (common/render_setting_table.hpp): its flag, its
// check and its help (or `help`, where the option is another command's).
CLI::Option* add_setting_option(CLI::App* command, const common::RenderSetting& setting,
                                std::optional<int>& value, const std::string& help = "");
CLI::Option* add_setting_option(CLI::App* command, const common::RenderSetting& setting,
                                std::string& value);

// How frames are compared and what is written of the comparison: `tumble diff` and
// `tumble render --golden` take the same options. --ignore-antialiasing's default depends on the
// metric: `apply_antialiasing` sets it in `diff` when it was given. With `needs`, each option is
// refused without it.
struct ComparisonOptions {
  bool ignore_antialiasing = false;
  CLI::Option* antialiasing = nullptr;
  void apply_antialiasing(diff::DiffCommandOptions& diff) const;
};
void add_comparison_options(CLI::App* command, diff::DiffCommandOptions& diff,
                            ComparisonOptions& comparison, CLI::Option* needs = nullptr);

}  // namespace tumble::cli
