// Reading back the JSON tumble writes (a chunk's report.json, for `tumble join`): a small strict
// reader of RFC 8259 JSON into plain values. Each value keeps the text it was read from, so that
// a part of one file can be written into another exactly as it was.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/result.hpp"

namespace tumble::io {

// An object's member (below): a struct, not a std::pair, which clang with libstdc++ refuses
// to hold while JsonValue is still incomplete.
struct JsonMember;

struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  bool boolean = false;
  double number = 0.0;
  std::string string;  // a string's value, escapes decoded
  std::vector<JsonValue> items;
  std::vector<JsonMember> members;  // in the order written
  std::string text;                 // the JSON text this value was read from

  // The member named `key`, or null when there is none (or this is not an object).
  const JsonValue* find(std::string_view key) const;
};

struct JsonMember {
  std::string key;
  JsonValue value;
};

// The one JSON value `text` holds (with white space around it); an error names the byte offset
// and what was expected there.
Result<JsonValue> parse_json(std::string_view text);

}  // namespace tumble::io
