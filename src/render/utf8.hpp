// UTF-8 text to code points and back, for the text the renderer draws. Free of GL and FreeType.
#pragma once

#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tumble::render {

// The code points of `text`. Invalid UTF-8 (a stray continuation byte, a sequence cut short, an
// overlong form, a surrogate, a value past U+10FFFF) is an error naming the byte offset of the
// sequence's first byte, e.g. "invalid UTF-8 at byte 3: 0xC3 is not followed by a continuation
// byte".
Result<std::u32string> decode_utf8(std::string_view text);

// `code_point` as UTF-8. Precondition: a Unicode scalar value (not a surrogate, <= U+10FFFF).
std::string encode_utf8(char32_t code_point);

// A character as a warning names it: "U+03C9 'ω'", "U+1F600 '😀'"; a control character by its
// number only ("U+000A").
std::string describe_character(char32_t code_point);

}  // namespace tumble::render
