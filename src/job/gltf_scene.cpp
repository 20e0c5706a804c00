#include "job/gltf_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/geometry.hpp"
#include "render/solid_mesh.hpp"
#include "render/view_extent.hpp"

namespace tumble::job {
namespace {

// Bodies are dielectrics with a soft highlight, as the renderer's Blinn-Phong lights them; planes
// and the ground are matte.
constexpr double kBodyRoughness = 0.5;
constexpr double kPlaneRoughness = 1.0;

io::GltfPose pose(const render::Vec3& position, const render::Quat& orientation) {
  const render::Quat unit = orientation.normalized();
  return {.translation = {position.x(), position.y(), position.z()},
          .rotation = {unit.x(), unit.y(), unit.z(), unit.w()}};
}

io::GltfPose camera_pose(const render::Camera& camera) {
  return pose(camera.position, render::camera_rotation(camera));
}

io::GltfMesh gltf_mesh(const render::SolidMesh& mesh, std::string name, std::size_t material) {
  io::GltfMesh out;
  out.name = std::move(name);
  out.material = material;
  for (const Eigen::Vector3f& p : mesh.positions) out.positions.push_back({p.x(), p.y(), p.z()});
  for (const Eigen::Vector3f& n : mesh.normals) out.normals.push_back({n.x(), n.y(), n.z()});
  out.triangles = mesh.triangles;
  return out;
}

// The scene being filled, with the materials and body meshes made so far, each once.
class Builder {
 public:
  explicit Builder(io::GltfScene& out) : out_(out) {}

  // The material of `color` (sRGB) and roughness, made on first use. glTF's baseColorFactor is
  // linear light, tumble's colours sRGB-encoded: decoded here (IEC 61966-2-1).
  std::size_t material(const render::Color& color, double roughness, bool double_sided,
                       const std::string& name) {
    const Eigen::Vector3f linear = render::linear_from_srgb(color);
    const std::array<double, 4> base = {linear.x(), linear.y(), linear.z(), 1.0};
    for (std::size_t i = 0; i < out_.materials.size(); ++i) {
      const io::GltfMaterial& m = out_.materials[i];
      if (m.base_color == base && m.roughness == roughness && m.double_sided == double_sided) {
        return i;
      }
    }
    out_.materials.push_back({.name = name,
                              .base_color = base,
                              .metallic = 0.0,
                              .roughness = roughness,
                              .double_sided = double_sided});
    return out_.materials.size() - 1;
  }

  // The mesh of a body drawn as `box` (hull: `hull`), shared by every body of the same solid,
  // size and colour; a hull's is its own.
  std::size_t body_mesh(const render::Box& box, const render::HullMesh* hull,
                        const std::string& name) {
    for (const Made& made : made_) {
      if (made.solid == box.solid && made.size == box.size && made.color == box.color &&
          box.solid != render::Solid::hull) {
        return made.mesh;
      }
    }
    const std::size_t material = this->material(box.color, kBodyRoughness, false, name);
    out_.meshes.push_back(gltf_mesh(render::solid_mesh(box.solid, box.size, hull), name, material));
    made_.push_back({box.solid, box.size, box.color, out_.meshes.size() - 1});
    return out_.meshes.size() - 1;
  }

  // A quad (a plane, or the ground's square) as a mesh and a node of its own.
  void quad(const render::Quad& quad, const std::string& name) {
    const std::size_t material = this->material(quad.color, kPlaneRoughness, true, name);
    out_.meshes.push_back(gltf_mesh(render::quad_mesh(quad.width, quad.depth), name, material));
    out_.nodes.push_back({.name = name,
                          .mesh = out_.meshes.size() - 1,
                          .camera = {},
                          .pose = pose(quad.center, quad.orientation)});
  }

 private:
  struct Made {
    render::Solid solid;
    render::Vec3 size;
    render::Color color;
    std::size_t mesh;
  };
  io::GltfScene& out_;
  std::vector<Made> made_;
};

// The renderer's reach over every frame: the camera's nearest near and farthest far, and the
// ground it shows unfaded (a square about the point each frame looks at), as one rectangle.
struct Reach {
  double near = std::numeric_limits<double>::infinity();  // m
  double far = 0.0;                                       // m
  Eigen::Vector2d ground_low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d ground_high = -ground_low;  // x and z (m)
};

Reach renderer_reach(const scene::Scene& scene, const view::Framing& framing,
                     const std::vector<view::FrameMotion>& motion) {
  Reach out;
  for (const view::FrameMotion& frame : motion) {
    const render::ViewExtent extent = render::view_extent(view::motion_view(scene, framing, frame));
    out.near = std::min(out.near, extent.near);
    out.far = std::max(out.far, extent.far);
    const Eigen::Vector2d centre(frame.camera.look_at.x(), frame.camera.look_at.z());
    const double half = render::kGroundFadeStart * extent.ground_half_extent;
    out.ground_low = out.ground_low.cwiseMin(centre - Eigen::Vector2d::Constant(half));
    out.ground_high = out.ground_high.cwiseMax(centre + Eigen::Vector2d::Constant(half));
  }
  return out;
}

void add_camera(const scene::Scene& scene, const std::vector<view::FrameMotion>& motion,
                const Reach& reach, io::GltfScene& out) {
  const render::Camera& first = motion.front().camera;
  out.cameras.push_back({.name = "camera",
                         .yfov = first.fov_degrees * M_PI / 180.0,
                         .aspect_ratio = static_cast<double>(scene.render.width) /
                                         static_cast<double>(scene.render.height),
                         .znear = reach.near,
                         .zfar = reach.far});
  out.nodes.push_back(
      {.name = "camera", .mesh = {}, .camera = out.cameras.size() - 1, .pose = camera_pose(first)});
}

bool camera_moves(const std::vector<view::FrameMotion>& motion) {
  const render::Camera& first = motion.front().camera;
  return std::any_of(motion.begin(), motion.end(), [&](const view::FrameMotion& frame) {
    return frame.camera.position != first.position || frame.camera.look_at != first.look_at ||
           frame.camera.up != first.up;
  });
}

// "motion": every body's pose at every frame's time, and the camera's when it moves.
io::GltfAnimation animation(const std::vector<view::FrameMotion>& motion, std::size_t camera_node) {
  io::GltfAnimation out{.name = "motion", .times = {}, .tracks = {}};
  const std::size_t bodies = motion.front().positions.size();
  for (std::size_t i = 0; i < bodies; ++i) out.tracks.push_back({.node = i, .poses = {}});
  if (camera_moves(motion)) out.tracks.push_back({.node = camera_node, .poses = {}});
  for (const view::FrameMotion& frame : motion) {
    out.times.push_back(frame.time);
    for (std::size_t i = 0; i < bodies; ++i) {
      out.tracks[i].poses.push_back(pose(frame.positions[i], frame.orientations[i]));
    }
    if (out.tracks.size() > bodies) out.tracks.back().poses.push_back(camera_pose(frame.camera));
  }
  return out;
}

}  // namespace

io::GltfScene gltf_scene(const scene::Scene& scene, const view::Framing& framing,
                         const std::vector<view::FrameMotion>& motion,
                         const std::string& generator) {
  io::GltfScene out;
  out.name = scene.name;
  out.generator = generator;
  if (motion.empty()) return out;
  Builder builder(out);
  // The bodies first, so that body i is node i.
  const render::RenderSettings settings = view::renderer_settings(scene, framing);
  std::size_t hulls = 0;  // before body i: its mesh's index in settings.hulls
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const scene::BodySpec& body = scene.bodies[i];
    const render::Box box{
        .size = body.size, .color = body.color, .solid = view::solid_of(body.shape)};
    const render::HullMesh* hull = body.hull ? &settings.hulls[hulls++] : nullptr;
    out.nodes.push_back(
        {.name = body.name,
         .mesh = builder.body_mesh(box, hull, body.name),
         .camera = {},
         .pose = pose(motion.front().positions[i], motion.front().orientations[i])});
  }
  for (std::size_t i = 0; i < framing.quads.size(); ++i) {
    builder.quad(framing.quads[i], i < framing.quad_names.size() ? framing.quad_names[i]
                                                                 : "plane " + std::to_string(i));
  }
  const Reach reach = renderer_reach(scene, framing, motion);
  if (framing.ground.enabled && !scene.render.transparent) {
    const Eigen::Vector2d centre = 0.5 * (reach.ground_low + reach.ground_high);
    const Eigen::Vector2d extent = reach.ground_high - reach.ground_low;
    builder.quad(render::Quad{.center = render::Vec3(centre.x(), framing.ground.height, centre.y()),
                              .width = extent.x(),
                              .depth = extent.y(),
                              .color = framing.ground.color},
                 "ground");
  }
  add_camera(scene, motion, reach, out);
  out.animation = animation(motion, out.nodes.size() - 1);
  return out;
}

}  // namespace tumble::job
