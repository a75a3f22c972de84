#include "sweetspot/collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/check.hpp"
#include "core/collision/ball_law.hpp"
#include "core/collision/bodies.hpp"
#include "core/collision/contact_force.hpp"
#include "core/collision/ledger.hpp"
#include "core/collision/modal_state.hpp"
#include "core/collision/step_mesh.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/roots.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot {

const char* to_string(BallLawForm form) {
  switch (form) {
    case BallLawForm::kHysteretic:
      return "hysteretic";
    case BallLawForm::kTwoMass:
      return "two_mass";
    case BallLawForm::kPower:
      break;
  }
  return "power";
}

namespace {

// The hysteretic law's problem, if any: each field in its range, each
// unloading exponent at or above its backbone's (1, 2, 1), so that no branch
// rises above its backbone (energy from nowhere).
std::string hysteretic_problem(const HystereticBallLaw& h) {
  using detail::format_number;
  const auto finite_at_least = [](const char* name, double v, double lo, bool open) -> std::string {
    if (std::isfinite(v) && (open ? v > lo : v >= lo)) return {};
    return std::string("hysteretic.") + name + ": must be " + (open ? "> " : ">= ") +
           format_number(lo) + ", got " + format_number(v);
  };
  for (const std::string& why :
       {finite_at_least("shell_stiffness", h.shell_stiffness, 0.0, true),
        finite_at_least("shell_compression", h.shell_compression, 0.0, true),
        finite_at_least("stiffening", h.stiffening, 0.0, false),
        finite_at_least("wall_stiffness", h.wall_stiffness, 0.0, false),
        finite_at_least("damping", h.damping, 0.0, false)}) {
    if (!why.empty()) return why;
  }
  if (h.shell_stiffness > kMaxBallStiffness || h.wall_stiffness > kMaxBallStiffness ||
      h.stiffening > kMaxBallStiffness || h.damping > kMaxBallDamping)
    return "hysteretic: a stiffness above " + format_number(kMaxBallStiffness) +
           " or a damping above " + format_number(kMaxBallDamping);
  if (std::isnan(h.unloading_offset) ||
      h.unloading_offset == -std::numeric_limits<double>::infinity())
    return "hysteretic.unloading_offset: must be a number or +infinity, got " +
           format_number(h.unloading_offset);
  const struct {
    const char* name;
    double q, lowest;
  } exponents[] = {{"shell_unloading", h.shell_unloading, 1.0},
                   {"stiffening_unloading", h.stiffening_unloading, 2.0},
                   {"wall_unloading", h.wall_unloading, 1.0}};
  for (const auto& e : exponents) {
    if (!std::isfinite(e.q))
      return std::string("hysteretic.") + e.name + ": must be finite, got " + format_number(e.q);
    if (!(e.q >= e.lowest))
      return std::string("hysteretic.") + e.name + ": must be >= " + format_number(e.lowest) +
             " (unloading never above loading), got " + format_number(e.q);
  }
  return {};
}

// The body's problem, if any: two masses for the two-mass form, one for the others.
std::string body_problem(BallLawForm form, const BallBody& b) {
  using detail::format_number;
  if (form != BallLawForm::kTwoMass) {
    if (b.front_mass_fraction == 1.0) return {};
    return std::string("body.front_mass_fraction: the ") + to_string(form) +
           " law's ball is one mass (1), got " + format_number(b.front_mass_fraction);
  }
  if (!(b.front_mass_fraction > 0.0 && b.front_mass_fraction < 1.0))
    return "body.front_mass_fraction: must be in (0, 1) for two masses, got " +
           format_number(b.front_mass_fraction);
  if (!(b.internal_stiffness > 0.0 && b.internal_stiffness <= kMaxBallStiffness))
    return "body.internal_stiffness: must be in (0, " + format_number(kMaxBallStiffness) +
           "] N/m, got " + format_number(b.internal_stiffness);
  if (!(b.internal_cubic_stiffness >= 0.0 && b.internal_cubic_stiffness <= kMaxBallStiffness))
    return "body.internal_cubic_stiffness: must be in [0, " + format_number(kMaxBallStiffness) +
           "] N/m^3, got " + format_number(b.internal_cubic_stiffness);
  if (!(b.internal_damping_ratio >= 0.0 && b.internal_damping_ratio < 1.0))
    return "body.internal_damping_ratio: must be in [0, 1), got " +
           format_number(b.internal_damping_ratio);
  return {};
}

}  // namespace

std::string BallContactLaw::validate() const {
  using detail::format_number;
  if (std::string why = body_problem(form, body); !why.empty()) return why;
  if (is_hysteretic(form)) return hysteretic_problem(hysteretic);
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
  if (is_hysteretic(law.form))
    return collision_detail::HystereticLaw(law.hysteretic).energy(compression_m);
  return collision_detail::PowerLaw(law).energy(compression_m);
}

FrameAtImpact frame_at_impact(const ResponseModel& model, double impact_from_butt_m, int modes) {
  if (!(impact_from_butt_m >= 0.0 && impact_from_butt_m <= model.length_m)) {
    throw FieldError("impact_from_butt_m", "must be on the implement [0, " +
                                               detail::format_number(model.length_m) + "] m, got " +
                                               detail::format_number(impact_from_butt_m));
  }
  FrameAtImpact frame;
  if (!model.rig) {
    frame.inverse_effective_mass_per_kg =
        1.0 / effective_mass(model.rigid_body, impact_from_butt_m);  // Eq. (17)
  } else if (model.rig->kind == BeamSupport::Kind::kPinned) {
    // Turning about the pivot p only: 1 / M_eff = (x - p)^2 / I_p, I_p by the
    // parallel-axis theorem (0 at the pivot: the impact does not move it).
    const MassProperties& body = model.rigid_body;
    const double arm = body.com_from_butt_m - model.rig->from_m;
    const double I_p = body.I_cm_kg_m2 + body.mass_kg * arm * arm;
    const double d = impact_from_butt_m - model.rig->from_m;
    frame.inverse_effective_mass_per_kg = d * d / I_p;
  }  // clamped: the rigid body does not move (inverse 0)
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

double rigid_surface_cor(const BallContactLaw& law, double ball_mass_kg, double speed_m_s) {
  return collide(rigid_frame(), std::nullopt, ball_mass_kg, law, speed_m_s).apparent_cor;
}

namespace {

bool same_law(const BallContactLaw& a, const BallContactLaw& b) {
  const HystereticBallLaw &h = a.hysteretic, &g = b.hysteretic;
  const BallBody &p = a.body, &r = b.body;
  return p.front_mass_fraction == r.front_mass_fraction &&
         p.internal_stiffness == r.internal_stiffness &&
         p.internal_cubic_stiffness == r.internal_cubic_stiffness &&
         p.internal_damping_ratio == r.internal_damping_ratio && a.stiffness == b.stiffness &&
         a.exponent == b.exponent && a.damping == b.damping &&
         a.damping_exponent == b.damping_exponent && a.form == b.form &&
         h.shell_stiffness == g.shell_stiffness && h.shell_compression == g.shell_compression &&
         h.stiffening == g.stiffening && h.wall_stiffness == g.wall_stiffness &&
         h.shell_unloading == g.shell_unloading &&
         h.stiffening_unloading == g.stiffening_unloading && h.wall_unloading == g.wall_unloading &&
         h.damping == g.damping && h.unloading_offset == g.unloading_offset;
}

BallContactLaw solve_rigid_surface_cor(const BallContactLaw& law, double ball_mass_kg, double cor) {
  using detail::format_number;
  constexpr const char* kField = "ball/cor_on_rigid_surface";
  // The loss parameter p of the law, e(p) falling: the power law's damping
  // (its logarithm, from 1e-9 to the largest accepted), the hysteretic
  // ball's unloading offset (from where every branch sits at its minimum).
  BallContactLaw out = law;
  const bool power = law.form == BallLawForm::kPower;
  double* loss = power ? &out.damping : &out.hysteretic.unloading_offset;
  const HystereticBallLaw& h = law.hysteretic;
  double lo = power ? std::log(kMaxBallDamping * 1e-21)
                    : -std::max({h.shell_unloading - 1.0, h.stiffening_unloading - 2.0,
                                 h.wall_unloading - 1.0});
  if (law.form == BallLawForm::kHysteretic && cor == 0.0) {
    *loss = std::numeric_limits<double>::infinity();  // a plastic ball
    return out;
  }
  // (A two-mass ball whose contact is plastic still rebounds: its back half
  // comes back off the internal spring. Its deadest is searched for below.)
  const auto excess = [&](double p) {
    *loss = power ? std::exp(p) : p;
    return rigid_surface_cor(out, ball_mass_kg) - cor;
  };
  const double lively = excess(lo);
  if (lively < 0.0) {
    throw FieldError(kField, "must be at most " + format_number(lively + cor) + " for the " +
                                 to_string(law.form) + " law's ball, got " + format_number(cor));
  }
  double hi = power ? std::log(kMaxBallDamping) : lo + 1.0;
  double dead = excess(hi);
  while (!power && dead > 0.0 && hi < 1e6) dead = excess(hi = lo + 2.0 * (hi - lo));
  if (dead > 0.0) {
    throw FieldError(kField,
                     "must be at least " + format_number(dead + cor) + " for the " +
                         to_string(law.form) + " law's ball" +
                         (power ? " (its damping at most " + format_number(kMaxBallDamping) +
                                      "; the hysteretic law's reaches 0)"
                                : "") +
                         ", got " + format_number(cor));
  }
  const double p = brent_root(excess, lo, hi, lively, dead, 1e-12 * std::max(1.0, std::abs(hi)));
  // A COR the loss cannot reach to 1e-6 is refused rather than answered for another ball.
  if (const double miss = excess(p); !(std::abs(miss) <= 1e-6)) {
    throw FieldError(kField, "cannot be matched closer than " + format_number(miss + cor) +
                                 " by the " + to_string(law.form) + " law's ball, got " +
                                 format_number(cor));
  }
  return out;
}

}  // namespace

BallContactLaw with_rigid_surface_cor(const BallContactLaw& law, double ball_mass_kg, double cor) {
  if (!(cor >= 0.0 && cor < 1.0)) {
    throw FieldError("ball/cor_on_rigid_surface",
                     "must be in [0, 1), got " + detail::format_number(cor));
  }
  // Solved once per ball: a design's collision is set up again for every
  // impact of a sweep, a catalogue's rows or the power point's search.
  struct Solved {
    BallContactLaw law;
    double mass_kg, cor;
    BallContactLaw answer;
  };
  thread_local std::vector<Solved> memo;
  for (const Solved& s : memo) {
    if (s.mass_kg == ball_mass_kg && s.cor == cor && same_law(s.law, law)) return s.answer;
  }
  const BallContactLaw answer = solve_rigid_surface_cor(law, ball_mass_kg, cor);
  if (memo.size() >= 16) memo.erase(memo.begin());
  memo.push_back({law, ball_mass_kg, cor, answer});
  return answer;
}

StaticLoop static_loop(const BallContactLaw& law, double force_N, double max_compression_m) {
  detail::require_positive("force_N", force_N, "N");
  detail::require_positive("max_compression_m", max_compression_m, "m");
  if (const std::string why = law.validate(); !why.empty())
    throw std::invalid_argument("law." + why);
  StaticLoop loop;
  if (law.form == BallLawForm::kPower) {
    loop.forward_deformation_m = std::pow(force_N / law.stiffness, 1.0 / law.exponent);
    loop.return_deformation_m = loop.forward_deformation_m;
    return loop;
  }
  // The relaxed ball: its wall alone, no shell, no stiffening, no damping;
  // a two-mass ball's internal spring G in series with it (at rest the two
  // halves carry the same force, and the ball's deformation is the sum of theirs).
  HystereticBallLaw relaxed = law.hysteretic;
  relaxed.shell_stiffness = relaxed.stiffening = relaxed.damping = 0.0;
  collision_detail::HystereticLaw ball(relaxed);
  const bool two = law.form == BallLawForm::kTwoMass;
  const double ki = law.body.internal_stiffness, k3 = law.body.internal_cubic_stiffness;
  // The internal spring's compression under a force f (G rises from 0).
  const auto inner = [&](double f) {
    if (!two || f <= 0.0) return 0.0;
    const auto excess = [&](double d) { return d * (ki + k3 * d * d) - f; };
    const double hi = f / ki;  // G(d) >= k_i d
    return brent_root(excess, 0.0, hi, -f, excess(hi), 1e-15 * hi);
  };
  // The wall's compression at max_compression_m in all.
  const auto rest = [&](double x) { return x + inner(ball.backbone(x)) - max_compression_m; };
  const double wall_max = two ? brent_root(rest, 0.0, max_compression_m, -max_compression_m,
                                           rest(max_compression_m), 1e-15 * max_compression_m)
                              : max_compression_m;
  if (!(ball.backbone(wall_max) >= force_N))
    throw std::invalid_argument("the relaxed ball reaches " +
                                detail::format_number(ball.backbone(wall_max)) +
                                " N at max_compression_m, short of force_N");
  // Where the branch in force (increasing in x) crosses force_N below `hi`.
  const auto crossing = [&](double hi) {
    const auto excess = [&](double x) { return ball.force(x) - force_N; };
    return brent_root(excess, 0.0, hi, -force_N, excess(hi), 1e-15 * hi);
  };
  const double inner_at_force = inner(force_N);
  loop.forward_deformation_m = crossing(wall_max) + inner_at_force;
  const double work_in = ball.backbone_work(wall_max);
  ball.commit(wall_max);
  loop.return_deformation_m = crossing(wall_max) + inner_at_force;
  // (The internal spring returns what it took: the loop is the wall's.)
  loop.loop_energy_J = work_in - ball.energy(wall_max);
  return loop;
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

using collision_detail::Ball;
using collision_detail::BallLaw;
using collision_detail::Bed;
using collision_detail::EnergyLedger;
using collision_detail::HystereticLaw;
using collision_detail::ModalState;
using collision_detail::PowerLaw;
using collision_detail::StepMesh;

// Every argument of collide() in its range, each problem named by its argument.
void check_arguments(const FrameAtImpact& frame, const std::optional<StringBedDynamics>& strings,
                     double ball_mass_kg, const BallContactLaw& ball_law, double speed_m_s,
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
}

// The ball force of the last two steps: the next force solve's first guess
// and the mesh's test for a falling force.
struct ForceHistory {
  double f_prev = 0.0, f_prev2 = 0.0, h_prev;
  // The last two forces extrapolated linearly over a step of length h.
  double guess(double h) const { return std::max(0.0, f_prev + (f_prev - f_prev2) * h / h_prev); }
  void push(double force, double h) {
    f_prev2 = f_prev;
    f_prev = force;
    h_prev = h;
  }
};

// The contacts: each crossing of x = 0, timed by linear interpolation in the step.
class Contacts {
 public:
  // A contact begins at the step's start if the ball touches there and closes in.
  void begin_step(double t, double x, double closing_speed) {
    if (!in_contact_ && x == 0.0 && closing_speed > 0.0) start_ = t;
  }
  double since_onset(double t) const { return t - start_; }

  // After a step of length h that ends at t and takes the compression from
  // x_old to x: true if the ball separated in it.
  bool end_step(double t, double h, double x_old, double x) {
    if (!in_contact_ && x > 0.0) {
      in_contact_ = true;
      ++count_;
      start_ = x_old <= 0.0 ? t - h + h * (-x_old) / (x - x_old) : t - h;
    } else if (in_contact_ && x <= 0.0) {
      in_contact_ = false;
      last_separation_ = t - h + h * x_old / (x_old - x);
      in_contact_s_ += last_separation_ - start_;
      return true;
    }
    return false;
  }
  // The run ends at t: a contact still on lasts until then.
  void end_run(double t) {
    if (in_contact_) last_separation_ = t;
  }

  bool in_contact() const { return in_contact_; }
  int count() const { return count_; }
  double last_separation() const { return last_separation_; }
  double in_contact_s() const { return in_contact_s_; }

 private:
  bool in_contact_ = false;
  int count_ = 0;
  double start_ = 0.0, last_separation_ = 0.0, in_contact_s_ = 0.0;
};

// The linear part (frame modes, string bed, ball) solved over a step of
// length h for the one unknown, the ball force F_b: the compression at the
// step's end x1 = a - c F_b and the string force F_s = P + Q F_b. (A
// two-mass ball's internal gradient g adds h A1 g to a: internal_part().)
struct LinearPart {
  double a, c, P = 0.0, Q = 1.0;
};

LinearPart linear_part(const Ball& ball, Ball::Start front, const Bed& bed, double B_w,
                       ModalState::Start modal, double h) {
  const double A_w = modal.A_w;
  LinearPart lp;
  if (bed.present) {
    const double kappa = bed.kappa, ms = bed.ms;
    const double D = 1.0 + kappa * (0.5 * h / ms + B_w);
    lp.P = (kappa * (bed.vs - A_w) + bed.ks * (bed.s - modal.w0)) / D;
    lp.Q = kappa * 0.5 * h / (ms * D);
    lp.a = ball.x + h * (front.A0 - bed.vs + 0.5 * h * lp.P / ms);
    lp.c = h * (front.B + 0.5 * h * (1.0 - lp.Q) / ms);
  } else {
    lp.a = ball.x + h * (front.A0 - A_w);
    lp.c = h * (front.B + B_w);
  }
  return lp;
}

// The string bed between F and F_s over the step, at its midpoint velocity
// (without strings s follows the frame point at w_dot_mid). Returns the
// bed's velocity relative to the frame point at the midpoint (0 without strings).
double move_bed(Bed& bed, double h, double F, double Fs, double w_dot_mid) {
  double vs_mid = w_dot_mid, rel = 0.0;
  if (bed.present) {
    vs_mid = bed.vs + 0.5 * h / bed.ms * (F - Fs);
    rel = vs_mid - w_dot_mid;
  }
  bed.s += h * vs_mid;
  bed.vs = 2.0 * vs_mid - bed.vs;
  return rel;
}

// The step's share of the impulse, the peaks and the force history, for a
// step from t of length h under F ending at compression x (the front's),
// the ball's centre of mass `centre` closer to the bed, and frame point w.
void record_step(const CollisionOptions& options, bool sampled, double t, double h, double F,
                 double x, double centre, const Bed& bed, double w, CollisionResult& res) {
  res.impulse_N_s += h * F;
  if (F > res.peak_force_N) res.peak_force_N = F;
  if (centre > res.peak_ball_compression_m) res.peak_ball_compression_m = centre;
  if (bed.present)
    res.peak_string_deflection_m =
        std::max(res.peak_string_deflection_m, x > 0.0 ? std::abs(bed.s - w) : 0.0);
  if (options.record_history && sampled) {
    res.time_s.push_back(t + 0.5 * h);
    res.force_N.push_back(F);
  }
}

// The velocities and momentum the result reports, from the state now.
void report_motion(const Ball& ball, const Bed& bed, const ModalState& modes,
                   double inverse_effective_mass, CollisionResult& res) {
  res.ball_velocity_after_m_s = ball.vy;
  res.frame_velocity_after_m_s = modes.rigid_velocity();
  res.implement_momentum_N_s = modes.rigid_momentum(inverse_effective_mass) + bed.ms * bed.vs;
  res.apparent_cor = -ball.vy / ball.v1;
}

// Gone for good? The vibration (modes and string bed relative to the rigid
// motion) moves the contact point by at most sqrt(2 E C), C the static
// compliance there, while the ball recedes from the rigid motion.
bool gone_for_good(const Ball& ball, const Bed& bed, const ModalState& modes, double compliance) {
  const double uF = modes.rigid_velocity();
  if (!(ball.vy - uF < 0.0)) return false;
  const double w = modes.displacement();
  double e_osc = modes.vibration_energy();
  if (bed.present)
    e_osc +=
        0.5 * bed.ks * (bed.s - w) * (bed.s - w) + 0.5 * bed.ms * (bed.vs - uF) * (bed.vs - uF);
  const double reach = std::sqrt(2.0 * e_osc * compliance);
  return ball.x + 2.0 * (reach + ball.internal_reach()) < 0.0;
}

// The step's ball force F and, for a two-mass ball, its internal spring's
// discrete gradient g: for a given g the force is solve_force()'s on the
// compression a + h A1 g - c F, and g must be the gradient from d to the
// internal compression that F and g leave, psi(g) = g - G(d, d1(F(g), g)) = 0.
// psi rises with slope >= 1 (a larger g pushes the front on, and F takes up
// less than all of it), so the root is unique and within |psi(g0)| of any g0.
struct BallForces {
  double F, g;
};
template <BallLaw Law>
BallForces solve_ball_forces(const Law& law, const Ball& ball, const Ball::Start& front,
                             const LinearPart& lp, double h, double guess, double force_floor,
                             double g_guess) {
  // (Each solve starts from the last one's force: the g's are close.)
  double last = guess;
  const auto force_at = [&](double g) {
    return last = collision_detail::solve_force(law, ball.x, ball.u_x, lp.a + h * front.A1 * g,
                                                lp.c, h, last, force_floor);
  };
  if (!ball.two_masses()) return {force_at(0.0), 0.0};
  const auto psi = [&](double g) {
    return g - ball.inner_gradient(ball.inner_end(h, force_at(g), g));
  };
  // Secant steps from g_guess and g_guess - psi (psi' >= 1: the root lies
  // between them), kept in the bracket; psi is nearly linear over a step, so
  // two or three evaluations usually do. Brent's method if they do not.
  double g0 = g_guess, p0 = psi(g0);
  if (p0 == 0.0) return {force_at(g0), g0};
  double g1 = g0 - p0, p1 = psi(g1);
  double lo = p0 < 0.0 ? g0 : g1, hi = p0 < 0.0 ? g1 : g0;
  double p_lo = p0 < 0.0 ? p0 : p1, p_hi = p0 < 0.0 ? p1 : p0;
  const double tol = 1e-14 * (std::abs(g0) + std::abs(g1) + force_floor);
  for (int it = 0; it < 8 && std::abs(p1) > tol; ++it) {
    if (p1 < 0.0 && g1 > lo) lo = g1, p_lo = p1;
    if (p1 > 0.0 && g1 < hi) hi = g1, p_hi = p1;
    const double next = g1 - p1 * (g1 - g0) / (p1 - p0);
    if (!(next > lo && next < hi)) break;
    g0 = g1, p0 = p1;
    g1 = next, p1 = psi(g1);
  }
  if (!(std::abs(p1) <= tol)) {
    if (p_lo > 0.0 || p_hi < 0.0) return {force_at(g1), g1};  // (round-off in the bracket)
    g1 = brent_root(psi, lo, hi, p_lo, p_hi, tol);
  }
  return {force_at(g1), g1};
}

// One run of the integrator (collision.hpp) at options' step, for any ball law.
// `law` by value: a law with a memory (HystereticLaw) moves it on after each
// step (commit()).
template <BallLaw Law>
CollisionResult integrate(const FrameAtImpact& frame,
                          const std::optional<StringBedDynamics>& strings, double m, Law law,
                          const BallBody& body, double v1, const CollisionOptions& options) {
  const StepMesh mesh(frame, strings, m, law, body, v1, options);
  const double inv_M = frame.inverse_effective_mass_per_kg;
  ModalState modes(frame);
  Ball ball(m, v1, body);
  Bed bed(strings, m);
  // The static compliance at the impact point: the modes and the string bed [m/N].
  double compliance = modes.static_compliance();
  if (bed.present) compliance += 1.0 / bed.ks;
  ForceHistory history{.h_prev = mesh.base_step()};
  EnergyLedger ledger;
  Contacts contacts;
  CollisionResult res;
  res.step_s = mesh.base_step();
  // Everything the result reports, from the state now. (The bodies, the
  // ledger and the time by value: the loop keeps them in registers.)
  auto snapshot = [&](const Ball b, const Bed d, const EnergyLedger l, double last_separation) {
    report_motion(b, d, modes, inv_M, res);
    l.report(b, d, modes, inv_M, res);
    res.contact_time_s = last_separation;
  };

  double t = 0.0, inner_gradient = 0.0;  // the last step's internal gradient
  long n = 0;
  // The force history keeps every step, or every stride-th where a contact
  // takes more than kHistoryPerContact steps (a stiff ball): bounded memory.
  constexpr double kHistoryPerContact = 1e5;
  const long stride =
      static_cast<long>(std::max(1.0, std::ceil(mesh.contact_steps() / kHistoryPerContact)));
  for (; n < mesh.max_steps() && t < options.max_time_s; ++n) {
    const double closing_speed = ball.front_velocity() - bed.vs;
    contacts.begin_step(t, ball.x, closing_speed);
    const double h = mesh.next({ball.x, closing_speed, contacts.since_onset(t), ball.x_dot,
                                history.f_prev, history.f_prev2, modes.step()});
    if (modes.set_step(h)) {
      bed.set_step(h);
      ball.set_step(h);
    }
    const ModalState::Start start = modes.begin_step();
    const Ball::Start front = ball.begin_step(h);
    const LinearPart lp = linear_part(ball, front, bed, modes.compliance_rate(), start, h);
    const auto [F, g] = solve_ball_forces(law, ball, front, lp, h, history.guess(h),
                                          mesh.force_floor(), inner_gradient);
    const double Fs = bed.present ? lp.P + lp.Q * F : F;
    // The linear part's update with the midpoint velocities.
    const ModalState::Advance modal = modes.advance(Fs);
    ledger.book_modal_damping(h, modal.damping_power);
    ledger.book_ball_internal_damping(h, ball.advance(h, F, g));
    inner_gradient = g;
    const double rel = move_bed(bed, h, F, Fs, modal.w_dot_mid);
    if (bed.present) ledger.book_strings(bed.cs, h, rel);
    const double x_old = ball.x, x_new = ball.front() - bed.s;
    if constexpr (requires { law.commit(x_new); }) law.commit(x_new);
    const double u_new = law.energy(x_new);
    ledger.book_ball(F, x_new - x_old, u_new - ball.u_x);
    record_step(options, n % stride == 0, t, h, F, x_new, ball.centre_compression(bed.s), bed,
                start.w0 + h * modal.w_dot_mid, res);
    ball.compress_to(x_new, u_new, h);
    history.push(F, h);
    t += h;
    if (contacts.end_step(t, h, x_old, x_new))
      snapshot(ball, bed, ledger, contacts.last_separation());
    if (!contacts.in_contact() && contacts.count() > 0 &&
        gone_for_good(ball, bed, modes, compliance)) {
      res.separated = true;
      ++n;
      break;
    }
  }
  res.steps = static_cast<int>(n);
  res.contacts = contacts.count();
  res.in_contact_s = contacts.in_contact_s();
  if (!res.separated) {
    contacts.end_run(t);
    snapshot(ball, bed, ledger, contacts.last_separation());
  }
  return res;
}

// One run at options' step of the law's form.
CollisionResult run(const FrameAtImpact& frame, const std::optional<StringBedDynamics>& strings,
                    double ball_mass_kg, const BallContactLaw& law, double speed_m_s,
                    const CollisionOptions& options) {
  check_arguments(frame, strings, ball_mass_kg, law, speed_m_s, options);
  if (is_hysteretic(law.form))
    return integrate(frame, strings, ball_mass_kg, HystereticLaw(law.hysteretic), law.body,
                     speed_m_s, options);
  return integrate(frame, strings, ball_mass_kg, PowerLaw(law), law.body, speed_m_s, options);
}

// (4 fine - coarse) / 3: the h^2 term of two runs at h and h/2 cancelled.
double extrapolated(double coarse, double fine) { return (4.0 * fine - coarse) / 3.0; }

// A lossless ball on an immovable support comes back at exactly its speed; the
// sum of a run's steps (and its extrapolation) can give it back 1e-15 more.
// Within kInvariantRoundOff of the incident energy that excess is the sums'
// round-off, not energy from nowhere: the ball keeps what it brought. (More
// is check_invariants()'s refusal.)
CollisionResult kept_within_its_energy(CollisionResult r) {
  const double excess_J = r.ball_out_J - r.ball_in_J;
  const double excess_cor = std::abs(r.apparent_cor) - 1.0;
  if ((excess_J > 0.0 && excess_J <= kInvariantRoundOff * r.ball_in_J) ||
      (excess_cor > 0.0 && excess_cor <= kInvariantRoundOff)) {
    const double v1 = -r.ball_velocity_after_m_s / r.apparent_cor;  // |e_A| is ~1 here
    r.apparent_cor = std::copysign(std::min(1.0, std::abs(r.apparent_cor)), r.apparent_cor);
    r.ball_velocity_after_m_s = -r.apparent_cor * v1;
    r.ball_out_J = std::min(r.ball_out_J, r.ball_in_J);
  }
  if (r.ball_loss_J < 0.0 && -r.ball_loss_J <= kInvariantRoundOff * r.ball_in_J)
    r.ball_loss_J = 0.0;
  return r;
}

}  // namespace

CollisionResult collide(const FrameAtImpact& frame, const std::optional<StringBedDynamics>& strings,
                        double ball_mass_kg, const BallContactLaw& law, double speed_m_s,
                        const CollisionOptions& options) {
  if (!options.extrapolate)
    return kept_within_its_energy(run(frame, strings, ball_mass_kg, law, speed_m_s, options));
  CollisionOptions o = options;
  o.extrapolate = false;
  o.record_history = false;
  const CollisionResult coarse = run(frame, strings, ball_mass_kg, law, speed_m_s, o);
  o.steps_per_contact *= 2;
  o.record_history = options.record_history;
  CollisionResult r = run(frame, strings, ball_mass_kg, law, speed_m_s, o);
  r.step_error = std::abs(r.apparent_cor - coarse.apparent_cor);
  // Only a smooth dependence on h extrapolates: the same number of contacts.
  if (coarse.contacts != r.contacts || coarse.separated != r.separated)
    return kept_within_its_energy(std::move(r));
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
  return kept_within_its_energy(std::move(r));
}

}  // namespace sweetspot
