#include "job/replay_assets.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

Result<std::string> read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path.string() + ": cannot read"};
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return Error{path.string() + ": cannot read"};
  return text.str();
}

}  // namespace

std::string find_web_directory() {
  std::error_code ignored;
  // Asked for by name: that folder or none, never a silent fall-back to another one.
  if (const char* env = std::getenv("TUMBLE_WEB_DIR")) {
    return fs::exists(fs::path(env) / "replay.html", ignored) ? std::string(env) : std::string();
  }
  std::vector<fs::path> candidates;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ignored);
  if (!executable.empty()) {
    candidates.push_back(executable.parent_path().parent_path() / "share/tumble/web");
  }
  candidates.emplace_back(TUMBLE_SOURCE_WEB_DIR);
  for (const fs::path& candidate : candidates) {
    if (fs::exists(candidate / "replay.html", ignored)) return candidate.string();
  }
  return {};
}

Result<ReplayAssets> load_replay_assets(const std::string& given) {
  const std::string directory = given.empty() ? find_web_directory() : given;
  if (directory.empty()) {
    const char* asked = std::getenv("TUMBLE_WEB_DIR");
    return Error{asked
                     ? std::string("no html replay files (replay.html) in TUMBLE_WEB_DIR=") + asked
                     : "cannot find the web/ folder of the html replay (set TUMBLE_WEB_DIR)"};
  }
  const fs::path folder(directory);
  const fs::path three = folder / "dist/three.bundle.js";
  std::error_code ignored;
  if (!fs::exists(three, ignored)) {
    return Error{"the html replay needs three.js, and " + three.string() +
                 " is missing: run scripts/install-deps (or `npm ci && npm run bundle` in " +
                 directory + ")"};
  }
  ReplayAssets assets{.directory = directory, .markup = {}, .replay_js = {}, .three_js = {}};
  for (const auto& [name, text] :
       {std::pair{"replay.html", &assets.markup}, std::pair{"replay.js", &assets.replay_js},
        std::pair{"dist/three.bundle.js", &assets.three_js}}) {
    Result<std::string> read = read_text(folder / name);
    if (!read) return Error{read.error()};
    *text = std::move(*read);
  }
  return assets;
}

}  // namespace tumble::job
