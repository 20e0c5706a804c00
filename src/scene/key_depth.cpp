#include "scene/key_depth.hpp"

namespace tumble::scene::detail {
namespace {

bool is_bare_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

// Scans `text` one byte at a time, counting the parts of the dotted chain being read.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::optional<TextPosition> find(int max_parts) {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == ' ' || c == '\t') {
        advance(1);  // TOML allows white space around the dots of a key
      } else if (c == '.') {
        dot_pending_ = parts_ > 0 && !dot_pending_;
        if (!dot_pending_) parts_ = 0;
        advance(1);
      } else if (c == '"' || c == '\'' || is_bare_key_char(c)) {
        const TextPosition start = position_;
        if (c == '"' || c == '\'') {
          skip_string(c);
        } else {
          while (at_ < text_.size() && is_bare_key_char(text_[at_])) advance(1);
        }
        if (dot_pending_) {
          ++parts_;
        } else {
          parts_ = 1;
          chain_start_ = start;
        }
        dot_pending_ = false;
        if (parts_ > max_parts) return chain_start_;
      } else {
        if (c == '#') {
          while (at_ < text_.size() && text_[at_] != '\n') advance(1);
        } else {
          advance(1);
        }
        parts_ = 0;
        dot_pending_ = false;
      }
    }
    return std::nullopt;
  }

 private:
  void advance(std::size_t count) {
    for (std::size_t i = 0; i < count && at_ < text_.size(); ++i, ++at_) {
      if (text_[at_] == '\n') {
        ++position_.line;
        position_.column = 1;
      } else {
        ++position_.column;
      }
    }
  }

  bool starts_with(std::string_view prefix) const {
    return text_.substr(at_, prefix.size()) == prefix;
  }

  // From an opening quote past the closing one (or the end of the text, if unclosed): basic
  // strings "…" and """…""" with backslash escapes, literal strings '…' and '''…''' without.
  // This must end each string where the TOML parser does, or a key after it could go unseen.
  void skip_string(char quote) {
    const std::string_view triple = quote == '"' ? "\"\"\"" : "'''";
    const bool multi_line = starts_with(triple);
    advance(multi_line ? 3 : 1);
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\\' && quote == '"') {
        advance(2);
      } else if (multi_line && starts_with(triple)) {
        // Up to two more quotes before the closing three belong to the string (TOML 1.0):
        // the string ends after the whole run of quotes.
        while (at_ < text_.size() && text_[at_] == quote) advance(1);
        return;
      } else if (!multi_line && c == quote) {
        advance(1);
        return;
      } else if (c == '\n' && !multi_line) {
        return;  // an unterminated string: the parser reports it
      } else {
        advance(1);
      }
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
  TextPosition position_;
  TextPosition chain_start_;
  int parts_ = 0;             // parts of the chain being read
  bool dot_pending_ = false;  // a dot follows the last part: the chain may go on
};

}  // namespace

std::optional<TextPosition> find_overlong_dotted_key(std::string_view text, int max_parts) {
  return Scanner(text).find(max_parts);
}

}  // namespace tumble::scene::detail
