// Reading one TOML table of a scene file with exact error locations: used by every part of the
// scene loader. Internal to src/scene/.
#pragma once

#include <toml++/toml.h>
#include <cstdint>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "physics/rigid_body.hpp"

namespace tumble::scene::detail {

using physics::Quat;
using physics::Vec3;

// Thrown inside the loader only; load_scene_file/parse_scene catch it and return its message
// as an Error.
struct LoadFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string_view type_name(const toml::node& node);

// Levenshtein distance, for "did you mean" hints on misspelt keys.
std::size_t edit_distance(std::string_view a, std::string_view b);

std::string format_number(double value);

// Text from the scene file as it goes into a message: control characters escaped (\n, \x1b),
// and cut to `max_bytes` with "..." so that a megabyte-long key does not fill the terminal.
std::string printable(std::string_view text, std::size_t max_bytes = 80);

// printable(text) in double quotes (not std::quoted: no escaping of quotes, and cut short).
std::string in_quotes(std::string_view text);

// A table being read: knows its dotted path for messages and which keys were asked for, so that
// every key nobody asked for can be reported as unknown.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, const std::string& file)
      : table_(table), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail_at(const toml::source_region& where, std::string_view key,
                            std::string_view what) const {
    std::ostringstream out;
    out << file_ << ':' << where.begin.line << ':' << where.begin.column << ": " << printable(key)
        << ": " << what;
    throw LoadFailure(out.str());
  }
  [[noreturn]] void fail(std::string_view key, std::string_view what) const {
    const toml::node* node = table_.get(key);
    fail_at(node ? node->source() : table_.source(), qualified(key), what);
  }

  std::string qualified(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }

  bool has(std::string_view key) {
    known_.insert(std::string(key));
    return table_.contains(key);
  }

  const toml::node& required(std::string_view key) {
    if (!has(key)) {
      // A missing key is often a misspelt one: point at the misspelling instead.
      for (auto&& [written, node] : table_) {
        if (!known_.count(std::string(written.str())) && edit_distance(written.str(), key) <= 2) {
          fail_at(written.source(), qualified(written.str()),
                  "unknown key (did you mean " + in_quotes(key) + "?)");
        }
      }
      fail_at(table_.source(), qualified(key),
              "missing required key" + (path_.empty() ? std::string() : " in " + path_));
    }
    return *table_.get(key);
  }

  double number(std::string_view key, const toml::node& node) const {
    if (!node.is_number()) {
      fail(key, "expected a number, found " + std::string(type_name(node)));
    }
    // toml++ will not convert integers beyond 2^53 to double; do it ourselves (rounding).
    const double value = node.is_integer() ? static_cast<double>(node.as_integer()->get())
                                           : node.as_floating_point()->get();
    if (!std::isfinite(value)) fail(key, "must be a finite number");
    return value;
  }

  double required_number(std::string_view key) { return number(key, required(key)); }
  double optional_number(std::string_view key, double fallback) {
    return has(key) ? number(key, *table_.get(key)) : fallback;
  }

  std::string required_string(std::string_view key) { return string(key, required(key)); }
  std::string optional_string(std::string_view key, std::string fallback) {
    return has(key) ? string(key, *table_.get(key)) : std::move(fallback);
  }

  Vec3 vector(std::string_view key, const toml::node& node) const {
    const toml::array* array = node.as_array();
    if (!array || array->size() != 3) {
      fail(key, "expected an array of 3 numbers [x, y, z], found " +
                    (array ? "an array of " + std::to_string(array->size())
                           : std::string(type_name(node))));
    }
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = number(key, (*array)[static_cast<std::size_t>(i)]);
    return out;
  }
  Vec3 required_vector(std::string_view key) { return vector(key, required(key)); }
  Vec3 optional_vector(std::string_view key, const Vec3& fallback) {
    return has(key) ? vector(key, *table_.get(key)) : fallback;
  }

  // A unit quaternion written [w, x, y, z]; a small normalisation error is forgiven.
  Quat optional_quaternion(std::string_view key) {
    if (!has(key)) return Quat::Identity();
    const toml::node& node = *table_.get(key);
    const toml::array* array = node.as_array();
    if (!array || array->size() != 4) {
      fail(key, "expected a unit quaternion [w, x, y, z], found " +
                    (array ? "an array of " + std::to_string(array->size())
                           : std::string(type_name(node))));
    }
    double c[4];
    for (std::size_t i = 0; i < 4; ++i) c[i] = number(key, (*array)[i]);
    const Quat q(c[0], c[1], c[2], c[3]);
    if (std::abs(q.norm() - 1.0) > 1e-3) {
      fail(key, "must be a unit quaternion [w, x, y, z] (its length is " + format_number(q.norm()) +
                    ")");
    }
    return q.normalized();
  }

  bool optional_bool(std::string_view key, bool fallback) {
    if (!has(key)) return fallback;
    const toml::node& node = *table_.get(key);
    if (!node.is_boolean()) {
      fail(key, "expected true or false, found " + std::string(type_name(node)));
    }
    return *node.value<bool>();
  }

  // A whole number in [low, high].
  std::int64_t optional_integer(std::string_view key, std::int64_t fallback, std::int64_t low,
                                std::int64_t high) {
    if (!has(key)) return fallback;
    const toml::node& node = *table_.get(key);
    if (node.is_floating_point()) {
      fail(key, "expected a whole number, found " + format_number(*node.value<double>()));
    }
    if (!node.is_integer()) {
      fail(key, "expected a whole number, found " + std::string(type_name(node)));
    }
    const std::int64_t value = node.as_integer()->get();
    if (value < low || value > high) {
      fail(key, "must be from " + std::to_string(low) + " to " + std::to_string(high) + " (got " +
                    std::to_string(value) + ")");
    }
    return value;
  }

  // An sRGB colour: [r, g, b] with components in [0, 1], or "#rrggbb".
  Vec3 optional_color(std::string_view key, const Vec3& fallback);
  // The colour `node` (at `key`, or an element of it) holds, as optional_color reads it.
  Vec3 color(std::string_view key, const toml::node& node) const;
  // An sRGB colour with a straight opacity: "#rrggbb", "#rrggbbaa", [r, g, b] or [r, g, b, a],
  // components in [0, 1] (opacity 1 when not given).
  Eigen::Vector4d optional_rgba(std::string_view key, const Eigen::Vector4d& fallback);

  // The sub-table at `key`, or null when absent; an error when `key` holds something else.
  const toml::table* optional_table(std::string_view key) {
    if (!has(key)) return nullptr;
    const toml::table* table = table_.get(key)->as_table();
    if (!table) fail(key, "expected a [" + qualified(key) + "] table");
    return table;
  }

  // Reads each table of the array `tables` written at `key` with `read(reader, index)`: at most
  // `limit` of them, each a table (`what` names one for the message: "a [[planes]] table").
  template <typename Read>
  void each_table(const toml::array& tables, std::string_view key, std::size_t limit,
                  std::string_view what, Read read) const {
    if (tables.size() > limit) {
      fail_at(tables[limit].source(), key,
              std::to_string(tables.size()) + " " + std::string(key) + ", more than the limit of " +
                  std::to_string(limit));
    }
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const std::string path = std::string(key) + "[" + std::to_string(i) + "]";
      const toml::table* table = tables[i].as_table();
      if (!table) fail_at(tables[i].source(), path, "expected " + std::string(what));
      TableReader in(*table, path, file_);
      read(in, i);
    }
  }

  const toml::table& table() const { return table_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  // Call after reading every key the schema allows.
  void reject_unknown_keys() const {
    for (auto&& [key, node] : table_) {
      if (known_.count(std::string(key.str()))) continue;
      std::string allowed;
      for (const std::string& k : known_) allowed += (allowed.empty() ? "" : ", ") + k;
      fail_at(key.source(), qualified(key.str()), "unknown key (allowed here: " + allowed + ")");
    }
  }

 private:
  std::string string(std::string_view key, const toml::node& node) const {
    if (!node.is_string()) fail(key, "expected a string, found " + std::string(type_name(node)));
    return *node.value<std::string>();
  }

  const toml::table& table_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> known_;
};

void require_positive(TableReader& reader, std::string_view key, double value);

void require_non_negative(TableReader& reader, std::string_view key, double value);

// Names become folder and file names: keep them to a safe alphabet.
bool is_safe_name(const std::string& name);

// What is_safe_name allows, as a clause for messages.
inline constexpr std::string_view kSafeNameRule =
    "must be 1-100 letters, digits, '_', '-' or '.', not starting with '.'";

// `value` (read from `key`) when its length is at most `bound` (in `unit`), else an error at the
// key: for places and motions the bounds past which a run counts as blown up
// (sim/simulation.hpp), since a start beyond them would stop at step 1; for forces and torques
// the largest double, since their length is used in the physics.
Vec3 vector_within(TableReader& in, std::string_view key, const Vec3& value, double bound,
                   const char* unit);

}  // namespace tumble::scene::detail
