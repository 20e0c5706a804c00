// Where on the frame a text's box sits, as plain data: shared by scene (which reads the names
// from `[[overlays]] anchor`) and render (which lays the text out there), so that neither
// includes the other.
#pragma once

#include <optional>
#include <string_view>
#include <utility>

namespace tumble::common {

// A corner, the middle of an edge or the centre. Lines of several-line text align to the same
// side (left, centre, right). In reading order, row by row: the layout (render/text_layout.cpp)
// takes the column and the row from the value.
enum class Anchor {
  kTopLeft,
  kTop,
  kTopRight,
  kLeft,
  kCentre,
  kRight,
  kBottomLeft,
  kBottom,
  kBottomRight
};

// The anchor a scene names "top-left", "top", "top-right", "left", "centre" (or "center"),
// "right", "bottom-left", "bottom" or "bottom-right"; nothing for another name.
inline std::optional<Anchor> anchor_from_name(std::string_view name) {
  static constexpr std::pair<std::string_view, Anchor> kNames[] = {
      {"top-left", Anchor::kTopLeft},   {"top", Anchor::kTop},
      {"top-right", Anchor::kTopRight}, {"left", Anchor::kLeft},
      {"centre", Anchor::kCentre},      {"center", Anchor::kCentre},
      {"right", Anchor::kRight},        {"bottom-left", Anchor::kBottomLeft},
      {"bottom", Anchor::kBottom},      {"bottom-right", Anchor::kBottomRight}};
  for (const auto& [known, anchor] : kNames) {
    if (name == known) return anchor;
  }
  return std::nullopt;
}

}  // namespace tumble::common
