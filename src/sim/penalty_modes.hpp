// The linear modes penalty contact (physics::PenaltyContact) gives a box lying on a face, which
// the step-size advice checks (sim/stability.hpp), and the restitution of its flat landing, which
// picks the damping for a wanted bounce.
#pragma once

#include <vector>

#include "physics/forces.hpp"
#include "physics/rigid_body.hpp"
#include "sim/stability.hpp"

namespace tumble::sim {

struct PenaltyMode {
  enum class Kind {
    bounce,  // the centre moving along the plane's normal on four corners
    rock,    // the box turning about an in-face axis on four corners
    slide,   // the corners slipping along the plane, the box rocking with it (friction)
    twist,   // the box turning about the face's normal (friction)
  };
  Kind kind = Kind::bounce;
  // Every mode's damping is the law's own, which a splitting kick evaluates once (frozen).
  LinearMode mode;
  int axis = -1;       // rock, slide: the body axis turned about; twist: the face's normal axis
  double lever = 0.0;  // m: rock, the in-face lever a_l; slide, the height h of the centre
};

struct PenaltyModes {
  PenaltyMode bounce;
  std::vector<PenaltyMode> rocking;  // one per body axis, with its longer lever
  // The regularised friction's decays, one per body axis for sliding and one per face normal
  // for twisting; empty without friction or gravity (nothing presses the box on a plane).
  std::vector<PenaltyMode> slipping;
  double friction = 0.0;  // μ: the largest of the law's planes
};

// The modes of a box with `constants` under `law`, lying on any face of it on a plane
// perpendicular to `gravity` (m/s², world frame), from the linearised law with four corners in
// contact (penalty_modes.cpp derives them).
PenaltyModes penalty_modes(const physics::BodyConstants& constants,
                           const physics::PenaltyContact& law, const physics::Vec3& gravity);

// The restitution of a box landing flat on four corners under penalty contact, as a function of
// the damping ratio of its bounce, ζ = c / sqrt(k m) (k, c per corner, m the mass), gravity
// during the contact neglected: e = exp(-2 ζ acos ζ / sqrt(1 - ζ²)), or with acosh for ζ > 1,
// and e^-2 at ζ = 1. It is not the linear damped spring's exp(-ζ π / sqrt(1 - ζ²)): the law only
// pushes, so the box leaves when k d - c v_n reaches 0, before the spring is back at its length.
double penalty_restitution(double damping_ratio);

// The damping per corner (N s/m) that gives a flat landing the restitution e in (0, 1), for
// stiffness k per corner (N/m) and mass m (kg): c = ζ sqrt(k m) with penalty_restitution(ζ) = e.
double penalty_damping_for_restitution(double restitution, double stiffness, double mass);

}  // namespace tumble::sim
