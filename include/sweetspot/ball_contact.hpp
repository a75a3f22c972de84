#pragma once

// The ball's side of the solved collision (collision.hpp): its contact law
// and the string bed's moving mass and loss, as plain values a design carries.

#include <string>

namespace sweetspot {

// A ball's force against a rigid flat surface as a function of its
// compression x [m] and compression rate x' [m/s]:
//   F = k x^n + b x^p x'  for x > 0 (and never < 0), 0 otherwise.
// p = n is the Hunt-Crossley law (F = k x^n (1 + c x'), c = b / k); p < n makes
// the COR fall more slowly with speed than Hunt-Crossley's nearly linear fall.
// The law's ranges (validate()); the solved collision resolves the stiffest
// ball on the lightest string bed (collision.hpp: its step follows the ball's
// own half-period) and was verified over the whole stiffness range.
inline constexpr double kMaxBallStiffness = 1e15;  // [N / m^n]
inline constexpr double kMinBallExponent = 1.0, kMaxBallExponent = 3.0;
inline constexpr double kMaxBallDamping = 1e12;  // [N s / m^(p+1)]
inline constexpr double kMaxBallDampingExponent = 3.0;

// The hysteretic ball (docs/model.md, "The ball"): a ball whose wall buckles
// and whose unloading differs from its loading. On loading (x at a new
// maximum x_m) its elastic part is the sum of three backbones
//   B_s(x) = k_s min(x, x_b)   the cover and the wall near the contact, a stiff
//                              shell that buckles at x_b and then carries no more,
//   B_p(x) = k_p x^2           the pressure and the doubled-over wall, stiffening,
//   B_w(x) = k_w x             the wall as the ITF's slow test loads it,
// and on unloading from x_m each falls as B_i(x_m) (x / x_m)^q_i', with
// q_i' = max(q_i + offset, its minimum 1, 2, 1), never above its backbone:
// the loop's area is what the ball loses. A damping part b sqrt(x) x' adds the
// rate's loss. A ball off the surface (x <= 0) forgets x_m: it recovers its
// shape before it touches again. The ITF's slow test loads the relaxed ball,
// the wall B_w alone (the shell and the pressure's stiffening are the
// impact's, relaxed over the test's seconds): static_loop() in collision.hpp.
// An offset -> infinity is the dead limit, a plastic ball that returns nothing.
struct HystereticBallLaw {
  double shell_stiffness = 0.0;       // k_s [N/m], > 0
  double shell_compression = 0.0;     // x_b [m], > 0
  double stiffening = 0.0;            // k_p [N/m^2], >= 0
  double wall_stiffness = 0.0;        // k_w [N/m], >= 0
  double shell_unloading = 1.0;       // q_s, >= 1
  double stiffening_unloading = 2.0;  // q_p, >= 2
  double wall_unloading = 1.0;        // q_w, >= 1
  double damping = 0.0;               // b [N s / m^1.5], >= 0
  double unloading_offset = 0.0;      // added to every q_i (> -infinity); +infinity: plastic
};

// The ball's own body (docs/model.md, "The ball"): one mass, or two, a front
// half that touches and a back half behind it, joined by a stiffening spring
// G(d) = k_i d + k_3 d^3 and a dashpot (Cross, "The bounce of a ball", Am. J.
// Phys. 67, 222-227, 1999: a ball's far side is still moving in when its near
// side has stopped, and it rebounds in a compressed state). The contact law
// acts on the front mass; the ball's velocity is its centre of mass's, and
// what its two halves still ring with when it leaves is the ball's loss.
struct BallBody {
  double front_mass_fraction = 1.0;       // m_f / m, in (0, 1]; 1: one mass
  double internal_stiffness = 0.0;        // k_i [N/m], > 0 with two masses
  double internal_cubic_stiffness = 0.0;  // k_3 [N/m^3], >= 0
  double internal_damping_ratio = 0.0;    // z_i = c_i / (2 sqrt(k_i mu)), in [0, 1)

  bool two_masses() const { return front_mass_fraction < 1.0; }
};

// The forms of a ball's contact law (BallContactLaw::form).
enum class BallLawForm {
  kPower,       // F = k x^n + b x^p x' (the first four fields)
  kHysteretic,  // HystereticBallLaw (the field `hysteretic`)
  kTwoMass,     // the hysteretic law on the front of a two-mass ball (`hysteretic`, `body`)
};

// True for the forms whose contact is the hysteretic law.
constexpr bool is_hysteretic(BallLawForm form) { return form != BallLawForm::kPower; }

struct BallContactLaw {
  double stiffness = 0.0;         // k [N / m^n], in (0, kMaxBallStiffness]
  double exponent = 1.0;          // n, in [kMinBallExponent, kMaxBallExponent]
  double damping = 0.0;           // b [N s / m^(p+1)], in [0, kMaxBallDamping]
  double damping_exponent = 0.0;  // p, in [0, kMaxBallDampingExponent]
  BallLawForm form = BallLawForm::kPower;
  HystereticBallLaw hysteretic{};  // the law when form is kHysteretic or kTwoMass
  BallBody body{};                 // two masses when form is kTwoMass, else one

  // Empty if consistent, otherwise the first problem, naming the field and value.
  std::string validate() const;
};

// "power", "hysteretic" or "two_mass", the names a design file gives (ball.contact.law).
const char* to_string(BallLawForm form);

// The elastic energy stored at compression x: U = k x^(n+1) / (n+1) for x > 0, else 0 [J].
double contact_elastic_energy(const BallContactLaw& law, double compression_m);

// The calibrated tennis ball (docs/model.md, "The solved collision"): n = 1.5
// (Hertz-like), p = 0.5, with k and b solved so that a 57 g ball dropped
// 254 cm onto a rigid surface (7.06 m/s) rebounds with e = 0.745 (the middle
// of the ITF's 135-147 cm rebound, e = 0.729-0.761) after 4.5 ms of contact
// (the 4-5 ms measured for tennis balls on rigid surfaces). tests/collision_test.cpp
// recomputes both targets from these constants.
inline constexpr double kTennisBallDropTestCor = 0.745;  // both laws' calibration
inline constexpr BallContactLaw kTennisBallLaw{3.2017627372e5, 1.5, 1.1645824609e2, 0.5};
inline constexpr double kTennisBallMass_kg = 0.057;

// The hysteretic tennis ball (docs/model.md, "The ball"): k_w and q_w from the
// ITF's slow test (18 lbf: forward deformation 6.5 mm and return deformation
// 9.4 mm after 1 in, the middles of 5.6-7.4 and 8.0-10.8 mm; ITF rules as
// tabled by C. Lindsey, "Tennis Ball Performance Testing", 2021), the rest
// solved so that the 57 g ball dropped 254 cm onto a rigid surface rebounds
// with e = 0.745 after squeezing 6.0 mm (about 6 mm: Cross, "Dynamic
// properties of tennis balls", Sports Eng. 2, 23-33, 1999, and The Physics and
// Technology of Tennis), reaching half its peak force in its first 200 us
// (ibid.), and that at 30 m/s it keeps the power law's e = 0.680 (no
// published value reached) with a shorter contact (Haake, Carre & Goodwill,
// J. Sports Sci. 21, 2003: the dynamic stiffness rises with speed) squeezing
// less than 25 mm. tests/core/collision_test.cpp recomputes each.
inline constexpr double kItfStaticForce_N = 18.0 * 4.4482216152605;  // 18 lbf
inline constexpr double kItfStaticMaxCompression_m = 0.0254;         // 1 in
inline constexpr BallContactLaw kHystereticTennisBallLaw{
    kTennisBallLaw.stiffness,
    kTennisBallLaw.exponent,
    kTennisBallLaw.damping,
    kTennisBallLaw.damping_exponent,
    BallLawForm::kHysteretic,
    HystereticBallLaw{1.6702099121007355e5, 1.0086648463382922e-3, 3.638502121250385e6,
                      kItfStaticForce_N / 6.5e-3, 1.000736340854124, 6.477418180098866,
                      1.3711195762688355, 7.363467083804934, 0.0}};

// The two-mass tennis ball (docs/model.md, "The ball"): the hysteretic law on
// the front of a ball of two masses. Fitted to the same numbers as the
// hysteretic ball (the ITF's slow test loading its relaxed wall in series with
// the internal spring G), to the contact's 4.5 ms on a rigid surface (4-5 ms:
// Cross, Sports Eng. 2, 1999), which one mass cannot reach with a 6 mm
// squeeze, and to the apparent COR of 0.40 mid-strings at 50 m/s (Cross 2004
// Sec. VI: "about 0.4"), which a linear internal spring misses (0.25): G
// stiffens; and so that it leaves the surface still compressed, its centre
// short of where it touched (Cross, Am. J. Phys. 67, 222, 1999, for every
// ball he dropped), its COR falling with speed from 3 to 50 m/s.
// tests/core/collision_test.cpp recomputes each.
inline constexpr BallContactLaw kTwoMassTennisBallLaw{
    kTennisBallLaw.stiffness,
    kTennisBallLaw.exponent,
    kTennisBallLaw.damping,
    kTennisBallLaw.damping_exponent,
    BallLawForm::kTwoMass,
    HystereticBallLaw{69531.67605741009, 1.3323948987784388e-3, 5.610793381568909e6,
                      65250.01248842569, 1.0009091755661441, 11.827013398442473, 3.051190579382525,
                      30.747956455208215, 0.0},
    BallBody{0.5057181705840291, 14058.065604957594, 4.052479014432263e7, 0.05382218494280447}};
// The middle of the ITF's 6.54-6.86 cm (Rules of Tennis, Appendix I).
inline constexpr double kTennisBallDiameter_m = 0.067;

// Defaults of the string bed's moving mass and loss (docs/model.md, "The solved
// collision"): a few grams of string move with the ball (1-8 g plausible), and
// a bed alone returns about 95 % of the energy, e_s^2 = exp(-2 pi z_s) ~ 0.95.
inline constexpr double kStringBedMass_kg = 0.004;
inline constexpr double kStringBedDampingRatio = 0.008;

}  // namespace sweetspot
