// The fixed-step clock: every body advances in steps of exactly dt, and any time in between is
// answered by interpolating the two steps that bracket it, so frame rate and step are independent.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "physics/contact.hpp"
#include "physics/integrators.hpp"
#include "physics/joint_solve.hpp"
#include "physics/penalty_pairs.hpp"
#include "physics/rigid_body.hpp"
#include "physics/world_step.hpp"

namespace tumble::sim {

// Past these a body's motion is taken to have blown up (a step far beyond the integrator's
// stability limit, or forces that are not what the scene meant): no scene tumble can draw moves
// a billion metres, at a third of the speed of light, or turns ten million radians a second.
inline constexpr double kMaxPosition = 1e9;      // m from the origin
inline constexpr double kMaxSpeed = 1e8;         // m/s
inline constexpr double kMaxAngularSpeed = 1e7;  // rad/s

// The first body whose state became non-finite or passed a bound, and when.
struct BlowUp {
  std::size_t body = 0;
  double time = 0.0;      // s: the step at which it was found
  std::int64_t step = 0;  // that step's number
  std::string what;       // e.g. "its velocity is not finite"
};

// Succeeds when the state is finite and within the bounds above; else the error says what is
// wrong with it ("its speed is not finite"), for BlowUp::what.
Result<void> check_in_bounds(const physics::BodyState& state);

class Simulation {
 public:
  // One model and one initial state per body. With impulse contact the bodies touch the planes
  // and each other (unless contact.collide_bodies is false or a model does not collide) through
  // the world step (physics/world_step.hpp). With no planes and nothing that collides each body
  // runs its integrator alone, the code that ran before contact existed. Penalty contact is a
  // force law of each body (physics::PenaltyContact) and needs no planes here.
  Simulation(std::vector<physics::BodyModel> models, std::vector<physics::BodyState> initial,
             physics::Integrator integrator, double dt /* s */,
             std::vector<physics::Plane> planes = {}, physics::ContactSettings contact = {},
             std::vector<physics::Joint> joints = {});

  // Advances every body by one step of dt. Once a body has blown up, nothing moves any more.
  void step();

  // Steps until the current step time is at or past t (s), then returns every body's state at t,
  // interpolated between the previous and the current step. t must not go backwards past the
  // previous step. Check blow_up() after each call: the states are meaningless once it is set.
  std::vector<physics::BodyState> states_at(double t);

  // Where t (s) is between previous() (0) and current() (1), as states_at(t) interpolates; 0
  // before the first step. Call after states_at(t).
  double alpha_at(double t) const;

  // Set by the step at which the first body blew up (see kMaxPosition).
  const std::optional<BlowUp>& blow_up() const { return blow_up_; }

  double dt() const { return dt_; }
  std::int64_t step_count() const { return step_count_; }
  // n dt, computed by multiplication so that no rounding accumulates over long runs (s).
  double time() const { return time_of_step(step_count_); }
  double time_of_step(std::int64_t n) const { return static_cast<double>(n) * dt_; }

  const std::vector<physics::BodyModel>& models() const { return models_; }
  const std::vector<physics::BodyState>& current() const { return current_; }
  const std::vector<physics::BodyState>& previous() const { return previous_; }
  // The joints and what they keep (their last impulses, for joint_wrenches).
  const physics::JointWorld& joints() const { return joints_; }
  // The contacts of the last step with impulse contact (empty otherwise): each body's manifolds
  // with the planes and each touching pair's, with their points' impulses.
  const physics::ContactMemory& contact_memory() const { return contacts_.memory; }

 private:
  std::vector<physics::BodyModel> models_;
  std::vector<physics::BodyState> previous_;  // at time_of_step(step_count_ - 1)
  std::vector<physics::BodyState> current_;   // at time_of_step(step_count_)
  physics::Integrator integrator_;
  double dt_;
  std::vector<physics::Plane> planes_;
  physics::ContactSettings contact_;
  // How a step goes: each body alone (with penalty contact, its planes are its own force law);
  // the world step of impulse contact, whenever anything can touch; penalty contact between
  // bodies that can touch each other; or the bodies together under their joints, when nothing
  // can touch (physics/joint_solve.hpp).
  enum class Stepping { alone, impulse_world, penalty_world, joint_world };
  Stepping stepping_ = Stepping::alone;
  // The manifolds from step to step (warm starting the contact solve).
  physics::WorldContacts contacts_;
  physics::PenaltyWorld penalty_;  // its scratch
  physics::JointWorld joints_;
  std::int64_t step_count_ = 0;
  std::optional<BlowUp> blow_up_;
};

}  // namespace tumble::sim
