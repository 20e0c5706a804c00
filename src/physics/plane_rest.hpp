// The resting step of one body that touches planes and nothing else (a box on a floor, in a
// corner of walls): step 3 of step_with_planes, and of step_world for an island of one body.
//
// It is the island solve of physics/contact_island.hpp for that one case, with the same rows, the
// same warm starting, the same passes and tolerance, the same pose update and projection, in the
// same order, so it gives the same states to the bit (plane_rest_test compares the two). What it
// drops is what one body against static planes does not need: a second body in every row, lists of
// rows grown per step, pointers back to each point's manifold, the island's copies of the states;
// README's "Speed against error" has what that saves.
#pragma once

#include <vector>

#include "physics/contact.hpp"
#include "physics/integrators.hpp"

namespace tumble::physics {

struct PlaneContacts;

// The most planes one body's resting step takes here; a body touching more goes to the island
// solve.
inline constexpr int kMostRestingPlanes = 4;

// The body at the end of its free step (`end`, whose rotation is `rotation`), corrected for its
// contacts with the planes whose corner separations contacts.separations holds: the velocity
// solve, the pose moved by `weight` (s, impulse_position_weight) times the velocity change, and
// the projection. contacts.manifolds then hold this step's points and impulses. Returns false,
// having changed nothing, when the step is not one it takes: a point that bounces (approaching
// faster than settings.restitution_threshold with restitution above 0: the island solve's bounce
// and its energy guard), or more than kMostRestingPlanes planes touched.
bool rest_alone_on_planes(const BodyModel& model, const BodyState& end, const Mat3& rotation,
                          double weight, const std::vector<Plane>& planes,
                          const ContactSettings& settings, PlaneContacts& contacts, BodyState& out);

}  // namespace tumble::physics
