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

struct BallContactLaw {
  double stiffness = 0.0;         // k [N / m^n], in (0, kMaxBallStiffness]
  double exponent = 1.0;          // n, in [kMinBallExponent, kMaxBallExponent]
  double damping = 0.0;           // b [N s / m^(p+1)], in [0, kMaxBallDamping]
  double damping_exponent = 0.0;  // p, in [0, kMaxBallDampingExponent]

  // Empty if consistent, otherwise the first problem, naming the field and value.
  std::string validate() const;
};

// The elastic energy stored at compression x: U = k x^(n+1) / (n+1) for x > 0, else 0 [J].
double contact_elastic_energy(const BallContactLaw& law, double compression_m);

// The calibrated tennis ball (docs/model.md, "The solved collision"): n = 1.5
// (Hertz-like), p = 0.5, with k and b solved so that a 57 g ball dropped
// 254 cm onto a rigid surface (7.06 m/s) rebounds with e = 0.745 (the middle
// of the ITF's 135-147 cm rebound, e = 0.729-0.761) after 4.5 ms of contact
// (the 4-5 ms measured for tennis balls on rigid surfaces). tests/collision_test.cpp
// recomputes both targets from these constants.
inline constexpr BallContactLaw kTennisBallLaw{3.2017627372e5, 1.5, 1.1645824609e2, 0.5};
inline constexpr double kTennisBallMass_kg = 0.057;
inline constexpr double kTennisBallDiameter_m = 0.065;

// Defaults of the string bed's moving mass and loss (docs/model.md, "The solved
// collision"): a few grams of string move with the ball (1-8 g plausible), and
// a bed alone returns about 95 % of the energy, e_s^2 = exp(-2 pi z_s) ~ 0.95.
inline constexpr double kStringBedMass_kg = 0.004;
inline constexpr double kStringBedDampingRatio = 0.008;

}  // namespace sweetspot
