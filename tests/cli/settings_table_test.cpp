// The settings table (common/render_setting_table.hpp) against its three readers: the scene
// reader holds each key to its row's range or names, `tumble render` has each row's option with
// its help and check, and docs/commands.md's option table of `tumble render` lists each row's
// flag and only options the command has. A setting missing from any of them fails here.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "cli/command.hpp"
#include "cli/render_command.hpp"
#include "common/render_setting_table.hpp"
#include "scene/scene_loader.hpp"

namespace {

using tumble::common::kRenderSettings;
using tumble::common::RenderSetting;
using tumble::common::SettingType;

// A scene whose [table] has `key = value` and nothing else.
std::string scene_with(const RenderSetting& setting, const std::string& value) {
  return "duration = 1.0\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n[" +
         std::string(setting.table) + "]\n" + std::string(setting.key) + " = " + value + "\n";
}

// "" when the scene loads, else its error.
std::string load_error(const std::string& text) {
  const tumble::Result<tumble::scene::Scene> loaded = tumble::scene::parse_scene(text, "s.toml");
  return loaded ? "" : loaded.error();
}

std::string quoted(std::string_view name) {
  return "\"" + std::string(name) + "\"";
}

// The values a row allows at its edges, and values just past them.
std::vector<std::string> allowed(const RenderSetting& setting) {
  if (setting.type == SettingType::name) {
    std::vector<std::string> names;
    for (const std::string_view name : setting.names) names.push_back(quoted(name));
    return names;
  }
  return {std::to_string(setting.min), std::to_string(setting.max)};
}
std::vector<std::string> refused(const RenderSetting& setting) {
  if (setting.type == SettingType::name) return {quoted("no-such-name"), quoted("")};
  return {std::to_string(setting.min - 1), std::to_string(setting.max + 1)};
}

TEST(SettingsTable, TheSceneReaderHoldsEachKeyToItsRow) {
  for (const RenderSetting& setting : kRenderSettings) {
    for (const std::string& value : allowed(setting)) {
      EXPECT_EQ(load_error(scene_with(setting, value)), "") << setting.key << " = " << value;
    }
    for (const std::string& value : refused(setting)) {
      const std::string error = load_error(scene_with(setting, value));
      const std::string key = std::string(setting.table) + "." + std::string(setting.key);
      EXPECT_NE(error.find(key), std::string::npos) << key << " = " << value << ": " << error;
    }
  }
}

TEST(SettingsTable, BackendNamesAreTheBackEndsNames) {
  const RenderSetting& backend = tumble::common::render_setting("backend");
  ASSERT_EQ(backend.names.size(), std::size(tumble::common::kAllBackends));
  for (std::size_t i = 0; i < backend.names.size(); ++i) {
    EXPECT_EQ(backend.names[i], tumble::common::backend_name(tumble::common::kAllBackends[i]));
  }
}

// `tumble render` as main builds it.
struct RenderCommandLine {
  CLI::App app{"tumble"};
  tumble::cli::Commands commands;
  CLI::App* render;
  RenderCommandLine() {
    tumble::cli::add_render_command(app, commands);
    render = app.get_subcommand("render");
  }
  // Whether `tumble render s.toml FLAG VALUE` parses.
  bool parses(std::string_view flag, const std::string& value) {
    RenderCommandLine fresh;
    std::vector<std::string> arguments = {value, std::string(flag), "s.toml", "render"};
    try {
      fresh.app.parse(arguments);  // CLI11 takes a vector in reverse order
    } catch (const CLI::ParseError&) {
      return false;
    }
    return true;
  }
};

std::string unquoted(const std::string& value) {
  return value.size() >= 2 && value.front() == '"' ? value.substr(1, value.size() - 2) : value;
}

TEST(SettingsTable, RenderHasEachRowsOptionWithItsHelpAndCheck) {
  RenderCommandLine line;
  for (const RenderSetting& setting : kRenderSettings) {
    const CLI::Option* option = line.render->get_option_no_throw(std::string(setting.flag));
    ASSERT_NE(option, nullptr) << setting.flag;
    EXPECT_EQ(option->get_description(), setting.help) << setting.flag;
    for (const std::string& value : allowed(setting)) {
      EXPECT_TRUE(line.parses(setting.flag, unquoted(value))) << setting.flag << " " << value;
    }
    for (const std::string& value : refused(setting)) {
      EXPECT_FALSE(line.parses(setting.flag, unquoted(value))) << setting.flag << " " << value;
    }
  }
}

// Every --flag in the first column of the option table under "## `tumble render".
std::set<std::string> documented_render_flags() {
  std::ifstream in(std::string(TUMBLE_SOURCE_DIR) + "/docs/commands.md");
  std::string line;
  bool in_section = false, in_table = false;
  std::set<std::string> flags;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) in_section = line.rfind("## `tumble render", 0) == 0;
    if (!in_section) continue;
    if (line.rfind("| option |", 0) == 0) in_table = true;
    if (!in_table) continue;
    if (line.rfind("|", 0) != 0) break;  // the end of the table
    const std::string first_column = line.substr(1, line.find('|', 1) - 1);
    // Each "--name" (a lower-case letter, then letters, digits and dashes), read by hand:
    // <regex> trips GCC 12's -Wmaybe-uninitialized in the sanitizer build.
    for (std::size_t at = first_column.find("--"); at != std::string::npos;
         at = first_column.find("--", at + 2)) {
      std::size_t end = at + 2;
      if (end >= first_column.size() ||
          !std::islower(static_cast<unsigned char>(first_column[end])))
        continue;
      while (end < first_column.size() &&
             (std::islower(static_cast<unsigned char>(first_column[end])) ||
              std::isdigit(static_cast<unsigned char>(first_column[end])) ||
              first_column[end] == '-'))
        ++end;
      flags.insert(first_column.substr(at, end - at));
      at = end - 2;
    }
  }
  return flags;
}

TEST(SettingsTable, DocsCommandsListsEachRowsFlagAndOnlyRendersOptions) {
  const std::set<std::string> documented = documented_render_flags();
  ASSERT_GT(documented.size(), 10u) << "docs/commands.md: no option table for tumble render";
  for (const RenderSetting& setting : kRenderSettings) {
    EXPECT_TRUE(documented.count(std::string(setting.flag)))
        << setting.flag << " is missing from docs/commands.md's table of tumble render";
  }
  RenderCommandLine line;
  for (const std::string& flag : documented) {
    EXPECT_NE(line.render->get_option_no_throw(flag), nullptr)
        << "docs/commands.md documents " << flag << ", which tumble render does not have";
  }
}

}  // namespace
