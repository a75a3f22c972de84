// The arm's load (studies/arm_load.hpp): the hand's frequency weighting
// against ISO 5349-1's table, the vibration at the hand against the closed
// form of a half-sine's residual energy, and the spread's factors on pairs of
// racquets whose answer the physics gives before the program does.
#include "studies/arm_load.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "io/design_reader.hpp"
#include "io/json_reader.hpp"
#include "studies/comparison.hpp"
#include "sweetspot/impact_response.hpp"

namespace sweetspot::studies {
namespace {

// ISO 5349-1 (2001) Table A.2 prints W_h to three figures.
constexpr double kTableRounding = 0.006;  // relative

TEST_CASE("the hand's weighting W_h matches ISO 5349-1's table at its one-third octaves") {
  // Band centres 10^(n/10) Hz and the factors the standard tabulates.
  const std::pair<int, double> table[] = {{8, 0.727},  {10, 0.951}, {12, 0.896}, {14, 0.647},
                                          {16, 0.411}, {18, 0.256}, {20, 0.160}};
  for (const auto& [n, factor] : table) {
    const double f = std::pow(10.0, n / 10.0);
    INFO("f = " << f << " Hz");
    CHECK(iso5349_weighting(f) == Approx(factor).epsilon(kTableRounding));
  }
  // Above the transition it falls as f4^2 / (f3 f) = 15.915 Hz / f: the
  // weighted acceleration of a vibration is proportional to its velocity.
  CHECK(iso5349_weighting(150.0) * 150.0 == Approx(15.915).epsilon(0.01));
  CHECK_THROWS_AS(iso5349_weighting(0.0), std::invalid_argument);
}

io::DesignFile design_of(const char* text) {
  return io::read_design(io::Json::parse(text), "test.json");
}

// A racquet whose rigid numbers do not depend on the frame's stiffness: a
// given COR and duration, evaluated at the modal fidelity.
const char* const kModal = R"({
  "name": "A",
  "implement": {"length_in": 27.0, "mass_g": 318, "balance_cm": 32.5, "swingweight_kg_cm2": 325,
                "headsize_sq_in": 100},
  "frame": {"fundamental_free_Hz": 155, "cor": 0.85},
  "strings": {"impact_duration_ms": 4.5}
})";

TEST_CASE("the vibration at the hand is each mode's residual energy read at the hand") {
  const io::DesignFile design = design_of(kModal);
  const Evaluation e = io::evaluate_design_file(design, "modal", 1e-6);
  const FreeFrame frame = free_frame_of(design, e);
  REQUIRE(frame.model);
  const double hand = design.design.hand.center_from_butt_m;
  const HandVibration v = hand_vibration(*frame.model, hand, e);
  // E_k = (J phi_k(x_F))^2 S(w_k T)^2 / 2 for an undamped mode (the Fourier
  // transform of the pulse), so the amplitude at the hand is |phi_k(x_h)| sqrt(2 E_k).
  double velocity2 = 0.0, weighted2 = 0.0;
  for (const ResponseMode& m : frame.model->modes) {
    const double energy =
        half_sine_residual_energy(e.impulse_N_s, mass_normalised_shape(m, e.impact_from_butt_m),
                                  m.omega_rad_s, e.impact_duration_s);
    const double velocity = std::fabs(mass_normalised_shape(m, hand)) * std::sqrt(2.0 * energy);
    velocity2 += velocity * velocity;
    const double f = m.omega_rad_s / (2.0 * std::numbers::pi);
    weighted2 += std::pow(iso5349_weighting(f) * m.omega_rad_s * velocity, 2);
  }
  CHECK(v.velocity_m_s == Approx(std::sqrt(velocity2)).epsilon(1e-9));
  CHECK(v.weighted_acceleration_m_s2 == Approx(std::sqrt(weighted2)).epsilon(1e-9));
  // The fundamental carries it: the frame given at 155 Hz free.
  CHECK(v.frequency_Hz == Approx(155.0).epsilon(1e-9));
}

ArmLoad load_of(const io::Json& document, const char* fidelity) {
  return compare_one(io::read_design(document, "d.json"), fidelity, 1e-6).arm;
}

TEST_CASE("a softer frame: a lower frequency and more vibration at the hand, the rest the same") {
  // Every EI scaled by one factor leaves the shapes and scales every
  // frequency (with_fundamental); a mode's residual energy goes as
  // S(w T)^2, which falls with w T below the spectrum's first zero (f T = 1.5;
  // here f T = 0.155 x 4.5 = 0.70). So the softer frame keeps more energy in
  // each mode, with the same amplitude per unit energy at the hand: more
  // vibration there. The rigid body's numbers (the wrist force, the twist) do
  // not see the stiffness at this fidelity.
  const io::Json a = io::Json::parse(kModal);
  io::Json b = a;
  b["frame"]["fundamental_free_Hz"] = 125;
  const ArmLoad la = load_of(a, "modal"), lb = load_of(b, "modal");
  REQUIRE(la.hand_weighted_acceleration_m_s2.value);
  REQUIRE(lb.hand_weighted_acceleration_m_s2.value);
  CHECK(*lb.hand_frequency_Hz.value == Approx(125.0).epsilon(1e-9));
  CHECK(*la.hand_frequency_Hz.value == Approx(155.0).epsilon(1e-9));
  CHECK(*lb.hand_velocity_m_s.value > *la.hand_velocity_m_s.value);
  CHECK(*lb.hand_weighted_acceleration_m_s2.value > *la.hand_weighted_acceleration_m_s2.value);
  CHECK(*lb.peak_wrist_force_N.value == Approx(*la.peak_wrist_force_N.value).epsilon(1e-12));
  CHECK(*lb.peak_twist_torque_N_m.value == Approx(*la.peak_twist_torque_N_m.value).epsilon(1e-12));
}

TEST_CASE("more mass in the head: less shock at the wrist for hits around the centre") {
  // Eq. (11): the wrist force of a hit between the tip and the hand-held COP
  // grows with the hit's distance from the COP, and lead at the tip moves the
  // COP towards the tip (Eq. 13, here 30.7 -> 29.3 cm from the tip), nearer
  // the centre of the strings (18 cm), while the impulse and F0 grow only
  // with e_A (a percent). Lead at an antinode also lowers the fundamental
  // (Rayleigh's quotient: kinetic energy added where the mode moves most).
  // The frame by its RA (a stiffness, not a frequency, so that the lead can
  // change the frequency; a given fundamental is the frame as measured).
  io::Json a = io::Json::parse(kModal);
  a["frame"].erase("fundamental_free_Hz");
  a["frame"]["RA"] = 66;
  io::Json b = a;
  b["implement"]["point_masses"] = io::Json::parse(R"([{"clock": 12, "mass_g": 10}])");
  const ComparedDesign ca = compare_one(io::read_design(a, "a.json"), "modal", 1e-6);
  const ComparedDesign cb = compare_one(io::read_design(b, "b.json"), "modal", 1e-6);
  REQUIRE(ca.spots.cop_from_tip_m);
  REQUIRE(cb.spots.cop_from_tip_m);
  CHECK(*cb.spots.cop_from_tip_m < *ca.spots.cop_from_tip_m);
  // The precondition of the argument: the whole spread lies tip-side of both COPs.
  for (const SpreadPoint& p : ca.arm.spread) CHECK(p.from_tip_m < *cb.spots.cop_from_tip_m);
  CHECK(*cb.arm.peak_wrist_force_N.value < *ca.arm.peak_wrist_force_N.value);
  CHECK(*cb.arm.hand_frequency_Hz.value < *ca.arm.hand_frequency_Hz.value);
}

TEST_CASE("a rigid design's vibration is a factor not known, never a failure") {
  io::Json a = io::Json::parse(kModal);
  a["frame"].erase("fundamental_free_Hz");
  const ArmLoad load = load_of(a, "");
  CHECK(load.peak_wrist_force_N.value);
  CHECK(load.peak_twist_torque_N_m.value);
  CHECK_FALSE(load.hand_weighted_acceleration_m_s2.value);
  CHECK(load.hand_weighted_acceleration_m_s2.unknown_why.find("no frame stiffness") !=
        std::string::npos);
  // The spread: nine points, 3 cm apart, around the centre of the strings.
  REQUIRE(load.spread.size() == 9);
  CHECK(load.around_centre_of_strings);
  CHECK(load.spread[4].off_axis_m == 0.0);
  CHECK(load.spread[8].from_tip_m - load.spread[0].from_tip_m == Approx(2 * kArmSpreadStep_m));
}

}  // namespace
}  // namespace sweetspot::studies
