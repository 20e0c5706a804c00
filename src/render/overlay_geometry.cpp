#include "render/overlay_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "render/text_layout.hpp"

namespace tumble::render {
namespace {

using Vec4 = Eigen::Vector4d;
using Vec2 = Eigen::Vector2d;

// Signed distance to GL's near plane in clip space (z_ndc >= -1): negative behind it.
double in_front(const Vec4& clip) {
  return clip.z() + clip.w();
}

// The segment a-b cut to the near plane's side of the camera; false when none of it is there.
bool clip_to_near(Vec4& a, Vec4& b, double& opacity_a, double& opacity_b) {
  const double fa = in_front(a), fb = in_front(b);
  if (fa < 0.0 && fb < 0.0) return false;
  if (fa < 0.0 || fb < 0.0) {
    const double u = fa / (fa - fb);  // where the clip-space segment crosses the plane
    const Vec4 cut = a + u * (b - a);
    const double opacity = opacity_a + u * (opacity_b - opacity_a);
    if (fa < 0.0) {
      a = cut;
      opacity_a = opacity;
    } else {
      b = cut;
      opacity_b = opacity;
    }
  }
  return true;
}

// Builds triangles on a frame: pixel offsets to clip space at each vertex's own depth.
struct Builder {
  int width, height;
  double scale;  // px per px at 720 rows
  std::vector<float> out;

  // GL's window position (px, y up) of a clip-space point in front of the camera.
  Vec2 pixel(const Vec4& clip) const {
    return Vec2((clip.x() / clip.w() + 1.0) * 0.5 * width,
                (clip.y() / clip.w() + 1.0) * 0.5 * height);
  }

  void vertex(const Vec4& clip, const Vec2& pixel_offset, const Eigen::Vector4f& color) {
    const Vec4 moved = clip + Vec4(2.0 * pixel_offset.x() / width * clip.w(),
                                   2.0 * pixel_offset.y() / height * clip.w(), 0.0, 0.0);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<float>(moved[i]));
    out.insert(out.end(), color.data(), color.data() + 4);
  }

  // A band from a to b, `half_width` px either side of the line on the picture.
  void band(const Vec4& a, const Vec4& b, const Vec2& normal, double half_width,
            const Eigen::Vector4f& color_a, const Eigen::Vector4f& color_b) {
    const Vec2 side = half_width * normal;
    vertex(a, side, color_a);
    vertex(a, -side, color_a);
    vertex(b, side, color_b);
    vertex(b, side, color_b);
    vertex(a, -side, color_a);
    vertex(b, -side, color_b);
  }

  void line(const Polyline& line) {
    std::vector<Vec4> clip;
    clip.reserve(line.points.size());
    for (const Vec3& point : line.points) clip.push_back(view_projection * point.homogeneous());
    for (std::size_t i = 0; i + 1 < clip.size();) {
      const std::size_t j = straight_run_end(clip, line.opacity, i);
      Vec4 a = clip[i], b = clip[j];
      double opacity_a = line.opacity[i], opacity_b = line.opacity[j];
      i = j;
      if (!clip_to_near(a, b, opacity_a, opacity_b)) continue;
      const Vec2 along = pixel(b) - pixel(a);
      if (!(along.norm() > 0.0)) continue;
      const Vec2 normal = Vec2(-along.y(), along.x()).normalized();
      band(a, b, normal, 0.5 * kLineWidth * scale, premultiplied(line.color, opacity_a),
           premultiplied(line.color, opacity_b));
    }
  }

  // The last point of the run from `first` that one band draws as the segments would: each
  // point between lies within kStraightPixels of the chord on the picture, with its opacity
  // within kStraightOpacity of the chord's there (interpolated as GL does, perspective-correct).
  // A trail's dozens of short segments a frame are mostly a few such runs: fewer, longer bands
  // for llvmpipe to set up, and no overlaps at the joints between.
  std::size_t straight_run_end(const std::vector<Vec4>& clip, const std::vector<double>& opacity,
                               std::size_t first) const {
    constexpr double kStraightPixels = 0.25, kStraightOpacity = 0.5 / 255.0;
    constexpr std::size_t kLongestRun = 64;  // points, bounding the checks to a few thousand
    const auto seen = [&](std::size_t i) { return in_front(clip[i]) > 0.0 && clip[i].w() > 0.0; };
    std::size_t end = first + 1;
    if (!seen(first) || !seen(end)) return end;
    const Vec2 a = pixel(clip[first]);
    for (std::size_t last = first + 2; last < clip.size() && last - first <= kLongestRun; ++last) {
      if (!seen(last)) break;
      const Vec2 chord = pixel(clip[last]) - a;
      const double length2 = chord.squaredNorm();
      if (!(length2 > 0.0)) break;
      for (std::size_t k = first + 1; k < last; ++k) {
        const Vec2 to_k = pixel(clip[k]) - a;
        const double s = to_k.dot(chord) / length2;  // along the chord on the picture
        if (s <= 0.0 || s >= 1.0) return end;
        if ((to_k - s * chord).norm() > kStraightPixels) return end;
        // GL interpolates attribute / w linearly on the picture: b's weight at s is
        // (s / w_b) / ((1 - s) / w_a + s / w_b).
        const double wa = clip[first].w(), wb = clip[last].w();
        const double weight_b = (s / wb) / ((1.0 - s) / wa + s / wb);
        const double expected = opacity[first] + weight_b * (opacity[last] - opacity[first]);
        if (std::abs(opacity[k] - expected) > kStraightOpacity) return end;
      }
      end = last;
    }
    return end;
  }

  void arrow(const Arrow& arrow) {
    Vec4 from = view_projection * arrow.from.homogeneous();
    Vec4 to = view_projection * arrow.to.homogeneous();
    double unused_a = 1.0, unused_b = 1.0;
    const bool tip_in_front = in_front(to) >= 0.0;
    if (!clip_to_near(from, to, unused_a, unused_b)) return;
    const Vec2 along = pixel(to) - pixel(from);
    const double length = along.norm();  // px
    if (!(length >= 1.0)) return;
    const Vec2 direction = along / length, normal(-direction.y(), direction.x());
    const Eigen::Vector4f color = premultiplied(arrow.color, 1.0);
    if (!tip_in_front) {
      band(from, to, normal, 0.5 * kArrowShaftWidth * scale, color, color);
      return;
    }
    const double head = std::min(kArrowHeadLength * scale, 0.5 * length);  // px
    // The head's base, a fraction s of the way on the picture, is the fraction u of the way in
    // clip space (perspective-correct interpolation: u = s w_a / ((1 - s) w_b + s w_a)).
    const double s = 1.0 - head / length;
    const double u = s * from.w() / ((1.0 - s) * to.w() + s * from.w());
    const Vec4 base = from + u * (to - from);
    band(from, base, normal, 0.5 * kArrowShaftWidth * scale, color, color);
    const Vec2 side = 0.5 * kArrowHeadWidth / kArrowHeadLength * head * normal;
    vertex(base, side, color);
    vertex(base, -side, color);
    vertex(to, Vec2::Zero(), color);
  }

  static Eigen::Vector4f premultiplied(const Rgba& color, double opacity) {
    const double alpha = std::clamp(color.w() * opacity, 0.0, 1.0);
    const Eigen::Vector3d rgb = color.head<3>().cwiseMax(0.0).cwiseMin(1.0) * alpha;
    return Eigen::Vector4f(static_cast<float>(rgb.x()), static_cast<float>(rgb.y()),
                           static_cast<float>(rgb.z()), static_cast<float>(alpha));
  }

  Mat4 view_projection;
};

}  // namespace

std::optional<Eigen::Vector2d> project_to_pixel(const Mat4& view_projection, const Vec3& point,
                                                int width, int height) {
  const Vec4 clip = view_projection * point.homogeneous();
  if (in_front(clip) < 0.0 || clip.w() <= 0.0) return std::nullopt;
  return Vec2((clip.x() / clip.w() + 1.0) * 0.5 * width,
              (1.0 - clip.y() / clip.w()) * 0.5 * height);
}

std::vector<float> overlay_triangles(const std::vector<Polyline>& lines,
                                     const std::vector<Arrow>& arrows, const Mat4& view_projection,
                                     int width, int height) {
  Builder builder{.width = width,
                  .height = height,
                  .scale = scale_to_frame(1.0, height),
                  .out = {},
                  .view_projection = view_projection};
  for (const Polyline& line : lines) builder.line(line);
  for (const Arrow& arrow : arrows) builder.arrow(arrow);
  return std::move(builder.out);
}

}  // namespace tumble::render
