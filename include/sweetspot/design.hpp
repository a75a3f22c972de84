#pragma once

// A design: an implement, the player holding it and the ball that hits it.
// Defaults are the conditions of Cross (2004) Table I, top row.

#include "sweetspot/implement.hpp"

namespace sweetspot {

// The hand, a point mass on the handle (Cross 2004: 0.07 m from the butt).
struct Hand {
  double mass_kg = 0.5;              // [kg], >= 0 (0: a free implement)
  double center_from_butt_m = 0.07;  // [m], in [0, L]
};

struct Ball {
  double mass_kg = 0.057;    // [kg], > 0 (a tennis ball)
  double speed_m_s = 50.0;   // incident speed relative to the impact point [m/s], > 0
};

struct Design {
  Implement implement;
  double cor = 0.8;                          // frame COR e at the impact point, in [0, 1]
  double impact_duration_s = 0.004;          // T [s], > 0
  Hand hand{};
  double forearm_equivalent_mass_kg = 0.5;   // M_e = M_F / 3 at the wrist [kg], >= 0
  Ball ball{};
  double impact_from_butt_m = 0.65;          // [m], in [0, L]
};

// Throws std::invalid_argument if any value is out of range. The message
// starts with the value's JSON pointer relative to a design file
// ("hand/mass_kg: must be >= 0 kg, got -0.5 kg").
void validate(const Design& design);

// The implement plus the hand rigidly attached: M, h and I_cm of Cross (2004) Eqs. (8)-(14).
MassProperties hand_held_system(const Design& design);

}  // namespace sweetspot
