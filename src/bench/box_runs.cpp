#include "bench/box_runs.hpp"

namespace tumble::bench {

using namespace physics;

BodyModel box_under_gravity(std::int64_t shape) {
  const Vec3 size = shape == 0 ? Vec3::Ones() : Vec3(1.0, 0.3, 2.0);
  BodyModel model{.constants = box_constants(1.0, size), .forces = {Gravity{}}};
  model.shape.half_size = 0.5 * size;
  return model;
}

BodyState box_at(const BodyModel& model, double height) {
  return make_state(model.constants, Vec3(0, height, 0), Vec3::Zero(), Quat::Identity(),
                    Vec3::Zero());
}

BoxRun::BoxRun(Stepper stepper, Integrator integrator, std::int64_t shape, double speed, bool sleep)
    : stepper_(stepper),
      integrator_(integrator),
      models_{box_under_gravity(shape)},
      settings_{.sleep = sleep},
      next_(1) {
  const BodyModel& model = models_[0];
  states_ = {box_at(model, model.shape.half_size.y())};
  if (stepper == Stepper::free) return;
  planes_ = {Plane{}};
  for (int n = 0; n < 600; ++n) advance();
  if (speed == 0.0) return;
  PrimaryState moving = states_[0].primary();
  moving.momentum.x() = model.constants.mass * speed;
  start_ = BodyState(moving, model.constants);
  states_[0] = start_;
  plane_memory_at_start_ = plane_memory_;
  world_at_start_ = world_;
  restarts_ = true;
}

void BoxRun::advance() {
  switch (stepper_) {
    case Stepper::free:
      states_[0] = physics::step(integrator_, models_[0], states_[0], time_, kBenchStep);
      break;
    case Stepper::planes:
      states_[0] = step_with_planes(integrator_, models_[0], states_[0], time_, kBenchStep, planes_,
                                    settings_, plane_memory_);
      break;
    case Stepper::world:
      step_world(integrator_, models_, states_, time_, kBenchStep, planes_, settings_, world_,
                 next_);
      states_.swap(next_);
      break;
  }
  time_ += kBenchStep;
}

void BoxRun::step() {
  if (restarts_ && steps_since_start_ == kSlideSteps) {
    states_[0] = start_;
    plane_memory_ = plane_memory_at_start_;
    world_ = world_at_start_;
    steps_since_start_ = 0;
  }
  advance();
  ++steps_since_start_;
}

}  // namespace tumble::bench
