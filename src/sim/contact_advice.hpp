// Advice on impulse contact before a run: settings that make the contact behave in a way a user
// may not expect. Pure computation: the commands print it.
#pragma once

#include <string>
#include <vector>

#include "physics/contact.hpp"
#include "physics/integrators.hpp"

namespace tumble::sim {

// Below this multiple of the speed gravity adds in one step, a resting contact's approach speed
// counts as a bounce (every step's free fall ends at |g| dt): at 1 the body would chatter.
inline constexpr double kThresholdOverStepSpeed = 1.5;

// One sentence per problem for a body (its model) among `planes` with impulse contact stepped at
// `dt` (s): a restitution_threshold below kThresholdOverStepSpeed × |g| dt on a pair that
// bounces (restitution > 0), since a body resting on such a plane then bounces on every step.
std::vector<std::string> check_contact(const physics::BodyModel& model,
                                       const std::vector<physics::Plane>& planes,
                                       const physics::ContactSettings& settings, double dt);

}  // namespace tumble::sim
