#include "io/json_reader.hpp"

#include <charconv>
#include <cstdint>
#include <cstdlib>

namespace tumble::io {
namespace {

// Recursive descent over RFC 8259's grammar; depth is bounded so a hostile file cannot exhaust
// the stack.
class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  Result<JsonValue> document() {
    JsonValue value;
    if (!parse_value(value, 0)) return Error{error_};
    skip_space();
    if (at_ < text_.size()) {
      fail("the end of the text");
      return Error{error_};
    }
    return value;
  }

 private:
  static constexpr int kMaxDepth = 64;

  bool fail(const std::string& expected) {
    if (error_.empty()) {
      error_ = "at byte " + std::to_string(at_) + ": expected " + expected;
    }
    return false;
  }

  void skip_space() {
    while (at_ < text_.size() &&
           (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r')) {
      ++at_;
    }
  }

  bool literal(std::string_view word) {
    if (text_.substr(at_, word.size()) != word) return fail(std::string(word));
    at_ += word.size();
    return true;
  }

  bool parse_value(JsonValue& value, int depth) {
    if (depth > kMaxDepth) return fail("less nesting");
    skip_space();
    const std::size_t start = at_;
    bool ok = false;
    const char next = at_ < text_.size() ? text_[at_] : '\0';
    if (next == '{') {
      ok = parse_object(value, depth);
    } else if (next == '[') {
      ok = parse_array(value, depth);
    } else if (next == '"') {
      value.kind = JsonValue::Kind::string;
      ok = parse_string(value.string);
    } else if (next == 't' || next == 'f') {
      value.kind = JsonValue::Kind::boolean;
      value.boolean = next == 't';
      ok = literal(next == 't' ? "true" : "false");
    } else if (next == 'n') {
      ok = literal("null");
    } else {
      ok = parse_number(value);
    }
    value.text = std::string(text_.substr(start, at_ - start));
    return ok;
  }

  bool parse_object(JsonValue& value, int depth) {
    value.kind = JsonValue::Kind::object;
    return parse_list('}', [&] {
      skip_space();
      std::string key;
      if (at_ >= text_.size() || text_[at_] != '"' || !parse_string(key)) return fail("a key");
      skip_space();
      if (at_ >= text_.size() || text_[at_] != ':') return fail("':'");
      ++at_;
      JsonValue member;
      if (!parse_value(member, depth + 1)) return false;
      value.members.push_back({std::move(key), std::move(member)});
      return true;
    });
  }

  bool parse_array(JsonValue& value, int depth) {
    value.kind = JsonValue::Kind::array;
    return parse_list(']', [&] {
      JsonValue item;
      if (!parse_value(item, depth + 1)) return false;
      value.items.push_back(std::move(item));
      return true;
    });
  }

  // An object's members or an array's items, from its opening bracket (at at_) to `close`: none,
  // or each read by `parse_one` and followed by ',' or `close`.
  template <typename ParseOne>
  bool parse_list(char close, ParseOne parse_one) {
    ++at_;  // '{' or '['
    skip_space();
    if (at_ < text_.size() && text_[at_] == close) {
      ++at_;
      return true;
    }
    for (;;) {
      if (!parse_one()) return false;
      skip_space();
      if (at_ < text_.size() && text_[at_] == ',') {
        ++at_;
      } else if (at_ < text_.size() && text_[at_] == close) {
        ++at_;
        return true;
      } else {
        return fail(std::string("',' or '") + close + "'");
      }
    }
  }

  bool parse_number(JsonValue& value) {
    const std::size_t start = at_;
    if (at_ < text_.size() && text_[at_] == '-') ++at_;
    const std::size_t digits = at_;
    while (at_ < text_.size() &&
           std::string_view("0123456789.eE+-").find(text_[at_]) != std::string_view::npos) {
      ++at_;
    }
    if (at_ == digits || text_[digits] < '0' || text_[digits] > '9') {
      at_ = start;
      return fail("a value");
    }
    const auto [end, error] =
        std::from_chars(text_.data() + start, text_.data() + at_, value.number);
    if (error != std::errc() || end != text_.data() + at_) {
      at_ = start;
      return fail("a number");
    }
    value.kind = JsonValue::Kind::number;
    return true;
  }

  static void append_utf8(std::uint32_t code, std::string& out) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  bool hex4(std::uint32_t& code) {
    if (at_ + 4 > text_.size()) return fail("four hex digits");
    const auto [end, error] = std::from_chars(text_.data() + at_, text_.data() + at_ + 4, code, 16);
    if (error != std::errc() || end != text_.data() + at_ + 4) return fail("four hex digits");
    at_ += 4;
    return true;
  }

  bool parse_string(std::string& out) {
    ++at_;  // '"'
    while (at_ < text_.size() && text_[at_] != '"') {
      const char c = text_[at_++];
      if (static_cast<unsigned char>(c) < 0x20) return fail("no control character");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (at_ >= text_.size()) break;
      const char escape = text_[at_++];
      const std::string_view simple = "\"\\/bfnrt";
      const std::string_view meant = "\"\\/\b\f\n\r\t";
      if (const std::size_t n = simple.find(escape); n != std::string_view::npos) {
        out += meant[n];
      } else if (escape == 'u') {
        std::uint32_t code = 0;
        if (!hex4(code)) return false;
        // A surrogate pair: the high half, then "\uDC00".."\uDFFF".
        if (code >= 0xD800 && code < 0xDC00 && text_.substr(at_, 2) == "\\u") {
          at_ += 2;
          std::uint32_t low = 0;
          if (!hex4(low)) return false;
          code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        }
        append_utf8(code, out);
      } else {
        return fail("an escape");
      }
    }
    if (at_ >= text_.size()) return fail("'\"' to end the string");
    ++at_;
    return true;
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::string error_;
};

}  // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const auto& [name, value] : members) {
    if (name == key) return &value;
  }
  return nullptr;
}

Result<JsonValue> parse_json(std::string_view text) {
  return Parser(text).document();
}

}  // namespace tumble::io
