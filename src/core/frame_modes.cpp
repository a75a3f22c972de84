#include "sweetspot/frame_modes.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/beam_modes/hand_held.hpp"
#include "core/check.hpp"
#include "core/frame_solve.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/frame_specs.hpp"
#include "sweetspot/invariants.hpp"

namespace sweetspot {
namespace {

std::optional<double> node_nearest_tip(const Mode& mode) {
  if (mode.nodes_from_butt_m.empty()) return std::nullopt;
  return mode.nodes_from_butt_m.back();
}

}  // namespace

std::vector<Section> fitted_sections(double length_m, const MassProperties& frame, int count) {
  detail::require_positive("length_m", length_m, "m");
  if (count < 3) throw FieldError("count", "must be >= 3, got " + std::to_string(count));
  const double l = length_m / count;
  // Section i's mass is L (a A_i + b B_i + c C_i): the integrals of 1, s, s^2.
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  std::vector<Eigen::Vector3d> basis(count);
  for (int i = 0; i < count; ++i) {
    const double s0 = static_cast<double>(i) / count, s1 = static_cast<double>(i + 1) / count;
    basis[i] = length_m *
               Eigen::Vector3d(s1 - s0, (s1 * s1 - s0 * s0) / 2, (s1 * s1 * s1 - s0 * s0 * s0) / 3);
    const double x = (i + 0.5) * l;
    // Rows: mass, first moment, second moment about the butt of a uniform section.
    moments.row(0) += basis[i].transpose();
    moments.row(1) += x * basis[i].transpose();
    moments.row(2) += (x * x + l * l / 12.0) * basis[i].transpose();
  }
  const double M = frame.mass_kg, B = frame.com_from_butt_m;
  const Eigen::Vector3d target(M, M * B, frame.I_cm_kg_m2 + M * B * B);
  const Eigen::Vector3d abc = moments.colPivHouseholderQr().solve(target);
  std::vector<Section> sections(count);
  for (int i = 0; i < count; ++i) {
    const double mass = basis[i].dot(abc);
    if (!(mass > 0.0)) {
      throw FieldError(
          "implement",
          "no smooth (quadratic) positive mass distribution has this mass, balance and "
          "swingweight; give sections instead");
    }
    sections[i] = Section{l, mass, {}};
  }
  return sections;
}

bool has_stiffness(const Design& design) {
  if (design.stiffness.EI_N_m2 || design.stiffness.fundamental_free_Hz || design.stiffness.RA)
    return true;
  const auto& sections = design.implement.sections();
  return !sections.empty() && std::all_of(sections.begin(), sections.end(),
                                          [](const Section& s) { return s.EI_N_m2.has_value(); });
}

FlexibleFrame flexible_frame(const Design& design) {
  const Implement& implement = design.implement;
  const FrameStiffness& stiffness = design.stiffness;
  FlexibleFrame frame;
  frame.point_masses = implement.point_masses();
  frame.mass_distribution_fitted = !implement.has_mass_distribution();
  frame.sections = implement.has_mass_distribution()
                       ? implement.sections()
                       : fitted_sections(implement.length_m(), implement.frame_mass_properties());
  if (stiffness.shear_modulus_Pa) {
    frame.options.method = ModeOptions::Method::kFiniteElement;
    frame.options.theory = ModeOptions::Theory::kTimoshenko;
    // kappa G A can underflow to 0 (or overflow) for inputs each inside
    // its range: the cross-section is then no beam's, named as the input.
    const auto checked = [](const TimoshenkoSection& t) {
      if (!(t.shear_stiffness_N > 0.0 && std::isfinite(t.shear_stiffness_N))) {
        throw FieldError("frame/cross_section",
                         "the shear stiffness kappa G A must be > 0 and finite, got " +
                             detail::format_number(t.shear_stiffness_N) + " N");
      }
      return t;
    };
    const CrossSection& shape = stiffness.cross_section;
    if (shape.shape == CrossSection::Shape::kProfile) {
      // Each slice its own circle or tube (validate() has checked that the
      // implement was given by its profile).
      const std::vector<RoundSlice>& slices = implement.round_slices();
      if (slices.size() != frame.sections.size()) {
        throw FieldError("frame/cross_section/shape",
                         "profile: the implement must be given by its profile");
      }
      frame.options.timoshenko.clear();
      for (const RoundSlice& slice : slices) {
        frame.options.timoshenko.push_back(checked(timoshenko_section(
            *stiffness.shear_modulus_Pa, round_cross_section(slice, shape.poisson_ratio))));
      }
    } else {
      frame.options.timoshenko.assign(
          frame.sections.size(),
          checked(timoshenko_section(*stiffness.shear_modulus_Pa, stiffness.cross_section)));
    }
  }
  if (stiffness.EI_N_m2) detail::require_positive("frame/EI_N_m2", *stiffness.EI_N_m2, "N m^2");
  for (Section& s : frame.sections) {
    if (!s.EI_N_m2) s.EI_N_m2 = stiffness.EI_N_m2;
    if (!s.EI_N_m2 && (stiffness.fundamental_free_Hz || stiffness.RA))
      s.EI_N_m2 = 1.0;  // scaled below
    if (!s.EI_N_m2) {
      throw FieldError("frame/EI_N_m2",
                       "the modes need the frame's stiffness: give frame RA (a racquet's "
                       "rating), fundamental_free_Hz or EI_N_m2, or EI_N_m2 for every section");
    }
  }
  if (stiffness.fundamental_free_Hz) {
    detail::require_positive("frame/fundamental_free_Hz", *stiffness.fundamental_free_Hz, "Hz");
    try {
      frame.sections = scale_EI_to_fundamental(frame.sections, frame.point_masses,
                                               *stiffness.fundamental_free_Hz, frame.options);
    } catch (const ModelRefusal& r) {
      throw ModelRefusal("frame/fundamental_free_Hz", *stiffness.fundamental_free_Hz,
                         "the frame's EI scaled to reach it: " + r.detail());
    }
    // The EI it takes stays in the range a given EI must be in: EI grows as
    // f^2, so the highest frequency is f sqrt(kMaxEI / the stiffest section's EI).
    double stiffest = 0.0;
    for (const Section& s : frame.sections) stiffest = std::max(stiffest, *s.EI_N_m2);
    const double f = *stiffness.fundamental_free_Hz;
    if (!(stiffest <= kMaxEI_N_m2)) {
      const double highest = f * std::sqrt(kMaxEI_N_m2 / stiffest);
      throw FieldError(
          "frame/fundamental_free_Hz",
          "must be in (0, " + detail::format_significant(highest) +
              "] Hz for the frame's EI to stay at most " + detail::format_number(kMaxEI_N_m2) +
              " N m^2, got " + detail::format_number(f) + " Hz",
          FieldError::Range{0.0, highest, true, f, "for the frame's EI to stay in its range"});
    }
  } else if (stiffness.RA) {
    // RA rates the frame as sold: its fundamental without the design's point
    // masses sets the stiffness, which the point masses then load.
    const double f1 = fundamental_free_Hz_from_RA(
        *stiffness.RA, implement.frame_mass_properties().mass_kg, implement.length_m());
    try {
      frame.sections = scale_EI_to_fundamental(frame.sections, {}, f1, frame.options);
    } catch (const ModelRefusal& r) {
      throw ModelRefusal("frame/RA", *stiffness.RA,
                         "the frame's EI scaled to reach it: " + r.detail());
    }
  }
  if (stiffness.shear_modulus_Pa) {
    // The beam's shear parameter 12 EI / (kappa G A L^2): past
    // kMaxShearParameter bending is no part of the frame's compliance and the
    // elements' matrices leave floating point (NaN modes).
    const double L = implement.length_m();
    for (std::size_t i = 0; i < frame.sections.size(); ++i) {
      const double kGA = frame.options.timoshenko[i].shear_stiffness_N;
      const double shear_parameter = 12.0 * (*frame.sections[i].EI_N_m2 / kGA) / L / L;
      if (!(shear_parameter <= kMaxShearParameter)) {
        throw FieldError("frame/cross_section",
                         "the shear parameter 12 EI/(kappa G A L^2) must be at most " +
                             detail::format_number(kMaxShearParameter) +
                             " (a beam in bending), got " + detail::format_number(shear_parameter));
      }
    }
  }
  return frame;
}

std::optional<BeamSupport> beam_support(const Design& design) {
  switch (design.support.kind) {
    case Support::Kind::kHandleClamped: {
      const double half = 0.5 * design.hand.grip_length_m;
      return BeamSupport{BeamSupport::Kind::kClamped, design.hand.center_from_butt_m - half,
                         design.hand.center_from_butt_m + half};
    }
    case Support::Kind::kPivot:
      return BeamSupport{BeamSupport::Kind::kPinned, design.support.pivot_from_butt_m,
                         design.support.pivot_from_butt_m};
    default:
      return std::nullopt;
  }
}

HandCoupling hand_coupling(const Design& design) {
  const Hand& hand = design.hand;
  detail::require_positive("hand/grip_length_m", hand.grip_length_m, "m");
  const double start = hand.center_from_butt_m - 0.5 * hand.grip_length_m;
  const double end = hand.center_from_butt_m + 0.5 * hand.grip_length_m;
  // The grip's length within what is left past its start, as the modes
  // check it (validate_hand): a tiny grip at the tip can end at the tip
  // while its start plus its length does not.
  const double L = design.implement.length_m();
  if (!(hand.grip_length_m <= L)) {
    throw FieldError("hand/grip_length_m",
                     "must be at most the implement's length " + detail::format_significant(L) +
                         " m, got " + detail::format_significant(hand.grip_length_m) + " m");
  }
  const double half = 0.5 * hand.grip_length_m;
  if (hand.center_from_butt_m < half || hand.center_from_butt_m > L - half) {
    // The rigid model takes the hand as a point anywhere on the implement;
    // the modes grip the handle over the grip, which must lie on it.
    throw FieldError("hand/center_from_butt_m",
                     "must be in [" + detail::format_significant(half) + ", " +
                         detail::format_significant(L - half) +
                         "] m for the modes, half the grip (" +
                         detail::format_significant(hand.grip_length_m) +
                         " m long) from either end, so the hand grips the implement; got " +
                         detail::format_significant(hand.center_from_butt_m) + " m",
                     FieldError::Range{half, L - half, false, hand.center_from_butt_m,
                                       "for the modes, half the grip from either end, so the "
                                       "hand grips the implement"});
  }
  // Its centre within the range, the grip still past an end by round-off
  // (a grip of 1e-300 m at the tip): as the modes check it (validate_hand).
  if (start < 0.0 || end > L || hand.grip_length_m > L - start) {
    throw FieldError("hand/grip_length_m", "the grip " + detail::format_significant(start) +
                                               " to " + detail::format_significant(end) +
                                               " m must lie on the implement");
  }
  detail::require_at_least("hand/grip_stiffness_N_m2", hand.grip_stiffness_N_m2, 0.0, "N/m^2");
  detail::require_at_least("hand/grip_damping_N_s_m2", hand.grip_damping_N_s_m2, 0.0, "N s/m^2");
  HandCoupling coupling;
  coupling.mass_kg = hand.mass_kg;
  coupling.grip_start_m = start;
  coupling.grip_length_m = hand.grip_length_m;
  coupling.stiffness_N_m2 = hand.grip_stiffness_N_m2;
  coupling.damping_N_s_m2 = hand.grip_damping_N_s_m2;
  return coupling;
}

const Mode* hand_held_fundamental(const ModalResult& result) {
  for (const Mode& mode : result.modes) {
    if (mode.hand_energy_fraction < kHandModeEnergyShare) return &mode;
  }
  return nullptr;
}

ModalOutputs evaluate_modes(const Design& design, double rel_tol) {
  return detail::evaluate_modes_on(design, flexible_frame(design), rel_tol);
}

ModalOutputs detail::evaluate_modes_on(const Design& design, const FlexibleFrame& frame,
                                       double rel_tol, const Mode* free_fundamental) {
  ModalOutputs out;
  out.mass_distribution_fitted = frame.mass_distribution_fitted;

  if (free_fundamental) {
    out.fundamental_free_Hz = free_fundamental->frequency_Hz;
    out.node_free_from_butt_m = node_nearest_tip(*free_fundamental);
  } else {
    ModeOptions free_options = frame.options;
    free_options.modes = 1;
    const ModalResult free = free_modes(frame.sections, frame.point_masses, free_options);
    if (free.modes.empty())
      throw FieldError("frame", "no flexible mode found (" + free.message + ")");
    out.fundamental_free_Hz = free.modes[0].frequency_Hz;
    out.node_free_from_butt_m = node_nearest_tip(free.modes[0]);
  }

  if (design.hand.mass_kg == 0.0) {
    out.fundamental_hand_Hz = out.fundamental_free_Hz;
    out.node_hand_from_butt_m = out.node_free_from_butt_m;
    return out;
  }
  ModeOptions hand_options = frame.options;
  hand_options.method = ModeOptions::Method::kFiniteElement;
  hand_options.rel_tol = rel_tol;
  hand_options.modes = 3;  // the hand's rocking modes come first
  // The free fundamental sizes the mesh (the same mesh as a coarse estimate's).
  const ModalResult held = beam_detail::hand_held_beam_fundamental(
      frame.sections, frame.point_masses, hand_coupling(design), hand_options,
      2.0 * std::numbers::pi * out.fundamental_free_Hz);
  const Mode* fundamental = hand_held_fundamental(held);
  if (!fundamental) throw FieldError("hand", "no beam mode found among the hand-held modes");
  out.fundamental_hand_Hz = fundamental->frequency_Hz;
  out.hand_damping_ratio = fundamental->damping_ratio;
  out.node_hand_from_butt_m = node_nearest_tip(*fundamental);
  out.hand_elements = held.elements_used;
  return out;
}

}  // namespace sweetspot
