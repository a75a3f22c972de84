#pragma once

// The rigid-body impact model of Cross (2004), "Center of percussion of
// hand-held implements", Am. J. Phys. 72, 622. Every equation of the paper is
// implemented by exactly one function here, which cites it.
//
// Conventions: positions x are measured along the implement from the butt
// (handle end, x = 0) towards the tip. The wrist is at the butt. An impulse J
// (or force F) acts at the impact point, transverse to the implement. A
// position that the physics puts at infinity (an impact through the centre of
// mass leaves the body translating without rotation) is std::nullopt.

#include <cmath>
#include <optional>
#include <span>

#include "sweetspot/mass_properties.hpp"

namespace sweetspot {

// Motion of a free body per unit transverse impulse at `impact_from_butt_m`.
struct RigidKick {
  double com_velocity_per_impulse = 0.0;      // V_cm / J  [m s^-1 per N s]
  double angular_velocity_per_impulse = 0.0;  // omega / J [rad s^-1 per N s], positive when
                                              // the tip side moves with the impulse
};

// Cross (2004) Eqs. (1)-(2): V_cm = J / M_b and omega = J b / I_0 with b the
// impact's distance from the centre of mass (positive towards the tip).
RigidKick free_kick(const MassProperties& body, double impact_from_butt_m);

// Cross (2004) Eqs. (3)-(4): velocity of the point P per unit impulse,
//   v / J = 1/M_b - A b / I_0,  A = x_cm - x_P  (P opposite the impact: A > 0).
// [m s^-1 per N s]; zero when P is the rotation axis conjugate to the impact.
double point_velocity_per_impulse(const MassProperties& body, double impact_from_butt_m,
                                  double point_from_butt_m);

// Cross (2004) Eq. (5): the conjugate of a point of a free body, b = I_0 / (A M_b).
// For an axis at x, the centre of percussion; for an impact at x, the rotation
// axis (the relation is symmetric). Returns its position from the butt [m],
// std::nullopt when x is the centre of mass (conjugate at infinity).
std::optional<double> free_conjugate_from_butt(const MassProperties& body, double from_butt_m);

// Cross (2004) Eq. (6) generalised to any two observation points p and q:
// v_p / v_q = (1 - M A_p b / I_0) / (1 - M A_q b / I_0) for an impact at x.
// std::nullopt when v_q = 0 (the impact is at q's centre of percussion).
std::optional<double> velocity_ratio(const MassProperties& body, double impact_from_butt_m,
                                     double p_from_butt_m, double q_from_butt_m);

// Cross (2004) Eq. (7): the forearm of mass M_F pivoting at the elbow acts at
// the wrist as the equivalent mass M_e = M_F / 3 [kg].
double forearm_equivalent_mass(double forearm_mass_kg);

// Cross (2004) Eq. (13): the centre of percussion of the hand-held implement,
// for which the wrist force vanishes: b = I_cm / (M h), returned as h + b from the
// butt [m]. `system` is implement plus hand (with_point_mass), whose centre of
// mass h must be > 0. std::nullopt when h = 0.
std::optional<double> hand_held_cop_from_butt(const MassProperties& system);

// Cross (2004) Eq. (11): F_w / F = (M b h - I_cm) / (M h^2 + I_cm (1 + M / M_e)),
// with M, I_cm, h of implement plus hand and b = x - h. Evaluated as
// M_e M h (x - x_cop) / (M_e M h^2 + I_cm (M_e + M)), which is exactly zero for
// an impact at the centre of percussion and finite for every M_e >= 0
// (M_e = 0: no forearm, no force). F_w is the wrist's force on the hand,
// counted along F; the hand pushes the forearm the other way, so a positive
// ratio jerks the forearm towards the outgoing ball (impacts tip-side of the
// COP), a negative one away from it (Sec. V.B). Dimensionless.
double wrist_force_ratio(const MassProperties& system, double forearm_equivalent_mass_kg,
                         double impact_from_butt_m);

// The peak force on the wrist [N] when the ball's force peaks at
// `peak_impact_force_N`: |F_w / F| F0 (Eq. 11 at the peak; the ratio is
// fixed through the impact). The rigid model's F0 is Eq. (15)'s; the solved
// collision's is its own peak.
inline double peak_wrist_force(double wrist_force_ratio, double peak_impact_force_N) {
  return std::abs(wrist_force_ratio) * peak_impact_force_N;
}

// Cross (2004) Eq. (12): the rotation axis of the hand-held implement,
//   A = (I_cm + M_e h (h + b)) / (M b + M_e (h + b)),
// returned as s = h - A, its position from the butt [m] (negative: beyond the
// butt, towards the elbow). With M_e = 0 it is the free axis of implement plus
// hand. std::nullopt when the denominator vanishes (pure translation).
std::optional<double> hand_held_rotation_axis_from_butt(const MassProperties& system,
                                                        double forearm_equivalent_mass_kg,
                                                        double impact_from_butt_m);

// Cross (2004) Eq. (12) solved for b: the impact point that makes the hand-held
// implement rotate about `axis_from_butt_m` (the paper's b = -0.77 m for an axis
// 16 cm from the handle end). Returns the impact position from the butt [m],
// std::nullopt when no impact gives that axis.
std::optional<double> hand_held_impact_for_axis(const MassProperties& system,
                                                double forearm_equivalent_mass_kg,
                                                double axis_from_butt_m);

// Cross (2004) Eq. (17): effective mass of the implement at the impact point,
// M_eff = M_b / (1 + M_b b^2 / I_cm) [kg]; M_eff <= M_b, equal at the centre of mass.
double effective_mass(const MassProperties& body, double impact_from_butt_m);

// Eq. (17) extended to an impact a distance y off the long axis, which also
// turns the implement about that axis (its polar inertia I_polar):
//   1 / M_eff = 1 / M_b + b^2 / I_cm + y^2 / I_polar  [kg].
// A rigid body with no product of inertia between the long axis and the
// transverse one (a head symmetric about the long axis); y = 0 gives Eq. (17)
// exactly. Throws std::invalid_argument naming "polar_inertia_kg_m2" unless it
// is > 0 when y != 0, and "off_axis_m" unless y is finite.
double effective_mass(const MassProperties& body, double impact_from_butt_m, double off_axis_m,
                      double polar_inertia_kg_m2);

// The twist term of the above, t = y^2 / I_polar [1/kg]: 0 when y = 0 (whatever
// I_polar, which may then be 0 for "unknown"). Throws like effective_mass().
double impact_twist_per_kg(double off_axis_m, double polar_inertia_kg_m2);

// Cross (2004) Eq. (16): apparent coefficient of restitution
// e_A = (e M_eff - m) / (M_eff + m), the ball's rebound speed over its incident
// speed when the implement is initially at rest. In (-1, 1].
double apparent_cor(double cor, double effective_mass_kg, double ball_mass_kg);

// The impulse the ball gives the implement, J = integral of F dt = m v1 (1 + e_A)
// (Cross 2004, Sec. VI) [N s].
double ball_impulse(double ball_mass_kg, double ball_speed_m_s, double apparent_cor);

// Peak of the half-sine force F0 sin(pi t / T) that carries the impulse J:
// F0 = pi J / (2 T) [N]. Throws std::invalid_argument for T <= 0.
double half_sine_peak_force(double impulse_N_s, double impact_duration_s);

// Cross (2004) Eq. (15): the two above together, F0 = (1 + e_A) pi m v1 / (2 T) [N].
double peak_impact_force(double ball_mass_kg, double ball_speed_m_s, double apparent_cor,
                         double impact_duration_s);

// ------------------------------------------------------------------ many at once
// The whole rigid model of one impact reduced to numbers, for evaluating
// millions of designs: the implement's mass properties (with its point masses),
// the hand, the forearm, the ball, the frame's COR, the impact duration and the
// impact point. Plain data (104 bytes); a Design makes one with rigid_case().
struct RigidCase {
  MassProperties body;                      // the implement with its point masses
  PointMass hand;                           // the hand's mass at its centre
  double forearm_equivalent_mass_kg = 0.0;  // M_e, Eq. (7)
  double ball_mass_kg = 0.0;
  double ball_speed_m_s = 0.0;
  double cor = 0.0;                // e of Eq. (16)
  double impact_duration_s = 0.0;  // T of Eq. (15), > 0
  double impact_from_butt_m = 0.0;
  // y^2 / I_polar of an impact off the long axis [1/kg] (impact_twist_per_kg()):
  // lowers M_eff; 0 on the axis.
  double impact_twist_per_kg = 0.0;
};

// What the paper asks of one impact, as plain numbers (56 bytes).
struct RigidOutcome {
  double effective_mass_kg = 0.0;     // Eq. (17)
  double apparent_cor = 0.0;          // Eq. (16)
  double impulse_N_s = 0.0;           // m v1 (1 + e_A)
  double peak_impact_force_N = 0.0;   // Eq. (15)
  double cop_hand_from_butt_m = 0.0;  // Eq. (13)
  double wrist_force_ratio = 0.0;     // Eq. (11)
  double peak_wrist_force_N = 0.0;    // |F_w / F| F0
};

// Evaluates one case with the functions above. The case must be valid as
// rigid_case() leaves it (implement plus hand with its centre of mass beyond
// the butt, T > 0); nothing is checked or allocated.
RigidOutcome rigid_outcome(const RigidCase& c);

// The same with implement plus hand (with_point_mass(c.body, c.hand)) formed
// by the caller, who evaluates one design at many impact points.
RigidOutcome rigid_outcome(const RigidCase& c, const MassProperties& system);

// rigid_outcome() for every case, into `out` (the same size: throws
// std::invalid_argument otherwise). No allocation; the cases are laid out as
// arrays (RigidCases) a block at a time and evaluated as below.
void rigid_outcomes(std::span<const RigidCase> cases, std::span<RigidOutcome> out);

// Many cases as one array per field (structure of arrays), case i being
// element i of every array: the layout a vectorising compiler wants. Every
// span has the same length. Plain views; the caller owns the storage.
struct RigidCases {
  std::span<const double> body_mass_kg, body_com_from_butt_m, body_I_cm_kg_m2;  // the implement
  std::span<const double> hand_from_butt_m, hand_mass_kg;
  std::span<const double> forearm_equivalent_mass_kg;
  std::span<const double> ball_mass_kg, ball_speed_m_s;
  std::span<const double> cor, impact_duration_s, impact_from_butt_m;
  // RigidCase::impact_twist_per_kg; empty means 0 for every case.
  std::span<const double> impact_twist_per_kg{};
};

// The outcomes as one array per field, each as long as the cases.
struct RigidOutcomes {
  std::span<double> effective_mass_kg, apparent_cor, impulse_N_s, peak_impact_force_N;
  std::span<double> cop_hand_from_butt_m, wrist_force_ratio, peak_wrist_force_N;
};

// rigid_outcome() of case i into element i of every output, bit for bit, in
// one loop without branches (vectorised). The cases must be valid as
// rigid_case() leaves them; nothing is checked but the lengths (throws
// std::invalid_argument naming the first span of another length). No allocation.
void rigid_outcomes(const RigidCases& cases, const RigidOutcomes& out);

}  // namespace sweetspot
