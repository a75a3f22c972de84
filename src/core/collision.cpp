#include "sweetspot/collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot {
namespace {

constexpr double kPi = 3.14159265358979323846;

// x^e for x > 0 with the calibrated ball's exponents fast (no pow).
inline double power(double x, double e) {
  if (e == 0.5) return std::sqrt(x);
  if (e == 1.0) return x;
  if (e == 1.5) return x * std::sqrt(x);
  if (e == 2.0) return x * x;
  if (e == 2.5) return x * x * std::sqrt(x);
  if (e == 0.0) return 1.0;
  return std::pow(x, e);
}

// The ball's law evaluated for the discrete-gradient step (header comment).
struct Law {
  double k, n, b, p;
  double k_over_n1 = k / (n + 1.0);
  double energy(double x) const { return x > 0.0 ? k_over_n1 * x * power(x, n) : 0.0; }
  double force(double x) const { return x > 0.0 ? k * power(x, n) : 0.0; }
  double stiffness(double x) const { return x > 0.0 ? k * n * power(x, n - 1.0) : 0.0; }
};

// The step's ball force for compressions x0 -> x1 (clamped at >= 0) and its
// derivative in x1.
struct StepForce {
  double force;
  double d_force_dx1;
};

StepForce step_force(const Law& law, double x0, double u0, double x1, double inv_h) {
  const double dx = x1 - x0;
  const double xm = 0.5 * (x0 + x1);
  double g, dg;
  const double scale = std::abs(x0) + std::abs(x1);
  if (std::abs(dx) > 1e-7 * scale && (x0 > 0.0 || x1 > 0.0)) {
    // U(x1) and U'(x1) from one power: x^n, then x^(n+1) = x x^n.
    const double xn = x1 > 0.0 ? power(x1, law.n) : 0.0;
    const double u1 = law.k_over_n1 * x1 * xn;
    const double inv_dx = 1.0 / dx;
    g = (u1 - u0) * inv_dx;
    dg = (law.k * xn - g) * inv_dx;
  } else {
    g = law.force(xm);
    dg = 0.5 * law.stiffness(xm);
  }
  double d = 0.0, dd = 0.0;
  if (law.b > 0.0 && xm > 0.0) {
    const double xp = power(xm, law.p);
    d = law.b * xp * dx * inv_h;
    dd = law.b * inv_h * (xp + (law.p > 0.0 ? 0.5 * law.p * xp / xm * dx : 0.0));
  }
  const double f = g + d;
  if (f <= 0.0) return {0.0, 0.0};
  return {f, dg + dd};
}

// Solves F = Phi(a - c F) for F >= 0 (Phi the step force, increasing in x1):
// g(F) = F - Phi(a - c F) is increasing with g' >= 1, so the root is unique,
// lies in [0, Phi(a)], and |F - F*| <= |g(F)|. Newton from `guess`, kept in
// the bracket (Phi(a) is evaluated only if Newton leaves [0, inf)).
double solve_force(const Law& law, double x0, double u0, double a, double c, double h, double guess,
                   double force_floor) {
  if (x0 <= 0.0 && a <= 0.0) return 0.0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double inv_h = 1.0 / h;
  double lo = 0.0, hi = kInf;
  double f = std::max(guess, 0.0);
  for (int it = 0; it < 100; ++it) {
    const StepForce s = step_force(law, x0, u0, a - c * f, inv_h);
    const double g = f - s.force;
    const double scale = std::max({f, s.force, force_floor});
    if (std::abs(g) <= 1e-15 * scale) return f;
    if (g > 0.0)
      hi = f;
    else
      lo = f;
    const double newton = f - g / (1.0 + c * s.d_force_dx1);
    // Newton converges quadratically: a step this small leaves ~its square
    // (relative to the force, or to the contact's typical force near 0).
    if (newton > lo && newton < hi && std::abs(newton - f) <= 1e-7 * scale) return newton;
    double next = newton;
    if (!(next > lo && next < hi)) {
      if (hi == kInf) hi = std::max(step_force(law, x0, u0, a, inv_h).force, lo);
      next = 0.5 * (lo + hi);
    }
    if (next == f || hi - lo <= 1e-15 * hi) return next;
    f = next;
  }
  return f;
}

}  // namespace

std::string BallContactLaw::validate() const {
  using detail::format_number;
  if (!(stiffness > 0.0 && stiffness <= kMaxBallStiffness))
    return "stiffness: must be in (0, " + format_number(kMaxBallStiffness) + "], got " +
           format_number(stiffness);
  if (!(exponent >= kMinBallExponent && exponent <= kMaxBallExponent))
    return "exponent: must be in [" + format_number(kMinBallExponent) + ", " +
           format_number(kMaxBallExponent) + "], got " + format_number(exponent);
  if (!(damping >= 0.0 && damping <= kMaxBallDamping))
    return "damping: must be in [0, " + format_number(kMaxBallDamping) + "], got " +
           format_number(damping);
  if (!(damping_exponent >= 0.0 && damping_exponent <= kMaxBallDampingExponent))
    return "damping_exponent: must be in [0, " + format_number(kMaxBallDampingExponent) +
           "], got " + format_number(damping_exponent);
  return {};
}

double contact_elastic_energy(const BallContactLaw& law, double compression_m) {
  return Law{law.stiffness, law.exponent, law.damping, law.damping_exponent}.energy(compression_m);
}

FrameAtImpact frame_at_impact(const ResponseModel& model, double impact_from_butt_m, int modes) {
  if (!(impact_from_butt_m >= 0.0 && impact_from_butt_m <= model.length_m)) {
    throw FieldError("impact_from_butt_m", "must be on the implement [0, " +
                                               detail::format_number(model.length_m) + "] m, got " +
                                               detail::format_number(impact_from_butt_m));
  }
  FrameAtImpact frame;
  frame.inverse_effective_mass_per_kg = 1.0 / effective_mass(model.rigid_body, impact_from_butt_m);
  const std::size_t count =
      modes < 0 ? model.modes.size() : std::min<std::size_t>(model.modes.size(), modes);
  for (std::size_t k = 0; k < count; ++k) {
    const ResponseMode& m = model.modes[k];
    frame.modes.push_back(
        {mass_normalised_shape(m, impact_from_butt_m), m.omega_rad_s, m.damping_ratio});
  }
  return frame;
}

FrameAtImpact rigid_frame() { return FrameAtImpact{}; }

std::string CollisionOptions::validate() const {
  if (steps_per_contact < 16 || steps_per_contact > 1000000)
    return "steps_per_contact: must be in [16, 1e6], got " + std::to_string(steps_per_contact);
  if (!(max_time_s > 0.0 && max_time_s <= 10.0))
    return "max_time_s: must be in (0, 10] s, got " + detail::format_number(max_time_s);
  return {};
}

double cor_from_apparent(double apparent_cor, double ball_mass_kg, double effective_mass_kg) {
  detail::require_positive("ball_mass_kg", ball_mass_kg, "kg");
  detail::require_positive("effective_mass_kg", effective_mass_kg, "kg");
  detail::require_finite("apparent_cor", apparent_cor);
  return (apparent_cor * (effective_mass_kg + ball_mass_kg) + ball_mass_kg) / effective_mass_kg;
}

StringBedDynamics string_bed_dynamics(const StringBed& bed, double mass_kg, double damping_ratio) {
  return StringBedDynamics{string_bed_stiffness(bed), mass_kg, damping_ratio};
}

namespace {

CollisionResult integrate(const FrameAtImpact& frame,
                          const std::optional<StringBedDynamics>& strings, double ball_mass_kg,
                          const BallContactLaw& ball_law, double speed_m_s,
                          const CollisionOptions& options) {
  detail::require_positive("ball_mass_kg", ball_mass_kg, "kg");
  detail::require_positive("speed_m_s", speed_m_s, "m/s");
  if (const std::string why = ball_law.validate(); !why.empty())
    throw std::invalid_argument("law." + why);
  if (const std::string why = options.validate(); !why.empty())
    throw std::invalid_argument("options." + why);
  if (!(frame.inverse_effective_mass_per_kg >= 0.0 &&
        std::isfinite(frame.inverse_effective_mass_per_kg))) {
    throw FieldError(
        "frame.inverse_effective_mass_per_kg",
        "must be >= 0, got " + detail::format_number(frame.inverse_effective_mass_per_kg));
  }
  for (std::size_t k = 0; k < frame.modes.size(); ++k) {
    const ModeAtImpact& m = frame.modes[k];
    detail::require_finite(detail::Element{"frame.modes", k, "phi"}, m.phi);
    detail::require_positive(detail::Element{"frame.modes", k, "omega_rad_s"}, m.omega_rad_s,
                             "rad/s");
    if (!(m.damping_ratio >= 0.0 && m.damping_ratio < 1.0))
      detail::fail_in_range(detail::indexed("frame.modes", k, "damping_ratio"), m.damping_ratio,
                            0.0, 1.0, "");
  }
  if (strings) {
    detail::require_positive("strings.stiffness_N_m", strings->stiffness_N_m, "N/m");
    detail::require_positive("strings.mass_kg", strings->mass_kg, "kg");
    if (!(strings->damping_ratio >= 0.0 && strings->damping_ratio < 1.0))
      detail::fail_in_range("strings.damping_ratio", strings->damping_ratio, 0.0, 1.0, "");
  }
  const Law law{ball_law.stiffness, ball_law.exponent, ball_law.damping, ball_law.damping_exponent};
  const double m = ball_mass_kg, v1 = speed_m_s;

  // Time step from the linearised contact: the ball's secant stiffness at
  // its elastic peak compression on a rigid surface, in series with the strings.
  const double x_peak = std::pow((law.n + 1.0) * m * v1 * v1 / (2.0 * law.k), 1.0 / (law.n + 1.0));
  double k_lin = law.k * std::pow(x_peak, law.n - 1.0);
  if (strings) k_lin = series_stiffness(k_lin, strings->stiffness_N_m);
  const double mu = m / (1.0 + m * frame.inverse_effective_mass_per_kg);
  const double t_est = kPi * std::sqrt(mu / k_lin);
  // The fastest motions within the contact: the ball's own spring on what it
  // touches first (the string bed's moving mass, or the frame's rigid body and
  // modes at the impact point), at the compression that stops their relative
  // motion, and the string bed's mass on its spring. A stiff ball (or stiff
  // strings) makes these far shorter than the contact; the step resolves them
  // with steps_per_contact / kFastShare steps per half-period, which never
  // binds for the calibrated ball at any tension in the strings' range.
  double frame_mobility = frame.inverse_effective_mass_per_kg;  // [1/kg], instantaneous
  for (const ModeAtImpact& md : frame.modes) frame_mobility += md.phi * md.phi;
  const double partner_mobility = strings ? 1.0 / strings->mass_kg : frame_mobility;
  const double mu_ball = m / (1.0 + m * partner_mobility);
  const double x_ball =
      std::pow((law.n + 1.0) * mu_ball * v1 * v1 / (2.0 * law.k), 1.0 / (law.n + 1.0));
  double t_fast = kPi * std::sqrt(mu_ball / (law.k * std::pow(x_ball, law.n - 1.0)));
  if (strings) {
    const double mu_bed = strings->mass_kg / (1.0 + strings->mass_kg * frame_mobility);
    t_fast = std::min(t_fast, kPi * std::sqrt(mu_bed / strings->stiffness_N_m));
  }
  constexpr double kFastShare = 8.0;
  // The base step. From a contact's onset, where the force grows like
  // sqrt(t) (x^p x' with p = 1/2), the mesh is t_i = kOnset T (i/N)^2
  // (the force a smooth function of i) until it reaches the base step, then
  // uniform. Towards an instant where the force or the compression falls to
  // 0 (a kink or a fractional power of the time) the steps shrink like t^2
  // and geometrically to kRefine of the base step; once the force is 0 the
  // step lands on the separation; between contacts, with the ball receding,
  // steps are kFreeSteps times longer, and a new touch is approached
  // geometrically. (kOnset = 2 and kRefine = 1e-3 keep the default's COR and
  // its observed order; docs/model.md, "The solved collision".)
  // The time the step resolves (the contact's, unless a faster motion binds).
  const double t_res = std::min(t_est, kFastShare * t_fast);
  const double h_base = t_res / options.steps_per_contact;
  // Forces below this are round-off for the force solve: 1e-9 of the mean force.
  const double force_floor = 1e-9 * m * v1 / t_est;
  constexpr double kOnset = 2.0, kRefine = 1e-3, kGrade = 0.5, kFreeSteps = 4.0;
  const double h_min = h_base * kRefine;

  // Coordinates: 0 the rigid body at the impact point (unit modal mass,
  // phi = 1/sqrt(M_eff), w = 0), then the flexible modes.
  const std::size_t nm = frame.modes.size() + 1;
  std::vector<double> phi(nm), om2(nm), damp(nm), r(nm, 0.0), v(nm, 0.0), inv_den(nm), beta(nm),
      half_om2(nm), alpha(nm);
  phi[0] = std::sqrt(frame.inverse_effective_mass_per_kg);
  for (std::size_t j = 1; j < nm; ++j) {
    const ModeAtImpact& md = frame.modes[j - 1];
    phi[j] = md.phi;
    om2[j] = md.omega_rad_s * md.omega_rad_s;
    damp[j] = 2.0 * md.damping_ratio * md.omega_rad_s;
  }
  double compliance = 0.0;  // static compliance of the vibration at the impact point [m/N]
  for (std::size_t j = 1; j < nm; ++j) compliance += phi[j] * phi[j] / om2[j];
  const bool has_strings = strings.has_value();
  const double ks = has_strings ? strings->stiffness_N_m : 0.0;
  const double ms = has_strings ? strings->mass_kg : 0.0;
  const double cs = has_strings ? 2.0 * strings->damping_ratio * std::sqrt(ks * m) : 0.0;
  if (has_strings) compliance += 1.0 / ks;

  // Step-dependent coefficients of the midpoint rule.
  double h = 0.0, B_w = 0.0, kappa = 0.0;
  auto set_step = [&](double hh) {
    if (hh == h) return;
    h = hh;
    B_w = 0.0;
    for (std::size_t j = 0; j < nm; ++j) {  // vectorisable: no sum
      inv_den[j] = 1.0 / (1.0 + 0.5 * h * damp[j] + 0.25 * h * h * om2[j]);
      beta[j] = 0.5 * h * phi[j] * inv_den[j];
      half_om2[j] = 0.5 * h * om2[j];
    }
    for (std::size_t j = 0; j < nm; ++j) B_w += phi[j] * beta[j];
    kappa = 0.5 * ks * h + cs;
  };

  CollisionResult res;
  res.step_s = h_base;
  double y = 0.0, vy = v1;    // ball
  double s = 0.0, vs = 0.0;   // string bed (or the frame point without strings)
  double x = 0.0, u_x = 0.0;  // compression and its elastic energy
  double x_dot = v1;          // the last step's mean compression rate
  double f_prev = 0.0, f_prev2 = 0.0, h_prev = h_base;
  double ball_loss = 0.0, strings_loss = 0.0, damping_loss = 0.0;
  bool in_contact = false;
  double t = 0.0, contact_start = 0.0, last_separation = 0.0;
  // At most 64 steps per base step until max_time_s, and never more than
  // kMaxSteps, counted in double (a contact resolved by a tiny step would
  // overflow a long). A contact that alone needs more than kMaxSteps is not
  // stepped at all: the ball is left in contact, which the invariants refuse
  // (invariants.hpp) at once rather than after minutes of stepping.
  constexpr double kMaxSteps = 1e8;
  const long max_steps =
      t_est / h_base > kMaxSteps
          ? 0L
          : static_cast<long>(std::min(kMaxSteps, 64.0 * std::ceil(options.max_time_s / h_base)));

  // Everything the result reports, from the state now.
  auto snapshot = [&] {
    res.ball_velocity_after_m_s = vy;
    res.frame_velocity_after_m_s = phi[0] * v[0];
    res.implement_momentum_N_s =
        (frame.inverse_effective_mass_per_kg > 0.0 ? v[0] / phi[0] : 0.0) + ms * vs;
    res.apparent_cor = -vy / v1;
    res.ball_in_J = 0.5 * m * v1 * v1;
    res.ball_out_J = 0.5 * m * vy * vy + u_x;  // u_x = 0 once separated
    res.mode_energy_J.assign(nm - 1, 0.0);
    double w = 0.0;
    for (std::size_t j = 0; j < nm; ++j) w += phi[j] * r[j];
    double vibration = damping_loss;
    for (std::size_t j = 1; j < nm; ++j) {
      res.mode_energy_J[j - 1] = 0.5 * (v[j] * v[j] + om2[j] * r[j] * r[j]);
      vibration += res.mode_energy_J[j - 1];
    }
    // The string bed rides on the frame: the rigid motion of both is their
    // common momentum P on M_eff + m_s; the rest is the bed's vibration.
    const double inv_M = frame.inverse_effective_mass_per_kg;
    const double uF = phi[0] * v[0];
    double rigid = 0.5 * v[0] * v[0];
    res.string_bed_energy_J = 0.0;
    if (has_strings) {
      const double d = s - w;
      if (inv_M > 0.0) {
        const double M = 1.0 / inv_M, P = M * uF + ms * vs;
        rigid = 0.5 * P * P / (M + ms);
        const double mu_s = M * ms / (M + ms);
        res.string_bed_energy_J = 0.5 * mu_s * (uF - vs) * (uF - vs) + 0.5 * ks * d * d;
      } else {
        res.string_bed_energy_J = 0.5 * ms * vs * vs + 0.5 * ks * d * d;
      }
    }
    res.implement_rigid_J = rigid;
    res.vibration_J = vibration + res.string_bed_energy_J;
    res.modal_damping_loss_J = damping_loss;
    res.ball_loss_J = ball_loss;
    res.strings_loss_J = strings_loss;
    res.contact_time_s = last_separation;
  };

  long n = 0;
  for (; n < max_steps && t < options.max_time_s; ++n) {
    // The step (the mesh above).
    double hh = h_base;
    if (x > 0.0 || (x == 0.0 && vy - vs > 0.0)) {
      if (!in_contact && x == 0.0) contact_start = t;
      const double since = t - contact_start;
      // (The square roots only where they can shorten the step.)
      if (kOnset * since < 0.25 * t_res)
        hh =
            h_base * (2.0 * std::sqrt(kOnset * since / t_res) + kOnset / options.steps_per_contact);
      if (x_dot < 0.0 || (f_prev > 0.0 && f_prev < f_prev2)) {
        double tau = x_dot < 0.0 ? x / -x_dot : std::numeric_limits<double>::infinity();
        if (f_prev > 0.0 && f_prev < f_prev2) tau = std::min(tau, f_prev * h / (f_prev2 - f_prev));
        if (f_prev > 0.0)
          hh = std::min({hh, kGrade * tau,
                         tau < 0.25 * t_res ? 2.0 * h_base * std::sqrt(tau / t_res) : h_base});
        else
          hh = std::min(hh, tau);  // no force: land on the separation
      }
      hh = std::clamp(hh, h_min, h_base);
    } else if (vy - vs > 0.0) {
      const double tau = -x / (vy - vs);  // to the next touch
      hh = std::clamp(kGrade * tau, h_min, h_base);
    } else {
      hh = kFreeSteps * h_base;
    }
    set_step(hh);
    double A_w = 0.0, w0 = 0.0;
    for (std::size_t j = 0; j < nm; ++j) {
      alpha[j] = (v[j] - half_om2[j] * r[j]) * inv_den[j];
      A_w += phi[j] * alpha[j];
      w0 += phi[j] * r[j];
    }
    // x1 = a - c F_b, F_s = P + Q F_b.
    double a, c, P = 0.0, Q = 1.0;
    if (has_strings) {
      const double D = 1.0 + kappa * (0.5 * h / ms + B_w);
      P = (kappa * (vs - A_w) + ks * (s - w0)) / D;
      Q = kappa * 0.5 * h / (ms * D);
      a = x + h * (vy - vs + 0.5 * h * P / ms);
      c = h * (0.5 * h / m + 0.5 * h * (1.0 - Q) / ms);
    } else {
      a = x + h * (vy - A_w);
      c = h * (0.5 * h / m + B_w);
    }
    const double guess = std::max(0.0, f_prev + (f_prev - f_prev2) * h / h_prev);
    const double F = solve_force(law, x, u_x, a, c, h, guess, force_floor);
    const double Fs = has_strings ? P + Q * F : F;
    // Update the linear part with the midpoint velocities.
    // (Sums in locals: an accumulator kept in memory serialises the loop.)
    double w_dot_mid = 0.0, damping_power = 0.0;
    for (std::size_t j = 0; j < nm; ++j) {
      const double vm = alpha[j] + beta[j] * Fs;
      w_dot_mid += phi[j] * vm;
      damping_power += damp[j] * vm * vm;
      r[j] += h * vm;
      v[j] = 2.0 * vm - v[j];
    }
    damping_loss += h * damping_power;
    const double vy_mid = vy - 0.5 * h / m * F;
    y += h * vy_mid;
    vy = 2.0 * vy_mid - vy;
    double vs_mid = w_dot_mid;
    if (has_strings) {
      vs_mid = vs + 0.5 * h / ms * (F - Fs);
      const double rel = vs_mid - w_dot_mid;
      strings_loss += cs * h * rel * rel;
    }
    s += h * vs_mid;
    vs = 2.0 * vs_mid - vs;
    const double x_new = y - s;
    const double u_new = law.energy(x_new);
    ball_loss += F * (x_new - x) - (u_new - u_x);
    res.impulse_N_s += h * F;
    if (F > res.peak_force_N) res.peak_force_N = F;
    if (x_new > res.peak_ball_compression_m) res.peak_ball_compression_m = x_new;
    if (has_strings)
      res.peak_string_deflection_m = std::max(
          res.peak_string_deflection_m, x_new > 0.0 ? std::abs(s - (w0 + h * w_dot_mid)) : 0.0);
    if (options.record_history) {
      res.time_s.push_back(t + 0.5 * h);
      res.force_N.push_back(F);
    }
    x_dot = (x_new - x) / h;
    h_prev = h;
    const double x_old = x;
    x = x_new;
    u_x = u_new;
    f_prev2 = f_prev;
    f_prev = F;
    t += h;
    // Contacts: crossings of x = 0, timed by linear interpolation in the step.
    if (!in_contact && x > 0.0) {
      in_contact = true;
      ++res.contacts;
      contact_start = x_old <= 0.0 ? t - h + h * (-x_old) / (x - x_old) : t - h;
    } else if (in_contact && x <= 0.0) {
      in_contact = false;
      last_separation = t - h + h * x_old / (x_old - x);
      res.in_contact_s += last_separation - contact_start;
      snapshot();
    }
    // Gone for good? The vibration (modes and string bed relative to the
    // rigid motion) moves the contact point by at most sqrt(2 E C), C the
    // static compliance there, while the ball recedes from the rigid motion.
    if (!in_contact && res.contacts > 0) {
      const double uF = phi[0] * v[0];
      if (vy - uF < 0.0) {
        double w = 0.0, e_osc = 0.0;
        for (std::size_t j = 0; j < nm; ++j) w += phi[j] * r[j];
        for (std::size_t j = 1; j < nm; ++j) e_osc += 0.5 * (v[j] * v[j] + om2[j] * r[j] * r[j]);
        if (has_strings) e_osc += 0.5 * ks * (s - w) * (s - w) + 0.5 * ms * (vs - uF) * (vs - uF);
        const double reach = std::sqrt(2.0 * e_osc * compliance);
        if (x + 2.0 * reach < 0.0) {
          res.separated = true;
          ++n;
          break;
        }
      }
    }
  }
  res.steps = static_cast<int>(n);
  if (!res.separated) {
    if (in_contact) last_separation = t;
    snapshot();
  }
  return res;
}

// (4 fine - coarse) / 3: the h^2 term of two runs at h and h/2 cancelled.
double extrapolated(double coarse, double fine) { return (4.0 * fine - coarse) / 3.0; }

}  // namespace

CollisionResult collide(const FrameAtImpact& frame, const std::optional<StringBedDynamics>& strings,
                        double ball_mass_kg, const BallContactLaw& law, double speed_m_s,
                        const CollisionOptions& options) {
  if (!options.extrapolate) return integrate(frame, strings, ball_mass_kg, law, speed_m_s, options);
  CollisionOptions o = options;
  o.extrapolate = false;
  o.record_history = false;
  const CollisionResult coarse = integrate(frame, strings, ball_mass_kg, law, speed_m_s, o);
  o.steps_per_contact *= 2;
  o.record_history = options.record_history;
  CollisionResult r = integrate(frame, strings, ball_mass_kg, law, speed_m_s, o);
  r.step_error = std::abs(r.apparent_cor - coarse.apparent_cor);
  // Only a smooth dependence on h extrapolates: the same number of contacts.
  if (coarse.contacts != r.contacts || coarse.separated != r.separated) return r;
  for (double CollisionResult::*field :
       {&CollisionResult::contact_time_s, &CollisionResult::in_contact_s,
        &CollisionResult::impulse_N_s, &CollisionResult::ball_velocity_after_m_s,
        &CollisionResult::frame_velocity_after_m_s, &CollisionResult::implement_momentum_N_s,
        &CollisionResult::apparent_cor, &CollisionResult::ball_out_J,
        &CollisionResult::implement_rigid_J, &CollisionResult::vibration_J,
        &CollisionResult::ball_loss_J, &CollisionResult::strings_loss_J}) {
    r.*field = extrapolated(coarse.*field, r.*field);
  }
  // The parts of vibration_J (each mode, the string bed, the modal damping) are
  // >= 0 in every run; one near 0 (an impact near a mode's node) whose h^2 term
  // is larger than itself would extrapolate below 0: it keeps the fine run's
  // value (the ledger sums vibration_J, extrapolated above, not its parts).
  const auto keep_sign = [](double coarse_value, double& fine_value) {
    const double e = extrapolated(coarse_value, fine_value);
    if (e >= 0.0) fine_value = e;
  };
  keep_sign(coarse.string_bed_energy_J, r.string_bed_energy_J);
  keep_sign(coarse.modal_damping_loss_J, r.modal_damping_loss_J);
  for (std::size_t k = 0; k < r.mode_energy_J.size(); ++k)
    keep_sign(coarse.mode_energy_J[k], r.mode_energy_J[k]);
  r.steps += coarse.steps;
  return r;
}

}  // namespace sweetspot
