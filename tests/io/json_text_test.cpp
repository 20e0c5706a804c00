// The JSON values tumble writes by hand: strings that stay valid JSON whatever bytes they hold,
// and numbers that read back as the doubles written.
#include "io/json_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace tumble::io {
namespace {

TEST(JsonText, StringsEscapeQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(json_string("a \"b\" \\ c\n\x01"), "\"a \\\"b\\\" \\\\ c\\u000a\\u0001\"");
}

TEST(JsonText, StringsKeepUtf8AndReplaceWhatIsNot) {
  EXPECT_EQ(json_string("m\xc2\xb3"), "\"m\xc2\xb3\"");                 // m³
  EXPECT_EQ(json_string(std::string("a\xff") + "b"), "\"a\\ufffdb\"");  // not UTF-8
  EXPECT_EQ(json_string("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");  // a surrogate
}

TEST(JsonText, NumbersReadBackExactlyAndNonFiniteIsNull) {
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::strtod(json_number(third).c_str(), nullptr), third);
  EXPECT_EQ(json_number(0.5), "0.5");
  EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(json_number(std::nan("")), "null");
}

TEST(JsonText, ArraysOfIntegersAndOfDoubles) {
  EXPECT_EQ(json_array(std::vector<int>{}), "[]");
  EXPECT_EQ(json_array(std::vector<int>{3, -1, 40}), "[3, -1, 40]");
  EXPECT_EQ(json_array(std::vector<double>{0.5, std::nan("")}), "[0.5, null]");
}

}  // namespace
}  // namespace tumble::io
