#include "cli/join_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

#include "cli/options.hpp"
#include "common/exit_codes.hpp"
#include "io/atomic_file.hpp"
#include "io/json_text.hpp"
#include "io/staged_directory.hpp"
#include "io/video_join.hpp"
#include "job/join_inputs.hpp"
#include "job/joined_stills.hpp"
#include "job/output_folder.hpp"
#include "pipeline/frame_sinks.hpp"
#include "sys/interrupt.hpp"

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;

// The chunks' reports, sorted by their frames, checked to be one render's and to hold each of
// its frames once.
Result<std::vector<job::ChunkReport>> checked_chunks(const std::vector<std::string>& folders) {
  std::vector<job::ChunkReport> chunks;
  for (const std::string& folder : folders) {
    Result<job::ChunkReport> chunk = job::read_chunk_report(folder);
    if (!chunk) return Error{chunk.error()};
    chunks.push_back(std::move(*chunk));
  }
  std::stable_sort(chunks.begin(), chunks.end(),
                   [](const job::ChunkReport& a, const job::ChunkReport& b) {
                     return a.frames.first < b.frames.first;
                   });
  if (const Result<void> one = job::check_one_render(chunks); !one) return Error{one.error()};
  std::vector<job::FrameRange> ranges;
  std::vector<std::string> names;
  for (const job::ChunkReport& chunk : chunks) {
    ranges.push_back(chunk.frames);
    names.push_back(chunk.folder.string());
  }
  if (const Result<void> covered = job::check_coverage(ranges, names, chunks.front().scene_frames);
      !covered) {
    return Error{"the chunks do not hold every frame once: " + covered.error()};
  }
  return chunks;
}

// Succeeds when the folder to write, spelt one way, may be written; else why not.
Result<void> check_output(const fs::path& out, const std::vector<job::ChunkReport>& chunks) {
  if (out.empty() || out.filename() == "." || out.filename() == "..") {
    return Error{"the output folder must be named (got \"" + out.string() + "\")"};
  }
  std::error_code error;
  for (const job::ChunkReport& chunk : chunks) {
    if (fs::equivalent(out, chunk.folder, error)) {
      return Error{out.string() + " is one of the chunks; join into another folder"};
    }
  }
  const fs::path root = out.has_parent_path() ? out.parent_path() : fs::path(".");
  return job::check_replaceable(root, out.filename());
}

// Every chunk's frames/frame_NNNNN.png in `frames`: hard links where the file system allows
// them (same bytes, no copy), else copies.
Result<void> merge_frames(const std::vector<job::ChunkReport>& chunks, const fs::path& frames) {
  std::error_code error;
  fs::create_directory(frames, error);
  if (error) return Error{"cannot create " + frames.string() + ": " + error.message()};
  for (const job::ChunkReport& chunk : chunks) {
    for (std::int64_t k = chunk.frames.first; k < chunk.frames.end; ++k) {
      if (sys::interrupt_signal() != 0) return Error{"stopped"};
      const std::string name = pipeline::png_frame_name(k);
      const fs::path from = chunk.folder / "frames" / name;
      if (!fs::is_regular_file(from, error)) {
        return Error{chunk.folder.string() + ": frames/" + name +
                     " is missing (its report.json says it holds frames " +
                     job::range_text(chunk.frames) + ")"};
      }
      fs::create_hard_link(from, frames / name, error);
      if (error) fs::copy_file(from, frames / name, error);
      if (error) return Error{"cannot copy " + from.string() + ": " + error.message()};
    }
  }
  return {};
}

std::string joined_report(const std::vector<job::ChunkReport>& chunks, const fs::path& out) {
  const job::ChunkReport& first = chunks.front();
  std::ostringstream text;
  // The first line as every render's report.json starts (output_folder.cpp knows it by that).
  text << "{\n  \"scene\": " << io::json_string(first.scene)
       << ",\n  \"version\": " << io::json_string(TUMBLE_VERSION)
       << ",\n  \"scene_file\": " << io::json_string(first.scene_file)
       << ",\n  \"scene_hash\": " << io::json_string(first.scene_hash)
       << ",\n  \"scene_frames\": " << first.scene_frames << ",\n  \"chunk\": null"
       << ",\n  \"settings\": " << first.settings.text
       << ",\n  \"frames\": {\"first\": 0, \"end\": " << first.scene_frames
       << ", \"count\": " << first.scene_frames << "}"
       << ",\n  \"frames_directory\": "
       << (first.has_frames ? io::json_string((out / "frames").string()) : "null")
       << ",\n  \"video\": "
       << (first.video_names.empty() ? "null"
                                     : io::json_string((out / first.video_names.front()).string()))
       << ",\n  \"videos\": {";
  for (std::size_t i = 0; i < first.video_names.size(); ++i) {
    const fs::path name = first.video_names[i];
    text << (i ? ", " : "") << io::json_string(name.extension().string().substr(1)) << ": "
         << io::json_string((out / name).string());
  }
  text << "},\n  \"renderer\": " << io::json_string(first.renderer) << ",\n  \"joined_from\": [";
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    text << (i ? "," : "") << "\n    {\"folder\": " << io::json_string(chunks[i].folder.string())
         << ", \"first\": " << chunks[i].frames.first << ", \"end\": " << chunks[i].frames.end
         << ", \"renderer\": " << io::json_string(chunks[i].renderer) << "}";
  }
  text << "\n  ]\n}\n";
  return text.str();
}

// Succeeds when the video segment at `path` holds exactly `frames`, the frames its chunk's report
// says it holds (a WebM's index does not count its frames, so a copy cut short shows here).
Result<void> check_segment(const std::string& path, const job::FrameRange& frames) {
  const Result<io::VideoSegmentInfo> read = io::read_segment_info(path);
  if (!read) return Error{read.error()};
  const io::VideoSegmentInfo& info = *read;
  if (info.first_frame != frames.first || info.first_frame + info.frames != frames.end) {
    return Error{path + ": holds frames " +
                 job::range_text({info.first_frame, info.first_frame + info.frames}) +
                 ", its report says " + job::range_text(frames) +
                 " (a truncated or replaced copy?)"};
  }
  return {};
}

// The joined render written into `staging`, with the stills a whole render writes.
Result<void> write_joined(const std::vector<job::ChunkReport>& chunks, const fs::path& staging,
                          const fs::path& out, job::JoinedStills& stills) {
  const job::ChunkReport& first = chunks.front();
  if (first.has_frames) {
    if (Result<void> merged = merge_frames(chunks, staging / "frames"); !merged) return merged;
  }
  for (const std::string& name : first.video_names) {
    std::vector<std::string> segments;
    for (const job::ChunkReport& chunk : chunks) {
      segments.push_back((chunk.folder / name).string());
      if (Result<void> whole = check_segment(segments.back(), chunk.frames); !whole) return whole;
    }
    if (Result<void> joined = io::join_videos(segments, (staging / name).string()); !joined) {
      return joined;
    }
  }
  Result<job::JoinedStills> written = job::write_joined_stills(chunks, staging);
  if (!written) return Error{written.error()};
  stills = *written;
  return io::write_file_atomically((staging / "report.json").string(), joined_report(chunks, out));
}

}  // namespace

CommandResult run_join(const JoinOptions& options, std::FILE* err) {
  sys::install_interrupt_handlers();
  const Result<std::vector<job::ChunkReport>> chunks = checked_chunks(options.chunks);
  if (!chunks) return Error{"join: " + chunks.error()};
  const fs::path out = fs::path(options.out).lexically_normal();
  const fs::path folder = out.filename().empty() ? out.parent_path() : out;  // "a/b/" is "a/b"
  if (const Result<void> writable = check_output(folder, *chunks); !writable) {
    return Error{"join: " + writable.error()};
  }
  Result<io::StagedDirectory> staged = io::StagedDirectory::create(folder.string());
  if (!staged) return Error{"join: " + staged.error()};
  job::JoinedStills stills;
  Result<void> joined = write_joined(*chunks, staged->path(), folder, stills);
  if (const int signal = sys::interrupt_signal()) {
    std::fprintf(err, "tumble: join stopped by %s; %s was left as it was\n",
                 sys::signal_name(signal), folder.c_str());
    return interrupted_by(signal);
  }
  // Checked again: the folder may have been made or filled while the chunks were copied.
  if (joined) joined = check_output(folder, *chunks);
  if (joined) joined = staged->commit();
  if (!joined)
    return Error{"join: " + joined.error() + "; " + folder.string() + " was left as it was"};
  if (!staged->leftover().empty())
    std::fprintf(err, "tumble: warning: %s\n", staged->leftover().c_str());
  if (!options.quiet) {
    const job::ChunkReport& first = chunks->front();
    std::string files = first.has_frames ? "frames/, " : "";
    for (const std::string& name : first.video_names) files += name + ", ";
    if (stills.poster) files += "poster.png, ";
    if (stills.contact_sheet) files += "contact_sheet.png, ";
    std::fprintf(err, "tumble: joined %zu chunks, frames 0:%lld -> %s/: %sreport.json\n",
                 chunks->size(), static_cast<long long>(first.scene_frames), folder.c_str(),
                 files.c_str());
    if (!first.has_frames) {
      std::fprintf(err,
                   "tumble: no contact_sheet.png: the chunks hold no PNG frames to make it of\n");
    }
  }
  return kExitOk;
}

void add_join_command(CLI::App& app, Commands& commands) {
  const auto options = std::make_shared<JoinOptions>();
  CLI::App* command = app.add_subcommand(
      "join", "Join the chunk folders of one render into one render folder (frames, MP4, report)");
  command->add_option("out", options->out, "Render folder to write (replaced as a whole)")
      ->required()
      ->check(not_empty());
  command->add_option("chunks", options->chunks, "Chunk folders, in any order")
      ->required()
      ->check(not_empty());
  command->add_flag("-q,--quiet", options->quiet, "No summary");
  commands.push_back({command, [options] { return run_join(*options, stderr); }});
}

}  // namespace tumble::cli
