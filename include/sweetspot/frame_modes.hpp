#pragma once

// The flexible frame of a design: its mass distribution (given, or fitted to
// industry specs), its bending stiffness, and the fundamental vibration mode
// free and held in the hand. Built on beam_modes.hpp.

#include <optional>
#include <vector>

#include "sweetspot/beam_modes.hpp"
#include "sweetspot/design.hpp"

namespace sweetspot {

// Sections used to represent a mass distribution fitted to industry specs.
inline constexpr int kFittedSections = 24;

// Equal-length uniform sections whose masses follow the smoothest density
// that can match three moments, a quadratic mu(x) = a + b s + c s^2 (s = x/L),
// with a, b, c solved so that the sections reproduce the mass, the balance
// point and the moment of inertia of `frame` exactly. Throws
// std::invalid_argument when that quadratic is negative somewhere (specs no
// smooth distribution can give).
std::vector<Section> fitted_sections(double length_m, const MassProperties& frame,
                                     int count = kFittedSections);

// True when the design says how stiff its frame is (so the modes can be computed).
bool has_stiffness(const Design& design);

// The design's frame ready for beam_modes: sections with EI and the point
// masses. Throws std::invalid_argument naming "frame/EI_N_m2" when the
// stiffness is not known for every section.
struct FlexibleFrame {
  std::vector<Section> sections;
  std::vector<PointMass> point_masses;
  bool mass_distribution_fitted = false;  // from industry specs
  ModeOptions options;                    // theory and Timoshenko data
};
// The largest shear parameter 12 EI / (kappa G A L^2) of a frame given a
// cross-section (a real racquet's is about 0.01-0.1): a frame past it is
// refused at frame/cross_section.
inline constexpr double kMaxShearParameter = 1e6;
FlexibleFrame flexible_frame(const Design& design);

// The hand of `design` as a grip coupling for hand_held_modes. Throws
// std::invalid_argument naming "hand/grip_length_m" when the grip leaves the implement.
HandCoupling hand_coupling(const Design& design);

// The beam's support for supported_modes() of a design on a rig that lets
// the frame vibrate: handle clamped, a clamp over the hand's grip (centre
// hand.center_from_butt_m, length hand.grip_length_m); a pivot, pinned there.
// std::nullopt for every other support (free, hand, and the head clamped or
// a rigid surface, where nothing vibrates).
std::optional<BeamSupport> beam_support(const Design& design);

// What the modes add to an evaluation.
struct ModalOutputs {
  double fundamental_free_Hz = 0.0;
  std::optional<double> node_free_from_butt_m;  // node of the fundamental nearest the tip
  double fundamental_hand_Hz = 0.0;             // damped
  double hand_damping_ratio = 0.0;
  std::optional<double> node_hand_from_butt_m;  // nearest the tip
  bool mass_distribution_fitted = false;
  int hand_elements = 0;
};

// Fundamental modes of the design free (exact transfer matrices; finite
// elements for Timoshenko) and hand-held (finite elements to `rel_tol` on the
// frequency). With no hand mass, the hand-held values are the free ones.
ModalOutputs evaluate_modes(const Design& design, double rel_tol = 1e-6);

// The beam-mode fundamental of a hand-held result: the first mode in which the
// hand carries less than half the kinetic energy (the lower ones are the hand
// rocking on the grip). nullptr when there is none.
const Mode* hand_held_fundamental(const ModalResult& result);

}  // namespace sweetspot
