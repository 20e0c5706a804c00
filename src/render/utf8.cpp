#include "render/utf8.hpp"

#include <cstdint>
#include <cstdio>

namespace tumble::render {
namespace {

std::string hex_byte(std::uint8_t byte) {
  char text[8];
  std::snprintf(text, sizeof(text), "0x%02X", byte);
  return text;
}

std::string code_point_number(char32_t code_point) {
  char text[16];
  std::snprintf(text, sizeof(text), "U+%04X", static_cast<unsigned>(code_point));
  return text;
}

Error invalid_at(std::size_t offset, const std::string& why) {
  return Error{"invalid UTF-8 at byte " + std::to_string(offset) + ": " + why};
}

// The length of the sequence that `lead` starts (1 to 4), or 0 for a byte no sequence starts
// with: a continuation byte (10xxxxxx), 0xC0/0xC1 (always overlong) or 0xF5 and above (past
// U+10FFFF).
int sequence_length(std::uint8_t lead) {
  if (lead < 0x80) return 1;
  if (lead < 0xC2) return 0;
  if (lead < 0xE0) return 2;
  if (lead < 0xF0) return 3;
  if (lead < 0xF5) return 4;
  return 0;
}

// The smallest code point each length may carry: a smaller one is an overlong form (RFC 3629 §3).
constexpr char32_t kShortestForm[5] = {0, 0, 0x80, 0x800, 0x10000};

}  // namespace

Result<std::u32string> decode_utf8(std::string_view text) {
  std::u32string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<std::uint8_t>(text[i]);
    const int length = sequence_length(lead);
    if (length == 0) {
      return invalid_at(i, hex_byte(lead) + (lead >= 0x80 && lead < 0xC0
                                                 ? " is a continuation byte with no lead byte"
                                                 : " cannot start a character"));
    }
    if (length == 1) {
      out.push_back(lead);
      ++i;
      continue;
    }
    char32_t code_point = lead & (0x7F >> length);  // the lead byte's payload bits
    for (int k = 1; k < length; ++k) {
      if (i + k >= text.size()) {
        return invalid_at(i, hex_byte(lead) + " starts a " + std::to_string(length) +
                                 "-byte character cut short by the end of the text");
      }
      const auto next = static_cast<std::uint8_t>(text[i + k]);
      if ((next & 0xC0) != 0x80) {
        return invalid_at(i, hex_byte(lead) + " is not followed by a continuation byte");
      }
      code_point = (code_point << 6) | (next & 0x3F);
    }
    if (code_point < kShortestForm[length]) {
      return invalid_at(i, "overlong encoding of " + code_point_number(code_point));
    }
    if (code_point >= 0xD800 && code_point <= 0xDFFF) {
      return invalid_at(i, "encodes a UTF-16 surrogate");
    }
    if (code_point > 0x10FFFF) return invalid_at(i, "encodes a value past U+10FFFF");
    out.push_back(code_point);
    i += static_cast<std::size_t>(length);
  }
  return out;
}

std::string encode_utf8(char32_t code_point) {
  std::string out;
  const auto byte = [&](char32_t bits) { out.push_back(static_cast<char>(bits)); };
  if (code_point < 0x80) {
    byte(code_point);
  } else if (code_point < 0x800) {
    byte(0xC0 | (code_point >> 6));
    byte(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    byte(0xE0 | (code_point >> 12));
    byte(0x80 | ((code_point >> 6) & 0x3F));
    byte(0x80 | (code_point & 0x3F));
  } else {
    byte(0xF0 | (code_point >> 18));
    byte(0x80 | ((code_point >> 12) & 0x3F));
    byte(0x80 | ((code_point >> 6) & 0x3F));
    byte(0x80 | (code_point & 0x3F));
  }
  return out;
}

std::string describe_character(char32_t code_point) {
  const std::string number = code_point_number(code_point);
  const bool control = code_point < 0x20 || (code_point >= 0x7F && code_point < 0xA0);
  const bool scalar = code_point <= 0x10FFFF && (code_point < 0xD800 || code_point > 0xDFFF);
  if (control || !scalar) return number;
  return number + " '" + encode_utf8(code_point) + "'";
}

}  // namespace tumble::render
