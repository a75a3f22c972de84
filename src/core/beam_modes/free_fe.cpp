#include "core/beam_modes/free_fe.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/beam_modes/banded_pencil.hpp"
#include "core/beam_modes/shapes.hpp"

namespace sweetspot::beam_detail {
namespace {

// Above this many elements the free beam's modes are not solved densely
// (O(N^3): 2000 elements took 3 minutes) but located on a coarse mesh and
// each refined on the full one with the banded solver of the hand-held modes.
constexpr int kDenseFreeElements = 256;
// Below it too, the modes are refined when the coarse mesh has at most this
// share of the elements (few modes of a fine mesh): the dense solve finds
// every mode, O(N^3). At 30 elements, one mode: 81 us against 530 us, f1
// within 3e-11 of the dense solve's (which is itself 1.6e-10 from LAPACK's).
constexpr double kRefineBelowShare = 0.25;

// lowest_free_omega2's power iteration: at most kPowerSteps steps, done when
// the Rayleigh quotient moves by less than kPowerSettled of itself.
constexpr int kPowerSteps = 60;
constexpr double kPowerSettled = 1e-15;

std::optional<std::pair<VectorXd, MatrixXd>> refined_free_spectrum(const Mesh& mesh,
                                                                   const ModeOptions& options,
                                                                   const Mesh& coarse,
                                                                   std::string* why) {
  const auto [coarse_omega2, coarse_vectors] = free_spectrum(coarse);
  if (coarse_omega2.size() <= options.modes) {
    *why = "coarse mesh has too few modes";
    return std::nullopt;
  }
  // The beam's K and M with two unit masses on no spring in the hand's place:
  // the banded pencil needs them, and they stay decoupled (their part of
  // every vector is zero).
  const Assembled beam = assemble(mesh, nullptr);
  const int n = beam.beam_dofs;
  Assembled a;
  a.beam_dofs = n;
  a.K = MatrixXd::Zero(n + 2, n + 2);
  a.C = MatrixXd::Zero(n + 2, n + 2);
  a.M = MatrixXd::Zero(n + 2, n + 2);
  a.K.topLeftCorner(n, n) = beam.K;
  a.M.topLeftCorner(n, n) = beam.M;
  a.M(n, n) = a.M(n + 1, n + 1) = 1.0;
  // Undamped coarse modes as damped estimates: s = i omega.
  const int coarse_n = static_cast<int>(coarse_vectors.rows());
  std::vector<DampedPair> guesses;
  for (int k = 0; k <= options.modes; ++k) {
    VectorXcd q0 = VectorXcd::Zero(coarse_n + 2);
    q0.head(coarse_n) = coarse_vectors.col(k).cast<Complex>();
    guesses.push_back({Complex(0.0, std::sqrt(std::max(coarse_omega2(k), 0.0))), std::move(q0)});
  }
  QuadraticPencil pencil(a);
  std::vector<int> wanted(options.modes);
  std::iota(wanted.begin(), wanted.end(), 0);
  const auto pairs = refine_estimates(pencil, coarse, mesh, n + 2, guesses, wanted, why);
  if (!pairs) return std::nullopt;
  VectorXd omega2(options.modes);
  MatrixXd vectors(n, options.modes);
  for (int k = 0; k < options.modes; ++k) {
    // Undamped: the eigenvector is real up to one complex factor.
    const VectorXcd q = (*pairs)[k].q.head(n);
    Eigen::Index largest = 0;
    q.cwiseAbs().maxCoeff(&largest);
    const VectorXd real = (q * (std::abs(q(largest)) / q(largest))).real();
    omega2(k) = std::norm((*pairs)[k].s);
    vectors.col(k) = real / std::sqrt(real.dot(beam.M * real));
  }
  return std::pair{omega2, vectors};
}

}  // namespace

std::pair<VectorXd, MatrixXd> free_spectrum(const Mesh& mesh) {
  const Assembled a = assemble(mesh, nullptr);
  const MatrixXd Q = flexible_basis(mesh, a, nullptr);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  // Kr is positive definite once the rigid-body modes are gone, so solve the
  // inverted pencil Mr b = (1/omega^2) Kr b: its largest eigenvalues, the low
  // modes, come out with relative (not ~cond(K) times worse) accuracy.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr);
  const int m = static_cast<int>(Kr.rows());
  VectorXd omega2(m);
  MatrixXd vectors(a.M.rows(), m);
  for (int k = 0; k < m; ++k) {
    const int j = m - 1 - k;
    omega2(k) = 1.0 / es.eigenvalues()(j);
    const VectorXd b = es.eigenvectors().col(j);
    vectors.col(k) = Q * (b / std::sqrt(b.dot(Mr * b)));
  }
  return {omega2, vectors};
}

double lowest_free_omega2(const Mesh& mesh) {
  const Assembled a = assemble(mesh, nullptr);
  const auto [Kr, Mr] = flexible_matrices(mesh, a, nullptr);
  // The largest eigenvalue of the inverted pencil Mr b = (1/omega^2) Kr b by
  // power iteration: its Rayleigh quotient converges as (omega1/omega2)^(4k)
  // (0.13^(2k) on a uniform free beam), a few steps to round-off, where the
  // dense solve of every eigenvalue cost four times as much. A pencil that
  // does not settle (close first modes) is solved densely.
  const Eigen::LLT<MatrixXd> llt(Kr);
  if (llt.info() == Eigen::Success) {
    const int m = static_cast<int>(Kr.rows());
    VectorXd b = VectorXd::LinSpaced(m, 1.0, 2.0);
    double previous = 0.0;
    for (int step = 0; step < kPowerSteps; ++step) {
      const VectorXd Mb = Mr * b;
      const VectorXd next = llt.solve(Mb);
      // The Rayleigh quotient of `next`: Kr next = Mr b.
      const double quotient = next.dot(Mr * next) / next.dot(Mb);
      if (std::abs(quotient - previous) <= kPowerSettled * quotient) return 1.0 / quotient;
      previous = quotient;
      b = next / next.norm();
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr, Eigen::EigenvaluesOnly);
  return 1.0 / es.eigenvalues().maxCoeff();
}

std::pair<Mode, double> fe_mode(const Mesh& mesh, const VectorXd& q, double omega) {
  Mode mode;
  mode.frequency_Hz = mode.undamped_frequency_Hz = omega / (2.0 * kPi);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    mode.shape.push_back(mesh.elements[e].piece(q.segment<4>(2 * e)));
  }
  const double scale = normalise_and_find_nodes(mode);
  mode.fe_dofs.assign(q.data(), q.data() + q.size());
  if (scale < 0.0) {
    for (double& v : mode.fe_dofs) v = -v;
  }
  return {std::move(mode), scale};
}

RootCount missed_roots(const Segmentation& seg, const ModalResult& found, int wanted,
                       double rel_tol) {
  for (const Segment& s : seg.segments) {
    if (!(s.mu_kg_m > 0.0)) return {};
  }
  const double omega_top = 2.0 * kPi * found.modes.back().frequency_Hz;
  // About 3 elements per radian of phase at the top root: its FE frequency
  // within ~1e-4 of the exact one, lower modes closer still.
  const std::vector<int> counts = counts_for(seg, 3.0 * std::sqrt(omega_top));
  if (total_elements(counts) > kMaxElements) return {};
  const Mesh mesh = build_mesh(seg, counts, ModeOptions{});
  const VectorXd omega2 = free_spectrum(mesh).first;
  const double below = omega_top * omega_top * (1.0 - 1e-6);
  int count = 0;
  for (int k = 0; k < omega2.size(); ++k) count += omega2(k) < below ? 1 : 0;
  const int k_wanted = std::max(0, std::min(wanted, static_cast<int>(omega2.size())) - 1);
  const double omega_wanted = std::sqrt(std::max(omega2(k_wanted), 0.0));
  const double beta_h = std::pow(kHermiteErrorConstant * kToleranceSafety * rel_tol, 0.25);
  return {
      std::max(0, count - (static_cast<int>(found.modes.size()) - 1)),
      std::min(kMaxElements, total_elements(counts_for(seg, std::sqrt(omega_wanted) / beta_h)))};
}

ModalResult fe_free_modes(const Segmentation& seg, const ModeOptions& options) {
  ModalResult result;
  result.method = ModeOptions::Method::kFiniteElement;
  result.theory = options.theory;
  const std::vector<int> counts = element_counts(seg, options);
  const Mesh mesh = build_mesh(seg, counts, options);
  result.elements_used = static_cast<int>(mesh.elements.size());  // after merge_tiny_elements
  result.message = "finite elements: " + std::to_string(result.elements_used) + " elements";
  std::optional<std::pair<VectorXd, MatrixXd>> spectrum;
  const Mesh coarse = coarse_mesh(seg, options);
  if (result.elements_used > kDenseFreeElements ||
      kRefineBelowShare * static_cast<double>(result.elements_used) >=
          static_cast<double>(coarse.elements.size())) {
    std::string why;
    spectrum = refined_free_spectrum(mesh, options, coarse, &why);
    result.message += spectrum ? ", each mode refined from a " +
                                     std::to_string(coarse.elements.size()) + "-element solve"
                               : ", dense (refinement skipped: " + why + ")";
  }
  if (!spectrum) spectrum = free_spectrum(mesh);
  const auto& [omega2, vectors] = *spectrum;
  const int available = static_cast<int>(omega2.size());
  for (int k = 0; k < std::min(options.modes, available); ++k) {
    result.modes.push_back(
        fe_mode(mesh, vectors.col(k), std::sqrt(std::max(omega2(k), 0.0))).first);
  }
  result.complete = static_cast<int>(result.modes.size()) == options.modes;
  return result;
}

}  // namespace sweetspot::beam_detail
