// Micro-benchmarks of one physics step (Google Benchmark; not run by ctest):
//   build/physics_bench [--benchmark_filter=Cube]
// Each integrator on a cube (scalar inertia: no matrix work) and on a box (R I⁻¹ Rᵀ per
// evaluation), and a cube with no force laws against one with four: a body pays only for the
// laws its scene lists. BlowUpCheck is the per-body check Simulation adds to every step.
#include <benchmark/benchmark.h>

#include <iterator>
#include <string>

#include "physics/integrators.hpp"
#include "physics/plane_contact_step.hpp"
#include "physics/world_step.hpp"
#include "sim/simulation.hpp"

namespace {

using namespace tumble::physics;

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
  for (auto _ : state) benchmark::DoNotOptimize(tumble::sim::blow_up_problem(body));
}

// Contact with a plane (range(0) = integrator), one step from the same state each time: a box
// resting on a floor under gravity through the world step (impulse contact), the same box sliding
// at 3 m/s, or resting with penalty contact, against the same box's free step
// (StepBoxWithGravity); and the box 10 m above the floor, where the world step only finds that
// nothing touches.
// range(1): 0 for a unit cube, 1 for a 0.3 × 1 × 2 m box on its long face.
BodyModel box_under_gravity(std::int64_t shape) {
  const Vec3 size = shape == 0 ? Vec3::Ones() : Vec3(0.3, 1.0, 2.0);
  BodyModel model{.constants = box_constants(1.0, size), .forces = {Gravity{}}};
  model.half_size = 0.5 * size;
  return model;
}

BodyState box_at(const BodyModel& model, double height /* m */) {
  return make_state(model.constants, Vec3(0, height, 0), Vec3::Zero(), Quat::Identity(),
                    Vec3::Zero());
}

void StepBoxWithGravity(benchmark::State& state) {
  const BodyModel model = box_under_gravity(state.range(1));
  const Integrator integrator = integrator_at(state.range(0));
  const BodyState start = box_at(model, 0.5);
  for (auto _ : state) benchmark::DoNotOptimize(step(integrator, model, start, 0.0, kDt));
  state.SetLabel(std::string(integrator_name(integrator)));
}

// `speed` (m/s) along x once settled: a sliding box, whose friction works at its limit.
void step_with_floor_repeatedly(benchmark::State& state, double height /* m */,
                                double speed = 0.0) {
  const BodyModel model = box_under_gravity(state.range(1));
  const Integrator integrator = integrator_at(state.range(0));
  const std::vector<Plane> floor = {Plane{}};
  PlaneContacts memory;
  // Settled first, so that the resting box is timed with its warm-started manifold.
  BodyState start = box_at(model, height);
  for (int n = 0; n < 600; ++n) {
    start = step_with_planes(integrator, model, start, 0.0, kDt, floor, {}, memory);
  }
  if (height > 1.0) start = box_at(model, height);
  if (speed != 0.0) {
    PrimaryState moving = start.primary();
    moving.momentum.x() = model.constants.mass * speed;
    start = BodyState(moving, model.constants);
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        step_with_planes(integrator, model, start, 0.0, kDt, floor, {}, memory));
  }
  state.SetLabel(std::string(integrator_name(integrator)));
}

void StepBoxRestingOnPlane(benchmark::State& state) {
  step_with_floor_repeatedly(state, 0.5);
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
  const BodyState start = box_at(model, 0.5 - sink);
  for (auto _ : state) benchmark::DoNotOptimize(step(integrator, model, start, 0.0, kDt));
  state.SetLabel(std::string(integrator_name(integrator)));
}
void StepBoxSlidingOnPlane(benchmark::State& state) {
  step_with_floor_repeatedly(state, 0.5, 3.0);
}

// The resting unit cube through the world step, as a scene steps it, each step from the last
// one's end: range(1) = 0 awake (sleep = false), 1 with sleeping on (the default), which the
// cube has fallen into during the 10 s it settles before it is timed.
void StepWorldBoxRestingOnPlane(benchmark::State& state) {
  const BodyModel model = box_under_gravity(0);
  const Integrator integrator = integrator_at(state.range(0));
  const std::vector<BodyModel> models = {model};
  const std::vector<Plane> floor = {Plane{}};
  const ContactSettings settings{.sleep = state.range(1) != 0};
  WorldContacts contacts;
  std::vector<BodyState> states = {box_at(model, 0.5)}, next(1);
  double t = 0.0;
  const auto step_once = [&] {
    step_world(integrator, models, states, t, kDt, floor, settings, contacts, next);
    states.swap(next);
    t += kDt;
  };
  for (int n = 0; n < 600; ++n) step_once();
  for (auto _ : state) {
    step_once();
    benchmark::DoNotOptimize(states);
  }
  state.SetLabel(std::string(integrator_name(integrator)) +
                 (contacts.asleep[0] ? " asleep" : " awake"));
}

// The unit cube sliding at 3 m/s on the floor through the world step, awake (sleep = false),
// each step from the same state (a box sliding on would stop within 0.6 s): the world step's
// counterpart of StepBoxSlidingOnPlane/shape:0.
void StepWorldBoxSlidingOnPlane(benchmark::State& state) {
  const BodyModel model = box_under_gravity(0);
  const Integrator integrator = integrator_at(state.range(0));
  const std::vector<BodyModel> models = {model};
  const std::vector<Plane> floor = {Plane{}};
  const ContactSettings settings{.sleep = false};
  WorldContacts contacts;
  std::vector<BodyState> start = {box_at(model, 0.5)}, next(1);
  for (int n = 0; n < 600; ++n) {
    step_world(integrator, models, start, 0.0, kDt, floor, settings, contacts, next);
    start.swap(next);
  }
  PrimaryState moving = start[0].primary();
  moving.momentum.x() = model.constants.mass * 3.0;  // m/s
  start[0] = BodyState(moving, model.constants);
  for (auto _ : state) {
    step_world(integrator, models, start, 0.0, kDt, floor, settings, contacts, next);
    benchmark::DoNotOptimize(next);
  }
  state.SetLabel(std::string(integrator_name(integrator)));
}

void StepBoxAbovePlane(benchmark::State& state) {
  step_with_floor_repeatedly(state, 10.0);
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
