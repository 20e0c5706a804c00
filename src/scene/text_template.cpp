#include "scene/text_template.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

namespace tumble::scene {
namespace {

constexpr std::array<std::pair<std::string_view, BodyQuantity>, 7> kQuantities = {{
    {"position", BodyQuantity::position},
    {"velocity", BodyQuantity::velocity},
    {"speed", BodyQuantity::speed},
    {"angular_velocity", BodyQuantity::angular_velocity},
    {"angular_speed", BodyQuantity::angular_speed},
    {"angular_momentum", BodyQuantity::angular_momentum},
    {"kinetic_energy", BodyQuantity::kinetic_energy},
}};

constexpr int kMaxPrecision = 17;  // digits: enough for any double, short enough for a frame

std::string quantity_list() {
  std::string out;
  for (const auto& [name, quantity] : kQuantities) {
    out += (out.empty() ? "" : ", ") + std::string(name);
  }
  return out;
}

constexpr int kMaxWidth = 40;  // characters a number is padded to

// A format spec after the colon, Python's mini-language subset
// [[fill]align][sign][0][width][.precision][type] with type f, e or g (default f, precision 2),
// into `out`; `whole` (the frame number) takes neither precision nor a type but d. False for
// anything else.
bool parse_format(std::string_view spec, Placeholder& out, bool whole) {
  const auto is_align = [](char c) { return c == '<' || c == '>' || c == '^' || c == '='; };
  std::size_t i = 0;
  bool filled = false, aligned = false;  // given in the spec
  if (spec.size() >= 2 && is_align(spec[1]) && spec[0] != '{' && spec[0] != '}') {
    out.fill = spec[0];
    out.align = spec[1];
    filled = aligned = true;
    i = 2;
  } else if (!spec.empty() && is_align(spec[0])) {
    out.align = spec[0];
    aligned = true;
    i = 1;
  }
  if (i < spec.size() && (spec[i] == '+' || spec[i] == '-' || spec[i] == ' ')) out.sign = spec[i++];
  if (i < spec.size() && spec[i] == '0') {  // as Python: zeros, after the sign unless aligned
    if (!filled) out.fill = '0';
    if (!aligned) out.align = '=';
    ++i;
  }
  const auto number = [&](int& value) {
    const std::size_t first = i;
    value = 0;
    while (i < spec.size() && spec[i] >= '0' && spec[i] <= '9' && i - first < 3) {
      value = 10 * value + (spec[i++] - '0');
    }
    return i > first;
  };
  number(out.width);
  if (out.width > kMaxWidth) return false;
  if (i < spec.size() && spec[i] == '.') {
    ++i;
    if (whole || !number(out.precision) || out.precision > kMaxPrecision) return false;
  }
  if (i < spec.size()) {
    const char type = spec[i++];
    if (whole ? type != 'd' : (type != 'f' && type != 'e' && type != 'g')) return false;
    if (!whole) out.conversion = type;
  }
  return i == spec.size();
}

// NAME.QUANTITY or NAME.QUANTITY.C; an error says which part is wrong. Body names may hold dots
// themselves ("cube.1"), and quantity names end in others ("angular_velocity" in "velocity"), so
// every split is tried; an unknown body is reported as the shortest name a split leaves.
Result<Placeholder> parse_body_value(std::string_view name,
                                     const std::vector<std::string>& body_names) {
  std::optional<std::string_view> unknown_body;
  for (const auto& [quantity_text, quantity] : kQuantities) {
    for (int component = -1; component < 3; ++component) {
      std::string suffix(1, '.');
      suffix.append(quantity_text);
      if (component >= 0) suffix.append(".").push_back(static_cast<char>('x' + component));
      if (name.size() <= suffix.size() || !name.ends_with(suffix)) continue;
      const std::string_view body = name.substr(0, name.size() - suffix.size());
      const auto found = std::find(body_names.begin(), body_names.end(), body);
      if (found == body_names.end()) {
        if (!unknown_body || body.size() < unknown_body->size()) unknown_body = body;
        continue;
      }
      if (component >= 0 && !is_vector(quantity)) {
        std::string what(quantity_text);
        what.append(" is a number, it has no component ").append(suffix, suffix.size() - 2, 2);
        return Error{what};
      }
      Placeholder out{.source = Placeholder::Source::body,
                      .body = static_cast<std::size_t>(found - body_names.begin()),
                      .quantity = quantity};
      out.component = component;
      return out;
    }
  }
  if (unknown_body) return Error{"no body is named \"" + std::string(*unknown_body) + "\""};
  if (name.find('.') == std::string_view::npos) {
    return Error{"expected time, frame or BODY.QUANTITY (QUANTITY one of " + quantity_list() + ")"};
  }
  return Error{"unknown quantity (expected one of " + quantity_list() +
               ", optionally with .x, .y or .z)"};
}

// JOINT.QUANTITY or JOINT.force.C for one of the joints; none when no joint's name starts it.
std::optional<Result<Placeholder>> parse_joint_value(std::string_view name,
                                                     const std::vector<JointName>& joints) {
  using physics::JointKind;
  constexpr std::pair<std::string_view, JointQuantity> kJointQuantities[] = {
      {"angle", JointQuantity::angle},
      {"speed", JointQuantity::speed},
      {"force", JointQuantity::force}};
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const std::string& joint = joints[j].name;
    if (name.size() <= joint.size() + 1 || !name.starts_with(joint) || name[joint.size()] != '.') {
      continue;
    }
    std::string_view rest = name.substr(joint.size() + 1);
    int component = -1;
    if (rest.size() > 2 && rest[rest.size() - 2] == '.' && rest.back() >= 'x' &&
        rest.back() <= 'z') {
      component = rest.back() - 'x';
      rest = rest.substr(0, rest.size() - 2);
    }
    for (const auto& [text, quantity] : kJointQuantities) {
      if (rest != text) continue;
      const JointKind kind = joints[j].kind;
      std::string what(1, '"');
      what.append(joint).append("\" is a ").append(physics::joint_kind_name(kind)).append(" joint");
      if (quantity == JointQuantity::angle && kind != JointKind::hinge) {
        return Result<Placeholder>(Error{"only a hinge has an angle (" + what + ")"});
      }
      if (quantity == JointQuantity::speed &&
          (kind == JointKind::ball || kind == JointKind::fixed)) {
        return Result<Placeholder>(
            Error{"a hinge, a slider or a distance has a speed (" + what + ")"});
      }
      if (component >= 0 && quantity != JointQuantity::force) {
        return Result<Placeholder>(Error{std::string(text) + " is a number, it has no component"});
      }
      Placeholder out{.source = Placeholder::Source::joint};
      out.joint = j;
      out.joint_quantity = quantity;
      out.component = component;
      return Result<Placeholder>(out);
    }
    std::string what = "unknown quantity of joint \"";
    what.append(joint).append("\" (expected angle, speed or force)");
    return Result<Placeholder>(Error{what});
  }
  return std::nullopt;
}

// The placeholder between the braces: a name, then an optional :format.
Result<Placeholder> parse_placeholder(std::string_view inside,
                                      const std::vector<std::string>& body_names,
                                      const std::vector<JointName>& joints) {
  const std::size_t colon = inside.find(':');
  const std::string_view name = inside.substr(0, colon);
  Placeholder out;
  if (name == "time") {
    out.source = Placeholder::Source::time;
  } else if (name == "frame") {
    out.source = Placeholder::Source::frame;
  } else if (std::optional<Result<Placeholder>> joint = parse_joint_value(name, joints)) {
    if (!*joint) return *joint;
    out = **joint;
  } else {
    Result<Placeholder> value = parse_body_value(name, body_names);
    if (!value) return value;
    out = *value;
  }
  const bool whole = out.source == Placeholder::Source::frame;
  if (colon != std::string_view::npos && !parse_format(inside.substr(colon + 1), out, whole)) {
    std::string what = "unknown format \"" + std::string(inside.substr(colon)) + "\" (expected ";
    what += whole ? std::string("[[fill]align][sign][0][width][d]: frame is a whole number")
                  : "[[fill]align][sign][0][width][.N][f|e|g], N from 0 to " +
                        std::to_string(kMaxPrecision);
    what += ", width up to " + std::to_string(kMaxWidth) + ")";
    return Error{what};
  }
  return out;
}

}  // namespace

std::string_view quantity_name(BodyQuantity quantity) {
  for (const auto& [name, known] : kQuantities) {
    if (known == quantity) return name;
  }
  return "?";
}

bool is_vector(BodyQuantity quantity) {
  return quantity == BodyQuantity::position || quantity == BodyQuantity::velocity ||
         quantity == BodyQuantity::angular_velocity || quantity == BodyQuantity::angular_momentum;
}

Result<TextTemplate> parse_text_template(std::string_view text,
                                         const std::vector<std::string>& body_names,
                                         const std::vector<JointName>& joints) {
  TextTemplate out;
  out.pieces.emplace_back();
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool doubled = i + 1 < text.size() && text[i + 1] == c;
    if ((c == '{' || c == '}') && doubled) {
      out.pieces.back() += c;
      ++i;
    } else if (c == '}') {
      return Error{"a lone \"}\" (write \"}}\" for a brace)"};
    } else if (c == '{') {
      const std::size_t close = text.find('}', i);
      if (close == std::string_view::npos) {
        return Error{"\"{\" without its \"}\" (write \"{{\" for a brace)"};
      }
      const std::string_view inside = text.substr(i + 1, close - i - 1);
      Result<Placeholder> value = parse_placeholder(inside, body_names, joints);
      if (!value) {
        // Appended one by one: GCC 12's -Wrestrict misreads "{" + std::string (a known bug).
        std::string what(1, '{');
        what.append(inside).append("}: ").append(value.error());
        return Error{what};
      }
      out.values.push_back(*value);
      out.pieces.emplace_back();
      i = close;
    } else {
      out.pieces.back() += c;
    }
  }
  return out;
}

}  // namespace tumble::scene
