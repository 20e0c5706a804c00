// Golden-image and determinism tests of the renderer. Goldens live in tests/render/golden/; to
// regenerate them after an intended change of the look, run the test with TUMBLE_UPDATE_GOLDEN=1
// and look at the new images before committing them.
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "diff/image_diff.hpp"
#include "io/png_io.hpp"
#include "render/geometry.hpp"
#include "support/render_golden.hpp"
#include "support/result_text.hpp"

namespace tumble::render {
namespace {

using testing::draw;
using testing::kGoldens;
using testing::kShaders;

// Same machine, same Mesa: renders are bit-identical (see DrawingTwiceIsByteIdentical). The
// tolerance absorbs another Mesa or LLVM version rounding a shading or rasterisation decision
// differently: a pixel may differ by up to 8 of 255 per channel, and up to 1% of pixels by more.
constexpr diff::DiffOptions kGoldenTolerance{.threshold = 8, .max_pixels = 160 * 120 / 100};

// 4 samples per pixel, as the goldens were drawn before the edge filter became the default; the
// plain look, as they were drawn before soft shadows, occlusion and exposure (the default look's
// goldens are tests/render/look_golden_test.cpp's).
RenderSettings small_settings() {
  RenderSettings settings;
  settings.look = common::Look::plain();
  settings.width = 160;
  settings.height = 120;
  settings.msaa = 4;
  settings.ground.height = -1.0;
  return settings;
}

FrameView cube_view(const Quat& orientation) {
  FrameView view;
  view.camera.position = Vec3(2.6, 2.0, 3.6);
  view.boxes.push_back(Box{.orientation = orientation});
  return view;
}

void expect_matches_golden(const io::Image& image, const std::string& name) {
  testing::expect_matches_golden(image, name, kGoldenTolerance);
}

TEST(Renderer, CubeAtRestMatchesGolden) {
  expect_matches_golden(draw(small_settings(), cube_view(Quat::Identity())), "cube_at_rest");
}

TEST(Renderer, TiltedBoxMatchesGolden) {
  FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.7, Vec3(1, 0.5, 0.2).normalized())));
  view.boxes[0].size = Vec3(0.4, 1.0, 1.6);
  view.boxes[0].color = Color(0.2, 0.5, 0.8);
  expect_matches_golden(draw(small_settings(), view), "tilted_box");
}

TEST(Renderer, TwoBoxesWithoutGroundOrShadowsOrMsaaMatchGolden) {
  RenderSettings settings = small_settings();
  settings.ground.enabled = false;
  settings.shadows = false;
  settings.msaa = 1;
  FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY())));
  view.boxes.push_back(Box{.position = Vec3(-1.2, 0.3, -0.5), .color = Color(0.3, 0.7, 0.3)});
  expect_matches_golden(draw(settings, view), "two_boxes_plain");
}

// A transparent background: the same colours where surfaces are, alpha 255 on the cube and 0
// where nothing is drawn; the ground is left out but for the cube's shadow, partly transparent
// black at most diffuse / (ambient + diffuse) opaque; an opaque render has no alpha plane.
TEST(Renderer, TransparentBackgroundKeepsTheCubeAndItsShadowOnly) {
  RenderSettings settings = small_settings();
  const FrameView view = cube_view(Quat::Identity());
  const io::Image opaque = draw(settings, view);
  EXPECT_TRUE(opaque.alpha.empty());
  settings.transparent = true;
  const io::Image clear = draw(settings, view);
  ASSERT_EQ(clear.alpha.size(), 160u * 120u);
  EXPECT_EQ(clear.alpha[0], 0);                // the sky
  EXPECT_EQ(clear.alpha[119 * 160 + 0], 0);    // lit ground, bottom-left corner
  EXPECT_EQ(clear.alpha[60 * 160 + 80], 255);  // the cube
  EXPECT_EQ(std::vector<std::uint8_t>(clear.rgb.begin() + 3 * (60 * 160 + 80),
                                      clear.rgb.begin() + 3 * (60 * 160 + 81)),
            std::vector<std::uint8_t>(opaque.rgb.begin() + 3 * (60 * 160 + 80),
                                      opaque.rgb.begin() + 3 * (60 * 160 + 81)));
  const double direction_y = settings.light.direction.normalized().y();
  const double darkest = -direction_y / (settings.light.ambient - direction_y);  // 0.736
  int partial = 0, most = 0;
  for (const std::uint8_t alpha : clear.alpha) {
    if (alpha == 0 || alpha == 255) continue;
    ++partial;
    most = std::max<int>(most, alpha);
  }
  EXPECT_GT(partial, 100);  // the shadow, over a few hundred pixels
  // Multisampled: an edge of the shadow may also blend with the cube's own alpha 255, so the
  // largest partial alpha is the shadow's core within 2 levels, or above it.
  EXPECT_GE(most, static_cast<int>(std::lround(255 * darkest)) - 2);
}

// The cube on a floor just under it, with a 4 m × 3 m wall.
FrameView wall_view(const Vec3& wall_center, const Vec3& wall_front, const Color& color) {
  FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY())));
  view.quads.push_back(Quad{.center = wall_center,
                            .orientation = Quat::FromTwoVectors(Vec3::UnitY(), wall_front),
                            .width = 4.0,
                            .depth = 3.0,
                            .color = color,
                            .grid_spacing = 0.5});
  return view;
}

RenderSettings floor_settings() {
  RenderSettings settings = small_settings();
  settings.ground.height = -0.5;  // the cube rests on it
  return settings;
}

// Behind the cube, its front towards the camera (so opaque), in blue to tell it from the ground.
const Vec3 kWallBehind(0.0, 0.5, -1.5);
const Color kBlue(0.3, 0.5, 0.9);

TEST(Renderer, WallBehindTheCubeMatchesGolden) {
  expect_matches_golden(draw(floor_settings(), wall_view(kWallBehind, Vec3::UnitZ(), kBlue)),
                        "wall_behind_cube");
}

// Where the wall stands, the picture shows it (blue, lit) instead of the far ground; the cube in
// front of it is untouched, and so is the floor nearer the camera.
TEST(Renderer, WallBehindTheCubeIsDrawnAndHidesNothingInFrontOfIt) {
  FrameView without = wall_view(kWallBehind, Vec3::UnitZ(), kBlue);
  without.quads.clear();
  const io::Image bare = draw(floor_settings(), without);
  const io::Image walled = draw(floor_settings(), wall_view(kWallBehind, Vec3::UnitZ(), kBlue));
  ASSERT_EQ(walled.width, 160);
  const std::uint8_t* wall = walled.row(22) + 3 * 100;  // above the cube
  const std::uint8_t* far_ground = bare.row(22) + 3 * 100;
  EXPECT_GT(wall[2], wall[0] + 40) << "blue wall expected";
  EXPECT_LT(far_ground[2], far_ground[0] + 20) << "grey ground expected without the wall";
  const int middle = 3 * (60 * 160 + 80);  // the cube's front
  for (int c = 0; c < 3; ++c) EXPECT_EQ(walled.rgb[middle + c], bare.rgb[middle + c]);
  const int near_floor = 3 * (115 * 160 + 80);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(walled.rgb[near_floor + c], bare.rgb[near_floor + c]);
}

// A grey wall between the camera and the cube, seen from its back: translucent, so the cube still
// shows through it, tinted but orange.
TEST(Renderer, WallSeenFromItsBackLeavesTheCubeVisible) {
  const FrameView in_front =
      wall_view(Vec3(0.0, 0.5, 1.5), Vec3(0.0, 0.0, -1.0), Color(0.75, 0.76, 0.78));
  expect_matches_golden(draw(floor_settings(), in_front), "wall_in_front_of_cube");
  FrameView without = in_front;
  without.quads.clear();
  const io::Image bare = draw(floor_settings(), without);
  const io::Image walled = draw(floor_settings(), in_front);
  ASSERT_EQ(walled.width, 160);
  const int middle = 3 * (60 * 160 + 80);
  const std::uint8_t* cube = &walled.rgb[middle];
  EXPECT_NE(std::vector<std::uint8_t>(cube, cube + 3),
            std::vector<std::uint8_t>(&bare.rgb[middle], &bare.rgb[middle] + 3))
      << "the wall is drawn over the cube";
  EXPECT_GT(cube[0], cube[2] + 60) << "the cube still reads orange through the wall";
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cube[c], bare.rgb[middle + c], 80);
}

// A 10 × 10 × 10 grid of boxes 1 m apart, of mixed sizes (0.2 to 0.6 m) and turned every way:
// the many-boxes case the instanced draw is for (tests/data/thousand_boxes.toml at scene level).
FrameView thousand_boxes_view() {
  const Color palette[] = {Color(0.89, 0.40, 0.18), Color(0.20, 0.51, 0.78),
                           Color(0.30, 0.69, 0.31), Color(0.93, 0.77, 0.18),
                           Color(0.61, 0.45, 0.76)};
  FrameView view;
  view.camera.position = Vec3(11.0, 8.5, 14.5);
  for (int i = 0; i < 1000; ++i) {
    const int x = i / 100, y = (i / 10) % 10, z = i % 10;
    const auto fraction = [&](int salt) { return ((i * 37 + salt * 101) % 97) / 96.0; };
    view.boxes.push_back(
        Box{.position = Vec3(x - 4.5, y - 4.5, z - 4.5),
            .orientation = Quat(Eigen::AngleAxisd(
                6.0 * fraction(1), Vec3(fraction(2) - 0.5, 0.5, fraction(3) - 0.5).normalized())),
            .size = Vec3(0.2 + 0.4 * fraction(4), 0.2 + 0.4 * fraction(5), 0.2 + 0.4 * fraction(6)),
            .color = palette[i % 5]});
  }
  return view;
}

// The golden was drawn by the renderer before instancing (a draw call per box with per-box
// uniforms, commit bac4cea): the one instanced draw per pass must give the same picture.
TEST(Renderer, ThousandBoxesMatchTheGoldenOfOneDrawPerBox) {
  RenderSettings settings = small_settings();
  settings.width = 320;
  settings.height = 180;
  settings.ground.height = -6.0;
  expect_matches_golden(draw(settings, thousand_boxes_view()), "thousand_boxes");
}

// The default antialiasing (one sample per pixel, then the edge filter) on the same boxes: the
// golden shows smoothed edges, the shadows and no artefacts next to thousand_boxes.png's MSAA.
TEST(Renderer, ThousandBoxesWithTheEdgeFilterMatchGolden) {
  RenderSettings settings = small_settings();
  settings.width = 320;
  settings.height = 180;
  settings.msaa = kEdgeFilter;
  settings.ground.height = -6.0;
  expect_matches_golden(draw(settings, thousand_boxes_view()), "thousand_boxes_defaults");
}

// 1000 boxes in a 40 × 25 wall facing the camera, each red, green or blue so that no two side by
// side or one above the other share a colour, of mixed sizes and turns: the pixel where each
// box's centre projects shows that box's colour. A record read with the wrong stride, offset or
// divisor puts a box in the wrong place or gives it its neighbour's colour.
TEST(Renderer, EveryBoxOfAThousandShowsItsColourAtItsCentre) {
  RenderSettings settings = small_settings();
  settings.width = 640;
  settings.height = 400;
  settings.ground.enabled = false;
  settings.background = Color(0.5, 0.5, 0.5);  // no channel above the others
  const Color colors[3] = {Color(0.9, 0.1, 0.1), Color(0.1, 0.8, 0.1), Color(0.1, 0.2, 0.9)};
  FrameView view;
  view.camera = Camera{.position = Vec3(0, 0, 60), .look_at = Vec3::Zero(), .fov_degrees = 26.0};
  for (int i = 0; i < 1000; ++i) {
    const int column = i % 40, row = i / 40;
    const double turn = 0.37 * i;  // rad
    view.boxes.push_back(Box{
        .position = Vec3(column - 19.5, row - 12.0, 0.0),
        .orientation = Quat(Eigen::AngleAxisd(turn, Vec3(std::sin(turn), 1.0, 0.3).normalized())),
        .size = Vec3::Constant(0.3 + 0.3 * ((i * 7) % 11) / 10.0),
        .color = colors[(column + 2 * row) % 3]});
  }
  const io::Image image = draw(settings, view);
  ASSERT_EQ(image.width, settings.width);
  const Mat4 view_projection =
      perspective(view.camera.fov_degrees * M_PI / 180.0,
                  static_cast<double>(settings.width) / settings.height, 1.0, 100.0) *
      look_at(view.camera.position, view.camera.look_at, view.camera.up);
  int wrong = 0;
  for (std::size_t i = 0; i < view.boxes.size(); ++i) {
    const Eigen::Vector4d clip = view_projection * view.boxes[i].position.homogeneous();
    const int x = static_cast<int>(0.5 * (clip.x() / clip.w() + 1.0) * settings.width);
    const int y = static_cast<int>(0.5 * (1.0 - clip.y() / clip.w()) * settings.height);
    ASSERT_TRUE(x >= 0 && x < settings.width && y >= 0 && y < settings.height) << "box " << i;
    const std::uint8_t* pixel = image.row(y) + 3 * x;
    int channel = 0;  // the one the box's colour is strongest in
    for (int c = 1; c < 3; ++c) {
      if (view.boxes[i].color[c] > view.boxes[i].color[channel]) channel = c;
    }
    for (int c = 0; c < 3; ++c) {
      if (c != channel && pixel[channel] < pixel[c] + 30) {
        ++wrong;
        ADD_FAILURE() << "box " << i << " at pixel (" << x << ", " << y << ") shows ("
                      << int(pixel[0]) << ", " << int(pixel[1]) << ", " << int(pixel[2])
                      << "), not its colour";
        break;
      }
    }
    if (wrong > 5) break;  // enough to see what went wrong
  }
}

TEST(Renderer, DrawingTwiceIsByteIdentical) {
  const FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.3, Vec3(0, 1, 1).normalized())));
  std::string error;
  const auto renderer =
      ::tumble::testing::value_or_empty(Renderer::create(small_settings(), kShaders), error);
  ASSERT_TRUE(renderer) << error;
  io::Image first, second;
  renderer->draw(view, first);
  renderer->draw(cube_view(Quat::Identity()), second);  // something else in between
  renderer->draw(view, second);
  EXPECT_EQ(first.rgb, second.rgb);
  // And a fresh renderer draws the same bytes.
  EXPECT_EQ(draw(small_settings(), view).rgb, first.rgb);
}

// The ground is kept while the camera stays and drawn again when it moves (ground_cache.hpp):
// either way a frame has the bytes a fresh renderer draws for it, with the edge filter and with
// multisampling, so a render's frames do not depend on the frame it started from.
TEST(Renderer, KeptGroundGivesTheBytesOfAFreshDrawing) {
  for (const int msaa : {kEdgeFilter, 4}) {
    RenderSettings settings = small_settings();
    settings.msaa = msaa;
    FrameView still = cube_view(Quat(Eigen::AngleAxisd(0.3, Vec3(0, 1, 1).normalized())));
    FrameView turned = still;  // the same camera, the cube turned further: the ground is kept
    turned.boxes[0].orientation = Quat(Eigen::AngleAxisd(0.9, Vec3(1, 1, 0).normalized()));
    FrameView moved = still;  // the camera elsewhere: the ground is drawn again
    moved.camera.position = Vec3(-3.0, 2.5, 2.0);
    std::string error;
    const auto renderer =
        ::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error);
    ASSERT_TRUE(renderer) << error;
    io::Image first, kept, after_move, back;
    renderer->draw(still, first);
    renderer->draw(turned, kept);
    renderer->draw(moved, after_move);
    renderer->draw(still, back);
    EXPECT_EQ(kept.rgb, draw(settings, turned).rgb) << "msaa " << msaa;
    EXPECT_EQ(after_move.rgb, draw(settings, moved).rgb) << "msaa " << msaa;
    EXPECT_EQ(back.rgb, first.rgb) << "msaa " << msaa;
    EXPECT_NE(after_move.rgb, first.rgb) << "msaa " << msaa;
  }
}

// The image is upright and the background and ground are where they belong: the top row is the
// background colour (sRGB as given, no ground reaches it), the bottom row is ground.
TEST(Renderer, ImageIsUprightWithBackgroundAboveAndGroundBelow) {
  RenderSettings settings = small_settings();
  settings.background = Color(0.2, 0.4, 0.6);
  settings.ground.color = Color(0.9, 0.9, 0.1);
  settings.ground.grid_spacing = 0.0;
  FrameView view = cube_view(Quat::Identity());
  view.camera.look_at = Vec3(0, 1.8, 0);  // looking level: the horizon crosses the middle
  const io::Image image = draw(settings, view);
  const std::uint8_t* top = image.row(0);
  EXPECT_NEAR(top[0], 51, 1);   // 0.2 * 255
  EXPECT_NEAR(top[1], 102, 1);  // 0.4 * 255
  EXPECT_NEAR(top[2], 153, 1);  // 0.6 * 255
  const std::uint8_t* bottom = image.row(image.height - 1);
  EXPECT_GT(bottom[0], 100);  // lit yellow ground: red and green well above blue
  EXPECT_GT(bottom[1], 100);
  EXPECT_LT(bottom[2], bottom[0] / 2);
}

// A ball, turned so that its three great circles cross its face, lit and shadowed on the ground.
TEST(Renderer, BallMatchesGolden) {
  RenderSettings settings = small_settings();
  settings.round_solids = true;
  FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.6, Vec3(1, 0.4, 0.3).normalized())));
  view.boxes[0].solid = Solid::ball;
  view.boxes.push_back(Box{.position = Vec3(-1.3, -0.2, -0.6),
                           .size = Vec3::Constant(0.6),
                           .color = Color(0.3, 0.6, 0.85)});
  expect_matches_golden(draw(settings, view), "ball");
}

// The widest row and column (px) of the pixels where `solid` differs from `empty` by more than
// 16 in a channel.
std::pair<int, int> widest_extents(const io::Image& empty, const io::Image& solid) {
  const int w = empty.width, h = empty.height;
  const auto differs = [&](int x, int y) {
    const std::size_t at = 3 * (static_cast<std::size_t>(y) * w + x);
    for (int c = 0; c < 3; ++c) {
      if (std::abs(solid.rgb[at + c] - empty.rgb[at + c]) > 16) return true;
    }
    return false;
  };
  int widest_row = 0, widest_column = 0;
  for (int y = 0; y < h; ++y) {
    int row = 0;
    for (int x = 0; x < w; ++x) row += differs(x, y) ? 1 : 0;
    widest_row = std::max(widest_row, row);
  }
  for (int x = 0; x < w; ++x) {
    int column = 0;
    for (int y = 0; y < h; ++y) column += differs(x, y) ? 1 : 0;
    widest_column = std::max(widest_column, column);
  }
  return {widest_row, widest_column};
}

// A camera 5 m from the origin looking at it, square pictures of 240 px, no ground or shadows.
FrameView head_on_view() {
  FrameView view;
  view.camera.position = Vec3(0.0, 0.0, 5.0);
  view.camera.look_at = Vec3::Zero();
  return view;
}
RenderSettings head_on_settings() {
  RenderSettings settings = small_settings();
  settings.width = settings.height = 240;
  settings.ground.enabled = false;
  settings.shadows = false;
  settings.round_solids = true;
  return settings;
}

// The picture's size (px) of an angle off the view's axis: (rows / 2) tan(angle) / tan(fov / 2).
double pixels_of(double angle, const FrameView& view) {
  return 120.0 * std::tan(angle) / std::tan(0.5 * view.camera.fov_degrees * M_PI / 180.0);
}

// Seen head-on, a ball's outline is a circle of the projected radius: at distance d a sphere of
// radius r subtends asin(r / d). Its widest row and column, measured against a picture without
// it, are that diameter within 2 px, and each other within 1.
TEST(Renderer, ABallSeenHeadOnIsACircleOfItsProjectedSize) {
  const RenderSettings settings = head_on_settings();
  FrameView view = head_on_view();
  const io::Image empty = draw(settings, view);
  view.boxes.push_back(Box{.orientation = Quat(Eigen::AngleAxisd(0.9, Vec3(0, 1, 1).normalized())),
                           .size = Vec3::Constant(2.0),
                           .solid = Solid::ball});
  const auto [widest_row, widest_column] = widest_extents(empty, draw(settings, view));
  const double diameter = 2.0 * pixels_of(std::asin(1.0 / 5.0), view);
  std::printf("[ measured ] widest row %d px, column %d px, projected diameter %.2f px\n",
              widest_row, widest_column, diameter);
  EXPECT_NEAR(widest_row, diameter, 2.0);
  EXPECT_NEAR(widest_column, diameter, 2.0);
  EXPECT_LE(std::abs(widest_row - widest_column), 1);
}

// A capsule of radius r = 0.5 and length 2 lying across the view (along x), turned about its
// axis so its lines show: its height is a cylinder's, 2 asin(r / d) across; its width runs to the
// tangents of its end spheres (centres at x = ±1): each half atan(1 / d) + asin(r / sqrt(d² + 1)).
// A cylinder of the same radius and length stood upright: its width is 2 asin(r / d) across too.
TEST(Renderer, ACapsuleAndACylinderHaveTheirProjectedOutlines) {
  const RenderSettings settings = head_on_settings();
  FrameView view = head_on_view();
  const io::Image empty = draw(settings, view);
  const double d = 5.0, r = 0.5;
  view.boxes.push_back(Box{.orientation = Quat(Eigen::AngleAxisd(-M_PI / 2.0, Vec3::UnitZ())) *
                                          Quat(Eigen::AngleAxisd(0.7, Vec3::UnitY())),
                           .size = Vec3(2.0 * r, 2.0 + 2.0 * r, 2.0 * r),
                           .solid = Solid::capsule});
  const auto [capsule_row, capsule_column] = widest_extents(empty, draw(settings, view));
  const double height = 2.0 * pixels_of(std::asin(r / d), view);
  const double width =
      2.0 * pixels_of(std::atan(1.0 / d) + std::asin(r / std::sqrt(d * d + 1.0)), view);
  std::printf("[ measured ] capsule %d x %d px, projected %.2f x %.2f px\n", capsule_row,
              capsule_column, width, height);
  EXPECT_NEAR(capsule_row, width, 2.0);
  EXPECT_NEAR(capsule_column, height, 2.0);
  view.boxes[0] = Box{.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3::UnitY())),
                      .size = Vec3(2.0 * r, 1.0, 2.0 * r),
                      .solid = Solid::cylinder};
  const auto [cylinder_row, cylinder_column] = widest_extents(empty, draw(settings, view));
  std::printf("[ measured ] cylinder %d px wide, projected %.2f px\n", cylinder_row, height);
  EXPECT_NEAR(cylinder_row, height, 2.0);
  EXPECT_GT(cylinder_column, cylinder_row / 2);  // its height: the caps seen past the side
}

// The hull of a unit cube's corners, turned to show three faces, has the cube's outline: its
// widest row and column within 1 px of the cube's.
TEST(Renderer, TheHullOfACubesCornersHasTheCubesOutline) {
  RenderSettings settings = head_on_settings();
  HullMesh cube;
  for (int k = 0; k < 8; ++k) {
    cube.corners.push_back(Vec3(k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5));
  }
  // Each face counter-clockwise seen from outside: −x, +x, −y, +y, −z, +z.
  cube.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  cube.normals = {-Vec3::UnitX(), Vec3::UnitX(),  -Vec3::UnitY(),
                  Vec3::UnitY(),  -Vec3::UnitZ(), Vec3::UnitZ()};
  settings.hulls = {cube};
  settings.hull_sizes = {Vec3::Ones()};
  FrameView view = head_on_view();
  const io::Image empty = draw(settings, view);
  const Quat turn(Eigen::AngleAxisd(0.6, Vec3(1, 1, 0).normalized()));
  view.boxes.push_back(Box{.orientation = turn, .size = Vec3::Ones()});
  const auto [box_row, box_column] = widest_extents(empty, draw(settings, view));
  view.boxes[0].solid = Solid::hull;
  const io::Image hull = draw(settings, view);
  const auto [hull_row, hull_column] = widest_extents(empty, hull);
  std::printf("[ measured ] cube %d x %d px, its hull %d x %d px\n", box_row, box_column, hull_row,
              hull_column);
  EXPECT_GT(box_row, 50);
  EXPECT_NEAR(hull_row, box_row, 1);
  EXPECT_NEAR(hull_column, box_column, 1);
  expect_matches_golden(hull, "hull_cube");
}

TEST(Renderer, MissingShaderIsAClearErrorNamingTheFile) {
  std::string error;
  const auto renderer = ::tumble::testing::value_or_empty(
      Renderer::create(small_settings(), "/nonexistent/shaders"), error);
  EXPECT_FALSE(renderer);
  EXPECT_NE(error.find("/nonexistent/shaders/body.vert: cannot open shader file"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace tumble::render
