#include "job/kept_files.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "common/video_format.hpp"
#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "job/scene_hash.hpp"

namespace tumble::job {
namespace {

namespace fs = std::filesystem;
using io::JsonValue;

constexpr const char* kFrames = "frames";
constexpr const char* kPoster = "poster.png";
constexpr const char* kContactSheet = "contact_sheet.png";

// The whole number from 0 to 10^15 at `key` of `object` (every width, rate and frame number a
// render writes), or -1 when there is none (a hand-edited report: nothing is cast out of range).
long long whole_number(const JsonValue* object, std::string_view key) {
  const JsonValue* value = object ? object->find(key) : nullptr;
  if (!value || value->kind != JsonValue::Kind::number ||
      value->number != std::floor(value->number) || !(value->number >= 0.0) ||
      value->number > 1e15) {
    return -1;
  }
  return static_cast<long long>(value->number);
}

EarlierRender other_scene(std::string why) {
  return {.kind = EarlierRender::Kind::other_scene, .why = std::move(why), .files = {}};
}

// What the earlier report says of the render that wrote it, as the "from" of a kept file.
std::string origin_json(const std::string& hash, long long width, long long height, long long fps,
                        long long first, long long end) {
  return "{\"scene_hash\": " + io::json_string(hash) + ", \"width\": " + std::to_string(width) +
         ", \"height\": " + std::to_string(height) + ", \"fps\": " + std::to_string(fps) +
         ", \"frames\": {\"first\": " + std::to_string(first) +
         ", \"end\": " + std::to_string(end) + ", \"count\": " + std::to_string(end - first) + "}}";
}

// The files that the earlier render kept itself, by name, with where they came from.
std::map<std::string, std::string> earlier_kept(const JsonValue& report) {
  std::map<std::string, std::string> kept;
  const JsonValue* list = report.find("kept");
  if (!list || list->kind != JsonValue::Kind::array) return kept;
  for (const JsonValue& item : list->items) {
    const JsonValue* file = item.find("file");
    const JsonValue* from = item.find("from");
    if (file && file->kind == JsonValue::Kind::string && from &&
        from->kind == JsonValue::Kind::object) {
      kept[file->string] = from->text;
    }
  }
  return kept;
}

// Which of the earlier render's files it wrote itself, by its report.
bool wrote(const JsonValue& report, const std::string& name) {
  if (name == kFrames) {
    const JsonValue* directory = report.find("frames_directory");
    return directory && directory->kind == JsonValue::Kind::string;
  }
  if (name == kPoster || name == kContactSheet) return true;  // unless kept (earlier_kept first)
  for (const char* key : {"gltf", "html"}) {
    const JsonValue* file = report.find(key);
    if (file && file->kind == JsonValue::Kind::string &&
        fs::path(file->string).filename() == name) {
      return true;
    }
  }
  const JsonValue* videos = report.find("videos");
  if (!videos) return false;
  for (const io::JsonMember& video : videos->members) {
    if (video.value.kind == JsonValue::Kind::string &&
        fs::path(video.value.string).filename() == name) {
      return true;
    }
  }
  return false;
}

Result<void> link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code error;
  fs::create_hard_link(from, to, error);
  if (error) fs::copy_file(from, to, error);
  if (error) return Error{"cannot keep " + from.string() + ": " + error.message()};
  return {};
}

Result<void> keep(const fs::path& from, const fs::path& to) {
  std::error_code error;
  if (!fs::is_directory(from, error)) return link_or_copy(from, to);
  fs::create_directory(to, error);
  if (error) return Error{"cannot create " + to.string() + ": " + error.message()};
  std::vector<fs::path> entries;
  for (const fs::directory_entry& entry : fs::directory_iterator(from, error)) {
    entries.push_back(entry.path());
  }
  if (error) return Error{"cannot read " + from.string() + ": " + error.message()};
  std::sort(entries.begin(), entries.end());
  for (const fs::path& entry : entries) {
    if (Result<void> kept = link_or_copy(entry, to / entry.filename()); !kept) return kept;
  }
  return {};
}

}  // namespace

bool EarlierRender::holds(std::string_view name) const {
  return std::any_of(files.begin(), files.end(),
                     [&](const RenderedFile& file) { return file.name == name; });
}

std::vector<std::string> render_files(const fs::path& folder, const std::string& scene_name) {
  std::vector<std::string> names = {kFrames};
  for (const common::VideoFormat format : common::kAllVideoFormats) {
    names.push_back(scene_name + "." + common::video_format_name(format));
  }
  names.push_back(scene_name + "." + std::string(common::kGltfExtension));
  names.push_back(scene_name + "." + std::string(common::kHtmlExtension));
  names.push_back(kPoster);
  names.push_back(kContactSheet);
  std::vector<std::string> present;
  std::error_code error;
  for (const std::string& name : names) {
    if (fs::exists(folder / name, error)) present.push_back(name);
  }
  return present;
}

EarlierRender read_earlier_render(const fs::path& folder, std::string_view scene_text,
                                  const scene::Scene& scene) {
  std::error_code error;
  if (!fs::is_directory(folder, error) || fs::is_empty(folder, error)) return {};
  std::ifstream file(folder / "report.json", std::ios::binary);
  std::ostringstream bytes;
  bytes << file.rdbuf();
  const Result<JsonValue> report = io::parse_json(bytes.str());
  const JsonValue* settings = report ? report->find("settings") : nullptr;
  const JsonValue* frames = report ? report->find("frames") : nullptr;
  const JsonValue* hash = report ? report->find("scene_hash") : nullptr;
  const long long width = whole_number(settings, "width"),
                  height = whole_number(settings, "height"), fps = whole_number(settings, "fps"),
                  msaa = whole_number(settings, "msaa"), first = whole_number(frames, "first"),
                  end = whole_number(frames, "end");
  if (!hash || hash->kind != JsonValue::Kind::string || std::min({width, height, fps, first}) < 0 ||
      end <= first || msaa < 0) {
    return other_scene("a render whose report.json this tumble cannot read");
  }
  scene::Scene as_drawn = scene;  // at the earlier render's size, rate and antialiasing
  as_drawn.render.width = static_cast<int>(width);
  as_drawn.render.height = static_cast<int>(height);
  as_drawn.fps = static_cast<int>(fps);
  as_drawn.render.msaa = static_cast<int>(msaa);
  if (scene_hash(scene_text, as_drawn) != hash->string) {
    return other_scene("a render of another scene file (or of another duration)");
  }
  const std::map<std::string, std::string> kept = earlier_kept(*report);
  const std::string own = origin_json(hash->string, width, height, fps, first, end);
  EarlierRender earlier{.kind = EarlierRender::Kind::same_scene, .why = {}, .files = {}};
  for (const std::string& name : render_files(folder, scene.name)) {
    if (const auto from = kept.find(name); from != kept.end()) {
      earlier.files.push_back({name, from->second});
    } else if (wrote(*report, name)) {
      earlier.files.push_back({name, own});
    }  // else a file of unknown origin: not kept
  }
  return earlier;
}

bool writes_own_stills(const scene::Scene& scene, const EarlierRender& earlier) {
  // No PNG frames and no MP4 or WebM: a GIF, a glTF, or both.
  const bool gif_alone =
      !scene.output.frames &&
      (!scene.output.video ||
       std::all_of(scene.output.formats.begin(), scene.output.formats.end(),
                   [](common::VideoFormat format) { return format == common::VideoFormat::gif; }));
  return !(gif_alone && (earlier.holds(kPoster) || earlier.holds(kContactSheet)));
}

Result<std::vector<RenderedFile>> keep_earlier_files(const EarlierRender& earlier,
                                                     const fs::path& from, const fs::path& staging,
                                                     bool own_stills) {
  std::vector<RenderedFile> kept;
  std::error_code error;
  for (const RenderedFile& file : earlier.files) {
    if (fs::exists(staging / file.name, error)) continue;  // the new render wrote its own
    if (own_stills && (file.name == kPoster || file.name == kContactSheet)) continue;
    if (Result<void> done = keep(from / file.name, staging / file.name); !done) {
      return Error{done.error()};
    }
    kept.push_back(file);
  }
  return kept;
}

std::string kept_json(const std::vector<RenderedFile>& kept) {
  std::string text = "[";
  for (std::size_t i = 0; i < kept.size(); ++i) {
    text += (i ? ", " : "") + std::string("{\"file\": ") + io::json_string(kept[i].name) +
            ", \"from\": " + kept[i].origin + "}";
  }
  return text + "]";
}

}  // namespace tumble::job
