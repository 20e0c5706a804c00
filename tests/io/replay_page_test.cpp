// The html replay page put together from its parts: each marker replaced once, in place, the
// data kept from ending its element, the GLB as base64, and markup or scripts that would break
// the page refused with the reason.
#include "io/replay_page.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tumble::io {
namespace {

// "" for a page, else the error.
std::string error_text(const Result<std::string>& page) {
  return page ? std::string() : page.error();
}

const std::string kMarkup =
    "<body>\n<!-- tumble: data -->\n<!-- tumble: three.js -->\n<!-- tumble: replay.js -->\n"
    "</body>\n";

TEST(ReplayPage, PutsEachPartInPlaceOfItsMarker) {
  const std::vector<std::uint8_t> glb = {'g', 'l', 'T', 'F'};
  const Result<std::string> page = replay_page({.markup = kMarkup,
                                                .three_js = "var TumbleThree = {};",
                                                .replay_js = "go();",
                                                .data_json = "{\"name\": \"a\"}",
                                                .glb = glb});
  ASSERT_TRUE(page) << page.error();
  EXPECT_EQ(*page,
            "<body>\n"
            "<script type=\"application/json\" id=\"tumble-replay-data\">{\"name\": \"a\"}"
            "</script>\n"
            "<script type=\"application/octet-stream\" id=\"tumble-replay-glb\">Z2xURg==</script>\n"
            "<script>\nvar TumbleThree = {};\n</script>\n"
            "<script>\ngo();\n</script>\n"
            "</body>\n");
}

TEST(ReplayPage, DataCannotEndItsElement) {
  const Result<std::string> page =
      replay_page({.markup = kMarkup,
                   .three_js = "",
                   .replay_js = "",
                   .data_json = "{\"name\": \"</script><script>alert(1)</script>\"}",
                   .glb = {}});
  ASSERT_TRUE(page) << page.error();
  EXPECT_NE(page->find("{\"name\": \"\\u003c/script>\\u003cscript>alert(1)\\u003c/script>\"}"),
            std::string::npos)
      << *page;
  EXPECT_EQ(page->find("<script>alert"), std::string::npos);
}

TEST(ReplayPage, MarkerTextInsideAPartIsLeftAlone) {
  const Result<std::string> page = replay_page({.markup = kMarkup,
                                                .three_js = "// <!-- tumble: replay.js -->",
                                                .replay_js = "go();",
                                                .data_json = "{}",
                                                .glb = {}});
  ASSERT_TRUE(page) << page.error();
  EXPECT_NE(page->find("<script>\n// <!-- tumble: replay.js -->\n</script>\n<script>\ngo();"),
            std::string::npos)
      << *page;
}

TEST(ReplayPage, RefusesMissingOrRepeatedMarkersAndScriptsThatEndTheirElement) {
  EXPECT_EQ(error_text(replay_page({.markup = "<!-- tumble: data --><!-- tumble: replay.js -->",
                                    .three_js = "",
                                    .replay_js = "",
                                    .data_json = "{}",
                                    .glb = {}})),
            "the replay page's markup (web/replay.html) has no <!-- tumble: three.js -->");
  EXPECT_EQ(error_text(replay_page({.markup = kMarkup + "<!-- tumble: data -->",
                                    .three_js = "",
                                    .replay_js = "",
                                    .data_json = "{}",
                                    .glb = {}})),
            "the replay page's markup (web/replay.html) has <!-- tumble: data --> twice");
  EXPECT_EQ(error_text(replay_page({.markup = kMarkup,
                                    .three_js = "s = '</SCRIPT>';",
                                    .replay_js = "",
                                    .data_json = "{}",
                                    .glb = {}})),
            "the replay page's three.js holds \"</script\", which would end its <script> element");
}

}  // namespace
}  // namespace tumble::io
