// One box stepped over and over, each step from the last one's end, for the step benchmarks:
// physics_bench times a run (Google Benchmark, CPU time) and step_instructions counts its
// instructions (callgrind). A run evolves as a scene does, so its figures are those of real
// steps, not of one state stepped again and again (which a cache keyed on the state would
// flatter, and which leaves out what the state grows into: a resting box's solve residue once
// sank into subnormal numbers and took 1.7 times as long).
#pragma once

#include <cstdint>
#include <vector>

#include "physics/integrators.hpp"
#include "physics/plane_contact_step.hpp"
#include "physics/world_step.hpp"

namespace tumble::bench {

inline constexpr double kBenchStep = 1.0 / 60.0;  // s
// A sliding run starts again from its start after this many steps: at 3 m/s and μ = 0.5 the box
// stops after 0.61 s, 36 steps, so every step timed is one of sliding.
inline constexpr int kSlideSteps = 30;

// A box of mass 1 kg under gravity: shape 0 a unit cube, 1 a 1 × 0.3 × 2 m box (lying on its
// largest face when it rests: sliding along x it does not tip), its centre `height` (m) above the
// floor y = 0.
physics::BodyModel box_under_gravity(std::int64_t shape);
physics::BodyState box_at(const physics::BodyModel& model, double height /* m */);

// What steps the box.
enum class Stepper {
  free,    // physics::step alone: the box falls, with no plane anywhere
  planes,  // physics::step_with_planes on the floor
  world,   // physics::step_world on the floor, as a scene of one box steps it
};

class BoxRun {
 public:
  // The box stepped by `stepper` and `integrator` at kBenchStep. On the floor (planes, world) it
  // first settles for 10 s; then, with `speed` (m/s) along x, it slides from there, restarting
  // every kSlideSteps steps. `sleep`: the world's ContactSettings::sleep (planes and free steps
  // have none); a box resting on the floor is asleep by the end of its 10 s with it.
  BoxRun(Stepper stepper, physics::Integrator integrator, std::int64_t shape, double speed = 0.0,
         bool sleep = false);

  void step();  // one step of kBenchStep

  const physics::BodyState& state() const { return states_[0]; }
  bool asleep() const { return !world_.memory.asleep.empty() && world_.memory.asleep[0] != 0; }

 private:
  void advance();

  Stepper stepper_;
  physics::Integrator integrator_;
  std::vector<physics::BodyModel> models_;
  std::vector<physics::Plane> planes_;
  physics::ContactSettings settings_;
  std::vector<physics::BodyState> states_, next_;
  physics::WorldContacts plane_memory_;
  physics::WorldContacts world_;
  // The sliding start, and the memory it had: a restart copies them back (no allocation once
  // the buffers have their sizes).
  bool restarts_ = false;
  physics::BodyState start_;
  physics::WorldContacts plane_memory_at_start_;
  physics::WorldContacts world_at_start_;
  int steps_since_start_ = 0;
  double time_ = 0.0;  // s
};

}  // namespace tumble::bench
