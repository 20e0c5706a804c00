// How a scene asks to be drawn, as plain data: the picture's size and smoothing, its colours,
// the key light and the ground. Shared by scene (which reads it from [render], [light] and
// [ground]) and render (which draws with it), so that neither includes the other.
#pragma once

#include <Eigen/Core>

namespace tumble::common {

// Colours are sRGB-encoded components in [0, 1], as people write them; the renderer lights in
// linear space and encodes the result back to sRGB.
using Color = Eigen::Vector3d;

struct DirectionalLight {
  Eigen::Vector3d direction = Eigen::Vector3d(0.25, -1.2, -0.75);  // the way it travels, world
  Color color = Color(1.0, 1.0, 1.0);  // key light colour and intensity (sRGB)
  double ambient = 0.3;                // ambient intensity, a fraction of the key
};

struct Ground {
  bool enabled = true;
  double height = -1.5;                   // y of the plane (m)
  Color color = Color(0.62, 0.64, 0.66);  // sRGB
  double grid_spacing = 1.0;              // m between grid lines; 0 = no grid
};

// RenderSettings::msaa when the scene asks for no multisampling: one sample per pixel, then the
// edge filter (render/edge_filter.hpp) on the picture read back. On llvmpipe 4 samples per pixel
// cost more than everything else a frame of 1000 boxes draws; the filter costs one pass over
// the picture.
inline constexpr int kEdgeFilter = 0;

// Which off-screen OpenGL draws (render/offscreen_context.hpp). Both are Mesa's and draw the same
// bytes on llvmpipe (tests/render/backend_test.cpp), so the choice is the machine's, not the
// picture's: a scene may ask for one ([render] backend) where it knows the machine.
enum class Backend {
  automatic,  // OSMesa where it was built in and works, else EGL
  osmesa,
  egl,
};

// "auto", "osmesa", "egl": the name in scenes and on the command line.
constexpr const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::automatic:
      return "auto";
    case Backend::osmesa:
      return "osmesa";
    case Backend::egl:
      return "egl";
  }
  return "unknown";
}
inline constexpr Backend kAllBackends[] = {Backend::automatic, Backend::osmesa, Backend::egl};

// RenderSettings::egl_device when none is named: EGL draws on the first device of EGL's list that
// is a GPU (not Mesa's software device), else on Mesa's surfaceless platform; and the automatic
// back end takes EGL first when there is such a GPU, else OSMesa first.
inline constexpr int kAutomaticEglDevice = -1;
inline constexpr int kMaxEglDevice = 255;  // the largest index a scene or --egl-device may name

// How the light falls ([render] shadow_softness, ambient_occlusion, fill_light, exposure;
// docs/scene-reference.md, "Lighting", gives the formula). The defaults are tumble's look; plain()
// is the look of the releases before it: hard-edged shadows, no occlusion, the old fill and no
// exposure (the goldens drawn before it still hold).
struct Look {
  // The key light's apparent diameter (degrees): a shadow's penumbra widens with the distance
  // from the caster as the sun's does (0.53°); 0 = hard shadows (a 2×2 filtered edge).
  double shadow_softness = 4.0;
  // The fill light hidden from a point of the ground by the bodies near it (Quílez's closed-form
  // occlusion of a box, of a sphere): 1 = all of it, 0 = none (off).
  double ambient_occlusion = 1.0;
  // The fill light's sky/ground contrast: a face turned straight down gets 1 − fill_light of the
  // fill a face turned straight up gets (the light the ground sends back); 0 = the same fill from
  // every direction.
  double fill_light = 0.6;
  // A factor on the key light's colour; kAutoExposure: the one that makes a face turned straight
  // to the key light show exactly its colour (1 / (1 + ambient × hemisphere)).
  double exposure = kAutoExposure;
  static constexpr double kAutoExposure = 0.0;

  // The fill's hemisphere factor for a unit normal's y: 1 facing up, 1 − fill_light facing down.
  double hemisphere(double normal_y) const {
    return (1.0 - fill_light) + fill_light * (0.5 * normal_y + 0.5);
  }
  // The factor on the key light's colour: `exposure`, or with kAutoExposure the one that makes a
  // face turned straight to the key `light` show its colour: 1 / (1 + ambient × hemisphere).
  double exposure_for(const DirectionalLight& light) const {
    if (exposure != kAutoExposure) return exposure;
    return 1.0 / (1.0 + light.ambient * hemisphere(-light.direction.normalized().y()));
  }

  static constexpr Look plain() {
    return Look{
        .shadow_softness = 0.0, .ambient_occlusion = 0.0, .fill_light = 0.45, .exposure = 1.0};
  }
  bool operator==(const Look&) const = default;
};

inline constexpr double kMaxShadowSoftness = 20.0;  // degrees

inline constexpr int kMaxMotionBlurSamples = 64;

struct MotionBlur {
  int samples = 1;       // pictures averaged a frame; 1 = no blur
  double shutter = 0.5;  // the fraction of the frame interval the shutter is open, in (0, 1]
  bool on() const { return samples > 1; }
  // The time of picture j (0 .. samples-1) of the frame at t (s), at `fps`: spread evenly over
  // the shutter's interval, centred on t.
  double time(double t, int j, int fps) const {
    return t + shutter / fps * ((j + 0.5) / samples - 0.5);
  }
};

// Fixed for a whole render.
struct RenderSettings {
  int width = 1280;  // pixels
  int height = 720;  // pixels
  // Samples per pixel of multisampling (2, 4, 8, 16), used as given; 1 = one sample and no
  // antialiasing at all; kEdgeFilter (the default) = one sample, then the edge filter.
  int msaa = kEdgeFilter;
  Color background = Color(0.78, 0.84, 0.9);
  // [render] background = "transparent": alpha 0 wherever no surface is drawn (the colour there
  // is `background`, unseen), alpha 1 on surfaces, overlays and text with their own alpha, all
  // straight (render/straight_alpha.hpp); the ground is not drawn, only the shadows on
  // it, as partly transparent black (docs/scene-reference.md says why).
  bool transparent = false;
  DirectionalLight light;
  Ground ground;
  bool shadows = true;
  Look look;
  Backend backend = Backend::automatic;  // [render] backend; tumble render's --backend overrides
  // [render] egl_device; --egl-device overrides: an index into EGL's device list
  // (eglQueryDevicesEXT's order), drawn on through EGL's device platform; or kAutomaticEglDevice.
  int egl_device = kAutomaticEglDevice;
  // [render] motion_blur = { samples = S, shutter = F }: each frame the average, in linear light,
  // of S pictures of the bodies at S times spread evenly over F of a frame's interval, centred on
  // the frame's time; overlays and texts are the frame's own. 1 sample (the default) is no blur.
  MotionBlur motion_blur;
};

}  // namespace tumble::common
