#include "scene/output_tables.hpp"

#include <algorithm>

namespace tumble::scene::detail {
namespace {

// The videos of [output] formats into output.formats, in order, and whether it names "gltf" and
// "html".
void read_formats(TableReader& in, OutputSpec& output) {
  const toml::array* array = in.table().get("formats")->as_array();
  if (!array) in.fail("formats", std::string("expected an array of ") + common::kFormatNames);
  if (array->empty()) {
    in.fail("formats", "names no format: list one or more, or set video = false for no video");
  }
  output.formats.clear();
  output.gltf = false;
  output.html = false;
  for (const toml::node& node : *array) {
    const std::optional<std::string_view> name = node.value<std::string_view>();
    const std::optional<common::VideoFormat> format =
        name ? common::video_format_named(*name) : std::nullopt;
    bool* const file = name ? file_format_flag(output, *name) : nullptr;
    if (!format && !file) {
      in.fail_at(node.source(), in.qualified("formats"),
                 (name ? "unknown format " + in_quotes(*name)
                       : "expected a string, found " + std::string(type_name(node))) +
                     " (" + common::kFormatNames + ")");
    }
    if (file ? *file
             : std::find(output.formats.begin(), output.formats.end(), *format) !=
                   output.formats.end()) {
      in.fail_at(node.source(), in.qualified("formats"), "lists " + in_quotes(*name) + " twice");
    }
    if (file) {
      *file = true;
    } else {
      output.formats.push_back(*format);
    }
  }
}

common::GifDither read_dither(TableReader& in) {
  const std::string name = in.required_string("gif_dither");
  for (const common::GifDither dither : common::kAllGifDithers) {
    if (name == common::gif_dither_name(dither)) return dither;
  }
  in.fail("gif_dither",
          "unknown dithering " + in_quotes(name) + " (\"none\", \"bayer\" or \"floyd_steinberg\")");
}

}  // namespace

void read_output_choices(TableReader& in, OutputSpec& output) {
  if (in.has("formats")) read_formats(in, output);
  output.gif_loop = in.optional_bool("gif_loop", output.gif_loop);
  if (in.has("gif_fps")) {
    output.gif_fps = static_cast<int>(in.optional_integer("gif_fps", 0, 1, common::kMaxGifFps));
  }
  output.gif_colors = static_cast<int>(in.optional_integer(
      "gif_colors", output.gif_colors, common::kMinGifColors, common::kMaxGifColors));
  if (in.has("gif_dither")) output.gif_dither = read_dither(in);
  if (in.has("poster_time")) {
    output.poster_time = in.required_number("poster_time");
    require_non_negative(in, "poster_time", *output.poster_time);
  }
}

void read_background(TableReader& in, common::RenderSettings& render) {
  if (in.has("background")) {
    if (in.table().get("background")->value<std::string_view>() == "transparent") {
      render.transparent = true;
      return;
    }
  }
  render.background = in.optional_color("background", render.background);
}

}  // namespace tumble::scene::detail
