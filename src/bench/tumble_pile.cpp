#include "bench/tumble_pile.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "physics/world_step.hpp"

namespace tumble::bench {
namespace {

// How many contact points the step's manifolds hold, with planes and between boxes.
int count_points(const physics::WorldContacts& contacts) {
  int points = 0;
  for (const physics::PairContact& pair : contacts.memory.pairs) {
    for (int k = 0; k < pair.manifold.count; ++k) {
      if (pair.manifold.points[static_cast<std::size_t>(k)].separation <
          physics::kTouchingDistance) {
        ++points;
      }
    }
  }
  for (const std::vector<physics::Manifold>& planes : contacts.memory.planes) {
    for (const physics::Manifold& m : planes) points += m.count;
  }
  return points;
}

}  // namespace

std::string tumble_engine_name() {
  return "tumble (impulse, rk4)";
}

PileRun run_pile_in_tumble(const Pile& pile, const StepObserver& observer) {
  std::vector<physics::BodyModel> models;
  std::vector<physics::BodyState> states;
  for (const PileBox& box : pile.boxes) {
    models.push_back({.constants = constants_of(box),
                      .forces = {physics::Gravity{.acceleration = pile.gravity}},
                      .shape = shape_of(box),
                      .material = pile.box_material});
    states.push_back(physics::make_state(models.back().constants, box.position, box.velocity,
                                         box.orientation, box.angular_velocity));
  }
  std::vector<physics::BodyState> next(states.size());
  physics::WorldContacts contacts;
  const physics::ContactSettings settings;
  PileDepth depth_of;
  std::vector<physics::BoxPose> poses(pile.boxes.size());
  PileRun run;
  run.engine = tumble_engine_name();
  for (int n = 0; n < pile.steps; ++n) {
    const std::clock_t cpu_start = std::clock();
    const auto wall_start = std::chrono::steady_clock::now();
    physics::step_world(physics::Integrator::rk4, models, states, n * pile.dt, pile.dt, pile.planes,
                        settings, contacts, next);
    const auto wall_end = std::chrono::steady_clock::now();
    const std::clock_t cpu_end = std::clock();
    states.swap(next);
    run.step_ms.push_back(std::chrono::duration<double, std::milli>(wall_end - wall_start).count());
    run.step_cpu_ms.push_back(1000.0 * static_cast<double>(cpu_end - cpu_start) / CLOCKS_PER_SEC);
    for (std::size_t i = 0; i < states.size(); ++i) {
      poses[i] = {.position = states[i].position(),
                  .rotation = states[i].rotation(),
                  .half_size = models[i].shape.half_size};
    }
    const double depth = depth_of(pile, poses);
    run.contacts.push_back(count_points(contacts));
    run.depth_m.push_back(depth);
    run.largest_penetration_m = std::max(run.largest_penetration_m, depth);
    double top = 0.0;
    for (const physics::BodyState& s : states) top = std::max(top, s.velocity().norm());
    run.top_speed.push_back(top);
    if (observer) observer(run);
  }
  for (const physics::BodyState& s : states) {
    run.final_positions.push_back(s.position());
    if (!inside_bin(pile, s.position())) ++run.escaped;
  }
  run.largest_final_speed = run.top_speed.empty() ? 0.0 : run.top_speed.back();
  return run;
}

}  // namespace tumble::bench
