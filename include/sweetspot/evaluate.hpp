#pragma once

// Every quantity of the rigid-body model of Cross (2004) for one design.

#include <optional>

#include "sweetspot/design.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot {

struct Evaluation {
  // The implement (with its point masses), Section III.
  double length_m = 0.0;
  double mass_kg = 0.0;
  double balance_from_butt_m = 0.0;
  double I_cm_kg_m2 = 0.0;            // recoil weight, in SI
  double swingweight_kg_m2 = 0.0;     // about the axis 10 cm from the butt
  double impact_from_butt_m = 0.0;
  double impact_from_com_m = 0.0;     // b of Eq. (17)
  // COP of the free implement for an axis through the butt (Eq. 5).
  std::optional<double> cop_free_from_butt_m;
  // Rotation axis of the free implement for this impact (Eq. 5).
  std::optional<double> rotation_axis_free_from_butt_m;

  // The ball on the strings, Section VI.
  double effective_mass_kg = 0.0;     // Eq. (17)
  double apparent_cor = 0.0;          // Eq. (16)
  double rebound_speed_m_s = 0.0;     // e_A v1, away from the implement when > 0
  double impulse_N_s = 0.0;           // m v1 (1 + e_A)
  double peak_impact_force_N = 0.0;   // Eq. (15)

  // Implement and hand, Section V.
  double system_mass_kg = 0.0;
  double system_com_from_butt_m = 0.0;   // h
  double system_I_cm_kg_m2 = 0.0;
  std::optional<double> cop_hand_from_butt_m;             // Eq. (13)
  std::optional<double> rotation_axis_hand_from_butt_m;   // s = h - A, Eq. (12)
  double wrist_force_ratio = 0.0;     // F_w / F, Eq. (11)
  double peak_wrist_force_N = 0.0;    // |F_w / F| F0

  // The flexible frame, when evaluated with Fidelity::kModal.
  std::optional<ModalOutputs> modal;
};

// How much model an evaluation uses: the rigid body of the paper alone, or
// also the vibration modes of the flexible frame (which need its stiffness).
enum class Fidelity { kRigid, kModal };

// Evaluates every quantity for a valid design (validate() first: evaluate()
// calls it and throws std::invalid_argument the same way).
Evaluation evaluate(const Design& design);

// The same with the modes too when `fidelity` is kModal, the hand-held ones
// to `rel_tol` (the frequency's relative error).
Evaluation evaluate(const Design& design, Fidelity fidelity, double rel_tol = 1e-6);

// The same without validation, for callers that validated once and evaluate
// many impacts or variants in a loop. No allocation.
Evaluation evaluate_unchecked(const Design& design);

}  // namespace sweetspot
