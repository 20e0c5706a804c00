#include "diff/perceptual_diff.hpp"

#include <algorithm>
#include <cstring>

namespace tumble::diff {
namespace {

// NTSC YIQ from RGB, with the coefficients pixelmatch uses (Kotsarenko & Ramos 2010).
double luma(const std::uint8_t* p) {
  return p[0] * 0.29889531 + p[1] * 0.58662247 + p[2] * 0.11448223;
}
double in_phase(const std::uint8_t* p) {
  return p[0] * 0.59597799 - p[1] * 0.27417610 - p[2] * 0.32180189;
}
double quadrature(const std::uint8_t* p) {
  return p[0] * 0.21147017 - p[1] * 0.52261711 + p[2] * 0.31114694;
}

const std::uint8_t* pixel_at(const io::Image& image, int x, int y) {
  return image.row(y) + 3 * static_cast<std::size_t>(x);
}

bool on_border(const io::Image& image, int x, int y) {
  return x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1;
}

// Three or more of the pixel's neighbours equal to it (a border counts as one): the pixel lies in
// a flat area, not on a gradient.
bool has_many_siblings(const io::Image& image, int x, int y) {
  const std::uint8_t* centre = pixel_at(image, x, y);
  int same = on_border(image, x, y) ? 1 : 0;
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, image.height - 1); ++ny) {
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, image.width - 1); ++nx) {
      if (nx == x && ny == y) continue;
      if (std::memcmp(pixel_at(image, nx, ny), centre, 3) == 0 && ++same > 2) return true;
    }
  }
  return false;
}

}  // namespace

double yiq_distance_squared(const std::uint8_t* a, const std::uint8_t* b) {
  const double y = luma(a) - luma(b);
  const double i = in_phase(a) - in_phase(b);
  const double q = quadrature(a) - quadrature(b);
  return 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;
}

bool is_antialiased(const io::Image& image, int x, int y, const io::Image& other) {
  const std::uint8_t* centre = pixel_at(image, x, y);
  const double centre_luma = luma(centre);
  int same = on_border(image, x, y) ? 1 : 0;
  double darkest = 0.0;  // most negative brightness step to a neighbour (levels)
  double brightest = 0.0;
  int darkest_x = 0, darkest_y = 0, brightest_x = 0, brightest_y = 0;
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, image.height - 1); ++ny) {
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, image.width - 1); ++nx) {
      if (nx == x && ny == y) continue;
      const double step = luma(pixel_at(image, nx, ny)) - centre_luma;
      if (step == 0.0) {
        if (++same > 2) return false;  // mostly flat around it: a real change, not an edge
      } else if (step < darkest) {
        darkest = step;
        darkest_x = nx;
        darkest_y = ny;
      } else if (step > brightest) {
        brightest = step;
        brightest_x = nx;
        brightest_y = ny;
      }
    }
  }
  // An edge pixel is a blend of the two sides: one neighbour darker and one brighter.
  if (darkest == 0.0 || brightest == 0.0) return false;
  return (has_many_siblings(image, darkest_x, darkest_y) &&
          has_many_siblings(other, darkest_x, darkest_y)) ||
         (has_many_siblings(image, brightest_x, brightest_y) &&
          has_many_siblings(other, brightest_x, brightest_y));
}

}  // namespace tumble::diff
