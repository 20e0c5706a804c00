// How a scene's static planes are drawn, since render knows no planes: the floor as the ground,
// every other visible plane as a quad; and how much of them the default camera frames.
#pragma once

#include <string>
#include <vector>

#include "render/frame.hpp"
#include "scene/scene.hpp"

namespace tumble::view {

// A plane whose unit normal has y above this is level (within 0.003° of it): the lowest visible
// one is the floor, drawn as the ground (endless, gridded, with shadows). A plane any more tilted
// is drawn as a quad, since the ground can only lie flat.
inline constexpr double kLevelNormalY = 1.0 - 1e-9;

// Floors and slopes (normal within about 45° of up, y > 0.7) lie under the motion and are often
// much larger than it: the camera does not frame them. Walls and ceilings it frames.
inline constexpr double kFacesUpNormalY = 0.7;

struct DrawnPlanes {
  // [ground]'s colour and grid; enabled, at the floor's height, only when there is a floor.
  render::Ground ground;
  // Every visible plane but the floor: its `size` centred at its point, in [ground]'s colour and
  // grid. Local x runs across the plane (level: world x), local z up its slope (level: world z).
  std::vector<render::Quad> quads;
  std::vector<std::string> names;  // each quad's plane's name, for a file that names them (glTF)
};

// For a scene with planes (without any, the ground is placed by frame_scene).
DrawnPlanes drawn_planes(const scene::Scene& scene);

// Grows the box [low, high] (world frame, m) that the camera frames by the walls and ceilings
// among `quads`, each only as far as it lies within `reach` (m) of the box: a wall as big as the
// default 20 m × 20 m must not push the camera far from a small motion beside it.
void frame_walls(const std::vector<render::Quad>& quads, double reach, render::Vec3& low,
                 render::Vec3& high);

}  // namespace tumble::view
