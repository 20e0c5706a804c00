#include "render/utf8.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tumble::render {
namespace {

TEST(Utf8, DecodesOneToFourByteCharacters) {
  const Result<std::u32string> decoded =
      decode_utf8("a\xCF\x89\xC2\xB2\xE2\x86\x92\xF0\x9F\x98\x80");
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(*decoded, (std::u32string{U'a', 0x3C9, 0xB2, 0x2192, 0x1F600}));  // a ω ² → 😀
}

TEST(Utf8, EmptyTextIsNoCharacters) {
  const Result<std::u32string> decoded = decode_utf8("");
  ASSERT_TRUE(decoded);
  EXPECT_TRUE(decoded->empty());
}

TEST(Utf8, EncodingThenDecodingGivesTheCharactersBack) {
  const std::u32string characters = {0x0,    0x7F,   0x80,   0x7FF,   0x800,   0xD7FF,
                                     0xE000, 0xFFFD, 0xFFFF, 0x10000, 0x10FFFF};
  std::string text;
  for (const char32_t c : characters) text += encode_utf8(c);
  const Result<std::u32string> decoded = decode_utf8(text);
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(*decoded, characters);
  EXPECT_EQ(encode_utf8(0x3C9), "\xCF\x89");  // ω
  EXPECT_EQ(encode_utf8(0x1F600), "\xF0\x9F\x98\x80");
}

// Each kind of invalid UTF-8 is an error naming the byte offset where its sequence starts.
struct BadText {
  std::string text;
  std::string expected;  // in the message
};

TEST(Utf8, InvalidTextIsAnErrorNamingTheByteOffset) {
  const BadText cases[] = {
      {"ab\x80", "invalid UTF-8 at byte 2: 0x80 is a continuation byte with no lead byte"},
      {"x = \xC3", "invalid UTF-8 at byte 4: 0xC3 starts a 2-byte character cut short"},
      {"\xE2\x86", "invalid UTF-8 at byte 0: 0xE2 starts a 3-byte character cut short"},
      {"ok \xC3(", "invalid UTF-8 at byte 3: 0xC3 is not followed by a continuation byte"},
      {"\xC0\xAF", "invalid UTF-8 at byte 0: 0xC0 cannot start a character"},
      {"1\xE0\x80\xAF", "invalid UTF-8 at byte 1: overlong encoding of U+002F"},
      {"\xF0\x82\x82\xAC", "invalid UTF-8 at byte 0: overlong encoding of U+20AC"},
      {"ab\xED\xA0\x80", "invalid UTF-8 at byte 2: encodes a UTF-16 surrogate"},
      {"\xF4\x90\x80\x80", "invalid UTF-8 at byte 0: encodes a value past U+10FFFF"},
      {"\xF5\x80\x80\x80", "invalid UTF-8 at byte 0: 0xF5 cannot start a character"},
      {"\xCF\x89\xFF", "invalid UTF-8 at byte 2: 0xFF cannot start a character"},
  };
  for (const BadText& bad : cases) {
    const Result<std::u32string> decoded = decode_utf8(bad.text);
    ASSERT_FALSE(decoded) << bad.expected;
    EXPECT_NE(decoded.error().find(bad.expected), std::string::npos) << decoded.error();
  }
}

TEST(Utf8, DescribeCharacterGivesTheNumberAndTheCharacter) {
  EXPECT_EQ(describe_character(0x1F600), "U+1F600 '\xF0\x9F\x98\x80'");
  EXPECT_EQ(describe_character(0x3C9), "U+03C9 '\xCF\x89'");
  EXPECT_EQ(describe_character(U'\n'), "U+000A");  // no control character in the message
  EXPECT_EQ(describe_character(0x85), "U+0085");
}

}  // namespace
}  // namespace tumble::render
