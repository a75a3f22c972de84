// Oracles: conservation of momentum and energy, Cross (2004) Eq. (4) and the
// numbers of Sec. III, the Fourier transform of the half-sine, and an
// independent time-stepping integration of each modal equation.
#include "sweetspot/impact_response.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {
namespace {

constexpr double kPi = std::numbers::pi;
// Closed forms and identities hold to round-off (relative).
constexpr double kRoundOff = 1e-10;
// Composite Simpson over 4000 intervals of a smooth velocity field.
constexpr double kQuadrature = 1e-9;
// RK4 with 2e5 steps per pulse on the modal equation: error ~ (w h)^4.
constexpr double kTimeStepping = 1e-8;
// The paper prints positions to 1 mm.
constexpr double kHalfMillimetre = 0.5e-3;

// The experimental beam of Cross (2004) Sec. II: 0.72 m, 0.328 kg, uniform,
// EI from its measured free fundamental 193 Hz (Sec. III).
constexpr double kBeamLength = 0.72;
constexpr double kBeamMass = 0.328;
std::vector<Section> paper_beam_sections() {
  std::vector<Section> s{Section{kBeamLength, kBeamMass, 1.0}};
  s[0].EI_N_m2 = uniform_EI_for_fundamental(s, {}, 193.0);
  return s;
}
ResponseModel paper_beam_model(int modes = 6, double damping = 0.0) {
  ModeOptions options;
  options.modes = modes;
  const auto sections = paper_beam_sections();
  return free_response_model(sections, {}, free_modes(sections, {}, options), damping);
}

// The Table I racquet: 0.70 m, 0.25 kg, M1/M2 = 0.8, EI uniform for a free f1.
std::vector<Section> table_one_sections(double f1_Hz) {
  std::vector<Section> s = Implement::paper_racquet(0.70, 0.25, 0.8).sections();
  const double EI = uniform_EI_for_fundamental(s, {}, f1_Hz);
  for (Section& section : s) section.EI_N_m2 = EI;
  return s;
}
ResponseModel table_one_model(double f1_Hz) {
  ModeOptions options;
  options.modes = 6;
  const auto sections = table_one_sections(f1_Hz);
  return free_response_model(sections, {}, free_modes(sections, {}, options));
}
constexpr double kTableOneImpact = 0.65;  // 5 cm from the tip
constexpr double kTableOneDuration = 0.004;

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = a + (b - a) * i / (n - 1);
  return v;
}

// int_0^L f(x) dx by composite Simpson on `intervals` (even) intervals.
template <class F>
double simpson(const F& f, double length, int intervals) {
  const double h = length / intervals;
  double sum = f(0.0) + f(length);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return sum * h / 3.0;
}

// Classical RK4 on q'' + 2 z w q' + w^2 q = P sin(pi t / T) up to t_end.
ModalState integrate_modal(double w, double z, double P, double T, double t_end, int steps_per_T) {
  auto force = [&](double t) { return t <= T ? P * std::sin(kPi * t / T) : 0.0; };
  auto rhs = [&](double t, double q, double v) {
    return std::pair{v, force(t) - 2.0 * z * w * v - w * w * q};
  };
  double q = 0.0, v = 0.0, t = 0.0;
  const double h = T / steps_per_T;
  while (t < t_end - 0.5 * h) {
    // Land on the kink at t = T exactly.
    const double step = (t < T && t + h > T) ? T - t : std::min(h, t_end - t);
    const auto [k1q, k1v] = rhs(t, q, v);
    const auto [k2q, k2v] = rhs(t + step / 2, q + step / 2 * k1q, v + step / 2 * k1v);
    const auto [k3q, k3v] = rhs(t + step / 2, q + step / 2 * k2q, v + step / 2 * k2v);
    const auto [k4q, k4v] = rhs(t + step, q + step * k3q, v + step * k3v);
    q += step / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    v += step / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    t += step;
  }
  return {q, v};
}

TEST_CASE("The half-sine carries the impulse 2 F0 T / pi and delivers it as F0 T/pi (1 - cos)") {
  const HalfSinePulse pulse{1000.0, 0.004};
  CHECK(half_sine_impulse(pulse) == Approx(2.0 * 1000.0 * 0.004 / kPi).epsilon(kRoundOff));
  // Brute-force integral of F over the pulse.
  const double brute =
      simpson([&](double t) { return 1000.0 * std::sin(kPi * t / 0.004); }, 0.004, 2000);
  CHECK(brute == Approx(half_sine_impulse(pulse)).epsilon(kQuadrature));
  CHECK(half_sine_impulse_until(pulse, 0.002) ==
        Approx(0.5 * half_sine_impulse(pulse)).epsilon(kRoundOff));
  CHECK(half_sine_impulse_until(pulse, -1.0) == 0.0);
  CHECK(half_sine_impulse_until(pulse, 1.0) == half_sine_impulse(pulse));
  CHECK(half_sine_with_impulse(half_sine_impulse(pulse), 0.004).peak_force_N ==
        Approx(1000.0).epsilon(kRoundOff));
}

TEST_CASE("The closed-form modal response matches time stepping, on and off resonance") {
  constexpr double T = 0.004;
  struct Case {
    double f_Hz, zeta;
  };
  // 125 Hz is the resonance w T = pi of a 4 ms pulse.
  for (const Case c : {Case{125.0, 0.0}, Case{193.0, 0.0}, Case{60.0, 0.0}, Case{171.0, 0.10},
                       Case{30.0, 0.65}, Case{900.0, 0.02}}) {
    const double w = 2.0 * kPi * c.f_Hz;
    for (const double t : {0.3 * T, T, 1.7 * T, 5.0 * T}) {
      const ModalState closed = half_sine_modal_response(w, c.zeta, 3.0, T, t);
      const ModalState stepped = integrate_modal(w, c.zeta, 3.0, T, t, 200000);
      // Scale of the answer: q' ~ P T, q ~ P T^2 (not zero-crossing values).
      CHECK(std::abs(closed.q_dot - stepped.q_dot) < kTimeStepping * 3.0 * T);
      CHECK(std::abs(closed.q - stepped.q) < kTimeStepping * 3.0 * T * T);
    }
  }
}

// Once the start-up transient has decayed (sigma t >= 24 here), a mode far
// above the pulse moves as the steady forced response
// q = P sin(W t - phase) / sqrt((w^2 - W^2)^2 + (2 z w W)^2), W = pi/T.
constexpr double kSteadyState = 1e-6;

TEST_CASE(
    "A stiff damped mode follows the steady forced response, with no overflow however stiff") {
  constexpr double T = 0.004, P = 3.0, zeta = 0.01;
  const double W = kPi / T;
  for (const double w : {1e6, 1e8, 1e10}) {
    INFO("w = " << w << " rad/s, sigma T = " << zeta * w * T);
    const double amplitude = P / std::hypot(w * w - W * W, 2.0 * zeta * w * W);
    const double phase = std::atan2(2.0 * zeta * w * W, w * w - W * W);
    for (const double t : {0.6 * T, 0.8 * T}) {
      const ModalState s = half_sine_modal_response(w, zeta, P, T, t);
      CHECK(s.q == Approx(amplitude * std::sin(W * t - phase)).epsilon(kSteadyState));
      CHECK(s.q_dot == Approx(amplitude * W * std::cos(W * t - phase)).epsilon(kSteadyState));
    }
    // After the pulse the mode is left at rest to within its steady amplitude.
    const ModalState after = half_sine_modal_response(w, zeta, P, T, 3.0 * T);
    CHECK(std::isfinite(after.q));
    CHECK(std::abs(after.q_dot) < kSteadyState * amplitude * W);
  }
}

TEST_CASE(
    "Undamped, the closed form is the textbook sine response P (sin Wt - W/w sin wt)/(w^2 - W^2)") {
  constexpr double T = 0.004, P = 2.5;
  const double W = kPi / T, w = 2.0 * kPi * 193.0;
  for (const double t : {0.001, 0.0025, 0.004}) {
    const double q = P * (std::sin(W * t) - W / w * std::sin(w * t)) / (w * w - W * W);
    const double v = P * W * (std::cos(W * t) - std::cos(w * t)) / (w * w - W * W);
    const ModalState s = half_sine_modal_response(w, 0.0, P, T, t);
    CHECK(s.q == Approx(q).epsilon(kRoundOff));
    CHECK(s.q_dot == Approx(v).epsilon(kRoundOff).margin(kRoundOff * P * T));
  }
}

TEST_CASE("An undamped mode keeps 1/2 (J phi)^2 S(wT)^2, the half-sine's Fourier transform") {
  constexpr double T = 0.004, J = 2.0, phi = 3.0;
  const double F0 = half_sine_with_impulse(J, T).peak_force_N;
  for (const double f : {20.0, 100.0, 125.0, 125.0 * (1 + 1e-9), 193.0, 375.0, 506.0, 962.0}) {
    const double w = 2.0 * kPi * f;
    const ModalState end = half_sine_modal_response(w, 0.0, F0 * phi, T, T);
    const double energy = 0.5 * (end.q_dot * end.q_dot + w * w * end.q * end.q);
    // Brute-force |F^(w)|: the transform integrated numerically.
    const double re =
        simpson([&](double t) { return F0 * std::sin(kPi * t / T) * std::cos(w * t); }, T, 4000);
    const double im =
        simpson([&](double t) { return F0 * std::sin(kPi * t / T) * std::sin(w * t); }, T, 4000);
    const double brute = 0.5 * phi * phi * (re * re + im * im);
    const double closed = half_sine_residual_energy(J, phi, w, T);
    CHECK(energy == Approx(closed).epsilon(kRoundOff).margin(kRoundOff * J * J * phi * phi));
    CHECK(brute == Approx(closed).epsilon(kQuadrature).margin(kQuadrature * J * J * phi * phi));
  }
  // The first zero of the spectrum is f = 1.5/T, the paper's cut-off.
  CHECK(half_sine_spectrum_ratio(2.0 * kPi * 1.5 / T, T) < kRoundOff);
  CHECK(half_sine_spectrum_ratio(0.0, T) == 1.0);
  CHECK(half_sine_spectrum_ratio(kPi / T, T) == Approx(kPi / 4.0).epsilon(kRoundOff));
}

TEST_CASE("As the pulse gets short each mode's energy tends to the impulse limit 1/2 (J phi)^2") {
  const ResponseModel beam = paper_beam_model();
  const double J = 0.1;
  const double x = 0.65;
  double previous_gap = 1.0;
  for (const double T : {1e-3, 1e-4, 1e-5, 1e-6}) {
    const ImpactResponse r = impact_response(beam, x, half_sine_with_impulse(J, T), {}, {});
    double gap = 0.0;
    for (const ModeExcitation& m : r.modes) {
      CHECK(m.impulse_limit_energy_J == Approx(0.5 * J * J * m.phi_at_impact * m.phi_at_impact));
      gap = std::max(gap, std::abs(m.energy_after_J / m.impulse_limit_energy_J - 1.0));
    }
    CHECK(gap < previous_gap);
    previous_gap = gap;
  }
  // S = 1 - O((wT)^2): at T = 1 us the highest mode (~3.3 kHz, wT ~ 0.02) is within 1e-4.
  CHECK(previous_gap < 1e-4);
}

TEST_CASE("The implement gains exactly the impulse as momentum, and the vibration carries none") {
  const ResponseModel beam = paper_beam_model();
  const HalfSinePulse pulse{500.0, 0.008};  // the paper's 8 ms tennis-ball impact
  const std::vector<double> x = linspace(0.0, kBeamLength, 4001);
  const std::vector<double> t{0.002, 0.004, 0.008, 0.011, 0.05};
  const ImpactResponse r = impact_response(beam, 0.60, pulse, x, t);
  const double mu = kBeamMass / kBeamLength;
  for (std::size_t i = 0; i < t.size(); ++i) {
    auto field = [&](bool ac) {
      return simpson(
          [&](double s) {
            const auto k = static_cast<std::size_t>(std::lround(s / kBeamLength * 4000));
            return mu * (ac ? r.points[k].ac_m_s[i] : r.points[k].dc_m_s[i]);
          },
          kBeamLength, 4000);
    };
    const double delivered = half_sine_impulse_until(pulse, t[i]);
    CHECK(field(false) == Approx(delivered).epsilon(kQuadrature));
    CHECK(std::abs(field(true)) < kQuadrature * half_sine_impulse(pulse));
  }
  CHECK(r.impulse_N_s == Approx(2.0 * 500.0 * 0.008 / kPi).epsilon(kRoundOff));
}

TEST_CASE(
    "The dc velocity is Eq. 4 and vanishes 2 cm from the end for an impact 23.3 cm from the "
    "other") {
  const ResponseModel beam = paper_beam_model();
  const MassProperties body = beam.rigid_body;
  const double point = kBeamLength - 0.02;
  const HalfSinePulse pulse{100.0, 0.008};
  const std::vector<double> t = linspace(0.0, 0.02, 41);
  // Uniform beam: v M / J = 1 - 12 A b / L^2 with A = L/2 - x_P, b = x_F - L/2.
  for (const double impact : {0.05, 0.2, 0.36, 0.5}) {
    const ImpactResponse r = impact_response(beam, impact, pulse, {point}, t);
    const double A = kBeamLength / 2 - point, b = impact - kBeamLength / 2;
    const double per_impulse = (1.0 - 12.0 * A * b / (kBeamLength * kBeamLength)) / kBeamMass;
    for (std::size_t i = 0; i < t.size(); ++i) {
      CHECK(r.points[0].dc_m_s[i] == Approx(per_impulse * half_sine_impulse_until(pulse, t[i]))
                                         .epsilon(kRoundOff)
                                         .margin(1e-14));
    }
  }
  // The paper: the COP for the disk 2 cm from one end is 23.3 cm from the other.
  const double cop = *free_conjugate_from_butt(body, point);
  CHECK(cop == Approx(0.233).margin(kHalfMillimetre));
  const ImpactResponse at_cop = impact_response(beam, cop, pulse, {point}, t);
  for (std::size_t i = 0; i < t.size(); ++i) CHECK(std::abs(at_cop.points[0].dc_m_s[i]) < 1e-12);
  // ... but the beam still vibrates there (Fig. 3, d = 22 cm).
  double ac_peak = 0.0;
  for (double v : at_cop.points[0].ac_m_s) ac_peak = std::max(ac_peak, std::abs(v));
  CHECK(ac_peak > 1e-3 * half_sine_impulse(pulse) / kBeamMass);
}

TEST_CASE("A mode is absent when the ball hits its node, and invisible at its node") {
  const ResponseModel beam = paper_beam_model();
  const HalfSinePulse pulse{100.0, 0.002};
  const std::vector<double> t = linspace(0.0, 0.02, 81);
  // The fundamental's nodes: 0.2242 L from each end for a uniform free beam
  // (16.1 cm; the paper measured 15.8 cm, Sec. III).
  const std::vector<double>& nodes = beam.modes[0].mode.nodes_from_butt_m;
  REQUIRE(nodes.size() == 2);
  CHECK(kBeamLength - nodes[1] == Approx(0.2242 * kBeamLength).margin(kHalfMillimetre));
  const ImpactResponse r = impact_response(beam, nodes[1], pulse, {0.70, 0.16}, t);
  CHECK(r.modes[0].energy_after_J < kRoundOff * r.modes[1].energy_after_J);
  for (const PointVelocity& p : r.points) {
    for (double v : p.mode_m_s[0]) CHECK(std::abs(v) < 1e-12);
  }
  // Observed at a node of the second mode, the second mode contributes nothing.
  const double node2 = beam.modes[1].mode.nodes_from_butt_m[0];
  const ImpactResponse seen = impact_response(beam, 0.70, pulse, {node2}, t);
  double mode1_peak = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    CHECK(std::abs(seen.points[0].mode_m_s[1][i]) < 1e-12);
    mode1_peak = std::max(mode1_peak, std::abs(seen.points[0].mode_m_s[0][i]));
  }
  CHECK(mode1_peak > 1e-3);
}

TEST_CASE("Modes above 1.5/T keep less than 1/64 of their impulse-limit energy") {
  // The paper's beam hit by an 8 ms tennis ball: 1.5/T = 187.5 Hz, so every
  // mode, even the 193 Hz fundamental, is above the cut-off.
  const ResponseModel beam = paper_beam_model();
  const double T = 0.008;
  const ImpactResponse r = impact_response(beam, 0.65, half_sine_with_impulse(0.1, T), {}, {});
  for (const ModeExcitation& m : r.modes) {
    REQUIRE(m.frequency_Hz > 1.5 / T);
    // S <= 1 / ((2 f T)^2 - 1) <= 1/8 above the cut-off, so at most 1/64 of the impulse limit.
    const double r_ft = 2.0 * m.frequency_Hz * T;
    CHECK(m.energy_after_J <=
          m.impulse_limit_energy_J / ((r_ft * r_ft - 1) * (r_ft * r_ft - 1)) * (1 + kRoundOff));
    CHECK(m.energy_after_J <= m.impulse_limit_energy_J / 64.0);
  }
  // A golf ball (1.5 ms, Sec. III) excites the second mode (measured 506 Hz,
  // 532 Hz here) strongly: below 1.5/T = 1 kHz it keeps S^2 = 0.31 of its
  // impulse-limit energy, twenty times the most a mode above the cut-off keeps.
  const ImpactResponse golf =
      impact_response(beam, 0.65, half_sine_with_impulse(0.1, 0.0015), {}, {});
  CHECK(golf.modes[1].frequency_Hz < 1.5 / 0.0015);
  CHECK(golf.modes[1].energy_after_J > 0.25 * golf.modes[1].impulse_limit_energy_J);
}

TEST_CASE("The ball's energy is its rebound, the rigid motion, the vibration and the string loss") {
  const ResponseModel racquet = table_one_model(150.0);
  const Ball ball{0.057, 50.0};
  const DerivedCor d = derive_cor(racquet, kTableOneImpact, 0.85, ball, kTableOneDuration);
  // Run the response with the derived force and add up the energies independently.
  const ImpactResponse r = impact_response(racquet, kTableOneImpact, d.pulse, {}, {});
  const RigidKick kick = free_kick(racquet.rigid_body, kTableOneImpact);
  const double V = kick.com_velocity_per_impulse * r.impulse_N_s;
  const double omega = kick.angular_velocity_per_impulse * r.impulse_N_s;
  const double rigid = 0.5 * racquet.rigid_body.mass_kg * V * V +
                       0.5 * racquet.rigid_body.I_cm_kg_m2 * omega * omega;
  CHECK(rigid == Approx(r.rigid_kinetic_energy_J).epsilon(kRoundOff));
  const double rebound = d.apparent_cor * ball.speed_m_s;
  const double before = 0.5 * ball.mass_kg * ball.speed_m_s * ball.speed_m_s;
  const double after = 0.5 * ball.mass_kg * rebound * rebound;
  CHECK(before == Approx(after + rigid + r.vibration_energy_J + d.rigid_loss_J).epsilon(kRoundOff));
  CHECK(r.vibration_energy_J == Approx(d.vibration_energy_J).epsilon(kRoundOff));
  CHECK(d.vibration_share == Approx(r.vibration_energy_J / before).epsilon(kRoundOff));
  // The impulse the response delivers is the ball's change of momentum.
  CHECK(r.impulse_N_s == Approx(ball.mass_kg * (ball.speed_m_s + rebound)).epsilon(kRoundOff));
}

TEST_CASE("The closed-form COR is the fixed point of the force-vibration loop") {
  const ResponseModel racquet = table_one_model(120.0);
  const Ball ball{0.057, 50.0};
  const DerivedCor d = derive_cor(racquet, kTableOneImpact, 0.85, ball, kTableOneDuration);
  // Iterate: COR -> F0 (Eqs. 15-16) -> vibration energy -> COR.
  const double mu = d.reduced_mass_kg;
  double e = 0.85;
  for (int i = 0; i < 200; ++i) {
    const double eA = apparent_cor(e, d.effective_mass_kg, ball.mass_kg);
    const HalfSinePulse p{peak_impact_force(ball.mass_kg, ball.speed_m_s, eA, kTableOneDuration),
                          kTableOneDuration};
    const double vib = impact_response(racquet, kTableOneImpact, p, {}, {}).vibration_energy_J;
    e = std::sqrt(0.85 * 0.85 - 2.0 * vib / (mu * ball.speed_m_s * ball.speed_m_s));
  }
  CHECK(e == Approx(d.cor).epsilon(kRoundOff));
}

TEST_CASE("The derived COR rises to cor_rigid as the frame becomes stiff") {
  const Ball ball{0.057, 50.0};
  double previous = 0.0;
  for (const double f1 : {80.0, 120.0, 180.0, 250.0, 350.0}) {
    const double e =
        derive_cor(table_one_model(f1), kTableOneImpact, 0.85, ball, kTableOneDuration).cor;
    CHECK(e > previous);
    CHECK(e < 0.85);
    previous = e;
  }
  // EI x 1e6 (f1 x 1000) recomputed from scratch: within 1e-9 of cor_rigid.
  const DerivedCor stiff =
      derive_cor(table_one_model(150e3), kTableOneImpact, 0.85, ball, kTableOneDuration);
  CHECK(stiff.cor == Approx(0.85).margin(1e-9));
  CHECK(stiff.vibration_share < 1e-9);
  // A frame with no modes at all is rigid.
  ResponseModel rigid = table_one_model(150.0);
  rigid.modes.clear();
  CHECK(derive_cor(rigid, kTableOneImpact, 0.85, ball, kTableOneDuration).cor ==
        Approx(0.85).epsilon(kRoundOff));
}

TEST_CASE("Scaling the fundamental matches recomputing the modes with scaled EI") {
  // The exact solver's fifth and sixth roots carry ~1e-9 (cosh(beta L) conditioning).
  constexpr double kExactHighModes = 1e-8;
  const ResponseModel base = table_one_model(150.0);
  const ResponseModel scaled = with_fundamental(base, 110.0);
  const ResponseModel direct = table_one_model(110.0);
  for (std::size_t k = 0; k < base.modes.size(); ++k) {
    CHECK(scaled.modes[k].omega_rad_s ==
          Approx(direct.modes[k].omega_rad_s).epsilon(kExactHighModes));
    CHECK(mass_normalised_shape(scaled.modes[k], 0.65) ==
          Approx(mass_normalised_shape(direct.modes[k], 0.65)).epsilon(10 * kExactHighModes));
  }
}

TEST_CASE("Exact and finite-element free modes give the same mass-normalised shapes") {
  const auto sections = table_one_sections(150.0);
  ModeOptions exact;
  exact.modes = 4;
  ModeOptions fe = exact;
  fe.method = ModeOptions::Method::kFiniteElement;
  fe.rel_tol = 1e-8;
  const ResponseModel a =
      free_response_model(sections, {{0.6, 0.01}}, free_modes(sections, {{0.6, 0.01}}, exact));
  const ResponseModel b =
      free_response_model(sections, {{0.6, 0.01}}, free_modes(sections, {{0.6, 0.01}}, fe));
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    for (const double x : {0.0, 0.3, 0.65, 0.7}) {
      // FE shapes converge like the frequencies: ~1e-6 on the fourth mode.
      CHECK(mass_normalised_shape(a.modes[k], x) ==
            Approx(mass_normalised_shape(b.modes[k], x)).margin(1e-5));
    }
  }
}

TEST_CASE(
    "With cor_rigid 0.85 a 255 Hz and a 137 Hz Table I racquet give the paper's 0.8 and 0.6") {
  // cor_rigid 0.85, T = 4 ms, 5 cm from the tip: see impact_response.hpp.
  const ResponseModel racquet = table_one_model(150.0);
  const Ball ball{0.057, 50.0};
  const auto stiff =
      fundamental_for_cor(racquet, kTableOneImpact, 0.85, ball, kTableOneDuration, 0.8, 50, 370);
  const auto flexible =
      fundamental_for_cor(racquet, kTableOneImpact, 0.85, ball, kTableOneDuration, 0.6, 50, 370);
  REQUIRE(stiff);
  REQUIRE(flexible);
  // Regression values of this model (Hz); the root is found to 1e-6 Hz.
  CHECK(*stiff == Approx(254.70).margin(0.01));
  CHECK(*flexible == Approx(136.53).margin(0.01));
  // At e = 0.8 the force is the paper's Table I row 1, 1117 N.
  const DerivedCor d =
      derive_cor(with_fundamental(racquet, *stiff), kTableOneImpact, 0.85, ball, kTableOneDuration);
  CHECK(d.pulse.peak_force_N == Approx(1117.0).margin(0.5));
  const DerivedCor f = derive_cor(with_fundamental(racquet, *flexible), kTableOneImpact, 0.85, ball,
                                  kTableOneDuration);
  CHECK(f.pulse.peak_force_N == Approx(993.0).margin(0.5));
}

TEST_CASE(
    "Held in the hand, the vibration dies away and leaves the rigid motion of implement plus "
    "hand") {
  Design design{Implement::paper_racquet(0.70, 0.25, 0.8)};
  design.stiffness.fundamental_free_Hz = 150.0;
  ResponseOptions options;
  options.support = ResponseOptions::Support::kHandHeld;
  options.modes = 4;
  options.rel_tol = 1e-4;
  const ResponseModel held = response_model(design, options);
  REQUIRE(held.hand_held);
  CHECK(held.rigid_body.mass_kg == Approx(0.75).epsilon(kRoundOff));
  const HalfSinePulse pulse{1000.0, 0.004};
  const ImpactResponse r = impact_response(held, 0.65, pulse, {0.02, 0.16}, {0.004, 2.0});
  for (const PointVelocity& p : r.points) {
    // Every mode is damped by the grip: after 2 s nothing is left.
    CHECK(std::abs(p.ac_m_s[1]) < 1e-9);
    CHECK(p.dc_m_s[1] ==
          Approx(point_velocity_per_impulse(held.rigid_body, 0.65, p.from_butt_m) * r.impulse_N_s)
              .epsilon(kRoundOff));
  }
  for (const ResponseMode& m : held.modes) CHECK(m.damping_ratio > 0.0);
  CHECK(r.vibration_energy_J > 0.0);
}

TEST_CASE("A microgram implement held in the hand has a finite response at every point and time") {
  const std::vector<Section> sections{Section{0.7, 1e-9, 152.0}};
  ModeOptions options;
  options.method = ModeOptions::Method::kFiniteElement;
  options.modes = 6;
  const HandCoupling hand = calibrated_hand();
  const ResponseModel held =
      hand_held_response_model(sections, {}, hand, hand_held_modes(sections, {}, hand, options));
  REQUIRE(held.modes.size() == 6);
  const HalfSinePulse pulse{1000.0, 0.004};
  std::vector<double> times, points;
  for (int i = 0; i <= 100; ++i) times.push_back(0.05 * i / 100);
  for (int i = 0; i <= 7; ++i) points.push_back(0.7 * i / 7);
  for (const double impact : {0.05, 0.35, 0.65}) {
    const ImpactResponse r = impact_response(held, impact, pulse, points, times);
    for (const PointVelocity& p : r.points) {
      for (std::size_t i = 0; i < times.size(); ++i) {
        INFO("impact " << impact << " m, point " << p.from_butt_m << " m, t " << times[i] << " s");
        REQUIRE(std::isfinite(p.ac_m_s[i]));
        // The dc part is Eq. (4) for implement plus hand.
        CHECK(p.dc_m_s[i] ==
              Approx(point_velocity_per_impulse(held.rigid_body, impact, p.from_butt_m) *
                     half_sine_impulse_until(pulse, times[i]))
                  .epsilon(kRoundOff));
      }
    }
    CHECK(std::isfinite(r.vibration_energy_J));
  }
}

TEST_CASE("Bad arguments are refused with the argument's name") {
  const ResponseModel beam = paper_beam_model(2);
  CHECK_THROWS_WITH(impact_response(beam, 0.8, {1.0, 0.004}, {}, {}),
                    Catch::Contains("impact_from_butt_m"));
  CHECK_THROWS_WITH(impact_response(beam, 0.3, {1.0, 0.0}, {}, {}),
                    Catch::Contains("pulse.duration_s"));
  CHECK_THROWS_WITH(impact_response(beam, 0.3, {1.0, 0.004}, {-0.1}, {}),
                    Catch::Contains("points_from_butt_m"));
  CHECK_THROWS_WITH(half_sine_modal_response(100.0, 1.0, 1.0, 0.004, 0.001),
                    Catch::Contains("damping_ratio"));
  CHECK_THROWS_WITH(derive_cor(beam, 0.3, 1.2, Ball{}, 0.004), Catch::Contains("cor_rigid"));
  CHECK_THROWS_WITH(derive_cor(beam, 0.3, 0.85, Ball{0.0, 50.0}, 0.004),
                    Catch::Contains("ball.mass_kg"));
  Design no_hand{Implement::paper_racquet(0.70, 0.25, 0.8)};
  no_hand.stiffness.fundamental_free_Hz = 150.0;
  no_hand.hand.mass_kg = 0.0;
  ResponseOptions options;
  options.support = ResponseOptions::Support::kHandHeld;
  CHECK_THROWS_WITH(response_model(no_hand, options), Catch::Contains("hand/mass_kg"));
}

}  // namespace
}  // namespace sweetspot
