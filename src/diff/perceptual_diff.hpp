// The perceptual pixel test of pixelmatch (Mapbox): a colour distance in YIQ space (Kotsarenko &
// Ramos 2010), and the anti-aliased pixel test of Vyšniauskas 2009 ("Anti-aliased pixel and
// intensity slope detector") as pixelmatch applies it. Written from those descriptions.
#pragma once

#include <cstdint>

#include "io/image.hpp"

namespace tumble::diff {

// The largest yiq_distance_squared of any two colours (pixelmatch's constant; red against
// cyan gives 35214.7), so a threshold T from 0 to 1 allows a distance² of 35215 T².
inline constexpr double kMaxYiqDistanceSquared = 35215.0;

// Weighted squared distance of two RGB pixels (3 bytes each) in YIQ:
// 0.5053 ΔY² + 0.299 ΔI² + 0.1957 ΔQ², channel levels 0-255 in, (levels)² out.
double yiq_distance_squared(const std::uint8_t* a, const std::uint8_t* b);

// Whether pixel (x, y) of `image` looks like an anti-aliased edge pixel: among its 8 neighbours
// (fewer at the border) it has both a darker and a brighter one, at most 2 of the same
// brightness, and the darkest or the brightest neighbour sits in a flat area (3 or more identical
// neighbours of its own) in both `image` and `other` (precondition: equal sizes).
bool is_antialiased(const io::Image& image, int x, int y, const io::Image& other);

}  // namespace tumble::diff
