// Micro-benchmarks of one physics step (Google Benchmark; not run by ctest):
//   build/physics_bench [--benchmark_filter=Cube]
// Each integrator on a cube (scalar inertia: no matrix work) and on a box (R I⁻¹ Rᵀ per
// evaluation), and a cube with no force laws against one with four: a body pays only for the
// laws its scene lists. BlowUpCheck is the per-body check Simulation adds to every step.
#include <benchmark/benchmark.h>

#include <iterator>
#include <string>

#include "bench/box_runs.hpp"
#include "physics/integrators.hpp"
#include "physics/plane_contact_step.hpp"
#include "physics/world_step.hpp"
#include "sim/simulation.hpp"

namespace {

using namespace tumble::physics;
using tumble::bench::box_at;
using tumble::bench::box_under_gravity;
using tumble::bench::BoxRun;
using tumble::bench::Stepper;

constexpr double kDt = 1.0 / 60.0;  // s

Integrator integrator_at(std::int64_t index) {
  return kAllIntegrators[index];
}

// Steps one body over and over from `start`, the time advancing as in a run.
void step_repeatedly(benchmark::State& state, Integrator integrator, const BodyModel& model,
                     const BodyState& start) {
  BodyState body = start;
  double t = 0.0;
  for (auto _ : state) {
    body = step(integrator, model, body, t, kDt);
    t += kDt;
    benchmark::DoNotOptimize(body);
  }
  state.SetLabel(std::string(integrator_name(integrator)));
}

BodyState spinning(const BodyConstants& constants) {
  return make_state(constants, Vec3::Zero(), Vec3(0.5, 1.0, 0.0),
                    Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized())), Vec3(1.0, -2.0, 3.0));
}

void StepCube(benchmark::State& state) {
  const BodyModel model{.constants = cube_constants(1.0, 1.0), .forces = {}};
  step_repeatedly(state, integrator_at(state.range(0)), model, spinning(model.constants));
}

void StepBox(benchmark::State& state) {
  const BodyModel model{.constants = box_constants(1.0, Vec3(0.3, 1.0, 2.0)), .forces = {}};
  step_repeatedly(state, integrator_at(state.range(0)), model, spinning(model.constants));
}

// range(1): 0 for no force laws, 4 for gravity, linear damping, angular damping and a torque.
void StepCubeWithForceLaws(benchmark::State& state) {
  BodyModel model{.constants = cube_constants(1.0, 1.0), .forces = {}};
  if (state.range(1) == 4) {
    model.forces = {Gravity{}, LinearDamping{.coefficient = 0.1},
                    AngularDamping{.coefficient = 0.1},
                    ConstantTorque{.torque = Vec3(1.0, 0.0, 0.0)}};
  }
  step_repeatedly(state, integrator_at(state.range(0)), model, spinning(model.constants));
}

// The check every Simulation::step makes of each body for a blow-up (non-finite values, bounds):
// compare with StepCube to see what it adds to a step.
void BlowUpCheck(benchmark::State& state) {
  const BodyState body = spinning(cube_constants(1.0, 1.0));
  for (auto _ : state) benchmark::DoNotOptimize(tumble::sim::check_in_bounds(body));
}

// Contact with a plane (range(0) = integrator), each step from the last one's end
// (bench/box_runs.hpp): a box resting on a floor under gravity (impulse contact), through
// step_with_planes and through the world step as a scene of one box steps it, or sliding at
// 3 m/s (restarted every 30 steps, before it stops), against the same box's free fall
// (StepBoxWithGravity). The ratios are what issue 11 bounds (a step on a plane at most twice the
// free RK4 step); bench/step_instructions.cpp counts the same runs' instructions with callgrind.
// range(1): 0 for a unit cube, 1 for a 1 × 0.3 × 2 m box on its largest face.
void time_run(benchmark::State& state, BoxRun& run) {
  for (auto _ : state) {
    run.step();
    benchmark::DoNotOptimize(run.state());
  }
}

void StepBoxWithGravity(benchmark::State& state) {
  const Integrator integrator = integrator_at(state.range(0));
  BoxRun run(Stepper::free, integrator, state.range(1));
  time_run(state, run);
  state.SetLabel(std::string(integrator_name(integrator)));
}

void StepBoxRestingOnPlane(benchmark::State& state) {
  const Integrator integrator = integrator_at(state.range(0));
  BoxRun run(Stepper::planes, integrator, state.range(1));
  time_run(state, run);
  state.SetLabel(std::string(integrator_name(integrator)));
}

void StepBoxSlidingOnPlane(benchmark::State& state) {
  const Integrator integrator = integrator_at(state.range(0));
  BoxRun run(Stepper::planes, integrator, state.range(1), 3.0);
  time_run(state, run);
  state.SetLabel(std::string(integrator_name(integrator)));
}

// The same box resting on the floor with penalty contact instead: the PenaltyContact law (the
// default k = 1e5 N/m, c = 500 N s/m per corner) evaluated at every stage of the integrator, no
// world step. It starts at rest sunk by m g/(4k), where the forces balance, so one step from there
// is what a resting step costs at any dt (1/60 s itself is far beyond penalty's stable step).
void StepBoxRestingOnPenaltyPlane(benchmark::State& state) {
  BodyModel model = box_under_gravity(state.range(1));
  const Integrator integrator = integrator_at(state.range(0));
  const ContactSettings contact{.method = ContactMethod::penalty};
  model = with_penalty_contact(model, {Plane{}}, contact.stiffness, contact.damping);
  const double sink = model.constants.mass * 9.81 / (4.0 * contact.stiffness);  // m
  const BodyState start = box_at(model, model.shape.half_size.y() - sink);
  for (auto _ : state) benchmark::DoNotOptimize(step(integrator, model, start, 0.0, kDt));
  state.SetLabel(std::string(integrator_name(integrator)));
}

// The resting unit cube through the world step: range(1) = 0 awake (sleep = false), 1 with
// sleeping on (the default), which the cube has fallen into during the 10 s it settles.
void StepWorldBoxRestingOnPlane(benchmark::State& state) {
  const Integrator integrator = integrator_at(state.range(0));
  BoxRun run(Stepper::world, integrator, 0, 0.0, state.range(1) != 0);
  time_run(state, run);
  state.SetLabel(std::string(integrator_name(integrator)) + (run.asleep() ? " asleep" : " awake"));
}

// The unit cube sliding at 3 m/s on the floor through the world step, awake: the world step's
// counterpart of StepBoxSlidingOnPlane/shape:0.
void StepWorldBoxSlidingOnPlane(benchmark::State& state) {
  const Integrator integrator = integrator_at(state.range(0));
  BoxRun run(Stepper::world, integrator, 0, 3.0);
  time_run(state, run);
  state.SetLabel(std::string(integrator_name(integrator)));
}

// The box 10 m above the floor, one step from the same state each time: the world step only
// finds that nothing touches.
void StepBoxAbovePlane(benchmark::State& state) {
  const BodyModel model = box_under_gravity(state.range(1));
  const Integrator integrator = integrator_at(state.range(0));
  const std::vector<Plane> floor = {Plane{}};
  WorldContacts memory;
  const BodyState start = box_at(model, 10.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        step_with_planes(integrator, model, start, 0.0, kDt, floor, {}, memory));
  }
  state.SetLabel(std::string(integrator_name(integrator)));
}

constexpr std::int64_t kLastIntegrator = std::size(kAllIntegrators) - 1;

BENCHMARK(StepCube)->DenseRange(0, kLastIntegrator)->ArgName("integrator");
BENCHMARK(BlowUpCheck);
BENCHMARK(StepBox)->DenseRange(0, kLastIntegrator)->ArgName("integrator");
BENCHMARK(StepBoxWithGravity)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 1}})
    ->ArgNames({"integrator", "shape"});
BENCHMARK(StepBoxRestingOnPlane)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 1}})
    ->ArgNames({"integrator", "shape"});
BENCHMARK(StepBoxSlidingOnPlane)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 1}})
    ->ArgNames({"integrator", "shape"});
BENCHMARK(StepBoxRestingOnPenaltyPlane)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 1}})
    ->ArgNames({"integrator", "shape"});
BENCHMARK(StepWorldBoxRestingOnPlane)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 1}})
    ->ArgNames({"integrator", "sleep"});
BENCHMARK(StepWorldBoxSlidingOnPlane)->DenseRange(0, kLastIntegrator)->ArgName("integrator");
BENCHMARK(StepBoxAbovePlane)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 1}})
    ->ArgNames({"integrator", "shape"});
BENCHMARK(StepCubeWithForceLaws)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 4}})
    ->ArgNames({"integrator", "laws"});

}  // namespace

BENCHMARK_MAIN();
