#include "diff/ssim.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tumble::diff {
namespace {

constexpr int kPaperWindowSide = 11;
constexpr double kSigma = 1.5;                       // pixels
constexpr double kC1 = (0.01 * 255) * (0.01 * 255);  // stabilises the luminance term (levels²)
constexpr double kC2 = (0.03 * 255) * (0.03 * 255);  // stabilises the contrast-structure term

std::vector<double> luma_plane(const io::Image& image) {
  std::vector<double> plane(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < plane.size(); ++i) {
    const std::uint8_t* p = &image.rgb[3 * i];
    plane[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
  }
  return plane;
}

// Weighted window sums of `plane`, 'valid' only: the Gaussian is separable, so rows then columns.
// In: width x height; out: (width - side + 1) x (height - side + 1).
std::vector<double> filter_valid(const std::vector<double>& plane, int width, int height,
                                 const std::vector<double>& weights) {
  const int side = static_cast<int>(weights.size());
  const int out_width = width - side + 1;
  const int out_height = height - side + 1;
  std::vector<double> across(static_cast<std::size_t>(out_width) * height);
  for (int y = 0; y < height; ++y) {
    const double* in = &plane[static_cast<std::size_t>(y) * width];
    double* out = &across[static_cast<std::size_t>(y) * out_width];
    for (int x = 0; x < out_width; ++x) {
      double sum = 0.0;
      for (int k = 0; k < side; ++k) sum += weights[k] * in[x + k];
      out[x] = sum;
    }
  }
  std::vector<double> filtered(static_cast<std::size_t>(out_width) * out_height, 0.0);
  for (int y = 0; y < out_height; ++y) {
    double* out = &filtered[static_cast<std::size_t>(y) * out_width];
    for (int k = 0; k < side; ++k) {
      const double* in = &across[static_cast<std::size_t>(y + k) * out_width];
      for (int x = 0; x < out_width; ++x) out[x] += weights[k] * in[x];
    }
  }
  return filtered;
}

std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] * b[i];
  return out;
}

}  // namespace

int ssim_window_side(int width, int height) {
  const int fits = std::min({kPaperWindowSide, width, height});
  return fits % 2 == 1 ? fits : fits - 1;
}

double ssim_window_weight(int offset, int side) {
  const int radius = side / 2;
  double total = 0.0;
  for (int k = -radius; k <= radius; ++k) total += std::exp(-k * k / (2 * kSigma * kSigma));
  return std::exp(-offset * offset / (2 * kSigma * kSigma)) / total;
}

double mean_ssim(const io::Image& a, const io::Image& b) {
  assert(a.width == b.width && a.height == b.height && a.width > 0 && a.height > 0);
  const int side = ssim_window_side(a.width, a.height);
  std::vector<double> weights(side);
  for (int k = 0; k < side; ++k) weights[k] = ssim_window_weight(k - side / 2, side);
  const std::vector<double> x = luma_plane(a);
  const std::vector<double> y = luma_plane(b);
  const auto filter = [&](const std::vector<double>& plane) {
    return filter_valid(plane, a.width, a.height, weights);
  };
  const std::vector<double> mean_x = filter(x);
  const std::vector<double> mean_y = filter(y);
  const std::vector<double> mean_xx = filter(product(x, x));
  const std::vector<double> mean_yy = filter(product(y, y));
  const std::vector<double> mean_xy = filter(product(x, y));
  double sum = 0.0;
  for (std::size_t i = 0; i < mean_x.size(); ++i) {
    const double mx = mean_x[i], my = mean_y[i];
    const double variance_x = mean_xx[i] - mx * mx;  // σx² = E[x²] - μx² (paper eq. 4)
    const double variance_y = mean_yy[i] - my * my;
    const double covariance = mean_xy[i] - mx * my;  // σxy (paper eq. 11)
    sum += (2 * mx * my + kC1) * (2 * covariance + kC2) /
           ((mx * mx + my * my + kC1) * (variance_x + variance_y + kC2));  // paper eq. 13
  }
  return sum / static_cast<double>(mean_x.size());
}

}  // namespace tumble::diff
