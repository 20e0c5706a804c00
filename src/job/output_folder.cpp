#include "job/output_folder.hpp"

#include <fstream>
#include <string>
#include <string_view>

#include "common/video_format.hpp"

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

// Whether `folder` is a render's: it holds a report.json that starts as report_json (in
// job/render_folder.cpp) starts it.
bool is_render_folder(const fs::path& folder) {
  constexpr std::string_view kStart = "{\n  \"scene\": ";
  std::ifstream report(folder / "report.json", std::ios::binary);
  char start[kStart.size()] = {};
  report.read(start, static_cast<std::streamsize>(kStart.size()));
  return std::string_view(start, static_cast<std::size_t>(report.gcount())) == kStart;
}

// Whether a render writes a file of this name at the top of its folder: report.json, poster.png,
// contact_sheet.png, <scene name>.<format> for each video format, <scene name>.glb and
// <scene name>.html.
bool is_render_file(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name == "report.json" || name == "poster.png" || name == "contact_sheet.png") return true;
  const std::string extension = file.extension().string();
  return !extension.empty() && (common::video_format_named(extension.substr(1)).has_value() ||
                                extension.substr(1) == common::kGltfExtension ||
                                extension.substr(1) == common::kHtmlExtension);
}

// The first thing in a render's folder that a render does not write: it writes the files of
// is_render_file and frames/frame_NNNNN.png, and nothing else. "" when there is none.
std::string foreign_entry(const fs::path& directory) {
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_symlink(error)) return name;
    if (name == "frames" && entry.is_directory(error)) {
      for (const fs::directory_entry& frame : fs::directory_iterator(entry.path(), error)) {
        const std::string frame_name = frame.path().filename().string();
        if (frame.is_symlink(error) || !frame.is_regular_file(error) ||
            frame_name.rfind("frame_", 0) != 0 || frame.path().extension() != ".png") {
          return "frames/" + frame_name;
        }
      }
    } else if (!entry.is_regular_file(error) || !is_render_file(entry.path())) {
      return name;
    }
  }
  return error ? "(unreadable: " + error.message() + ")" : std::string();
}

}  // namespace

Result<void> check_replaceable(const fs::path& root, const fs::path& relative) {
  const std::string advice =
      "; a render replaces its folder as a whole, so choose another -o or [output] directory";
  const auto inside_render = [&](const fs::path& folder) {
    return folder.string() + " is a render's folder, which a render inside it would change" +
           advice;
  };
  std::error_code error;
  // The output root and every folder above it, where they really are (a link named by -o may
  // lead into a render's folder), then each folder down to the scene's.
  fs::path real_root = fs::weakly_canonical(root, error);
  if (error) real_root = fs::absolute(root, error);
  for (fs::path above = real_root; !above.empty(); above = above.parent_path()) {
    if (is_render_folder(above)) return Error{inside_render(above)};
    if (above == above.root_path()) break;
  }
  fs::path directory = root;
  for (const fs::path& part : relative) {
    if (directory != root && is_render_folder(directory)) return Error{inside_render(directory)};
    directory /= part;
    const fs::file_status status = fs::symlink_status(directory, error);
    if (!fs::exists(status)) return {};
    if (fs::is_symlink(status)) return Error{directory.string() + " is a symbolic link" + advice};
    if (!fs::is_directory(status)) return Error{directory.string() + " exists and is not a folder"};
  }
  if (!is_render_folder(directory) && !fs::is_empty(directory, error)) {
    return Error{"output folder " + directory.string() + " exists and is not a tumble render (it " +
                 "has no report.json of tumble's)" + advice + ", or remove it"};
  }
  if (const std::string foreign = foreign_entry(directory); !foreign.empty()) {
    return Error{"output folder " + directory.string() + " holds " + foreign +
                 ", which a render does not write" + advice + ", or move it"};
  }
  return {};
}

}  // namespace tumble::job
