#include "diff/diff_inputs.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace tumble::diff {
namespace fs = std::filesystem;
namespace {

bool ends_in_png(const std::string& name) {
  if (name.size() < 4) return false;
  std::string tail = name.substr(name.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".png";
}

bool starts_with_png_signature(const std::string& path) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  unsigned char head[8] = {};
  const bool whole = std::fread(head, 1, sizeof head, file) == sizeof head;
  std::fclose(file);
  return whole && std::memcmp(head, kSignature, sizeof head) == 0;
}

// Regular files ending in .png directly inside `folder`, sorted by name (frame_00000.png, …).
std::vector<std::string> png_names(const fs::path& folder, std::error_code& error) {
  std::vector<std::string> names;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (ends_in_png(name) && it->is_regular_file(error)) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

bool names_png(const std::string& path) {
  return ends_in_png(path) || starts_with_png_signature(path);
}

Result<DiffInput> resolve_diff_input(const std::string& path) {
  DiffInput out;
  out.path = path;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) return Error{path + ": no such file or folder"};
  if (!fs::is_directory(status)) {
    out.kind = names_png(path) ? DiffInputKind::png : DiffInputKind::video;
    return out;
  }
  out.kind = DiffInputKind::folder;
  out.folder = path;
  std::error_code no_frames_folder;  // not an error: the folder then holds no frames
  // A render's output folder holds its frames in frames/, beside the videos, report.json and
  // the stills (poster.png, contact_sheet.png), which are not frames.
  if (fs::is_directory(fs::path(path) / "frames", no_frames_folder)) {
    out.folder = (fs::path(path) / "frames").string();
  }
  out.frames = png_names(out.folder, error);
  if (error) return Error{out.folder + ": cannot list the folder: " + error.message()};
  if (out.frames.empty()) {
    return Error{path + ": folder holds no PNG frames (*.png, or frames/*.png)"};
  }
  return out;
}

}  // namespace tumble::diff
