// A text overlay's text, parsed once at load: literal UTF-8 and {…} placeholders such as
// {time:.1f}, {frame} and {cube.angular_speed:.2f} (scene/overlays.hpp's TextTemplate).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "scene/overlays.hpp"

namespace tumble::scene {

// The quantity's name in a placeholder and in docs/scene-reference.md ("angular_speed").
std::string_view quantity_name(BodyQuantity quantity);

// Whether the quantity is a vector (x, y, z) rather than a number.
bool is_vector(BodyQuantity quantity);

// Parses `text`: `{{` and `}}` stand for braces; a placeholder is {time}, {frame} or
// {NAME.QUANTITY} with NAME one of `body_names` and an optional component .x, .y or .z of a
// vector quantity, then an optional printf-like format :.Nf, :.Ne or :.Ng (N from 0 to 17;
// default .2f). An error quotes the placeholder and says what is wrong with it.
Result<TextTemplate> parse_text_template(std::string_view text,
                                         const std::vector<std::string>& body_names);

}  // namespace tumble::scene
