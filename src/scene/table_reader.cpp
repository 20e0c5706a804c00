#include "scene/table_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>
#include <vector>

namespace tumble::scene::detail {

std::string_view type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date or time";
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::size_t length = std::min(text.size(), max_bytes);
  while (length < text.size() && length > 0 && (text[length] & 0xc0) == 0x80) --length;  // UTF-8
  std::string out;
  for (const char c : text.substr(0, length)) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  if (length < text.size()) out += "...";
  return out;
}

std::string in_quotes(std::string_view text) {
  return '"' + printable(text) + '"';
}

void require_positive(TableReader& reader, std::string_view key, double value) {
  if (!(value > 0.0)) reader.fail(key, "must be greater than 0 (got " + format_number(value) + ")");
}

void require_non_negative(TableReader& reader, std::string_view key, double value) {
  if (value < 0.0) reader.fail(key, "must not be negative (got " + format_number(value) + ")");
}

bool is_safe_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.size() > 100) return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

Vec3 vector_within(TableReader& in, std::string_view key, const Vec3& value, double bound,
                   const char* unit) {
  const double length = value.stableNorm();  // norm() squares: 1e200 would read as infinite
  if (!(length <= bound)) {
    in.fail(key, "its length " + format_number(length) + " " + unit + " is past the " +
                     format_number(bound) + " " + unit + " tumble can simulate");
  }
  return value;
}

namespace {

// "#rrggbb" (or "#rrggbbaa" when `with_alpha`) as components in [0, 1]; nothing for other text.
std::optional<std::vector<double>> hex_components(const std::string& text, bool with_alpha) {
  const bool hex = (text.size() == 7 || (with_alpha && text.size() == 9)) && text[0] == '#' &&
                   text.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
  if (!hex) return std::nullopt;
  std::vector<double> out;
  for (std::size_t i = 1; i < text.size(); i += 2) {
    out.push_back(std::stoi(text.substr(i, 2), nullptr, 16) / 255.0);
  }
  return out;
}

}  // namespace

Vec3 TableReader::optional_color(std::string_view key, const Vec3& fallback) {
  return has(key) ? color(key, *table_.get(key)) : fallback;
}

Vec3 TableReader::color(std::string_view key, const toml::node& node) const {
  if (node.is_string()) {
    const std::string text = *node.value<std::string>();
    const auto hex = hex_components(text, false);
    if (!hex) fail(key, "expected a colour \"#rrggbb\" or [r, g, b], found " + in_quotes(text));
    return Vec3((*hex)[0], (*hex)[1], (*hex)[2]);
  }
  const toml::array* array = node.as_array();
  if (!array || array->size() != 3) {
    fail(key, "expected a colour \"#rrggbb\" or [r, g, b], found " +
                  (array ? "an array of " + std::to_string(array->size())
                         : std::string(type_name(node))));
  }
  const Vec3 out = vector(key, node);
  if (out.minCoeff() < 0.0 || out.maxCoeff() > 1.0) {
    fail(key, "colour components must be from 0 to 1 (got [" + format_number(out.x()) + ", " +
                  format_number(out.y()) + ", " + format_number(out.z()) + "])");
  }
  return out;
}

Eigen::Vector4d TableReader::optional_rgba(std::string_view key, const Eigen::Vector4d& fallback) {
  if (!has(key)) return fallback;
  const toml::node& node = *table_.get(key);
  const char* form =
      "expected a colour \"#rrggbb\", \"#rrggbbaa\", [r, g, b] or [r, g, b, a], found ";
  if (node.is_string()) {
    const std::string text = *node.value<std::string>();
    const auto hex = hex_components(text, true);
    if (!hex) fail(key, form + in_quotes(text));
    return Eigen::Vector4d((*hex)[0], (*hex)[1], (*hex)[2], hex->size() == 4 ? (*hex)[3] : 1.0);
  }
  const toml::array* array = node.as_array();
  if (!array || (array->size() != 3 && array->size() != 4)) {
    fail(key, form + (array ? "an array of " + std::to_string(array->size())
                            : std::string(type_name(node))));
  }
  Eigen::Vector4d out(0.0, 0.0, 0.0, 1.0);
  for (std::size_t i = 0; i < array->size(); ++i) {
    out[static_cast<int>(i)] = number(key, (*array)[i]);
    if (out[static_cast<int>(i)] < 0.0 || out[static_cast<int>(i)] > 1.0) {
      fail(key, "colour components must be from 0 to 1 (got " +
                    format_number(out[static_cast<int>(i)]) + ")");
    }
  }
  return out;
}

}  // namespace tumble::scene::detail
