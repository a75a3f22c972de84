// Mass properties: the parallel-axis theorem, Cross (2004) Eq. (14) for an
// attached point mass, and the swingweight's inverse.
#include "sweetspot/mass_properties.hpp"

#include <catch2/catch.hpp>
#include <stdexcept>

namespace sweetspot {
namespace {

// Sums of a few products of O(1) numbers: a few ulps.
constexpr double kRoundOff = 1e-14;

TEST_CASE("Inertia about an axis adds M d^2 to the inertia about the centre of mass") {
  const MassProperties beam{0.328, 0.36, 0.328 * 0.72 * 0.72 / 12.0};
  // About the end of a uniform beam: M L^2 / 3.
  CHECK(inertia_about(beam, 0.0) == Approx(0.328 * 0.72 * 0.72 / 3.0).epsilon(kRoundOff));
  CHECK(inertia_about(beam, 0.36) == beam.I_cm_kg_m2);
  // The swingweight is the inertia about the axis 10 cm from the butt.
  CHECK(swingweight_kg_m2(beam) == inertia_about(beam, kSwingweightAxisFromButt_m));
}

TEST_CASE(
    "A 0.5 kg hand 7 cm from the butt moves the beam's centre 0.175 m, Cross (2004) Eq. (14)") {
  const MassProperties beam{0.328, 0.36, 0.328 * 0.72 * 0.72 / 12.0};
  const MassProperties held = with_point_mass(beam, PointMass{0.07, 0.5});
  CHECK(held.mass_kg == Approx(0.828).epsilon(kRoundOff));
  // x = M_h (c - 0.07) / (M_b + M_h) = 0.5 * 0.29 / 0.828 = 0.1751 m (the paper: 0.175 m).
  CHECK(beam.com_from_butt_m - held.com_from_butt_m ==
        Approx(0.5 * 0.29 / 0.828).epsilon(kRoundOff));
  // Parallel axes for both parts about the new centre (the paper's printed
  // 0.0309 kg m^2 is checked in rigid_impact_test with its rounding).
  const double h = held.com_from_butt_m;
  CHECK(held.I_cm_kg_m2 ==
        Approx(beam.I_cm_kg_m2 + 0.328 * (0.36 - h) * (0.36 - h) + 0.5 * (h - 0.07) * (h - 0.07))
            .epsilon(kRoundOff));
}

TEST_CASE("Attaching a point mass keeps the inertia about every axis additive") {
  const MassProperties body{0.3, 0.33, 0.012};
  const PointMass tape{0.68, 0.006};
  const MassProperties sum = with_point_mass(body, tape);
  for (const double axis : {0.0, 0.1, 0.33, 0.7}) {
    const double expected = inertia_about(body, axis) +
                            tape.mass_kg * (tape.from_butt_m - axis) * (tape.from_butt_m - axis);
    CHECK(inertia_about(sum, axis) == Approx(expected).epsilon(kRoundOff));
  }
  CHECK(with_point_mass(body, PointMass{0.5, 0.0}).I_cm_kg_m2 == body.I_cm_kg_m2);
  CHECK_THROWS_AS(with_point_mass(body, PointMass{0.5, -0.001}), std::invalid_argument);
}

TEST_CASE(
    "from_swingweight inverts swingweight_kg_m2 and refuses a swingweight below M (B - 0.1)^2") {
  const MassProperties body = from_swingweight(0.318, 0.325, 0.0325);
  CHECK(swingweight_kg_m2(body) == Approx(0.0325).epsilon(kRoundOff));
  CHECK(body.com_from_butt_m == 0.325);
  CHECK(body.I_cm_kg_m2 == Approx(0.0325 - 0.318 * 0.225 * 0.225).epsilon(kRoundOff));
  // Exactly the point-mass limit is allowed (I_cm = 0); a hair below is not.
  const double limit = 0.318 * 0.225 * 0.225;
  CHECK(from_swingweight(0.318, 0.325, limit).I_cm_kg_m2 == Approx(0.0).margin(kRoundOff));
  CHECK_THROWS_WITH(from_swingweight(0.318, 0.325, limit * 0.99),
                    Catch::StartsWith("swingweight: must be >="));
  CHECK_THROWS_AS(from_swingweight(0.0, 0.325, 0.03), std::invalid_argument);
}

}  // namespace
}  // namespace sweetspot
