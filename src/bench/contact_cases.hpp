// Contact cases for the integrators: a box against a floor, run through sim::Simulation with
// impulse contact (the floor given to the world step) and with penalty contact (the floor in the
// body's PenaltyContact law), each judged by measures of its motion against a closed form.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "physics/contact.hpp"
#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"
#include "sim/simulation.hpp"

namespace tumble::bench {

// One error a contact case is judged by.
struct ContactMeasure {
  std::string name;   // for files: "apex_error_m"
  std::string label;  // for tables and plots: "apex error (m)"
};

struct ContactCase {
  std::string name;          // short, for files and tables: "bounce"
  std::string summary;       // one line for people
  std::string measure_note;  // how the errors are measured, one sentence
  physics::BodyModel model;  // gravity, the box (or ball) and its material; no contact law
  physics::BodyState initial;
  std::vector<physics::Plane> planes;
  double duration = 0.0;  // s; a whole number of every benchmarked step
  // Penalty runs: the default stiffness, and the damping that gives the case's restitution to a
  // flat landing (sim::penalty_damping_for_restitution).
  physics::ContactSettings penalty;
  // The methods the case runs with: both, or impulse alone (penalty contact's springs sit at a
  // box's corners, and a ball has none).
  std::vector<physics::ContactMethod> methods = {physics::ContactMethod::impulse,
                                                 physics::ContactMethod::penalty};
  // One or two; the first is the headline, plotted.
  std::vector<ContactMeasure> measures;
  // The errors, one per measure, of a run that went through `states` (states[0] the initial,
  // then one per step of dt (s)).
  std::function<std::vector<double>(const std::vector<physics::BodyState>& states, double dt)>
      judge;
};

// Every contact case, in a fixed order (see contact_cases.cpp for what each one is and why).
const std::vector<ContactCase>& contact_cases();
// The case of that name, or nullptr.
const ContactCase* find_contact_case(const std::string& name);

// The energy (J) the box has above lying still on the case's first plane (its floor): kinetic,
// plus m |g| times the height of its centre above the lowest it can rest on a face. Contact only
// takes energy away and gravity keeps it, so a run that doubles it has met an unstable step.
double energy_above_rest(const ContactCase& c, const physics::BodyState& state);

// The case's world for one contact method: with impulse the planes go to the world step, with
// penalty the body carries them in a PenaltyContact law (as scene/scene_builder.cpp builds it).
sim::Simulation contact_simulation(const ContactCase& c, physics::ContactMethod method,
                                   physics::Integrator integrator, double dt /* s */);

}  // namespace tumble::bench
