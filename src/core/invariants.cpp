#include "sweetspot/invariants.hpp"

#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "core/check.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot {

ModelRefusal::ModelRefusal(std::string field, double value, std::string detail, std::string reason)
    : FieldError(std::move(field), detail),
      value_(value),
      reason_(reason.empty() ? std::move(detail) : std::move(reason)) {}

namespace {

std::string number(double value) { return detail::format_significant(value); }

// "NAME = VALUE is not finite", or empty.
std::string not_finite(const char* name, double value) {
  if (std::isfinite(value)) return {};
  return std::string(name) + " is " + detail::format_number(value);
}

// Every printed number of `e` finite.
std::string first_not_finite(const Evaluation& e) {
  const std::pair<const char*, double> values[] = {
      {"the mass", e.mass_kg},
      {"the recoil weight", e.I_cm_kg_m2},
      {"the swingweight", e.swingweight_kg_m2},
      // Infinite where a rig holds the impact point still (Evaluation::support).
      {"the effective mass",
       is_rig(e.support) && e.effective_mass_kg == INFINITY ? 0.0 : e.effective_mass_kg},
      {"the apparent COR", e.apparent_cor},
      {"the rebound speed", e.rebound_speed_m_s},
      {"the impulse", e.impulse_N_s},
      {"the peak force", e.peak_impact_force_N},
      {"the system's inertia", e.system_I_cm_kg_m2},
      {"the wrist force ratio", e.wrist_force_ratio},
      {"the peak wrist force", e.peak_wrist_force_N},
      {"the twist rate", e.twist_rate_rad_s},
      {"the twist torque", e.peak_twist_torque_N_m},
      {"the COR", e.cor},
      {"the contact time", e.impact_duration_s},
      {"the vibration energy", e.vibration_energy_J.value_or(0.0)},
      {"the vibration share", e.vibration_share.value_or(0.0)},
      {"the polar inertia", e.polar_inertia_kg_m2.value_or(0.0)},
  };
  for (const auto& [name, value] : values) {
    if (std::string why = not_finite(name, value); !why.empty()) return why;
  }
  if (e.modal) {
    if (!std::isfinite(e.modal->fundamental_free_Hz) ||
        !std::isfinite(e.modal->fundamental_hand_Hz))
      return "a fundamental frequency is not finite";
  }
  if (e.details) {
    for (const auto& [frequency, energy] : e.details->vibration_modes) {
      if (!std::isfinite(frequency) || !std::isfinite(energy))
        return "a mode's frequency or energy is not finite";
    }
  }
  return {};
}

}  // namespace

std::string broken_invariant(const CollisionResult& r, double m, double M_eff, double m_s) {
  const double tol = kInvariantRoundOff * r.ball_in_J;
  const std::pair<const char*, double> terms[] = {
      {"the ball-out energy", r.ball_out_J},
      {"the implement's rigid-body energy", r.implement_rigid_J},
      {"the vibration energy", r.vibration_J},
      {"the energy lost in the modes' damping", r.modal_damping_loss_J},
      {"the energy lost in the ball", r.ball_loss_J},
      {"the energy lost in the strings", r.strings_loss_J},
      {"the string bed's energy", r.string_bed_energy_J},
  };
  for (const auto& [name, value] : terms) {
    if (!std::isfinite(value)) return std::string(name) + " is " + detail::format_number(value);
    if (value < -tol) return std::string(name) + " is " + number(value) + " J, below 0";
  }
  for (std::size_t k = 0; k < r.mode_energy_J.size(); ++k) {
    if (!(r.mode_energy_J[k] >= -tol))
      return "mode " + std::to_string(k + 1) + " keeps " + number(r.mode_energy_J[k]) +
             " J, below 0";
  }
  const double residual = r.ball_in_J - (r.ball_out_J + r.implement_rigid_J + r.vibration_J +
                                         r.ball_loss_J + r.strings_loss_J);
  if (!(std::abs(residual) <= tol))
    return "the energy ledger does not close (" + number(residual) + " J of " +
           number(r.ball_in_J) + " J unaccounted)";
  if (!(r.ball_out_J <= r.ball_in_J + tol))
    return "the ball leaves with " + number(r.ball_out_J) + " J, more than the " +
           number(r.ball_in_J) + " J it brought";
  if (!(r.vibration_J <= r.ball_in_J + tol))
    return "the frame keeps " + number(r.vibration_J) + " J as vibration, more than the " +
           number(r.ball_in_J) + " J the ball brought";
  if (!(r.impulse_N_s > 0.0)) return "the impulse is " + number(r.impulse_N_s) + " N s, not > 0";
  if (!(r.contact_time_s > 0.0))
    return "the contact lasts " + number(r.contact_time_s) + " s, not > 0";
  // The rigid-body bounds (Cross 2004 Eq. 16 at e = 0 and at e = 1; the string
  // bed's mass moves with the frame, so the upper bound uses M_eff + m_s).
  // An immovable frame (M_eff infinite): -0 <= e_A <= 1.
  const double low = -m / (M_eff + m), M_up = M_eff + m_s;
  const double high = std::isinf(M_up) ? 1.0 : (M_up - m) / (M_up + m);
  if (!(r.apparent_cor >= low - kInvariantRoundOff))
    return "the apparent COR " + number(r.apparent_cor) + " is below " + number(low) +
           ", the ball stuck to the frame (Eq. 16 with e = 0)";
  if (!(r.apparent_cor <= high + kInvariantRoundOff))
    return "the apparent COR " + number(r.apparent_cor) + " is above " + number(high) +
           ", an elastic collision (Eq. 16 with e = 1)";
  return {};
}

std::string broken_invariant(const Evaluation& e, const Design& d) {
  if (std::string why = first_not_finite(e); !why.empty()) return why;
  const double m = d.ball.mass_kg, v1 = d.ball.speed_m_s;
  const double ball_in = 0.5 * m * v1 * v1;
  const double tol_J = kInvariantRoundOff * ball_in;
  const double M = e.effective_mass_kg;
  // Every fidelity: the COR, Eq. (16)'s bounds, the impulse, the contact.
  if (!(e.cor >= -kInvariantRoundOff && e.cor <= 1.0 + kInvariantRoundOff))
    return "the COR is " + number(e.cor) + ", outside [0, 1]";
  if (!(M > 0.0)) return "the effective mass is " + number(M) + " kg, not > 0";
  const double low = -m / (M + m);
  if (!(e.apparent_cor >= low - kInvariantRoundOff))
    return "the apparent COR " + number(e.apparent_cor) + " is below " + number(low) +
           ", the ball stuck to the frame (Eq. 16 with e = 0)";
  if (!(e.apparent_cor <= e.cor + kInvariantRoundOff))
    return "the apparent COR " + number(e.apparent_cor) + " is above the COR " + number(e.cor);
  if (!(e.impulse_N_s > 0.0)) return "the impulse is " + number(e.impulse_N_s) + " N s, not > 0";
  if (!(e.impact_duration_s > 0.0))
    return "the contact lasts " + number(e.impact_duration_s) + " s, not > 0";
  if (!(e.peak_impact_force_N > 0.0))
    return "the peak force is " + number(e.peak_impact_force_N) + " N, not > 0";
  const double ball_out = 0.5 * m * e.rebound_speed_m_s * e.rebound_speed_m_s;
  if (!(ball_out <= ball_in + tol_J))
    return "the ball leaves with " + number(ball_out) + " J, more than the " + number(ball_in) +
           " J it brought";
  // The rigid body's share: J^2 / (2 M_eff) out of what the ball lost.
  const double rigid = 0.5 * e.impulse_N_s * e.impulse_N_s / M;
  if (!(rigid <= ball_in - ball_out + tol_J))
    return "the implement gains " + number(rigid) + " J, more than the " +
           number(ball_in - ball_out) + " J the ball lost";
  if (e.vibration_energy_J) {
    const double vibration = *e.vibration_energy_J;
    if (!(vibration >= -tol_J))
      return "the vibration energy is " + number(vibration) + " J, below 0";
    // What the ball lost: the solved collision's own ledger, whose terms are
    // extrapolated together with the vibration's (its rebound speed is
    // extrapolated apart, and its square differs from the ledger's ball_out_J
    // by the step's error, which a lossless rig shows as 1e-7 of the energy).
    const CollisionResult* solved =
        e.details && e.details->collision ? &*e.details->collision : nullptr;
    const double lost = solved ? solved->ball_in_J - solved->ball_out_J : ball_in - ball_out;
    if (!(vibration <= lost + tol_J))
      return "the frame keeps " + number(vibration) + " J as vibration, more than the " +
             number(lost) + " J the ball lost";
    if (e.details) {
      for (std::size_t k = 0; k < e.details->vibration_modes.size(); ++k) {
        const double energy = e.details->vibration_modes[k].second;
        if (!(energy >= -tol_J))
          return "mode " + std::to_string(k + 1) + " keeps " + number(energy) + " J, below 0";
      }
    }
  }
  if (e.details && e.details->collision) {
    const double m_s = d.strings ? d.string_bed_mass_kg : 0.0;
    if (std::string why = broken_invariant(*e.details->collision, m, M, m_s); !why.empty())
      return why;
  }
  return {};
}

namespace {

// The calibrated racquet the solved collision was verified on
// (designs/racquets/tour-100-strung.json): its ball's speed, its bed's
// tension and its frame's free fundamental.
constexpr double kVerifiedSpeed_m_s = 50.0;
constexpr double kVerifiedTension_N = 250.0;
constexpr double kVerifiedFundamental_Hz = 155.0;

// A design input against the verified racquet's: `squeezes` +1 counts it only
// above its reference, -1 only below, 0 either way.
struct Candidate {
  const char* field;
  double value, reference;
  int squeezes = 0;
};

// The candidate furthest in ratio from its reference (in its direction); the
// first when none is away from it.
const Candidate& furthest(std::span<const Candidate> candidates) {
  const Candidate* worst = &candidates.front();
  double worst_distance = 0.0;
  for (const Candidate& c : candidates) {
    const double log_ratio = std::log(c.value / c.reference);
    const double distance = c.squeezes == 0 ? std::abs(log_ratio) : c.squeezes * log_ratio;
    if (distance > worst_distance) {
      worst_distance = distance;
      worst = &c;
    }
  }
  return *worst;
}

double tension_of(const Design& d) { return d.strings ? d.strings->tension_N : kVerifiedTension_N; }

}  // namespace

Suspect collision_suspect(const Design& d, double fundamental_free_Hz) {
  const char* frame_field = d.stiffness.RA                    ? "frame/RA"
                            : d.stiffness.fundamental_free_Hz ? "frame/fundamental_free_Hz"
                                                              : "frame/EI_N_m2";
  const Candidate candidates[] = {
      {"ball/contact/stiffness", d.ball_contact.stiffness, kTennisBallLaw.stiffness},
      // A ball deader (or livelier) than the calibrated one's; a dead one (0) first.
      {"ball/cor_on_rigid_surface", d.ball.cor_on_rigid_surface.value_or(kTennisBallDropTestCor),
       kTennisBallDropTestCor},
      {"strings/tension_N", tension_of(d), kVerifiedTension_N},
      {"strings/bed_mass_kg", d.string_bed_mass_kg, kStringBedMass_kg},
      {"ball/speed_m_s", d.ball.speed_m_s, kVerifiedSpeed_m_s},
      {"ball/mass_kg", d.ball.mass_kg, kTennisBallMass_kg},
      {frame_field, fundamental_free_Hz, kVerifiedFundamental_Hz},
  };
  const Candidate& worst = furthest(candidates);
  double value = worst.value;
  if (worst.field == frame_field) {
    value = d.stiffness.RA                    ? *d.stiffness.RA
            : d.stiffness.fundamental_free_Hz ? *d.stiffness.fundamental_free_Hz
                                              : d.stiffness.EI_N_m2.value_or(0.0);
  }
  return {worst.field, value};
}

Suspect squeeze_suspect(const Design& d) {
  const Candidate candidates[] = {
      {"ball/speed_m_s", d.ball.speed_m_s, kVerifiedSpeed_m_s, +1},
      {"ball/diameter_m", d.ball.diameter_m, kTennisBallDiameter_m, -1},
      {"ball/contact/stiffness", d.ball_contact.stiffness, kTennisBallLaw.stiffness, -1},
      {"ball/contact/exponent", d.ball_contact.exponent, kTennisBallLaw.exponent, +1},
      {"strings/tension_N", tension_of(d), kVerifiedTension_N, +1},
      {"ball/mass_kg", d.ball.mass_kg, kTennisBallMass_kg, +1}};
  const Candidate& worst = furthest(candidates);
  return {worst.field, worst.value};
}

void check_invariants(const Evaluation& e, const Design& design) {
  const std::string why = broken_invariant(e, design);
  if (why.empty()) [[likely]]
    return;
  const std::string model = "the " + std::string(to_string(fidelity_of(e))) +
                            " model cannot answer this design (" + why + ")";
  if (fidelity_of(e) != Fidelity::kCollision)
    throw ModelRefusal("implement", design.implement.length_m(), model);
  const Suspect blame = collision_suspect(design, e.modal ? e.modal->fundamental_free_Hz : 155.0);
  throw ModelRefusal(blame.field, blame.value,
                     model + "; " + detail::format_number(blame.value) +
                         " is the input furthest from the racquet it was verified on");
}

}  // namespace sweetspot
