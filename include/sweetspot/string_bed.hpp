#pragma once

// Impact duration from string tension. The ball and the string bed are two
// springs in series between the ball's mass m and the implement's effective
// mass M_eff at the impact point (Cross 2004 Eq. 17). A linear spring between
// two free masses makes a half-sine contact force lasting half a period of the
// relative motion:
//   T = pi sqrt(mu / k),  mu = m M_eff / (m + M_eff),  1/k = 1/k_ball + 1/k_strings
// (the half-sine of Cross 2004 Sec. VI; the spring model of the ball and
// strings of Cross 2000, "Flexible beam analysis of the effects of string
// tension and frame stiffness on racket performance", Sports Eng. 3, 111-122,
// ref. 13 of the paper).
//
// String-bed stiffness: the strung area as a tensioned membrane. An
// orthogonal grid of strings of tension T_s [N] at spacing d [m] carries a
// tension per unit length N = T_s / d across any cut along either family, so
// for small transverse deflections it obeys the membrane equation
// N (w_xx + w_yy) = -p (the same model Cross & Bower use to find string tension
// from the string plane's vibration frequency: "Measurements of string tension
// in a tennis racket", Sports Eng. 4, 165-175 (2001)). For a circular
// membrane of radius R with a rigid rim, pushed at its centre over a contact
// disc of radius r0 (the flattened ball), vertical equilibrium of the part
// inside radius r gives 2 pi r N (-dw/dr) = F, so w(r0) = F ln(R/r0) / (2 pi N):
//   k_strings = 2 pi N / ln(R / r0) = 2 pi T_s / (d ln(R / r0))  [N/m].
// Assumptions: a central impact on a head replaced by the circle of the same
// area; small slopes (the real bed stiffens as the strings stretch at large
// deflection); tension unchanged during the impact; rim and frame rigid
// (the frame's flexibility is the impact response's business); string mass
// ignored; the ball linear. It gives k_strings ~ 60 kN/m at 250 N with the
// defaults below, the same order as the ball, as the models cited above assume.

#include <optional>
#include <string>

namespace sweetspot {

// Stiffness of a tennis ball compressed against a flat surface at 30-50 m/s,
// the middle of the 30-50 kN/m range of the tennis literature (Brody, Cross &
// Lindsey, The Physics and Technology of Tennis, 2002, ref. 10 of Cross 2004;
// Cross 2000, ref. 13, models the ball as such a spring) [N/m]. A tennis ball is
// not a linear spring; this is the secant stiffness that reproduces the
// contact time, not a measured constant.
inline constexpr double kTennisBallStiffness_N_m = 40.0e3;

// A string bed. Defaults: a 100 in^2 (0.0645 m^2) head strung 16 x 19.
struct StringBed {
  double tension_N =
      250.0;  // T_s, tension of each string [N], > 0 (the JSON layer converts lb, kg)
  double string_spacing_m =
      0.0165;                      // d, mean centre-to-centre spacing of mains and crosses [m], > 0
  double head_radius_m = 0.1433;   // R = sqrt(area / pi) [m], > contact_radius_m
  double contact_radius_m = 0.03;  // r0, radius of the ball's contact on the strings [m], > 0

  // Empty if consistent, otherwise the first problem, naming the field and value.
  std::string validate() const;
};

// k_strings = 2 pi T_s / (d ln(R / r0)) [N/m] (see above). Throws
// std::invalid_argument naming the field of an invalid bed.
double string_bed_stiffness(const StringBed& bed);

// Reduced mass of the ball and the implement's effective mass at the impact
// point, mu = m M_eff / (m + M_eff) [kg]: the mass of their relative motion in
// the collision. Both > 0.
double reduced_mass(double ball_mass_kg, double effective_mass_kg);

// Springs in series: 1/k = 1/k_ball + 1/k_strings [N/m]; both > 0.
double series_stiffness(double ball_stiffness_N_m, double string_bed_stiffness_N_m);

// Contact time of two masses meeting through a linear spring:
// T = pi sqrt(mu / k), mu = m M_eff / (m + M_eff) [s]. Masses [kg] and k [N/m] > 0.
double spring_contact_duration(double ball_mass_kg, double effective_mass_kg, double stiffness_N_m);

struct TensionDuration {
  double duration_s = 0.0;                // T
  double stiffness_N_m = 0.0;             // k, ball and strings in series
  double string_bed_stiffness_N_m = 0.0;  // k_strings
  double reduced_mass_kg = 0.0;           // mu
};

// The impact duration a string bed gives a ball of `ball_mass_kg` and
// stiffness `ball_stiffness_N_m` meeting the effective mass `effective_mass_kg`
// (Cross 2004 Eq. 17 at the impact point). Throws std::invalid_argument naming
// the offending argument.
TensionDuration tension_impact_duration(const StringBed& bed, double ball_mass_kg,
                                        double effective_mass_kg,
                                        double ball_stiffness_N_m = kTennisBallStiffness_N_m);

// The string tension [N] that makes the impact last `duration_s`, the other
// fields of `bed` kept: the inverse of tension_impact_duration in closed form,
//   k = pi^2 mu / T^2, k_strings = 1 / (1/k - 1/k_ball), T_s = k_strings d ln(R/r0) / (2 pi).
// std::nullopt when T <= pi sqrt(mu / k_ball): even infinitely tight strings
// leave the ball's own contact time. The duration falls monotonically with
// tension, so the answer is unique.
std::optional<double> tension_for_duration(const StringBed& bed, double duration_s,
                                           double ball_mass_kg, double effective_mass_kg,
                                           double ball_stiffness_N_m = kTennisBallStiffness_N_m);

}  // namespace sweetspot
