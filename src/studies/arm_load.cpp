#include "studies/arm_load.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "io/input_error.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::studies {
namespace {

// ISO 5349-1 (2001) Table A.1, W_h.
constexpr double kHighPass_Hz = 6.310;
constexpr double kLowPass_Hz = 1258.9;
constexpr double kTransition_Hz = 15.915;  // f3 = f4
constexpr double kTransitionQ = 0.64;      // Q4

std::string refusal_text(const std::exception& refusal) {
  std::string why = refusal.what();
  if (const auto colon = why.find(": "); colon != std::string::npos) why = why.substr(colon + 2);
  return why;
}

}  // namespace

double iso5349_weighting(double frequency_Hz) {
  if (!(frequency_Hz > 0.0) || !std::isfinite(frequency_Hz)) {
    throw std::invalid_argument("frequency_Hz: must be a finite frequency > 0 Hz, got " +
                                std::to_string(frequency_Hz));
  }
  const double f = frequency_Hz;
  const double high_pass = 1.0 / std::sqrt(1.0 + std::pow(kHighPass_Hz / f, 4));
  const double low_pass = 1.0 / std::sqrt(1.0 + std::pow(f / kLowPass_Hz, 4));
  const double x3 = f / kTransition_Hz;
  const double x4 = f / kTransition_Hz;
  const double transition = std::sqrt(1.0 + x3 * x3) /
                            std::sqrt(std::pow(1.0 - x4 * x4, 2) + std::pow(x4 / kTransitionQ, 2));
  return high_pass * low_pass * transition;
}

HandVibration hand_vibration(const ResponseModel& model, double hand_from_butt_m,
                             const Evaluation& evaluation) {
  const HalfSinePulse pulse =
      half_sine_with_impulse(evaluation.impulse_N_s, evaluation.impact_duration_s);
  const ImpactResponse response =
      impact_response(model, evaluation.impact_from_butt_m, pulse, {hand_from_butt_m}, {});
  HandVibration out;
  double velocity2 = 0.0, weighted2 = 0.0, largest = -1.0;
  for (std::size_t k = 0; k < model.modes.size(); ++k) {
    const double at_hand = std::fabs(mass_normalised_shape(model.modes[k], hand_from_butt_m));
    const double velocity = at_hand * std::sqrt(2.0 * response.modes[k].energy_after_J);
    const double frequency = response.modes[k].frequency_Hz;
    const double weighted =
        iso5349_weighting(frequency) * 2.0 * std::numbers::pi * frequency * velocity;
    velocity2 += velocity * velocity;
    weighted2 += weighted * weighted;
    if (weighted > largest) largest = weighted, out.frequency_Hz = frequency;
  }
  out.velocity_m_s = std::sqrt(velocity2);
  out.weighted_acceleration_m_s2 = std::sqrt(weighted2);
  return out;
}

FreeFrame free_frame_of(const io::DesignFile& design, const Evaluation& asked) {
  FreeFrame frame;
  if (!has_stiffness(design.design)) {
    frame.why = "no frame stiffness given (frame.RA, frame.fundamental_free_Hz or frame.EI_N_m2)";
    return frame;
  }
  if (fidelity_of(asked) == Fidelity::kRigid) {
    frame.why = "the rigid model has no vibration";
    return frame;
  }
  try {
    frame.model = response_model(design.design, {});
  } catch (const std::invalid_argument& refusal) {
    frame.why = "the frame's modes are not known: " + refusal_text(refusal);
  }
  return frame;
}

ArmLoad arm_load(const io::DesignFile& design, const Evaluation& asked, double asked_from_tip_m,
                 const std::optional<double>& centre_of_strings_from_tip_m, const FreeFrame& frame,
                 double rel_tol) {
  ArmLoad load;
  load.around_centre_of_strings = centre_of_strings_from_tip_m.has_value();
  const double centre = centre_of_strings_from_tip_m.value_or(asked_from_tip_m);
  // Without a polar inertia (no twistweight, no head) a hit off the axis has
  // no answer: the three hits along it, and the twist not known.
  const bool twists = asked.polar_inertia_kg_m2.has_value();
  for (const double along : {-kArmSpreadStep_m, 0.0, kArmSpreadStep_m}) {
    if (!twists) {
      load.spread.push_back({centre + along, 0.0});
      continue;
    }
    for (const double across : {-kArmSpreadStep_m, 0.0, kArmSpreadStep_m})
      load.spread.push_back({centre + along, across});
  }

  const std::string_view fidelity = to_string(fidelity_of(asked));
  double wrist = 0.0, twist = 0.0, weighted = 0.0, velocity = 0.0;
  bool twist_known = twists;  // the polar inertia: a twistweight or a head
  std::string refused;
  std::vector<HandVibration> vibrations;
  for (const SpreadPoint& p : load.spread) {
    io::DesignFile moved = design;
    moved.design.impact_from_butt_m = design.design.implement.length_m() - p.from_tip_m;
    moved.design.impact_off_axis_m = p.off_axis_m;
    try {
      const Evaluation e = io::evaluate_design_file(moved, fidelity, rel_tol);
      wrist += e.peak_wrist_force_N;
      twist += e.peak_twist_torque_N_m;
      twist_known = twist_known && e.polar_inertia_kg_m2.has_value();
      if (frame.model) {
        const HandVibration v =
            hand_vibration(*frame.model, design.design.hand.center_from_butt_m, e);
        vibrations.push_back(v);
        weighted += v.weighted_acceleration_m_s2;
        velocity += v.velocity_m_s;
      }
    } catch (const std::exception& refusal) {  // io::InputError, or the response's complaint
      refused = fmt::format("{:.1f} cm from the tip, {:.1f} cm off the axis: {}",
                            p.from_tip_m * 100.0, p.off_axis_m * 100.0, refusal_text(refusal));
      break;
    }
  }
  const double n = static_cast<double>(load.spread.size());
  if (!refused.empty()) {
    const std::string why = "the model refuses a hit of the spread (" + refused + ")";
    for (ArmFactor* f :
         {&load.peak_wrist_force_N, &load.hand_weighted_acceleration_m_s2, &load.hand_velocity_m_s,
          &load.hand_frequency_Hz, &load.peak_twist_torque_N_m})
      f->unknown_why = why;
    return load;
  }
  load.peak_wrist_force_N.value = wrist / n;
  if (twist_known)
    load.peak_twist_torque_N_m.value = twist / n;
  else
    load.peak_twist_torque_N_m.unknown_why = "no twistweight or head size given";
  if (frame.model) {
    load.hand_weighted_acceleration_m_s2.value = weighted / n;
    load.hand_velocity_m_s.value = velocity / n;
    // The frequency of the hit that leaves the most weighted vibration.
    const HandVibration* most = &vibrations.front();
    for (const HandVibration& v : vibrations)
      if (v.weighted_acceleration_m_s2 > most->weighted_acceleration_m_s2) most = &v;
    load.hand_frequency_Hz.value = most->frequency_Hz;
  } else {
    for (ArmFactor* f :
         {&load.hand_weighted_acceleration_m_s2, &load.hand_velocity_m_s, &load.hand_frequency_Hz})
      f->unknown_why = frame.why;
  }
  return load;
}

}  // namespace sweetspot::studies
