// Speed against error: every integrator on every hard case at a ladder of steps, with the error
// of the final state against the case's reference and the cost measured in the same run.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bench/hard_cases.hpp"
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
  std::vector<std::string> cases;  // hard case names; empty means every case
  std::vector<double> steps = std::vector<double>(std::begin(kAccuracySteps),
                                                  std::end(kAccuracySteps));  // dt (s)
  TimingSettings timing = {};
};

// A reduced sweep for tests and a quick look: three cases, the two coarsest steps, one sample.
AccuracySettings quick_accuracy_settings();

// One integrator on one case at one step.
struct AccuracyRow {
  std::string case_name;
  std::string integrator;
  double dt = 0.0;         // s
  std::int64_t steps = 0;  // round(duration / dt)
  // The state became non-finite or left the case's bounds (see measure_accuracy); the errors
  // are then NaN and the timing covers the steps taken before that.
  bool blew_up = false;
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

// The whole sweep, case by case, integrator by integrator (in kAllIntegrators order), step by
// step. `on_start` (optional) is called before each case's integrator, for progress.
std::vector<AccuracyRow> measure_accuracy(
    const AccuracySettings& settings,
    const std::function<void(const HardCase&, physics::Integrator)>& on_start = {});

}  // namespace tumble::bench
