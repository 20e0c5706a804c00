// Hard cases for the integrators: one body each, with a start, a duration and a final state that
// can be trusted — a closed form where one exists, otherwise a long-double RKF78 solution checked
// against a second solution at a looser tolerance (bench/reference_solver.hpp).
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bench/reference_solver.hpp"
#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::bench {

// Tolerances of the two odeint runs behind every reference: the trusted one, and a looser one
// whose distance from it bounds the trusted one's error.
inline constexpr double kReferenceTolerance = 1e-18;
inline constexpr double kCrossCheckTolerance = 1e-16;

// Which error a case is judged by in plots: what the case is about.
enum class HeadlineError { orientation, position };

struct Reference {
  FinalState state;  // the final state runs are measured against
  bool closed_form = false;
  // relative_difference between the odeint runs at kReferenceTolerance and kCrossCheckTolerance.
  double tolerance_difference = 0.0;
  // For a closed form: relative_difference between it and the odeint run at kReferenceTolerance.
  std::optional<double> closed_form_difference;
};

struct HardCase {
  std::string name;     // short, for files and tables: "article_cube"
  std::string summary;  // one line for people
  physics::BodyModel model;
  physics::BodyState initial;
  double duration = 0.0;  // s; a whole number of every benchmarked step
  // No net torque (|L| is constant) / no work done on the body (kinetic energy is constant).
  bool conserves_angular_momentum = false;
  bool conserves_energy = false;
  HeadlineError headline = HeadlineError::orientation;
  // The exact final state, for cases that have one; empty otherwise.
  std::function<FinalState()> closed_form = nullptr;

  // The trusted final state: computed on first use (the odeint runs take up to a second), then
  // kept for the process and shared by copies of this case. Thread-safe.
  const Reference& reference() const;

  struct ReferenceCache {
    std::once_flag once;
    Reference value;
  };
  std::shared_ptr<ReferenceCache> cache = std::make_shared<ReferenceCache>();
};

// Every hard case, in a fixed order (see hard_cases.cpp for what each one is and why).
const std::vector<HardCase>& hard_cases();
// The case of that name, or nullptr.
const HardCase* find_hard_case(const std::string& name);

}  // namespace tumble::bench
