#include "sweetspot/rigid_impact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "core/rigid_kernel.hpp"
#include "sweetspot/errors.hpp"

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
  if (system.com_from_butt_m == 0.0) return std::nullopt;
  return kernel::hand_held_cop_from_butt(system.mass_kg, system.com_from_butt_m, system.I_cm_kg_m2,
                                         0.0);  // Eq. (13)
}

double wrist_force_ratio(const MassProperties& system, double forearm_equivalent_mass_kg,
                         double impact_from_butt_m) {
  // Eq. (11) multiplied through by M_e. Its numerator M b h - I_cm is M h (x - x_cop)
  // with x_cop the COP of Eq. (13), which makes it exactly zero at the COP; with
  // no forearm to push against there is no force, whatever the body.
  return kernel::wrist_force_ratio(system.mass_kg, system.com_from_butt_m, system.I_cm_kg_m2,
                                   forearm_equivalent_mass_kg, impact_from_butt_m);
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
  return kernel::effective_mass(body.mass_kg, body.com_from_butt_m, body.I_cm_kg_m2,
                                impact_from_butt_m);  // (17)
}

double impact_twist_per_kg(double off_axis_m, double polar_inertia_kg_m2) {
  detail::require_finite("off_axis_m", off_axis_m);
  if (off_axis_m == 0.0) return 0.0;
  detail::require_positive("polar_inertia_kg_m2", polar_inertia_kg_m2, "kg m^2");
  return off_axis_m * off_axis_m / polar_inertia_kg_m2;
}

double effective_mass(const MassProperties& body, double impact_from_butt_m, double off_axis_m,
                      double polar_inertia_kg_m2) {
  return kernel::twisted_effective_mass(effective_mass(body, impact_from_butt_m),
                                        impact_twist_per_kg(off_axis_m, polar_inertia_kg_m2));
}

double apparent_cor(double cor, double effective_mass_kg, double ball_mass_kg) {
  return kernel::apparent_cor(cor, effective_mass_kg, ball_mass_kg);  // Eq. (16)
}

double ball_impulse(double ball_mass_kg, double ball_speed_m_s, double apparent_cor) {
  return kernel::ball_impulse(ball_mass_kg, ball_speed_m_s, apparent_cor);
}

double half_sine_peak_force(double impulse_N_s, double impact_duration_s) {
  detail::require_positive("impact_duration_s", impact_duration_s, "s");
  return kernel::half_sine_peak_force(impulse_N_s, impact_duration_s);
}

double peak_impact_force(double ball_mass_kg, double ball_speed_m_s, double apparent_cor,
                         double impact_duration_s) {
  return half_sine_peak_force(ball_impulse(ball_mass_kg, ball_speed_m_s, apparent_cor),
                              impact_duration_s);  // Eq. (15)
}

RigidOutcome rigid_outcome(const RigidCase& c) {
  return rigid_outcome(c, with_point_mass(c.body, c.hand));
}

RigidOutcome rigid_outcome(const RigidCase& c, const MassProperties& system) {
  detail::require_positive("impact_duration_s", c.impact_duration_s, "s");  // Eq. (15)
  return kernel::rigid_outcome<true>(
      c.body.mass_kg, c.body.com_from_butt_m, c.body.I_cm_kg_m2,
      kernel::System{system.mass_kg, system.com_from_butt_m, system.I_cm_kg_m2},
      c.impact_from_butt_m, c.impact_twist_per_kg, c.forearm_equivalent_mass_kg, c.ball_mass_kg,
      c.ball_speed_m_s, c.cor, c.impact_duration_s);
}

namespace {

// One loop over arrays, every special case selected rather than branched on
// (kernel::), so the compiler vectorises it; on x86-64 GCC also builds an AVX2
// copy, picked at load time on a processor that has it. No FMA: the results
// are those of the scalar functions, bit for bit (kernel::rigid_outcome()).
// No AVX-512 copy: one built with -ffp-contract=off (without it GCC fuses
// multiply-adds there and the results differ) gave the same results but was
// no faster on an AMD EPYC with AVX-512: the loop's time goes to its eight
// or so divisions a case, and wider vectors divide no more numbers a cycle.
template <bool kTwist>
[[gnu::always_inline]] inline void outcomes_body(
    std::size_t n, const double* __restrict M, const double* __restrict c,
    const double* __restrict I, const double* __restrict hand_x, const double* __restrict hand_m,
    const double* __restrict Me, const double* __restrict ball_m, const double* __restrict ball_v,
    const double* __restrict cor, const double* __restrict T, const double* __restrict x,
    const double* __restrict twist, double* __restrict m_eff, double* __restrict e_A,
    double* __restrict J, double* __restrict F0, double* __restrict cop, double* __restrict ratio,
    double* __restrict F_w) {
  for (std::size_t i = 0; i < n; ++i) {
    const kernel::System held = kernel::with_point_mass(M[i], c[i], I[i], hand_x[i], hand_m[i]);
    const RigidOutcome o =
        kernel::rigid_outcome<kTwist>(M[i], c[i], I[i], held, x[i], kTwist ? twist[i] : 0.0, Me[i],
                                      ball_m[i], ball_v[i], cor[i], T[i]);
    m_eff[i] = o.effective_mass_kg;
    e_A[i] = o.apparent_cor;
    J[i] = o.impulse_N_s;
    F0[i] = o.peak_impact_force_N;
    cop[i] = o.cop_hand_from_butt_m;
    ratio[i] = o.wrist_force_ratio;
    F_w[i] = o.peak_wrist_force_N;
  }
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define SWEETSPOT_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define SWEETSPOT_AVX2_CLONE
#endif

SWEETSPOT_AVX2_CLONE
void outcomes_loop(std::size_t n, const double* __restrict M, const double* __restrict c,
                   const double* __restrict I, const double* __restrict hand_x,
                   const double* __restrict hand_m, const double* __restrict Me,
                   const double* __restrict ball_m, const double* __restrict ball_v,
                   const double* __restrict cor, const double* __restrict T,
                   const double* __restrict x, const double* __restrict twist,
                   double* __restrict m_eff, double* __restrict e_A, double* __restrict J,
                   double* __restrict F0, double* __restrict cop, double* __restrict ratio,
                   double* __restrict F_w) {
  outcomes_body<true>(n, M, c, I, hand_x, hand_m, Me, ball_m, ball_v, cor, T, x, twist, m_eff, e_A,
                      J, F0, cop, ratio, F_w);
}

// The same for cases all on the long axis (no twist given).
SWEETSPOT_AVX2_CLONE
void outcomes_loop_on_axis(std::size_t n, const double* __restrict M, const double* __restrict c,
                           const double* __restrict I, const double* __restrict hand_x,
                           const double* __restrict hand_m, const double* __restrict Me,
                           const double* __restrict ball_m, const double* __restrict ball_v,
                           const double* __restrict cor, const double* __restrict T,
                           const double* __restrict x, double* __restrict m_eff,
                           double* __restrict e_A, double* __restrict J, double* __restrict F0,
                           double* __restrict cop, double* __restrict ratio,
                           double* __restrict F_w) {
  outcomes_body<false>(n, M, c, I, hand_x, hand_m, Me, ball_m, ball_v, cor, T, x, nullptr, m_eff,
                       e_A, J, F0, cop, ratio, F_w);
}

#undef SWEETSPOT_AVX2_CLONE

}  // namespace

void rigid_outcomes(const RigidCases& in, const RigidOutcomes& out) {
  const std::size_t n = in.body_mass_kg.size();
  const auto check = [n](std::size_t size, const char* name) {
    if (size != n) {
      throw std::invalid_argument(std::string("rigid_outcomes: ") + name + " has " +
                                  std::to_string(size) + " elements, body_mass_kg " +
                                  std::to_string(n));
    }
  };
  check(in.body_com_from_butt_m.size(), "body_com_from_butt_m");
  check(in.body_I_cm_kg_m2.size(), "body_I_cm_kg_m2");
  check(in.hand_from_butt_m.size(), "hand_from_butt_m");
  check(in.hand_mass_kg.size(), "hand_mass_kg");
  check(in.forearm_equivalent_mass_kg.size(), "forearm_equivalent_mass_kg");
  check(in.ball_mass_kg.size(), "ball_mass_kg");
  check(in.ball_speed_m_s.size(), "ball_speed_m_s");
  check(in.cor.size(), "cor");
  check(in.impact_duration_s.size(), "impact_duration_s");
  check(in.impact_from_butt_m.size(), "impact_from_butt_m");
  if (!in.impact_twist_per_kg.empty()) check(in.impact_twist_per_kg.size(), "impact_twist_per_kg");
  check(out.effective_mass_kg.size(), "effective_mass_kg");
  check(out.apparent_cor.size(), "apparent_cor");
  check(out.impulse_N_s.size(), "impulse_N_s");
  check(out.peak_impact_force_N.size(), "peak_impact_force_N");
  check(out.cop_hand_from_butt_m.size(), "cop_hand_from_butt_m");
  check(out.wrist_force_ratio.size(), "wrist_force_ratio");
  check(out.peak_wrist_force_N.size(), "peak_wrist_force_N");
  if (!in.impact_twist_per_kg.empty()) {
    outcomes_loop(n, in.body_mass_kg.data(), in.body_com_from_butt_m.data(),
                  in.body_I_cm_kg_m2.data(), in.hand_from_butt_m.data(), in.hand_mass_kg.data(),
                  in.forearm_equivalent_mass_kg.data(), in.ball_mass_kg.data(),
                  in.ball_speed_m_s.data(), in.cor.data(), in.impact_duration_s.data(),
                  in.impact_from_butt_m.data(), in.impact_twist_per_kg.data(),
                  out.effective_mass_kg.data(), out.apparent_cor.data(), out.impulse_N_s.data(),
                  out.peak_impact_force_N.data(), out.cop_hand_from_butt_m.data(),
                  out.wrist_force_ratio.data(), out.peak_wrist_force_N.data());
    return;
  }
  outcomes_loop_on_axis(
      n, in.body_mass_kg.data(), in.body_com_from_butt_m.data(), in.body_I_cm_kg_m2.data(),
      in.hand_from_butt_m.data(), in.hand_mass_kg.data(), in.forearm_equivalent_mass_kg.data(),
      in.ball_mass_kg.data(), in.ball_speed_m_s.data(), in.cor.data(), in.impact_duration_s.data(),
      in.impact_from_butt_m.data(), out.effective_mass_kg.data(), out.apparent_cor.data(),
      out.impulse_N_s.data(), out.peak_impact_force_N.data(), out.cop_hand_from_butt_m.data(),
      out.wrist_force_ratio.data(), out.peak_wrist_force_N.data());
}

void rigid_outcomes(std::span<const RigidCase> cases, std::span<RigidOutcome> out) {
  if (cases.size() != out.size()) {
    throw FieldError("rigid_outcomes", "" + std::to_string(cases.size()) + " cases but room for " +
                                           std::to_string(out.size()) + " outcomes");
  }
  // A block at a time laid out as arrays (19 kB on the stack), then back.
  constexpr std::size_t kBlock = 128;
  constexpr std::size_t kIn = 12, kOut = 7;
  double a[kIn][kBlock];
  double b[kOut][kBlock];
  for (std::size_t begin = 0; begin < cases.size(); begin += kBlock) {
    const std::size_t n = std::min(kBlock, cases.size() - begin);
    for (std::size_t i = 0; i < n; ++i) {
      const RigidCase& c = cases[begin + i];
      a[0][i] = c.body.mass_kg;
      a[1][i] = c.body.com_from_butt_m;
      a[2][i] = c.body.I_cm_kg_m2;
      a[3][i] = c.hand.from_butt_m;
      a[4][i] = c.hand.mass_kg;
      a[5][i] = c.forearm_equivalent_mass_kg;
      a[6][i] = c.ball_mass_kg;
      a[7][i] = c.ball_speed_m_s;
      a[8][i] = c.cor;
      a[9][i] = c.impact_duration_s;
      a[10][i] = c.impact_from_butt_m;
      a[11][i] = c.impact_twist_per_kg;
    }
    outcomes_loop(n, a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10], a[11], b[0],
                  b[1], b[2], b[3], b[4], b[5], b[6]);
    for (std::size_t i = 0; i < n; ++i) {
      out[begin + i] = RigidOutcome{b[0][i], b[1][i], b[2][i], b[3][i], b[4][i], b[5][i], b[6][i]};
    }
  }
}

}  // namespace sweetspot
