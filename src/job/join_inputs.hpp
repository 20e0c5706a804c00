// What `tumble join` reads and checks before it writes anything: each chunk folder's report.json,
// that the chunks are renders of one scene with one set of settings, and that together they hold
// every frame of it once.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "io/json_reader.hpp"
#include "job/chunk_plan.hpp"

namespace tumble::job {

// A render folder as its report.json describes it.
struct ChunkReport {
  std::filesystem::path folder;  // as given on the command line
  std::string scene;             // the scene's name
  std::string scene_file;
  std::string scene_hash;                // app/scene_hash.hpp
  std::int64_t scene_frames = 0;         // frames of the whole render
  FrameRange frames;                     // the frames this folder holds
  io::JsonValue settings;                // what must agree (job/render_folder.cpp's settings_json)
  bool has_frames = false;               // frames/ holds its PNG frames
  std::vector<std::string> video_names;  // its videos' file names in the folder ("spin.mp4")
  std::string renderer;                  // the OpenGL and back end that drew it
  std::vector<std::string> kept;         // files kept of an earlier render (job/kept_files.hpp)
};

// Reads `folder`/report.json; errors name the folder and what is missing or malformed.
Result<ChunkReport> read_chunk_report(const std::filesystem::path& folder);

// Succeeds when every chunk is of the first one's scene and settings; else why `chunks` cannot
// be joined, as a sentence naming the two folders and the setting that differs.
Result<void> check_one_render(const std::vector<ChunkReport>& chunks);

// Succeeds when `ranges` (sorted by their first frame; `folders` names each) cover every frame of
// 0 .. frame_count-1 once; else the frames they leave out or hold more than once, as "frames
// 40:60 are missing" and "frames 10:12 are in both A and B", joined by "; ".
Result<void> check_coverage(const std::vector<FrameRange>& ranges,
                            const std::vector<std::string>& folders, std::int64_t frame_count);

}  // namespace tumble::job
