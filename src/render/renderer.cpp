#include "render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

#include "render/box_batch.hpp"
#include "render/edge_filter.hpp"
#include "render/framebuffer.hpp"
#include "render/geometry.hpp"
#include "render/gl.hpp"
#include "render/ground_cache.hpp"
#include "render/occluders.hpp"
#include "render/occlusion_layer.hpp"
#include "render/offscreen_context.hpp"
#include "render/overlay_geometry.hpp"
#include "render/overlay_layer.hpp"
#include "render/screen_bounds.hpp"
#include "render/shader_program.hpp"
#include "render/sketch_layer.hpp"
#include "render/straight_alpha.hpp"
#include "render/text_layer.hpp"
#include "render/view_extent.hpp"

namespace tumble::render {
namespace {

using Mat4f = Eigen::Matrix4f;
using Mat3 = Eigen::Matrix3d;

constexpr int kShadowMapSize = 1024;  // texels per side
// The widest soft penumbra's radius, in shadow-map texels (lighting.glsl's kMaxFilterTexels).
constexpr double kMaxPenumbraTexels = 12.0;
// A quad seen from its back (from inside the solid, between the camera and the boxes): enough
// to show where the wall is, little enough to show the boxes behind it clearly.
constexpr float kBackSideOpacity = 0.3f;
// How far beyond the boxes' sphere (a multiple of its radius) the shadow map may grow to hold
// the quads' shadows: each doubling halves the sharpness of the boxes' shadows.
constexpr double kQuadShadowReach = 16.0;

void set_matrix(GLint location, const Mat4& m) {
  const Mat4f f = m.cast<float>();
  glUniformMatrix4fv(location, 1, GL_FALSE, f.data());  // Eigen is column-major, as GL wants
}

void set_vector(GLint location, const Eigen::Vector3f& v) {
  glUniform3fv(location, 1, v.data());
}

// The screen rectangle (x, y, width, height in pixels, GL's bottom-up rows) that holds the
// shadows of all boxes and quads on the ground: each corner projected along the light onto the
// ground plane, then onto the screen, widened by `penumbra` (m, soft shadows' widest) where it
// is nearest the camera. Nothing when no shadow can fall on the ground in view.
std::optional<PixelRect> shadow_region(const FrameView& view, const std::vector<Box>& boxes,
                                       const RenderSettings& settings, const Mat4& view_projection,
                                       const Vec3& light_direction, double penumbra) {
  if (light_direction.y() > -1e-3) return std::nullopt;  // light from below or level: none
  ScreenBounds bounds(view_projection);
  // Takes in one corner's shadow; false when it falls behind the camera.
  const auto take_in = [&](Vec3 point) {
    // Along the light to the ground (a corner below the ground casts nothing above it).
    point += light_direction * ((settings.ground.height - point.y()) / light_direction.y());
    return bounds.take_in(point);
  };
  const PixelRect whole = {0, 0, settings.width, settings.height};
  for (const Box& box : boxes) {
    const Mat3 rotation = box.orientation.normalized().toRotationMatrix();
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 local(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5, corner & 4 ? 0.5 : -0.5);
      if (!take_in(box.position + rotation * local.cwiseProduct(box.size))) return whole;
    }
  }
  // Quads cast shadows too (a ramp shades the floor beneath it, and the boxes' shadows there).
  for (const Quad& quad : view.quads) {
    if (seen_from_back(quad, view.camera.position)) continue;
    for (const Vec3& point : corners(quad)) {
      if (!take_in(point)) return whole;
    }
  }
  // Widened by two for the filter's reach, and by the penumbra.
  const double margin = penumbra > 0.0 ? bounds.pixels_of(penumbra, settings.height) : 0.0;
  return bounds.pixels(settings.width, settings.height, 2 + static_cast<int>(std::ceil(margin)));
}

// A vertex array of one attribute (location 0) of `components` floats a vertex, from `bytes`
// bytes of `vertices`, left bound; its names go to `vao` and `vbo`.
void vertex_array(const float* vertices, std::size_t bytes, int components, GLuint& vao,
                  GLuint& vbo) {
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), vertices, GL_STATIC_DRAW);
  glVertexAttribPointer(0, components, GL_FLOAT, GL_FALSE,
                        static_cast<GLsizei>(components * sizeof(float)), nullptr);
  glEnableVertexAttribArray(0);
}

}  // namespace

// What the passes of one frame share.
struct FrameSetup {
  Mat4 view_projection;
  Mat4 light_view_projection;
  Vec3 light_direction;        // the way the key light travels, world frame, unit
  Vec3 light_right, light_up;  // the shadow map's x and y axes, world frame, unit
  ViewExtent extent;           // the boxes' sphere, near and far, the ground's square
  double shadow_radius;        // of the sphere the shadow map covers: extent's radius, or more (m)
};

struct Renderer::Resources {
  RenderSettings settings;
  std::unique_ptr<OffscreenContext> context;
  ShaderProgram body_program;
  // With ambient occlusion: body.frag receiving the occlusion of the bodies beside a box, drawn
  // for the boxes that have any (BoxBatch::draw_part); likewise each RoundSolid's.
  ShaderProgram body_occluded_program;
  ShaderProgram ground_program;
  ShaderProgram shadowed_ground_program;  // the same, receiving shadows (and occlusion)
  ShaderProgram shadow_program;           // quads
  ShaderProgram box_shadow_program;       // boxes, instanced
  ShaderProgram plane_program;            // quads
  BoxBatch boxes;                         // every box of the frame, one instanced draw per pass
  // With settings.round_solids: each round solid's program, shadow program and batch.
  struct RoundSolid {
    ShaderProgram program, occluded_program, shadow_program;
    BoxBatch batch;
  };
  std::vector<RoundSolid> rounds;
  Framebuffer target;                     // what a frame is drawn into
  Framebuffer resolved;                   // one sample per pixel of a multisampled target
  std::vector<std::uint8_t> rgba;         // the frame read back: RGBA, top row first
  GroundCache ground;                     // the ground without shadows, while the camera stays
  OcclusionLayer occlusion;               // with ambient occlusion on the ground
  std::unique_ptr<TextLayer> text;        // when the settings name a font
  std::unique_ptr<OverlayLayer> overlay;  // when the settings ask for overlays
  GLuint ground_vao = 0, ground_vbo = 0;
  GLuint quad_vao = 0, quad_vbo = 0;
  GLuint shadow_fbo = 0, shadow_texture = 0;
  GLuint depth_sampler = 0;  // the shadow map read as depths (no comparison), for soft shadows
  // With ambient occlusion: every body's shape, for the solids beside it (occluders.hpp).
  GLuint occluder_texture = 0;

  ~Resources() {
    if (!context) return;
    context->use();  // the names below are this context's
    glDeleteVertexArrays(1, &ground_vao);
    glDeleteVertexArrays(1, &quad_vao);
    const GLuint buffers[] = {ground_vbo, quad_vbo};
    glDeleteBuffers(2, buffers);
    glDeleteFramebuffers(1, &shadow_fbo);
    glDeleteTextures(1, &shadow_texture);
    glDeleteSamplers(1, &depth_sampler);
    glDeleteTextures(1, &occluder_texture);
  }

  Result<void> create(const std::string& shader_directory);
  FrameSetup setup(const FrameView& view) const;
  void draw_shadow_map(const FrameView& view, const FrameSetup& frame);
  // Binds `program` with the uniforms every lit shader shares.
  void use(const ShaderProgram& program, const FrameSetup& frame, const Camera& camera);
  // The key light's colour, linear, times the exposure (common::Look::exposure_for).
  Eigen::Vector3f key_light_color() const;
  GroundKey ground_key(const FrameView& view, const FrameSetup& frame) const;
  void draw_ground_with(const ShaderProgram& program, const FrameView& view,
                        const FrameSetup& frame);
  // Binds `target` and fills it with the background and the ground without shadows.
  void start_frame(const FrameView& view, const FrameSetup& frame, GLuint target);
  // The ground again with `program` (its shadows, its occlusion), inside `region`.
  void draw_ground_shadows(const ShaderProgram& program, const FrameView& view,
                           const FrameSetup& frame, const PixelRect& region);
  void draw_quads(const FrameView& view, const FrameSetup& frame, bool back_sides);
  // Reads the frame into `out`, through the edge filter unless multisampled, which leaves
  // `text_boxes` (from TextLayer::lay_out) alone.
  void read_pixels(io::Image& out, const std::vector<PixelBox>& text_boxes);
  // The labels placed on the picture where their points land, then the texts.
  std::vector<Text> texts_with_labels(const FrameView& view, const FrameSetup& frame) const;
  // Whether the arrow is at least kMinArrowPixels long on the picture (then it and its label
  // are drawn).
  bool shows(const Arrow& arrow, const FrameSetup& frame) const;
};

Result<void> Renderer::Resources::create(const std::string& shader_directory) {
  Result<std::unique_ptr<OffscreenContext>> made_context = create_offscreen_context(
      settings.width, settings.height, settings.backend, settings.egl_device);
  if (!made_context) return Error{made_context.error()};
  context = std::move(made_context).value();
  // Each program compiled and linked, or the error.
  const auto build = [&](ShaderProgram& program, const std::vector<std::string>& vertex_files,
                         const std::vector<std::string>& fragment_files) -> Result<void> {
    Result<ShaderProgram> built =
        ShaderProgram::build(shader_directory, vertex_files, fragment_files);
    if (!built) return Error{built.error()};
    program = std::move(built).value();
    return Result<void>::success();
  };

  // A lit fragment shader's sources: lighting.glsl (soft or hard shadows, as the look has them)
  // and then `files`.
  const bool soft = settings.look.shadow_softness > 0.0;
  const auto lit = [soft](const std::vector<std::string>& files) {
    std::vector<std::string> out = {"version.glsl"};
    if (soft) out.push_back("soft_shadows.glsl");
    out.push_back("lighting.glsl");
    out.insert(out.end(), files.begin(), files.end());
    return out;
  };
  const bool occluded = settings.ground.enabled && settings.look.ambient_occlusion > 0.0;
  // The solids receive the occlusion of the bodies beside them whether or not there is a ground.
  const bool bodies_occluded = settings.look.ambient_occlusion > 0.0;
  // Each solid's program, and the same receiving occlusion when the look has it.
  const auto build_solid = [&](ShaderProgram& plain, ShaderProgram& occluded,
                               const std::vector<std::string>& vertex,
                               const std::string& fragment) -> Result<void> {
    if (Result<void> built = build(plain, vertex, lit({fragment})); !built) return built;
    if (!bodies_occluded) return Result<void>::success();
    return build(occluded, vertex,
                 lit({"form_factor.glsl", "receive_body_occlusion.glsl", fragment}));
  };
  if (Result<void> built =
          build_solid(body_program, body_occluded_program, {"body.vert"}, "body.frag");
      !built)
    return built;
  if (bodies_occluded) {
    glGenTextures(1, &occluder_texture);
    glBindTexture(GL_TEXTURE_2D, occluder_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  if (Result<void> built = build(ground_program, {"ground.vert"}, lit({"ground.frag"})); !built)
    return built;
  if (Result<void> built =
          build(shadowed_ground_program, {"ground.vert"},
                occluded ? lit({"receive_shadows.glsl", "receive_occlusion.glsl", "ground.frag"})
                         : lit({"receive_shadows.glsl", "ground.frag"}));
      !built)
    return built;
  if (Result<void> built = build(shadow_program, {"shadow.vert"}, {"shadow.frag"}); !built)
    return built;
  if (Result<void> built = build(box_shadow_program, {"box_shadow.vert"}, {"shadow.frag"}); !built)
    return built;
  if (Result<void> built = build(plane_program, {"plane.vert"}, lit({"plane.frag"})); !built)
    return built;

  boxes = BoxBatch::create(Solid::box);
  if (settings.round_solids) {
    struct Sources {
      Solid solid;
      std::vector<std::string> vertex, shadow;
    };
    const Sources sources[] = {
        {Solid::ball, {"ball.vert"}, {"box_shadow.vert"}},
        {Solid::capsule, {"capsule.glsl", "capsule.vert"}, {"capsule.glsl", "capsule_shadow.vert"}},
        {Solid::cylinder, {"cylinder.vert"}, {"box_shadow.vert"}},
    };
    for (const Sources& source : sources) {
      RoundSolid& round = rounds.emplace_back();
      if (Result<void> built =
              build_solid(round.program, round.occluded_program, source.vertex, "ball.frag");
          !built)
        return built;
      if (Result<void> built = build(round.shadow_program, source.shadow, {"shadow.frag"}); !built)
        return built;
      round.batch = BoxBatch::create(source.solid);
    }
  }
  for (std::uint32_t k = 0; k < settings.hulls.size(); ++k) {
    {
      RoundSolid& hull = rounds.emplace_back();
      // Each hull its own program objects: the same two sources, built once per mesh (a scene
      // has a few).
      if (Result<void> built =
              build_solid(hull.program, hull.occluded_program, {"hull.vert"}, "hull.frag");
          !built)
        return built;
      if (Result<void> built = build(hull.shadow_program, {"box_shadow.vert"}, {"shadow.frag"});
          !built)
        return built;
      hull.batch = BoxBatch::create_hull(settings.hulls[k], settings.hull_sizes[k], k);
    }
  }

  // Ground: one square as a triangle strip.
  const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  vertex_array(corners, sizeof(corners), 2, ground_vao, ground_vbo);
  // Quads: the same square in the x-z plane, in three dimensions for the shadow shader.
  vertex_array(kUnitSquare[0], sizeof(kUnitSquare), 3, quad_vao, quad_vbo);
  glBindVertexArray(0);

  if (settings.shadows) {
    glGenTextures(1, &shadow_texture);
    glBindTexture(GL_TEXTURE_2D, shadow_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kShadowMapSize, kShadowMapSize, 0,
                 GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Outside the map nothing casts a shadow: the border is the far plane.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[] = {1, 1, 1, 1};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &shadow_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_texture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      return Error{"shadow-map framebuffer is incomplete"};
    }
    glGenSamplers(1, &depth_sampler);
    glSamplerParameteri(depth_sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(depth_sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(depth_sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(depth_sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(depth_sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }

  if (settings.msaa > 1) {
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (settings.msaa > max_samples) {
      return Error{"[render] msaa = " + std::to_string(settings.msaa) +
                   " is more than this OpenGL allows: set it to " + std::to_string(max_samples) +
                   " or less"};
    }
  }
  const int samples = std::max(settings.msaa, 1);
  Result<Framebuffer> made_target = Framebuffer::create(settings.width, settings.height, samples);
  if (!made_target) return Error{made_target.error()};
  target = std::move(made_target).value();
  if (samples > 1) {
    Result<Framebuffer> made_resolved = Framebuffer::create(settings.width, settings.height, 1);
    if (!made_resolved) return Error{made_resolved.error()};
    resolved = std::move(made_resolved).value();
  }
  // Frames are read top row first, as images are stored, by Mesa's pack-invert: no copy to flip.
  bool pack_invert = false;
  GLint extension_count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &extension_count);
  for (GLint i = 0; i < extension_count; ++i) {
    const GLubyte* name = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
    pack_invert = pack_invert ||
                  std::string_view(reinterpret_cast<const char*>(name)) == "GL_MESA_pack_invert";
  }
  if (!pack_invert) return Error{"this OpenGL lacks GL_MESA_pack_invert (Mesa has it)"};
  glPixelStorei(GL_PACK_INVERT_MESA, GL_TRUE);
  rgba.resize(static_cast<std::size_t>(settings.width) * settings.height * 4);
  if (settings.ground.enabled) {
    Result<GroundCache> made_ground = GroundCache::create(settings.width, settings.height, samples);
    if (!made_ground) return Error{made_ground.error()};
    ground = std::move(made_ground).value();
    if (occluded) {
      Result<OcclusionLayer> made_occlusion =
          OcclusionLayer::create(settings.width, settings.height, shader_directory);
      if (!made_occlusion) return Error{made_occlusion.error()};
      occlusion = std::move(made_occlusion).value();
    }
  }
  if (!settings.font.empty()) {
    Result<std::unique_ptr<TextLayer>> layer =
        TextLayer::create(settings.width, settings.height, settings.font);
    if (!layer) return Error{layer.error()};
    text = std::move(layer).value();
  }
  if (settings.overlays) {
    Result<std::unique_ptr<OverlayLayer>> layer =
        OverlayLayer::create(settings.width, settings.height, shader_directory);
    if (!layer) return Error{layer.error()};
    overlay = std::move(layer).value();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (glGetError() != GL_NO_ERROR) return Error{"OpenGL error while setting up the renderer"};
  return Result<void>::success();
}

Renderer::Renderer(std::unique_ptr<Resources> resources) : resources_(std::move(resources)) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(const RenderSettings& settings,
                                                   const std::string& shader_directory) {
  auto resources = std::make_unique<Resources>();
  resources->settings = settings;
  if (Result<void> created = resources->create(shader_directory); !created) {
    return Error{created.error()};
  }
  return std::unique_ptr<Renderer>(new Renderer(std::move(resources)));
}

std::string Renderer::description() const {
  return resources_->context->description();
}

common::Backend Renderer::backend() const {
  return resources_->context->backend();
}

std::string Renderer::device() const {
  return resources_->context->device();
}

std::string Renderer::opengl() const {
  return gl_description();
}

const Font* Renderer::font() const {
  return resources_->text ? &resources_->text->font() : nullptr;
}

FrameSetup Renderer::Resources::setup(const FrameView& view) const {
  const Camera& camera = view.camera;
  FrameSetup frame;
  // The part of the world worth lighting and showing: a sphere around the look-at point that
  // holds every box.
  frame.extent = view_extent(view);
  // The shadow map grows to hold the quads that cast shadows, up to kQuadShadowReach times the
  // boxes' sphere.
  double caster_reach = 0.0;
  for (const Quad& quad : view.quads) {
    if (seen_from_back(quad, camera.position)) continue;
    for (const Vec3& corner : corners(quad)) {
      caster_reach = std::max(caster_reach, (corner - camera.look_at).norm());
    }
  }
  frame.shadow_radius =
      std::max(frame.extent.radius, std::min(caster_reach, kQuadShadowReach * frame.extent.radius));
  frame.view_projection =
      perspective(camera.fov_degrees * M_PI / 180.0,
                  static_cast<double>(settings.width) / static_cast<double>(settings.height),
                  frame.extent.near, frame.extent.far) *
      look_at(camera.position, camera.look_at, camera.up);

  frame.light_direction = settings.light.direction.normalized();
  const Vec3& light = frame.light_direction;
  const double r = frame.shadow_radius;
  const Mat4 light_view = look_at(camera.look_at - 2.0 * r * light, camera.look_at,
                                  std::abs(light.y()) > 0.99 ? Vec3::UnitZ() : Vec3::UnitY());
  frame.light_view_projection = orthographic(r, 0.1, 4.0 * r + 0.1) * light_view;
  frame.light_right = light_view.row(0).head<3>().transpose();
  frame.light_up = light_view.row(1).head<3>().transpose();
  return frame;
}

void Renderer::Resources::draw_shadow_map(const FrameView& view, const FrameSetup& frame) {
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo);
  glViewport(0, 0, kShadowMapSize, kShadowMapSize);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  glUseProgram(box_shadow_program.id());
  set_matrix(box_shadow_program.uniform("u_light_view_projection"), frame.light_view_projection);
  boxes.draw();
  for (const RoundSolid& round : rounds) {
    glUseProgram(round.shadow_program.id());
    set_matrix(round.shadow_program.uniform("u_light_view_projection"),
               frame.light_view_projection);
    round.batch.draw();
  }
  if (!view.quads.empty()) {
    glUseProgram(shadow_program.id());
    set_matrix(shadow_program.uniform("u_light_view_projection"), frame.light_view_projection);
    glDisable(GL_CULL_FACE);  // a quad casts whichever side the light falls on
    glBindVertexArray(quad_vao);
    for (const Quad& quad : view.quads) {
      if (seen_from_back(quad, view.camera.position)) continue;
      set_matrix(shadow_program.uniform("u_model"), model_matrix(quad));
      glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glEnable(GL_CULL_FACE);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::Resources::use(const ShaderProgram& program, const FrameSetup& frame,
                              const Camera& camera) {
  glUseProgram(program.id());
  set_matrix(program.uniform("u_view_projection"), frame.view_projection);
  set_matrix(program.uniform("u_light_view_projection"), frame.light_view_projection);
  set_vector(program.uniform("u_light_direction"), frame.light_direction.cast<float>());
  set_vector(program.uniform("u_light_color"), key_light_color());
  glUniform1f(program.uniform("u_ambient"), static_cast<float>(settings.light.ambient));
  glUniform1f(program.uniform("u_fill_low"), static_cast<float>(1.0 - settings.look.fill_light));
  set_vector(program.uniform("u_camera_position"), camera.position.cast<float>());
  glUniform1i(program.uniform("u_shadows"), settings.shadows ? 1 : 0);
  glUniform1i(program.uniform("u_shadow_map"), 0);
  glUniform1i(program.uniform("u_shadow_depth"), 1);
  // The filter's radius per unit of map depth: the map is 2r across and 4r deep (setup()).
  const double half_angle = 0.5 * settings.look.shadow_softness * M_PI / 180.0;
  glUniform1f(program.uniform("u_penumbra"), static_cast<float>(2.0 * std::tan(half_angle)));
  set_vector(program.uniform("u_light_right"), frame.light_right.cast<float>());
  set_vector(program.uniform("u_light_up"), frame.light_up.cast<float>());
  glUniform1i(program.uniform("u_occluders"), 3);
  glUniform1f(program.uniform("u_occlusion_strength"),
              static_cast<float>(settings.look.ambient_occlusion));
}

Eigen::Vector3f Renderer::Resources::key_light_color() const {
  const Eigen::Vector3f color = linear_from_srgb(settings.light.color);
  const double exposure = settings.look.exposure_for(settings.light);
  return exposure == 1.0 ? color : Eigen::Vector3f(color * static_cast<float>(exposure));
}

GroundKey Renderer::Resources::ground_key(const FrameView& view, const FrameSetup& frame) const {
  GroundKey key;
  Eigen::Map<Eigen::Matrix4f>(key.view_projection.data()) = frame.view_projection.cast<float>();
  key.center = {static_cast<float>(view.camera.look_at.x()),
                static_cast<float>(settings.ground.height),
                static_cast<float>(view.camera.look_at.z())};
  key.half_extent = static_cast<float>(frame.extent.ground_half_extent);
  return key;
}

void Renderer::Resources::draw_ground_with(const ShaderProgram& program, const FrameView& view,
                                           const FrameSetup& frame) {
  const RenderSettings& s = settings;
  const GroundKey key = ground_key(view, frame);
  use(program, frame, view.camera);
  glUniform3fv(program.uniform("u_center"), 1, key.center.data());
  glUniform1f(program.uniform("u_half_extent"), key.half_extent);
  glUniform1f(program.uniform("u_fade_start"), static_cast<float>(kGroundFadeStart));
  // lighting.glsl's shade() for the normal (0, 1, 0) without specular (the hemisphere
  // term is 1 there).
  const Eigen::Vector3f albedo = linear_from_srgb(s.ground.color);
  const Eigen::Vector3f key_light = key_light_color();
  const float ambient = static_cast<float>(s.light.ambient);
  const float diffuse = static_cast<float>(std::max(-frame.light_direction.y(), 0.0));
  set_vector(program.uniform("u_lit_color"), albedo.cwiseProduct(key_light) * (ambient + diffuse));
  set_vector(program.uniform("u_shadow_color"), albedo.cwiseProduct(key_light) * ambient);
  set_vector(program.uniform("u_background"), linear_from_srgb(s.background));
  // A transparent picture keeps only the ground's shadows, as black of this opacity at the
  // darkest: how much darker the ground is in shadow than lit, diffuse / (ambient + diffuse).
  // Negative: the ground is drawn.
  const float lit = ambient + diffuse;
  glUniform1f(program.uniform("u_shadow_opacity"),
              !s.transparent ? -1.0f : (lit > 0.0f ? diffuse / lit : 0.0f));
  glUniform1f(program.uniform("u_grid_spacing"), static_cast<float>(s.ground.grid_spacing));
  if (occlusion.texture() != 0) {
    glUniform1i(program.uniform("u_occlusion"), 2);
    glUniform2f(program.uniform("u_occlusion_scale"),
                1.0f / static_cast<float>(kOcclusionDownsampling * occlusion.buffer_width()),
                1.0f / static_cast<float>(kOcclusionDownsampling * occlusion.buffer_height()));
  }
  glDisable(GL_CULL_FACE);  // seen from below too, if the camera goes there
  glBindVertexArray(ground_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glEnable(GL_CULL_FACE);
}

void Renderer::Resources::start_frame(const FrameView& view, const FrameSetup& frame,
                                      GLuint target) {
  // The shaders encode to sRGB themselves, so the clear colour is given encoded too. Surfaces
  // write alpha 1, so alpha 0 is left exactly where nothing was drawn; a transparent picture's
  // partial alphas are made straight against this colour at the end (straight_alpha.hpp).
  glClearColor(static_cast<float>(settings.background.x()),
               static_cast<float>(settings.background.y()),
               static_cast<float>(settings.background.z()), settings.transparent ? 0.0f : 1.0f);
  glViewport(0, 0, settings.width, settings.height);
  // A transparent picture draws no ground; its shadows come later (draw_ground_shadows).
  if (!settings.ground.enabled || settings.transparent) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return;
  }
  // Every frame is the kept ground copied, whether it was kept or drawn just now: the same
  // bytes either way, so a render's frames do not depend on where it started.
  const GroundKey key = ground_key(view, frame);
  if (!ground.holds(key)) {
    ground.begin_drawing(key);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw_ground_with(ground_program, view, frame);
  }
  ground.copy_to(target);
}

void Renderer::Resources::draw_ground_shadows(const ShaderProgram& program, const FrameView& view,
                                              const FrameSetup& frame, const PixelRect& region) {
  // Again with shadows inside the screen rectangle that holds every box's shadow on the ground
  // (and its occlusion): the same triangles give the same depths (ground.vert's gl_Position is
  // invariant), so GL_LEQUAL passes where the kept ground shows and fails where a box is nearer,
  // before shading.
  glEnable(GL_SCISSOR_TEST);
  glScissor(region[0], region[1], region[2], region[3]);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);  // the depths are the kept ground's already
  draw_ground_with(program, view, frame);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_SCISSOR_TEST);
}

void Renderer::Resources::draw_quads(const FrameView& view, const FrameSetup& frame,
                                     bool back_sides) {
  const Vec3& eye = view.camera.position;
  std::vector<const Quad*> quads;
  for (const Quad& quad : view.quads) {
    if (seen_from_back(quad, eye) == back_sides) quads.push_back(&quad);
  }
  if (quads.empty()) return;
  if (back_sides) {
    // Blended back to front (by centre: exact for quads that do not cross); a stable sort keeps
    // the given order for equal distances.
    std::stable_sort(quads.begin(), quads.end(), [&](const Quad* a, const Quad* b) {
      return (a->center - eye).squaredNorm() > (b->center - eye).squaredNorm();
    });
    glEnable(GL_BLEND);
    // "Over" for colour and alpha alike (a + (1 − a) × the alpha below): on a transparent
    // picture the colour stays the picture over the background colour (straight_alpha.hpp).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);  // what is behind a translucent quad stays drawable
  }
  use(plane_program, frame, view.camera);
  glDisable(GL_CULL_FACE);
  glBindVertexArray(quad_vao);
  for (const Quad* quad : quads) {
    const Vec3 normal = back_sides ? Vec3(-front_normal(*quad)) : front_normal(*quad);
    set_matrix(plane_program.uniform("u_model"), model_matrix(*quad));
    glUniform2f(plane_program.uniform("u_half_size"), static_cast<float>(0.5 * quad->width),
                static_cast<float>(0.5 * quad->depth));
    set_vector(plane_program.uniform("u_normal"), normal.cast<float>());
    set_vector(plane_program.uniform("u_albedo"), linear_from_srgb(quad->color));
    glUniform1f(plane_program.uniform("u_grid_spacing"), static_cast<float>(quad->grid_spacing));
    glUniform1f(plane_program.uniform("u_opacity"), back_sides ? kBackSideOpacity : 1.0f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  glEnable(GL_CULL_FACE);
  if (back_sides) {
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
}

// The alpha of the read-back `rgba` (top row first) into `alpha`, one byte per pixel: with
// multisampling an edge's alpha is its coverage, with one sample all or nothing.
static void copy_alpha(const std::vector<std::uint8_t>& rgba, int width, int height,
                       std::vector<std::uint8_t>& alpha) {
  alpha.resize(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < alpha.size(); ++i) alpha[i] = rgba[4 * i + 3];
}

void Renderer::Resources::read_pixels(io::Image& out, const std::vector<PixelBox>& text_boxes) {
  // Straight from the frame's own framebuffer (glReadPixels waits for the drawing): copying it
  // into the context's buffer first, with glBlitFramebuffer, costs llvmpipe more than the read.
  const Framebuffer& source = settings.msaa > 1 ? resolved : target;
  if (settings.msaa > 1) target.copy_to(resolved.id(), GL_COLOR_BUFFER_BIT);  // resolves
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source.id());
  glReadPixels(0, 0, settings.width, settings.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  if (settings.msaa == kEdgeFilter) {
    // The filter blends a transparent frame's alpha with its colour (edge_filter.hpp).
    filter_edges(rgba.data(), settings.width, settings.height, out, text_boxes,
                 settings.transparent);
    return;
  }
  if (out.width != settings.width || out.height != settings.height) {
    out = io::Image(settings.width, settings.height);
  }
  const std::size_t pixel_count = static_cast<std::size_t>(settings.width) * settings.height;
  for (std::size_t i = 0; i < pixel_count; ++i) {
    out.rgb[3 * i + 0] = rgba[4 * i + 0];
    out.rgb[3 * i + 1] = rgba[4 * i + 1];
    out.rgb[3 * i + 2] = rgba[4 * i + 2];
  }
  if (settings.transparent) {
    copy_alpha(rgba, settings.width, settings.height, out.alpha);
  } else {
    out.alpha.clear();
  }
}

bool Renderer::Resources::shows(const Arrow& arrow, const FrameSetup& frame) const {
  const auto from =
      project_to_pixel(frame.view_projection, arrow.from, settings.width, settings.height);
  const auto to =
      project_to_pixel(frame.view_projection, arrow.to, settings.width, settings.height);
  if (!from || !to) return (arrow.to - arrow.from).norm() > 0.0;  // partly behind: clipped
  return (*to - *from).norm() >= scale_to_frame(kMinArrowPixels, settings.height);
}

std::vector<Text> Renderer::Resources::texts_with_labels(const FrameView& view,
                                                         const FrameSetup& frame) const {
  const bool arrow_labels = std::any_of(view.arrows.begin(), view.arrows.end(),
                                        [](const Arrow& a) { return !a.label.empty(); });
  if (view.labels.empty() && !arrow_labels) return view.texts;
  std::vector<Text> out;
  // A gap between the point and the label's box, so that the label clears an arrow's tip.
  constexpr double kLabelGap = 6.0;  // px at 720 rows
  const double reference = static_cast<double>(kTextReferenceHeight) / settings.height;
  const auto add = [&](const Label& label) {
    const auto pixel =
        project_to_pixel(frame.view_projection, label.position, settings.width, settings.height);
    if (!pixel) return;
    // Anchored left and middle: x from the left edge, y from the frame's middle row.
    out.push_back(Text{.text = label.text,
                       .anchor = Anchor::kLeft,
                       .offset = Eigen::Vector2d(pixel->x() * reference + kLabelGap,
                                                 (pixel->y() - 0.5 * settings.height) * reference) +
                                 label.offset,
                       .height = label.height,
                       .color = label.color,
                       .background = label.background,
                       .opacity = label.opacity,
                       .keep_apart = true});
  };
  for (const Arrow& arrow : view.arrows) {
    if (arrow.label.empty() || !shows(arrow, frame)) continue;
    add(Label{.text = arrow.label,
              .position = arrow.to,
              .height = arrow.label_height,
              .color = arrow.color});
  }
  for (const Label& label : view.labels) add(label);
  out.insert(out.end(), view.texts.begin(), view.texts.end());
  return out;
}

namespace {

// sRGB level -> linear light, for every 8-bit level (IEC 61966-2-1).
const std::array<double, 256>& linear_levels() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> out{};
    for (int level = 0; level < 256; ++level) out[level] = linear_from_srgb(level / 255.0);
    return out;
  }();
  return table;
}

// Linear light in [0, 1] -> the nearest sRGB level.
std::uint8_t srgb_level(double linear) {
  return static_cast<std::uint8_t>(
      std::clamp(std::lround(255.0 * srgb_from_linear(linear)), 0L, 255L));
}

}  // namespace

void Renderer::draw(const FrameView& view, io::Image& out) {
  Resources& r = *resources_;
  const RenderSettings& s = r.settings;
  // Another renderer of this thread may have drawn last.
  [[maybe_unused]] const bool current = r.context->use();
  assert(current && "the off-screen context could not be made current again");
  if (view.blurred_boxes.empty()) {
    draw_picture(view, view.boxes, out, false);
    return;
  }
  // Motion blur: each picture drawn and read back, summed in linear light (colour) and as
  // coverage (alpha), in a fixed order: the same bytes every run.
  const std::size_t pixels = static_cast<std::size_t>(s.width) * s.height;
  std::vector<double> sum(pixels * 3, 0.0), alpha_sum;
  if (s.transparent) alpha_sum.assign(pixels, 0.0);
  const std::array<double, 256>& linear = linear_levels();
  io::Image picture;
  const std::size_t count = view.blurred_boxes.size();
  for (std::size_t j = 0; j < count; ++j) {
    draw_picture(view, view.blurred_boxes[j], picture, true);
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += linear[picture.rgb[i]];
    for (std::size_t i = 0; i < alpha_sum.size(); ++i) alpha_sum[i] += picture.alpha[i];
  }
  if (out.width != s.width || out.height != s.height) out = io::Image(s.width, s.height);
  for (std::size_t i = 0; i < sum.size(); ++i) out.rgb[i] = srgb_level(sum[i] / count);
  out.alpha.resize(alpha_sum.size());
  for (std::size_t i = 0; i < alpha_sum.size(); ++i) {
    out.alpha[i] = static_cast<std::uint8_t>(std::lround(alpha_sum[i] / count));
  }
  finish_picture(view, out);
}

void Renderer::draw_picture(const FrameView& view, const std::vector<Box>& boxes, io::Image& out,
                            bool one_of_several) {
  Resources& r = *resources_;
  const RenderSettings& s = r.settings;
  const FrameSetup frame = r.setup(view);

  // The bodies each box receives occlusion from, and every body's shape for the shader.
  std::vector<std::array<int, kOccludersPerBody>> occluders;
  if (r.occluder_texture != 0 && !boxes.empty()) {
    occluders = nearest_occluders(boxes);
    const std::vector<float> texels = occluder_texels(boxes);
    glBindTexture(GL_TEXTURE_2D, r.occluder_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 4 * kOccludersPerRow,
                 static_cast<GLsizei>(texels.size() / (16 * kOccludersPerRow)), 0, GL_RGBA,
                 GL_FLOAT, texels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  const auto* receives = occluders.empty() ? nullptr : &occluders;
  r.boxes.upload(boxes, view.camera.position, receives);
  // A round solid needs RenderSettings::round_solids, a hull its mesh among RenderSettings::hulls.
  assert(std::all_of(boxes.begin(), boxes.end(), [&](const Box& b) {
    return b.solid == Solid::box ||
           (b.solid == Solid::hull ? b.mesh < s.hulls.size() : s.round_solids);
  }));
  for (Resources::RoundSolid& round : r.rounds) {
    round.batch.upload(boxes, view.camera.position, receives);
  }
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  if (s.shadows) r.draw_shadow_map(view, frame);
  // Where the ground is drawn again with its shadows (and their occlusion), and where the
  // occlusion falls (drawn now for both).
  std::optional<PixelRect> shadowed_region;
  OcclusionLayer::Regions occluded;
  if (s.ground.enabled) {
    if (s.shadows) {
      // A soft shadow's penumbra reaches kMaxPenumbraTexels of the map past the hard edge,
      // stretched on the ground by the light's slant.
      const double penumbra = s.look.shadow_softness > 0.0
                                  ? kMaxPenumbraTexels * 2.0 * frame.shadow_radius /
                                        kShadowMapSize / std::max(-frame.light_direction.y(), 0.2)
                                  : 0.0;
      shadowed_region =
          shadow_region(view, boxes, s, frame.view_projection, frame.light_direction, penumbra);
    }
    if (r.occlusion.texture() != 0) {
      occluded = r.occlusion.draw(boxes, s.ground.height, s.look.ambient_occlusion,
                                  frame.view_projection, shadowed_region);
    }
  }

  r.start_frame(view, frame, r.target.id());
  // The occlusion of the lit ground, before the bodies hide any of it. A transparent picture has
  // no ground drawn: its shadowed pass covers the occlusion's region instead.
  if (occluded.occluded && s.transparent) shadowed_region = occluded.fresh;
  if (occluded.occluded && !s.transparent) {
    const double diffuse = std::max(-frame.light_direction.y(), 0.0);
    const double lit = s.light.ambient + diffuse;
    r.occlusion.apply(*occluded.occluded, lit > 0.0 ? s.light.ambient / lit : 0.0);
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, r.shadow_texture);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, r.shadow_texture);
  glBindSampler(1, r.depth_sampler);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, r.occlusion.texture());
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_2D, r.occluder_texture);
  glActiveTexture(GL_TEXTURE0);

  // The opaque surfaces in any order give the same picture (GL_LESS keeps the nearest) but
  // where two are at exactly the same depth. The ground is there first (the kept copy), then the
  // boxes, then the ground's shadows where a box does not hide it. A quad seen from its front
  // has the camera on the same side as every box (boxes stay outside planes), so it can hide
  // none of them: opaque too. Those seen from their back are blended over everything, last.
  // Each solid's boxes that receive no occlusion, then those that do, with the program that
  // computes it.
  const auto draw_solid = [&](const ShaderProgram& plain, const ShaderProgram& occluded,
                              const BoxBatch& batch) {
    r.use(plain, frame, view.camera);
    if (!occluded.valid()) {
      batch.draw();
      return;
    }
    batch.draw_part(false);
    r.use(occluded, frame, view.camera);
    batch.draw_part(true);
  };
  draw_solid(r.body_program, r.body_occluded_program, r.boxes);
  for (const Resources::RoundSolid& round : r.rounds) {
    draw_solid(round.program, round.occluded_program, round.batch);
  }
  if (shadowed_region) {
    r.draw_ground_shadows(r.shadowed_ground_program, view, frame, *shadowed_region);
  }
  r.draw_quads(view, frame, false);
  r.draw_quads(view, frame, true);
  // Lines and arrows in the scene (overlay_layer.hpp says how they meet it), then text last,
  // over the picture read back, and left alone by the edge filter (text_layer.hpp says why). A
  // frame without overlays or text never reaches their layers.
  if (!view.lines.empty() || !view.arrows.empty()) {
    assert(r.overlay && "FrameView::lines and arrows need RenderSettings::overlays");
    std::vector<Arrow> arrows;
    for (const Arrow& arrow : view.arrows) {
      if (r.shows(arrow, frame)) arrows.push_back(arrow);
    }
    if (r.overlay) r.overlay->draw(view.lines, arrows, frame.view_projection);
  }
  const bool labelled = std::any_of(view.arrows.begin(), view.arrows.end(),
                                    [](const Arrow& a) { return !a.label.empty(); });
  const bool text = (!view.texts.empty() || !view.labels.empty() || labelled) && r.text;
  assert((text || (view.texts.empty() && view.labels.empty() && !labelled)) &&
         "FrameView::texts and labels need RenderSettings::font");
  std::vector<PixelBox> text_boxes;
  if (text) text_boxes = r.text->lay_out(r.texts_with_labels(view, frame));
  glBindSampler(1, 0);  // unit 1 is the shadow map's only while the frame is drawn
  r.read_pixels(out, text_boxes);
  if (!one_of_several) finish_picture(view, out);  // else once, over the pictures' average
}

void Renderer::finish_picture(const FrameView& view, io::Image& out) {
  Resources& r = *resources_;
  const RenderSettings& s = r.settings;
  if (!view.panels.empty() || !view.strokes.empty()) draw_sketch(view.panels, view.strokes, out);
  const bool labelled = std::any_of(view.arrows.begin(), view.arrows.end(),
                                    [](const Arrow& a) { return !a.label.empty(); });
  if ((!view.texts.empty() || !view.labels.empty() || labelled) && r.text) r.text->draw(out);
  // Last: every layer blends onto the background colour (straight_alpha.hpp says why).
  if (s.transparent) make_alpha_straight(out, s.background);
}

}  // namespace tumble::render
