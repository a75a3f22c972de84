// A frame's stiffness from its spec sheet: the RA relation's closed form,
// its monotonicity and range, and a design given by RA.
#include "sweetspot/frame_specs.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "sweetspot/frame_modes.hpp"

namespace sweetspot {
namespace {

constexpr double kRoundOff = 1e-12;

// The coach's racquet of the README: 27 in, 318 g strung, balance 32.5 cm, swingweight 325.
Design coach_racquet(double RA) {
  Design d{Implement::from_specs(IndustrySpecs{27 * 0.0254, 0.318, 0.325, 0.0325})};
  d.stiffness.RA = RA;
  return d;
}

constexpr double kL = 27.0 * 0.0254;  // a 27 in racquet, inside the fit's lengths

TEST_CASE("The RA relation is its closed form: the reference frequency at the reference racquet") {
  CHECK(fundamental_free_Hz_from_RA(kRAFitReferenceRA, kRAFitReferenceMass_kg, kL) ==
        Approx(kRAFitReference_Hz).epsilon(kRoundOff));
  // f1 = f_ref (RA/65)^1.115 (m/0.31)^-0.276, term by term.
  const double f = fundamental_free_Hz_from_RA(71.0, 0.29, kL);
  CHECK(f == Approx(146.9 * std::pow(71.0 / 65.0, 1.115) * std::pow(0.29 / 0.31, -0.276))
                 .epsilon(kRoundOff));
  // Ratios are the exponents' powers, whatever the reference.
  CHECK(fundamental_free_Hz_from_RA(60.0, 0.3, kL) / fundamental_free_Hz_from_RA(70.0, 0.3, kL) ==
        Approx(std::pow(60.0 / 70.0, kRAFitRAExponent)).epsilon(kRoundOff));
  CHECK(fundamental_free_Hz_from_RA(66.0, 0.25, kL) / fundamental_free_Hz_from_RA(66.0, 0.35, kL) ==
        Approx(std::pow(0.25 / 0.35, kRAFitMassExponent)).epsilon(kRoundOff));
}

TEST_CASE("A stiffer frame vibrates faster, a heavier one slower, over the whole range") {
  for (double m = kMinRAFrameMass_kg + 0.01; m <= kMaxRAFrameMass_kg; m += 0.02) {
    double previous = 0.0;
    for (double RA = kMinRA; RA <= kMaxRA; RA += 1.0) {
      const double f = fundamental_free_Hz_from_RA(RA, m, kL);
      CHECK(f > previous);
      CHECK(f < fundamental_free_Hz_from_RA(RA, m - 0.01, kL));
      previous = f;
    }
  }
  // The sample's corners stay in the range racquets are measured in (100-200 Hz).
  CHECK(fundamental_free_Hz_from_RA(54, 0.349, kL) > 100.0);
  CHECK(fundamental_free_Hz_from_RA(75, 0.242, kL) < 200.0);
}

TEST_CASE("An RA or a frame mass the fit does not cover is refused, naming frame/RA") {
  for (const double RA : {49.9, 80.1, 0.0, -66.0, std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity()}) {
    INFO(RA);
    CHECK_THROWS_WITH(fundamental_free_Hz_from_RA(RA, 0.3, kL), Catch::StartsWith("frame/RA: "));
  }
  CHECK_THROWS_WITH(fundamental_free_Hz_from_RA(66, 0.09, kL),
                    Catch::StartsWith("frame/RA: ") && Catch::Contains("90 g"));
  CHECK_THROWS_WITH(fundamental_free_Hz_from_RA(66, 1.0, kL), Catch::StartsWith("frame/RA: "));
  CHECK_THROWS_WITH(validate(coach_racquet(95)), Catch::StartsWith("frame/RA: "));
}

TEST_CASE("A design given by RA has the free fundamental the relation gives") {
  const Design d = coach_racquet(66);
  CHECK(has_stiffness(d));
  const ModalOutputs modes = evaluate_modes(d);
  CHECK(modes.fundamental_free_Hz ==
        Approx(fundamental_free_Hz_from_RA(66, 0.318, kL)).epsilon(1e-6));
  // The same as giving that frequency.
  Design by_frequency = d;
  by_frequency.stiffness.RA.reset();
  by_frequency.stiffness.fundamental_free_Hz = fundamental_free_Hz_from_RA(66, 0.318, kL);
  CHECK(evaluate_modes(by_frequency).node_free_from_butt_m.value() ==
        Approx(modes.node_free_from_butt_m.value()).epsilon(1e-9));
}

TEST_CASE(
    "Lead tape on a frame rated by RA lowers its fundamental: the rating holds the stiffness") {
  const Design bare = coach_racquet(66);
  Design taped{Implement::from_specs(IndustrySpecs{27 * 0.0254, 0.318, 0.325, 0.0325},
                                     {PointMass{0.60, 0.006}})};
  taped.stiffness.RA = 66;
  const double f_bare = evaluate_modes(bare).fundamental_free_Hz;
  const double f_taped = evaluate_modes(taped).fundamental_free_Hz;
  CHECK(f_taped < f_bare);
  // Given the frequency instead, the tape would not change it: that form holds the frequency.
  Design held = taped;
  held.stiffness.RA.reset();
  held.stiffness.fundamental_free_Hz = f_bare;
  CHECK(evaluate_modes(held).fundamental_free_Hz == Approx(f_bare).epsilon(1e-6));
}

TEST_CASE("RA with another measure of the stiffness is a contradiction") {
  Design d = coach_racquet(66);
  d.stiffness.fundamental_free_Hz = 150;
  CHECK_THROWS_WITH(validate(d), Catch::StartsWith("frame/RA: contradicts"));
  d.stiffness.fundamental_free_Hz.reset();
  d.stiffness.EI_N_m2 = 300;
  CHECK_THROWS_WITH(validate(d), Catch::StartsWith("frame/RA: contradicts"));
}

TEST_CASE("The RA relation is not used outside the lengths it was fitted on") {
  // The sample's racquets are 27-28 in; a junior's 25 in frame is refused,
  // naming the RA and the length, as a frame outside the masses is.
  CHECK_NOTHROW(fundamental_free_Hz_from_RA(60.0, 0.23, kMinRALength_m));
  CHECK_NOTHROW(fundamental_free_Hz_from_RA(60.0, 0.23, kMaxRALength_m));
  CHECK_THROWS_WITH(
      fundamental_free_Hz_from_RA(60.0, 0.23, 25.0 * 0.0254),
      Catch::StartsWith("frame/RA: the RA relation is fitted to tennis racquets 27-28 "
                        "in long (used for 26-29 in); this frame is 25 in"));
  CHECK_THROWS(fundamental_free_Hz_from_RA(60.0, 0.23, 29.5 * 0.0254));
}

}  // namespace
}  // namespace sweetspot
