#pragma once

// The quadratic pencil T(s) = s^2 M + s C + K of a mesh, banded, and the
// Rayleigh-functional iteration that converges an estimated eigenpair on it.
// Internal to the beam-mode solvers.

#include <optional>
#include <string>
#include <vector>

#include "core/beam_modes/fe_mesh.hpp"

namespace sweetspot::beam_detail {

// An eigenpair of (s^2 M + s C + K) q = 0, q over every DOF of the mesh.
struct DampedPair {
  Complex s;
  VectorXcd q;
};

// T(s) = s^2 M + s C + K of a hand-held mesh, stored by structure: the beam
// DOFs are banded (half-bandwidth 3, one element joins two nodes) and the two
// hand DOFs, last, couple only to the grip. With T = [A B; B^T D] (complex
// symmetric), A gets a banded LU with partial pivoting and the hand a 2 x 2
// Schur complement: O(n) per factorisation and solve.
class QuadraticPencil {
 public:
  static constexpr int kBand = 3;
  static constexpr int kLd = 3 * kBand + 1;  // LU rows per column (fill-in kBand above)

  explicit QuadraticPencil(const Assembled& a) : n_(a.beam_dofs) {
    const MatrixXd* src[3] = {&a.K, &a.C, &a.M};
    for (int m = 0; m < 3; ++m) {
      band_[m].assign(static_cast<std::size_t>(n_) * (2 * kBand + 1), 0.0);
      for (int j = 0; j < n_; ++j) {
        for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
          band_[m][j * (2 * kBand + 1) + (i - j + kBand)] = (*src[m])(i, j);
        }
      }
      border_[m] = src[m]->block(0, n_, n_, 2);
      corner_[m] = src[m]->block(n_, n_, 2, 2);
    }
  }

  // Infinity norm of K (m = 0), C (1) or M (2).
  double norm(int m) const {
    VectorXd rows = VectorXd::Zero(n_ + 2);
    for (int j = 0; j < n_; ++j) {
      for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
        rows(i) += std::abs(band_[m][j * (2 * kBand + 1) + (i - j + kBand)]);
      }
    }
    rows.head(n_) += border_[m].cwiseAbs().rowwise().sum();
    rows.tail(2) +=
        border_[m].cwiseAbs().colwise().sum().transpose() + corner_[m].cwiseAbs().rowwise().sum();
    return rows.maxCoeff();
  }

  // (c0 K + c1 C + c2 M) q.
  VectorXcd apply(Complex c0, Complex c1, Complex c2, const VectorXcd& q) const {
    VectorXcd out = VectorXcd::Zero(n_ + 2);
    const Complex c[3] = {c0, c1, c2};
    for (int m = 0; m < 3; ++m) {
      if (c[m] == 0.0) continue;
      for (int j = 0; j < n_; ++j) {
        const Complex cq = c[m] * q(j);
        for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
          out(i) += band_[m][j * (2 * kBand + 1) + (i - j + kBand)] * cq;
        }
      }
      out.head(n_) += c[m] * (border_[m].cast<Complex>() * q.tail(2));
      out.tail(2) += c[m] * (border_[m].transpose().cast<Complex>() * q.head(n_) +
                             corner_[m].cast<Complex>() * q.tail(2));
    }
    return out;
  }

  // Factorises T(s); false when a pivot vanishes (s is an eigenvalue of A or T).
  bool factorize(Complex s) {
    const Complex c[3] = {1.0, s, s * s};
    lu_.assign(static_cast<std::size_t>(n_) * kLd, 0.0);
    pivots_.assign(n_, 0);
    inverse_pivots_.assign(n_, 0.0);
    for (int j = 0; j < n_; ++j) {
      for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
        Complex v = 0.0;
        for (int m = 0; m < 3; ++m) v += c[m] * band_[m][j * (2 * kBand + 1) + (i - j + kBand)];
        at(i, j) = v;
      }
    }
    for (int k = 0; k < n_; ++k) {
      const int last_row = std::min(n_ - 1, k + kBand);
      const int last_col = std::min(n_ - 1, k + 2 * kBand);
      int p = k;
      // |Re| + |Im| as in LAPACK: no hypot in the inner loop.
      auto size = [](Complex z) { return std::abs(z.real()) + std::abs(z.imag()); };
      for (int i = k + 1; i <= last_row; ++i) {
        if (size(at(i, k)) > size(at(p, k))) p = i;
      }
      pivots_[k] = p;
      if (at(p, k) == 0.0) return false;
      if (p != k) {
        for (int j = k; j <= last_col; ++j) std::swap(at(k, j), at(p, j));
      }
      const Complex inv = 1.0 / at(k, k);
      inverse_pivots_[k] = inv;
      for (int i = k + 1; i <= last_row; ++i) {
        const Complex l = at(i, k) * inv;
        at(i, k) = l;
        if (l == 0.0) continue;
        for (int j = k + 1; j <= last_col; ++j) at(i, j) -= l * at(k, j);
      }
    }
    border_s_ = Eigen::MatrixX2cd(n_, 2);
    Eigen::Matrix2cd corner = Eigen::Matrix2cd::Zero();
    border_s_.setZero();
    for (int m = 0; m < 3; ++m) {
      border_s_ += c[m] * border_[m].cast<Complex>();
      corner += c[m] * corner_[m].cast<Complex>();
    }
    solved_border_ = border_s_;
    for (int col = 0; col < 2; ++col) {
      VectorXcd v = solved_border_.col(col);
      band_solve(v);
      solved_border_.col(col) = v;
    }
    schur_ = corner - border_s_.transpose() * solved_border_;
    const Complex det = schur_.determinant();
    if (det == 0.0) return false;
    schur_inverse_ = schur_.inverse();
    return true;
  }

  // x with T(s) x = r for the last factorised s.
  VectorXcd solve(const VectorXcd& r) const {
    VectorXcd xb = r.head(n_);
    band_solve(xb);
    const Eigen::Vector2cd xh = schur_inverse_ * (r.tail(2) - border_s_.transpose() * xb);
    VectorXcd x(n_ + 2);
    x.head(n_) = xb - solved_border_ * xh;
    x.tail(2) = xh;
    return x;
  }

 private:
  Complex& at(int i, int j) { return lu_[j * kLd + (i - j + 2 * kBand)]; }
  const Complex& at(int i, int j) const { return lu_[j * kLd + (i - j + 2 * kBand)]; }

  void band_solve(VectorXcd& b) const {
    for (int k = 0; k < n_; ++k) {
      if (pivots_[k] != k) std::swap(b(k), b(pivots_[k]));
      for (int i = k + 1; i <= std::min(n_ - 1, k + kBand); ++i) b(i) -= at(i, k) * b(k);
    }
    for (int k = n_ - 1; k >= 0; --k) {
      Complex sum = b(k);
      for (int j = k + 1; j <= std::min(n_ - 1, k + 2 * kBand); ++j) sum -= at(k, j) * b(j);
      b(k) = sum * inverse_pivots_[k];
    }
  }

  int n_ = 0;
  std::vector<double> band_[3];  // K, C, M of the beam DOFs, column-major band
  Eigen::MatrixX2d border_[3];   // beam-hand coupling
  Eigen::Matrix2d corner_[3];    // hand-hand
  std::vector<Complex> lu_;
  std::vector<int> pivots_;
  std::vector<Complex> inverse_pivots_;
  Eigen::MatrixX2cd border_s_, solved_border_;
  Eigen::Matrix2cd schur_, schur_inverse_;
};

// Converges an estimate (s, q) to an eigenpair of T(s) q = 0 by
// Rayleigh-functional iteration: s <- the root of q^T T(s) q = 0 nearest s,
// q <- T(s)^-1 T'(s) q. T is complex symmetric, so q is its own left
// eigenvector and the iteration converges cubically. Empty if it does not
// reach kRefineAccept.
std::optional<DampedPair> refine_damped_pair(QuadraticPencil& t, Complex s, VectorXcd q);

// The coarse estimates guesses[k] for each k of `which` (s, q on `coarse`;
// `guesses` ascending, one more than the last wanted so it is matched
// unambiguously) refined on `mesh`, in the order of `which`. Each must stay
// within kMatchFraction of the distance to its nearest neighbour (or its
// conjugate root); else empty with a reason. Each refinement depends on its
// own estimate only.
std::optional<std::vector<DampedPair>> refine_estimates(QuadraticPencil& pencil, const Mesh& coarse,
                                                        const Mesh& mesh, int size,
                                                        const std::vector<DampedPair>& guesses,
                                                        const std::vector<int>& which,
                                                        std::string* why);

}  // namespace sweetspot::beam_detail
