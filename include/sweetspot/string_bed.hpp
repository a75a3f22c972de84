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
//
// A stringer's bed (a pattern, a hybrid): mains of tension T_m at spacing d_m
// and crosses of T_c at d_c carry N_m = T_m / d_m along the mains and
// N_c = T_c / d_c along the crosses, N_m w_xx + N_c w_yy = -p. Scaling x by
// sqrt(N_m) and y by sqrt(N_c) makes it Laplace's equation with the tension
// sqrt(N_m N_c); the head's and the contact's areas scale alike, so the ratio of
// the equal-area radii is unchanged and
//   k_strings = 2 pi sqrt(N_m N_c) / ln(R / r0),
// which is the plain bed's formula with T_s = sqrt(T_m T_c) and d = sqrt(d_m d_c).
// The string material's stretch does not enter: for the small slopes of the
// model the bed's stiffness is its tension's, and the strings' stretch adds only
// at large deflection (second order in the slope).
//
// The bed's ring (the tap-tone apps' input): the fundamental of the membrane of
// areal density sigma = mu_m / d_m + mu_c / d_c over a square of the head's area
// A (Cross & Bower 2001 found the frequency to depend on the area, not the
// shape; Cross, "Measuring string tension", 2006, gives f = sqrt(T / (4 m L)) for
// a string of mass m and length L = sqrt(A), the equal-family case of this):
//   f = (1/2) sqrt((N_m + N_c) / (sigma A)).

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

// A string's material, by the densities of its polymers (docs/model.md, "The
// stringer's bed"): natural gut (collagen, about 1300 kg/m^3, the least certain),
// nylon and nylon multifilament (polyamide 6 and 6.6, 1140), polyester (PET,
// 1380; measured co-polyesters run 5-10 % lighter, textured or shaped strings
// differ: give linear_density to use a measured one), Kevlar (para-aramid,
// 1440).
enum class StringMaterial { kNaturalGut, kNylon, kMultifilament, kPolyester, kKevlar };
double string_material_density_kg_m3(StringMaterial material);

// The mass per length of a round string of `diameter_m` in `material` [kg/m].
double string_linear_density(StringMaterial material, double diameter_m);

// The ranges of a stringer's inputs: a string from a badminton's 0.5 mm to a
// 2 mm (thicker than any tennis gauge, 15 is 1.41-1.49 mm); its mass per length
// 0.1-5 g/m; the share of the pull tension the bed loses, at most 60 % (Cross &
// Bower 2001 measured about 30 % right after stringing; the retailer's
// laboratory's tension-loss test, a harsher one, reaches 45-55 % for polyesters).
inline constexpr double kMinGauge_m = 0.5e-3, kMaxGauge_m = 2.0e-3;
inline constexpr double kMinStringLinearDensity_kg_m = 1e-4, kMaxStringLinearDensity_kg_m = 5e-3;
inline constexpr double kMaxTensionLoss = 0.6;

// The mass per length of a 1.30 mm (gauge 16) nylon string, the plain bed's
// string: 1140 kg/m^3 times pi (1.30 mm)^2 / 4 [kg/m] (string_linear_density's
// product, in its order, so that a ticket of 1.30 mm nylon is this bed to the bit).
inline constexpr double kDefaultStringLinearDensity_kg_m =
    1140.0 * 3.141592653589793 * 1.30e-3 * 1.30e-3 / 4.0;

// A string bed. Defaults: a 100 in^2 (0.0645 m^2) head strung 16 x 19 with
// 1.30 mm nylon, mains and crosses alike.
struct StringBed {
  double tension_N =
      250.0;  // T_m, tension in the bed of each main (and of each cross but for
              // cross_tension_ratio) [N], > 0 (the JSON layer converts lb, kg, a pull)
  double string_spacing_m =
      0.0165;  // d = sqrt(d_m d_c), mean centre-to-centre spacing of mains and crosses [m], > 0
  double head_radius_m = 0.1433;   // R = sqrt(area / pi) [m], > contact_radius_m
  double contact_radius_m = 0.03;  // r0, radius of the ball's contact on the strings [m], > 0
  // The second family: T_c / T_m (a hybrid or a cross strung tighter) and
  // d_c / d_m (the pattern over the head), both > 0; a tension study that
  // changes tension_N keeps the crosses in proportion.
  double cross_tension_ratio = 1.0;
  double cross_spacing_ratio = 1.0;
  // The strings' mass per length, mains and crosses [kg/m], > 0.
  double main_linear_density_kg_m = kDefaultStringLinearDensity_kg_m;
  double cross_linear_density_kg_m = kDefaultStringLinearDensity_kg_m;

  // The share of the machine's pull the bed has lost, in [0, kMaxTensionLoss]:
  // the pull was tension_N / (1 - tension_loss). Only reported (the physics is
  // the bed's tension).
  double tension_loss = 0.0;

  double main_spacing_m() const;   // d_m = d / sqrt(d_c / d_m)
  double cross_spacing_m() const;  // d_c = d sqrt(d_c / d_m)
  double cross_tension_N() const { return tension_N * cross_tension_ratio; }
  double pull_tension_N() const { return tension_N / (1.0 - tension_loss); }

  // Empty if consistent, otherwise the first problem, naming the field and value.
  std::string validate() const;
};

// k_strings = 2 pi T_s / (d ln(R / r0)) [N/m] (see above). Throws
// std::invalid_argument naming the field of an invalid bed.
double string_bed_stiffness(const StringBed& bed);

// The fundamental of the bed's membrane, f = (1/2) sqrt((N_m + N_c) / (sigma A))
// [Hz] (see above). Throws std::invalid_argument naming the field of an invalid bed.
double string_bed_ring_frequency(const StringBed& bed);

// The mass of the strings inside the head, sigma A [kg].
double string_bed_strings_mass(const StringBed& bed);

// The mains' tension [N] (the crosses' kept in proportion) that gives the bed
// the stiffness `stiffness_N_m` (> 0), or the ring `frequency_Hz` (> 0): both in
// closed form and unique (k grows linearly with the tension, f as its square root).
double tension_for_stiffness(const StringBed& bed, double stiffness_N_m);
double tension_for_ring(const StringBed& bed, double frequency_Hz);

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
