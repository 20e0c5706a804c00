#include "physics/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::physics {

Material combine(const Material& a, const Material& b) {
  return {.restitution = std::max(a.restitution, b.restitution),
          .friction = std::sqrt(a.friction * b.friction),
          .rolling_resistance = std::max(a.rolling_resistance, b.rolling_resistance)};
}

}  // namespace tumble::physics
