#include "sweetspot/kernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "core/kernels_detail.hpp"
#include "core/rigid_kernel.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/invariants.hpp"

namespace sweetspot {

bool all_finite(double mass_kg, double I_cm_kg_m2, double swingweight_kg_m2,
                double effective_mass_kg, double apparent_cor, double impulse_N_s,
                double peak_impact_force_N, double system_I_cm_kg_m2, double wrist_force_ratio,
                double peak_wrist_force_N) {
  bool finite = true;
  for (const double value :
       {mass_kg, I_cm_kg_m2, swingweight_kg_m2, effective_mass_kg, apparent_cor, impulse_N_s,
        peak_impact_force_N, system_I_cm_kg_m2, wrist_force_ratio, peak_wrist_force_N}) {
    finite = finite && std::isfinite(value);
  }
  return finite;
}

// The impact duration: given, or derived from the string tension. The
// duration depends on M_eff only (Eq. 17), not on the COR.
double settled_duration(const Design& design) {
  if (!design.strings) return design.impact_duration_s;
  const double duration_s =
      tension_impact_duration(
          *design.strings, design.ball.mass_kg,
          effective_mass(design.implement.mass_properties(), design.impact_from_butt_m,
                         design.impact_off_axis_m, polar_inertia_kg_m2(design).value_or(0.0)))
          .duration_s;
  // Out of range, the tension is to blame: the duration is not the user's.
  if (!(duration_s >= kMinDuration_s && duration_s <= kMaxDuration_s)) {
    throw FieldError("strings/tension_N", "" + detail::format_number(design.strings->tension_N) +
                                              " N gives an impact duration of " +
                                              detail::format_number(duration_s) + " s, outside [" +
                                              detail::format_number(kMinDuration_s) + ", " +
                                              detail::format_number(kMaxDuration_s) + "] s");
  }
  return duration_s;
}

void put_string_bed(const Design& design, Evaluation& e) {
  if (!design.strings) return;
  e.string_bed_tension_N = design.strings->tension_N;
  e.string_bed_stiffness_N_m = string_bed_stiffness(*design.strings);
  e.string_bed_ring_Hz = string_bed_ring_frequency(*design.strings);
}

namespace {

// The parts of the rigid evaluation that do not depend on the impact point.
Evaluation design_part(const Design& d, const MassProperties& body, const MassProperties& system) {
  Evaluation e;
  e.cor = d.cor;
  e.impact_duration_s = d.impact_duration_s;
  e.length_m = d.implement.length_m();
  e.mass_kg = body.mass_kg;
  e.balance_from_butt_m = body.com_from_butt_m;
  e.I_cm_kg_m2 = body.I_cm_kg_m2;
  e.swingweight_kg_m2 = swingweight_kg_m2(body);
  e.cop_free_from_butt_m = free_conjugate_from_butt(body, 0.0);
  e.system_mass_kg = system.mass_kg;
  e.system_com_from_butt_m = system.com_from_butt_m;
  e.system_I_cm_kg_m2 = system.I_cm_kg_m2;
  e.cop_hand_from_butt_m = hand_held_cop_from_butt(system);
  e.polar_inertia_kg_m2 = polar_inertia_kg_m2(d);
  e.polar_inertia_estimated = polar_inertia_estimated(d);
  return e;
}

// The design's numbers as the rigid model reads them, unchecked.
RigidCase case_of(const Design& d, double impact_duration_s, double twist_per_kg) {
  return RigidCase{d.implement.mass_properties(),
                   PointMass{d.hand.center_from_butt_m, d.hand.mass_kg},
                   d.forearm_equivalent_mass_kg,
                   d.ball.mass_kg,
                   d.ball.speed_m_s,
                   d.cor,
                   impact_duration_s,
                   d.impact_from_butt_m,
                   twist_per_kg};
}

// y^2 / I_polar for an impact y off the axis; names the input when the polar
// inertia is unknown.
double twist_per_kg(const std::optional<double>& polar_inertia_kg_m2, double off_axis_m) {
  if (off_axis_m != 0.0 && !polar_inertia_kg_m2) {
    throw FieldError("impact/off_axis_m",
                     "an impact off the long axis needs the polar inertia "
                     "(implement/twistweight_kg_cm2 or implement/headsize_sq_in), got " +
                         detail::format_number(off_axis_m) + " m");
  }
  return impact_twist_per_kg(off_axis_m, polar_inertia_kg_m2.value_or(0.0));
}

// What rigid_outcome() gives: Eqs. (11), (15)-(17) and the rebound speed.
void outcome_part(const Design& d, const RigidOutcome& o, Evaluation& e) {
  e.effective_mass_kg = o.effective_mass_kg;
  e.apparent_cor = o.apparent_cor;
  e.rebound_speed_m_s = o.apparent_cor * d.ball.speed_m_s;
  e.impulse_N_s = o.impulse_N_s;
  e.peak_impact_force_N = o.peak_impact_force_N;
  e.wrist_force_ratio = o.wrist_force_ratio;
  e.peak_wrist_force_N = o.peak_wrist_force_N;
}

// The parts that do: Eqs. (5), (11), (12), (15)-(17) at x: rigid_outcome()
// and the rotation axes.
void impact_part(const Design& d, const MassProperties& body, const MassProperties& system,
                 double x, double y, Evaluation& e) {
  RigidCase c = case_of(d, d.impact_duration_s, twist_per_kg(e.polar_inertia_kg_m2, y));
  c.impact_from_butt_m = x;
  const RigidOutcome o = rigid_outcome(c, system);
  e.impact_from_butt_m = x;
  e.impact_from_com_m = x - body.com_from_butt_m;
  e.rotation_axis_free_from_butt_m = free_conjugate_from_butt(body, x);
  outcome_part(d, o, e);
  e.rotation_axis_hand_from_butt_m =
      hand_held_rotation_axis_from_butt(system, d.forearm_equivalent_mass_kg, x);
  e.impact_off_axis_m = y;
  if (y != 0.0) {
    e.twist_rate_rad_s = o.impulse_N_s * y / *e.polar_inertia_kg_m2;
    e.peak_twist_torque_N_m = o.peak_impact_force_N * std::abs(y);
  } else {
    e.twist_rate_rad_s = 0.0;
    e.peak_twist_torque_N_m = 0.0;
  }
}

}  // namespace

Evaluation evaluate_unchecked(const Design& d) {
  const MassProperties& body = d.implement.mass_properties();
  const MassProperties system = hand_held_system(d);
  Evaluation e = design_part(d, body, system);
  impact_part(d, body, system, d.impact_from_butt_m, d.impact_off_axis_m, e);
  return e;
}

bool evaluate_rigid_outcome(const Design& d, Evaluation& e) {
  if (d.cor_rigid || d.strings || d.swing || d.impact_off_axis_m != 0.0 || is_rig(d.support))
    return false;
  const MassProperties& body = d.implement.mass_properties();
  const MassProperties system = hand_held_system(d);
  // The case impact_part() builds: on the axis, the twist is 0 whatever the polar inertia.
  const RigidOutcome o = rigid_outcome(case_of(d, d.impact_duration_s, 0.0), system);
  if (!all_finite(body.mass_kg, body.I_cm_kg_m2, swingweight_kg_m2(body), o.effective_mass_kg,
                  o.apparent_cor, o.impulse_N_s, o.peak_impact_force_N, system.I_cm_kg_m2,
                  o.wrist_force_ratio, o.peak_wrist_force_N)) {
    return false;
  }
  outcome_part(d, o, e);
  return true;
}

RigidCase rigid_case(const Design& design) {
  require_player(design, "the rigid model");
  if (design.cor_rigid) {
    throw FieldError("frame/cor_rigid",
                     "a COR derived from the frame's vibration needs the response model, not a "
                     "rigid case");
  }
  validate(design);
  return case_of(design, settled_duration(design),
                 twist_per_kg(polar_inertia_kg_m2(design), design.impact_off_axis_m));
}

bool impact_sweep_answers(const Design& design) {
  return !design.cor_rigid && !design.strings && !design.swing;
}

ImpactSweep::ImpactSweep(const Design& design)
    : design_(design), system_(hand_held_system(design)) {
  require_player(design, "the rigid model at many impacts");
  if (!impact_sweep_answers(design)) {
    throw FieldError(design.swing ? "swing" : "frame/cor_rigid",
                     "ImpactSweep evaluates the rigid model at rest with a given COR and "
                     "duration");
  }
  validate(design_);
  base_ = design_part(design_, design_.implement.mass_properties(), system_);
}

Evaluation ImpactSweep::at(double impact_from_butt_m) const {
  return at(impact_from_butt_m, design_.impact_off_axis_m);
}

Evaluation ImpactSweep::at(double impact_from_butt_m, double off_axis_m) const {
  Evaluation e = base_;
  impact_part(design_, design_.implement.mass_properties(), system_, impact_from_butt_m, off_axis_m,
              e);
  check_invariants(e, design_);
  put_assumed_shot(design_, e);
  return e;
}

void put_assumed_shot(const Design& design, Evaluation& e) {
  e.incoming_speed_m_s = design.ball.speed_m_s;
  e.racquet_speed_m_s = racquet_speed_m_s(e.swing, e.impact_from_butt_m);
  e.shot_speed_m_s = shot_speed_m_s(e.apparent_cor, e.incoming_speed_m_s, e.racquet_speed_m_s);
}

}  // namespace sweetspot

namespace sweetspot {
namespace {

// value in [min, max], false for NaN: the test of detail::require_in_range.
// The tests below combine with & rather than &&, so that the loops over a
// block have no branches and are vectorised.
inline bool within(double value, double min, double max) { return (value >= min) & (value <= max); }

inline bool finite(double value) { return std::abs(value) <= std::numeric_limits<double>::max(); }

// The rigid model's laws (the tests broken_invariant() in invariants.cpp
// makes of a rigid evaluation), each multiplied through by its positive
// denominator and with half the tolerance, so that a case passing here passes
// there whatever the rounding of the division it leaves out.
inline bool keeps_laws(double m, double v1, double cor, double M_eff, double e_A, double J,
                       double F0, double T) {
  const double ball_in = 0.5 * m * v1 * v1;
  const double half_tol_J = 0.5 * kInvariantRoundOff * ball_in;
  const double rebound = e_A * v1;
  const double ball_out = 0.5 * m * rebound * rebound;
  return (M_eff > 0.0) & (e_A * (M_eff + m) >= -m - 0.5 * kInvariantRoundOff * (M_eff + m)) &
         (e_A <= cor + 0.5 * kInvariantRoundOff) & (J > 0.0) & (T > 0.0) & (F0 > 0.0) &
         (ball_out <= ball_in + half_tol_J) &
         (0.5 * J * J <= (ball_in - ball_out + half_tol_J) * M_eff);
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define SWEETSPOT_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define SWEETSPOT_AVX2_CLONE
#endif

// A case's inputs: the racquet's (length, mass, ratio) and the impact point
// one per case; the settings (hand, forearm, ball, COR, duration) one per
// case or, kUniform, one for every case (element 0).
struct CaseInputs {
  const double *L, *M, *r, *x;
  const double *hand_m, *hand_x, *Me, *ball_m, *ball_v, *cor, *T;
};
struct CaseOutputs {
  double *m_eff, *e_A, *J, *F0, *cop, *ratio, *F_w;
};

// The settings inside validate()'s ranges (the hand's place, which depends on
// the length, is each case's own).
inline bool settings_in_range(double hand_m, double Me, double ball_m, double ball_v, double cor,
                              double T) {
  return within(hand_m, 0.0, kMaxMass_kg) & within(Me, 0.0, kMaxForearmMass_kg) &
         within(ball_m, kMinBallMass_kg, kMaxMass_kg) &
         within(ball_v, kMinSpeed_m_s, kMaxSpeed_m_s) & within(cor, 0.0, 1.0) &
         within(T, kMinDuration_s, kMaxDuration_s);
}

// n cases with settings for every case, each as evaluate() computes it: the body
// (kernel::paper_racquet_body(), kept for the checks), the hand-held system,
// and Eqs. (11), (13), (15)-(17) in rigid_outcome()'s order. Its selections
// are if-converted (this file is compiled without trapping math, which lets a
// division be computed on the side not taken; the values are IEEE's either
// way) and the loop vectorised.
[[gnu::always_inline]] inline void cases_body(
    std::size_t n, const double* __restrict L, const double* __restrict M,
    const double* __restrict r, const double* __restrict x, double hand_m, double hand_x, double Me,
    double ball_m, double ball_v, double cor, double T, double* __restrict m_eff,
    double* __restrict e_A, double* __restrict J, double* __restrict F0, double* __restrict cop,
    double* __restrict ratio, double* __restrict F_w, double* __restrict mass,
    double* __restrict com, double* __restrict inertia) {
  for (std::size_t i = 0; i < n; ++i) {
    const kernel::System body = kernel::paper_racquet_body(L[i], M[i], r[i]);
    const kernel::System held = kernel::with_point_mass(body.mass_kg, body.com_from_butt_m,
                                                        body.I_cm_kg_m2, hand_x, hand_m);
    const RigidOutcome o =
        kernel::rigid_outcome<false>(body.mass_kg, body.com_from_butt_m, body.I_cm_kg_m2, held,
                                     x[i], 0.0, Me, ball_m, ball_v, cor, T);
    m_eff[i] = o.effective_mass_kg;
    e_A[i] = o.apparent_cor;
    J[i] = o.impulse_N_s;
    F0[i] = o.peak_impact_force_N;
    cop[i] = o.cop_hand_from_butt_m;
    ratio[i] = o.wrist_force_ratio;
    F_w[i] = o.peak_wrist_force_N;
    mass[i] = body.mass_kg;
    com[i] = body.com_from_butt_m;
    inertia[i] = body.I_cm_kg_m2;
  }
}

// 1 where case i is one evaluate() answers with these numbers (see
// paper_rigid_outcomes()), 0 where it leaves it to evaluate(). Uniform
// settings are checked once by the caller, not here.
template <bool kUniform>
[[gnu::always_inline]] inline void answerable_body(std::size_t n, CaseInputs in,
                                                   const double* __restrict mass,
                                                   const double* __restrict com,
                                                   const double* __restrict inertia,
                                                   CaseOutputs out, std::uint32_t* __restrict ok) {
  for (std::size_t i = 0; i < n; ++i) {
    const double L = in.L[i];
    const double ball_m = (kUniform ? in.ball_m[0] : in.ball_m[i]);
    const double ball_v = (kUniform ? in.ball_v[0] : in.ball_v[i]);
    const double cor = (kUniform ? in.cor[0] : in.cor[i]);
    const double T = (kUniform ? in.T[0] : in.T[i]);
    // Inside validate()'s ranges and paper_racquet()'s, with margins where a
    // bound is on a derived number (an inertia that must not underflow).
    const bool settings =
        kUniform || settings_in_range(in.hand_m[i], in.Me[i], ball_m, ball_v, cor, T);
    const bool inputs =
        within(L, 1e-3, kMaxLength_m) & within(in.M[i], kMinImplementMass_kg, kMaxMass_kg) &
        within(in.r[i], 1e-6, 1e6) & within(mass[i], kMinImplementMass_kg, kMaxMass_kg) &
        within((kUniform ? in.hand_x[0] : in.hand_x[i]), 0.0, L) & within(in.x[i], 0.0, L);
    // evaluate_settled_valid()'s finite results (the system's inertia through
    // the centre of percussion, which divides by it), the inertia a normal
    // number as section_mass_properties() requires.
    const double arm = kSwingweightAxisFromButt_m - com[i];
    const double swingweight = inertia[i] + mass[i] * arm * arm;  // inertia_about()
    const bool results = finite(mass[i]) & finite(swingweight) & finite(out.m_eff[i]) &
                         finite(out.e_A[i]) & finite(out.J[i]) & finite(out.F0[i]) &
                         finite(out.cop[i]) & finite(out.ratio[i]) & finite(out.F_w[i]) &
                         (inertia[i] >= std::numeric_limits<double>::min()) & finite(inertia[i]);
    ok[i] = settings & inputs & results &
            keeps_laws(ball_m, ball_v, cor, out.m_eff[i], out.e_A[i], out.J[i], out.F0[i], T);
  }
}

// The bodies of n paper racquets (kernel::paper_racquet_body()).
SWEETSPOT_AVX2_CLONE
void paper_bodies(std::size_t n, const double* __restrict L, const double* __restrict M,
                  const double* __restrict r, double* __restrict mass, double* __restrict com,
                  double* __restrict inertia) {
  for (std::size_t i = 0; i < n; ++i) {
    const kernel::System body = kernel::paper_racquet_body(L[i], M[i], r[i]);
    mass[i] = body.mass_kg;
    com[i] = body.com_from_butt_m;
    inertia[i] = body.I_cm_kg_m2;
  }
}

// cases_body() with a setting per case, in two loops (GCC vectorises each, not their fusion):
// the bodies, then rigid_outcomes().
void cases_each(std::size_t n, CaseInputs in, CaseOutputs out, double* __restrict mass,
                double* __restrict com, double* __restrict inertia) {
  paper_bodies(n, in.L, in.M, in.r, mass, com, inertia);
  const auto span = [n](const double* values) { return std::span<const double>(values, n); };
  const auto into = [n](double* values) { return std::span<double>(values, n); };
  rigid_outcomes(RigidCases{span(mass), span(com), span(inertia), span(in.hand_x), span(in.hand_m),
                            span(in.Me), span(in.ball_m), span(in.ball_v), span(in.cor), span(in.T),
                            span(in.x)},
                 RigidOutcomes{into(out.m_eff), into(out.e_A), into(out.J), into(out.F0),
                               into(out.cop), into(out.ratio), into(out.F_w)});
}
SWEETSPOT_AVX2_CLONE
void cases_uniform(std::size_t n, CaseInputs in, CaseOutputs out, double* __restrict mass,
                   double* __restrict com, double* __restrict inertia) {
  cases_body(n, in.L, in.M, in.r, in.x, in.hand_m[0], in.hand_x[0], in.Me[0], in.ball_m[0],
             in.ball_v[0], in.cor[0], in.T[0], out.m_eff, out.e_A, out.J, out.F0, out.cop,
             out.ratio, out.F_w, mass, com, inertia);
}
SWEETSPOT_AVX2_CLONE
void answerable_each(std::size_t n, CaseInputs in, const double* __restrict mass,
                     const double* __restrict com, const double* __restrict inertia,
                     CaseOutputs out, std::uint32_t* __restrict ok) {
  answerable_body<false>(n, in, mass, com, inertia, out, ok);
}
SWEETSPOT_AVX2_CLONE
void answerable_uniform(std::size_t n, CaseInputs in, const double* __restrict mass,
                        const double* __restrict com, const double* __restrict inertia,
                        CaseOutputs out, std::uint32_t* __restrict ok) {
  answerable_body<true>(n, in, mass, com, inertia, out, ok);
}

#undef SWEETSPOT_AVX2_CLONE

}  // namespace

void paper_rigid_outcomes(const PaperRigidCases& in, const RigidOutcomes& out,
                          std::span<unsigned char> answered) {
  const std::size_t n = in.length_m.size();
  const auto check = [n](std::size_t size, const char* name) {
    if (size != n) {
      throw std::invalid_argument(std::string("paper_rigid_outcomes: ") + name + " has " +
                                  std::to_string(size) + " elements, length_m " +
                                  std::to_string(n));
    }
  };
  const std::span<const double> settings[] = {
      in.hand_mass_kg,     in.hand_center_from_butt_m, in.forearm_equivalent_mass_kg,
      in.ball_mass_kg,     in.ball_speed_m_s,          in.cor,
      in.impact_duration_s};
  const bool uniform = std::all_of(std::begin(settings), std::end(settings),
                                   [](std::span<const double> s) { return s.size() == 1; });
  const auto check_setting = [&](std::span<const double> s, const char* name) {
    if (s.size() != n && s.size() != 1) {
      throw std::invalid_argument(std::string("paper_rigid_outcomes: ") + name + " has " +
                                  std::to_string(s.size()) +
                                  " elements, expected 1 or length_m's " + std::to_string(n));
    }
  };
  check(in.mass_kg.size(), "mass_kg");
  check(in.head_to_handle_mass_ratio.size(), "head_to_handle_mass_ratio");
  check_setting(in.hand_mass_kg, "hand_mass_kg");
  check_setting(in.hand_center_from_butt_m, "hand_center_from_butt_m");
  check_setting(in.forearm_equivalent_mass_kg, "forearm_equivalent_mass_kg");
  check_setting(in.ball_mass_kg, "ball_mass_kg");
  check_setting(in.ball_speed_m_s, "ball_speed_m_s");
  check_setting(in.cor, "cor");
  check_setting(in.impact_duration_s, "impact_duration_s");
  check(in.impact_from_butt_m.size(), "impact_from_butt_m");
  check(out.effective_mass_kg.size(), "effective_mass_kg");
  check(out.apparent_cor.size(), "apparent_cor");
  check(out.impulse_N_s.size(), "impulse_N_s");
  check(out.peak_impact_force_N.size(), "peak_impact_force_N");
  check(out.cop_hand_from_butt_m.size(), "cop_hand_from_butt_m");
  check(out.wrist_force_ratio.size(), "wrist_force_ratio");
  check(out.peak_wrist_force_N.size(), "peak_wrist_force_N");
  check(answered.size(), "answered");
  if (uniform &&
      !settings_in_range(in.hand_mass_kg[0], in.forearm_equivalent_mass_kg[0], in.ball_mass_kg[0],
                         in.ball_speed_m_s[0], in.cor[0], in.impact_duration_s[0])) {
    std::fill(answered.begin(), answered.end(), static_cast<unsigned char>(0));
    return;
  }
  // A block at a time: the cases' outcomes and bodies, then the checks. A
  // setting given once where others are given per case is spread over the block.
  constexpr std::size_t kBlock = 256;
  double mass[kBlock], com[kBlock], inertia[kBlock];
  double spread[std::size(settings)][kBlock];
  std::uint32_t ok[kBlock];
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t count = std::min(kBlock, n - begin);
    const double* each[std::size(settings)];
    for (std::size_t k = 0; k < std::size(settings); ++k) {
      if (uniform) {
        each[k] = settings[k].data();
      } else if (settings[k].size() == 1) {
        std::fill(spread[k], spread[k] + count, settings[k][0]);
        each[k] = spread[k];
      } else {
        each[k] = settings[k].data() + begin;
      }
    }
    const CaseInputs c{in.length_m.data() + begin,
                       in.mass_kg.data() + begin,
                       in.head_to_handle_mass_ratio.data() + begin,
                       in.impact_from_butt_m.data() + begin,
                       each[0],
                       each[1],
                       each[2],
                       each[3],
                       each[4],
                       each[5],
                       each[6]};
    const CaseOutputs o{
        out.effective_mass_kg.data() + begin,    out.apparent_cor.data() + begin,
        out.impulse_N_s.data() + begin,          out.peak_impact_force_N.data() + begin,
        out.cop_hand_from_butt_m.data() + begin, out.wrist_force_ratio.data() + begin,
        out.peak_wrist_force_N.data() + begin};
    if (uniform) {
      cases_uniform(count, c, o, mass, com, inertia);
      answerable_uniform(count, c, mass, com, inertia, o, ok);
    } else {
      cases_each(count, c, o, mass, com, inertia);
      answerable_each(count, c, mass, com, inertia, o, ok);
    }
    for (std::size_t i = 0; i < count; ++i) answered[begin + i] = static_cast<unsigned char>(ok[i]);
  }
}

}  // namespace sweetspot
