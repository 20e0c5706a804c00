#include "cli/options.hpp"

#include <charconv>
#include <climits>
#include <vector>

namespace tumble::cli {

CLI::Validator whole_number_in(long long min, long long max, const std::string& range) {
  return CLI::Validator(
      [=](std::string& value) {
        long long parsed = 0;
        const auto [end, error] =
            std::from_chars(value.data(), value.data() + value.size(), parsed);
        const bool whole = error == std::errc() && end == value.data() + value.size();
        return whole && parsed >= min && parsed <= max
                   ? std::string()
                   : "expected a whole number " + range + ", got " + value;
      },
      range);
}

CLI::Validator not_empty() {
  return CLI::Validator(
      [](std::string& value) {
        return value.empty() ? std::string("expected a name, got \"\"") : "";
      },
      "NAME");
}

std::optional<std::pair<long long, long long>> parse_range(const std::string& text) {
  const char* const end = text.data() + text.size();
  long long first = 0, last = 0;
  const auto [colon, first_error] = std::from_chars(text.data(), end, first);
  if (first_error != std::errc() || colon == end || *colon != ':') return std::nullopt;
  const auto [after, last_error] = std::from_chars(colon + 1, end, last);
  if (last_error != std::errc() || after != end) return std::nullopt;
  return std::make_pair(first, last);
}

std::string frames_error(const std::string& text) {
  return "--frames: expected A:B (frames A to B-1), got " + text;
}

CLI::Option* add_setting_option(CLI::App* command, const common::RenderSetting& setting,
                                std::optional<int>& value, const std::string& help) {
  return command
      ->add_option(std::string(setting.flag), value,
                   help.empty() ? std::string(setting.help) : help)
      ->check(CLI::Range(setting.min, setting.max));
}

CLI::Option* add_setting_option(CLI::App* command, const common::RenderSetting& setting,
                                std::string& value) {
  return command->add_option(std::string(setting.flag), value, std::string(setting.help))
      ->check(CLI::IsMember(std::vector<std::string>(setting.names.begin(), setting.names.end())));
}

void ComparisonOptions::apply_antialiasing(diff::DiffCommandOptions& diff) const {
  if (antialiasing->count() > 0) diff.ignore_antialiasing = ignore_antialiasing;
}

void add_comparison_options(CLI::App* command, diff::DiffCommandOptions& diff,
                            ComparisonOptions& comparison, CLI::Option* needs) {
  const std::size_t before = command->get_options().size();
  command
      ->add_option("--metric", diff.metric,
                   "max (channel levels), rms (levels), perceptual (YIQ distance 0-1, as "
                   "pixelmatch), ssim (0-1) or psnr (dB)")
      ->check(CLI::IsMember({"max", "rms", "perceptual", "ssim", "psnr"}))
      ->capture_default_str();
  command->add_option(
      "--threshold", diff.threshold,
      "In the metric's unit: a pixel differs beyond it (max: 0-255, default 0; perceptual: 0-1, "
      "default 0.1); a frame differs beyond it (rms: 0-255, default 1; ssim below it: 0-1, "
      "default 0.99; psnr below it: dB, default 40)");
  comparison.antialiasing = command->add_flag(
      "--ignore-antialiasing,!--count-antialiasing", comparison.ignore_antialiasing,
      "Do not count pixels on anti-aliased edges (Vyšniauskas 2009, as pixelmatch); default on "
      "for perceptual only");
  CLI::Option* max_pixels =
      command
          ->add_option("--max-pixels", diff.max_pixels,
                       "A frame matches when at most this many pixels differ (default 0)")
          ->check(whole_number_in(0, LLONG_MAX, ">= 0"));
  command
      ->add_option("--max-percent", diff.max_percent,
                   "A frame matches when at most this share of its pixels differ (%)")
      ->check(CLI::Range(0.0, 100.0))
      ->excludes(max_pixels);
  command
      ->add_option("--report", diff.report,
                   "Write an HTML report (index.html and images) into this folder")
      ->check(not_empty());
  command->add_option("--junit", diff.junit, "Write JUnit XML, one test case per frame")
      ->check(not_empty());
  command->add_option("--json", diff.json, "Write every figure as JSON")->check(not_empty());
  const std::vector<CLI::Option*> added = command->get_options();
  for (std::size_t i = before; needs && i < added.size(); ++i) added[i]->needs(needs);
}

}  // namespace tumble::cli
