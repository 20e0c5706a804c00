// A text overlay's text, parsed once at load: literal UTF-8 and {…} placeholders such as
// {time:.1f}, {frame} and {cube.angular_speed:.2f} (scene/overlays.hpp's TextTemplate).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "physics/joints.hpp"
#include "scene/overlays.hpp"

namespace tumble::scene {

// The quantity's name in a placeholder and in docs/scene-reference.md ("angular_speed").
std::string_view quantity_name(BodyQuantity quantity);

// Whether the quantity is a vector (x, y, z) rather than a number.
bool is_vector(BodyQuantity quantity);

// A joint as texts name it.
struct JointName {
  std::string name;
  physics::JointKind kind = physics::JointKind::ball;
};

// Parses `text`: `{{` and `}}` stand for braces; a placeholder is {time}, {frame},
// {NAME.QUANTITY} with NAME one of `body_names`, or {JOINT.angle}, {JOINT.speed} or
// {JOINT.force} with JOINT one of `joints` (an angle a hinge's, a speed a hinge's, slider's or
// distance's), each with an optional component .x, .y or .z of a vector quantity, then an
// optional format in Python's mini-language, the subset [[fill]align][sign][0][width][.N][type]
// with type f, e or g (N from 0 to 17, width up to 40; default .2f; {frame} takes no precision
// and only the type d). An error quotes the placeholder and says what is wrong with it.
Result<TextTemplate> parse_text_template(std::string_view text,
                                         const std::vector<std::string>& body_names,
                                         const std::vector<JointName>& joints = {});

}  // namespace tumble::scene
