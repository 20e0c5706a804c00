// The html replay as one page (docs/scene-reference.md, [output] formats): web/replay.html's
// markup with everything it shows put inside it, so that it needs nothing at view time, no
// network and no file beside it. A page opened from file:// cannot load ES modules by URL (its
// origin is null), so three.js comes as one classic script (web/three-entry.js, bundled by
// `npm run bundle`), and the glTF as base64 text that the page decodes for GLTFLoader.parse.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tumble::io {

// The markers of web/replay.html, each on a line of its own, each replaced by its part.
inline constexpr std::string_view kReplayDataMarker = "<!-- tumble: data -->";
inline constexpr std::string_view kReplayThreeMarker = "<!-- tumble: three.js -->";
inline constexpr std::string_view kReplayScriptMarker = "<!-- tumble: replay.js -->";

struct ReplayPageParts {
  std::string_view markup;     // web/replay.html: each marker exactly once
  std::string_view three_js;   // web/dist/three.bundle.js: sets the global TumbleThree
  std::string_view replay_js;  // web/replay.js: reads the two elements below
  std::string_view data_json;  // one JSON object: #tumble-replay-data (web/replay.js reads it)
  std::span<const std::uint8_t> glb;  // the render's glTF binary: #tumble-replay-glb, base64
};

// The page: the markup with the data marker replaced by <script type="application/json"
// id="tumble-replay-data"> (every '<' of the JSON written \u003c, so that no text of it can end
// the element) and <script type="application/octet-stream" id="tumble-replay-glb">, and each
// script marker by a <script> holding that script. The same parts give the same bytes. An error
// names the marker that the markup lacks or repeats, or the script that holds "</script", which
// would end its element early.
Result<std::string> replay_page(const ReplayPageParts& parts);

}  // namespace tumble::io
