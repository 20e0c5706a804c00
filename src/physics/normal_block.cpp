#include "physics/normal_block.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::physics {
namespace {

// The part of a row on body k: its sign (+1 on a, -1 on b), its moment arm × direction and its
// turn per unit impulse; false when the row does not move body k.
struct RowOnBody {
  double sign;
  const Vec3* moment;
  const Vec3* turn;
};
bool row_on(const BlockRow& row, std::uint32_t k, RowOnBody& out) {
  if (row.a == k) {
    out = {1.0, &row.direction->moment_a, &row.direction->turn_a};
    return true;
  }
  if (row.b == k) {
    out = {-1.0, &row.direction->moment_b, &row.direction->turn_b};
    return true;
  }
  return false;
}

// The change of row i's relative speed per unit impulse along row j, through their common bodies.
double coupling(const BlockRow& i, const BlockRow& j, std::span<const double> inverse_masses) {
  double out = 0.0;
  for (const std::uint32_t k : {i.a, i.b}) {
    if (k == kStatic) continue;
    RowOnBody on_i, on_j;
    if (!row_on(j, k, on_j)) continue;
    row_on(i, k, on_i);
    out += on_i.sign * on_j.sign *
           (inverse_masses[k] * i.direction->linear.dot(j.direction->linear) +
            on_i.moment->dot(*on_j.turn));
  }
  return out;
}

// Changes of the guess allowed per row before a solve gives up.
constexpr int kPivotsPerRow = 8;

}  // namespace

void block_matrix(std::span<const BlockRow> rows, std::span<const double> inverse_masses,
                  Eigen::MatrixXd& out) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  out.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) {
      const double a = coupling(rows[static_cast<std::size_t>(i)],
                                rows[static_cast<std::size_t>(j)], inverse_masses);
      out(i, j) = a;
      out(j, i) = a;
    }
  }
}

void BlockLcp::set_matrix(const Eigen::MatrixXd& matrix) {
  matrix_ = matrix;
  regulariser_ = matrix_.rows() > 0 ? kRegularisation * matrix_.diagonal().maxCoeff() : 0.0;
  factored_.assign(1, -1);  // no factorisation of this matrix yet
}

bool BlockLcp::solve(const Eigen::VectorXd& offset, double tolerance, Eigen::VectorXd& solution) {
  const Eigen::Index n = matrix_.rows();
  pushing_.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    pushing_[static_cast<std::size_t>(i)] = solution(i) > 0.0 || offset(i) < 0.0;
  }
  const int most = kPivotsPerRow * static_cast<int>(n) + 8;
  for (int change = 0; change < most; ++change) {
    active_.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
      if (pushing_[static_cast<std::size_t>(i)]) active_.push_back(static_cast<int>(i));
    }
    const auto m = static_cast<Eigen::Index>(active_.size());
    if (active_ != factored_) {
      sub_.resize(m, m);
      for (Eigen::Index r = 0; r < m; ++r) {
        for (Eigen::Index c = 0; c < m; ++c) sub_(r, c) = matrix_(active_[r], active_[c]);
        sub_(r, r) += regulariser_;
      }
      factor_.compute(sub_);
      factored_ = active_;
    }
    rhs_.resize(m);
    for (Eigen::Index r = 0; r < m; ++r) rhs_(r) = -offset(active_[r]);
    solution.setZero(n);
    if (m > 0) {
      const Eigen::VectorXd x = factor_.solve(rhs_);
      for (Eigen::Index r = 0; r < m; ++r) solution(active_[r]) = x(r);
    }
    const Eigen::VectorXd w = matrix_ * solution + offset;
    const double largest = solution.cwiseAbs().maxCoeff();
    // Murty's rule: the broken condition of least index changes the guess.
    Eigen::Index broken = -1;
    for (Eigen::Index i = 0; i < n && broken < 0; ++i) {
      const bool pushes = pushing_[static_cast<std::size_t>(i)] != 0;
      if (pushes ? solution(i) < -1e-12 * largest : w(i) < -tolerance) broken = i;
    }
    if (broken < 0) {
      solution = solution.cwiseMax(0.0);
      return true;
    }
    pushing_[static_cast<std::size_t>(broken)] ^= 1;
  }
  return false;
}

void NormalBlock::build(std::span<const SolverBody> bodies,
                        std::span<const ContactConstraint> points,
                        std::span<const std::uint32_t> rows) {
  rows_.assign(rows.begin(), rows.end());
  std::vector<BlockRow> block;
  block.reserve(rows_.size());
  for (const std::uint32_t i : rows_) {
    block.push_back({.a = points[i].a, .b = points[i].b, .direction = &points[i].normal});
  }
  std::vector<double> inverse_masses;
  inverse_masses.reserve(bodies.size());
  for (const SolverBody& body : bodies) inverse_masses.push_back(body.inverse_mass);
  block_matrix(block, inverse_masses, matrix_);
  lcp_.set_matrix(matrix_);
}

bool NormalBlock::solve(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
                        std::span<const double> least, std::span<double> impulses) {
  const auto n = static_cast<Eigen::Index>(rows_.size());
  if (n == 0) return true;
  // q = u - least - A λ: the speeds less `least` the rows would have with no impulse of theirs.
  solved_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) solved_(i) = impulses[static_cast<std::size_t>(i)];
  offset_ = -(lcp_.matrix() * solved_);
  double scale = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const ContactConstraint& c = points[rows_[k]];
    const double above =
        relative_speed(c.normal, bodies[c.a], c.b == kStatic ? nullptr : &bodies[c.b]) - least[k];
    offset_(i) += above;
    scale = std::max(scale, std::abs(above));
  }
  if (!lcp_.solve(offset_, 1e-10 * scale + 1e-14, solved_)) return false;
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const ContactConstraint& c = points[rows_[k]];
    push(c.normal, bodies[c.a], c.b == kStatic ? nullptr : &bodies[c.b], solved_(i) - impulses[k]);
    impulses[k] = solved_(i);
  }
  return true;
}

}  // namespace tumble::physics
