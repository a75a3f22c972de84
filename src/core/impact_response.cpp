#include "sweetspot/impact_response.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "core/check.hpp"
#include "core/frame_solve.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/roots.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// Below this |z| the divided difference (e^z - 1)/z is summed as a series
// (the direct form loses digits to cancellation); 20 terms leave < 1e-25.
constexpr double kSeriesRadius = 0.5;
constexpr int kSeriesTerms = 20;
// Gauss-Legendre points per sub-interval, and the largest beta h per
// sub-interval, for the mass normalisation of exact shapes (error << 1e-14).
constexpr int kGaussPoints = 8;
constexpr double kMaxPhasePerInterval = 1.0;
// The resonance w T = pi of half_sine_spectrum_ratio is a removable
// singularity; within this relative distance the limit's Taylor form is used.
constexpr double kResonanceBand = 1e-6;
// e^x overflows beyond x = 709.78; divided_exp switches form below that.
constexpr double kMaxFactoredExponent = 700.0;

// (e^z - 1) / z, finite at z = 0.
Complex exp_divided(Complex z) {
  if (std::abs(z) < kSeriesRadius) {
    Complex term = 1.0, sum = 1.0;
    for (int n = 1; n <= kSeriesTerms; ++n) {
      term *= z / static_cast<double>(n + 1);
      sum += term;
    }
    return sum;
  }
  return (std::exp(z) - 1.0) / z;
}

// g(a, b; t) = (e^{a t} - e^{b t}) / (a - b) = t e^{b t} (e^{(a-b) t} - 1) / ((a-b) t),
// the factored form (a series near a = b). For a stiff, damped mode,
// Re((a - b) t) = sigma t > kMaxFactoredExponent, that form multiplies e^{b t},
// underflowing to 0, by e^{(a-b) t}, overflowing to inf: NaN. There the
// difference is taken directly, both exponentials bounded by 1 (Re a = 0,
// Re b <= 0), with no cancellation since |e^{b t}| < e^-700.
Complex divided_exp(Complex a, Complex b, double t) {
  const Complex z = (a - b) * t;
  if (z.real() > kMaxFactoredExponent) return (std::exp(a * t) - std::exp(b * t)) / (a - b);
  return t * std::exp(b * t) * exp_divided(z);
}

void require_on_implement(const char* name, double x_m, double length_m) {
  detail::require_in_range(name, x_m, 0.0, length_m, "m");
}

// Nodes and weights of n-point Gauss-Legendre on [-1, 1] (Newton on P_n).
struct GaussRule {
  std::array<double, kGaussPoints> x{}, w{};
};
GaussRule gauss_legendre() {
  GaussRule rule;
  const int n = kGaussPoints;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.x[i] = x;
    rule.w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

// Mass per length of the section holding x (sections butt to tip, `ends`
// their cumulative ends): O(log n), so that normalising a mode of n pieces is
// O(n log n), not O(n^2).
double mass_per_length_at(const std::vector<Section>& sections, const std::vector<double>& ends,
                          double x_m) {
  const auto it = std::lower_bound(ends.begin(), ends.end(), x_m);
  const std::size_t i =
      std::min<std::size_t>(static_cast<std::size_t>(it - ends.begin()), sections.size() - 1);
  return sections[i].mass_kg / sections[i].length_m;
}

// int mu w^2 dx + sum m_j w(x_j)^2 for the shape as reported [kg].
double generalised_mass(const Mode& mode, const std::vector<Section>& sections,
                        const std::vector<PointMass>& point_masses) {
  static const GaussRule rule = gauss_legendre();
  std::vector<double> ends;
  ends.reserve(sections.size());
  double x = 0.0;
  for (const Section& s : sections) ends.push_back(x += s.length_m);
  double sum = 0.0;
  for (const ShapePiece& p : mode.shape) {
    const double length = p.end_m - p.start_m;
    if (length <= 0.0) continue;
    const double mu = mass_per_length_at(sections, ends, 0.5 * (p.start_m + p.end_m));
    const int intervals = std::max(
        1, static_cast<int>(std::ceil(p.wavenumber_per_m * length / kMaxPhasePerInterval)));
    const double h = length / intervals;
    for (int j = 0; j < intervals; ++j) {
      const double mid = p.start_m + (j + 0.5) * h;
      for (int i = 0; i < kGaussPoints; ++i) {
        const double w = mode_shape_at(mode, mid + 0.5 * h * rule.x[i]);
        sum += mu * 0.5 * h * rule.w[i] * w * w;
      }
    }
  }
  for (const PointMass& m : point_masses) {
    const double w = mode_shape_at(mode, m.from_butt_m);
    sum += m.mass_kg * w * w;
  }
  return sum;
}

// phi / w for a finite-element mode: its mass-normalised fe_dofs over its
// shape, read at the node where the shape is largest (one piece per element,
// each starting at its node; DOF 2e is w at node e).
double fe_normalisation(const Mode& mode) {
  std::size_t best = 0;
  for (std::size_t e = 0; e < mode.shape.size(); ++e) {
    if (std::abs(mode.shape[e].derivatives[0]) > std::abs(mode.shape[best].derivatives[0]))
      best = e;
  }
  if (2 * best >= mode.fe_dofs.size() || mode.shape[best].derivatives[0] == 0.0) {
    throw FieldError("modes", "finite-element mode without matching fe_dofs");
  }
  return mode.fe_dofs[2 * best] / mode.shape[best].derivatives[0];
}

// Backstop: a response that is not finite is never handed out.
void require_finite_response(const ImpactResponse& r) {
  auto fail = [](const std::string& what) {
    throw FieldError(
        "model",
        "" + what +
            " is not finite; the implement is outside the range the response model can represent");
  };
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const ModeExcitation& e = r.modes[k];
    for (double v : {e.frequency_Hz, e.phi_at_impact, e.energy_after_J, e.impulse_limit_energy_J}) {
      if (!std::isfinite(v)) fail("the excitation of mode " + std::to_string(k + 1));
    }
  }
  for (double v : {r.impulse_N_s, r.rigid_kinetic_energy_J, r.vibration_energy_J}) {
    if (!std::isfinite(v)) fail("the impulse or an energy");
  }
  for (const PointVelocity& p : r.points) {
    for (std::size_t i = 0; i < r.time_s.size(); ++i) {
      if (!std::isfinite(p.dc_m_s[i]) || !std::isfinite(p.ac_m_s[i])) {
        fail("the velocity at " + detail::format_number(p.from_butt_m) +
             " m from the butt, t = " + detail::format_number(r.time_s[i]) + " s,");
      }
    }
  }
}

// The root e in [0, e_r] of e^2 + a (1 + e)^2 = e_r^2, a = mu kappa >= 0:
// e = (sqrt(e_r^2 (1 + a) - a) - a) / (1 + a); none when a > e_r^2 (the
// frame would keep more energy than the collision has; header).
std::optional<double> cor_from_balance(double a, double cor_rigid) {
  const double er2 = cor_rigid * cor_rigid;
  if (!(a <= er2)) return std::nullopt;
  return std::clamp((std::sqrt(er2 * (1.0 + a) - a) - a) / (1.0 + a), 0.0, cor_rigid);
}

ResponseMode prepare_mode(const Mode& mode, double normalisation) {
  ResponseMode out;
  out.mode = mode;
  out.shape_to_mass_normalised = normalisation;
  out.omega_rad_s = 2.0 * kPi * mode.undamped_frequency_Hz;
  out.damping_ratio = mode.damping_ratio;
  return out;
}

// 2 E_k / J^2 for mode k hit at x_F by a pulse of duration T: the closed form at t = T.
double mode_energy_per_impulse_squared(const ResponseMode& mode, double phi_at_impact,
                                       double duration_s) {
  const double unit_peak = half_sine_peak_force(1.0, duration_s);  // F0 of the unit impulse
  const ModalState s = half_sine_modal_response(mode.omega_rad_s, mode.damping_ratio,
                                                unit_peak * phi_at_impact, duration_s, duration_s);
  return s.q_dot * s.q_dot + mode.omega_rad_s * mode.omega_rad_s * s.q * s.q;
}

}  // namespace

// ------------------------------------------------------------ the pulse

void validate(const HalfSinePulse& pulse) {
  detail::require_at_least("pulse.peak_force_N", pulse.peak_force_N, 0.0, "N");
  detail::require_positive("pulse.duration_s", pulse.duration_s, "s");
}

double half_sine_impulse(const HalfSinePulse& pulse) {
  return 2.0 * pulse.peak_force_N * pulse.duration_s / kPi;
}

double half_sine_impulse_until(const HalfSinePulse& pulse, double t_s) {
  if (!(t_s > 0.0)) return 0.0;
  if (t_s >= pulse.duration_s) return half_sine_impulse(pulse);
  return pulse.peak_force_N * pulse.duration_s / kPi *
         (1.0 - std::cos(kPi * t_s / pulse.duration_s));
}

HalfSinePulse half_sine_with_impulse(double impulse_N_s, double duration_s) {
  detail::require_at_least("impulse_N_s", impulse_N_s, 0.0, "N s");
  detail::require_positive("duration_s", duration_s, "s");
  return {half_sine_peak_force(impulse_N_s, duration_s), duration_s};
}

double half_sine_spectrum_ratio(double omega_rad_s, double duration_s) {
  detail::require_at_least("omega_rad_s", omega_rad_s, 0.0, "rad/s");
  detail::require_positive("duration_s", duration_s, "s");
  const double r = omega_rad_s * duration_s / kPi;  // = 2 f T
  const double d = r - 1.0;
  if (std::abs(d) < kResonanceBand) {
    // cos(pi r / 2) / (1 - r^2) near r = 1: pi/4 (1 - d/2 + O(d^2)).
    return kPi / 4.0 * (1.0 - 0.5 * d);
  }
  return std::abs(std::cos(0.5 * kPi * r) / (1.0 - r * r));
}

double half_sine_residual_energy(double impulse_N_s, double phi_at_impact_per_sqrt_kg,
                                 double omega_rad_s, double duration_s) {
  const double s = half_sine_spectrum_ratio(omega_rad_s, duration_s);
  const double jp = impulse_N_s * phi_at_impact_per_sqrt_kg;
  return 0.5 * jp * jp * s * s;
}

ModalState half_sine_modal_response(double omega_rad_s, double damping_ratio,
                                    double modal_peak_force, double duration_s, double t_s) {
  detail::require_positive("omega_rad_s", omega_rad_s, "rad/s");
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0)) {
    throw FieldError("damping_ratio",
                     "must be in [0, 1), got " + detail::format_number(damping_ratio));
  }
  detail::require_positive("duration_s", duration_s, "s");
  detail::require_finite("modal_peak_force", modal_peak_force);
  detail::require_finite("t_s", t_s);
  if (t_s <= 0.0) return {};

  const double w = omega_rad_s;
  const double sigma = damping_ratio * w;
  const double wd = w * std::sqrt((1.0 - damping_ratio) * (1.0 + damping_ratio));
  const Complex lambda(-sigma, wd);
  const Complex lambda_bar = std::conj(lambda);
  const Complex a(0.0, kPi / duration_s);
  auto during = [&](double t) {
    const Complex g1 = divided_exp(a, lambda, t);
    const Complex g2 = divided_exp(a, lambda_bar, t);
    const Complex d = lambda - lambda_bar;  // 2 i w_d
    return ModalState{modal_peak_force * ((g1 - g2) / d).imag(),
                      modal_peak_force * ((lambda * g1 - lambda_bar * g2) / d).imag()};
  };
  if (t_s <= duration_s) return during(t_s);
  // Free damped vibration from the state at the end of the pulse.
  const ModalState end = during(duration_s);
  const double tau = t_s - duration_s;
  const double decay = std::exp(-sigma * tau);
  const double c = std::cos(wd * tau), s = std::sin(wd * tau);
  return {decay * (end.q * c + (end.q_dot + sigma * end.q) / wd * s),
          decay * (end.q_dot * c - (w * w * end.q + sigma * end.q_dot) / wd * s)};
}

// ------------------------------------------------------------ the model

double mass_normalised_shape(const ResponseMode& mode, double x_m) {
  return mode.shape_to_mass_normalised * mode_shape_at(mode.mode, x_m);
}

ResponseModel free_response_model(const std::vector<Section>& sections,
                                  const std::vector<PointMass>& point_masses,
                                  const ModalResult& free, double damping_ratio) {
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0)) {
    throw FieldError("damping_ratio",
                     "must be in [0, 1), got " + detail::format_number(damping_ratio));
  }
  ResponseModel model;
  const Implement implement = Implement::from_sections(sections, point_masses);
  model.rigid_body = implement.mass_properties();
  model.length_m = implement.length_m();
  for (const Mode& mode : free.modes) {
    if (mode.shape.empty() ||
        std::abs(mode.shape.back().end_m - model.length_m) > 1e-9 * model.length_m) {
      throw FieldError("free.modes", "shape does not span the sections' length " +
                                         detail::format_number(model.length_m) + " m");
    }
    const double n = mode.fe_dofs.empty()
                         ? 1.0 / std::sqrt(generalised_mass(mode, sections, point_masses))
                         : fe_normalisation(mode);
    ResponseMode m = prepare_mode(mode, n);
    m.damping_ratio = damping_ratio;
    model.modes.push_back(std::move(m));
  }
  return model;
}

ResponseModel hand_held_response_model(const std::vector<Section>& sections,
                                       const std::vector<PointMass>& point_masses,
                                       const HandCoupling& hand, const ModalResult& hand_held) {
  detail::require_positive("hand.mass_kg", hand.mass_kg, "kg");
  const Implement implement = Implement::from_sections(sections, point_masses);
  ResponseModel model;
  model.hand_held = true;
  model.length_m = implement.length_m();
  const double grip_centre = hand.grip_start_m + 0.5 * hand.grip_length_m;
  require_on_implement("hand.grip centre", grip_centre, model.length_m);
  // The rigid-body motions hand_held_modes deflates: implement and hand moving together.
  model.rigid_body = with_point_mass(implement.mass_properties(), {grip_centre, hand.mass_kg});
  model.rigid_body.I_cm_kg_m2 += hand.rotary_inertia_kg_m2.value_or(
      hand.mass_kg * hand.grip_length_m * hand.grip_length_m / 12.0);
  for (const Mode& mode : hand_held.modes) {
    if (mode.fe_dofs.empty()) {
      throw FieldError("hand_held.modes", "need finite-element modes (fe_dofs)");
    }
    // A damped complex mode used as a real mode (header comment).
    model.modes.push_back(prepare_mode(mode, fe_normalisation(mode)));
  }
  return model;
}

ResponseModel with_fundamental(const ResponseModel& model, double f1_Hz) {
  detail::require_positive("f1_Hz", f1_Hz, "Hz");
  if (model.modes.empty()) throw FieldError("model.modes", "empty, no fundamental to scale");
  if (model.hand_held) {
    throw FieldError("model",
                     "with_fundamental needs a free model (hand modes do not scale with EI)");
  }
  ResponseModel out = model;
  const double ratio = 2.0 * kPi * f1_Hz / model.modes.front().omega_rad_s;
  for (ResponseMode& m : out.modes) {
    m.omega_rad_s *= ratio;
    m.mode.frequency_Hz *= ratio;
    m.mode.undamped_frequency_Hz *= ratio;
  }
  return out;
}

std::string ResponseOptions::validate() const {
  if (modes < 1 || modes > kMaxModes) {
    return "modes: must be in [1, " + std::to_string(kMaxModes) + "], got " + std::to_string(modes);
  }
  if (!(free_damping_ratio >= 0.0 && free_damping_ratio < 1.0)) {
    return "free_damping_ratio: must be in [0, 1), got " +
           detail::format_number(free_damping_ratio);
  }
  if (!(rel_tol >= kMinRelTol && rel_tol <= kMaxRelTol)) {
    return "rel_tol: must be in [" + detail::format_number(kMinRelTol) + ", " +
           detail::format_number(kMaxRelTol) + "], got " + detail::format_number(rel_tol);
  }
  return {};
}

ResponseModel response_model(const Design& design, const ResponseOptions& options) {
  const std::string why = options.validate();
  if (!why.empty()) throw std::invalid_argument("options." + why);
  return detail::response_model_on(design, flexible_frame(design), options);
}

ResponseModel detail::response_model_on(const Design& design, const FlexibleFrame& frame,
                                        const ResponseOptions& options, bool* exact_free) {
  if (exact_free) *exact_free = false;
  ModeOptions mode_options = frame.options;
  mode_options.modes = options.modes;
  mode_options.rel_tol = options.rel_tol;
  mode_options.shape_samples = 0;
  if (options.support == ResponseOptions::Support::kFree) {
    // The exact solver gives at most kMaxExactModes; finite elements beyond.
    if (options.modes > kMaxExactModes) mode_options.method = ModeOptions::Method::kFiniteElement;
    const ModalResult free = free_modes(frame.sections, frame.point_masses, mode_options);
    if (exact_free && free.method == ModeOptions::Method::kExact && !free.modes.empty()) {
      // A one-mode exact solve scans the total phase lambda = sum beta l up
      // to 8 pi and finds the same first root; well below that bound the two agree.
      double phase_per_root_omega = 0.0;
      for (const Section& s : frame.sections)
        phase_per_root_omega += std::pow(s.mass_kg / s.length_m / *s.EI_N_m2, 0.25) * s.length_m;
      const double lambda1 =
          std::sqrt(2.0 * kPi * free.modes.front().frequency_Hz) * phase_per_root_omega;
      *exact_free = lambda1 < 7.0 * kPi;
    }
    return free_response_model(frame.sections, frame.point_masses, free,
                               options.free_damping_ratio);
  }
  if (options.support == ResponseOptions::Support::kRig) {
    mode_options.method = ModeOptions::Method::kFiniteElement;
    const ModalResult held =
        supported_modes(frame.sections, frame.point_masses, options.rig, mode_options);
    ResponseModel model =
        free_response_model(frame.sections, frame.point_masses, held, options.free_damping_ratio);
    model.rig = options.rig;
    return model;
  }
  if (!(design.hand.mass_kg > 0.0)) {
    throw FieldError("hand/mass_kg", "the hand-held response needs a hand, got " +
                                         detail::format_number(design.hand.mass_kg) + " kg");
  }
  const HandCoupling hand = hand_coupling(design);
  mode_options.method = ModeOptions::Method::kFiniteElement;
  const ModalResult held = hand_held_modes(frame.sections, frame.point_masses, hand, mode_options);
  return hand_held_response_model(frame.sections, frame.point_masses, hand, held);
}

// ------------------------------------------------------------ the response

ImpactResponse impact_response(const ResponseModel& model, double impact_from_butt_m,
                               const HalfSinePulse& pulse,
                               const std::vector<double>& points_from_butt_m,
                               const std::vector<double>& time_s) {
  validate(pulse);
  require_on_implement("impact_from_butt_m", impact_from_butt_m, model.length_m);
  for (double x : points_from_butt_m)
    require_on_implement("points_from_butt_m[]", x, model.length_m);
  for (double t : time_s) detail::require_finite("time_s[]", t);

  ImpactResponse out;
  out.time_s = time_s;
  out.impulse_N_s = half_sine_impulse(pulse);
  out.rigid_kinetic_energy_J = 0.5 * out.impulse_N_s * out.impulse_N_s /
                               effective_mass(model.rigid_body, impact_from_butt_m);

  const std::size_t n_modes = model.modes.size();
  const std::size_t n_times = time_s.size();
  // Modal rates q_k'(t), shared by every observed point.
  std::vector<std::vector<double>> q_dot(n_modes, std::vector<double>(n_times));
  for (std::size_t k = 0; k < n_modes; ++k) {
    const ResponseMode& m = model.modes[k];
    const double phi_f = mass_normalised_shape(m, impact_from_butt_m);
    const double p = pulse.peak_force_N * phi_f;
    for (std::size_t i = 0; i < n_times; ++i) {
      q_dot[k][i] =
          half_sine_modal_response(m.omega_rad_s, m.damping_ratio, p, pulse.duration_s, time_s[i])
              .q_dot;
    }
    const ModalState end = half_sine_modal_response(m.omega_rad_s, m.damping_ratio, p,
                                                    pulse.duration_s, pulse.duration_s);
    ModeExcitation e;
    const double zeta = m.damping_ratio;
    e.frequency_Hz = m.omega_rad_s * std::sqrt((1.0 - zeta) * (1.0 + zeta)) / (2.0 * kPi);
    e.phi_at_impact = phi_f;
    e.energy_after_J =
        0.5 * (end.q_dot * end.q_dot + m.omega_rad_s * m.omega_rad_s * end.q * end.q);
    const double jp = out.impulse_N_s * phi_f;
    e.impulse_limit_energy_J = 0.5 * jp * jp;
    out.vibration_energy_J += e.energy_after_J;
    out.modes.push_back(e);
  }

  for (double x : points_from_butt_m) {
    PointVelocity p;
    p.from_butt_m = x;
    const double per_impulse =
        point_velocity_per_impulse(model.rigid_body, impact_from_butt_m, x);  // Eq. (4)
    p.dc_m_s.resize(n_times);
    p.ac_m_s.assign(n_times, 0.0);
    for (std::size_t i = 0; i < n_times; ++i) {
      p.dc_m_s[i] = per_impulse * half_sine_impulse_until(pulse, time_s[i]);
    }
    for (std::size_t k = 0; k < n_modes; ++k) {
      const double phi_x = mass_normalised_shape(model.modes[k], x);
      std::vector<double> v(n_times);
      for (std::size_t i = 0; i < n_times; ++i) {
        v[i] = phi_x * q_dot[k][i];
        p.ac_m_s[i] += v[i];
      }
      p.mode_m_s.push_back(std::move(v));
    }
    out.points.push_back(std::move(p));
  }
  require_finite_response(out);
  return out;
}

std::vector<double> vibration_compliance_per_mode(const ResponseModel& model,
                                                  double impact_from_butt_m, double duration_s) {
  require_on_implement("impact_from_butt_m", impact_from_butt_m, model.length_m);
  detail::require_positive("duration_s", duration_s, "s");
  std::vector<double> kappa;
  for (const ResponseMode& m : model.modes) {
    kappa.push_back(mode_energy_per_impulse_squared(m, mass_normalised_shape(m, impact_from_butt_m),
                                                    duration_s));
  }
  return kappa;
}

double vibration_compliance(const ResponseModel& model, double impact_from_butt_m,
                            double duration_s) {
  double kappa = 0.0;
  for (double k : vibration_compliance_per_mode(model, impact_from_butt_m, duration_s)) kappa += k;
  return kappa;
}

// ------------------------------------------------------------ derived COR

DerivedCor derive_cor(const ResponseModel& model, double impact_from_butt_m, double cor_rigid,
                      const Ball& ball, double duration_s) {
  detail::require_in_range("cor_rigid", cor_rigid, 0.0, 1.0, "");
  detail::require_positive("ball.mass_kg", ball.mass_kg, "kg");
  detail::require_positive("ball.speed_m_s", ball.speed_m_s, "m/s");
  detail::require_positive("duration_s", duration_s, "s");
  require_on_implement("impact_from_butt_m", impact_from_butt_m, model.length_m);

  DerivedCor out;
  out.cor_rigid = cor_rigid;
  const double m = ball.mass_kg, v1 = ball.speed_m_s;
  out.effective_mass_kg = effective_mass(model.rigid_body, impact_from_butt_m);  // Eq. (17)
  out.reduced_mass_kg = reduced_mass(m, out.effective_mass_kg);
  std::vector<double> per_mode;  // 2 E_k / J^2
  for (const ResponseMode& mode : model.modes) {
    per_mode.push_back(mode_energy_per_impulse_squared(
        mode, mass_normalised_shape(mode, impact_from_butt_m), duration_s));
    out.vibration_compliance_per_kg += per_mode.back();
  }
  const double a = out.reduced_mass_kg * out.vibration_compliance_per_kg;
  const std::optional<double> e = cor_from_balance(a, cor_rigid);
  if (!e) {
    throw FieldError("cor_rigid",
                     "the frame would keep more than the collision's energy as vibration (mu kappa "
                     "= " +
                         detail::format_significant(a) +
                         " > cor_rigid^2 = " + detail::format_significant(cor_rigid * cor_rigid) +
                         "); the prescribed-pulse model does not hold for this implement");
  }
  out.cor = *e;
  out.apparent_cor = apparent_cor(out.cor, out.effective_mass_kg, m);                // Eq. (16)
  out.pulse = {peak_impact_force(m, v1, out.apparent_cor, duration_s), duration_s};  // Eq. (15)
  out.impulse_N_s = ball_impulse(m, v1, out.apparent_cor);
  const double j2 = out.impulse_N_s * out.impulse_N_s;
  out.collision_energy_J = 0.5 * m * v1 * v1;
  out.vibration_energy_J = 0.5 * j2 * out.vibration_compliance_per_kg;
  out.vibration_share = out.vibration_energy_J / out.collision_energy_J;
  out.rigid_loss_J = 0.5 * out.reduced_mass_kg * v1 * v1 * (1.0 - cor_rigid * cor_rigid);
  for (double r : per_mode) out.mode_energy_J.push_back(0.5 * j2 * r);
  return out;
}

std::optional<double> fundamental_for_cor(const ResponseModel& model, double impact_from_butt_m,
                                          double cor_rigid, const Ball& ball, double duration_s,
                                          double target_cor, double f_lo_Hz, double f_hi_Hz,
                                          double abs_tol_Hz) {
  detail::require_positive("f_lo_Hz", f_lo_Hz, "Hz");
  detail::require_positive("f_hi_Hz", f_hi_Hz, "Hz");
  detail::require_positive("abs_tol_Hz", abs_tol_Hz, "Hz");
  detail::require_in_range("cor_rigid", cor_rigid, 0.0, 1.0, "");
  detail::require_positive("ball.mass_kg", ball.mass_kg, "kg");
  const double mu =
      reduced_mass(ball.mass_kg, effective_mass(model.rigid_body, impact_from_butt_m));
  auto gap = [&](double f) {
    const double kappa =
        vibration_compliance(with_fundamental(model, f), impact_from_butt_m, duration_s);
    return cor_from_balance(mu * kappa, cor_rigid).value_or(0.0) - target_cor;
  };
  return find_root(gap, f_lo_Hz, f_hi_Hz, abs_tol_Hz);
}

}  // namespace sweetspot
