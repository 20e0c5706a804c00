#include "io/replay_page.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

#include "io/base64.hpp"

namespace tumble::io {
namespace {

// Where `marker` is in `markup`: an error when it is not there exactly once.
Result<std::size_t> marker_at(std::string_view markup, std::string_view marker) {
  const std::size_t at = markup.find(marker);
  if (at == std::string_view::npos) {
    return Error{"the replay page's markup (web/replay.html) has no " + std::string(marker)};
  }
  if (markup.find(marker, at + marker.size()) != std::string_view::npos) {
    return Error{"the replay page's markup (web/replay.html) has " + std::string(marker) +
                 " twice"};
  }
  return at;
}

// Whether `text` holds "</script", in any case: HTML ends a script element there, whatever
// JavaScript would make of it.
bool ends_script(std::string_view text) {
  constexpr std::string_view kEnd = "</script";
  const auto lower_equal = [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == b;
  };
  return std::search(text.begin(), text.end(), kEnd.begin(), kEnd.end(), lower_equal) != text.end();
}

std::string script_element(std::string_view script) {
  return "<script>\n" + std::string(script) + "\n</script>";
}

std::string data_elements(std::string_view json, std::span<const std::uint8_t> glb) {
  std::string escaped;
  escaped.reserve(json.size());
  for (const char c : json) {
    // Only a JSON string can hold '<', and \u003c is the same character there.
    if (c == '<') {
      escaped += "\\u003c";
    } else {
      escaped += c;
    }
  }
  return "<script type=\"application/json\" id=\"tumble-replay-data\">" + escaped +
         "</script>\n<script type=\"application/octet-stream\" id=\"tumble-replay-glb\">" +
         base64(glb) + "</script>";
}

}  // namespace

Result<std::string> replay_page(const ReplayPageParts& parts) {
  for (const auto& [name, script] :
       {std::pair{"three.js", parts.three_js}, std::pair{"replay.js", parts.replay_js}}) {
    if (ends_script(script)) {
      return Error{std::string("the replay page's ") + name +
                   " holds \"</script\", which would end its <script> element"};
    }
  }
  struct Replacement {
    std::size_t at;  // in the markup
    std::string_view marker;
    std::string text;
  };
  std::vector<Replacement> replacements = {
      {0, kReplayDataMarker, data_elements(parts.data_json, parts.glb)},
      {0, kReplayThreeMarker, script_element(parts.three_js)},
      {0, kReplayScriptMarker, script_element(parts.replay_js)}};
  // Found in the markup alone, so that no text put in can be taken for a marker.
  for (Replacement& replacement : replacements) {
    const Result<std::size_t> at = marker_at(parts.markup, replacement.marker);
    if (!at) return Error{at.error()};
    replacement.at = *at;
  }
  std::sort(replacements.begin(), replacements.end(),
            [](const Replacement& a, const Replacement& b) { return a.at < b.at; });
  std::string page;
  std::size_t copied = 0;  // of the markup
  for (const Replacement& replacement : replacements) {
    page.append(parts.markup.substr(copied, replacement.at - copied));
    page += replacement.text;
    copied = replacement.at + replacement.marker.size();
  }
  page.append(parts.markup.substr(copied));
  return page;
}

}  // namespace tumble::io
