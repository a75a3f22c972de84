#include "sweetspot/implement.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sweetspot/errors.hpp"

namespace sweetspot {
namespace {

constexpr double kRoundOff = 1e-13;

void check_same_body(const MassProperties& a, const MassProperties& b) {
  CHECK(a.mass_kg == Approx(b.mass_kg).epsilon(kRoundOff));
  CHECK(a.com_from_butt_m == Approx(b.com_from_butt_m).epsilon(kRoundOff));
  CHECK(a.I_cm_kg_m2 == Approx(b.I_cm_kg_m2).epsilon(kRoundOff));
}

TEST_CASE("A uniform beam has I_cm = M L^2 / 12 and its centre in the middle") {
  const Implement beam = Implement::from_sections({Section{0.72, 0.328, {}}});
  CHECK(beam.mass_properties().com_from_butt_m == Approx(0.36).epsilon(kRoundOff));
  // Section V.B prints 0.0142 kg m^2.
  CHECK(beam.mass_properties().I_cm_kg_m2 == Approx(0.328 * 0.72 * 0.72 / 12).epsilon(kRoundOff));
  CHECK(beam.mass_properties().I_cm_kg_m2 == Approx(0.0142).margin(0.5e-4));
}

TEST_CASE("The paper's racquet is two uniform halves with M1/M2 = ratio") {
  const Implement racquet = Implement::paper_racquet(0.70, 0.25, 0.8);
  REQUIRE(racquet.sections().size() == 2);
  CHECK(racquet.sections()[1].mass_kg / racquet.sections()[0].mass_kg == Approx(0.8));
  // Centre of mass: (M2 L/4 + M1 3L/4) / M in closed form.
  const double M2 = 0.25 / 1.8, M1 = 0.25 - M2;
  CHECK(racquet.mass_properties().com_from_butt_m ==
        Approx((M2 * 0.175 + M1 * 0.525) / 0.25).epsilon(kRoundOff));
  // A ratio of 1 is the uniform beam.
  check_same_body(Implement::paper_racquet(0.72, 0.328, 1.0).mass_properties(),
                  Implement::from_sections({Section{0.72, 0.328, {}}}).mass_properties());
}

TEST_CASE("The three implement forms agree where they describe the same body") {
  const std::vector<PointMass> tape{{0.68, 0.006}, {0.02, 0.010}};
  const Implement paper = Implement::paper_racquet(0.70, 0.30, 1.1, tape);
  const Implement sections = Implement::from_sections(
      {Section{0.35, 0.30 / 2.1, {}}, Section{0.35, 0.30 * 1.1 / 2.1, {}}}, tape);
  const MassProperties frame = paper.frame_mass_properties();
  const Implement specs = Implement::from_specs(
      IndustrySpecs{0.70, frame.mass_kg, frame.com_from_butt_m, swingweight_kg_m2(frame)}, tape);
  check_same_body(paper.mass_properties(), sections.mass_properties());
  check_same_body(paper.mass_properties(), specs.mass_properties());
  CHECK_FALSE(specs.has_mass_distribution());
}

TEST_CASE("Point masses add by the parallel-axis theorem, in any order") {
  const MassProperties beam =
      Implement::from_sections({Section{0.72, 0.328, {}}}).mass_properties();
  const MassProperties ab = with_point_mass(with_point_mass(beam, {0.1, 0.2}), {0.6, 0.05});
  const MassProperties ba = with_point_mass(with_point_mass(beam, {0.6, 0.05}), {0.1, 0.2});
  check_same_body(ab, ba);
  // Direct sum of second moments about the butt.
  const double I_butt = 0.328 * 0.72 * 0.72 / 3 + 0.2 * 0.01 + 0.05 * 0.36;
  CHECK(inertia_about(ab, 0.0) == Approx(I_butt).epsilon(kRoundOff));
}

TEST_CASE("Swingweight and balance round-trip through from_swingweight") {
  const MassProperties body{0.300, 0.32, 0.0150};
  const MassProperties back = from_swingweight(0.300, 0.32, swingweight_kg_m2(body));
  check_same_body(body, back);
}

TEST_CASE("Impossible implements are refused with the argument named") {
  CHECK_THROWS_WITH(Implement::from_sections({}), Catch::Contains("sections"));
  CHECK_THROWS_WITH(Implement::from_sections({Section{-0.1, 0.3, {}}}),
                    Catch::Contains("sections/0/length_m"));
  CHECK_THROWS_WITH(Implement::from_sections({Section{0.7, 0.3, {}}}, {{0.8, 0.01}}),
                    Catch::Contains("point_masses/0/from_butt_m"));
  CHECK_THROWS_WITH(Implement::paper_racquet(0.7, 0.3, 0.0),
                    Catch::Contains("head_to_handle_mass_ratio"));
  // Balance outside the length, and a swingweight below what the mass at its
  // balance point alone gives (0.3 kg at 0.32 m: 0.3 * 0.22^2 = 0.01452 kg m^2).
  CHECK_THROWS_WITH(Implement::from_specs({0.686, 0.3, 0.70, 0.032}),
                    Catch::Contains("balance_from_butt_m"));
  CHECK_THROWS_WITH(Implement::from_specs({0.686, 0.3, 0.32, 0.0145}),
                    Catch::Contains("swingweight_kg_m2"));
  // Nor above what all the mass at the two ends gives: M B (L - B) more.
  CHECK_THROWS_WITH(Implement::from_specs({0.686, 0.3, 0.32, 0.01452 + 0.3 * 0.32 * 0.366 + 1e-6}),
                    Catch::Contains("swingweight_kg_m2"));
}

TEST_CASE("A swingweight that no mass fits says which mass and balance it would fit") {
  // 27 in, 32.5 cm, 320 kg cm^2 at 318 kg (grams meant). SW in (M a^2, M (a^2 + B (L - B))]
  // with a = B - 0.1 m: M from SW / (a^2 + B (L - B)) = 0.1906 to SW / a^2 = 0.6321 kg;
  // B from (SW / M - a0^2) / (L - 2 a0) and a0 - sqrt(SW / M) to a0 + sqrt(SW / M).
  const double L = 0.6858, B = 0.325, SW = 0.032;
  CHECK_THROWS_WITH(Implement::from_specs({L, 318.0, B, SW}),
                    Catch::EndsWith(": it would fit a mass of 0.19 to 0.63 kg, or a balance of "
                                    "9 to 11 cm from the butt, the others as given"));
  // The ends of the stated ranges, just inside them, are specs the model builds.
  const double a = B - 0.1;
  CHECK_NOTHROW(Implement::from_specs({L, SW / (a * a + B * (L - B)) * 1.0001, B, SW}));
  CHECK_NOTHROW(Implement::from_specs({L, SW / (a * a) * 0.9999, B, SW}));
  const double per_kg = SW / 318.0;
  CHECK_NOTHROW(Implement::from_specs({L, 318.0, 0.1 - std::sqrt(per_kg) + 1e-5, SW}));
  CHECK_NOTHROW(Implement::from_specs({L, 318.0, 0.1 + std::sqrt(per_kg) - 1e-5, SW}));
  // The hint survives being placed under a part of the design.
  try {
    rethrow_under("implement/", FieldError("swingweight_kg_m2", "must be", std::nullopt, ": hint"));
  } catch (const FieldError& e) {
    CHECK(e.detail() == "must be: hint");
    CHECK(e.after() == ": hint");
    CHECK(std::string(e.what()) == "implement/swingweight_kg_m2: must be: hint");
  }
}

TEST_CASE("A round profile of one diameter is the uniform rod: rho pi d^2 L / 4, E pi d^4 / 64") {
  constexpr double kPi = 3.14159265358979323846;
  const double L = 0.84, d = 0.06, rho = 650.0, E = 1.2e10;
  const RoundProfile rod{{{0.0, d}, {L, d}}, rho, E};
  const std::vector<Section> slices = profile_sections(rod);
  REQUIRE(slices.size() == 168);  // 84 cm in slices of kProfileSlice_m
  for (const Section& s : slices) {
    CHECK(s.EI_N_m2.value() == Approx(E * kPi * d * d * d * d / 64.0).epsilon(kRoundOff));
  }
  const MassProperties body = Implement::from_profile(rod).mass_properties();
  const double M = rho * kPi * d * d / 4.0 * L;
  CHECK(body.mass_kg == Approx(M).epsilon(kRoundOff));
  CHECK(body.com_from_butt_m == Approx(L / 2).epsilon(kRoundOff));
  CHECK(body.I_cm_kg_m2 == Approx(M * L * L / 12).epsilon(1e-12));
}

TEST_CASE("A tapered profile has the cone frustum's exact mass, and its centre and inertia") {
  // A straight taper d(x) = d0 + (d1 - d0) x / L: the mass rho pi/4 int d^2 dx
  // is exact slice by slice; the centre and the inertia of the slices, each
  // taken uniform, are within O((h / L)^2) of the integrals, here in closed
  // form by the moments of d^2, a quadratic in x.
  constexpr double kPi = 3.14159265358979323846;
  const double L = 0.80, d0 = 0.025, d1 = 0.065, rho = 700.0;
  const RoundProfile bat{{{0.0, d0}, {L, d1}}, rho, 1.1e10};
  const double a = d0 * d0, b = 2 * d0 * (d1 - d0) / L, c = (d1 - d0) * (d1 - d0) / (L * L);
  // int_0^L x^n (a + b x + c x^2) dx
  const auto moment = [&](int n) {
    return a * std::pow(L, n + 1) / (n + 1) + b * std::pow(L, n + 2) / (n + 2) +
           c * std::pow(L, n + 3) / (n + 3);
  };
  const double k = rho * kPi / 4.0;
  const double M = k * moment(0), com = k * moment(1) / M, I_cm = k * moment(2) - M * com * com;
  const MassProperties body = Implement::from_profile(bat).mass_properties();
  const double h_over_L = kProfileSlice_m / L;
  CHECK(body.mass_kg == Approx(M).epsilon(1e-13));
  CHECK(body.com_from_butt_m == Approx(com).epsilon(h_over_L * h_over_L));
  CHECK(body.I_cm_kg_m2 == Approx(I_cm).epsilon(h_over_L * h_over_L));
  // Halving the slice (two stations more at the third points) moves nothing
  // beyond that order: a station on a straight taper changes no volume.
  const RoundProfile same{{{0.0, d0}, {L / 3, d0 + (d1 - d0) / 3}, {L, d1}}, rho, 1.1e10};
  CHECK(Implement::from_profile(same).mass_properties().mass_kg == Approx(M).epsilon(1e-13));
}

TEST_CASE(
    "A shell profile of one diameter is the tube: rho pi (d^2 - d_i^2) L / 4, E pi (d^4 - d_i^4) / "
    "64") {
  constexpr double kPi = 3.14159265358979323846;
  const double L = 0.81, d = 0.066, wall = 0.0025, rho = 2700.0, E = 7.1e10;
  const double di = d - 2 * wall;
  const RoundProfile tube{{{0.0, d}, {L, d}}, rho, E, wall};
  for (const Section& s : profile_sections(tube)) {
    CHECK(s.EI_N_m2.value() ==
          Approx(E * kPi * (d * d * d * d - di * di * di * di) / 64.0).epsilon(kRoundOff));
  }
  const MassProperties body = Implement::from_profile(tube).mass_properties();
  const double M = rho * kPi * (d * d - di * di) / 4.0 * L;
  CHECK(body.mass_kg == Approx(M).epsilon(kRoundOff));
  CHECK(body.com_from_butt_m == Approx(L / 2).epsilon(kRoundOff));
  CHECK(body.I_cm_kg_m2 == Approx(M * L * L / 12).epsilon(1e-12));
  // A wall of half the diameter is the solid rod; a tapered shell weighs the
  // solid taper less the solid taper of its bore (d - 2 wall at each station).
  const RoundProfile full{{{0.0, d}, {L, d}}, rho, E, d / 2};
  const RoundProfile solid{{{0.0, d}, {L, d}}, rho, E};
  check_same_body(Implement::from_profile(full).mass_properties(),
                  Implement::from_profile(solid).mass_properties());
  const double d0 = 0.03, d1 = 0.066;
  const RoundProfile shell{{{0.0, d0}, {L, d1}}, rho, E, wall};
  const RoundProfile outer{{{0.0, d0}, {L, d1}}, rho, E};
  const RoundProfile bore{{{0.0, d0 - 2 * wall}, {L, d1 - 2 * wall}}, rho, E};
  CHECK(Implement::from_profile(shell).mass_properties().mass_kg ==
        Approx(Implement::from_profile(outer).mass_properties().mass_kg -
               Implement::from_profile(bore).mass_properties().mass_kg)
            .epsilon(kRoundOff));
}

TEST_CASE("A profile names the station or the material it cannot take") {
  const auto message = [](const RoundProfile& p) {
    try {
      (void)profile_sections(p);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(message({{{0.0, 0.05}}, 650.0, 1e10}),
             Catch::StartsWith("profile: needs at least two"));
  CHECK_THAT(message({{{0.01, 0.05}, {0.8, 0.06}}, 650.0, 1e10}),
             Catch::StartsWith("profile/0/from_butt_m: the first station is the butt"));
  CHECK_THAT(message({{{0.0, 0.05}, {0.8, 0.06}, {0.8, 0.06}}, 650.0, 1e10}),
             Catch::StartsWith("profile/2/from_butt_m: must be beyond"));
  CHECK_THAT(message({{{0.0, 0.05}, {0.8, 0.0}}, 650.0, 1e10}),
             Catch::StartsWith("profile/1/diameter_m"));
  CHECK_THAT(message({{{0.0, 0.05}, {0.8, 0.03}}, 650.0, 1e10, 0.0151}),
             Catch::StartsWith("wall_m: must be at most half the profile's smallest diameter "
                               "(0.03 m at station 1)"));
  CHECK_THAT(message({{{0.0, 0.05}, {0.8, 0.06}}, 650.0, 1e10, -1e-3}),
             Catch::StartsWith("wall_m: must be in"));
  CHECK_THAT(message({{{0.0, 0.05}, {0.8, 0.06}}, -1.0, 1e10}), Catch::StartsWith("density_kg_m3"));
  CHECK_THAT(message({{{0.0, 0.05}, {0.8, 0.06}}, 650.0, 1e13}),
             Catch::StartsWith("youngs_modulus_Pa"));
}

}  // namespace
}  // namespace sweetspot
