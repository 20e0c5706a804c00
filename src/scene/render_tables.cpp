#include "scene/render_tables.hpp"

#include <algorithm>
#include <array>

#include "common/render_setting_table.hpp"
#include "scene/camera_keys.hpp"
#include "scene/limits.hpp"
#include "scene/output_tables.hpp"
#include "scene/video_rules.hpp"

namespace tumble::scene::detail {
namespace {

constexpr std::array<std::string_view, 10> kPresets = {
    "ultrafast", "superfast", "veryfast", "faster",   "fast",
    "medium",    "slow",      "slower",   "veryslow", "placebo"};

// A [render] key of the settings table (common/render_setting_table.hpp), held to its row.
int setting_integer(TableReader& in, const common::RenderSetting& setting, int fallback) {
  return static_cast<int>(in.optional_integer(setting.key, fallback, setting.min, setting.max));
}

// motion_blur = { samples = S, shutter = F }: S from 2 to 64 pictures a frame, F in (0, 1] of
// the frame's interval (default 0.5, a 180° shutter).
common::MotionBlur read_motion_blur(TableReader& in) {
  const toml::table* table = in.table().get("motion_blur")->as_table();
  if (!table) in.fail("motion_blur", "expected a table { samples = 8, shutter = 0.5 }");
  TableReader blur(*table, in.qualified("motion_blur"), in.file());
  common::MotionBlur out;
  blur.required("samples");  // no default: the cost is the user's to choose
  out.samples =
      static_cast<int>(blur.optional_integer("samples", 2, 2, common::kMaxMotionBlurSamples));
  out.shutter = blur.optional_number("shutter", out.shutter);
  if (!(out.shutter > 0.0 && out.shutter <= 1.0)) {
    blur.fail("shutter", "must be more than 0 and at most 1 (of a frame's interval; got " +
                             format_number(out.shutter) + ")");
  }
  blur.reject_unknown_keys();
  return out;
}

// A number of [render] from `low` to `high` (inclusive), or the fallback.
double number_within(TableReader& in, std::string_view key, double fallback, double low,
                     double high, std::string_view unit) {
  const double value = in.optional_number(key, fallback);
  if (!(value >= low && value <= high)) {
    in.fail(key, "must be from " + format_number(low) + " to " + format_number(high) +
                     std::string(unit) + " (got " + format_number(value) + ")");
  }
  return value;
}

// shadow_softness, ambient_occlusion, fill_light, exposure: how the light falls
// (common::Look).
common::Look read_look(TableReader& in) {
  common::Look look;
  look.shadow_softness = number_within(in, "shadow_softness", look.shadow_softness, 0.0,
                                       common::kMaxShadowSoftness, " degrees");
  look.ambient_occlusion =
      number_within(in, "ambient_occlusion", look.ambient_occlusion, 0.0, 1.0, "");
  look.fill_light = number_within(in, "fill_light", look.fill_light, 0.0, 1.0, "");
  if (in.has("exposure")) {
    const toml::node& node = *in.table().get("exposure");
    if (node.is_string()) {
      if (node.as_string()->get() != "auto") {
        in.fail("exposure",
                "expected \"auto\" or a number, found " + in_quotes(node.as_string()->get()));
      }
    } else {
      look.exposure = in.number("exposure", node);
      if (!(look.exposure > 0.0 && look.exposure <= 100.0)) {
        in.fail("exposure", "must be more than 0 and at most 100 (got " +
                                format_number(look.exposure) + "), or \"auto\"");
      }
    }
  }
  return look;
}

void read_render(TableReader& in, Scene& scene) {
  common::RenderSettings& r = scene.render;
  r.width = setting_integer(in, common::render_setting("width"), r.width);
  r.height = setting_integer(in, common::render_setting("height"), r.height);
  scene.fps = setting_integer(in, common::render_setting("fps"), scene.fps);
  r.msaa = static_cast<int>(in.optional_integer("msaa", r.msaa, 1, 16));
  if (r.msaa & (r.msaa - 1)) {
    in.fail("msaa",
            "must be 1, 2, 4, 8 or 16 samples per pixel (got " + std::to_string(r.msaa) + ")");
  }
  read_background(in, r);
  r.shadows = in.optional_bool("shadows", r.shadows);
  r.look = read_look(in);
  constexpr const common::RenderSetting& backend_setting = common::render_setting("backend");
  const std::string backend =
      in.optional_string(backend_setting.key, common::backend_name(r.backend));
  const auto named =
      std::find_if(std::begin(common::kAllBackends), std::end(common::kAllBackends),
                   [&](common::Backend each) { return backend == backend_name(each); });
  if (named == std::end(common::kAllBackends)) {
    in.fail("backend",
            "unknown off-screen OpenGL " + in_quotes(backend) + " (auto, osmesa or egl)");
  }
  r.backend = *named;
  r.egl_device = setting_integer(in, common::render_setting("egl_device"), r.egl_device);
  if (in.has("egl_device") && r.backend == common::Backend::osmesa) {
    in.fail("egl_device",
            "names an EGL device, but backend is \"osmesa\" (use \"egl\" or \"auto\")");
  }
  scene.font = in.optional_string("font", scene.font);
  if (in.has("font") && scene.font.empty()) in.fail("font", "expected a fontconfig family name");
  if (in.has("motion_blur")) r.motion_blur = read_motion_blur(in);
  in.reject_unknown_keys();
}

void read_camera(TableReader& in, Scene& scene) {
  CameraSpec& c = scene.camera;
  if (in.has("position")) c.position = in.required_vector("position");
  if (in.has("look_at")) c.look_at = in.required_vector("look_at");
  c.up = in.optional_vector("up", c.up);
  if (c.up.norm() == 0.0) in.fail("up", "must not be the zero vector");
  c.fov_degrees = in.optional_number("fov_degrees", c.fov_degrees);
  if (!(c.fov_degrees > 1.0 && c.fov_degrees < 170.0)) {
    in.fail("fov_degrees", "must be more than 1 and less than 170 degrees (got " +
                               format_number(c.fov_degrees) + ")");
  }
  c.follow = in.optional_string("follow", "");
  if (!c.follow.empty() &&
      std::none_of(scene.bodies.begin(), scene.bodies.end(),
                   [&](const BodySpec& body) { return body.name == c.follow; })) {
    in.fail("follow", "no body is named " + in_quotes(c.follow));
  }
  if (c.position && c.look_at && (*c.position - *c.look_at).norm() == 0.0) {
    in.fail("look_at", "the camera cannot look at its own position");
  }
  read_camera_moves(in, scene);
  in.reject_unknown_keys();
}

void read_light(TableReader& in, Scene& scene) {
  common::DirectionalLight& l = scene.render.light;
  l.direction = in.optional_vector("direction", l.direction);
  if (l.direction.norm() == 0.0) in.fail("direction", "must not be the zero vector");
  l.color = in.optional_color("color", l.color);
  l.ambient = in.optional_number("ambient", l.ambient);
  if (l.ambient < 0.0 || l.ambient > 1.0) {
    in.fail("ambient", "must be from 0 to 1 (got " + format_number(l.ambient) + ")");
  }
  in.reject_unknown_keys();
}

void read_ground(TableReader& in, Scene& scene) {
  common::Ground& g = scene.render.ground;
  // With planes the drawn floor is a plane (app/plane_view.hpp): one home for where it is and
  // whether it shows, so [ground] keeps only its look.
  for (const char* key : {"enabled", "height"}) {
    if (!scene.planes.empty() && in.has(key)) {
      in.fail(key,
              "not used in a scene with [[planes]]: the floor drawn is the lowest level plane, "
              "placed by its point and shown or hidden by its visible");
    }
  }
  g.enabled = in.optional_bool("enabled", g.enabled);
  if (in.has("height")) scene.ground_height = in.required_number("height");
  g.color = in.optional_color("color", g.color);
  g.grid_spacing = in.optional_number("grid_spacing", g.grid_spacing);
  require_non_negative(in, "grid_spacing", g.grid_spacing);
  in.reject_unknown_keys();
}

void read_output(TableReader& in, Scene& scene) {
  OutputSpec& o = scene.output;
  o.directory = in.optional_string("directory", o.directory);
  // The scene chooses a folder below the output root, never a place elsewhere, nor the output
  // folder itself (the scene's folder is replaced as a whole by each render): every part a safe
  // name, so no "..", ".", "/" at the start, empty part, NUL or control character.
  bool safe = true;
  for (std::size_t start = 0; safe && start <= o.directory.size();) {
    const std::size_t slash = std::min(o.directory.find('/', start), o.directory.size());
    safe = is_safe_name(o.directory.substr(start, slash - start));
    start = slash + 1;
  }
  if (!safe) {
    in.fail("directory",
            "must be a relative folder inside the output folder: parts separated by '/', each "
            "1-100 letters, digits, '_', '-' or '.', not starting with '.' (so no \"..\")");
  }
  o.frames = in.optional_bool("frames", o.frames);
  o.video = in.optional_bool("video", o.video);
  o.crf = static_cast<int>(in.optional_integer("crf", o.crf, 0, 51));
  o.webm_crf = static_cast<int>(in.optional_integer("webm_crf", o.webm_crf, 0, 63));
  o.preset = in.optional_string("preset", o.preset);
  if (std::find(kPresets.begin(), kPresets.end(), o.preset) == kPresets.end()) {
    in.fail("preset", "unknown x264 preset " + in_quotes(o.preset) +
                          " (ultrafast, superfast, veryfast, faster, fast, medium, slow, "
                          "slower, veryslow, placebo)");
  }
  read_output_choices(in, o);
  in.reject_unknown_keys();
}

}  // namespace

void read_render_tables(TableReader& root, Scene& scene) {
  scene.output.directory = scene.name;
  const auto read = [&](std::string_view key, void (*reader)(TableReader&, Scene&)) {
    if (const toml::table* table = root.optional_table(key)) {
      TableReader in(*table, std::string(key), root.file());
      reader(in, scene);
    }
  };
  read("render", read_render);
  read("camera", read_camera);
  read("light", read_light);
  read("ground", read_ground);
  read("output", read_output);

  // The scene describes a video: what no render of it could write is refused here, at the first
  // of the rule's keys the file has, else at its top-level key.
  const std::optional<BrokenRule> broken = broken_video_rule(scene);
  if (!broken) return;
  for (const std::string& key : broken->keys) {
    const std::size_t dot = key.find('.');
    const std::string table = key.substr(0, dot);
    const toml::table* in = root.table().get_as<toml::table>(table);
    if (in && in->contains(key.substr(dot + 1))) {
      TableReader(*in, table, root.file()).fail(key.substr(dot + 1), broken->problem);
    }
  }
  root.fail(broken->fallback, broken->problem);
}

}  // namespace tumble::scene::detail
