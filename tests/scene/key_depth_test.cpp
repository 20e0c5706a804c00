#include "scene/key_depth.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tumble::scene::detail {
namespace {

// The texts joined (by append: GCC 12 warns wrongly on "literal" + std::string here).
template <typename... Texts>
std::string cat(const Texts&... texts) {
  std::string joined;
  (joined.append(texts), ...);
  return joined;
}

// "a.a.a…" of `parts` parts, joined by `dot`.
std::string chain(int parts, const std::string& dot = ".", const std::string& part = "a") {
  std::string text = part;
  for (int i = 1; i < parts; ++i) text.append(dot).append(part);
  return text;
}

TEST(KeyDepth, AKeyOfTheLimitPassesAndOneMorePartIsFoundWhereItStarts) {
  EXPECT_FALSE(find_overlong_dotted_key(cat("[", chain(32), "]\n")));
  const auto found = find_overlong_dotted_key(cat("x = 1\n\n  [", chain(33), "]\n"));
  ASSERT_TRUE(found);
  EXPECT_EQ(found->line, 3);
  EXPECT_EQ(found->column, 4);
}

TEST(KeyDepth, QuotedPartsAndSpacesAroundDotsStillCount) {
  EXPECT_TRUE(find_overlong_dotted_key(cat(chain(33, " . ", "\"a\""), " = 1\n")));
  EXPECT_TRUE(find_overlong_dotted_key(cat(chain(33, ".", "'a b'"), " = 1\n")));
}

// Dots that are not key separators: in strings of each kind, in comments, in numbers.
TEST(KeyDepth, DotsInStringsCommentsAndNumbersAreNotParts) {
  const std::string dots = chain(100);
  EXPECT_FALSE(find_overlong_dotted_key(cat("name = \"", dots, "\"\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat("name = '", dots, "'\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat("name = \"\"\"\n", dots, "\n\"\"\"\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat("name = '''", dots, "'''\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat("name = \"a \\\" ", dots, "\"\n")));  // \" inside
  EXPECT_FALSE(find_overlong_dotted_key(cat("# ", dots, "\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat("size = [", chain(100, ", ", "1.5"), "]\n")));
}

// TOML lets one or two quotes stand just before a multi-line string's closing three. Read as
// the end of the string, the extra quote opened another one in the scanner's eyes, which hid
// the key on the next line from it, but not from the parser.
TEST(KeyDepth, QuotesBeforeAMultiLineStringsCloseDoNotHideTheNextKey) {
  const std::string deep = cat("[", chain(40), "]\n");
  for (const std::string& first_line :
       {std::string("x = { s = '''a'''', t = '''b''' }\n"),
        std::string("x = ['''a''''', '''b''']\n"),
        std::string("x = \"\"\"a\"\"\"\"\nx = \"\"\"b\"\"\"\n"), std::string("x = \"\"\"\"\"\"\n"),
        std::string("x = ''''''\n")}) {
    const auto found = find_overlong_dotted_key(cat(first_line, deep));
    ASSERT_TRUE(found) << first_line;
    EXPECT_EQ(found->column, 2) << first_line;
  }
}

TEST(KeyDepth, AChainEndsAtAnythingButADotOrSpace) {
  // 20 parts, "=", 20 parts: two chains of 20, not one of 40.
  EXPECT_FALSE(find_overlong_dotted_key(cat(chain(20), " = ", chain(20), "\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat(chain(20), "\n", chain(20), "\n")));
  EXPECT_FALSE(find_overlong_dotted_key(cat(chain(20), "..", chain(20), "\n")));
}

}  // namespace
}  // namespace tumble::scene::detail
