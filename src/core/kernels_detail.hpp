#pragma once

// What evaluate() and the loop paths (kernels.hpp) share. Private to the core.

#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot {

// validate() bounds every input, so this is a backstop: never hand out inf or
// NaN. Whether these numbers of an evaluation are all finite.
bool all_finite(double mass_kg, double I_cm_kg_m2, double swingweight_kg_m2,
                double effective_mass_kg, double apparent_cor, double impulse_N_s,
                double peak_impact_force_N, double system_I_cm_kg_m2, double wrist_force_ratio,
                double peak_wrist_force_N);

// The impact duration: given, or derived from the string tension (which
// depends on M_eff only, Eq. 17, not on the COR). Throws FieldError naming
// strings/tension_N when the derived duration is out of range.
double settled_duration(const Design& design);

// The string bed's outputs of `design` (its tension, stiffness and ring) into
// `e`; nothing without a string bed.
void put_string_bed(const Design& design, Evaluation& e);

}  // namespace sweetspot
