// The normal rows of a small island solved together, exactly, as one linear complementarity
// problem, where sequential impulses solve them one after another; and the same for the position
// projection's points.
//
// Why: Gauss-Seidel moves an error between a heavy body and a light one by a factor r/(1+r) per
// pass (r the mass ratio), so a 1000 kg cube on a 1 kg one needs thousands of passes and sinks
// through it in any budget; and the four points of a face, solved in turn, leave a spin that the
// physics does not have (two cubes head-on, a cube striking a plate face-on) and, in the
// projection, a tilt that grows step by step under a heavy load. Solved as one block the rows give
// every point its share at once, whatever the masses, and a symmetric contact a symmetric answer.
// Box2D 2.4 solved a two-point manifold so (its "block solver", total enumeration of the 2 x 2
// LCP); ODE's dWorldStep and Bullet's btMLCPSolver solve a whole island's rows as one LCP
// (Dantzig, Lemke); DART holds a 1000:1 stack with such a solve where sequential impulses sink it
// (dartsim/dart#3442). This one is Murty's principal pivoting method (K. G. Murty, "Note on a
// Bard-type scheme for solving the complementarity problem", Opsearch 11, 1974): the rows pushing
// are a guess, solved as equalities; the guess changes by the row of least index that breaks a
// condition (a pushing row pulling, or a free row approaching), which ends in finitely many
// changes for a positive definite matrix. The four coplanar points of a face make the matrix
// singular (a rigid face has three degrees of freedom, not four): it is regularised by
// kRegularisation of its largest diagonal, which picks the least-norm impulses (the symmetric
// share of a symmetric contact) and leaves a row's speed short of its target by that fraction of
// its impulse over its mass at most (a 100 kg cube resting on a 1 kg one sinks 2e-9 m/s so,
// which the projection takes back).
//
// The cost grows as the cube of the rows, so only islands of up to kMostBlockRows rows are solved
// so; larger ones (piles) keep sequential impulses, where sub-steps carry what a pass misses.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/contact_solver.hpp"

namespace tumble::physics {

// The most rows an island may have for them to be solved as one block: a tower of ten cubes on a
// floor has 40.
inline constexpr std::size_t kMostBlockRows = 48;
inline constexpr double kRegularisation = 1e-10;

// A row of a block: a direction pushing body a along it and b against it (b kStatic for a
// static shape), with its Jacobian and its image through the inverse inertias.
struct BlockRow {
  std::uint32_t a = 0;
  std::uint32_t b = kStatic;
  const ImpulseDirection* direction = nullptr;
};

// Into `out`: A = J M⁻¹ Jᵀ of the rows, the change of each row's relative speed (m/s) per unit
// impulse (N s) along each row, with `inverse_masses` (1/kg) the bodies'.
void block_matrix(std::span<const BlockRow> rows, std::span<const double> inverse_masses,
                  Eigen::MatrixXd& out);

// A linear complementarity problem w = A λ + q, λ >= 0, w >= 0, λᵢ wᵢ = 0 with a fixed matrix
// (its factorisations kept while the guess of pushing rows stays the same).
class BlockLcp {
 public:
  // The matrix A (symmetric, positive semi-definite).
  void set_matrix(const Eigen::MatrixXd& matrix);
  const Eigen::MatrixXd& matrix() const { return matrix_; }
  std::size_t size() const { return static_cast<std::size_t>(matrix_.rows()); }

  // Solves for `offset` q into `solution` λ, starting from the guess that the rows with
  // `solution` > 0 on entry (or q < 0) push. `tolerance`: how far below zero a w may be (in q's
  // units). Returns false, `solution` unspecified, if the pivoting did not end (it should not: a
  // bound on the changes guards against rounding).
  bool solve(const Eigen::VectorXd& offset, double tolerance, Eigen::VectorXd& solution);

 private:
  Eigen::MatrixXd matrix_;
  double regulariser_ = 0.0;
  std::vector<char> pushing_;
  std::vector<int> active_, factored_;
  Eigen::MatrixXd sub_;
  Eigen::VectorXd rhs_;
  Eigen::LDLT<Eigen::MatrixXd> factor_;
};

// The normal rows of some points of an island as one block.
class NormalBlock {
 public:
  // The rows of the points `rows` (indices into `points`), at the bodies' masses.
  void build(std::span<const SolverBody> bodies, std::span<const ContactConstraint> points,
             std::span<const std::uint32_t> rows);

  std::size_t size() const { return rows_.size(); }

  // Solves the rows: each ends with an impulse λ >= 0 (its entry of `impulses`, N s, which holds
  // the impulse already applied to the bodies on entry) and a relative normal speed of at least
  // its entry of `least` (m/s), equal where λ > 0. Applies the impulses' change to the bodies.
  // Returns false, changing nothing, if the block did not solve.
  bool solve(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
             std::span<const double> least, std::span<double> impulses);

 private:
  std::vector<std::uint32_t> rows_;
  BlockLcp lcp_;
  Eigen::MatrixXd matrix_;
  Eigen::VectorXd offset_, solved_;
};

}  // namespace tumble::physics
