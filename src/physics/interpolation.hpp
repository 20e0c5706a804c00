// Blending two states of one body that bracket a frame time.
#pragma once

#include "physics/rigid_body.hpp"

namespace tumble::physics {

// Spherical linear interpolation from a (alpha = 0) to b (alpha = 1) along the shorter arc:
// q and -q are the same rotation, so b is negated first when a·b < 0.
Quat slerp_shortest(const Quat& a, const Quat& b, double alpha);

// The state at alpha in [0, 1] between `previous` and `current`: positions and momenta lerped,
// orientation slerped the short way, derived state recomputed.
BodyState interpolate(const BodyState& previous, const BodyState& current, double alpha,
                      const BodyConstants& constants);

}  // namespace tumble::physics
