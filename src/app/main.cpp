// The command line: parses arguments and hands them to the commands in src/app/.
#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdio>

#include "app/simulate_command.hpp"

namespace {

// A whole number >= 1, with a message a person can read (CLI11's ranges print DBL_MAX).
const CLI::Validator kAtLeastOne(
    [](std::string& value) {
      long long parsed = 0;
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), parsed);
      const bool whole = error == std::errc() && end == value.data() + value.size();
      return whole && parsed >= 1 ? std::string() : "expected a whole number >= 1, got " + value;
    },
    "N>=1");

}  // namespace

int main(int argc, char** argv) {
  using namespace tumble::app;
  CLI::App app{"tumble: rigid-body scenes to frames and video, headless"};
  app.require_subcommand(1);

  SimulateOptions simulate;
  CLI::App* simulate_command =
      app.add_subcommand("simulate", "Run a scene's physics and write the states as CSV");
  simulate_command->add_option("scene", simulate.scene_path, "Scene file (TOML)")->required();
  simulate_command->add_option("--out", simulate.out, "CSV file to write, or - for stdout")
      ->capture_default_str();
  simulate_command->add_option("--every", simulate.every, "Write a row every N steps")
      ->check(kAtLeastOne)
      ->capture_default_str();

  if (argc < 2) {
    std::fputs(app.help().c_str(), stderr);
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  if (simulate_command->parsed()) return run_simulate(simulate, stderr);
  return kExitBadInput;
}
