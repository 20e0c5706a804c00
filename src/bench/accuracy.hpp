// Speed against error: every integrator on every hard case at a ladder of steps, with the error
// of the final state against the case's reference, and on every contact case with both contact
// methods, with the case's own errors; the cost is measured in the same run.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bench/contact_cases.hpp"
#include "bench/hard_cases.hpp"
#include "bench/joint_cases.hpp"
#include "common/result.hpp"
#include "physics/contact.hpp"
#include "physics/integrators.hpp"

namespace tumble::bench {

// The steps every integrator is tried at (s): 1/30 to 1/960, each half the one before.
inline constexpr double kAccuracySteps[] = {1.0 / 30,  1.0 / 60,  1.0 / 120,
                                            1.0 / 240, 1.0 / 480, 1.0 / 960};

// How a run is timed: the median of `samples` samples, each repeating the whole run until at
// least `min_sample_seconds` have passed (so that short runs are not timed at clock resolution).
struct TimingSettings {
  int samples = 5;
  double min_sample_seconds = 0.002;  // s
};

struct AccuracySettings {
  std::vector<std::string> cases = {};  // hard case names; empty means every case
  // Contact case names (bench/contact_cases.hpp), each run with both contact methods; empty
  // means every case.
  std::vector<std::string> contact_cases = {};
  // Joint case names (bench/joint_cases.hpp); empty means every case.
  std::vector<std::string> joint_cases = {};
  std::vector<double> steps = std::vector<double>(std::begin(kAccuracySteps),
                                                  std::end(kAccuracySteps));  // dt (s)
  TimingSettings timing = {};
};

// A reduced sweep for tests and a quick look: three hard cases, the bounce, slide and rest
// contact cases and the pendulum, the two coarsest steps, one sample.
AccuracySettings quick_accuracy_settings();

// The cases a sweep runs, in sweep order: those the settings name, or every one when they name
// none; an error naming a case that does not exist.
struct AccuracySelection {
  std::vector<const HardCase*> hard;
  std::vector<const ContactCase*> contact;
  std::vector<const JointCase*> joint;
};
Result<AccuracySelection> select_accuracy_cases(const AccuracySettings& settings);

// One integrator on one case at one step.
struct AccuracyRow {
  std::string case_name;
  // "impulse" or "penalty" on a contact case; "none" on a hard case, which touches nothing.
  std::string contact = "none";
  std::string integrator;
  double dt = 0.0;         // s
  std::int64_t steps = 0;  // round(duration / dt)
  // The state became non-finite or left the case's bounds (see measure_accuracy); the errors
  // are then NaN and the timing covers the steps taken before that.
  bool blew_up = false;
  // The error a case is judged by, and its name with its unit: a hard case's orientation or
  // position error ("orientation_error_rad", "position_error_m"), a contact case's own measures
  // (ContactCase::measures, e.g. "apex_error_m"). A second one where the case has it (the rest
  // case's corner motion), else "" and NaN.
  std::string measure = "";
  double error = 0.0;
  std::string second_measure = "";
  double second_error = std::numeric_limits<double>::quiet_NaN();
  // Of the final state against the reference, on hard cases only (NaN on contact cases):
  double orientation_error = 0.0;  // angle from the reference orientation (rad)
  double position_error = 0.0;     // distance from the reference position (m)
  // Conserved quantities: the relative drift | |L| - |L0| | / |L0| and |E - E0| / E0. Otherwise
  // the relative error against the reference, |L - L_ref| / max(|L_ref|, |L0|) and likewise E.
  double angular_momentum_error = 0.0;
  double energy_error = 0.0;
  double ns_per_step = 0.0;              // median over the timing samples (ns)
  double ns_per_simulated_second = 0.0;  // ns_per_step / dt
};

// Runs one case with one integrator at one step: once, checking every step for a blow-up, to
// measure the error; then the timing samples.
AccuracyRow measure_accuracy(const HardCase& hard_case, physics::Integrator integrator,
                             double dt /* s */, const TimingSettings& timing);

// Runs one contact case with one contact method and one integrator at one step, through
// sim::Simulation: once, keeping every state for the case's measures and checking each step for
// a blow-up (the Simulation's, or the energy above rest doubling: energy_above_rest); then the
// timing samples of the same steps.
AccuracyRow measure_contact_accuracy(const ContactCase& contact_case, physics::ContactMethod method,
                                     physics::Integrator integrator, double dt /* s */,
                                     const TimingSettings& timing);

// Runs one joint case with one integrator at one step through sim::Simulation (its bodies under
// their joints, physics/joint_solve.hpp), keeping every state for the case's measures; then the
// timing samples of the same steps.
AccuracyRow measure_joint_accuracy(const JointCase& joint_case, physics::Integrator integrator,
                                   double dt /* s */, const TimingSettings& timing);

// The whole sweep: the hard cases, then the contact cases with impulse and then penalty contact,
// then the joint cases, each integrator by integrator (in kAllIntegrators order), step by step.
// `on_start` (optional) is called before each run of the steps, with its name ("article_cube",
// "bounce (penalty contact)", "pendulum (joints)") and integrator, for progress. An unknown case
// name is an error before anything runs.
Result<std::vector<AccuracyRow>> measure_accuracy(
    const AccuracySettings& settings,
    const std::function<void(const std::string& run, physics::Integrator)>& on_start = {});

}  // namespace tumble::bench
