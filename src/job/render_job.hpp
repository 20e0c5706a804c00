// One render of a scene, decided once and checked in one place (make_render_job), then run
// (render_scene): shared by `tumble render` and `tumble bench pipeline`, which runs it several
// ways on the same scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "io/png_io.hpp"
#include "io/video_encoder.hpp"
#include "job/chunk_plan.hpp"
#include "job/replay_assets.hpp"
#include "pipeline/frame_pipeline.hpp"
#include "render/offscreen_context.hpp"
#include "scene/scene.hpp"

namespace tumble::job {

// What the command line asks of a render. Each override, when set, replaces the scene's value
// before the scene is checked.
struct RenderOptions {
  std::string scene_path;
  std::string output_root = "output";     // files go to <output_root>/<scene output directory>/
  std::optional<int> width, height, fps;  // [render] width, height (pixels) and fps
  std::optional<int> msaa;                // [render] msaa (bench pipeline's --msaa)
  std::optional<double> duration;         // s (bench pipeline's --frames)
  std::optional<std::string> preset;      // [output] preset (bench pipeline's x264 presets)
  // --quality: a named width, height and fps (app/quality_preset.hpp), under width/height/fps.
  std::optional<std::string> quality;
  std::vector<std::string> formats;                    // --format: [output] formats when not empty
  std::optional<std::int64_t> first_frame, end_frame;  // --frames A:B renders A .. B-1
  // --chunk I/N: line I of `tumble plan --chunks N`, into <scene output directory>.chunk-I-of-N
  std::optional<ChunkIndex> chunk;
  bool frames = true;  // false: no PNG frames, whatever [output] frames says
  bool video = true;   // false: no video, whatever [output] video says
  bool quiet = false;
  bool verbose = false;
  bool serial = false;  // one thread: the reference the pipelined path must match byte for byte
  io::PngSettings png;  // fast by default; see io/png_io.hpp
  std::optional<render::Backend> backend;  // --backend: replaces [render] backend
  std::optional<int> egl_device;           // --egl-device: replaces [render] egl_device
  // The shaders/ folder to draw with; "" finds it (find_shader_directory). The Python module
  // gives the one installed beside it.
  std::string shader_directory;
  // The html replay's web/ folder; "" finds it (find_web_directory). The Python module gives the
  // one installed beside it.
  std::string web_directory;
};

struct RenderJob {
  // With the overrides; keeps every rule of scene/video_rules. For a chunk, its
  // output.directory is the chunk's folder, <the scene's>.chunk-I-of-N.
  scene::Scene scene;
  std::int64_t frame_count = 0;       // of the whole scene, from scene::frame_count
  std::int64_t first = 0, end = 0;    // frames first .. end-1 are rendered
  std::optional<ChunkIndex> chunk;    // when rendered as --chunk I/N
  std::string scene_hash;             // app/scene_hash.hpp, when the scene came from a file
  std::filesystem::path output_root;  // spelt one way ("a/../b" is "b"), as StagedDirectory does
  std::filesystem::path directory;    // the final folder: output_root / [output] directory
  io::PngSettings png;
  bool serial = false;  // one thread, for comparison (same bytes as the pipeline)
  bool stills = true;   // poster.png and contact_sheet.png (bench pipeline measures without)
  std::string shader_directory;
  // The html replay's page, player and three.js, read when [output] formats lists "html".
  std::optional<ReplayAssets> replay_assets;

  // A part of the whole render (a chunk or --frames A:B): its videos are then segments to be
  // joined (io::VideoSettings::segment).
  bool partial() const { return first > 0 || end < frame_count; }

  // Where the frames and the videos go in `folder` (the folder being written, or `directory` in
  // the report): "" for an output that is off. video_path is the MP4's.
  std::string frames_path(const std::filesystem::path& folder) const;
  std::string video_path(const std::filesystem::path& folder) const;
  std::string video_path(const std::filesystem::path& folder, io::VideoFormat format) const;
  // <name>.glb (job/gltf_scene.hpp), or "" when [output] formats does not name "gltf".
  std::string gltf_path(const std::filesystem::path& folder) const;
  // <name>.html (job/html_replay.hpp), or "" when [output] formats does not name "html".
  std::string html_path(const std::filesystem::path& folder) const;
};

// The scene with the options' overrides, held to the video rules once more (an override can
// break them). Errors name the scene file and the key.
Result<scene::Scene> scene_as_rendered(scene::Scene scene, const RenderOptions& options);

// Succeeds when every video the scene writes can be written in parts that `tumble join` joins
// (not a GIF: its palette is its own frames'), and it writes no glTF or html replay (one
// animation of the frames it holds, which nothing joins); else the error, after `asked_by`
// ("--chunk", "plan"). One home for the rule of `render --chunk` and `tumble plan`.
Result<void> check_joinable_formats(const scene::Scene& scene, const std::string& asked_by);

// scene_as_rendered, with its frame range (all, --frames or --chunk), shaders and, for an html
// replay, its assets (an error when three.js is not installed, before any work).
Result<RenderJob> make_render_job(scene::Scene scene, const RenderOptions& options);

struct BodyDiagnostics {
  double energy_start = 0.0, energy_end = 0.0;                      // J
  double angular_momentum_start = 0.0, angular_momentum_end = 0.0;  // |L| (kg m²/s)
};

// What a render did, as far as it got: also when it failed (the frames done, the renderer and the
// warnings are still told).
struct RenderResult {
  pipeline::PipelineReport pipeline;  // the frames
  double setup_seconds = 0.0;         // framing, renderer and sinks' set-up (s, wall)
  double finish_seconds = 0.0;  // finishing the sinks: draining the encoder, closing the MP4 (s)
  std::string renderer;         // the OpenGL implementation and the back end that drew
  std::string backend;          // "osmesa" or "egl": the back end that drew
  std::string device;           // EGL's: "surfaceless" or "device I of N: <name>"; "" for OSMesa
  std::string opengl;           // the OpenGL implementation alone: what decides the pixels
  std::vector<const char*> stages;  // each sink's stage name, as in pipeline.sinks
  std::int64_t framing_steps = 0;   // physics steps of the framing pass (0 when not run)
  std::int64_t seek_steps = 0;      // physics steps up to the first frame (0 from frame 0)
  std::int64_t frame_steps = 0;     // physics steps of the frames, from the start of time
  // What a render pays before its first frame whatever its length (s, CPU of every thread):
  double framing_seconds = 0.0;   // the framing pass
  double renderer_seconds = 0.0;  // the OpenGL context and the shaders' compilation
  double seek_seconds = 0.0;      // the physics up to the first frame
  std::vector<BodyDiagnostics> bodies;
  std::vector<std::string> warnings;  // for the user (characters the font lacks)
};

// Renders the job's frames into `folder` (which must exist), describing the run in `result`.
// Asks `stop_requested` before each frame and calls `on_frame_done` as each one finishes. On
// success every output is complete.
Result<void> render_scene(const RenderJob& job, const std::filesystem::path& folder,
                          const std::function<bool()>& stop_requested,
                          const std::function<void(std::int64_t done)>& on_frame_done,
                          RenderResult& result);

// shaders/ beside an installed binary, else in the source tree this binary was built from;
// TUMBLE_SHADER_DIR overrides both. "" if none is found.
std::string find_shader_directory();

// How a render with [render] msaa = `msaa` smooths its edges, for reports: "edge filter" (the
// default), "none" (msaa = 1) or "MSAA 4".
std::string antialiasing_name(int msaa);

// Peak resident memory of this process so far (bytes).
std::int64_t peak_memory_bytes();

}  // namespace tumble::job
