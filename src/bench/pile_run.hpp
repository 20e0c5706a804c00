// What one engine did with the pile of bench/pile.hpp, measured the same way for every engine
// (tumble, and Bullet as a peer), so that `tumble bench contact` can set them side by side.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "physics/rigid_body.hpp"

namespace tumble::bench {

struct PileRun {
  std::vector<double> step_ms;  // wall time of each step (ms, steady clock)
  // Processor time of each step (ms, std::clock): on a machine shared with other work it counts
  // only the time the step ran, where the wall time also counts the time it waited for a core.
  std::vector<double> step_cpu_ms;
  std::vector<int> contacts;           // contact points after each step, over all pairs
  std::vector<double> depth_m;         // deepest contact point after each step (m; 0 if none)
  std::vector<double> top_speed;       // largest box speed after each step (m/s)
  double largest_penetration_m = 0.0;  // deepest contact point of the whole run (m, >= 0)
  int escaped = 0;                     // boxes whose centre left the bin (pile.hpp inside_bin)
  double largest_final_speed = 0.0;    // largest box speed after the last step (m/s)
  std::vector<physics::Vec3> final_positions;  // box centres after the last step (m, world)
  std::string engine;                          // e.g. "bullet 3.24 float64"
};

// Called after each step of a run with what has been measured so far (the step just done is the
// last element of each per-step vector): progress, or passing the steps on as they come. Called
// outside the timed part of the step.
using StepObserver = std::function<void(const PileRun& so_far)>;

// The mean of the steps' wall times (ms): the whole run's stepping time over its steps, which
// counts a pour's costly steps in full where the median hides them; 0 for a run of no steps.
double mean_step_ms(const PileRun& run);
// The mean of the steps' processor times (ms); 0 for a run of no steps.
double mean_step_cpu_ms(const PileRun& run);
// The median of the steps' wall times (ms); 0 for a run of no steps.
double median_step_ms(const PileRun& run);
// The median of the steps' processor times (ms); 0 for a run of no steps.
double median_step_cpu_ms(const PileRun& run);
// The index of the first step with the most contacts (0 for a run of no steps).
std::size_t peak_contact_step(const PileRun& run);
// When the peak is reached (s): the end of peak_contact_step, with `dt` the pile's step (s).
double peak_contact_time(const PileRun& run, double dt);
// The cost when the most pairs touch (ms): the median wall time of the steps with at least 95% of
// the peak contact count. One step's time alone is mostly scheduler noise on a shared machine;
// the steps near the peak do the same work.
double ms_at_peak_contacts(const PileRun& run);

// How many times `first`'s step time is `second`'s (tumble / bullet: above 1, tumble is slower),
// by each of the measures above. Infinite or NaN when `second` took no time.
struct StepTimeRatios {
  double mean_ms = 0.0;
  double mean_cpu_ms = 0.0;
  double median_ms = 0.0;
  double median_cpu_ms = 0.0;
  double ms_at_peak_contacts = 0.0;
};
StepTimeRatios step_time_ratios(const PileRun& first, const PileRun& second);

}  // namespace tumble::bench
