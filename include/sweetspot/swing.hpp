#pragma once

// The racquet swung at the ball (Brody; Cross): the shot off a moving racquet.
// During the few milliseconds of contact the racquet is treated as free, so
// the collision in the frame moving with the impact point is the laboratory's
// (a ball onto a racquet at rest), and the outgoing ball speed follows from
// its apparent COR e_A (R. Cross, "The sweet spots of a tennis racket",
// Am. J. Phys. 67, 692 (1999); H. Brody, "Tennis Science for Tennis Players",
// 1987). Valid while the racquet's rotation during the contact is small (a
// few degrees at 15 rad/s over 5 ms) and the hand does not matter during it.

#include <optional>

namespace sweetspot {

// Swing speed against swingweight at maximum effort: V = C / I^n with
// n = 0.27 for I > 0.03 kg m^2 (R. Cross and R. Bower, "Effects of swing-weight
// on swing speed and racket power", J. Sports Sci. 24, 23-30 (2006)).
inline constexpr double kSwingweightExponent = 0.27;

// The ranges a swing is accepted over: up to 100 rad/s (a serve's racquet
// turns at 30-40 rad/s), a pivot up to 3 m beyond the butt (an arm's length
// is under 1 m).
inline constexpr double kMaxAngularSpeed_rad_s = 100.0;
inline constexpr double kMaxPivotBeyondButt_m = 3.0;

// The racquet's rigid rotation at the impact: angular speed omega [rad/s]
// (> 0, at most kMaxAngularSpeed_rad_s) about a pivot `pivot_beyond_butt_m`
// beyond the butt (>= 0, at most kMaxPivotBeyondButt_m; 0: about the butt).
// With `reference_swingweight_kg_m2` the angular speed is the one measured
// with a racquet of that swingweight (about the axis 10 cm from the butt), and
// the design's own swingweight scales it (scaled_to_swingweight()).
struct Swing {
  double angular_speed_rad_s = 0.0;
  double pivot_beyond_butt_m = 0.0;
  std::optional<double> reference_swingweight_kg_m2;
};

// The swing assumed when a design gives none: a groundstroke whose racquet
// moves at 15.4 m/s 50 cm from the butt (the centre of the strings), the mean
// horizontal racquet-head speed before impact of collegiate players' forehands
// (Kwon, Pfister, Hager, Hunter & Seeley, J. Sports Sci. Med. 16, 505-513
// (2017): 15.4 +- 1.4 m/s), turning about a pivot 60 cm beyond the butt (about
// the shoulder: an assumption, no measurement of the pivot was found), so
// omega = 15.4 / 1.10 = 14 rad/s.
inline constexpr Swing kTypicalGroundstroke{14.0, 0.60, std::nullopt};

// Throws std::invalid_argument naming the field ("swing/angular_speed_rad_s:
// must be in [...]") when a value is out of the ranges above or the reference
// swingweight is not > 0.
void validate(const Swing& swing);

// The racquet's speed at `from_butt_m` [m] from the butt:
// V = omega (pivot_beyond_butt + from_butt) [m/s].
double racquet_speed_m_s(const Swing& swing, double from_butt_m);

// The outgoing ball speed off a moving, free racquet (Brody; Cross 1999):
// v_out = e_A v_in + (1 + e_A) V [m/s], with e_A the apparent COR at the
// impact point (a ball onto the racquet at rest), v_in the incoming ball's
// speed towards the racquet [m/s] (0 for a serve) and V the racquet's speed at
// the impact point towards the ball [m/s].
double shot_speed_m_s(double apparent_cor, double incoming_speed_m_s, double racquet_speed_m_s);

// The swing with its angular speed scaled to a racquet of swingweight
// `swingweight_kg_m2` (> 0): omega (I_ref / I)^kSwingweightExponent (Cross &
// Bower 2006); the swing itself without a reference swingweight.
Swing scaled_to_swingweight(const Swing& swing, double swingweight_kg_m2);

}  // namespace sweetspot
