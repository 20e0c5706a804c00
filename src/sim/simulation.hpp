// The fixed-step clock: every body advances in steps of exactly dt, and any time in between is
// answered by interpolating the two steps that bracket it, so frame rate and step are independent.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::sim {

class Simulation {
 public:
  // One model and one initial state per body; bodies do not interact.
  Simulation(std::vector<physics::BodyModel> models, std::vector<physics::BodyState> initial,
             physics::Integrator integrator, double dt /* s */);

  // Advances every body by one step of dt.
  void step();

  // Steps until the current step time is at or past t (s), then returns every body's state at t,
  // interpolated between the previous and the current step. t must not go backwards past the
  // previous step.
  std::vector<physics::BodyState> states_at(double t);

  double dt() const { return dt_; }
  std::int64_t step_count() const { return step_count_; }
  // n dt, computed by multiplication so that no rounding accumulates over long runs (s).
  double time() const { return time_of_step(step_count_); }
  double time_of_step(std::int64_t n) const { return static_cast<double>(n) * dt_; }

  const std::vector<physics::BodyModel>& models() const { return models_; }
  const std::vector<physics::BodyState>& current() const { return current_; }
  const std::vector<physics::BodyState>& previous() const { return previous_; }

 private:
  std::vector<physics::BodyModel> models_;
  std::vector<physics::BodyState> previous_;  // at time_of_step(step_count_ - 1)
  std::vector<physics::BodyState> current_;   // at time_of_step(step_count_)
  physics::Integrator integrator_;
  double dt_;
  std::int64_t step_count_ = 0;
};

}  // namespace tumble::sim
