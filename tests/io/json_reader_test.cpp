// The JSON reader that `tumble join` reads report.json with: values, escapes, the text each value
// came from, and errors with the byte offset.
#include "io/json_reader.hpp"

#include <gtest/gtest.h>

#include "io/json_text.hpp"

namespace tumble::io {
namespace {

TEST(JsonReader, ReadsEveryKindOfValue) {
  const Result<JsonValue> value =
      parse_json(R"( {"a": 1.5, "b": [true, false, null], "c": {"d": "x\"y\u00e9\ud83d\ude00"}} )");
  ASSERT_TRUE(value) << value.error();
  ASSERT_EQ(value->kind, JsonValue::Kind::object);
  EXPECT_EQ(value->find("a")->number, 1.5);
  const JsonValue& b = *value->find("b");
  ASSERT_EQ(b.items.size(), 3u);
  EXPECT_TRUE(b.items[0].boolean);
  EXPECT_EQ(b.items[1].kind, JsonValue::Kind::boolean);
  EXPECT_FALSE(b.items[1].boolean);
  EXPECT_EQ(b.items[2].kind, JsonValue::Kind::null);
  EXPECT_EQ(value->find("c")->find("d")->string, "x\"y\xc3\xa9\xf0\x9f\x98\x80");
  EXPECT_EQ(value->find("missing"), nullptr);
}

// A value keeps its text, so that join copies a chunk's settings into its report as they were.
TEST(JsonReader, EachValueKeepsTheTextItWasReadFrom) {
  const Result<JsonValue> value =
      parse_json(R"({"settings": {"width": 64, "preset": "veryfast"}})");
  ASSERT_TRUE(value) << value.error();
  EXPECT_EQ(value->find("settings")->text, R"({"width": 64, "preset": "veryfast"})");
  EXPECT_EQ(value->find("settings")->find("preset")->text, "\"veryfast\"");
}

// What json_string writes (escapes, U+FFFD for bytes that are not UTF-8) reads back.
TEST(JsonReader, ReadsBackWhatJsonStringWrites) {
  const std::string text = "a\\b\"c\n\td\x01 \xff";
  const Result<JsonValue> value = parse_json(json_string(text));
  ASSERT_TRUE(value) << value.error();
  EXPECT_EQ(value->string, "a\\b\"c\n\td\x01 \xef\xbf\xbd");
}

TEST(JsonReader, RefusesWhatIsNotJsonNamingTheByte) {
  EXPECT_EQ(parse_json(R"({"a": 1,})").error(), "at byte 8: expected a key");
  EXPECT_EQ(parse_json(R"({"a" 1})").error(), "at byte 5: expected ':'");
  EXPECT_EQ(parse_json("[1, 2").error(), "at byte 5: expected ',' or ']'");
  EXPECT_EQ(parse_json(R"({"a": 1 "b": 2})").error(), "at byte 8: expected ',' or '}'");
  EXPECT_EQ(parse_json("\"abc").error(), "at byte 4: expected '\"' to end the string");
  EXPECT_EQ(parse_json("{} x").error(), "at byte 3: expected the end of the text");
  EXPECT_EQ(parse_json("tru").error(), "at byte 0: expected true");
  EXPECT_FALSE(parse_json(std::string(100, '[')));  // nesting is bounded
  EXPECT_FALSE(parse_json(""));
}

}  // namespace
}  // namespace tumble::io
