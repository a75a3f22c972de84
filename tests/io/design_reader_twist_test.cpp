// Lead tape where people put it and the second dimension's inputs:
// from the tip, at clock positions on the hoop, off the axis; the head's size,
// the measured twistweight and an impact off the axis.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/head_geometry.hpp"

namespace sweetspot::io {
namespace {

constexpr double kRoundOff = 1e-12;
constexpr double kLength_m = 27 * 0.0254;

DesignFile read(const std::string& implement_extra, const std::string& rest = "") {
  const std::string text =
      R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
          "swingweight_kg_cm2": 320)" +
      implement_extra + "}" + rest + "}";
  return read_design(parse_json(text, "test.json"), "test.json");
}

std::string error_of(const std::string& implement_extra, const std::string& rest = "") {
  try {
    read(implement_extra, rest);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST_CASE("Lead tape from the tip lands L - d from the butt, on the axis") {
  const DesignFile d = read(R"(, "point_masses": [{"mass_g": 4, "from_tip_cm": 3}])");
  const PointMass& p = d.design.implement.point_masses().at(0);
  CHECK(p.from_butt_m == Approx(kLength_m - 0.03).epsilon(kRoundOff));
  CHECK(p.mass_kg == Approx(0.004).epsilon(kRoundOff));
  CHECK(p.off_axis_m == 0.0);
}

TEST_CASE("Clock positions: 12 alone, a 3-and-9 pair of pieces, the throat and the handle") {
  const DesignFile d = read(R"(, "headsize_sq_in": 100, "point_masses": [
      {"mass_g": 3, "clock": 12}, {"mass_g": 2, "clock": [3, 9]},
      {"mass_g": 5, "clock": "throat"}, {"mass_g": 10, "clock": "handle"}])");
  const HeadShape head{100 * 0.0254 * 0.0254};
  const auto& points = d.design.implement.point_masses();
  REQUIRE(points.size() == 5);
  CHECK(points[0].from_butt_m == Approx(kLength_m - 0.5 * kDefaultHoopWidth_m).epsilon(kRoundOff));
  CHECK(points[1].off_axis_m == clock_position(head, kLength_m, 3).off_axis_m);
  CHECK(points[2].off_axis_m == -points[1].off_axis_m);
  CHECK(points[1].mass_kg == Approx(0.002).epsilon(kRoundOff));  // each piece
  CHECK(points[2].mass_kg == Approx(0.002).epsilon(kRoundOff));
  CHECK(points[3].from_butt_m == clock_position(head, kLength_m, 6).from_butt_m);
  CHECK(points[4].from_butt_m == kHandleWeightFromButt_m);
  // The pair raises the polar inertia by 2 m r^2 over the head's estimate.
  const DesignFile bare = read(R"(, "headsize_sq_in": 100)");
  const double r = points[1].off_axis_m;
  CHECK(*polar_inertia_kg_m2(d.design) - *polar_inertia_kg_m2(bare.design) ==
        Approx(2 * 0.002 * r * r).epsilon(kRoundOff));
}

TEST_CASE("A measured twistweight is the polar inertia, an impact off the axis is read in cm") {
  const DesignFile d = read(R"(, "twistweight_kg_cm2": 14.5)",
                            R"(, "impact": {"from_tip_cm": 17, "off_axis_cm": -4})");
  CHECK(*d.design.twistweight_kg_m2 == Approx(14.5e-4).epsilon(kRoundOff));
  CHECK(d.design.impact_off_axis_m == Approx(-0.04).epsilon(kRoundOff));
  CHECK(d.provenance.at("implement/twistweight_kg_m2") == "given");
  const Evaluation e = evaluate(d.design);
  CHECK(*e.polar_inertia_kg_m2 == Approx(14.5e-4).epsilon(kRoundOff));
  CHECK(e.impact_off_axis_m == Approx(-0.04).epsilon(kRoundOff));
}

TEST_CASE("Bad clock positions and head inputs are named at the user's key") {
  CHECK_THAT(error_of(R"(, "point_masses": [{"mass_g": 3, "clock": 12}])"),
             Catch::Contains("/implement/point_masses/0/clock") && Catch::Contains("headsize"));
  CHECK_THAT(error_of(R"(, "headsize_sq_in": 100, "point_masses": [{"mass_g": 3, "clock": 13}])"),
             Catch::Contains("/implement/point_masses/0/clock") && Catch::Contains("13"));
  CHECK_THAT(
      error_of(R"(, "headsize_sq_in": 100, "point_masses": [{"mass_g": 3, "clock": [3, "nine"]}])"),
      Catch::Contains("/implement/point_masses/0/clock"));
  CHECK_THAT(
      error_of(
          R"(, "headsize_sq_in": 100, "point_masses": [{"mass_g": 3, "clock": 3, "from_tip_cm": 2}])"),
      Catch::Contains("/implement/point_masses/0/"));
  CHECK_THAT(error_of(R"(, "point_masses": [{"mass_g": 3}])"),
             Catch::Contains("/implement/point_masses/0") && Catch::Contains("clock"));
  CHECK_THAT(error_of(R"(, "point_masses": [{"mass_g": 3, "from_tip_cm": 90}])"),
             Catch::Contains("/implement/point_masses/0/from_tip_cm"));
  CHECK_THAT(error_of(R"(, "headsize_sq_in": -100)"), Catch::Contains("/implement/headsize_sq_in"));
  CHECK_THAT(error_of(R"(, "headsize_sq_in": 3000)"), Catch::Contains("/implement/headsize_sq_in"));
  CHECK_THAT(error_of(R"(, "head_aspect_ratio": 1.2)"),
             Catch::Contains("/implement/head_aspect_ratio"));
  CHECK_THAT(error_of(R"(, "twistweight_kg_cm2": 0)"),
             Catch::Contains("/implement/twistweight_kg_cm2"));
  CHECK_THAT(error_of("", R"(, "impact": {"off_axis_cm": 3})"),
             Catch::Contains("/impact/off_axis_cm") && Catch::Contains("twistweight"));
}

}  // namespace
}  // namespace sweetspot::io
