#include "bench/chain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "physics/joints.hpp"
#include "sim/simulation.hpp"

namespace tumble::bench {

ChainRun run_chain_in_tumble(int links, double seconds, double dt, physics::Integrator integrator) {
  using physics::Vec3;
  const Vec3 pivot(0.0, 0.0, 0.0);
  const physics::Quat along_x(Eigen::AngleAxisd(-std::numbers::pi / 2.0, Vec3::UnitZ()));
  std::vector<physics::BodyModel> models;
  std::vector<physics::BodyState> states;
  for (int k = 0; k < links; ++k) {
    models.push_back(
        {.constants = physics::box_constants(kChainLinkMass, Vec3(0.02, kChainLinkLength, 0.02)),
         .forces = {physics::Gravity{.acceleration = Vec3(0.0, -9.81, 0.0)}},
         .shape = physics::box_shape(Vec3(0.01, 0.5 * kChainLinkLength, 0.01)),
         .collides = false});
    states.push_back(physics::make_state(models.back().constants,
                                         pivot + Vec3((k + 0.5) * kChainLinkLength, 0.0, 0.0),
                                         Vec3::Zero(), along_x, Vec3::Zero()));
  }
  std::vector<physics::Joint> joints;
  for (int k = 0; k < links; ++k) {
    const Vec3 top = pivot + Vec3(k * kChainLinkLength, 0.0, 0.0);
    joints.push_back(physics::place_joint(
        physics::JointKind::ball, static_cast<std::uint32_t>(k),
        k == 0 ? physics::kWorldBody : static_cast<std::uint32_t>(k - 1), states, top, top));
  }
  const auto widest = [&](const std::vector<physics::BodyState>& now) {
    double out = 0.0;
    for (const physics::Joint& joint : joints) {
      out = std::max(out, physics::joint_opening(joint, now));
    }
    return out;
  };
  sim::Simulation simulation(models, states, integrator, dt, {}, {}, joints);
  ChainRun run{.engine = "tumble (" + std::string(physics::integrator_name(integrator)) + ")",
               .steps = std::llround(seconds / dt)};
  double stepping = 0.0;  // s of wall clock inside the steps
  for (std::int64_t n = 0; n < run.steps; ++n) {
    const auto start = std::chrono::steady_clock::now();
    simulation.step();
    stepping += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (simulation.blow_up()) {
      run.blew_up = true;
      run.steps = n + 1;
      break;
    }
    run.final_widest_gap = widest(simulation.current());
    run.widest_gap = std::max(run.widest_gap, run.final_widest_gap);
  }
  run.ms_per_step = 1e3 * stepping / static_cast<double>(std::max<std::int64_t>(run.steps, 1));
  return run;
}

}  // namespace tumble::bench
