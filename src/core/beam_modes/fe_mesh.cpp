#include "core/beam_modes/fe_mesh.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/beam_modes/free_fe.hpp"
#include "core/beam_modes/shapes.hpp"
#include "core/check.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/invariants.hpp"

namespace sweetspot::beam_detail {
namespace {

// An element far shorter than the mesh's sizing asks for (a sliver of a
// section, a point mass a hair from a section boundary) makes K
// ill-conditioned by (h_neighbour / h)^3: at 1e-6 m beside 1 cm elements the
// frequencies came out wrong by a factor of 2. Elements are sized to equal
// phase (mu/EI)^(1/4) h, so one whose phase is below kMergeRatio of its
// neighbour's is merged into a neighbour, which then integrates both uniform
// pieces exactly and carries the node's point mass where it is
// (Element::pieces, masses). Round-off then stays below about
// 1e4 eps / kMergeRatio^3 ~ 2e-9.
constexpr double kMergeRatio = 0.1;
// One cubic cannot bend differently on either side of a stiffness jump: a
// merged element spanning EI_min..EI_max misstates the frame's compliance by
// about (EI_max / EI_min - 1) h_short / L. Merges that would exceed this are
// refused (the exact solver, free modes only, has no such limit).
constexpr double kMergeTolerance = 1e-9;

double phase(const Element& e) {
  double sum = 0.0;
  for (const ElementPiece& p : e.pieces) sum += phase_weight(p.mu, p.EI, p.e - p.s);
  return sum;
}

double merge_error(const Element& a, const Element& b, double length_m) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const Element* e : {&a, &b}) {
    for (const ElementPiece& p : e->pieces) {
      lo = std::min(lo, p.EI);
      hi = std::max(hi, p.EI);
    }
  }
  return (hi / lo - 1.0) * std::min(a.h, b.h) / length_m;
}

void merge_tiny_elements(Mesh& mesh, const std::vector<double>& keep_nodes) {
  std::vector<double> phases;  // of each element, kept in step with the merges
  for (const Element& e : mesh.elements) phases.push_back(phase(e));
  // A node on a support stays a node: an element whose merges would remove
  // one is left as it is (`stays`).
  const double on_node = 1e-12 * mesh.length_m;
  const auto kept = [&](double x) {
    return std::any_of(keep_nodes.begin(), keep_nodes.end(),
                       [&](double k) { return std::abs(x - k) <= on_node; });
  };
  std::vector<bool> stays(mesh.elements.size(), false);
  while (mesh.elements.size() > 1) {
    std::size_t tiny = 0;
    double worst = kMergeRatio;
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      if (stays[e]) continue;
      double neighbour = 0.0;
      if (e > 0) neighbour = std::max(neighbour, phases[e - 1]);
      if (e + 1 < mesh.elements.size()) neighbour = std::max(neighbour, phases[e + 1]);
      const double ratio = phases[e] / neighbour;
      if (ratio < worst) {
        worst = ratio;
        tiny = e;
      }
    }
    if (!(worst < kMergeRatio)) return;
    // Into the neighbour that misstates the stiffness least, else the longer in phase.
    const std::size_t last = mesh.elements.size() - 1;
    // Into the left removes the tiny element's first node, into the right its last.
    const bool blocked_left = tiny > 0 && kept(mesh.nodes_m[tiny]);
    const bool blocked_right = tiny < last && kept(mesh.nodes_m[tiny + 1]);
    const double error_left =
        tiny > 0 && !blocked_left
            ? merge_error(mesh.elements[tiny - 1], mesh.elements[tiny], mesh.length_m)
            : std::numeric_limits<double>::infinity();
    const double error_right =
        tiny < last && !blocked_right
            ? merge_error(mesh.elements[tiny], mesh.elements[tiny + 1], mesh.length_m)
            : std::numeric_limits<double>::infinity();
    if (std::min(error_left, error_right) > kMergeTolerance && (blocked_left || blocked_right)) {
      stays[tiny] = true;  // a short element beside the support, resolved as it is
      continue;
    }
    if (std::min(error_left, error_right) > kMergeTolerance) {
      const ElementPiece& p = mesh.elements[tiny].pieces.front();
      throw FieldError(
          detail::indexed("sections", p.section, "length_m"),
          "a stretch of " + detail::format_number(mesh.elements[tiny].h) + " m at " +
              detail::format_number(mesh.elements[tiny].x0) + " m from the butt, with EI " +
              detail::format_number(p.EI) +
              " N m^2 unlike its neighbours', is too short for finite elements to resolve (the "
              "hand-held "
              "modes always use them); lengthen it or give it its neighbours' EI");
    }
    const bool into_left = error_left < error_right || (error_left == error_right && tiny > 0 &&
                                                        phases[tiny - 1] >= phases[tiny + 1]);
    const std::size_t left = into_left ? tiny - 1 : tiny;
    const Element& a = mesh.elements[left];
    const Element& b = mesh.elements[left + 1];
    Element merged(a.x0, a.h + b.h, a.EI, a.mu, 0.0, 0.0);
    merged.pieces = a.pieces;
    merged.masses = a.masses;
    for (const ElementPiece& p : b.pieces)
      merged.pieces.push_back({p.s + a.h, p.e + a.h, p.EI, p.mu, p.section});
    merged.pieces.back().e = merged.h;
    if (mesh.nodal_mass_kg[left + 1] > 0.0)
      merged.masses.emplace_back(a.h, mesh.nodal_mass_kg[left + 1]);
    for (const auto& [xi, kg] : b.masses) merged.masses.emplace_back(xi + a.h, kg);
    phases[left] += phases[left + 1];
    phases.erase(phases.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    mesh.elements[left] = std::move(merged);
    mesh.elements.erase(mesh.elements.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    stays.erase(stays.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    mesh.nodes_m.erase(mesh.nodes_m.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    mesh.nodal_mass_kg.erase(mesh.nodal_mass_kg.begin() + static_cast<std::ptrdiff_t>(left) + 1);
  }
}

}  // namespace

Mesh build_mesh(const Segmentation& seg, const std::vector<int>& counts, const ModeOptions& options,
                const std::vector<double>& keep_nodes) {
  Mesh mesh;
  mesh.length_m = seg.length_m;
  mesh.nodes_m.push_back(0.0);
  mesh.nodal_mass_kg.push_back(0.0);
  const bool timoshenko = options.theory == ModeOptions::Theory::kTimoshenko;
  std::size_t group = 0;  // first segment of the open group (counts 0 ... 0 1)
  for (std::size_t i = 0; i < seg.segments.size(); ++i) {
    const Segment& s = seg.segments[i];
    if (counts[i] == 0 || (i > group && counts[i - 1] == 0)) {
      // Part of a group: one element over segments group..i once counts[i] == 1.
      if (i == group) mesh.nodal_mass_kg.back() += s.mass_at_start_kg;
      if (counts[i] == 0) continue;
      const Segment& first = seg.segments[group];
      Element element(first.start_m, s.start_m + s.length_m - first.start_m, first.EI_N_m2,
                      first.mu_kg_m, 0.0, 0.0);
      element.pieces.clear();
      for (std::size_t j = group; j <= i; ++j) {
        const Segment& p = seg.segments[j];
        element.pieces.push_back({p.start_m - first.start_m, p.start_m + p.length_m - first.start_m,
                                  p.EI_N_m2, p.mu_kg_m, p.section});
        if (j > group && p.mass_at_start_kg > 0.0)
          element.masses.emplace_back(p.start_m - first.start_m, p.mass_at_start_kg);
      }
      element.pieces.back().e = element.h;
      mesh.elements.push_back(std::move(element));
      mesh.nodes_m.push_back(s.start_m + s.length_m);
      mesh.nodal_mass_kg.push_back(0.0);
      group = i + 1;
      continue;
    }
    group = i + 1;
    mesh.nodal_mass_kg.back() += s.mass_at_start_kg;
    double g = 0.0, rotary = 0.0;
    if (timoshenko) {
      const TimoshenkoSection& t = options.timoshenko[s.section];
      g = s.EI_N_m2 / t.shear_stiffness_N;
      rotary = s.mu_kg_m * t.radius_of_gyration_m * t.radius_of_gyration_m;
    }
    const double h = s.length_m / counts[i];
    for (int e = 0; e < counts[i]; ++e) {
      mesh.elements.emplace_back(s.start_m + e * h, h, s.EI_N_m2, s.mu_kg_m, rotary, g);
      mesh.elements.back().pieces.front().section = s.section;
      mesh.nodes_m.push_back(e + 1 == counts[i] ? s.start_m + s.length_m : s.start_m + (e + 1) * h);
      mesh.nodal_mass_kg.push_back(0.0);
    }
  }
  mesh.nodal_mass_kg.back() += seg.tip_mass_kg;
  if (!timoshenko) merge_tiny_elements(mesh, keep_nodes);
  return mesh;
}

Assembled assemble(const Mesh& mesh, const HandCoupling* hand) {
  const int beam_dofs = 2 * static_cast<int>(mesh.nodes_m.size());
  const int n = beam_dofs + (hand ? 2 : 0);
  Assembled out;
  out.beam_dofs = beam_dofs;
  out.K = MatrixXd::Zero(n, n);
  out.M = MatrixXd::Zero(n, n);
  out.C = MatrixXd::Zero(n, n);
  double grip_start = 0, grip_end = 0, xc = 0;
  if (hand) {
    grip_start = hand->grip_start_m;
    grip_end = hand->grip_start_m + hand->grip_length_m;
    xc = 0.5 * (grip_start + grip_end);
  }
  const double eps = 1e-12 * mesh.length_m;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& el = mesh.elements[e];
    const int i0 = 2 * static_cast<int>(e);
    out.K.block<4, 4>(i0, i0) += el.stiffness();
    out.M.block<4, 4>(i0, i0) += el.mass();
    // The part of the element under the grip, [s, e] in element coordinates
    // (the whole element or none, unless merge_tiny_elements joined across a grip end).
    const double s = std::max(0.0, grip_start - el.x0), e_end = std::min(el.h, grip_end - el.x0);
    const bool whole = s <= eps && e_end >= el.h - eps;
    if (hand && (whole || e_end - s > eps)) {
      const double lo = whole ? 0.0 : s, hi = whole ? el.h : e_end;
      // 1/2 int k (w - u - phi (x - xc))^2 dx, and the same with c for the dashpots.
      const Matrix4d gram = el.gram(lo, hi);
      const Vector4d l0 = el.load(0, xc, lo, hi), l1 = el.load(1, xc, lo, hi);
      const double r0 = hi - lo;
      const double r1 = r0 * (el.x0 + 0.5 * (lo + hi) - xc);
      const double d0 = el.x0 + lo - xc, d1 = d0 + r0;
      const double r2 = (d1 * d1 * d1 - d0 * d0 * d0) / 3.0;
      const int u = beam_dofs, phi = beam_dofs + 1;
      auto add = [&](MatrixXd& A, double k) {
        A.block<4, 4>(i0, i0) += k * gram;
        A.block<4, 1>(i0, u) -= k * l0;
        A.block<1, 4>(u, i0) -= k * l0.transpose();
        A.block<4, 1>(i0, phi) -= k * l1;
        A.block<1, 4>(phi, i0) -= k * l1.transpose();
        A(u, u) += k * r0;
        A(u, phi) += k * r1;
        A(phi, u) += k * r1;
        A(phi, phi) += k * r2;
      };
      add(out.K, hand->stiffness_N_m2);
      add(out.C, hand->damping_N_s_m2);
    }
  }
  for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i)
    out.M(2 * i, 2 * i) += mesh.nodal_mass_kg[i];
  if (hand) {
    out.M(beam_dofs, beam_dofs) = hand->mass_kg;
    out.M(beam_dofs + 1, beam_dofs + 1) = hand->rotary_inertia_kg_m2.value_or(
        hand->mass_kg * hand->grip_length_m * hand->grip_length_m / 12.0);
  }
  return out;
}

bool hand_detached(const HandCoupling* hand) {
  return hand && hand->stiffness_N_m2 == 0.0 && hand->damping_N_s_m2 == 0.0;
}

int drift_roots(const HandCoupling& hand) {
  return hand.stiffness_N_m2 == 0.0 && hand.damping_N_s_m2 > 0.0 ? 2 : 0;
}

namespace {

// QR of M R, R the rigid-body motions: Q's trailing columns span their
// M-orthogonal complement.
Eigen::HouseholderQR<MatrixXd> rigid_motions_qr(const Mesh& mesh, const Assembled& a,
                                                const HandCoupling* hand) {
  const int n = static_cast<int>(a.M.rows());
  const bool detached = hand_detached(hand);
  MatrixXd R = MatrixXd::Zero(n, detached ? 4 : 2);
  for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i) {
    R(2 * i, 0) = 1.0;
    R(2 * i, 1) = mesh.nodes_m[i];
    R(2 * i + 1, 1) = 1.0;
  }
  if (hand) {
    const int u = detached ? 2 : 0, phi = detached ? 3 : 1;
    R(a.beam_dofs, u) = 1.0;
    if (!detached) R(a.beam_dofs, phi) = hand->grip_start_m + 0.5 * hand->grip_length_m;
    R(a.beam_dofs + 1, phi) = 1.0;
  }
  return Eigen::HouseholderQR<MatrixXd>(a.M * R);
}

}  // namespace

MatrixXd flexible_basis(const Mesh& mesh, const Assembled& a, const HandCoupling* hand) {
  const int n = static_cast<int>(a.M.rows());
  const Eigen::HouseholderQR<MatrixXd> qr = rigid_motions_qr(mesh, a, hand);
  const MatrixXd Q = qr.householderQ() * MatrixXd::Identity(n, n);
  return Q.rightCols(n - qr.matrixQR().cols());
}

FlexibleMatrices flexible_matrices(const Mesh& mesh, const Assembled& a, const HandCoupling* hand) {
  const Eigen::HouseholderQR<MatrixXd> qr = rigid_motions_qr(mesh, a, hand);
  const auto m = static_cast<int>(a.M.rows() - qr.matrixQR().cols());
  const auto reduce = [&](MatrixXd X) -> MatrixXd {
    X.applyOnTheLeft(qr.householderQ().adjoint());
    X.applyOnTheRight(qr.householderQ());
    return X.bottomRightCorner(m, m);
  };
  return {reduce(a.K), reduce(a.M)};
}

std::vector<int> counts_for(const Segmentation& seg, double per_phase_weight, bool share_short) {
  const bool group = seg.groupable && (share_short || seg.segments.size() > kMaxFollowedSegments);
  std::vector<int> counts;
  counts.reserve(seg.segments.size());
  double open = 0.0;                           // elements asked for by the open run, < 1
  std::size_t last_close = std::string::npos;  // the run's last closed element
  // Ends a run: a remainder asking for under half an element joins the run's
  // previous element rather than make a sliver.
  auto close_run = [&] {
    if (!counts.empty() && counts.back() == 0) {
      if (open < 0.5 && last_close != std::string::npos) counts[last_close] = 0;
      counts.back() = 1;
    }
    open = 0.0;
    last_close = std::string::npos;
  };
  for (const Segment& s : seg.segments) {
    const double asked = per_phase_weight * phase_weight(s.mu_kg_m, s.EI_N_m2, s.length_m);
    if (!group || asked >= 1.0 - 1e-9) {
      close_run();
      counts.push_back(std::max(1, static_cast<int>(std::ceil(asked - 1e-9))));
      continue;
    }
    open += asked;
    counts.push_back(open >= 1.0 - 1e-9 ? 1 : 0);
    if (counts.back() == 1) {
      open = 0.0;
      last_close = counts.size() - 1;
    }
  }
  close_run();
  return counts;
}

double total_phase_weight(const Segmentation& seg) {
  double sum = 0.0;
  for (const Segment& s : seg.segments) sum += phase_weight(s.mu_kg_m, s.EI_N_m2, s.length_m);
  return sum;
}

std::vector<int> element_counts(const Segmentation& seg, const ModeOptions& options,
                                std::optional<double> free_omega1) {
  const double weight = total_phase_weight(seg);
  if (options.elements > 0) return counts_for(seg, options.elements / weight);
  const double beta_h = std::pow(kHermiteErrorConstant * kToleranceSafety * options.rel_tol, 0.25);
  std::vector<int> counts;
  // Each segment's count grows with omega1 (below kMaxFollowedSegments
  // segments): equal counts at both ends of the band around the known
  // fundamental are the counts of every estimate inside it.
  const bool followed = !(seg.groupable && seg.segments.size() > kMaxFollowedSegments);
  if (free_omega1 && followed && options.theory == ModeOptions::Theory::kEulerBernoulli) {
    const std::vector<int> low =
        counts_for(seg, std::sqrt(*free_omega1 * (1.0 - kKnownFundamentalBand)) / beta_h);
    if (low == counts_for(seg, std::sqrt(*free_omega1 * (1.0 + kKnownFundamentalBand)) / beta_h))
      counts = low;
  }
  if (counts.empty()) {
    // Coarse estimate: ~2 elements per radian of phase at the first mode.
    ModeOptions coarse = options;
    const std::vector<int> coarse_counts = counts_for(seg, 2.0 * 4.73 / weight);
    const Mesh mesh = build_mesh(seg, coarse_counts, coarse);
    const double omega1 = std::sqrt(std::max(lowest_free_omega2(mesh), 0.0));
    counts = counts_for(seg, std::sqrt(omega1) / beta_h);
  }
  int total = 0;
  for (int c : counts) total += c;
  if (total > kMaxAutoElements) {
    throw ModelRefusal("implement/sections", static_cast<double>(total),
                       "resolving the modes to rel_tol " +
                           detail::format_significant(options.rel_tol) + " needs " +
                           std::to_string(total) + " finite elements, more than the " +
                           std::to_string(kMaxAutoElements) +
                           " the modal model solves (the sections' stiffness and mass differ "
                           "too much)");
  }
  if (total < options.modes + 2) counts = counts_for(seg, (options.modes + 2) / weight);
  return counts;
}

int total_elements(const std::vector<int>& counts) {
  int total = 0;
  for (int c : counts) total += c;
  return total;
}

Mesh coarse_mesh(const Segmentation& seg, const ModeOptions& options, bool share_short) {
  const double per_phase = (options.modes + 0.5) * kPi / (kCoarseBetaH * total_phase_weight(seg));
  std::vector<int> counts = counts_for(seg, per_phase);
  // One element per segment at least: a frame of many short sections (the 24
  // fitted ones) makes that "coarse" mesh several times the sizing, and its
  // dense solve most of the hand-held modes' time.
  if (share_short &&
      total_elements(counts) > kCoarseFollowedShare * per_phase * total_phase_weight(seg)) {
    counts = counts_for(seg, per_phase, true);
  }
  return build_mesh(seg, counts, options);
}

VectorXcd interpolate_dofs(const Mesh& coarse, const VectorXcd& q, const Mesh& fine,
                           int fine_size) {
  VectorXcd out = VectorXcd::Zero(fine_size);
  const int coarse_beam = 2 * static_cast<int>(coarse.nodes_m.size());
  const int fine_beam = 2 * static_cast<int>(fine.nodes_m.size());
  std::size_t e = 0;
  for (std::size_t i = 0; i < fine.nodes_m.size(); ++i) {
    const double x = fine.nodes_m[i];
    while (e + 1 < coarse.elements.size() && x > coarse.elements[e].x0 + coarse.elements[e].h) ++e;
    const Element& el = coarse.elements[e];
    const Eigen::Vector4cd c = el.c_inv.cast<Complex>() * q.segment<4>(2 * e);
    const double xi = std::clamp(x - el.x0, 0.0, el.h);
    out(2 * i) = c(0) + xi * (c(1) + xi * (c(2) + xi * c(3)));
    out(2 * i + 1) = c(1) + xi * (2.0 * c(2) + xi * 3.0 * c(3)) + 6.0 * el.g * c(3);
  }
  out.tail(fine_size - fine_beam) = q.tail(q.size() - coarse_beam);
  return out;
}

}  // namespace sweetspot::beam_detail
