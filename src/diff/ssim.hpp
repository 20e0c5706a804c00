// Structural similarity (SSIM) of two images, after Wang, Bovik, Sheikh & Simoncelli 2004,
// "Image quality assessment: from error visibility to structural similarity", IEEE TIP 13(4).
#pragma once

#include "io/image.hpp"

namespace tumble::diff {

// The side of the square SSIM window for an image of `width` x `height` pixels: the paper's 11,
// or for a smaller image the largest odd side that fits (1 for a 1-pixel-wide one).
int ssim_window_side(int width, int height);

// Weight of window offset `offset` (pixels from the centre) in one direction: the paper's
// Gaussian of σ = 1.5 pixels, normalised over a window of `side` pixels, so that the 2D weights
// w(i) w(j) sum to 1.
double ssim_window_weight(int offset, int side);

// Mean SSIM over every window position that lies wholly inside the images (as the paper's
// reference code, 'valid' filtering), on the luma Y = 0.299 R + 0.587 G + 0.114 B (Rec. 601,
// levels 0-255), with the paper's 8-bit constants C1 = (0.01 · 255)², C2 = (0.03 · 255)².
// 1 for identical images, lower the more they differ. Precondition: equal, non-zero sizes.
double mean_ssim(const io::Image& a, const io::Image& b);

}  // namespace tumble::diff
