// The keys that choose what a render writes beyond PNG frames and an MP4: [output] formats,
// gif_loop, gif_fps, gif_colors, gif_dither and poster_time, and [render] background =
// "transparent". Internal to src/scene/.
#pragma once

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// [output] formats, the gif_ keys and poster_time (`in` is the [output] table), into `output`.
void read_output_choices(TableReader& in, OutputSpec& output);

// [render] background: a colour, or "transparent" (`in` is the [render] table).
void read_background(TableReader& in, common::RenderSettings& render);

}  // namespace tumble::scene::detail
