#include "sim/simulation.hpp"

#include <cassert>
#include <utility>

#include "physics/interpolation.hpp"

namespace tumble::sim {

Simulation::Simulation(std::vector<physics::BodyModel> models,
                       std::vector<physics::BodyState> initial, physics::Integrator integrator,
                       double dt)
    : models_(std::move(models)),
      previous_(initial),
      current_(std::move(initial)),
      integrator_(integrator),
      dt_(dt) {
  assert(models_.size() == current_.size());
  assert(dt_ > 0.0);
}

void Simulation::step() {
  const double t = time();
  previous_.swap(current_);
  for (std::size_t i = 0; i < models_.size(); ++i) {
    current_[i] = physics::step(integrator_, models_[i], previous_[i], t, dt_);
  }
  ++step_count_;
}

std::vector<physics::BodyState> Simulation::states_at(double t) {
  while (time() < t) step();
  if (step_count_ == 0) return current_;
  const double previous_time = time_of_step(step_count_ - 1);
  assert(t >= previous_time);
  const double alpha = (t - previous_time) / dt_;
  std::vector<physics::BodyState> out;
  out.reserve(models_.size());
  for (std::size_t i = 0; i < models_.size(); ++i) {
    out.push_back(physics::interpolate(previous_[i], current_[i], alpha, models_[i].constants));
  }
  return out;
}

}  // namespace tumble::sim
