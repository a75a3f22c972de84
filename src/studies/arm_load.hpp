#pragma once

// What a racquet does to the arm, from the quantities the literature ties to
// arm load (docs/model.md, "The arm"): the shock at the wrist (the peak wrist
// force, Cross 2004 Eq. 11), the vibration reaching the hand (its amplitude at
// the grip and its frequency, weighted by the hand's sensitivity, ISO 5349-1's
// W_h) and the twist of an off-centre hit (the peak torque about the long
// axis), each over a spread of impact points a player makes rather than one
// point. Plain data: reports/comparison.hpp says it in words.

#include <optional>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/impact_response.hpp"

namespace sweetspot::studies {

// ISO 5349-1 (2001), Annex A: the magnitude of the hand-arm frequency
// weighting W_h at f [Hz] (> 0), the band limits (second-order Butterworth
// high-pass at 6.310 Hz and low-pass at 1258.9 Hz) times the
// acceleration-velocity transition (f3 = f4 = 15.915 Hz, Q4 = 0.64):
//   |W_h| = |H_hp| |H_lp| sqrt(1 + (f/f3)^2) / sqrt((1 - (f/f4)^2)^2 + (f/(Q4 f4))^2).
// Above some 30 Hz it falls as 15.9 Hz / f: the weighted acceleration of a
// vibration is then proportional to its velocity. Throws std::invalid_argument
// naming "frequency_Hz" for f <= 0 or not finite.
double iso5349_weighting(double frequency_Hz);

// The vibration the ball leaves in the frame, at the hand's position.
struct HandVibration {
  // Velocity amplitude at the hand's centre [m/s]: the modes' amplitudes
  // |phi_k(x_hand)| sqrt(2 E_k) combined as a root sum of squares.
  double velocity_m_s = 0.0;
  // The same as acceleration, each mode's weighted by W_h at its frequency
  // (root sum of squares of W_h(f_k) w_k |phi_k(x_hand)| sqrt(2 E_k)) [m/s^2].
  double weighted_acceleration_m_s2 = 0.0;
  // The frequency of the mode that carries most of the weighted acceleration [Hz].
  double frequency_Hz = 0.0;
};

// The vibration a hit leaves at `hand_from_butt_m` of the free frame
// `model` (response_model(..., kFree)): the half-sine of the evaluation's
// impulse and duration at its impact (Cross 2004 Sec. VI: the ball leaves
// before the bending wave returns from the hand, so the frame is hit as if
// free), each mode's energy after the pulse (ImpactResponse::modes), then its
// amplitude at the hand. The amplitude the vibration starts with there; the
// hand then damps it (not modelled). Throws like impact_response().
HandVibration hand_vibration(const ResponseModel& model, double hand_from_butt_m,
                             const Evaluation& evaluation);

// Where a player hits: a stated spread of nine points around the centre of
// the strings (a racquet; else the impact asked about), a 3 x 3 grid
// kArmSpreadStep_m apart along the long axis and across it (the three along
// the axis alone for an implement without a polar inertia, which cannot be
// hit off the axis). A stated assumption, not a measured distribution.
inline constexpr double kArmSpreadStep_m = 0.03;
struct SpreadPoint {
  double from_tip_m = 0.0;
  double off_axis_m = 0.0;  // positive towards 3 o'clock
};

// One factor of the arm's load: its mean over the spread, or why it is not
// known (the fidelity cannot give it, or the model refuses a hit of the spread).
struct ArmFactor {
  std::optional<double> value;  // SI
  std::string unknown_why;      // when !value
};

struct ArmLoad {
  std::vector<SpreadPoint> spread;
  bool around_centre_of_strings = false;      // else around the impact asked about
  ArmFactor peak_wrist_force_N;               // mean peak wrist force (the shock)
  ArmFactor hand_weighted_acceleration_m_s2;  // mean W_h-weighted amplitude at the hand
  ArmFactor hand_velocity_m_s;                // mean velocity amplitude at the hand
  ArmFactor hand_frequency_Hz;                // the mode carrying most of the weighted vibration
  ArmFactor peak_twist_torque_N_m;            // mean peak torque about the long axis (the twist)
};

// The free frame's response model of a design, or why there is none (no
// stiffness, or a fidelity below kModal).
struct FreeFrame {
  std::optional<ResponseModel> model;
  std::string why;
};
FreeFrame free_frame_of(const io::DesignFile& design, const Evaluation& asked);

// The design hit at every point of the spread at the fidelity of `asked`
// (its own evaluation), the hand-held modes to `rel_tol`. Never throws for a
// design whose asked impact was answered: a point the model refuses, or a
// factor the fidelity cannot give, is a factor not known, said why.
ArmLoad arm_load(const io::DesignFile& design, const Evaluation& asked, double asked_from_tip_m,
                 const std::optional<double>& centre_of_strings_from_tip_m, const FreeFrame& frame,
                 double rel_tol);

}  // namespace sweetspot::studies
