#include "bench/accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace tumble::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// |difference| / scale; a difference from a zero scale is infinitely large.
double relative(double difference, double scale) {
  if (scale > 0.0) return std::abs(difference) / scale;
  return difference == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

// Beyond these a run has blown up: a million times the largest value the true motion has (or a
// floor of 1 m, 1 m/s and 1 rad/s of the body), far past any merely inaccurate run, and far below
// overflow, so every state stays finite (the physics asserts that in debug builds).
struct BlowUpBounds {
  double displacement;      // |x - x0| (m)
  double momentum;          // |p| (kg m/s)
  double angular_momentum;  // |L| (kg m²/s)

  BlowUpBounds(const HardCase& c, const FinalState& reference) {
    constexpr double kFactor = 1e6;
    const physics::BodyState& start = c.initial;
    const physics::BodyConstants& constants = c.model.constants;
    displacement = kFactor * std::max((reference.position - start.position()).norm(), 1.0);
    momentum = kFactor *
               std::max({start.momentum().norm(), reference.momentum.norm(), constants.mass * 1.0});
    angular_momentum =
        kFactor * std::max({start.angular_momentum().norm(), reference.angular_momentum.norm(),
                            constants.inertia.maxCoeff() * 1.0});
  }

  bool exceeded_by(const physics::BodyState& s, const physics::Vec3& start_position) const {
    // Written so that NaN counts as exceeding.
    return !((s.position() - start_position).norm() <= displacement &&
             s.momentum().norm() <= momentum && s.angular_momentum().norm() <= angular_momentum &&
             s.orientation().coeffs().allFinite());
  }
};

// `steps` steps from the case's start, unchecked: the loop that is timed.
physics::BodyState run(const HardCase& c, physics::Integrator integrator, double dt,
                       std::int64_t steps) {
  physics::BodyState state = c.initial;
  for (std::int64_t n = 0; n < steps; ++n) {
    state = physics::step(integrator, c.model, state, static_cast<double>(n) * dt, dt);
  }
  return state;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

// Fills the row's cost: the median over the samples of `timing`, each repeating `run` (which
// takes `steps` steps and returns a number that depends on them) until min_sample_seconds
// have passed, guessed from the error run's `error_run_seconds`.
void time_runs(AccuracyRow& row, const TimingSettings& timing, double error_run_seconds,
               std::int64_t steps, const std::function<double()>& run) {
  const std::int64_t repeats = std::max<std::int64_t>(
      1, std::llround(std::ceil(timing.min_sample_seconds / std::max(error_run_seconds, 1e-9))));
  std::vector<double> ns_per_step;
  volatile double sink = 0.0;  // keeps the timed runs from being optimised away
  for (int sample = 0; sample < std::max(1, timing.samples); ++sample) {
    const Clock::time_point start = Clock::now();
    for (std::int64_t r = 0; r < repeats; ++r) sink = sink + run();
    ns_per_step.push_back(seconds_since(start) * 1e9 /
                          static_cast<double>(repeats * std::max<std::int64_t>(steps, 1)));
  }
  row.ns_per_step = median(ns_per_step);
  row.ns_per_simulated_second = row.ns_per_step / row.dt;
}

}  // namespace

AccuracySettings quick_accuracy_settings() {
  return {.cases = {"article_cube", "stiff_linear_damping", "box_on_spring"},
          .contact_cases = {"bounce", "slide", "rest"},
          .joint_cases = {"pendulum"},
          .steps = {1.0 / 30, 1.0 / 60},
          .timing = {.samples = 1, .min_sample_seconds = 0.0}};
}

namespace {

// The cases named in `names`, in that order, or all of `all` when none are named; false, with
// the unknown name in `unknown`, for a name that is no case.
template <typename Case, typename Find>
bool select_cases(const std::vector<std::string>& names, const std::vector<Case>& all, Find find,
                  std::vector<const Case*>& out, std::string& unknown) {
  if (names.empty()) {
    for (const Case& c : all) out.push_back(&c);
  }
  for (const std::string& name : names) {
    const Case* c = find(name);
    if (!c) {
      unknown = name;
      return false;
    }
    out.push_back(c);
  }
  return true;
}

}  // namespace

Result<AccuracySelection> select_accuracy_cases(const AccuracySettings& settings) {
  AccuracySelection out;
  std::string unknown;
  if (!select_cases(settings.cases, hard_cases(), find_hard_case, out.hard, unknown)) {
    return Error{"no hard case named " + unknown};
  }
  if (!select_cases(settings.contact_cases, contact_cases(), find_contact_case, out.contact,
                    unknown)) {
    return Error{"no contact case named " + unknown};
  }
  if (!select_cases(settings.joint_cases, joint_cases(), find_joint_case, out.joint, unknown)) {
    return Error{"no joint case named " + unknown};
  }
  return out;
}

AccuracyRow measure_accuracy(const HardCase& c, physics::Integrator integrator, double dt,
                             const TimingSettings& timing) {
  const Reference& reference = c.reference();
  AccuracyRow row{.case_name = c.name,
                  .integrator = std::string(physics::integrator_name(integrator)),
                  .dt = dt,
                  .steps = std::llround(c.duration / dt)};

  // The error run: every step checked, so a blow-up stops it while the state is still finite.
  const BlowUpBounds bounds(c, reference.state);
  const Clock::time_point error_run_start = Clock::now();
  physics::BodyState state = c.initial;
  std::int64_t taken = 0;
  while (taken < row.steps && !row.blew_up) {
    state = physics::step(integrator, c.model, state, static_cast<double>(taken) * dt, dt);
    ++taken;
    row.blew_up = bounds.exceeded_by(state, c.initial.position());
  }
  const double error_run_seconds = seconds_since(error_run_start);

  row.measure =
      c.headline == HeadlineError::orientation ? "orientation_error_rad" : "position_error_m";
  if (row.blew_up) {
    row.orientation_error = row.position_error = kNaN;
    row.angular_momentum_error = row.energy_error = kNaN;
  } else {
    const FinalState end = final_state_of(state);
    const FinalState start = final_state_of(c.initial);
    const FinalState& exact = reference.state;
    row.orientation_error = physics::angle_between(end.orientation, exact.orientation);
    row.position_error = (end.position - exact.position).norm();
    row.angular_momentum_error =
        c.conserves_angular_momentum
            ? relative(end.angular_momentum.norm() - start.angular_momentum.norm(),
                       start.angular_momentum.norm())
            : relative((end.angular_momentum - exact.angular_momentum).norm(),
                       std::max(exact.angular_momentum.norm(), start.angular_momentum.norm()));
    row.energy_error = c.conserves_energy
                           ? relative(end.energy - start.energy, start.energy)
                           : relative(end.energy - exact.energy,
                                      std::max(std::abs(exact.energy), std::abs(start.energy)));
  }

  row.error = c.headline == HeadlineError::orientation ? row.orientation_error : row.position_error;
  // The timing samples repeat exactly the steps the error run took (all of them finite: the runs
  // are deterministic), without the per-step check.
  time_runs(row, timing, error_run_seconds, taken,
            [&] { return run(c, integrator, dt, taken).position().x(); });
  return row;
}

namespace {

// A row of a case that measures its own errors (`measures`), with NaN in the final-state ones.
AccuracyRow measured_row(const std::string& name, const std::string& contact,
                         physics::Integrator integrator, double dt, double duration,
                         const std::vector<ContactMeasure>& measures) {
  return {.case_name = name,
          .contact = contact,
          .integrator = std::string(physics::integrator_name(integrator)),
          .dt = dt,
          .steps = std::llround(duration / dt),
          .measure = measures.at(0).name,
          .second_measure = measures.size() > 1 ? measures[1].name : "",
          .orientation_error = kNaN,
          .position_error = kNaN,
          .angular_momentum_error = kNaN,
          .energy_error = kNaN};
}

// A case run through sim::Simulation (`make` gives a fresh one): the error run keeps `keep(world)`
// after each step, from `start`, and stops where the Simulation or `blew_up(kept)` says it blew
// up; `judge(states)` gives the errors; then the timing samples of the same steps.
template <class State, class Make, class Keep, class BlewUp, class Judge>
void run_measured(AccuracyRow& row, const TimingSettings& timing, State start, Make make, Keep keep,
                  BlewUp blew_up, Judge judge) {
  const Clock::time_point error_run_start = Clock::now();
  sim::Simulation world = make();
  std::vector<State> states = {std::move(start)};
  states.reserve(static_cast<std::size_t>(row.steps) + 1);
  while (world.step_count() < row.steps && !row.blew_up) {
    world.step();
    states.push_back(keep(world));
    row.blew_up = world.blow_up().has_value() || blew_up(states.back());
  }
  const double error_run_seconds = seconds_since(error_run_start);
  const std::int64_t taken = world.step_count();
  if (row.blew_up) {
    row.error = kNaN;
  } else {
    const std::vector<double> errors = judge(states);
    row.error = errors.at(0);
    if (errors.size() > 1) row.second_error = errors[1];
  }
  time_runs(row, timing, error_run_seconds, taken, [&] {
    sim::Simulation timed = make();
    while (timed.step_count() < taken) timed.step();
    return timed.current().front().position().x();
  });
}

}  // namespace

AccuracyRow measure_contact_accuracy(const ContactCase& c, physics::ContactMethod method,
                                     physics::Integrator integrator, double dt,
                                     const TimingSettings& timing) {
  AccuracyRow row = measured_row(c.name, physics::contact_method_name(method), integrator, dt,
                                 c.duration, c.measures);
  const double energy_bound = 2.0 * energy_above_rest(c, c.initial);  // J
  run_measured(
      row, timing, c.initial, [&] { return contact_simulation(c, method, integrator, dt); },
      [](const sim::Simulation& world) { return world.current().front(); },
      [&](const physics::BodyState& state) {
        return !(energy_above_rest(c, state) <= energy_bound);
      },
      [&](const std::vector<physics::BodyState>& states) { return c.judge(states, dt); });
  return row;
}

AccuracyRow measure_joint_accuracy(const JointCase& c, physics::Integrator integrator, double dt,
                                   const TimingSettings& timing) {
  AccuracyRow row = measured_row(c.name, "none", integrator, dt, c.duration, c.measures);
  run_measured(
      row, timing, c.initial, [&] { return joint_simulation(c, integrator, dt); },
      [](const sim::Simulation& world) { return world.current(); },
      [](const std::vector<physics::BodyState>&) { return false; },
      [&](const std::vector<std::vector<physics::BodyState>>& states) {
        return c.judge(states, dt);
      });
  return row;
}

Result<std::vector<AccuracyRow>> measure_accuracy(
    const AccuracySettings& settings,
    const std::function<void(const std::string&, physics::Integrator)>& on_start) {
  // Both lists first, so that an unknown name fails before anything runs.
  const Result<AccuracySelection> selection = select_accuracy_cases(settings);
  if (!selection) return Error{selection.error()};
  std::vector<AccuracyRow> rows;
  for (const HardCase* c : selection->hard) {
    for (const physics::Integrator integrator : physics::kAllIntegrators) {
      if (on_start) on_start(c->name, integrator);
      for (const double dt : settings.steps) {
        rows.push_back(measure_accuracy(*c, integrator, dt, settings.timing));
      }
    }
  }
  for (const ContactCase* c : selection->contact) {
    for (const physics::ContactMethod method : c->methods) {
      for (const physics::Integrator integrator : physics::kAllIntegrators) {
        if (on_start) {
          on_start(c->name + " (" + physics::contact_method_name(method) + " contact)", integrator);
        }
        for (const double dt : settings.steps) {
          rows.push_back(measure_contact_accuracy(*c, method, integrator, dt, settings.timing));
        }
      }
    }
  }
  for (const JointCase* c : selection->joint) {
    for (const physics::Integrator integrator : physics::kAllIntegrators) {
      if (on_start) on_start(c->name + " (joints)", integrator);
      for (const double dt : settings.steps) {
        rows.push_back(measure_joint_accuracy(*c, integrator, dt, settings.timing));
      }
    }
  }
  return rows;
}

}  // namespace tumble::bench
