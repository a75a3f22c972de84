#pragma once

// The arithmetic of the rigid model's equations on plain numbers, unchecked
// and without branches: each side of a special case is computed and one is
// selected, so that a loop over many designs is if-converted and vectorised.
// The public functions of mass_properties.hpp and rigid_impact.hpp check
// their arguments and call these; this is the only place each formula is written.

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::kernel {

// Implement plus a point mass m at x_m (Cross 2004 Eq. 14 and the parallel-axis
// theorem); the body itself when m = 0.
struct System {
  double mass_kg, com_from_butt_m, I_cm_kg_m2;
};
inline System with_point_mass(double M, double c, double I, double x_m, double m) {
  const double total = M + m;
  const double shift = m * (c - x_m) / total;  // Eq. (14)
  const double com = c - shift;
  const double body_arm = c - com;
  const double point_arm = x_m - com;
  const double inertia = I + M * body_arm * body_arm + m * point_arm * point_arm;
  const bool none = m == 0.0;
  return System{none ? M : total, none ? c : com, none ? I : inertia};
}

// A uniform section of mass m and length l starting x0 from the butt: its
// first moment about the butt, and its inertia about a point `arm` from its
// middle. section_mass_properties() sums these over the sections in order.
inline double section_first_moment(double m, double x0, double l) { return m * (x0 + 0.5 * l); }
inline double section_inertia(double m, double l, double arm) {
  return m * (l * l / 12.0 + arm * arm);
}

// The paper racquet's handle and head masses, M / (1 + r) and M r / (1 + r),
// as M q and M r q with q = 1 / (1 + r).
struct Halves {
  double handle_kg, head_kg;
};
inline Halves paper_racquet_halves(double M, double r) {
  const double q = 1.0 / (1.0 + r);
  return Halves{M * q, M * (r * q)};
}

// Cross (2004) Table I racquet (Implement::paper_racquet without point
// masses): two uniform halves of length h = L/2, the head M r / (1 + r)
// beyond the handle M / (1 + r). Their sums in closed form, with q as above
// (one division):
//   x_cm = h (q + 3 r q) / 2,   I_cm = M h^2 (1/12 + (r q) q),
// section_mass_properties() of the two halves to round-off (r = 1 is the
// uniform beam's L/2 and M L^2 / 12); r q = r / (1 + r) is formed first, so
// that no step overflows however large r is. The mass is the halves' sum,
// the number section_mass_properties() checks against the model's range.
inline System paper_racquet_body(double L, double M, double r) {
  const double h = 0.5 * L;
  const Halves halves = paper_racquet_halves(M, r);
  const double q = 1.0 / (1.0 + r);
  const double rq = r * q;
  const double com = 0.5 * h * (q + 3.0 * rq);
  const double inertia = M * h * h * (1.0 / 12.0 + rq * q);
  return System{halves.handle_kg + halves.head_kg, com, inertia};
}

// Cross (2004) Eq. (17): M_eff = M / (1 + M b^2 / I_cm), b = x - x_cm, written
// M I_cm / (I_cm + M b^2) (one division); M at the centre of mass.
inline double effective_mass(double M, double c, double I, double x) {
  const double b = x - c;
  const double general = M * I / (I + M * b * b);
  return b == 0.0 ? M : general;
}

// Eq. (17) with the twist about the long axis of an impact a distance y off it:
// 1/M_eff = 1/M + b^2/I_cm + y^2/I_polar, written M_eff,axis / (1 + M_eff,axis t)
// with t = y^2 / I_polar [1/kg], so that t = 0 gives M_eff,axis exactly.
inline double twisted_effective_mass(double axis_effective_mass_kg, double twist_per_kg) {
  return axis_effective_mass_kg / (1.0 + axis_effective_mass_kg * twist_per_kg);
}

// Cross (2004) Eq. (16): e_A = (e M_eff - m) / (M_eff + m).
inline double apparent_cor(double cor, double effective_mass_kg, double ball_mass_kg) {
  return (cor * effective_mass_kg - ball_mass_kg) / (effective_mass_kg + ball_mass_kg);
}

// J = m v1 (1 + e_A) (Cross 2004, Sec. VI).
inline double ball_impulse(double ball_mass_kg, double ball_speed_m_s, double apparent_cor) {
  return ball_mass_kg * (1.0 + apparent_cor) * ball_speed_m_s;
}

// F0 = pi J / (2 T), the peak of the half-sine carrying J (Eq. 15 with the
// above), written J (pi / (2 T)): a loop over impacts of one duration divides once.
inline double half_sine_peak_force(double impulse_N_s, double impact_duration_s) {
  return impulse_N_s * (std::numbers::pi / (2.0 * impact_duration_s));
}

// Cross (2004) Eq. (13): h + I_cm / (M h) from the butt; `at_wrist` when h = 0.
inline double hand_held_cop_from_butt(double M, double h, double I, double at_wrist) {
  const double general = h + I / (M * h);
  return h == 0.0 ? at_wrist : general;
}

// Cross (2004) Eq. (11) multiplied through by M_e (see wrist_force_ratio() in
// rigid_impact.hpp): M_e M h (x - x_cop) / (M_e M h^2 + I_cm (M_e + M)),
// -M_e I_cm / (...) when h = 0, and 0 without a forearm.
// The numerator is selected before the one division, which is the division
// of either side (one division fewer in a vectorised loop, the same bits).
// The selection is a bit mask: GCC pushes a division after a plain ?: back
// into both of its sides.
inline double wrist_force_ratio(double M, double h, double I, double Me, double x) {
  const double denominator = Me * M * h * h + I * (Me + M);
  const double x_cop = h + I / (M * h);
  const double at_wrist = -Me * I;
  const double general = Me * M * h * (x - x_cop);
  const std::uint64_t wrist = std::uint64_t{0} - static_cast<std::uint64_t>(h == 0.0);
  const double numerator = std::bit_cast<double>((std::bit_cast<std::uint64_t>(at_wrist) & wrist) |
                                                 (std::bit_cast<std::uint64_t>(general) & ~wrist));
  const double ratio = numerator / denominator;
  return Me == 0.0 ? 0.0 : ratio;
}

// One impact at x of the rigid model on a body (M, c, I) that is `held`
// (the body with the hand, Eq. 14): Eqs. (17), (16), the impulse, (15), (13)
// and (11), unchecked; the only place their order is written. rigid_outcome()
// and the loops over many cases call it. Without a twist (kTwist false) its
// division is left out: M_eff / (1 + M_eff * 0) is M_eff exactly for a finite
// M_eff, so either gives the same bits there.
template <bool kTwist>
[[gnu::always_inline]] inline RigidOutcome rigid_outcome(double M, double c, double I,
                                                         const System& held, double x,
                                                         double twist_per_kg, double Me,
                                                         double ball_m, double ball_v, double cor,
                                                         double T) {
  const double axis = effective_mass(M, c, I, x);
  RigidOutcome o;
  o.effective_mass_kg = kTwist ? twisted_effective_mass(axis, twist_per_kg) : axis;
  o.apparent_cor = apparent_cor(cor, o.effective_mass_kg, ball_m);
  o.impulse_N_s = ball_impulse(ball_m, ball_v, o.apparent_cor);
  o.peak_impact_force_N = half_sine_peak_force(o.impulse_N_s, T);
  o.cop_hand_from_butt_m =
      hand_held_cop_from_butt(held.mass_kg, held.com_from_butt_m, held.I_cm_kg_m2, 0.0);
  o.wrist_force_ratio =
      wrist_force_ratio(held.mass_kg, held.com_from_butt_m, held.I_cm_kg_m2, Me, x);
  o.peak_wrist_force_N = peak_wrist_force(o.wrist_force_ratio, o.peak_impact_force_N);
  return o;
}

}  // namespace sweetspot::kernel
