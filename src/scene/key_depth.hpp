// A guard run before the TOML parser: toml++ limits the nesting of inline arrays and tables
// (256) but not of dotted keys and table headers, and recurses once per part, so a key such as
// [a.a.a.…] of 40 000 parts (an 80 kB file) overflows the stack. Scene keys have at most three
// parts (bodies.forces.kind); anything far longer is refused before parsing.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace tumble::scene::detail {

inline constexpr int kMaxKeyParts = 32;

// Where a key starts (1-based line and column, in bytes).
struct TextPosition {
  std::int64_t line = 1;
  std::int64_t column = 1;
};

// The start of the first dotted key with more than `max_parts` parts, if any. A lexical scan:
// comments and the insides of strings are skipped, a quoted part counts as one part, and a
// number such as 1.5 reads as two parts, which no limit near kMaxKeyParts confuses with a key.
std::optional<TextPosition> find_overlong_dotted_key(std::string_view text,
                                                     int max_parts = kMaxKeyParts);

}  // namespace tumble::scene::detail
