// The look of the light (docs/scene-reference.md, "Lighting"), measured on frames of a unit cube
// resting on the ground at 1280 × 720: its shadow meets its base (no gap of light wider than a
// pixel), its penumbra widens away from the contact as a light shadow_softness degrees across
// makes it, and the ambient occlusion darkens the ground within a box width of the base and
// not at all beyond two.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/geometry.hpp"
#include "render/occluders.hpp"
#include "render/overlay_geometry.hpp"
#include "render/renderer.hpp"
#include "support/render_golden.hpp"

namespace tumble::render {
namespace {

using testing::draw;

constexpr int kWidth = 1280, kHeight = 720;

double linear(double level) {
  const double c = level / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgb_from_linear(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

RenderSettings cube_settings() {
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.ground.height = 0.0;
  settings.ground.grid_spacing = 0.0;  // a plain floor: nothing but light changes its level
  settings.msaa = 1;                   // the pixels as shaded, no edge filter between them
  return settings;
}

FrameView cube_view(const Vec3& eye, const Vec3& target) {
  FrameView view;
  view.camera.position = eye;
  view.camera.look_at = target;
  view.boxes.push_back(Box{.position = Vec3(0.0, 0.5, 0.0), .color = Color(0.8, 0.1, 0.1)});
  return view;
}

struct Frame {
  io::Image image;
  Mat4 view_projection;
  // Green channel, linear and as stored, at the pixel the world point lands on.
  double green(const Vec3& point) const { return linear(green_level(point)); }
  int green_level(const Vec3& point) const {
    const auto pixel = project_to_pixel(view_projection, point, kWidth, kHeight);
    EXPECT_TRUE(pixel);
    const int x = std::clamp(static_cast<int>(pixel->x()), 0, kWidth - 1);
    const int y = std::clamp(static_cast<int>(pixel->y()), 0, kHeight - 1);
    return image.row(y)[3 * x + 1];
  }
  int level(int x, int y, int channel) const { return image.row(y)[3 * x + channel]; }
};

Frame render(const RenderSettings& settings, const FrameView& view) {
  Frame out;
  out.image = draw(settings, view);
  out.view_projection = perspective(view.camera.fov_degrees * M_PI / 180.0,
                                    static_cast<double>(kWidth) / kHeight, 0.1, 100.0) *
                        look_at(view.camera.position, view.camera.look_at, view.camera.up);
  return out;
}

// The fraction of the key light a ground pixel lacks: 0 lit, 1 in full shadow, from the same
// frame with and without shadows (the ground's light is ambient + diffuse, its shadow ambient).
struct ShadowFraction {
  Frame lit, shadowed;
  double key_share;  // diffuse / (ambient + diffuse) of the ground
  double at(const Vec3& point) const {
    const double off = lit.green(point), on = shadowed.green(point);
    return (off - on) / (off * key_share);
  }
};

// The cube seen from where its shadow falls (the light travels to +x and -z).
const Vec3 kShadowEye(1.5, 2.5, -4.5);
const Vec3 kShadowTarget(0.2, 0.2, -0.7);

ShadowFraction shadow_fraction(const common::Look& look) {
  RenderSettings settings = cube_settings();
  settings.look = look;
  settings.look.ambient_occlusion = 0.0;
  ShadowFraction out;
  out.shadowed = render(settings, cube_view(kShadowEye, kShadowTarget));
  settings.shadows = false;
  out.lit = render(settings, cube_view(kShadowEye, kShadowTarget));
  const double diffuse = -settings.light.direction.normalized().y();
  out.key_share = diffuse / (settings.light.ambient + diffuse);
  return out;
}

// Walking on the picture from the cube's base outward, the first pixel of ground and every pixel
// after it are in shadow (fraction above one half): no line of light between cube and shadow.
TEST(Look, TheShadowOfACubeRestingOnTheFloorMeetsItsBase) {
  for (const common::Look& look : {common::Look{}, common::Look::plain()}) {
    SCOPED_TRACE(look.shadow_softness > 0.0 ? "soft" : "plain");
    const ShadowFraction shadow = shadow_fraction(look);
    // Points on the two edges of the base the shadow leaves from, each with its way out.
    struct Start {
      Vec3 base, outward;
    };
    const Start starts[] = {{Vec3(-0.3, 0, -0.5), -Vec3::UnitZ()},
                            {Vec3(0.1, 0, -0.5), -Vec3::UnitZ()},
                            {Vec3(0.4, 0, -0.5), -Vec3::UnitZ()},
                            {Vec3(0.5, 0, -0.3), Vec3::UnitX()},
                            {Vec3(0.5, 0, 0.1), Vec3::UnitX()}};
    for (const Start& start : starts) {
      const Eigen::Vector2d from =
          *project_to_pixel(shadow.lit.view_projection, start.base, kWidth, kHeight);
      const Eigen::Vector2d ahead = *project_to_pixel(
          shadow.lit.view_projection, start.base + 0.2 * start.outward, kWidth, kHeight);
      const Eigen::Vector2d step = (ahead - from).normalized();
      int first_ground = -1;
      for (int k = 0; k <= 12; ++k) {
        const Eigen::Vector2d p = from + k * step;
        const int x = static_cast<int>(p.x()), y = static_cast<int>(p.y());
        // The cube is red with a dark frame; the ground, without shadows, a light grey.
        const bool cube = shadow.lit.level(x, y, 0) > shadow.lit.level(x, y, 1) + 40 ||
                          shadow.lit.level(x, y, 1) < 110;
        if (cube) continue;
        if (first_ground < 0) first_ground = k;
        const double off = linear(shadow.lit.level(x, y, 1));
        const double on = linear(shadow.shadowed.level(x, y, 1));
        const double fraction = (off - on) / (off * shadow.key_share);
        EXPECT_GT(fraction, 0.5) << "from (" << start.base.transpose() << "), pixel " << k
                                 << " of the walk, " << k - first_ground << " past the cube's edge";
      }
      EXPECT_GE(first_ground, 0);
      EXPECT_LE(first_ground, 3) << "the walk should leave the cube within 3 pixels";
    }
  }
}

// Where the shadow fraction falls through 0.8 and through 0.2 along `across` (unit, on the
// ground, from inside the shadow to outside) from each of `starts`, averaged over them; their
// distance (m): the width of the penumbra there.
double penumbra_width(const ShadowFraction& shadow, const std::vector<Vec3>& starts,
                      const Vec3& across, double length) {
  constexpr int kSamples = 400;
  std::vector<double> profile(kSamples + 1, 0.0);
  for (int i = 0; i <= kSamples; ++i) {
    for (const Vec3& start : starts) {
      profile[i] += shadow.at(start + across * (length * i / kSamples)) / starts.size();
    }
  }
  const auto first_below = [&](double level) {
    for (int i = 0; i <= kSamples; ++i) {
      if (profile[i] < level) return length * i / kSamples;
    }
    return length;
  };
  return first_below(0.2) - first_below(0.8);
}

TEST(Look, ThePenumbraWidensAwayFromTheContact) {
  const common::Look look;  // the default: a light 4 degrees across
  const ShadowFraction shadow = shadow_fraction(look);
  // Near the base: across the shadow of the cube's vertical edge at (-0.5, y, -0.5), 0.1 to
  // 0.2 m above the floor. The light travels (0.25, -1.2, -0.75): per metre of height the
  // edge's shadow moves (0.208, -0.625) on the floor; outside is to the -x side of it.
  const Vec3 along = Vec3(0.25 / 1.2, 0.0, -0.75 / 1.2).normalized();
  const Vec3 out_near = Vec3(-along.z(), 0.0, along.x()).x() < 0.0
                            ? Vec3(-along.z(), 0.0, along.x())
                            : Vec3(along.z(), 0.0, -along.x());
  std::vector<Vec3> near_starts;
  for (const double y : {0.1, 0.125, 0.15, 0.175, 0.2}) {
    near_starts.push_back(Vec3(-0.5 + 0.25 / 1.2 * y, 0.0, -0.5 - 0.75 / 1.2 * y) -
                          0.06 * out_near);
  }
  const double near = penumbra_width(shadow, near_starts, out_near, 0.12);
  // Far: across the shadow of the cube's top edge (y = 1), at z = -0.5 - 0.625 = -1.125.
  std::vector<Vec3> far_starts;
  for (const double x : {-0.1, 0.0, 0.1, 0.2, 0.3}) far_starts.push_back(Vec3(x, 0.0, -0.925));
  const double far = penumbra_width(shadow, far_starts, -Vec3::UnitZ(), 0.4);
  // The light's size casts a penumbra 2 d tan(2°) wide at distance d = 1.2 m behind the top
  // edge, measured across the light; on the floor, 1 / cos(33.5°) wider: 0.10 m, of which the
  // 20-80% band of a disk filter is about a third.
  std::printf("[ measured ] penumbra 20-80%%: %.4f m near the base, %.4f m at the far edge\n", near,
              far);
  EXPECT_GT(far, 2.0 * near);
  EXPECT_GT(far, 0.015);
  EXPECT_LT(far, 0.1);
  // And the plain look's hard shadow is about a texel wide everywhere.
  const ShadowFraction hard = shadow_fraction(common::Look::plain());
  EXPECT_LT(penumbra_width(hard, far_starts, -Vec3::UnitZ(), 0.4), 0.5 * far);
}

// Shadows off, so the floor beside the lit side of the cube is lit: with occlusion it is
// darker within a box width of the base, and the same bytes beyond two widths.
TEST(Look, OcclusionDarkensTheFloorWithinABoxWidthAndNotBeyondTwo) {
  RenderSettings settings = cube_settings();
  settings.shadows = false;
  const FrameView view = cube_view(Vec3(1.5, 2.5, 4.8), Vec3(0.1, 0.2, 1.0));
  const Frame occluded = render(settings, view);
  settings.look.ambient_occlusion = 0.0;
  const Frame open = render(settings, view);
  double previous = 0.0;
  for (const double widths : {0.1, 0.25, 0.5, 0.75, 0.9}) {
    const Vec3 point(0.1, 0.0, 0.5 + widths);
    const double ratio = occluded.green(point) / open.green(point);
    std::printf("[ measured ] %.2f box widths from the base: the floor at %.4f of its light\n",
                widths, ratio);
    EXPECT_LT(ratio, 0.995) << widths << " widths";  // at least half a percent darker
    EXPECT_GE(ratio, previous - 1e-3) << "less dark further out";
    previous = ratio;
  }
  // At a box width, a trace of it (it fades to nothing at 1.25 widths).
  EXPECT_LT(occluded.green(Vec3(0.1, 0.0, 1.5)), open.green(Vec3(0.1, 0.0, 1.5)));
  for (const double widths : {1.3, 2.0, 2.5, 3.0}) {
    for (const double x : {-0.4, 0.1, 0.4}) {
      const Vec3 point(x, 0.0, 0.5 + widths + 0.01);
      EXPECT_EQ(occluded.green(point), open.green(point)) << widths << " widths, x " << x;
    }
  }
}

}  // namespace
}  // namespace tumble::render

namespace tumble::render {
namespace {

// The fraction of a uniform sky, cosine-weighted over the hemisphere of the unit `normal` at
// `point`, that the axis-aligned box [low, high] hides: a quadrature over 300 × 300 directions
// (Malley's method: points spread evenly on the unit disk, lifted to the hemisphere), each ray
// tested against the box's slabs. An estimate independent of the shaders' closed form.
double box_form_factor_by_rays(const Vec3& point, const Vec3& low, const Vec3& high,
                               const Vec3& normal = Vec3::UnitY()) {
  const Vec3 across = normal.unitOrthogonal(), along = normal.cross(across);
  constexpr int kSide = 300;
  int hits = 0;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const double u = (i + 0.5) / kSide, v = (j + 0.5) / kSide;
      const double r = std::sqrt(u), angle = 2.0 * M_PI * v;
      const Vec3 d =
          r * std::cos(angle) * across + r * std::sin(angle) * along + std::sqrt(1.0 - u) * normal;
      double near = 0.0, far = 1e30;
      for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(d[axis]) < 1e-12) {
          if (point[axis] < low[axis] || point[axis] > high[axis]) far = -1.0;
          continue;
        }
        double t0 = (low[axis] - point[axis]) / d[axis], t1 = (high[axis] - point[axis]) / d[axis];
        if (t0 > t1) std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
      }
      hits += near <= far ? 1 : 0;
    }
  }
  return static_cast<double>(hits) / (kSide * kSide);
}

// A light grey body of unit size (`solid`: a cube, a ball) resting on a table, a box 4 × 0.5 × 4 m
// whose top is at y = 0.5: its frames with the settings' occlusion and without any.
struct OnTable {
  Frame occluded, open;
};
OnTable on_table(RenderSettings settings, const Vec3& eye, const Vec3& target, Solid solid) {
  FrameView view = cube_view(eye, target);
  // Bright: a level is a small step of its light.
  view.boxes[0] =
      Box{.position = Vec3(0.0, 1.0, 0.0), .color = Color(0.9, 0.9, 0.9), .solid = solid};
  view.boxes.push_back(Box{.position = Vec3(0.0, 0.25, 0.0),
                           .size = Vec3(4.0, 0.5, 4.0),
                           .color = Color(0.8, 0.8, 0.8)});
  OnTable out;
  out.occluded = render(settings, view);
  settings.look.ambient_occlusion = 0.0;
  out.open = render(settings, view);
  return out;
}

// A unit cube resting on a table (a box 4 × 0.5 × 4 m whose top is at y = 0.5): the table's top
// beside the cube receives the cube's occlusion (form_factor.glsl, per pixel). Its light there is
// 1 - s F f of its light without occlusion, s the fill's share of that light, F the cube's form
// factor (by rays, above) and f the fade past half the reach: within a level of that out to a box
// width, and the same bytes beyond 1.3 widths.
TEST(Look, OcclusionDarkensABoxTopBesideACubeByItsFormFactor) {
  RenderSettings settings = cube_settings();
  settings.shadows = false;
  const OnTable frames = on_table(settings, Vec3(1.5, 3.0, 4.8), Vec3(0.1, 0.7, 1.0), Solid::box);
  const Frame& occluded = frames.occluded;
  const Frame& open = frames.open;
  const double diffuse = -settings.light.direction.normalized().y();
  const double fill_share = settings.light.ambient / (settings.light.ambient + diffuse);
  const double reach = kOcclusionReach;  // × the cube's edge, 1 m
  for (const double widths : {0.1, 0.25, 0.5, 0.75, 0.9}) {
    const Vec3 point(0.1, 0.5, 0.5 + widths);
    const double ratio = occluded.green(point) / open.green(point);
    const double t = std::clamp((widths - 0.5 * reach) / (0.5 * reach), 0.0, 1.0);
    const double fade = 1.0 - t * t * (3.0 - 2.0 * t);
    const double form_factor =
        box_form_factor_by_rays(point, Vec3(-0.5, 0.5, -0.5), Vec3(0.5, 1.5, 0.5));
    const double expected = 1.0 - fill_share * form_factor * fade;
    std::printf(
        "[ measured ] %.2f box widths from the base: the table top at %.4f of its light "
        "(form factor %.4f: %.4f expected)\n",
        widths, ratio, form_factor, expected);
    // Within a level of 255 (a level is about 1 % of the light at the table's 193): the open
    // top's light times the expected fraction, encoded.
    const double predicted = 255.0 * srgb_from_linear(open.green(point) * expected);
    EXPECT_NEAR(occluded.green_level(point), predicted, 1.0) << widths << " widths";
    std::printf("[ measured ] levels %d open, %d occluded, %.2f predicted\n",
                open.green_level(point), occluded.green_level(point), predicted);
  }
  for (const double widths : {1.3, 1.4}) {
    for (const double x : {-0.4, 0.1, 0.4}) {
      const Vec3 point(x, 0.5, 0.5 + widths + 0.01);
      EXPECT_EQ(occluded.green(point), open.green(point)) << widths << " widths, x " << x;
    }
  }
  // The cube's side facing +z receives the table's occlusion, the table cut to the half in front
  // of the face (its top, seen from beside it): 0.48 of the sky near the bottom edge, 0.21 near
  // the top. The face's fill share is less than the top's (the hemisphere turned sideways, more
  // key light): the same formula, within a level.
  const Vec3 normal = Vec3::UnitZ();
  const double hemisphere = 1.0 - 0.5 * settings.look.fill_light;
  const double side_diffuse = normal.dot(-settings.light.direction.normalized());
  const double side_share =
      settings.light.ambient * hemisphere / (settings.light.ambient * hemisphere + side_diffuse);
  for (const double height : {0.55, 0.8, 1.45}) {
    const Vec3 point(0.1, height, 0.5);
    const double form_factor =
        box_form_factor_by_rays(point + 1e-4 * normal, Vec3(-2, 0, -2), Vec3(2, 0.5, 2), normal);
    const double expected = 1.0 - side_share * form_factor;
    const double predicted = 255.0 * srgb_from_linear(open.green(point) * expected);
    std::printf(
        "[ measured ] the cube's side %.2f m up: levels %d open, %d occluded, %.2f "
        "predicted (form factor %.4f)\n",
        height, open.green_level(point), occluded.green_level(point), predicted, form_factor);
    EXPECT_NEAR(occluded.green_level(point), predicted, 1.0) << height << " m up";
  }
}

// A ball (radius 0.5 m) resting on the same table: a point of it below its equator, turned to
// the camera, receives the table's occlusion (the table cut to the ball's tangent plane there).
// Its light is the light without occlusion less the fill's part of it times the form factor:
// exposure × ambient × hemisphere(n) × albedo × F, within a level.
TEST(Look, OcclusionDarkensABallBesideTheTableItRestsOn) {
  RenderSettings settings = cube_settings();
  settings.shadows = false;
  settings.round_solids = true;
  const OnTable frames = on_table(settings, Vec3(1.5, 2.0, 4.0), Vec3(0.1, 0.8, 0.5), Solid::ball);
  const Frame& occluded = frames.occluded;
  const Frame& open = frames.open;
  const double exposure = settings.look.exposure_for(settings.light);
  const double albedo = linear(255.0 * 0.9);
  for (const double down : {0.2, 0.45, 0.7}) {
    const Vec3 normal = Vec3(0.3, -down, 0.84).normalized();
    const Vec3 point = Vec3(0.0, 1.0, 0.0) + 0.5 * normal;
    const double form_factor =
        box_form_factor_by_rays(point + 1e-4 * normal, Vec3(-2, 0, -2), Vec3(2, 0.5, 2), normal);
    const double hemisphere =
        (1.0 - settings.look.fill_light) + settings.look.fill_light * (0.5 * normal.y() + 0.5);
    const double fill = exposure * settings.light.ambient * hemisphere * albedo;
    const double predicted = 255.0 * srgb_from_linear(open.green(point) - fill * form_factor);
    std::printf(
        "[ measured ] the ball's side, normal %.2f down: levels %d open, %d occluded, "
        "%.2f predicted (form factor %.4f)\n",
        -normal.y(), open.green_level(point), occluded.green_level(point), predicted, form_factor);
    EXPECT_NEAR(occluded.green_level(point), predicted, 1.0) << down;
  }
}

}  // namespace
}  // namespace tumble::render
