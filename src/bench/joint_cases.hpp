// Joint cases for the integrators (issue "Joints"): bodies held by joints with a closed form or a
// trusted reference, run through sim::Simulation, each judged by measures of its motion.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bench/contact_cases.hpp"
#include "physics/joints.hpp"
#include "sim/simulation.hpp"

namespace tumble::bench {

struct JointCase {
  std::string name;          // short, for files and tables: "pendulum"
  std::string summary;       // one line for people
  std::string measure_note;  // how the errors are measured
  std::vector<physics::BodyModel> models = {};
  std::vector<physics::BodyState> initial = {};
  std::vector<physics::Joint> joints = {};    // placed on `initial`
  double duration = 0.0;                      // s; a whole number of every benchmarked step
  std::vector<ContactMeasure> measures = {};  // one or two; the first is the headline, plotted
  // The errors, one per measure, of a run through `states` (states[0] the initial, then one per
  // step of dt (s); each holds every body).
  std::function<std::vector<double>(const std::vector<std::vector<physics::BodyState>>& states,
                                    double dt)>
      judge = nullptr;
};

// Every joint case, in a fixed order (joint_cases.cpp says what each is).
const std::vector<JointCase>& joint_cases();
const JointCase* find_joint_case(const std::string& name);

sim::Simulation joint_simulation(const JointCase& c, physics::Integrator integrator,
                                 double dt /* s */);

// Where within a step a coordinate passes 0: the fraction s in [0, 1] of the step at which the
// cubic through its values x0, x1 and its changes over the whole step d0 = ẋ0 dt, d1 = ẋ1 dt at
// the step's two ends is 0 (Hermite, by Newton's method from the straight line's s); the
// pendulum's periods are timed so.
double crossing_in_step(double x0, double d0, double x1, double d1);

// The double pendulum of two unit point masses on rods of 1 m, in the angles from the downward
// vertical: y = (θ1, θ2, θ̇1, θ̇2) at t0 (s) integrated to t1 by Boost.Odeint's Runge-Kutta-
// Fehlberg 7(8) at `tolerance` (the reference of the case "double_pendulum" and of the tests).
std::vector<double> double_pendulum_angles(std::vector<double> y, double t0, double t1,
                                           double tolerance, double g /* m/s² */);

}  // namespace tumble::bench
