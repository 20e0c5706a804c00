// What a render keeps of an earlier render of the same scene in its folder. The folder is still
// staged and swapped in whole (io::StagedDirectory); before the swap, each file of the earlier
// render that the new one did not write is linked (or copied) into the staged folder, so that a
// GIF rendered apart, or a render with --no-frames, does not take the MP4 or the frames with it.
// An earlier render of another scene is replaced as a whole, as before.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "scene/scene.hpp"

namespace tumble::job {

// A file of a render folder, or its frames/ folder, and the render that wrote it.
struct RenderedFile {
  std::string name;    // in the folder: "frames", "spin.mp4", "poster.png"
  std::string origin;  // JSON: {"scene_hash", "width", "height", "fps", "frames"} of that render
};

// What a render found in the folder it is about to replace.
struct EarlierRender {
  enum class Kind {
    none,         // no folder, or an empty one
    same_scene,   // a render of this scene file: `files` may be kept
    other_scene,  // replaced as a whole; `why` says what differs
  };
  Kind kind = Kind::none;
  std::string why;                  // other_scene: "another scene file", "a report.json ..."
  std::vector<RenderedFile> files;  // same_scene: each file there whose render is known

  bool holds(std::string_view name) const;
};

// The render in `folder`. It is of the same scene when its report.json's scene_hash is this
// scene file's hash as that render drew it: the file's bytes with the earlier width, height,
// fps and msaa (job/scene_hash.hpp). So a GIF at another size or rate of the same file is the
// same scene; an edited file is another. `scene` is the scene as it is rendered now.
EarlierRender read_earlier_render(const std::filesystem::path& folder, std::string_view scene_text,
                                  const scene::Scene& scene);

// The files a render writes that `folder` holds, in a fixed order: "frames" (the folder), the
// scene's videos in mp4, webm, gif order, its .glb, its .html, "poster.png", "contact_sheet.png".
std::vector<std::string> render_files(const std::filesystem::path& folder,
                                      const std::string& scene_name);

// Whether a render writes the earlier render's poster.png and contact_sheet.png itself: not when
// it writes only a GIF, a glTF or an html replay (no PNG frames, no MP4 or WebM) over an earlier
// render of the same scene that has them, since the stills belong with the frames and the main
// video.
bool writes_own_stills(const scene::Scene& scene, const EarlierRender& earlier);

// Each file of `earlier` (in `from`) that `staging` lacks, hard-linked into `staging` (copied
// where links fail): the same bytes. With `own_stills` (writes_own_stills) the earlier poster
// and contact sheet go even where the new render wrote none (its frames miss the poster frame).
// Returns the files kept.
Result<std::vector<RenderedFile>> keep_earlier_files(const EarlierRender& earlier,
                                                     const std::filesystem::path& from,
                                                     const std::filesystem::path& staging,
                                                     bool own_stills);

// report.json's "kept": [{"file": NAME, "from": ORIGIN}, ...].
std::string kept_json(const std::vector<RenderedFile>& kept);

}  // namespace tumble::job
