#include "job/join_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

// A whole number that report.json holds at `key` of `object`.
Result<std::int64_t> whole_number(const io::JsonValue& object, std::string_view key) {
  const io::JsonValue* value = object.find(key);
  if (!value || value->kind != io::JsonValue::Kind::number ||
      value->number != std::floor(value->number)) {
    return Error{"no whole number \"" + std::string(key) + "\""};
  }
  return static_cast<std::int64_t>(value->number);
}

Result<std::string> text(const io::JsonValue& object, std::string_view key) {
  const io::JsonValue* value = object.find(key);
  if (!value || value->kind != io::JsonValue::Kind::string) {
    return Error{"no text \"" + std::string(key) + "\""};
  }
  return value->string;
}

// The fields of a parsed report; errors say which is missing.
Result<ChunkReport> chunk_fields(const io::JsonValue& report, const fs::path& folder) {
  ChunkReport chunk;
  chunk.folder = folder;
  const io::JsonValue* frames = report.find("frames");
  const io::JsonValue* settings = report.find("settings");
  const io::JsonValue* videos = report.find("videos");
  const io::JsonValue* frames_directory = report.find("frames_directory");
  Result<std::string> scene = text(report, "scene"), file = text(report, "scene_file"),
                      hash = text(report, "scene_hash"), renderer = text(report, "renderer");
  Result<std::int64_t> total = whole_number(report, "scene_frames");
  Result<std::int64_t> first = frames ? whole_number(*frames, "first") : Error{"no \"frames\""};
  Result<std::int64_t> end = frames ? whole_number(*frames, "end") : Error{"no \"frames\""};
  for (const std::string* error :
       {scene ? nullptr : &scene.error(), file ? nullptr : &file.error(),
        hash ? nullptr : &hash.error(), renderer ? nullptr : &renderer.error(),
        total ? nullptr : &total.error(), first ? nullptr : &first.error(),
        end ? nullptr : &end.error()}) {
    if (error) return Error{*error};
  }
  if (!settings || settings->kind != io::JsonValue::Kind::object) return Error{"no \"settings\""};
  if (!frames_directory || (frames_directory->kind != io::JsonValue::Kind::string &&
                            frames_directory->kind != io::JsonValue::Kind::null)) {
    return Error{"no \"frames_directory\""};
  }
  if (!videos || videos->kind != io::JsonValue::Kind::object) return Error{"no \"videos\""};
  for (const auto& [format, path] : videos->members) {
    if (path.kind != io::JsonValue::Kind::string)
      return Error{"no path for its " + format + " video"};
    chunk.video_names.push_back(fs::path(path.string).filename().string());
  }
  chunk.has_frames = frames_directory->kind == io::JsonValue::Kind::string;
  if (const io::JsonValue* kept = report.find("kept")) {
    for (const io::JsonValue& item : kept->items) {
      const io::JsonValue* name = item.find("file");
      if (name && name->kind == io::JsonValue::Kind::string) chunk.kept.push_back(name->string);
    }
  }
  chunk.scene = *scene;
  chunk.scene_file = *file;
  chunk.scene_hash = *hash;
  chunk.renderer = *renderer;
  chunk.scene_frames = *total;
  chunk.frames = {*first, *end};
  chunk.settings = *settings;
  if (chunk.frames.first < 0 || chunk.frames.end > chunk.scene_frames ||
      chunk.frames.first >= chunk.frames.end) {
    return Error{"frames " + range_text(chunk.frames) +
                 " are not within the scene's 0:" + std::to_string(chunk.scene_frames)};
  }
  return chunk;
}

std::string shown(const std::string& hash) {
  return hash.substr(0, 12) + "…";
}

}  // namespace

Result<ChunkReport> read_chunk_report(const fs::path& folder) {
  const fs::path path = folder / "report.json";
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    return Error{folder.string() + ": no report.json: not a render's folder (or not finished)"};
  }
  std::ostringstream bytes;
  bytes << file.rdbuf();
  const Result<io::JsonValue> report = io::parse_json(bytes.str());
  if (!report) return Error{path.string() + ": not JSON: " + report.error()};
  Result<ChunkReport> chunk = chunk_fields(*report, folder);
  if (!chunk) {
    return Error{path.string() + ": " + chunk.error() +
                 " (a report of an older tumble? render the chunk again)"};
  }
  return chunk;
}

Result<void> check_one_render(const std::vector<ChunkReport>& chunks) {
  const ChunkReport& first = chunks.front();
  for (const ChunkReport& chunk : chunks) {
    const std::string pair =
        "chunks " + first.folder.string() + " and " + chunk.folder.string() + " differ in ";
    if (chunk.scene != first.scene) {
      return Error{pair + "scene name: " + first.scene + " and " + chunk.scene};
    }
    for (const auto& [key, value] : first.settings.members) {
      const io::JsonValue* other = chunk.settings.find(key);
      if (!other || other->text != value.text) {
        return Error{pair + key + ": " + value.text + " and " + (other ? other->text : "none")};
      }
    }
    if (chunk.settings.members.size() != first.settings.members.size()) {
      return Error{pair +
                   "which settings their report.json records (rendered by different tumbles?)"};
    }
    if (chunk.scene_frames != first.scene_frames) {
      return Error{pair + "the scene's frame count: " + std::to_string(first.scene_frames) +
                   " and " + std::to_string(chunk.scene_frames)};
    }
    if (chunk.scene_hash != first.scene_hash) {
      return Error{pair + "the scene they rendered (scene_hash " + shown(first.scene_hash) +
                   " and " + shown(chunk.scene_hash) + "): the scene file (" + first.scene_file +
                   ", " + chunk.scene_file + ") or an override changed between them"};
    }
  }
  return {};
}

Result<void> check_coverage(const std::vector<FrameRange>& ranges,
                            const std::vector<std::string>& folders, std::int64_t frame_count) {
  std::vector<std::string> problems;
  std::int64_t covered = 0;  // frames 0 .. covered-1 are in some chunk
  std::size_t last = 0;      // the chunk that reaches furthest so far
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const FrameRange& range = ranges[i];
    if (range.first > covered) {
      problems.push_back("frames " + range_text({covered, range.first}) + " are missing");
    } else if (range.first < covered) {
      problems.push_back("frames " + range_text({range.first, std::min(range.end, covered)}) +
                         " are in both " + folders[last] + " and " + folders[i]);
    }
    if (range.end > covered) {
      covered = range.end;
      last = i;
    }
  }
  if (covered < frame_count) {
    problems.push_back("frames " + range_text({covered, frame_count}) + " are missing");
  }
  if (problems.empty()) return {};
  std::string text;
  for (const std::string& problem : problems) text += (text.empty() ? "" : "; ") + problem;
  return Error{text};
}

}  // namespace tumble::job
