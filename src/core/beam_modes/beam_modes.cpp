// The public entry points of beam_modes.hpp. The solvers live beside this
// file: segmentation (validation, segments), shapes (Krylov pieces, nodes),
// transfer_matrix (exact), fe_mesh (elements, mesh, assembly), free_fe,
// banded_pencil and hand_held (damped modes).
#include "sweetspot/beam_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/beam_modes/fe_mesh.hpp"
#include "core/beam_modes/free_fe.hpp"
#include "core/beam_modes/hand_held.hpp"
#include "core/beam_modes/segmentation.hpp"
#include "core/beam_modes/shapes.hpp"
#include "core/beam_modes/transfer_matrix.hpp"
#include "core/check.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/invariants.hpp"

namespace sweetspot {
namespace {
// scale_EI_to_fundamental's Timoshenko iteration: f1 within this of the
// target after its last step, else refused.
constexpr double kScaleEISettled = 1e-9;
}  // namespace

using namespace beam_detail;
using detail::format_number;

TimoshenkoSection rectangular_timoshenko_section(double shear_modulus_Pa, double width_m,
                                                 double thickness_m) {
  return timoshenko_section(shear_modulus_Pa,
                            CrossSection{.width_m = width_m, .thickness_m = thickness_m});
}

namespace {

using Shape = CrossSection::Shape;

// The tube's radius ratio m = r_inner / r_outer in [0, 1), 0 for a solid circle.
double radius_ratio(const CrossSection& section) {
  if (section.shape == Shape::kCircle) return 0.0;
  const double outer = 0.5 * section.diameter_m;
  return (outer - section.wall_m) / outer;
}

void check_section(const CrossSection& section) {
  if (section.shape == Shape::kProfile) {
    throw std::invalid_argument(
        "shape: a profile's sections are each the circle or tube of its own slice, not one "
        "section with sizes");
  }
  if (!(section.poisson_ratio >= 0.0 && section.poisson_ratio <= 0.5)) {
    throw std::invalid_argument("poisson_ratio: must be in [0, 0.5], got " +
                                format_number(section.poisson_ratio));
  }
  if (sized_by_width(section.shape)) {
    detail::require_positive("width_m", section.width_m, "m");
    detail::require_positive("thickness_m", section.thickness_m, "m");
    const double half = 0.5 * std::min(section.width_m, section.thickness_m);
    if (section.shape == Shape::kBox && !(section.wall_m > 0.0 && section.wall_m < half)) {
      throw std::invalid_argument(
          "wall_m: must be in (0, min(width, thickness) / 2 = " + format_number(half) +
          ") m (a wall that fills the box is the rectangle: give shape rectangle), got " +
          format_number(section.wall_m) + " m");
    }
    return;
  }
  detail::require_positive("diameter_m", section.diameter_m, "m");
  if (section.shape == Shape::kHollowCircle &&
      !(section.wall_m > 0.0 && section.wall_m <= 0.5 * section.diameter_m)) {
    throw std::invalid_argument(
        "wall_m: must be in (0, diameter / 2 = " + format_number(0.5 * section.diameter_m) +
        "] m, got " + format_number(section.wall_m));
  }
}

}  // namespace

double shear_coefficient(const CrossSection& section) {
  check_section(section);
  const double nu = section.poisson_ratio;
  switch (section.shape) {
    case Shape::kRectangle:
      return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
    case Shape::kEllipse: {
      const double m2 =
          (section.thickness_m / section.width_m) * (section.thickness_m / section.width_m);
      // Divided through by m^4 where m > 1, so that a blade on edge neither
      // overflows nor loses its leading terms.
      if (m2 > 1.0) {
        const double u = 1.0 / m2;
        return 12.0 * (1.0 + nu) * (3.0 + u) /
               ((40.0 + 37.0 * nu) + (16.0 + 10.0 * nu) * u + nu * u * u);
      }
      // Divided through by m^2 where m <= 1; nu / m^2 is left out at nu = 0,
      // where a flat ellipse's m^2 may underflow.
      return 12.0 * (1.0 + nu) * (3.0 * m2 + 1.0) /
             ((40.0 + 37.0 * nu) * m2 + (16.0 + 10.0 * nu) + (nu > 0.0 ? nu / m2 : 0.0));
    }
    case Shape::kBox: {
      const double b = section.width_m - section.wall_m;
      const double h = section.thickness_m - section.wall_m;
      // Cowper's m and n are both b / h with one wall. Where m > 1 numerator
      // and denominator are divided by m^4 (u = 1 / m), so that a flat box
      // neither overflows nor loses its leading terms.
      if (b > h) {
        const double u = h / b;
        return 10.0 * (1.0 + nu) * (u + 3.0) * (u + 3.0) * u * u /
               (u * (90.0 + u * (150.0 + u * (72.0 + 12.0 * u))) +
                nu * u * (90.0 + u * (135.0 + u * (66.0 + 11.0 * u))) +
                10.0 * ((3.0 + nu) * u + 3.0));
      }
      const double m = b / h;
      return 10.0 * (1.0 + nu) * (1.0 + 3.0 * m) * (1.0 + 3.0 * m) /
             ((12.0 + m * (72.0 + m * (150.0 + 90.0 * m))) +
              nu * (11.0 + m * (66.0 + m * (135.0 + 90.0 * m))) +
              10.0 * m * m * ((3.0 + nu) * m + 3.0 * m * m));
    }
    case Shape::kCircle:
    case Shape::kHollowCircle:
    case Shape::kProfile:  // refused by check_section()
      break;
  }
  const double m = radius_ratio(section);
  const double c = (1.0 + m * m) * (1.0 + m * m);
  return 6.0 * (1.0 + nu) * c / ((7.0 + 6.0 * nu) * c + (20.0 + 12.0 * nu) * m * m);
}

CrossSection round_cross_section(const RoundSlice& slice, double poisson_ratio) {
  if (slice.wall_m == 0.0) {
    return {
        .shape = Shape::kCircle, .diameter_m = slice.diameter_m, .poisson_ratio = poisson_ratio};
  }
  return {.shape = Shape::kHollowCircle,
          .diameter_m = slice.diameter_m,
          .wall_m = slice.wall_m,
          .poisson_ratio = poisson_ratio};
}

TimoshenkoSection timoshenko_section(double shear_modulus_Pa, const CrossSection& section) {
  detail::require_positive("shear_modulus_Pa", shear_modulus_Pa, "Pa");
  const double kappa = shear_coefficient(section);
  const double w = section.width_m;
  const double t = section.thickness_m;
  switch (section.shape) {
    case Shape::kRectangle:
      return {kappa * shear_modulus_Pa * w * t, t / std::sqrt(12.0)};
    case Shape::kEllipse:
      return {kappa * shear_modulus_Pa * 0.25 * std::numbers::pi * w * t, 0.25 * t};
    case Shape::kBox: {
      // The outer rectangle less its bore: I / A = (w t^3 - wi ti^3) / (12 (w t - wi ti)).
      const double wi = w - 2.0 * section.wall_m;
      const double ti = t - 2.0 * section.wall_m;
      const double area = w * t - wi * ti;
      const double second_moment = (w * t * t * t - wi * ti * ti * ti) / 12.0;
      return {kappa * shear_modulus_Pa * area, std::sqrt(second_moment / area)};
    }
    case Shape::kCircle:
    case Shape::kHollowCircle:
    case Shape::kProfile:  // refused by check_section()
      break;
  }
  const double outer = 0.5 * section.diameter_m;
  const double inner = radius_ratio(section) * outer;
  const double area = std::numbers::pi * (outer - inner) * (outer + inner);
  return {kappa * shear_modulus_Pa * area, 0.5 * std::sqrt(outer * outer + inner * inner)};
}

std::string ModeOptions::validate() const {
  auto bad = [](const std::string& name, const std::string& expected, double value) {
    return name + ": must be " + expected + ", got " + format_number(value);
  };
  const int max_modes = method == Method::kExact ? kMaxExactModes : kMaxModes;
  if (modes < 1 || modes > max_modes) {
    return bad("modes", "in [1, " + std::to_string(max_modes) + "]", modes);
  }
  if (!(rel_tol >= kMinRelTol && rel_tol <= kMaxRelTol)) {
    return bad("rel_tol",
               "in [" + format_number(kMinRelTol) + ", " + format_number(kMaxRelTol) + "]",
               rel_tol);
  }
  if (elements < 0 || elements > kMaxElements) {
    return bad("elements", "in [0, " + std::to_string(kMaxElements) + "]", elements);
  }
  if (shape_samples < 0 || shape_samples == 1) {
    return bad("shape_samples", "0 or >= 2", shape_samples);
  }
  if (theory == Theory::kTimoshenko) {
    if (method != Method::kFiniteElement) {
      return "theory: Timoshenko needs method kFiniteElement, got kExact";
    }
    for (std::size_t i = 0; i < timoshenko.size(); ++i) {
      const TimoshenkoSection& t = timoshenko[i];
      if (!(t.shear_stiffness_N > 0.0 && std::isfinite(t.shear_stiffness_N))) {
        return bad(detail::indexed("timoshenko", i, "shear_stiffness_N"), "> 0 N",
                   t.shear_stiffness_N);
      }
      if (!(t.radius_of_gyration_m >= 0.0 && std::isfinite(t.radius_of_gyration_m))) {
        return bad(detail::indexed("timoshenko", i, "radius_of_gyration_m"), ">= 0 m",
                   t.radius_of_gyration_m);
      }
    }
  }
  return {};
}

double mode_shape_at(const Mode& mode, double x_m) {
  if (mode.shape.empty()) throw FieldError("mode", "has no shape");
  const double length = mode.shape.back().end_m;
  const double eps = 1e-12 * length;
  if (!(x_m >= -eps && x_m <= length + eps))
    fail("x_m", "in [0, " + format_number(length) + "] m", x_m);
  auto it = std::upper_bound(mode.shape.begin(), mode.shape.end(), x_m,
                             [](double x, const ShapePiece& p) { return x < p.end_m; });
  if (it == mode.shape.end()) --it;
  return evaluate_piece(*it, std::clamp(x_m - it->start_m, 0.0, it->end_m - it->start_m));
}

ModalResult free_modes(const std::vector<Section>& sections,
                       const std::vector<PointMass>& point_masses, const ModeOptions& options) {
  const bool fe = options.method == ModeOptions::Method::kFiniteElement;
  const double length = validated_length(sections, fe);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  const Segmentation seg = segment(sections, point_masses, {}, timoshenko_of(options));
  ModalResult result = fe ? fe_free_modes(seg, options) : exact_free_modes(seg, options);
  fill_shape_table(result, length, options.shape_samples);
  return result;
}

BeamMatrices assemble_beam_matrices(const std::vector<Section>& sections,
                                    const std::vector<PointMass>& point_masses,
                                    const ModeOptions& options,
                                    const std::optional<HandCoupling>& hand) {
  const double length = validated_length(sections, true);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  if (hand) validate_hand(*hand, length);
  const Segmentation seg = hand ? hand_segmentation(sections, point_masses, *hand, options)
                                : segment(sections, point_masses, {}, timoshenko_of(options));
  const Mesh mesh = build_mesh(seg, element_counts(seg, options), options);
  const Assembled a = assemble(mesh, hand ? &*hand : nullptr);
  BeamMatrices out;
  out.node_positions_m = mesh.nodes_m;
  out.size = static_cast<int>(a.K.rows());
  auto row_major = [](const MatrixXd& m) {
    std::vector<double> v(m.size());
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        v.data(), m.rows(), m.cols()) = m;
    return v;
  };
  out.stiffness = row_major(a.K);
  out.mass = row_major(a.M);
  out.damping = row_major(a.C);
  return out;
}

namespace {

// hand_held_modes(), or with `beam_fundamental_only` the first beam mode alone.
ModalResult solve_hand_held(const std::vector<Section>& sections,
                            const std::vector<PointMass>& point_masses, const HandCoupling& hand,
                            const ModeOptions& options, bool beam_fundamental_only,
                            std::optional<double> free_omega1 = std::nullopt) {
  const double length = validated_length(sections, true);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  if (options.method != ModeOptions::Method::kFiniteElement) {
    throw FieldError("options.method", "the hand-held beam needs kFiniteElement, got kExact");
  }
  validate_hand(hand, length);

  ModalResult result;
  result.method = ModeOptions::Method::kFiniteElement;
  result.theory = options.theory;
  const Segmentation seg = hand_segmentation(sections, point_masses, hand, options);
  const std::vector<int> counts = element_counts(seg, options, free_omega1);
  const Mesh mesh = build_mesh(seg, counts, options);
  result.elements_used = static_cast<int>(mesh.elements.size());  // after merge_tiny_elements
  const Assembled a = assemble(mesh, &hand);

  std::optional<DampedSpectrum> spectrum;
  std::string how;
  if (options.damped_solver == ModeOptions::DampedSolver::kRefined) {
    const Mesh coarse = coarse_mesh(seg, options, true);
    std::string why = "mesh no finer than the coarse one";
    if (coarse.elements.size() < mesh.elements.size()) {
      spectrum =
          refined_damped_spectrum(mesh, a, hand, options, coarse, &why, beam_fundamental_only);
    }
    how = spectrum ? "quadratic eigenproblem refined from a " +
                         std::to_string(coarse.elements.size()) + "-element state-space solve"
                   : "dense state-space eigenproblem (refinement skipped: " + why + ")";
  } else {
    how = "dense state-space eigenproblem";
  }
  if (!spectrum) spectrum = dense_damped_spectrum(mesh, a, hand, options.modes);
  for (const DampedPair& pair : spectrum->pairs) {
    result.modes.push_back(damped_mode(mesh, a, pair.s, pair.q));
  }
  result.complete = static_cast<int>(result.modes.size()) == options.modes;
  if (beam_fundamental_only) {
    // The refinement may have shaped every mode (a coarse share near the
    // line, or the dense solve): keep the first beam mode.
    const auto beam = std::find_if(result.modes.begin(), result.modes.end(), [](const Mode& m) {
      return m.hand_energy_fraction < kHandModeEnergyShare;
    });
    if (beam == result.modes.end()) {
      // The coarse mesh called a mode the beam's that the fine one gives
      // to the hand: ask the full solve, which shapes every mode.
      ModalResult full = solve_hand_held(sections, point_masses, hand, options, false, free_omega1);
      const auto found = std::find_if(full.modes.begin(), full.modes.end(), [](const Mode& m) {
        return m.hand_energy_fraction < kHandModeEnergyShare;
      });
      std::vector<Mode> kept;
      if (found != full.modes.end()) kept.push_back(std::move(*found));
      full.complete = !kept.empty();
      full.modes = std::move(kept);
      full.shape_w.clear();
      fill_shape_table(full, length, options.shape_samples);
      return full;
    }
    std::vector<Mode> kept;
    kept.push_back(std::move(*beam));
    result.complete = true;
    result.modes = std::move(kept);
  }
  result.message = "finite elements: " + std::to_string(result.elements_used) + " elements, " +
                   how + "; " + std::to_string(spectrum->overdamped) +
                   " overdamped (real) roots not reported";
  fill_shape_table(result, length, options.shape_samples);
  return result;
}

}  // namespace

ModalResult hand_held_modes(const std::vector<Section>& sections,
                            const std::vector<PointMass>& point_masses, const HandCoupling& hand,
                            const ModeOptions& options) {
  return solve_hand_held(sections, point_masses, hand, options, false);
}

ModalResult hand_held_beam_fundamental(const std::vector<Section>& sections,
                                       const std::vector<PointMass>& point_masses,
                                       const HandCoupling& hand, const ModeOptions& options) {
  return solve_hand_held(sections, point_masses, hand, options, true);
}

ModalResult beam_detail::hand_held_beam_fundamental(const std::vector<Section>& sections,
                                                    const std::vector<PointMass>& point_masses,
                                                    const HandCoupling& hand,
                                                    const ModeOptions& options,
                                                    double free_omega1_rad_s) {
  return solve_hand_held(sections, point_masses, hand, options, true, free_omega1_rad_s);
}

HandCoupling calibrated_hand() {
  HandCoupling hand;
  hand.stiffness_N_m2 = kCalibratedGripStiffness_N_m2;
  hand.damping_N_s_m2 = kCalibratedGripDamping_N_s_m2;
  return hand;
}

std::vector<Section> scale_EI_to_fundamental(const std::vector<Section>& sections,
                                             const std::vector<PointMass>& point_masses,
                                             double f1_Hz, const ModeOptions& options) {
  detail::require_positive("f1_Hz", f1_Hz, "Hz");
  ModeOptions one = options;
  one.modes = 1;
  one.shape_samples = 0;
  std::vector<Section> scaled = sections;
  // Euler-Bernoulli: f ~ sqrt(EI) exactly, one step. Timoshenko: the shear
  // stiffness does not scale, so repeat the step until f1 matches.
  const int steps = options.theory == ModeOptions::Theory::kTimoshenko ? 30 : 1;
  for (int i = 0; i < steps; ++i) {
    const ModalResult r = free_modes(scaled, point_masses, one);
    if (r.modes.empty()) throw FieldError("sections", "no flexible mode found");
    const double ratio = f1_Hz / r.modes[0].frequency_Hz;
    for (Section& s : scaled) s.EI_N_m2 = *s.EI_N_m2 * ratio * ratio;
    if (std::abs(ratio - 1.0) < 1e-13) break;
    // Timoshenko: f1 is bounded by the shear stiffness as EI grows; a target
    // above that bound is never reached, however far EI is scaled.
    if (steps > 1 && i + 1 == steps && !(std::abs(ratio - 1.0) < kScaleEISettled)) {
      throw ModelRefusal("f1_Hz", f1_Hz,
                         "the frame's shear stiffness does not let its fundamental reach it "
                         "(scaling EI left it a factor " +
                             detail::format_significant(ratio) + " short)");
    }
  }
  return scaled;
}

double uniform_EI_for_fundamental(const std::vector<Section>& sections,
                                  const std::vector<PointMass>& point_masses, double f1_Hz) {
  detail::require_positive("f1_Hz", f1_Hz, "Hz");
  std::vector<Section> unit = sections;
  for (Section& s : unit) s.EI_N_m2 = 1.0;
  ModeOptions one;
  one.modes = 1;
  const ModalResult r = free_modes(unit, point_masses, one);
  if (r.modes.empty()) throw FieldError("sections", "no flexible mode found");
  const double ratio = f1_Hz / r.modes[0].frequency_Hz;
  return ratio * ratio;
}

}  // namespace sweetspot
