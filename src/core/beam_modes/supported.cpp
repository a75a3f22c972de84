// supported_modes() of beam_modes.hpp: the free beam's finite elements with
// the DOFs a clamp or a pivot fixes removed.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/beam_modes/fe_mesh.hpp"
#include "core/beam_modes/free_fe.hpp"
#include "core/beam_modes/segmentation.hpp"
#include "core/beam_modes/shapes.hpp"
#include "core/check.hpp"
#include "sweetspot/beam_modes.hpp"

namespace sweetspot {
namespace {

using beam_detail::MatrixXd;
using beam_detail::VectorXd;

// Nodes closer than this share of the length to a support's end are on it.
constexpr double kOnSupport = 1e-9;
// A stretch outside a clamp that moves less than this share of the mode's
// largest displacement is held still with it: no node is reported there.
constexpr double kStillShare = 1e-3;

}  // namespace

ModalResult supported_modes(const std::vector<Section>& sections,
                            const std::vector<PointMass>& point_masses, const BeamSupport& support,
                            const ModeOptions& options) {
  using namespace beam_detail;
  const double length = validated_length(sections, true);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  if (options.method != ModeOptions::Method::kFiniteElement) {
    throw std::invalid_argument(
        "options.method: the modes of a supported beam are found by finite elements only");
  }
  const bool clamped = support.kind == BeamSupport::Kind::kClamped;
  const double from = support.from_m;
  const double to = clamped ? support.to_m : support.from_m;
  if (!(from >= 0.0 && from <= length)) {
    fail(clamped ? "support.from_m" : "support.pivot_m",
         "on the beam [0, " + detail::format_number(length) + "] m", from);
  }
  if (clamped && !(to >= from && to <= length)) {
    fail("support.to_m",
         "in [support.from_m, beam length] = [" + detail::format_number(from) + ", " +
             detail::format_number(length) + "] m",
         to);
  }
  const Segmentation seg = segment(sections, point_masses, {from, to}, timoshenko_of(options));
  // A support's ends are nodes of the mesh: a segment that ends on one is
  // its own element at least, never grouped with the next across the support
  // (a bat's profile groups its short stations).
  std::vector<int> counts = element_counts(seg, options);
  for (std::size_t i = 0; i < seg.segments.size(); ++i) {
    const double end = seg.segments[i].start_m + seg.segments[i].length_m;
    for (const double x : {from, to}) {
      if (std::abs(end - x) <= kOnSupport * length) counts[i] = std::max(counts[i], 1);
    }
  }
  const Mesh mesh = build_mesh(seg, counts, options, {from, to});
  const Assembled a = assemble(mesh, nullptr);
  const int n = static_cast<int>(a.K.rows());
  // The DOFs the support leaves free: (w_i, theta_i) at node i.
  const double tol = kOnSupport * length;
  std::vector<bool> fixed(static_cast<std::size_t>(n), false);
  std::size_t held = 0;
  for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i) {
    const double x = mesh.nodes_m[i];
    if (x < from - tol || x > to + tol) continue;
    ++held;
    fixed[2 * i] = true;
    if (clamped) fixed[2 * i + 1] = true;
  }
  if (held == 0) {
    throw std::logic_error("supported_modes: no node of the mesh on the support at " +
                           detail::format_number(from) + " m");
  }
  std::vector<int> free_dofs;
  for (int j = 0; j < n; ++j) {
    if (!fixed[static_cast<std::size_t>(j)]) free_dofs.push_back(j);
  }
  const int m = static_cast<int>(free_dofs.size());
  MatrixXd S = MatrixXd::Zero(n, m);
  for (int j = 0; j < m; ++j) S(free_dofs[static_cast<std::size_t>(j)], j) = 1.0;
  MatrixXd B = S;
  if (!clamped) {
    // The rigid turn about the pivot (w = x - p, theta = 1) costs no strain:
    // keep the M-orthogonal complement of it (one Householder reflection).
    VectorXd turn = VectorXd::Zero(n);
    for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i) {
      turn(static_cast<int>(2 * i)) = mesh.nodes_m[i] - from;
      turn(static_cast<int>(2 * i + 1)) = 1.0;
    }
    for (int j = 0; j < n; ++j) {
      if (fixed[static_cast<std::size_t>(j)]) turn(j) = 0.0;  // w at the pivot: 0 to round-off
    }
    const VectorXd v = S.transpose() * (a.M * turn);
    Eigen::HouseholderQR<MatrixXd> qr(v);
    const MatrixXd H = qr.householderQ() * MatrixXd::Identity(m, m);
    B = S * H.rightCols(m - 1);
  }
  const MatrixXd Kr = B.transpose() * a.K * B;
  const MatrixXd Mr = B.transpose() * a.M * B;
  // As free_spectrum(): the inverted pencil, the low modes with relative accuracy.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr);
  ModalResult result;
  result.method = ModeOptions::Method::kFiniteElement;
  result.theory = options.theory;
  result.elements_used = static_cast<int>(mesh.elements.size());
  result.message = "finite elements: " + std::to_string(result.elements_used) + " elements, " +
                   (clamped ? "clamped" : "pinned");
  const int count = static_cast<int>(Kr.rows());
  for (int k = 0; k < std::min(options.modes, count); ++k) {
    const int j = count - 1 - k;
    const VectorXd b = es.eigenvectors().col(j);
    const VectorXd q = B * (b / std::sqrt(b.dot(Mr * b)));
    Mode mode = fe_mode(mesh, q, 1.0 / std::sqrt(es.eigenvalues()(j))).first;
    if (clamped) {
      // No node inside the clamp, nor on a stretch beyond it that barely
      // moves (a stub of handle behind the vice: its zeros are round-off).
      double largest = 0.0, before = 0.0, after = 0.0;
      for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i) {
        const double w = std::abs(q(static_cast<int>(2 * i)));
        largest = std::max(largest, w);
        if (mesh.nodes_m[i] < from - tol) before = std::max(before, w);
        if (mesh.nodes_m[i] > to + tol) after = std::max(after, w);
      }
      const double still = kStillShare * largest;
      std::erase_if(mode.nodes_from_butt_m, [&](double x) {
        return (x >= from - tol && x <= to + tol) || (x < from && before < still) ||
               (x > to && after < still);
      });
    }
    result.modes.push_back(std::move(mode));
  }
  result.complete = static_cast<int>(result.modes.size()) == options.modes;
  fill_shape_table(result, length, options.shape_samples);
  return result;
}

}  // namespace sweetspot
