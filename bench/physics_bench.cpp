// Micro-benchmarks of one physics step (Google Benchmark; not run by ctest):
//   build/physics_bench [--benchmark_filter=Cube]
// Each integrator on a cube (scalar inertia: no matrix work) and on a box (R I⁻¹ Rᵀ per
// evaluation), and a cube with no force laws against one with four: a body pays only for the
// laws its scene lists. BlowUpCheck is the per-body check Simulation adds to every step.
#include <benchmark/benchmark.h>

#include <iterator>
#include <string>

#include "physics/integrators.hpp"
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

constexpr std::int64_t kLastIntegrator = std::size(kAllIntegrators) - 1;

BENCHMARK(StepCube)->DenseRange(0, kLastIntegrator)->ArgName("integrator");
BENCHMARK(BlowUpCheck);
BENCHMARK(StepBox)->DenseRange(0, kLastIntegrator)->ArgName("integrator");
BENCHMARK(StepCubeWithForceLaws)
    ->ArgsProduct({benchmark::CreateDenseRange(0, kLastIntegrator, 1), {0, 4}})
    ->ArgNames({"integrator", "laws"});

}  // namespace

BENCHMARK_MAIN();
