#include "core/beam_modes/banded_pencil.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweetspot::beam_detail {
namespace {

// Rayleigh-functional iteration: at most this many steps per mode ...
constexpr int kMaxRefineSteps = 12;
// ... and a mode is accepted when its backward error (relative to the norms
// of K, C and M) is below kRefineAccept. It stops at round-off: a backward
// error below kRefineDone or one that no longer falls by kRefineStall.
constexpr double kRefineAccept = 1e-11;
constexpr double kRefineDone = 1e-14;
constexpr double kRefineStall = 0.1;
// A refined mode must lie nearer its coarse estimate than this fraction of
// the distance to the nearest other coarse mode, or the match is ambiguous.
constexpr double kMatchFraction = 0.25;

}  // namespace

std::optional<DampedPair> refine_damped_pair(QuadraticPencil& t, Complex s, VectorXcd q) {
  auto form = [](const VectorXcd& u, const VectorXcd& v) { return (u.transpose() * v)(0); };
  const double norm_K = t.norm(0), norm_C = t.norm(1), norm_M = t.norm(2);
  q /= q.norm();
  double error = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= kMaxRefineSteps; ++step) {
    const VectorXcd Kq = t.apply(1.0, 0.0, 0.0, q);
    const VectorXcd Cq = t.apply(0.0, 1.0, 0.0, q);
    const VectorXcd Mq = t.apply(0.0, 0.0, 1.0, q);
    const Complex a2 = form(q, Mq), a1 = form(q, Cq), a0 = form(q, Kq);
    const Complex root = std::sqrt(a1 * a1 - 4.0 * a2 * a0);
    const Complex s1 = (-a1 + root) / (2.0 * a2), s2 = (-a1 - root) / (2.0 * a2);
    const Complex next = std::abs(s1 - s) <= std::abs(s2 - s) ? s1 : s2;
    // Backward error of (s, q): the relative change of K, C, M that makes it exact.
    const double next_error = (Kq + next * Cq + next * next * Mq).norm() /
                              (norm_K + std::abs(next) * norm_C + std::norm(next) * norm_M);
    const bool stalled = step > 0 && !(next_error < kRefineStall * error);
    if (!stalled) s = next;
    error = std::min(error, next_error);
    if (error < kRefineDone || stalled || step == kMaxRefineSteps) break;
    if (!t.factorize(s)) break;  // s is an eigenvalue to working precision
    const VectorXcd x = t.solve(2.0 * s * Mq + Cq);
    const double norm = x.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return std::nullopt;
    q = x / norm;
  }
  if (!(error < kRefineAccept)) return std::nullopt;
  return DampedPair{s, std::move(q)};
}

std::optional<std::vector<DampedPair>> refine_estimates(QuadraticPencil& pencil, const Mesh& coarse,
                                                        const Mesh& mesh, int size,
                                                        const std::vector<DampedPair>& guesses,
                                                        const std::vector<int>& which,
                                                        std::string* why) {
  std::vector<DampedPair> out;
  for (const int k : which) {
    const Complex s0 = guesses[k].s;
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < guesses.size(); ++j) {
      if (static_cast<int>(j) != k) gap = std::min(gap, std::abs(guesses[j].s - s0));
    }
    // The conjugate root is a neighbour too (and the overdamped real axis between).
    gap = std::min(gap, 2.0 * s0.imag());
    std::optional<DampedPair> pair =
        refine_damped_pair(pencil, s0, interpolate_dofs(coarse, guesses[k].q, mesh, size));
    if (!pair) {
      *why = "mode " + std::to_string(k + 1) + " did not converge";
      return std::nullopt;
    }
    if (!(std::abs(pair->s - s0) < kMatchFraction * gap)) {
      *why = "mode " + std::to_string(k + 1) + " moved too far from its coarse estimate";
      return std::nullopt;
    }
    out.push_back(std::move(*pair));
  }
  return out;
}

}  // namespace sweetspot::beam_detail
