// Oracles: the numbers printed in Cross (2004), Sections III and V, and the
// identities the equations must satisfy.
#include "sweetspot/rigid_impact.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "sweetspot/implement.hpp"

namespace sweetspot {
namespace {

// The paper prints lengths to 1 mm (0.1 cm) and inertias to 0.1 g m^2; a
// printed value is matched to half its last digit.
constexpr double kHalfMillimetre = 0.5e-3;
constexpr double kHalfCentimetre = 0.5e-2;
constexpr double kHalfInertiaDigit = 0.5e-4;  // kg m^2
// Section V.B rounds the beam's I_0 to 0.0142 kg m^2 before adding the hand, so
// a printed I_cm of the hand-held beam carries that rounding on top of its own.
constexpr double kPrintedHandHeldInertia = kHalfInertiaDigit + 0.5e-4;
constexpr double kPaperRoundedBeamInertia = 0.0142;  // kg m^2, as printed
// Identities hold to round-off; positions are O(1 m).
constexpr double kRoundOff = 1e-12;

// The experimental beam: 72 cm, 328 g, uniform (Section II). Its handle end is the butt.
Implement paper_beam() { return Implement::from_sections({Section{0.72, 0.328, {}}}); }
constexpr double kBeamLength = 0.72;

TEST_CASE("A free beam struck at one end rotates about a point 24 cm from the other end") {
  const MassProperties beam = paper_beam().mass_properties();
  const auto axis = free_conjugate_from_butt(beam, kBeamLength);
  REQUIRE(axis);
  CHECK(*axis == Approx(0.24).margin(kRoundOff));
  // and conversely an impact 24 cm from one end turns the beam about the other end.
  CHECK(*free_conjugate_from_butt(beam, 0.0) == Approx(kBeamLength - 0.24).margin(kRoundOff));
}

TEST_CASE("The free-beam COPs for axes through the disks at 2 and 16 cm are 23.3 and 14.4 cm") {
  const MassProperties beam = paper_beam().mass_properties();
  CHECK(kBeamLength - *free_conjugate_from_butt(beam, 0.02) ==
        Approx(0.233).margin(kHalfMillimetre));
  CHECK(kBeamLength - *free_conjugate_from_butt(beam, 0.16) ==
        Approx(0.144).margin(kHalfMillimetre));
}

TEST_CASE("Eq. 6 coefficients are 0.0787 and 0.0463 per cm and the ratio is 1 at the centre") {
  const MassProperties beam = paper_beam().mass_properties();
  // v2/v16 = (1 - 0.0787 b)/(1 - 0.0463 b), b in cm from the centre towards the far end.
  for (const double b_cm : {-30.0, -10.0, 5.0, 20.0, 33.0}) {
    const double x = beam.com_from_butt_m + b_cm / 100.0;
    const double paper = (1.0 - 0.0787 * b_cm) / (1.0 - 0.0463 * b_cm);
    const auto ours = velocity_ratio(beam, x, 0.02, 0.16);
    REQUIRE(ours);
    // The paper's coefficients carry 3 significant digits.
    CHECK(*ours == Approx(paper).epsilon(2e-3));
  }
  CHECK(*velocity_ratio(beam, beam.com_from_butt_m, 0.02, 0.16) == 1.0);
}

TEST_CASE("The velocity ratio is zero and infinite at the two disks' centres of percussion") {
  const MassProperties beam = paper_beam().mass_properties();
  const double cop2 = *free_conjugate_from_butt(beam, 0.02);
  const double cop16 = *free_conjugate_from_butt(beam, 0.16);
  CHECK(*velocity_ratio(beam, cop2, 0.02, 0.16) == Approx(0.0).margin(kRoundOff));
  // v16 vanishes to round-off: the ratio is at infinity or beyond any O(1) value.
  const auto pole = velocity_ratio(beam, cop16, 0.02, 0.16);
  CHECK((!pole || std::abs(*pole) > 1e12));
  CHECK(point_velocity_per_impulse(beam, cop16, 0.16) == Approx(0.0).margin(kRoundOff));
}

TEST_CASE("A 0.5 kg hand puts h at 0.185 m, I_cm at 0.0309 and the COP 0.33 m from the free end") {
  const MassProperties system = with_point_mass(paper_beam().mass_properties(), {0.07, 0.5});
  CHECK(system.com_from_butt_m == Approx(0.185).margin(kHalfMillimetre));
  CHECK(0.36 - system.com_from_butt_m == Approx(0.175).margin(kHalfMillimetre));  // x, Eq. (14)
  CHECK(system.I_cm_kg_m2 == Approx(0.0309).margin(kPrintedHandHeldInertia));
  // With the paper's own rounded I_0 the printed digit comes out exactly.
  const MassProperties rounded_beam{0.328, 0.36, kPaperRoundedBeamInertia};
  CHECK(with_point_mass(rounded_beam, {0.07, 0.5}).I_cm_kg_m2 ==
        Approx(0.0309).margin(kHalfInertiaDigit));
  const double cop = *hand_held_cop_from_butt(system);
  CHECK(cop - system.com_from_butt_m == Approx(0.20).margin(kHalfCentimetre));  // b, Eq. (13)
  CHECK(kBeamLength - cop == Approx(0.33).margin(kHalfCentimetre));
  // "The effect of the hand is therefore to shift the COP 9 cm closer to the handle."
  CHECK(*free_conjugate_from_butt(paper_beam().mass_properties(), 0.0) - cop ==
        Approx(0.09).margin(kHalfCentimetre));
}

TEST_CASE("A 0.4 kg hand puts h at 0.20 m, I_cm at 0.0294 and the COP 0.32 m from the free end") {
  const MassProperties system = with_point_mass(paper_beam().mass_properties(), {0.07, 0.4});
  CHECK(0.36 - system.com_from_butt_m == Approx(0.159).margin(kHalfMillimetre));  // x
  CHECK(system.com_from_butt_m == Approx(0.20).margin(kHalfCentimetre));
  CHECK(system.I_cm_kg_m2 == Approx(0.0294).margin(kPrintedHandHeldInertia));
  // With the paper's own rounded I_0 the printed digit comes out exactly.
  const MassProperties rounded_beam{0.328, 0.36, kPaperRoundedBeamInertia};
  CHECK(with_point_mass(rounded_beam, {0.07, 0.4}).I_cm_kg_m2 ==
        Approx(0.0294).margin(kHalfInertiaDigit));
  const double cop = *hand_held_cop_from_butt(system);
  CHECK(cop - system.com_from_butt_m == Approx(0.20).margin(kHalfCentimetre));
  CHECK(kBeamLength - cop == Approx(0.32).margin(kHalfCentimetre));
}

TEST_CASE("No impact turns the hand-held beam about the point 16 cm from the handle end") {
  // Section V.B: h = 0.185 m, A = 0.025 m, M_h = M_e = 0.5 kg gives b = -0.77 m.
  const MassProperties system = with_point_mass(paper_beam().mass_properties(), {0.07, 0.5});
  const auto impact = hand_held_impact_for_axis(system, 0.5, 0.16);
  REQUIRE(impact);
  CHECK(*impact - system.com_from_butt_m == Approx(-0.77).margin(kHalfCentimetre));
  // and Eq. (12) maps that (off-beam) impact back onto the axis.
  CHECK(*hand_held_rotation_axis_from_butt(system, 0.5, *impact) == Approx(0.16).margin(kRoundOff));
}

TEST_CASE("The wrist force vanishes exactly at the hand-held COP, where the axis is the wrist") {
  for (const double hand_kg : {0.0, 0.1, 0.4, 0.5, 2.0}) {
    for (const double forearm_kg : {1e-9, 0.4, 0.5, 1e9}) {
      const MassProperties system =
          with_point_mass(paper_beam().mass_properties(), {0.07, hand_kg});
      const double cop = *hand_held_cop_from_butt(system);
      CHECK(wrist_force_ratio(system, forearm_kg, cop) == 0.0);
      // Eq. (12) gives A = h there: the rotation axis is the wrist at the butt.
      CHECK(*hand_held_rotation_axis_from_butt(system, forearm_kg, cop) ==
            Approx(0.0).margin(kRoundOff));
    }
  }
}

TEST_CASE(
    "The wrist force changes sign across the COP: tip-side impacts jerk the forearm towards the "
    "outgoing ball") {
  const MassProperties system = with_point_mass(paper_beam().mass_properties(), {0.07, 0.5});
  const double cop = *hand_held_cop_from_butt(system);
  CHECK(wrist_force_ratio(system, 0.5, cop + 0.05) > 0.0);
  CHECK(wrist_force_ratio(system, 0.5, cop - 0.05) < 0.0);
}

TEST_CASE("As the forearm mass goes to zero the hand-held axis tends to the free one") {
  const MassProperties system = with_point_mass(paper_beam().mass_properties(), {0.07, 0.5});
  for (const double x : {0.05, 0.3, 0.5, 0.7}) {
    const double free_axis = *free_conjugate_from_butt(system, x);
    CHECK(*hand_held_rotation_axis_from_butt(system, 0.0, x) ==
          Approx(free_axis).margin(kRoundOff));
    CHECK(*hand_held_rotation_axis_from_butt(system, 1e-9, x) == Approx(free_axis).margin(1e-6));
    CHECK(wrist_force_ratio(system, 0.0, x) == 0.0);
  }
}

TEST_CASE("As the forearm mass grows without bound the wrist becomes a fixed pivot") {
  // M_e -> infinity: the wrist cannot move, so the axis is the butt and
  // F_w / F -> (M b h - I) / (M h^2 + I), the pivot reaction of a pendulum.
  const MassProperties system = with_point_mass(paper_beam().mass_properties(), {0.07, 0.5});
  const double M = system.mass_kg, I = system.I_cm_kg_m2, h = system.com_from_butt_m;
  for (const double x : {0.1, 0.4, 0.7}) {
    const double b = x - h;
    CHECK(wrist_force_ratio(system, 1e12, x) ==
          Approx((M * b * h - I) / (M * h * h + I)).epsilon(1e-9));
    CHECK(*hand_held_rotation_axis_from_butt(system, 1e12, x) == Approx(0.0).margin(1e-9));
  }
}

TEST_CASE("An impact through the centre of mass leaves the axis at infinity, not NaN") {
  const MassProperties beam = paper_beam().mass_properties();
  CHECK_FALSE(free_conjugate_from_butt(beam, beam.com_from_butt_m).has_value());
  const MassProperties system = with_point_mass(beam, {0.07, 0.5});
  CHECK_FALSE(hand_held_rotation_axis_from_butt(system, 0.0, system.com_from_butt_m).has_value());
  // 1e-12 m off the centre the axis is far but finite.
  const auto far = free_conjugate_from_butt(beam, beam.com_from_butt_m + 1e-12);
  REQUIRE(far);
  CHECK(std::abs(*far) > 1e9);
}

TEST_CASE("The effective mass is at most the mass, equal at the centre of mass") {
  const MassProperties beam = paper_beam().mass_properties();
  CHECK(effective_mass(beam, beam.com_from_butt_m) == beam.mass_kg);
  for (double x = 0.0; x <= kBeamLength; x += 0.01) CHECK(effective_mass(beam, x) <= beam.mass_kg);
  // Eq. (17) at the end of a uniform beam: M / (1 + 3) = M / 4.
  CHECK(effective_mass(beam, kBeamLength) == Approx(beam.mass_kg / 4.0).epsilon(1e-14));
}

TEST_CASE("The apparent COR equals the COR on an infinitely heavy implement") {
  CHECK(apparent_cor(0.8, 1e12, 0.057) == Approx(0.8).epsilon(1e-9));
  CHECK(apparent_cor(0.0, 0.3, 0.057) == Approx(-0.057 / 0.357).epsilon(1e-14));
}

TEST_CASE("The half-sine peak force carries the impulse m v1 (1 + e_A)") {
  // Integral of F0 sin(pi t / T) over [0, T] is 2 F0 T / pi.
  const double F0 = peak_impact_force(0.057, 50.0, 0.4, 0.004);
  CHECK(2.0 * F0 * 0.004 / 3.141592653589793 == Approx(0.057 * 50.0 * 1.4).epsilon(1e-14));
  CHECK_THROWS_AS(peak_impact_force(0.057, 50.0, 0.4, 0.0), std::invalid_argument);
}

TEST_CASE("With all the mass at the wrist the wrist force is finite: -M_e / (M_e + M)") {
  // h = 0: Eq. (11) is (M b h - I) / (M h^2 + I (1 + M / M_e)) = -I / (I (1 + M / M_e)).
  const MassProperties at_wrist{0.8, 0.0, 0.01};
  CHECK(wrist_force_ratio(at_wrist, 0.5, 0.3) == Approx(-0.5 / 1.3).epsilon(1e-15));
}

TEST_CASE("The forearm acts at the wrist as a third of its mass") {
  CHECK(forearm_equivalent_mass(1.5) == 0.5);
  CHECK_THROWS_AS(forearm_equivalent_mass(-1.0), std::invalid_argument);
}

}  // namespace
}  // namespace sweetspot
