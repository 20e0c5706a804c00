#include "sim/simulation.hpp"

#include <cassert>
#include <cstdio>
#include <utility>

#include "physics/interpolation.hpp"

namespace tumble::sim {

Simulation::Simulation(std::vector<physics::BodyModel> models,
                       std::vector<physics::BodyState> initial, physics::Integrator integrator,
                       double dt, std::vector<physics::Plane> planes,
                       physics::ContactSettings contact, std::vector<physics::Joint> joints)
    : models_(std::move(models)),
      previous_(initial),
      current_(std::move(initial)),
      integrator_(integrator),
      dt_(dt),
      planes_(std::move(planes)),
      contact_(contact) {
  assert(models_.size() == current_.size());
  assert(dt_ > 0.0);
  const bool pairs = physics::pairs_possible(models_, contact_);
  if (contact_.method == physics::ContactMethod::impulse) {
    if (!planes_.empty() || pairs) stepping_ = Stepping::impulse_world;
  } else if (pairs) {
    stepping_ = Stepping::penalty_world;
  }
  joints_ = physics::make_joint_world(std::move(joints), models_);
  if (!joints_.joints.empty() && stepping_ == Stepping::alone) stepping_ = Stepping::joint_world;
}

namespace {

// The common case, on every step of every body: NaN and infinity fail each comparison, so one
// squared norm per vector tests both finiteness and the bound, with no square root.
bool within_bounds(const physics::BodyState& state) {
  return state.position().squaredNorm() <= kMaxPosition * kMaxPosition &&
         state.velocity().squaredNorm() <= kMaxSpeed * kMaxSpeed &&
         state.angular_velocity().squaredNorm() <= kMaxAngularSpeed * kMaxAngularSpeed &&
         state.orientation().coeffs().squaredNorm() <= 2.0;  // unit after recalculate
}

}  // namespace

Result<void> check_in_bounds(const physics::BodyState& state) {
  if (within_bounds(state)) return Result<void>::success();
  const auto check = [](const auto& value, double bound, const char* name,
                        const char* unit) -> std::string {
    if (!value.allFinite()) return std::string("its ") + name + " is not finite";
    const double size = value.stableNorm();  // finite even past 1e154
    if (size <= bound) return {};
    char text[160];
    std::snprintf(text, sizeof text, "its %s reached %.3g %s, past the bound of %.0e %s", name,
                  size, unit, bound, unit);
    return text;
  };
  if (!state.orientation().coeffs().allFinite()) return Error{"its orientation is not finite"};
  std::string problem = check(state.position(), kMaxPosition, "distance from the origin", "m");
  if (problem.empty()) problem = check(state.velocity(), kMaxSpeed, "speed", "m/s");
  if (problem.empty()) {
    problem = check(state.angular_velocity(), kMaxAngularSpeed, "angular speed", "rad/s");
  }
  if (problem.empty()) return Result<void>::success();
  return Error{std::move(problem)};
}

void Simulation::step() {
  if (blow_up_) return;
  const double t = time();
  previous_.swap(current_);
  switch (stepping_) {
    case Stepping::impulse_world:
      physics::step_world(integrator_, models_, previous_, t, dt_, planes_, contact_, contacts_,
                          current_, &joints_);
      break;
    case Stepping::penalty_world:
      physics::step_penalty_world(integrator_, models_, previous_, t, dt_, contact_, penalty_,
                                  current_, &joints_);
      break;
    case Stepping::joint_world:
      physics::step_joints(integrator_, models_, previous_, t, dt_, joints_, current_);
      break;
    case Stepping::alone:
      for (std::size_t i = 0; i < models_.size(); ++i) {
        current_[i] = models_[i].is_static
                          ? previous_[i]
                          : physics::step(integrator_, models_[i], previous_[i], t, dt_);
      }
      break;
  }
  ++step_count_;
  for (std::size_t i = 0; i < models_.size(); ++i) {
    if (const Result<void> checked = check_in_bounds(current_[i]); !checked) {
      blow_up_ = BlowUp{.body = i, .time = time(), .step = step_count_, .what = checked.error()};
      return;
    }
  }
}

double Simulation::alpha_at(double t) const {
  return step_count_ == 0 ? 0.0 : (t - time_of_step(step_count_ - 1)) / dt_;
}

std::vector<physics::BodyState> Simulation::states_at(double t) {
  while (time() < t && !blow_up_) step();
  if (step_count_ == 0) return current_;
  assert(t >= time_of_step(step_count_ - 1));
  const double alpha = alpha_at(t);
  std::vector<physics::BodyState> out;
  out.reserve(models_.size());
  for (std::size_t i = 0; i < models_.size(); ++i) {
    out.push_back(physics::interpolate(previous_[i], current_[i], alpha, models_[i].constants));
  }
  return out;
}

}  // namespace tumble::sim
