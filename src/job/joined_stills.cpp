#include "job/joined_stills.hpp"

#include <algorithm>

#include "io/png_io.hpp"
#include "pipeline/contact_sheet.hpp"
#include "pipeline/frame_sinks.hpp"

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

// The PNG settings the chunks were written with (report.json's settings).
io::PngSettings png_settings(const io::JsonValue& settings) {
  io::PngSettings png;
  if (const io::JsonValue* encoder = settings.find("png_encoder")) {
    png.own_encoder = encoder->string == "tumble";
  }
  if (const io::JsonValue* level = settings.find("png_zlib_level")) {
    png.compression_level = static_cast<int>(level->number);
  }
  if (const io::JsonValue* filter = settings.find("png_filter")) png.filter = filter->boolean;
  return png;
}

Result<void> link_poster(const std::vector<ChunkReport>& chunks, const fs::path& to,
                         bool& written) {
  std::error_code error;
  for (const ChunkReport& chunk : chunks) {
    const fs::path from = chunk.folder / "poster.png";
    const bool own =
        std::find(chunk.kept.begin(), chunk.kept.end(), "poster.png") == chunk.kept.end();
    if (!own || !fs::is_regular_file(from, error)) continue;
    fs::create_hard_link(from, to, error);
    if (error) fs::copy_file(from, to, error);
    if (error) return Error{"cannot copy " + from.string() + ": " + error.message()};
    written = true;
    return {};
  }
  return {};
}

}  // namespace

Result<JoinedStills> write_joined_stills(const std::vector<ChunkReport>& chunks,
                                         const fs::path& staging) {
  JoinedStills stills;
  if (Result<void> poster = link_poster(chunks, staging / "poster.png", stills.poster); !poster) {
    return Error{poster.error()};
  }
  const ChunkReport& first = chunks.front();
  if (!first.has_frames) return stills;
  const io::JsonValue* fps = first.settings.find("fps");
  if (!fps || fps->number < 1) return Error{first.folder.string() + ": report.json: no fps"};
  const std::int64_t end = first.scene_frames;
  // The labels' font as the chunks' render drew them (report.json settings.font; the default
  // for a report written before it was recorded).
  const io::JsonValue* font = first.settings.find("font");
  const std::string family = font && font->kind == io::JsonValue::Kind::string
                                 ? font->string
                                 : std::string(render::kDefaultFontFamily);
  Result<std::unique_ptr<pipeline::ContactSheet>> sheet = pipeline::ContactSheet::open(
      (staging / "contact_sheet.png").string(), 0, end, static_cast<int>(fps->number),
      png_settings(first.settings), family);
  if (!sheet) return Error{sheet.error()};
  for (const std::int64_t k : pipeline::contact_sheet_frames(0, end)) {
    const Result<io::Image> frame =
        io::read_png((staging / "frames" / pipeline::png_frame_name(k)).string());
    if (!frame) return Error{frame.error()};
    if (Result<void> taken = (*sheet)->write(k, *frame); !taken) return Error{taken.error()};
  }
  if (Result<void> finished = (*sheet)->finish(); !finished) return Error{finished.error()};
  stills.contact_sheet = true;
  return stills;
}

}  // namespace tumble::job
