// Lines and arrows drawn by the renderer in the 3D scene: an arrow's tip where the camera
// projects it, the part a body hides drawn faint, and frames without them on today's path, byte
// for byte. Goldens of each overlay kind, drawn from a scene, are in app/overlay_view_test.cpp.
#include "render/overlay_layer.hpp"

#include <gtest/gtest.h>

#include "render/font.hpp"

#include <cmath>
#include <string>

#include "render/geometry.hpp"
#include "render/overlay_geometry.hpp"
#include "render/renderer.hpp"
#include "support/render_golden.hpp"
#include "support/result_text.hpp"

namespace tumble::render {
namespace {

using testing::draw;
using testing::kShaders;

const Rgba kMagenta(1.0, 0.0, 1.0, 1.0);

RenderSettings overlay_settings(int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.ground.enabled = false;
  settings.shadows = false;
  settings.overlays = true;
  return settings;
}

FrameView cube_with_arrow() {
  FrameView view;
  view.camera.position = Vec3(2.6, 2.0, 3.6);
  view.boxes.push_back(Box{.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY()))});
  view.arrows.push_back(Arrow{.from = Vec3::Zero(), .to = Vec3(1.4, 0.9, -0.3), .color = kMagenta});
  return view;
}

// The arrow's colour at least half over the background (the edge filter blends its edges).
bool is_magenta(const std::uint8_t* pixel) {
  return pixel[0] - pixel[1] > 128 && pixel[2] - pixel[1] > 128;
}

// The tip, projected with the frame's camera (the renderer's matrices: near and far do not move
// a point's x and y), against the magenta pixel farthest along the arrow on the picture.
void expect_tip_within_two_pixels(int width, int height) {
  const FrameView view = cube_with_arrow();
  const io::Image image = draw(overlay_settings(width, height), view);
  ASSERT_EQ(image.width, width);
  const Camera& camera = view.camera;
  const Mat4 view_projection = perspective(camera.fov_degrees * M_PI / 180.0,
                                           static_cast<double>(width) / height, 0.1, 100.0) *
                               look_at(camera.position, camera.look_at, camera.up);
  const auto base = project_to_pixel(view_projection, view.arrows[0].from, width, height);
  const auto tip = project_to_pixel(view_projection, view.arrows[0].to, width, height);
  ASSERT_TRUE(base && tip);
  const Eigen::Vector2d direction = (*tip - *base).normalized();
  double farthest = -1e9;
  Eigen::Vector2d farthest_pixel;
  int count = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!is_magenta(image.row(y) + 3 * x)) continue;
      ++count;
      const Eigen::Vector2d centre(x + 0.5, y + 0.5);
      if ((centre - *base).dot(direction) > farthest) {
        farthest = (centre - *base).dot(direction);
        farthest_pixel = centre;
      }
    }
  }
  ASSERT_GT(count, 10) << "no arrow drawn";
  EXPECT_LE((farthest_pixel - *tip).norm(), 2.0)
      << width << "x" << height << ": tip projected at (" << tip->x() << ", " << tip->y()
      << "), farthest arrow pixel at (" << farthest_pixel.x() << ", " << farthest_pixel.y() << ")";
}

TEST(OverlayLayer, ArrowTipIsWithinTwoPixelsOfItsProjectionAt320x180) {
  expect_tip_within_two_pixels(320, 180);
}

TEST(OverlayLayer, ArrowTipIsWithinTwoPixelsOfItsProjectionAt1280x720) {
  expect_tip_within_two_pixels(1280, 720);
}

// Where the cube hides the shaft (its start, at the cube's centre) the arrow is drawn at
// kHiddenOpacity over the cube: neither the cube alone nor the arrow's colour. No edge filter,
// so the pixels are the blend itself: 0.3 × magenta + 0.7 × cube, within 2 of 255.
TEST(OverlayLayer, ThePartABodyHidesIsDrawnFaint) {
  RenderSettings settings = overlay_settings(1280, 720);  // a shaft 5 px wide
  settings.msaa = 1;
  const FrameView with = cube_with_arrow();
  FrameView without = with;
  without.arrows.clear();
  const io::Image a = draw(settings, with), b = draw(settings, without);
  const Mat4 view_projection =
      perspective(with.camera.fov_degrees * M_PI / 180.0, 1280.0 / 720.0, 0.1, 100.0) *
      look_at(with.camera.position, with.camera.look_at, with.camera.up);
  // A tenth of the way along the arrow: inside the cube, seen through its front faces.
  const auto inside = project_to_pixel(view_projection, 0.1 * with.arrows[0].to, 1280, 720);
  ASSERT_TRUE(inside);
  const int x = static_cast<int>(inside->x()), y = static_cast<int>(inside->y());
  const std::uint8_t* drawn = a.row(y) + 3 * x;
  const std::uint8_t* cube = b.row(y) + 3 * x;
  for (int c = 0; c < 3; ++c) {
    const double expected = kHiddenOpacity * 255.0 * kMagenta[c] + (1.0 - kHiddenOpacity) * cube[c];
    EXPECT_NEAR(drawn[c], expected, 2.0) << "channel " << c;
  }
}

// A renderer that draws overlays gives a frame without any the bytes of one that does not.
TEST(OverlayLayer, FramesWithoutOverlaysAreThoseOfARendererWithoutThem) {
  for (const int msaa : {kEdgeFilter, 4}) {
    RenderSettings settings = overlay_settings(320, 180);
    settings.msaa = msaa;
    settings.ground.enabled = true;
    settings.shadows = true;
    RenderSettings without = settings;
    without.overlays = false;
    std::string error;
    const auto renderer =
        ::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error);
    ASSERT_TRUE(renderer) << error;
    FrameView plain = cube_with_arrow();
    plain.arrows.clear();
    io::Image with_arrow, after;
    renderer->draw(cube_with_arrow(), with_arrow);
    renderer->draw(plain, after);
    EXPECT_EQ(after.rgb, draw(without, plain).rgb) << "msaa " << msaa;
    EXPECT_NE(with_arrow.rgb, after.rgb) << "msaa " << msaa;
  }
}

// Six vertices (two triangles) a line segment; an arrow's shaft and head nine; what is behind
// the camera nothing; a segment crossing the near plane cut, not dropped.
// A zero vector (and one too short to read, under kMinArrowPixels on the picture) draws neither
// its arrow nor its label: the frame is the cube's alone, byte for byte. One just long enough
// draws both.
TEST(OverlayLayer, AnArrowTooShortToReadDrawsNeitherItselfNorItsLabel) {
  RenderSettings settings = overlay_settings(320, 180);
  settings.font = std::string(kDefaultFontFamily);
  FrameView plain = cube_with_arrow();
  plain.arrows.clear();
  const io::Image expected = draw(settings, plain);
  FrameView zero = plain;
  zero.arrows.push_back(Arrow{
      .from = Vec3(0.5, 0.5, 0.5), .to = Vec3(0.5, 0.5, 0.5), .color = kMagenta, .label = "L"});
  EXPECT_EQ(draw(settings, zero).rgb, expected.rgb);
  // 1 mm at ~4.7 m: about 0.04 px at 180 rows, under the 3 px (at 720 rows) to read it.
  FrameView tiny = plain;
  tiny.arrows.push_back(Arrow{
      .from = Vec3(0.5, 0.5, 0.5), .to = Vec3(0.501, 0.5, 0.5), .color = kMagenta, .label = "L"});
  EXPECT_EQ(draw(settings, tiny).rgb, expected.rgb);
  FrameView shown = plain;
  shown.arrows.push_back(Arrow{
      .from = Vec3(0.5, 0.5, 0.5), .to = Vec3(1.5, 0.5, 0.5), .color = kMagenta, .label = "L"});
  EXPECT_NE(draw(settings, shown).rgb, expected.rgb);
}

TEST(OverlayGeometry, TrianglesPerItemAndTheNearPlane) {
  const Mat4 view_projection = perspective(M_PI / 4.0, 16.0 / 9.0, 0.1, 100.0) *
                               look_at(Vec3(0, 0, 5), Vec3::Zero(), Vec3::UnitY());
  const auto vertices = [&](const std::vector<Polyline>& lines, const std::vector<Arrow>& arrows) {
    return overlay_triangles(lines, arrows, view_projection, 1280, 720).size() /
           kOverlayFloatsPerVertex;
  };
  const Polyline line{.points = {Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 0)},
                      .opacity = {0.0, 0.5, 1.0}};
  EXPECT_EQ(vertices({line}, {}), 12u);
  EXPECT_EQ(vertices({}, {Arrow{.from = Vec3::Zero(), .to = Vec3(1, 0, 0)}}), 9u);
  EXPECT_EQ(vertices({}, {Arrow{.from = Vec3(0, 0, 6), .to = Vec3(1, 0, 7)}}), 0u);  // behind
  EXPECT_EQ(vertices({}, {Arrow{.from = Vec3::Zero(), .to = Vec3(0, 0, 0.0001)}}), 0u);
  // From in front to behind the camera: the shaft to the near plane, no head.
  EXPECT_EQ(vertices({}, {Arrow{.from = Vec3(0.5, 0, 0), .to = Vec3(0.5, 0, 8)}}), 6u);
  const Polyline crossing{.points = {Vec3(0, 0, 0), Vec3(0, 1, 9)}, .opacity = {1.0, 1.0}};
  EXPECT_EQ(vertices({crossing}, {}), 6u);
}

// A trail's points that one band draws within a quarter pixel and half an opacity level are one
// band: a straight line fading evenly is one, however many points; a bend, a kink in its fading,
// or a point beyond the near plane ends a band; a circle keeps every point within a quarter pixel
// of the bands drawn.
TEST(OverlayGeometry, StraightRunsOfALineAreOneBand) {
  const Mat4 view_projection = perspective(M_PI / 4.0, 16.0 / 9.0, 0.1, 100.0) *
                               look_at(Vec3(0, 0, 5), Vec3::Zero(), Vec3::UnitY());
  const auto bands = [&](const Polyline& line) {
    return overlay_triangles({line}, {}, view_projection, 1280, 720).size() /
           kOverlayFloatsPerVertex / 6;
  };
  Polyline straight;  // across the picture at the camera's depth: even on the picture too
  for (int i = 0; i <= 40; ++i) {
    straight.points.push_back(Vec3(-1.0 + 0.05 * i, 0.0, 0.0));
    straight.opacity.push_back(i / 40.0);
  }
  EXPECT_EQ(bands(straight), 1u);
  Polyline receding = straight;  // away from the camera: opacity interpolated as GL does
  for (Vec3& point : receding.points) point.z() = -2.0 - point.x();
  EXPECT_EQ(bands(receding), 1u);
  Polyline kinked_fade = straight;
  kinked_fade.opacity[20] = 0.6;  // 0.5 on the straight fade
  // Points 0-19 and 21-40 are each one band; the segments either side of 20 bands of their own
  // (a band from 0 to 20 would fade 19 towards 0.6, not hold it at 0.475).
  EXPECT_EQ(bands(kinked_fade), 4u);
  Polyline bent = straight;
  bent.points[20].y() = 0.01;  // about 1.7 px off the chord at 720p
  EXPECT_EQ(bands(bent), 4u);  // as the kink
  Polyline through_camera = straight;
  through_camera.points[40].z() = 6.0;  // behind the camera at z = 5
  // Points 0-39 one band; the last segment its own, cut at the near plane.
  EXPECT_EQ(bands(through_camera), 2u);

  Polyline circle;  // 121 points of a circle of 1 m seen face on: about 270 px across
  for (int i = 0; i <= 120; ++i) {
    const double angle = 2.0 * M_PI * i / 120.0;
    circle.points.push_back(Vec3(std::cos(angle), std::sin(angle), 0.0));
    circle.opacity.push_back(1.0);
  }
  const std::vector<float> triangles = overlay_triangles({circle}, {}, view_projection, 1280, 720);
  const std::size_t drawn = triangles.size() / kOverlayFloatsPerVertex / 6;
  EXPECT_GT(drawn, 4u);
  EXPECT_LT(drawn, 120u);
  // Every point within a quarter pixel of some band's centre line, on the picture.
  const auto on_picture = [](const float* vertex) {
    return Eigen::Vector2d(vertex[0] / vertex[3] * 640.0, vertex[1] / vertex[3] * 360.0);
  };
  for (const Vec3& point : circle.points) {
    const Eigen::Vector2d p =
        *project_to_pixel(view_projection, point, 1280, 720) - Eigen::Vector2d(640.0, 360.0);
    const Eigen::Vector2d q(p.x(), -p.y());  // y up, as clip space
    double nearest = 1e9;
    for (std::size_t band = 0; band < drawn; ++band) {
      const float* v = &triangles[band * 6 * kOverlayFloatsPerVertex];
      // Vertices 0 and 1 straddle the start, 2 and 5 the end.
      const Eigen::Vector2d a = 0.5 * (on_picture(v) + on_picture(v + kOverlayFloatsPerVertex));
      const Eigen::Vector2d b = 0.5 * (on_picture(v + 2 * kOverlayFloatsPerVertex) +
                                       on_picture(v + 5 * kOverlayFloatsPerVertex));
      const double s = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (q - a - s * (b - a)).norm());
    }
    EXPECT_LE(nearest, 0.25 + 1e-3);
  }
}

}  // namespace
}  // namespace tumble::render
