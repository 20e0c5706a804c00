// The render settings a command line may override, declared once: the scene key each is read
// from, its type and range, the `tumble render` option that replaces it and that option's help.
// The scene reader (scene/render_tables.cpp) checks each key against its row, the command line
// (cli/render_command.cpp) makes each option from its row, and tests/cli/settings_table_test.cpp
// holds the table, the options and docs/commands.md's option table to each other. Adding a
// setting is a row here and its uses (docs/design.md, "Adding a render setting").
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>

#include "common/render_settings.hpp"

namespace tumble::common {

enum class SettingType {
  integer,  // a whole number from min to max
  name,     // one of names
};

struct RenderSetting {
  std::string_view table;  // the scene's table: [render]
  std::string_view key;    // the key in it, also the setting's name
  std::string_view flag;   // tumble render's option that replaces it
  SettingType type;
  std::int64_t min = 0, max = 0;                 // integer: the range, both ends allowed
  std::span<const std::string_view> names = {};  // name: every value allowed
  std::string_view help;                         // the option's help text
};

inline constexpr std::string_view kBackendNames[] = {"auto", "osmesa", "egl"};  // backend_name

inline constexpr RenderSetting kRenderSettings[] = {
    {.table = "render",
     .key = "width",
     .flag = "--width",
     .type = SettingType::integer,
     .min = 16,
     .max = 8192,
     .help = "Image width (pixels)"},
    {.table = "render",
     .key = "height",
     .flag = "--height",
     .type = SettingType::integer,
     .min = 16,
     .max = 8192,
     .help = "Image height (pixels)"},
    {.table = "render",
     .key = "fps",
     .flag = "--fps",
     .type = SettingType::integer,
     .min = 1,
     .max = 240,
     .help = "Frames per second"},
    {.table = "render",
     .key = "backend",
     .flag = "--backend",
     .type = SettingType::name,
     .names = kBackendNames,
     .help = "Off-screen OpenGL: osmesa, egl (a GPU's EGL device, else surfaceless) or auto (EGL "
             "on a GPU, else OSMesa if built in); replaces the scene's [render] backend"},
    {.table = "render",
     .key = "egl_device",
     .flag = "--egl-device",
     .type = SettingType::integer,
     .min = 0,
     .max = kMaxEglDevice,
     .help = "Draw with EGL on device N of EGL's list (EGL_EXT_platform_device; a wrong N "
             "lists them); replaces the scene's [render] egl_device"},
};

// The row of `key`, found while compiling: a key not in the table does not compile.
consteval const RenderSetting& render_setting(std::string_view key) {
  for (const RenderSetting& setting : kRenderSettings) {
    if (setting.key == key) return setting;
  }
  throw std::logic_error("not in kRenderSettings");
}

}  // namespace tumble::common
