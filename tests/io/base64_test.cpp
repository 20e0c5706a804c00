// Base64 against RFC 4648's test vectors (section 10), and every byte value against a decoder
// written from the alphabet.
#include "io/base64.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tumble::io {
namespace {

std::string encoded(const std::string& text) {
  const std::vector<std::uint8_t> bytes(text.begin(), text.end());
  return base64(bytes);
}

TEST(Base64, MatchesTheRfcTestVectors) {
  EXPECT_EQ(encoded(""), "");
  EXPECT_EQ(encoded("f"), "Zg==");
  EXPECT_EQ(encoded("fo"), "Zm8=");
  EXPECT_EQ(encoded("foo"), "Zm9v");
  EXPECT_EQ(encoded("foob"), "Zm9vYg==");
  EXPECT_EQ(encoded("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encoded("foobar"), "Zm9vYmFy");
}

TEST(Base64, EveryByteValueDecodesBack) {
  std::vector<std::uint8_t> bytes;
  for (int round = 0; round < 3; ++round) {
    for (int value = 255; value >= 0; --value) bytes.push_back(static_cast<std::uint8_t>(value));
  }
  bytes.push_back(7);  // 769 bytes: the last group one byte long
  const std::string text = base64(bytes);
  ASSERT_EQ(text.size(), 4 * 257u);
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> decoded;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t value = alphabet.find(c);
    ASSERT_NE(value, std::string::npos) << c;
    bits = (bits << 6) | static_cast<std::uint32_t>(value);
    count += 6;
    if (count >= 8) {
      count -= 8;
      decoded.push_back(static_cast<std::uint8_t>(bits >> count));
    }
  }
  EXPECT_EQ(decoded, bytes);
  EXPECT_EQ(text.substr(text.size() - 2), "==");
}

}  // namespace
}  // namespace tumble::io
