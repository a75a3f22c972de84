#include "core/beam_modes/hand_held.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/beam_modes/free_fe.hpp"
#include "core/beam_modes/shapes.hpp"

namespace sweetspot::beam_detail {
namespace {

// The coarse damped problem is solved in the basis of this many undamped
// modes more than requested.
constexpr int kExtraBasisModes = 4;
// A coarse mode whose hand share lies this near kHandModeEnergyShare is not
// classified on the coarse mesh (shares are near 1 or near 0 in practice).
constexpr double kShareMargin = 0.2;

}  // namespace

OscillatoryRoots select_oscillatory(const VectorXcd& eigenvalues, int drift, int wanted) {
  const int n = static_cast<int>(eigenvalues.size());
  std::vector<int> by_size(n);
  for (int j = 0; j < n; ++j) by_size[j] = j;
  std::sort(by_size.begin(), by_size.end(),
            [&](int i, int j) { return std::abs(eigenvalues(i)) < std::abs(eigenvalues(j)); });
  OscillatoryRoots out;
  for (int k = std::min(drift, n); k < n; ++k) {
    const int j = by_size[k];
    const Complex s = eigenvalues(j);
    if (s.imag() > kRealRootTol * std::abs(s)) out.order.push_back(j);
    if (std::abs(s.imag()) <= kRealRootTol * std::abs(s)) ++out.overdamped;
  }
  std::sort(out.order.begin(), out.order.end(),
            [&](int i, int j) { return eigenvalues(i).imag() < eigenvalues(j).imag(); });
  if (static_cast<int>(out.order.size()) > wanted) out.order.resize(wanted);
  return out;
}

DampedSpectrum dense_damped_spectrum(const Mesh& mesh, const Assembled& a, const HandCoupling& hand,
                                     int wanted) {
  const MatrixXd Q = flexible_basis(mesh, a, &hand);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Cr = Q.transpose() * a.C * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  const int m = static_cast<int>(Mr.rows());

  // y = L^T b with Mr = L L^T: y'' + Ct y' + Kt y = 0, then the state space
  // x = (y, y'), x' = A x, A = [0 I; -Kt -Ct].
  const Eigen::LLT<MatrixXd> llt(Mr);
  const MatrixXd Kt = llt.matrixL().solve(MatrixXd(llt.matrixL().solve(Kr)).transpose());
  const MatrixXd Ct = llt.matrixL().solve(MatrixXd(llt.matrixL().solve(Cr)).transpose());
  // Balance: x = (sigma y, y') with sigma ~ the highest natural frequency
  // makes both off-diagonal blocks O(sigma) instead of O(1) and O(sigma^2),
  // so the low eigenvalues keep relative accuracy.
  const double sigma = std::sqrt(std::max(Kt.diagonal().maxCoeff(), 1e-300));
  MatrixXd A = MatrixXd::Zero(2 * m, 2 * m);
  A.topRightCorner(m, m) = sigma * MatrixXd::Identity(m, m);
  A.bottomLeftCorner(m, m) = -Kt / sigma;
  A.bottomRightCorner(m, m) = -Ct;
  const Eigen::EigenSolver<MatrixXd> es(A, true);

  DampedSpectrum out;
  const OscillatoryRoots roots = select_oscillatory(es.eigenvalues(), drift_roots(hand), wanted);
  out.overdamped = roots.overdamped;
  for (int j : roots.order) {
    const VectorXcd y = es.eigenvectors().col(j).head(m) / sigma;
    const VectorXd b_re = llt.matrixU().solve(y.real());
    const VectorXd b_im = llt.matrixU().solve(y.imag());
    VectorXcd q = (Q * b_re).cast<Complex>() + Complex(0, 1) * (Q * b_im).cast<Complex>();
    out.pairs.push_back({es.eigenvalues()(j), std::move(q)});
  }
  return out;
}

DampedSpectrum modal_damped_spectrum(const Mesh& mesh, const Assembled& a, const HandCoupling& hand,
                                     int wanted, int basis) {
  const MatrixXd Q = flexible_basis(mesh, a, &hand);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  // Inverted pencil as in free_spectrum: the low modes keep relative accuracy.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr);
  const int n = static_cast<int>(Kr.rows());
  const int r = std::min(basis, n);
  MatrixXd phi(n, r);
  VectorXd omega2(r);
  for (int k = 0; k < r; ++k) {
    const int j = n - 1 - k;
    omega2(k) = 1.0 / es.eigenvalues()(j);
    const VectorXd b = es.eigenvectors().col(j);
    phi.col(k) = b / std::sqrt(b.dot(Mr * b));
  }
  const MatrixXd QPhi = Q * phi;
  const MatrixXd Cm = QPhi.transpose() * a.C * QPhi;
  const double sigma = std::sqrt(std::max(omega2(r - 1), 1e-300));
  MatrixXd A = MatrixXd::Zero(2 * r, 2 * r);
  A.topRightCorner(r, r) = sigma * MatrixXd::Identity(r, r);
  A.bottomLeftCorner(r, r).diagonal() = -omega2 / sigma;
  A.bottomRightCorner(r, r) = -Cm;
  const Eigen::EigenSolver<MatrixXd> ses(A, true);
  DampedSpectrum out;
  const OscillatoryRoots roots = select_oscillatory(ses.eigenvalues(), drift_roots(hand), wanted);
  out.overdamped = roots.overdamped;
  for (int j : roots.order) {
    const VectorXcd y = ses.eigenvectors().col(j).head(r);
    out.pairs.push_back({ses.eigenvalues()(j), QPhi.cast<Complex>() * y});
  }
  return out;
}

namespace {

// The shape of q turned to be as real as possible and its real part
// mass-normalised (phi^T M phi = 1), with |Im|/|Re| of the turned beam part.
// Mass-weighted rather than a sum over nodes, so the angle (and the nodes of
// the turned shape) converge with the mesh at the element's rate. M is real
// and symmetric: q_b^T M_b q_b = a^T M a - b^T M b + 2i a^T M b for q = a + ib.
struct TurnedShape {
  VectorXd re;
  double complexity = 0.0;
};
TurnedShape turned_shape(const Assembled& a, VectorXcd q) {
  const int nb = a.beam_dofs;
  const auto Mb = a.M.topLeftCorner(nb, nb);
  {
    const VectorXd qa = q.head(nb).real(), qb = q.head(nb).imag();
    const VectorXd Ma = Mb * qa, Mqb = Mb * qb;
    const Complex sum_sq(qa.dot(Ma) - qb.dot(Mqb), 2.0 * qa.dot(Mqb));
    q *= std::exp(Complex(0, -0.5 * std::arg(sum_sq)));
  }
  const VectorXd q_re = q.head(nb).real(), q_im = q.head(nb).imag();
  const double re2 = q_re.dot(Mb * q_re), im2 = q_im.dot(Mb * q_im);
  TurnedShape out;
  out.re = q.real();
  out.re /= std::sqrt(out.re.dot(a.M * out.re));
  out.complexity = std::sqrt(im2 / re2);
  return out;
}

// The hand's share of the kinetic energy of a mass-normalised real shape.
double hand_share(const Assembled& a, const VectorXd& re) {
  const int u = a.beam_dofs;
  return a.M(u, u) * re(u) * re(u) + a.M(u + 1, u + 1) * re(u + 1) * re(u + 1);
}

}  // namespace

Mode damped_mode(const Mesh& mesh, const Assembled& a, Complex s, VectorXcd q) {
  const TurnedShape turned = turned_shape(a, std::move(q));
  auto [mode, scale] = fe_mode(mesh, turned.re, std::abs(s));
  mode.frequency_Hz = s.imag() / (2.0 * kPi);
  // The grip's dashpot can only take energy out: a root a rounding error to
  // the right of the axis (an undamped grip) is undamped, not negatively damped.
  mode.damping_ratio = std::max(0.0, -s.real() / std::abs(s));
  mode.complexity = turned.complexity;
  mode.hand_displacement = scale * turned.re(a.beam_dofs);
  mode.hand_energy_fraction = hand_share(a, turned.re);
  return mode;
}

double damped_hand_share(const Assembled& a, const VectorXcd& q) {
  return hand_share(a, turned_shape(a, q).re);
}

std::optional<DampedSpectrum> refined_damped_spectrum(const Mesh& mesh, const Assembled& a,
                                                      const HandCoupling& hand,
                                                      const ModeOptions& options,
                                                      const Mesh& coarse, std::string* why,
                                                      bool beam_fundamental_only) {
  const Assembled ca = assemble(coarse, &hand);
  const DampedSpectrum guess =
      modal_damped_spectrum(coarse, ca, hand, options.modes + 1, options.modes + kExtraBasisModes);
  if (static_cast<int>(guess.pairs.size()) <= options.modes) {
    *why = "coarse mesh has too few oscillatory modes";
    return std::nullopt;
  }
  std::vector<int> wanted;
  if (beam_fundamental_only) {
    for (int k = 0; k < options.modes; ++k) {
      const double share = damped_hand_share(ca, guess.pairs[k].q);
      if (std::abs(share - kHandModeEnergyShare) < kShareMargin) {
        wanted.clear();  // too near the line to trust the coarse mesh: refine them all
        break;
      }
      if (share < kHandModeEnergyShare) {
        wanted.push_back(k);
        break;
      }
    }
  }
  if (wanted.empty()) {
    wanted.resize(options.modes);
    std::iota(wanted.begin(), wanted.end(), 0);
  }
  QuadraticPencil pencil(a);
  auto pairs = refine_estimates(pencil, coarse, mesh, static_cast<int>(a.M.rows()), guess.pairs,
                                wanted, why);
  if (!pairs) return std::nullopt;
  return DampedSpectrum{std::move(*pairs), guess.overdamped};
}

}  // namespace sweetspot::beam_detail
