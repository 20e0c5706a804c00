#include "view/plane_view.hpp"

#include <cmath>

namespace tumble::view {
namespace {

using render::Vec3;

// Quad to world for a plane: local y along the normal, local x across the plane (horizontal),
// local z = x × y up its slope. A level (or upside-down) plane has no slope: x is world x.
render::Quat plane_orientation(const Vec3& normal) {
  Vec3 across = normal.cross(Vec3::UnitY());
  across = across.norm() > 1e-12 ? Vec3(across.normalized()) : Vec3(Vec3::UnitX());
  Eigen::Matrix3d rotation;
  rotation << across, normal, across.cross(normal);
  return render::Quat(rotation).normalized();
}

// Lighter than the floor, so that a ramp lit like the floor still stands out from it.
render::Color quad_color(const render::Color& ground) {
  return ground + 0.35 * (render::Color::Ones() - ground);
}

}  // namespace

DrawnPlanes drawn_planes(const scene::Scene& scene) {
  DrawnPlanes out;
  out.ground = scene.render.ground;
  int floor = -1;
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const scene::PlaneSpec& plane = scene.planes[i];
    const bool lower = floor < 0 || plane.point.y() < scene.planes[floor].point.y();
    if (plane.visible && plane.normal.y() > kLevelNormalY && lower) floor = static_cast<int>(i);
  }
  out.ground.enabled = floor >= 0;
  if (floor >= 0) out.ground.height = scene.planes[floor].point.y();
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const scene::PlaneSpec& plane = scene.planes[i];
    if (!plane.visible || static_cast<int>(i) == floor) continue;
    out.names.push_back(plane.name);
    out.quads.push_back(render::Quad{.center = plane.point,
                                     .orientation = plane_orientation(plane.normal),
                                     .width = plane.size[0],
                                     .depth = plane.size[1],
                                     .color = quad_color(scene.render.ground.color),
                                     .grid_spacing = scene.render.ground.grid_spacing});
  }
  return out;
}

void frame_walls(const std::vector<render::Quad>& quads, double reach, Vec3& low, Vec3& high) {
  const Vec3 near_low = low - Vec3::Constant(reach);
  const Vec3 near_high = high + Vec3::Constant(reach);
  for (const render::Quad& quad : quads) {
    const Eigen::Matrix3d axes = quad.orientation.toRotationMatrix();
    if (axes.col(1).y() > kFacesUpNormalY) continue;
    // The quad's bounding box, cut to the part near the motion.
    const Vec3 half_box =
        0.5 * quad.width * axes.col(0).cwiseAbs() + 0.5 * quad.depth * axes.col(2).cwiseAbs();
    const Vec3 quad_low = (quad.center - half_box).cwiseMax(near_low);
    const Vec3 quad_high = (quad.center + half_box).cwiseMin(near_high);
    if ((quad_low.array() > quad_high.array()).any()) continue;  // not near the motion
    low = low.cwiseMin(quad_low);
    high = high.cwiseMax(quad_high);
  }
}

}  // namespace tumble::view
