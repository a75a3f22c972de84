#include "sweetspot/rigid_impact.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "check.hpp"

namespace sweetspot {

RigidKick free_kick(const MassProperties& body, double impact_from_butt_m) {
  const double b = impact_from_butt_m - body.com_from_butt_m;
  return RigidKick{1.0 / body.mass_kg, b / body.I_cm_kg_m2};  // Eqs. (1), (2)
}

double point_velocity_per_impulse(const MassProperties& body, double impact_from_butt_m,
                                  double point_from_butt_m) {
  const RigidKick kick = free_kick(body, impact_from_butt_m);
  const double A = body.com_from_butt_m - point_from_butt_m;
  return kick.com_velocity_per_impulse - A * kick.angular_velocity_per_impulse;  // Eq. (3)
}

std::optional<double> free_conjugate_from_butt(const MassProperties& body, double from_butt_m) {
  const double A = body.com_from_butt_m - from_butt_m;
  if (A == 0.0) return std::nullopt;
  return body.com_from_butt_m + body.I_cm_kg_m2 / (A * body.mass_kg);  // Eq. (5)
}

std::optional<double> velocity_ratio(const MassProperties& body, double impact_from_butt_m,
                                     double p_from_butt_m, double q_from_butt_m) {
  const double v_q = point_velocity_per_impulse(body, impact_from_butt_m, q_from_butt_m);
  if (v_q == 0.0) return std::nullopt;
  return point_velocity_per_impulse(body, impact_from_butt_m, p_from_butt_m) / v_q;  // Eq. (6)
}

double forearm_equivalent_mass(double forearm_mass_kg) {
  detail::require_at_least("forearm mass_kg", forearm_mass_kg, 0.0, "kg");
  return forearm_mass_kg / 3.0;  // Eq. (7)
}

std::optional<double> hand_held_cop_from_butt(const MassProperties& system) {
  const double h = system.com_from_butt_m;
  if (h == 0.0) return std::nullopt;
  return h + system.I_cm_kg_m2 / (system.mass_kg * h);  // Eq. (13)
}

double wrist_force_ratio(const MassProperties& system, double forearm_equivalent_mass_kg,
                         double impact_from_butt_m) {
  const double M = system.mass_kg;
  const double I = system.I_cm_kg_m2;
  const double h = system.com_from_butt_m;
  const double Me = forearm_equivalent_mass_kg;
  if (Me == 0.0) return 0.0;  // no forearm to push against: no force, whatever the body
  const double denominator = Me * M * h * h + I * (Me + M);
  // Eq. (11) multiplied through by M_e. Its numerator M b h - I_cm is M h (x - x_cop)
  // with x_cop the COP of Eq. (13), which makes it exactly zero at the COP.
  const auto x_cop = hand_held_cop_from_butt(system);
  if (!x_cop) return -Me * I / denominator;  // h = 0: M b h - I_cm = -I_cm
  return Me * M * h * (impact_from_butt_m - *x_cop) / denominator;
}

std::optional<double> hand_held_rotation_axis_from_butt(const MassProperties& system,
                                                        double forearm_equivalent_mass_kg,
                                                        double impact_from_butt_m) {
  const double M = system.mass_kg;
  const double h = system.com_from_butt_m;
  const double Me = forearm_equivalent_mass_kg;
  const double b = impact_from_butt_m - h;  // so h + b is the impact's distance from the wrist
  const double denominator = M * b + Me * impact_from_butt_m;
  if (denominator == 0.0) return std::nullopt;
  // Eq. (12): A = (I_cm + M_e h (h + b)) / denominator; s = h - A written without
  // the cancellation of h - A when the axis is near the wrist.
  return (M * b * h - system.I_cm_kg_m2) / denominator;
}

std::optional<double> hand_held_impact_for_axis(const MassProperties& system,
                                                double forearm_equivalent_mass_kg,
                                                double axis_from_butt_m) {
  const double M = system.mass_kg;
  const double h = system.com_from_butt_m;
  const double Me = forearm_equivalent_mass_kg;
  const double A = h - axis_from_butt_m;
  // Eq. (12) is linear in b: b (A (M + M_e) - M_e h) = I_cm + M_e h (h - A).
  const double coefficient = A * (M + Me) - Me * h;
  if (coefficient == 0.0) return std::nullopt;
  const double b = (system.I_cm_kg_m2 + Me * h * (h - A)) / coefficient;
  return h + b;
}

double effective_mass(const MassProperties& body, double impact_from_butt_m) {
  const double b = impact_from_butt_m - body.com_from_butt_m;
  if (b == 0.0) return body.mass_kg;
  return body.mass_kg / (1.0 + body.mass_kg * b * b / body.I_cm_kg_m2);  // Eq. (17)
}

double apparent_cor(double cor, double effective_mass_kg, double ball_mass_kg) {
  return (cor * effective_mass_kg - ball_mass_kg) / (effective_mass_kg + ball_mass_kg);  // (16)
}

double ball_impulse(double ball_mass_kg, double ball_speed_m_s, double apparent_cor) {
  return ball_mass_kg * (1.0 + apparent_cor) * ball_speed_m_s;
}

double half_sine_peak_force(double impulse_N_s, double impact_duration_s) {
  detail::require_positive("impact_duration_s", impact_duration_s, "s");
  return std::numbers::pi * impulse_N_s / (2.0 * impact_duration_s);
}

double peak_impact_force(double ball_mass_kg, double ball_speed_m_s, double apparent_cor,
                         double impact_duration_s) {
  return half_sine_peak_force(ball_impulse(ball_mass_kg, ball_speed_m_s, apparent_cor),
                              impact_duration_s);  // Eq. (15)
}

RigidOutcome rigid_outcome(const RigidCase& c) { return rigid_outcome(c, with_point_mass(c.body, c.hand)); }

RigidOutcome rigid_outcome(const RigidCase& c, const MassProperties& system) {
  RigidOutcome o;
  o.effective_mass_kg = effective_mass(c.body, c.impact_from_butt_m);
  o.apparent_cor = apparent_cor(c.cor, o.effective_mass_kg, c.ball_mass_kg);
  o.impulse_N_s = ball_impulse(c.ball_mass_kg, c.ball_speed_m_s, o.apparent_cor);
  o.peak_impact_force_N = half_sine_peak_force(o.impulse_N_s, c.impact_duration_s);
  o.cop_hand_from_butt_m = hand_held_cop_from_butt(system).value_or(0.0);  // h > 0 in a valid case
  o.wrist_force_ratio = wrist_force_ratio(system, c.forearm_equivalent_mass_kg, c.impact_from_butt_m);
  o.peak_wrist_force_N = std::abs(o.wrist_force_ratio) * o.peak_impact_force_N;
  return o;
}

void rigid_outcomes(std::span<const RigidCase> cases, std::span<RigidOutcome> out) {
  if (cases.size() != out.size()) {
    throw std::invalid_argument("rigid_outcomes: " + std::to_string(cases.size()) + " cases but room for " +
                                std::to_string(out.size()) + " outcomes");
  }
  for (std::size_t i = 0; i < cases.size(); ++i) out[i] = rigid_outcome(cases[i]);
}

}  // namespace sweetspot
