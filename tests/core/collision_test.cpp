// Oracles for the solved collision: the energy ledger and the momentum
// balance (identities of the discrete-gradient step), closed forms of a linear
// ball, the rigid-surface measurements the ball is calibrated to, the
// prescribed-pulse model where it is valid, observed orders of convergence,
// and published measurements on racquets (each cited where it is used).
#include "sweetspot/collision.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {
namespace {

constexpr double kPi = std::numbers::pi;
// The ledger and the momentum balance are identities of the step: round-off
// over a few thousand steps (relative to the ball's energy / momentum).
constexpr double kRoundOff = 1e-11;
// Extrapolated runs at the default step: the COR to ~1e-6 (see the convergence test).
constexpr double kStepError = 5e-6;
constexpr double kBall_kg = kTennisBallMass_kg;
// ITF rules: a ball dropped 100 in (2.54 m) onto concrete must rebound 53-58 in
// (1.35-1.47 m), e = sqrt(h2/h1) = 0.729-0.761 (Cross, "Dynamic properties of
// tennis balls", Sports Eng. 2, 23-33, 1999, quoting the ITF's rules).
const double kDropSpeed = std::sqrt(2.0 * 9.81 * 2.54);
const double kItfCorLow = std::sqrt(1.35 / 2.54), kItfCorHigh = std::sqrt(1.47 / 2.54);

double ledger_residual(const CollisionResult& r) {
  return r.ball_in_J -
         (r.ball_out_J + r.implement_rigid_J + r.vibration_J + r.ball_loss_J + r.strings_loss_J);
}

// designs/racquets/tour-100.json: a 27 in, 305 g racquet, balance 32.5 cm,
// swingweight 320 kg cm^2, free fundamental 155 Hz (typical strung specs).
Design tour_100() {
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  d.stiffness.fundamental_free_Hz = 155.0;
  d.impact_from_butt_m = d.implement.length_m() - 0.16;
  return d;
}
ResponseModel tour_100_model(int modes = 6) {
  ResponseOptions o;
  o.modes = modes;
  return response_model(tour_100(), o);
}
StringBedDynamics strings_at(double tension_N, double mass_kg = kStringBedMass_kg,
                             double damping_ratio = kStringBedDampingRatio) {
  StringBed bed;
  bed.tension_N = tension_N;
  return string_bed_dynamics(bed, mass_kg, damping_ratio);
}
// A uniform 0.25 kg beam of EI 152 N m^2 hit 5 cm from its tip (the
// implements on which the prescribed pulse breaks down, evaluate_test.cpp).
FrameAtImpact long_beam(double length_m, int modes) {
  Design d{Implement::from_sections({Section{length_m, 0.25, {}}}, {})};
  d.stiffness.EI_N_m2 = 152.0;
  ResponseOptions o;
  o.modes = modes;
  return frame_at_impact(response_model(d, o), length_m - 0.05);
}

TEST_CASE("The calibrated tennis ball bounces off a rigid surface as the ITF's rules require") {
  const CollisionResult r =
      collide(rigid_frame(), std::nullopt, kBall_kg, kTennisBallLaw, kDropSpeed);
  CHECK(r.separated);
  CHECK(r.apparent_cor >= kItfCorLow);
  CHECK(r.apparent_cor <= kItfCorHigh);
  // The calibration targets: the middle of the band, 4.5 ms of contact (tennis
  // balls on rigid surfaces: 4-5 ms, Cross 1999 above).
  CHECK(r.apparent_cor == Approx(0.745).margin(1e-4));
  CHECK(r.contact_time_s == Approx(4.5e-3).margin(1e-6));
  // A plausible squeeze of a 65 mm ball: about 1 cm at the drop test's speed.
  CHECK(r.peak_ball_compression_m > 0.005);
  CHECK(r.peak_ball_compression_m < 0.015);
}

TEST_CASE(
    "The ball's COR falls and its contact shortens as it hits harder, never squashing it flat") {
  // Haake, Carre & Goodwill, J. Sports Sci. 21, 839-850 (2003): the COR of
  // tennis balls on a rigid surface falls with impact speed, their dynamic
  // stiffness rises.
  double previous_cor = 1.0, previous_time = 1.0;
  for (const double v : {3.0, 7.0, 15.0, 30.0, 50.0}) {
    INFO(v << " m/s");
    const CollisionResult r = collide(rigid_frame(), std::nullopt, kBall_kg, kTennisBallLaw, v);
    CHECK(r.apparent_cor < previous_cor);
    CHECK(r.contact_time_s < previous_time);
    CHECK(r.peak_ball_compression_m < 0.7 * kTennisBallDiameter_m);
    previous_cor = r.apparent_cor;
    previous_time = r.contact_time_s;
  }
}

// ------------------------------------------------------------ the hysteretic ball

// The force history's value at t (the step whose midpoint is last at or before t).
double force_at(const CollisionResult& r, double t) {
  double f = 0.0;
  for (std::size_t i = 0; i < r.time_s.size() && r.time_s[i] <= t; ++i) f = r.force_N[i];
  return f;
}

TEST_CASE("The drop test's speed is sqrt(2 g h) of the ITF's 100 in") {
  CHECK(kDropTestSpeed_m_s == Approx(kDropSpeed).epsilon(1e-10));
}

TEST_CASE("The hysteretic ball meets its calibration on a rigid surface") {
  CollisionOptions o;
  o.record_history = true;
  const CollisionResult r =
      collide(rigid_frame(), std::nullopt, kBall_kg, kHystereticTennisBallLaw, kDropSpeed, o);
  CHECK(r.separated);
  CHECK(r.apparent_cor == Approx(0.745).margin(1e-4));
  // About 6 mm of compression, half the peak force in the first 200 us
  // (Cross, Sports Eng. 2, 1999).
  CHECK(r.peak_ball_compression_m == Approx(6.0e-3).margin(1e-5));
  CHECK(force_at(r, 200e-6) >= 0.5 * r.peak_force_N);
  // At 30 m/s: the power law's COR, a shorter contact (the dynamic stiffness
  // rises with speed, Haake et al. 2003), a squeeze under 25 mm.
  const CollisionResult fast =
      collide(rigid_frame(), std::nullopt, kBall_kg, kHystereticTennisBallLaw, 30.0);
  CHECK(fast.apparent_cor == Approx(0.680).margin(1e-4));
  CHECK(fast.contact_time_s < 0.9 * r.contact_time_s);
  CHECK(fast.peak_ball_compression_m < 0.025);
  // The COR falls with speed over the range the power law's test covers.
  double previous = 1.0;
  for (const double v : {3.0, 7.0, 15.0, 30.0, 50.0}) {
    INFO(v << " m/s");
    const double e =
        collide(rigid_frame(), std::nullopt, kBall_kg, kHystereticTennisBallLaw, v).apparent_cor;
    CHECK(e < previous);
    previous = e;
  }
}

TEST_CASE("The hysteretic ball's ledger closes, and its limits are an elastic and a plastic ball") {
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  for (const double from_tip : {0.04, 0.16}) {
    for (const double v : {7.0, 50.0}) {
      INFO(from_tip << " m from the tip, " << v << " m/s");
      const CollisionResult r = collide(frame_at_impact(racquet, L - from_tip), strings_at(250.0),
                                        kBall_kg, kHystereticTennisBallLaw, v);
      CHECK(std::abs(ledger_residual(r)) <= kRoundOff * r.ball_in_J);
      CHECK(r.ball_loss_J > 0.0);
    }
  }
  // Every branch elastic (the shell's share made negligible) and no damping:
  // the ball returns its energy to round-off.
  BallContactLaw elastic = kHystereticTennisBallLaw;
  elastic.hysteretic.shell_stiffness = 1e-6;
  elastic.hysteretic.damping = 0.0;
  elastic.hysteretic.unloading_offset = -100.0;  // every exponent at its minimum
  const CollisionResult bounce = collide(rigid_frame(), std::nullopt, kBall_kg, elastic, 20.0);
  CHECK(bounce.apparent_cor == Approx(1.0).margin(1e-9));
  CHECK(bounce.ball_loss_J == Approx(0.0).margin(1e-9 * bounce.ball_in_J));
  // The dead limit: a plastic ball stops on a rigid surface and keeps nothing
  // but the step's share: its force drops from the backbone to 0 at the turn,
  // inside a step, and the velocity that step leaves (under 0.5 % of the
  // incoming) is all it takes back.
  BallContactLaw plastic = kHystereticTennisBallLaw;
  plastic.hysteretic.unloading_offset = std::numeric_limits<double>::infinity();
  CollisionOptions o;
  o.max_time_s = 0.02;
  const CollisionResult dead = collide(rigid_frame(), std::nullopt, kBall_kg, plastic, 7.0, o);
  CHECK(dead.apparent_cor >= 0.0);
  CHECK(dead.apparent_cor < 5e-3);
  CHECK(dead.ball_loss_J >= (1.0 - 25e-6) * dead.ball_in_J);
  CHECK(std::abs(ledger_residual(dead)) <= kRoundOff * dead.ball_in_J);
}

TEST_CASE("A ball given by its COR on a rigid surface: each law's loss solved to it") {
  for (const BallContactLaw& law : {kTennisBallLaw, kHystereticTennisBallLaw}) {
    for (const double cor : {0.5, 0.7, 0.78}) {
      INFO(to_string(law.form) << " at " << cor);
      const BallContactLaw solved = with_rigid_surface_cor(law, kBall_kg, cor);
      CHECK(rigid_surface_cor(solved, kBall_kg) == Approx(cor).margin(1e-8));
      // Only the loss moves: the power law's damping, the hysteretic ball's offset.
      CHECK(solved.stiffness == law.stiffness);
      CHECK(solved.hysteretic.shell_stiffness == law.hysteretic.shell_stiffness);
    }
  }
  // A dead hysteretic ball is plastic; outside each law's reach, a refusal naming the field.
  CHECK(std::isinf(
      with_rigid_surface_cor(kHystereticTennisBallLaw, kBall_kg, 0.0).hysteretic.unloading_offset));
  CHECK_THROWS_WITH(with_rigid_surface_cor(kHystereticTennisBallLaw, kBall_kg, 0.95),
                    Catch::Contains("ball/cor_on_rigid_surface") && Catch::Contains("at most"));
  CHECK_THROWS_WITH(with_rigid_surface_cor(kTennisBallLaw, kBall_kg, 0.1),
                    Catch::Contains("ball/cor_on_rigid_surface") && Catch::Contains("at least"));
  CHECK_THROWS_WITH(with_rigid_surface_cor(kTennisBallLaw, kBall_kg, 1.0),
                    Catch::Contains("[0, 1)"));
}

TEST_CASE("The hysteretic ball keeps the racquet's published rows: e_A along the strings") {
  // The same oracles as the power law's below: Cross (2004) Sec. VI's "about
  // 0.4" mid-strings and "about 0.1" near the tip, and the lower tension's
  // faster return (Bower & Cross 2005).
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  const auto e_A = [&](double from_tip, double tension) {
    return collide(frame_at_impact(racquet, L - from_tip), strings_at(tension), kBall_kg,
                   kHystereticTennisBallLaw, 50.0)
        .apparent_cor;
  };
  CHECK(e_A(0.16, 250.0) > 0.3);
  CHECK(e_A(0.16, 250.0) < 0.5);
  CHECK(e_A(0.04, 250.0) > 0.0);
  CHECK(e_A(0.04, 250.0) < 0.2);
  CHECK(e_A(0.16, 180.0) > e_A(0.16, 280.0));
}

// ------------------------------------------------------------ the two-mass ball

TEST_CASE("The two-mass ball meets its calibration on a rigid surface, its contact 4.5 ms") {
  CollisionOptions o;
  o.record_history = true;
  const CollisionResult r =
      collide(rigid_frame(), std::nullopt, kBall_kg, kTwoMassTennisBallLaw, kDropSpeed, o);
  CHECK(r.separated);
  CHECK(r.contacts == 1);
  // The drop test's COR; about 6 mm of compression (the force integrated
  // twice over the mass: the centre's travel), 4-5 ms of contact and half the
  // peak force in the first 200 us (Cross, Sports Eng. 2, 1999).
  CHECK(r.apparent_cor == Approx(0.745).margin(1e-5));
  CHECK(r.peak_ball_compression_m == Approx(6.0e-3).margin(1e-6));
  CHECK(r.contact_time_s == Approx(4.5e-3).margin(1e-6));
  CHECK(force_at(r, 200e-6) >= 0.5 * r.peak_force_N);
  // At 30 m/s: the power law's COR, a shorter contact, a squeeze under 25 mm.
  const CollisionResult fast =
      collide(rigid_frame(), std::nullopt, kBall_kg, kTwoMassTennisBallLaw, 30.0);
  CHECK(fast.apparent_cor == Approx(0.680).margin(1e-5));
  CHECK(fast.contact_time_s < 0.9 * r.contact_time_s);
  CHECK(fast.peak_ball_compression_m < 0.025);
  double previous = 1.0;
  for (const double speed : {3.0, 7.0, 15.0, 30.0, 50.0}) {
    INFO(speed << " m/s");
    const double e =
        collide(rigid_frame(), std::nullopt, kBall_kg, kTwoMassTennisBallLaw, speed).apparent_cor;
    CHECK(e < previous);
    previous = e;
  }
}

// The ball's centre's travel towards the surface when it separates: the
// force history integrated twice over the ball's mass by the integrator's own
// midpoint rule (history times are the steps' midpoints, from t = 0).
double centre_at_separation(const CollisionResult& r, double mass_kg, double speed) {
  double t = 0.0, v = speed, y = 0.0;
  for (std::size_t i = 0; i < r.time_s.size(); ++i) {
    const double h = 2.0 * (r.time_s[i] - t);
    const double v_next = v - h * r.force_N[i] / mass_kg;
    const double y_next = y + 0.5 * h * (v + v_next);
    if (t + h >= r.contact_time_s) return y + (r.contact_time_s - t) / h * (y_next - y);
    t += h;
    v = v_next;
    y = y_next;
  }
  return y;
}

TEST_CASE("The two-mass ball leaves a rigid surface still compressed, which one mass cannot") {
  // Cross, "The bounce of a ball", Am. J. Phys. 67, 222 (1999): every ball
  // he dropped "rebounds in a compressed state", its centre's displacement
  // still finite when the force ends. A ball of one mass leaves where it
  // touched: its compression is its centre's.
  CollisionOptions o;
  o.record_history = true;
  o.extrapolate = false;
  const CollisionResult two =
      collide(rigid_frame(), std::nullopt, kBall_kg, kTwoMassTennisBallLaw, kDropSpeed, o);
  const CollisionResult one =
      collide(rigid_frame(), std::nullopt, kBall_kg, kHystereticTennisBallLaw, kDropSpeed, o);
  CHECK(centre_at_separation(two, kBall_kg, kDropSpeed) > 0.2e-3);
  CHECK(std::abs(centre_at_separation(one, kBall_kg, kDropSpeed)) < 1e-3 * 6.0e-3);
  // The history integrates to the reported speed: the same midpoint rule.
  double v = kDropSpeed, t = 0.0;
  for (std::size_t i = 0; i < two.time_s.size(); ++i) {
    const double h = 2.0 * (two.time_s[i] - t);
    v -= h * two.force_N[i] / kBall_kg;
    t += h;
  }
  CHECK(v == Approx(two.ball_velocity_after_m_s).epsilon(1e-9));
}

TEST_CASE("The two-mass ball keeps the racquet's apparent COR along the strings") {
  // Cross (2004) Sec. VI: "about 0.4" mid-strings (fitted) and "about 0.1"
  // near the tip (checked); the lower tension's faster return.
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  const auto e_A = [&](double from_tip, double tension) {
    return collide(frame_at_impact(racquet, L - from_tip), strings_at(tension), kBall_kg,
                   kTwoMassTennisBallLaw, 50.0)
        .apparent_cor;
  };
  CHECK(e_A(0.16, 250.0) == Approx(0.40).margin(1e-3));
  CHECK(e_A(0.04, 250.0) > 0.0);
  CHECK(e_A(0.04, 250.0) < 0.2);
  CHECK(e_A(0.16, 180.0) > e_A(0.16, 280.0));
}

TEST_CASE(
    "The two-mass ball's ledger closes, its ring is its loss, and stiff halves are one mass") {
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  for (const double from_tip : {0.04, 0.16}) {
    for (const double speed : {7.0, 50.0}) {
      for (const bool extrapolate : {true, false}) {
        INFO(from_tip << " m from the tip, " << speed << " m/s, extrapolated " << extrapolate);
        CollisionOptions o;
        o.extrapolate = extrapolate;
        const CollisionResult r = collide(frame_at_impact(racquet, L - from_tip), strings_at(250.0),
                                          kBall_kg, kTwoMassTennisBallLaw, speed, o);
        CHECK(r.separated);
        CHECK(std::abs(ledger_residual(r)) <= kRoundOff * r.ball_in_J);
        CHECK(r.ball_loss_J > 0.0);
      }
    }
  }
  // No loss anywhere (an elastic contact, no dashpot inside): what the ball
  // brought is what it leaves with plus what its halves still ring with; its
  // COR is below 1 by that ring alone.
  BallContactLaw elastic = kTwoMassTennisBallLaw;
  elastic.hysteretic.shell_stiffness = 1e-6;
  elastic.hysteretic.damping = 0.0;
  elastic.hysteretic.unloading_offset = -100.0;
  elastic.body.internal_damping_ratio = 0.0;
  CollisionOptions one_run;
  one_run.extrapolate = false;
  const CollisionResult bounce =
      collide(rigid_frame(), std::nullopt, kBall_kg, elastic, 20.0, one_run);
  CHECK(bounce.ball_out_J + bounce.ball_loss_J == Approx(bounce.ball_in_J).epsilon(1e-12));
  CHECK(bounce.ball_loss_J > 0.0);
  CHECK(bounce.apparent_cor ==
        Approx(std::sqrt(bounce.ball_out_J / bounce.ball_in_J)).epsilon(1e-12));
  // Halves joined ever more stiffly approach the hysteretic ball of one mass
  // with the same contact: the difference shrinks with the internal period.
  BallContactLaw one = kTwoMassTennisBallLaw;
  one.form = BallLawForm::kHysteretic;
  one.body = BallBody{};
  const double e_one = rigid_surface_cor(one, kBall_kg);
  double previous_gap = 1.0;
  for (const double k_i : {1e6, 1e8, 1e10}) {
    INFO("k_i " << k_i);
    BallContactLaw stiff = kTwoMassTennisBallLaw;
    stiff.body.internal_stiffness = k_i;
    stiff.body.internal_cubic_stiffness = 0.0;
    const double gap = std::abs(rigid_surface_cor(stiff, kBall_kg) - e_one);
    CHECK(gap < previous_gap);
    previous_gap = gap;
  }
  CHECK(previous_gap < 1e-3);
}

TEST_CASE("The energy ledger closes to round-off, from a rigid wall to a 100 m implement") {
  std::vector<std::pair<std::string, FrameAtImpact>> frames;
  frames.emplace_back("rigid", rigid_frame());
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  for (const double from_tip : {0.02, 0.12, 0.16, 0.25})
    frames.emplace_back("tour 100 " + std::to_string(from_tip),
                        frame_at_impact(racquet, L - from_tip));
  ResponseOptions held;
  held.support = ResponseOptions::Support::kHandHeld;
  held.modes = 6;
  frames.emplace_back("tour 100 hand-held",
                      frame_at_impact(response_model(tour_100(), held), L - 0.16));
  frames.emplace_back("2 m beam", long_beam(2.0, 20));
  frames.emplace_back("100 m beam", long_beam(100.0, 30));
  for (const auto& [name, frame] : frames) {
    for (const bool with_strings : {true, false}) {
      for (const bool extrapolate : {true, false}) {
        INFO(name << (with_strings ? ", strings" : ", no strings")
                  << (extrapolate ? ", extrapolated" : ""));
        CollisionOptions o;
        o.extrapolate = extrapolate;
        const auto strings = with_strings ? std::optional(strings_at(250.0)) : std::nullopt;
        const CollisionResult r = collide(frame, strings, kBall_kg, kTennisBallLaw, 50.0, o);
        CHECK(std::abs(ledger_residual(r)) <= kRoundOff * r.ball_in_J);
        for (const double part :
             {r.ball_out_J, r.implement_rigid_J, r.vibration_J, r.ball_loss_J, r.strings_loss_J})
          CHECK(part >= -kRoundOff * r.ball_in_J);
        // No output reports more energy than went in.
        CHECK(r.vibration_J <= r.ball_in_J);
        CHECK(r.ball_out_J <= r.ball_in_J);
      }
    }
  }
}

TEST_CASE("The long implements catch the ball again and the ledger still closes") {
  CollisionOptions o;
  o.extrapolate = false;
  const CollisionResult r =
      collide(long_beam(2.0, 20), strings_at(250.0), kBall_kg, kTennisBallLaw, 50.0, o);
  CHECK(r.contacts >= 2);
  CHECK(std::abs(ledger_residual(r)) <= kRoundOff * r.ball_in_J);
}

// A linear ball (40 kN/m, undamped) at 40 m/s on a string bed of 60 kN/m
// weighing `bed_kg`, in front of 0.2 kg of effective mass.
CollisionResult linear_ball_on_a_light_bed(double bed_kg, int steps_per_contact, bool history) {
  const BallContactLaw linear{40e3, 1.0, 0.0, 0.0};
  const StringBedDynamics strings{60e3, bed_kg, 0.0};
  FrameAtImpact body;
  body.inverse_effective_mass_per_kg = 1.0 / 0.2;
  CollisionOptions o;
  o.steps_per_contact = steps_per_contact;
  o.record_history = history;
  return collide(body, strings, kBall_kg, linear, 40.0, o);
}

TEST_CASE("A contact too stiff to step through is not stepped: bounded time and memory") {
  // The linear ball on a bed of 1e-12 kg at 1000 steps a contact: the bed's
  // half-period binds the step, about 4e7 steps for the contact, more than
  // the 2e7 a contact may take (step_mesh.hpp). Nothing is stepped and the
  // ball is left in contact, which the evaluation refuses; one at 1e-11 kg
  // and 500 steps a contact (7e6 steps) is answered in the test above.
  const CollisionResult r = linear_ball_on_a_light_bed(1e-12, 1000, true);
  CHECK(r.steps == 0);
  CHECK(!r.separated);
  CHECK(r.time_s.empty());
}

TEST_CASE("The impulse is the ball's loss of momentum and the implement's gain") {
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  for (const double from_tip : {0.03, 0.16}) {
    const CollisionResult r = collide(frame_at_impact(racquet, L - from_tip), strings_at(250.0),
                                      kBall_kg, kTennisBallLaw, 50.0);
    const double p_in = kBall_kg * 50.0;
    CHECK(r.impulse_N_s ==
          Approx(kBall_kg * (50.0 - r.ball_velocity_after_m_s)).epsilon(kRoundOff));
    CHECK(r.implement_momentum_N_s == Approx(r.impulse_N_s).margin(kRoundOff * p_in));
  }
}

TEST_CASE("Rigid strings on a rigid frame give the ball's own COR and contact time") {
  const CollisionResult wall = collide(rigid_frame(), std::nullopt, kBall_kg, kTennisBallLaw, 30.0);
  // Strings 1e4 times stiffer than the ball's secant stiffness, weighing a
  // microgram: their compliance changes the contact by ~1e-4.
  const StringBedDynamics stiff{1e9, 1e-9, 0.0};
  const CollisionResult r = collide(rigid_frame(), stiff, kBall_kg, kTennisBallLaw, 30.0);
  CHECK(r.apparent_cor == Approx(wall.apparent_cor).epsilon(1e-4));
  CHECK(r.contact_time_s == Approx(wall.contact_time_s).epsilon(1e-4));
}

TEST_CASE("A linear ball on strings lasts pi sqrt(mu/k) with k the two springs in series") {
  // Undamped: a half period of the relative motion of m and M_eff on
  // 1/k = 1/k_ball + 1/k_strings (string_bed.hpp), and e = 1.
  // The string bed weighs 1e-11 kg: its own vibration (resolved by the step)
  // moves the instant the ball's spring relaxes by ~sqrt(m_s / mu) of T
  // (3e-4 at 1 mg, 3e-6 at 1e-10 kg), ~1e-6 here.
  // The bed binds the step: 62 steps per half-period of its own at 500 a contact.
  const CollisionResult r = linear_ball_on_a_light_bed(1e-11, 500, false);
  const double mu = reduced_mass(kBall_kg, 0.2), k = series_stiffness(40e3, 60e3);
  CHECK(r.contact_time_s == Approx(kPi * std::sqrt(mu / k)).epsilon(kStepError));
  // e = 1: the apparent COR is Eq. (16) with e = 1.
  CHECK(r.apparent_cor == Approx((0.2 - kBall_kg) / (0.2 + kBall_kg)).epsilon(1e-8));
}

TEST_CASE("A linear spring-dashpot ball has the damped oscillator's COR") {
  // m x'' + b x' + k x = 0, x(0) = 0, x'(0) = v: x = (v/w_d) e^{-s t} sin(w_d t),
  // s = b/2m. The force k x + b x' = -m x'' falls to 0 (and would pull after)
  // where tan(w_d t) = 2 s w_d / (s^2 - w_d^2); the ball leaves with x'(t*).
  const double k = 40e3, b = 6.0, m = kBall_kg;
  const double s = b / (2 * m), wd = std::sqrt(k / m - s * s);
  const double t_star = (kPi - std::atan(2 * s * wd / (wd * wd - s * s))) / wd;
  const double e =
      -std::exp(-s * t_star) * (std::cos(wd * t_star) - s / wd * std::sin(wd * t_star));
  const CollisionResult r =
      collide(rigid_frame(), std::nullopt, m, BallContactLaw{k, 1.0, b, 0.0}, 20.0);
  CHECK(r.apparent_cor == Approx(e).epsilon(kStepError));
  // The undamped classic, e = exp(-pi s / w_d) when the force may pull, lies above.
  CHECK(e < std::exp(-kPi * s / wd) + 0.05);
}

TEST_CASE("Convergence: second order in the step, third after extrapolation, and in the modes") {
  const ResponseModel racquet = tour_100_model();
  const FrameAtImpact frame = frame_at_impact(racquet, tour_100().impact_from_butt_m);
  const StringBedDynamics strings = strings_at(250.0);
  CollisionOptions o;
  o.extrapolate = false;
  o.steps_per_contact = 8192;
  const double reference = collide(frame, strings, kBall_kg, kTennisBallLaw, 50.0, o).apparent_cor;
  std::vector<double> plain, extrapolated;
  for (const int steps : {64, 128, 256}) {
    o.steps_per_contact = steps;
    o.extrapolate = false;
    plain.push_back(std::abs(
        collide(frame, strings, kBall_kg, kTennisBallLaw, 50.0, o).apparent_cor - reference));
    o.extrapolate = true;
    extrapolated.push_back(std::abs(
        collide(frame, strings, kBall_kg, kTennisBallLaw, 50.0, o).apparent_cor - reference));
  }
  for (std::size_t i = 1; i < plain.size(); ++i) {
    const double order = std::log2(plain[i - 1] / plain[i]);
    INFO("observed order " << order);
    CHECK(order > 1.8);
    CHECK(order < 2.3);
    CHECK(std::log2(extrapolated[i - 1] / extrapolated[i]) > 2.5);
  }
  // The default (64 steps, extrapolated) to 1e-6 in the COR.
  CHECK(std::abs(collide(frame, strings, kBall_kg, kTennisBallLaw, 50.0).apparent_cor - reference) <
        1e-6);

  // Modes: each pair added changes the COR less; from six modes (to ~3 kHz,
  // far beyond 1.5/T ~ 370 Hz) on, the truncation error is < 1e-4.
  const ResponseModel many = tour_100_model(12);
  const FrameAtImpact f12 = frame_at_impact(many, tour_100().impact_from_butt_m);
  auto cor_with = [&](int modes) {
    return collide(frame_at_impact(many, tour_100().impact_from_butt_m, modes), strings, kBall_kg,
                   kTennisBallLaw, 50.0)
        .apparent_cor;
  };
  const double converged = collide(f12, strings, kBall_kg, kTennisBallLaw, 50.0).apparent_cor;
  double previous_change = 1.0;
  for (const int modes : {4, 6, 8, 10}) {
    const double change = std::abs(cor_with(modes + 2) - cor_with(modes));
    CHECK(change < previous_change);
    previous_change = change;
    if (modes >= 6) CHECK(std::abs(cor_with(modes) - converged) < 1e-4);
  }
  CHECK(std::abs(cor_with(1) - converged) > 1e-3);  // the fundamental alone is not enough
}

TEST_CASE("A stiff frame keeps the vibration energy the prescribed pulse gives it") {
  // Where the prescribed half-sine is valid (f1 >> 1.5/T) both models leave
  // the frame little energy; with the solved impulse and duration the
  // half-sine's modal energies (impact_response.hpp) match the solved ones to
  // the pulse-shape difference of the spectrum's tail.
  const ResponseModel racquet = with_fundamental(tour_100_model(), 155.0);
  const double x = tour_100().impact_from_butt_m;
  for (const double f1 : {155.0, 1000.0}) {
    INFO(f1 << " Hz");
    const ResponseModel model = with_fundamental(racquet, f1);
    const CollisionResult r =
        collide(frame_at_impact(model, x), strings_at(250.0), kBall_kg, kTennisBallLaw, 50.0);
    double modes_J = 0.0;
    for (const double e : r.mode_energy_J) modes_J += e;
    const double prescribed_J =
        0.5 * r.impulse_N_s * r.impulse_N_s * vibration_compliance(model, x, r.contact_time_s);
    if (f1 > 1.5 / r.contact_time_s * 2.0) {
      CHECK(modes_J < 0.01 * r.ball_in_J);
      CHECK(prescribed_J < 0.01 * r.ball_in_J);
    } else {
      // A real racquet (f1 ~ 0.6 / T): the same order, the prescribed pulse more.
      CHECK(modes_J == Approx(prescribed_J).epsilon(0.5));
    }
  }
}

// ---------------------------------------------------------------- published numbers

TEST_CASE("The typical racquet's apparent COR: about 0.4 mid-strings, about 0.1 near the tip") {
  // Cross (2004) Sec. VI: e_A "is typically about 0.4 in the middle of the
  // strings and about 0.1 near the tip". Accepted: 0.3-0.5 and 0-0.2 (the
  // paper's "about" to one figure).
  const ResponseModel racquet = tour_100_model();
  const double L = tour_100().implement.length_m();
  const StringBedDynamics strings = strings_at(250.0);
  const double middle =
      collide(frame_at_impact(racquet, L - 0.16), strings, kBall_kg, kTennisBallLaw, 50.0)
          .apparent_cor;
  const double tip =
      collide(frame_at_impact(racquet, L - 0.04), strings, kBall_kg, kTennisBallLaw, 50.0)
          .apparent_cor;
  CHECK(middle > 0.3);
  CHECK(middle < 0.5);
  CHECK(tip > 0.0);
  CHECK(tip < 0.2);
}

TEST_CASE("The COR along the strings peaks at the fundamental's node") {
  // Cross, Am. J. Phys. 68, 1025 (2000) ("happy and unhappy balls"): the COR
  // of a racket "varies with the impact point and is a maximum at the
  // vibration node near the center of the strings".
  const Design d = tour_100();
  const ResponseModel racquet = tour_100_model();
  const double node = *evaluate_modes(d).node_free_from_butt_m;
  const StringBedDynamics strings = strings_at(250.0);
  double best = 0.0, best_x = 0.0;
  for (double x = d.implement.length_m() - 0.30; x <= d.implement.length_m() - 0.01; x += 0.0025) {
    const FrameAtImpact f = frame_at_impact(racquet, x);
    const double e =
        cor_from_apparent(collide(f, strings, kBall_kg, kTennisBallLaw, 50.0).apparent_cor,
                          kBall_kg, 1.0 / f.inverse_effective_mass_per_kg);
    if (e > best) best = e, best_x = x;
  }
  CHECK(best_x == Approx(node).margin(0.01));
}

TEST_CASE("Lower string tension returns the ball slightly faster, the contact lasts 4-6 ms") {
  // Bower & Cross, J. Sports Sci. 23, 765-771 (2005), in play: 108.1 km/h at
  // 180 N against 105.3 km/h at 280 N, a 2.7 % faster shot at the lower tension
  // (the in-play comparison is tests/studies/swing_test.cpp).
  // The solved model's sign must agree; its size depends on the string bed's
  // moving mass and loss (issue 12: 0-6 % over 1-8 g): checked in (0, 8 %).
  const ResponseModel racquet = tour_100_model();
  const FrameAtImpact f = frame_at_impact(racquet, tour_100().impact_from_butt_m);
  for (const double mass : {0.001, 0.004, 0.008}) {
    const double low =
        collide(f, strings_at(180.0, mass), kBall_kg, kTennisBallLaw, 50.0).apparent_cor;
    const double high =
        collide(f, strings_at(280.0, mass), kBall_kg, kTennisBallLaw, 50.0).apparent_cor;
    INFO(mass << " kg: " << low / high);
    CHECK(low > high);
    CHECK(low / high < 1.08);
  }
  // Contact times of 4-6 ms at common tensions (200-250 N; Brody, Cross &
  // Lindsey, The Physics and Technology of Tennis, 2002).
  for (const double tension : {200.0, 250.0}) {
    const double T = collide(f, strings_at(tension), kBall_kg, kTennisBallLaw, 50.0).contact_time_s;
    CHECK(T > 4e-3);
    CHECK(T < 6e-3);
  }
}

TEST_CASE(
    "Table I racquet: a flexible frame gives e = 0.6 inside the racquet range, 0.8 only above") {
  // Free frames of racquets run about 100-180 Hz (Brody, Cross & Lindsey
  // 2002). The prescribed pulse gave e = 0.6 at 137 Hz and 0.8 at 217-255 Hz
  // (reports/cor-from-stiffness.md); the solved collision, with the calibrated
  // ball and a 250 N string bed, is checked for the same ordering.
  Design d{Implement::paper_racquet(0.70, 0.25, 0.8)};
  d.stiffness.EI_N_m2 = 152.0;
  ResponseOptions o;
  o.modes = 6;
  const ResponseModel base = response_model(d, o);
  auto cor_at = [&](double f1) {
    const FrameAtImpact f = frame_at_impact(with_fundamental(base, f1), 0.65);
    return cor_from_apparent(
        collide(f, strings_at(250.0), kBall_kg, kTennisBallLaw, 50.0).apparent_cor, kBall_kg,
        1.0 / f.inverse_effective_mass_per_kg);
  };
  CHECK(cor_at(100.0) < 0.6);
  CHECK(cor_at(180.0) > 0.6);
  CHECK(cor_at(180.0) < 0.8);
  CHECK(cor_at(400.0) > 0.8);
}

TEST_CASE("auto solves the collision for a strung racquet without a COR, and says so") {
  Design d = tour_100();
  d.strings = StringBed{};
  d.cor_given = false;
  REQUIRE(needed_fidelity(d) == Fidelity::kCollision);
  const Evaluation e = evaluate(d, Fidelity::kCollision);
  CHECK(fidelity_of(e) == Fidelity::kCollision);
  REQUIRE(e.details);
  REQUIRE(e.details->collision);
  const CollisionResult& c = *e.details->collision;
  // The evaluation's numbers are the solved ones, and Eq. (16) with the
  // derived COR gives back the solved apparent COR.
  CHECK(e.apparent_cor == c.apparent_cor);
  CHECK(e.impact_duration_s == c.contact_time_s);
  CHECK(e.peak_impact_force_N == c.peak_force_N);
  CHECK(e.peak_wrist_force_N == Approx(std::abs(e.wrist_force_ratio) * c.peak_force_N));
  CHECK((e.cor * e.effective_mass_kg - kBall_kg) / (e.effective_mass_kg + kBall_kg) ==
        Approx(e.apparent_cor).epsilon(1e-12));
  CHECK(std::abs(ledger_residual(c)) <= kRoundOff * c.ball_in_J);
  // A given COR, or cor_rigid, keeps the cheaper models; the collision,
  // which derives the COR, refuses either rather than ignore it.
  d.cor_given = true;
  CHECK(needed_fidelity(d) == Fidelity::kModal);
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kCollision), Catch::StartsWith("frame/cor: "));
  d.cor_given = false;
  d.cor_rigid = 0.85;
  CHECK(needed_fidelity(d) == Fidelity::kResponse);
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kCollision), Catch::Contains("frame/cor_rigid"));
  d.cor_rigid.reset();
  d.strings.reset();
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kCollision), Catch::Contains("strings/tension_N"));
}

TEST_CASE(
    "An off-axis hit: the collision's rigid body has evaluate's M_eff with y^2 / I_polar, and "
    "the ball comes back slower") {
  Design d = tour_100();
  d.strings = StringBed{};
  d.cor_given = false;
  // A typical strung twistweight, about 14 kg cm^2 (Taraborrelli et al., Sports
  // Eng. 22 (2019): 12-17 kg cm^2 for modern rackets).
  d.twistweight_kg_m2 = 14e-4;
  // On the axis nothing changes: the solved collision is the one on
  // frame_at_impact()'s in-plane M_eff, to the bit, whether I_polar is known or not.
  ResponseOptions o;
  o.modes = 6;  // kCollisionModes
  o.rel_tol = 1e-6;
  const FrameAtImpact on_axis = frame_at_impact(response_model(d, o), d.impact_from_butt_m);
  CollisionOptions with_history;
  with_history.record_history = true;
  const CollisionResult direct = collide(on_axis, string_bed_dynamics(*d.strings), kBall_kg,
                                         kTennisBallLaw, d.ball.speed_m_s, with_history);
  const Evaluation e0 = evaluate(d, Fidelity::kCollision);
  CHECK(e0.apparent_cor == direct.apparent_cor);
  CHECK(e0.impulse_N_s == direct.impulse_N_s);
  Design unknown_polar = d;
  unknown_polar.twistweight_kg_m2.reset();
  CHECK(evaluate(unknown_polar, Fidelity::kCollision).apparent_cor == e0.apparent_cor);

  // 5 cm off the axis: the collision's M_eff is evaluate's rigid M_eff, so
  // Eq. (16) with the derived COR gives back the solved apparent COR, and
  // 1/M_eff grows by exactly y^2 / I_polar.
  const double y = 0.05;
  d.impact_off_axis_m = y;
  const Evaluation ey = evaluate(d, Fidelity::kCollision);
  CHECK(1.0 / ey.effective_mass_kg - 1.0 / e0.effective_mass_kg ==
        Approx(y * y / 14e-4).epsilon(1e-12));
  CHECK((ey.cor * ey.effective_mass_kg - kBall_kg) / (ey.effective_mass_kg + kBall_kg) ==
        Approx(ey.apparent_cor).epsilon(1e-12));
  FrameAtImpact twisted = on_axis;
  twisted.inverse_effective_mass_per_kg += y * y / 14e-4;
  const CollisionResult twisted_direct = collide(twisted, string_bed_dynamics(*d.strings), kBall_kg,
                                                 kTennisBallLaw, d.ball.speed_m_s, with_history);
  CHECK(ey.apparent_cor == twisted_direct.apparent_cor);
  // The twist is the solved impulse's and force's: J y / I_polar and F0 |y|.
  CHECK(ey.twist_rate_rad_s == twisted_direct.impulse_N_s * y / 14e-4);
  CHECK(ey.peak_twist_torque_N_m == twisted_direct.peak_force_N * y);
  // The lighter effective mass returns the ball slower. With the frame's COR
  // held at its on-axis value, Eq. (16) predicts the drop from M_eff alone; the
  // solved drop differs from it only by the vibration, which M_eff also changes
  // (1.4 % of the drop here, 0.380 to 0.283 for 5 cm: the frame's COR is nearly a
  // property of the point along the axis).
  CHECK(ey.apparent_cor < e0.apparent_cor);
  const double M = ey.effective_mass_kg;
  const double rigid_prediction = (e0.cor * M - kBall_kg) / (M + kBall_kg);
  CHECK(ey.apparent_cor ==
        Approx(rigid_prediction).margin(0.1 * (e0.apparent_cor - rigid_prediction)));
  // Without the polar inertia an off-axis hit is refused by name.
  unknown_polar.impact_off_axis_m = y;
  CHECK_THROWS_WITH(evaluate(unknown_polar, Fidelity::kCollision),
                    Catch::Contains("impact/off_axis_m"));
}

// Issue 20: a stiff ball's contact with the 4 g string bed lasts far less than
// the contact with the frame; the step follows it, so the ledger closes with
// every term >= 0 (before, from k ~ 1e12 it closed only by booking a negative
// ball loss, and at 1e15 the ball left at 193 m/s from 50 m/s).
// The ledger's round-off is the invariant checker's (a stiff ball takes ~1e6 steps).
void require_physical(const CollisionResult& r, double ball_mass_kg, double M_eff, double m_s) {
  const double tol = kInvariantRoundOff * r.ball_in_J;
  CHECK(r.separated);
  CHECK(std::abs(ledger_residual(r)) <= tol);
  for (const double term : {r.ball_out_J, r.implement_rigid_J, r.vibration_J,
                            r.modal_damping_loss_J, r.ball_loss_J, r.strings_loss_J}) {
    CHECK(term >= -tol);
  }
  for (const double mode : r.mode_energy_J) CHECK(mode >= -tol);
  CHECK(r.ball_out_J <= r.ball_in_J);
  CHECK(r.impulse_N_s > 0.0);
  CHECK(r.contact_time_s > 0.0);
  CHECK(r.apparent_cor >= -ball_mass_kg / (M_eff + ball_mass_kg));
  CHECK(r.apparent_cor <= (M_eff + m_s - ball_mass_kg) / (M_eff + m_s + ball_mass_kg));
  CHECK(r.step_error <= kMaxStepError);
}

TEST_CASE("A stiff ball is resolved: every ledger term >= 0 from k = 1e4 to the largest accepted") {
  const ResponseModel model = tour_100_model();
  const double x = tour_100().impact_from_butt_m;
  const FrameAtImpact frame = frame_at_impact(model, x);
  const double M_eff = 1.0 / frame.inverse_effective_mass_per_kg;
  for (const double k :
       {1e4, kTennisBallLaw.stiffness, 1e8, 1e10, 1e12, 1e13, 1e14, kMaxBallStiffness}) {
    for (const double damping : {0.0, kTennisBallLaw.damping}) {
      INFO("k = " << k << ", b = " << damping);
      const BallContactLaw law{k, 1.5, damping, 0.5};
      require_physical(collide(frame, strings_at(250.0), kBall_kg, law, 50.0), kBall_kg, M_eff,
                       kStringBedMass_kg);
      require_physical(collide(frame, strings_at(250.0, kMinStringBedMass_kg), kBall_kg, law, 50.0),
                       kBall_kg, M_eff, kMinStringBedMass_kg);
      // No strings: the ball on the frame's rigid body and modes.
      require_physical(collide(frame, std::nullopt, kBall_kg, law, 50.0), kBall_kg, M_eff, 0.0);
    }
  }
}

TEST_CASE("The stiffest ball's answer converges as the step halves") {
  const FrameAtImpact frame = frame_at_impact(tour_100_model(), tour_100().impact_from_butt_m);
  const BallContactLaw law{kMaxBallStiffness, 1.5, 0.0, 0.5};
  std::vector<double> cor;
  for (const int steps : {64, 128, 256}) {
    CollisionOptions o;
    o.steps_per_contact = steps;
    cor.push_back(collide(frame, strings_at(250.0), kBall_kg, law, 50.0, o).apparent_cor);
  }
  // The differences shrink (faster than halving: the extrapolated error is O(h^3)).
  CHECK(std::abs(cor[2] - cor[1]) < 0.5 * std::abs(cor[1] - cor[0]));
  CHECK(std::abs(cor[2] - cor[1]) < 1e-5);
  // A lossless stiff ball on a lossy string bed and frame: a plausible rebound,
  // not 193 m/s out of 50.
  CHECK(cor[2] > 0.0);
  CHECK(cor[2] < 0.6);
}

TEST_CASE("A collision refuses bad arguments by name") {
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message([] {
          collide(rigid_frame(), std::nullopt, -1.0, kTennisBallLaw, 50.0);
        }).rfind("ball_mass_kg", 0) == 0);
  CHECK(message([] {
          collide(rigid_frame(), std::nullopt, kBall_kg, kTennisBallLaw, 0.0);
        }).rfind("speed_m_s", 0) == 0);
  CHECK(message([] {
          collide(rigid_frame(), std::nullopt, kBall_kg, BallContactLaw{-1, 1.5, 0, 0}, 50.0);
        }).rfind("law.stiffness", 0) == 0);
  CHECK(message([] {
          collide(rigid_frame(), StringBedDynamics{1e4, 0.0, 0.0}, kBall_kg, kTennisBallLaw, 50.0);
        }).rfind("strings.mass_kg", 0) == 0);
  CollisionOptions o;
  o.steps_per_contact = 2;
  CHECK(message([&] {
          collide(rigid_frame(), std::nullopt, kBall_kg, kTennisBallLaw, 50.0, o);
        }).rfind("options.steps_per_contact", 0) == 0);
}

}  // namespace
}  // namespace sweetspot
