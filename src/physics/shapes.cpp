#include "physics/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::physics {

Material combine(const Material& a, const Material& b) {
  return {.restitution = std::max(a.restitution, b.restitution),
          .friction = std::sqrt(a.friction * b.friction)};
}

}  // namespace tumble::physics
