// Tests that load a page in headless Chromium and look at what it did: tests/support/
// chromium_page.py drives it through the DevTools protocol with no network (a proxy where nothing
// listens), runs the steps given, and answers with every step's value, every URL the page asked
// for and every error it logged.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "io/json_reader.hpp"
#include "support/command_test.hpp"

namespace tumble::testing {

// Why Chromium's tests cannot run here, or "" when they can.
inline std::string chromium_missing() {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) {
    return "chromium is not installed (apt-get install chromium; CI installs it)";
  }
  if (std::system("command -v python3 >/dev/null 2>&1") != 0) {
    return "python3 is not installed (scripts/install-deps installs it): it drives Chromium";
  }
  return {};
}

struct PageRun {
  int exit_code = -1;
  std::string output;    // the JSON answer, or the reason on failure (stderr)
  io::JsonValue answer;  // parsed: results, requests, errors
};

// Opens `url` and runs `steps` (a JSON array, chromium_page.py's docstring lists them).
inline PageRun run_page(const std::string& url, const std::string& steps) {
  const std::string command = "python3 " TUMBLE_SOURCE_DIR "/tests/support/chromium_page.py " +
                              shell_quoted(url) + " " + shell_quoted(steps) + " 2>&1";
  PageRun run;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), &::pclose);
  char buffer[4096];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe.get())) run.output += buffer;
  const int status = ::pclose(pipe.release());
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (run.exit_code == 0) {
    Result<io::JsonValue> parsed = io::parse_json(run.output);
    if (parsed) {
      run.answer = std::move(*parsed);
    } else {
      run.exit_code = -1;
      run.output = "unreadable answer (" + parsed.error() + "): " + run.output;
    }
  }
  return run;
}

// Step n's value in a run's answer, or null.
inline const io::JsonValue* step_result(const PageRun& run, std::size_t n) {
  const io::JsonValue* results = run.answer.find("results");
  return results && n < results->items.size() ? &results->items[n] : nullptr;
}

}  // namespace tumble::testing
