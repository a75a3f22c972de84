// The stringer's bed through the design reader: a ticket with equal families
// is the plain bed, the pattern's spacings and the pull's loss as the docs
// state them, a measurement calibrates the bed to itself, every inverse put
// back gives its target, and Cross's 500-700 Hz for strung racquets.
#include "studies/string_ticket.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::studies {
namespace {

constexpr double kRoundOff = 1e-12;
constexpr double kPi = std::numbers::pi;

io::DesignFile read(const std::string& strings) {
  return io::read_design(io::Json::parse(R"({"implement": {"length_in": 27, "mass_g": 305,
      "balance_cm": 32.5, "swingweight_kg_cm2": 320, "headsize_sq_in": 100},
      "frame": {"cor": 0.8}, "strings": )" +
                                         strings + "}"),
                         "ticket.json");
}

const StringBed& bed(const io::DesignFile& f) { return *f.design.strings; }

TEST_CASE("A ticket with equal mains and crosses evaluates as the plain bed, to the bit") {
  const io::DesignFile plain =
      read(R"({"tension_lb": 52, "string_spacing_mm": 16, "material": "nylon", "gauge_mm": 1.30})");
  const io::DesignFile ticket = read(R"({"string_spacing_mm": 16,
      "mains": {"tension_lb": 52, "material": "nylon", "gauge_mm": 1.30},
      "crosses": {"tension_lb": 52, "material": "nylon", "gauge_mm": 1.30}})");
  const Evaluation a = evaluate(plain.design, Fidelity::kRigid);
  const Evaluation b = evaluate(ticket.design, Fidelity::kRigid);
  for (const io::OutputSpec& spec : io::output_specs()) {
    INFO(spec.name);
    CHECK(spec.value(a) == spec.value(b));
  }
}

TEST_CASE("A pattern is read as a stringer writes it: x, X or the sign, spaces around it") {
  const io::DesignFile f = read(R"({"tension_lb": 52, "pattern": "16x19"})");
  for (const char* spelling : {"16X19", "16 x 19", "16\u00d719", " 16 \u00d7 19 "}) {
    INFO(spelling);
    const io::DesignFile g =
        read(std::string(R"({"tension_lb": 52, "pattern": ")") + spelling + "\"}");
    CHECK(bed(g).main_spacing_m() == bed(f).main_spacing_m());
    CHECK(bed(g).cross_spacing_m() == bed(f).cross_spacing_m());
  }
  // Digits only: no sign, and a count too large for an int is refused, not wrapped.
  for (const char* refused : {"+16x19", "-16x19", "16x", "x19", "16x19x2", "16.0x19",
                              "99999999999999999999x19", "16x4294967315"}) {
    INFO(refused);
    CHECK_THROWS_AS(read(std::string(R"({"tension_lb": 52, "pattern": ")") + refused + "\"}"),
                    io::InputError);
  }
}

TEST_CASE("The pattern spaces the mains across the head's width and the crosses along it") {
  const io::DesignFile f = read(R"({"tension_lb": 52, "pattern": "16x19"})");
  const double area = 100 * 0.0254 * 0.0254, aspect = 1.35;
  const double width = 2.0 * std::sqrt(area / (kPi * aspect));
  CHECK(bed(f).main_spacing_m() == Approx(width / 16).epsilon(kRoundOff));
  CHECK(bed(f).cross_spacing_m() == Approx(width * aspect / 19).epsilon(kRoundOff));
  // At one tension on one head, 18x20 is sqrt(360 / 304) times as stiff as
  // 16x19, and rings the same (the tension over the mass per length).
  const io::DesignFile dense = read(R"({"tension_lb": 52, "pattern": "18x20"})");
  CHECK(string_bed_stiffness(bed(dense)) / string_bed_stiffness(bed(f)) ==
        Approx(std::sqrt(360.0 / 304.0)).epsilon(kRoundOff));
  CHECK(string_bed_ring_frequency(bed(dense)) ==
        Approx(string_bed_ring_frequency(bed(f))).epsilon(kRoundOff));
}

TEST_CASE("The bed holds the pull less its tension loss, a hybrid keeps its crosses' share") {
  const io::DesignFile f = read(R"({"tension_loss": 0.3, "pattern": "16x19",
      "mains": {"material": "polyester", "gauge_mm": 1.25, "tension_lb": 52},
      "crosses": {"material": "multifilament", "gauge": "16", "tension_lb": 54}})");
  CHECK(bed(f).tension_N == Approx(52 * 4.4482216152605 * 0.7).epsilon(kRoundOff));
  CHECK(bed(f).cross_tension_N() == Approx(54 * 4.4482216152605 * 0.7).epsilon(kRoundOff));
  CHECK(bed(f).pull_tension_N() == Approx(52 * 4.4482216152605).epsilon(kRoundOff));
  CHECK(bed(f).main_linear_density_kg_m ==
        Approx(1380.0 * kPi * 1.25e-3 * 1.25e-3 / 4).epsilon(kRoundOff));
  CHECK(bed(f).cross_linear_density_kg_m ==
        Approx(1140.0 * kPi * 1.295e-3 * 1.295e-3 / 4).epsilon(kRoundOff));
}

TEST_CASE("Strung racquets ring at 500-700 Hz (Cross 2006) with the 30 % lost in stringing") {
  // Cross & Bower (2001): right after stringing the bed holds about 70 % of
  // the pull; Cross ("Measuring string tension", 2006): strung racquets ring
  // at 500-700 Hz. Typical tickets, 50-60 lb of nylon or polyester.
  for (const char* material : {"nylon", "polyester", "multifilament"}) {
    for (const int lb : {50, 55, 60}) {
      const io::DesignFile f = read(std::string(R"({"tension_loss": 0.3, "pattern": "16x19",
          "material": ")") + material +
                                    R"(", "tension_lb": )" + std::to_string(lb) + "}");
      INFO(material << " " << lb << " lb");
      const double ring = string_bed_ring_frequency(bed(f));
      CHECK(ring >= 500.0);
      CHECK(ring <= 700.0);
    }
  }
}

TEST_CASE("A measured ring or stiffness calibrates the bed to itself") {
  const io::DesignFile ring = read(R"({"tension_lb": 52, "measured_ring_Hz": 560})");
  CHECK(string_bed_ring_frequency(bed(ring)) == Approx(560.0).epsilon(kRoundOff));
  CHECK(ring.provenance.at("strings/tension_N").find("predicted") != std::string::npos);
  const io::DesignFile k = read(R"({"pattern": "18x20", "measured_stiffness_lb_in": 180})");
  CHECK(string_bed_stiffness(bed(k)) == Approx(180 * 4.4482216152605 / 0.0254).epsilon(kRoundOff));
}

TEST_CASE("Each inverse, put back into the forward model, gives its target") {
  const io::DesignFile f = read(R"({"pattern": "18x20", "tension_loss": 0.1,
      "mains": {"material": "polyester", "gauge_mm": 1.25, "tension_lb": 52},
      "crosses": {"material": "multifilament", "gauge": "16", "tension_lb": 54}})");
  const BedReading now = read_bed(f.design);
  for (const BedQuantity q : {BedQuantity::kStiffness, BedQuantity::kRing, BedQuantity::kDwell}) {
    INFO(to_string(q));
    const double target = 0.93 * now.value(q);
    const TensionAnswer a = tension_for(f.design, q, target);
    REQUIRE(a.reachable);
    CHECK(read_bed(with_pull(f.design, a.exact_pull_N)).value(q) == Approx(target).epsilon(1e-9));
    // Each family rounded to the machine's half pound: the mains within a
    // quarter pound of the exact, the crosses within a quarter of their share of
    // the rounded mains, so the bed within half a pound's change of the target.
    CHECK(std::fmod(a.rounded_pull_lb * 2, 1.0) == 0.0);
    CHECK(std::fmod(a.rounded_cross_pull_lb * 2, 1.0) == 0.0);
    CHECK(std::fabs(a.rounded_pull_lb - a.exact_pull_N / 4.4482216152605) <= 0.25);
    CHECK(std::fabs(a.rounded_cross_pull_lb - a.rounded_pull_lb * 54.0 / 52.0) <= 0.25);
    CHECK(std::fabs(a.at_rounded.value(q) - target) <= 0.5 * std::fabs(a.at_rounded.per_lb(q)));
    // The exact answer keeps the crosses' share of the mains'.
    CHECK(a.exact_cross_pull_N / a.exact_pull_N == Approx(54.0 / 52.0).epsilon(kRoundOff));
  }
  // The same bed is matched by its own tension.
  const TensionAnswer self = tension_for(f.design, BedQuantity::kStiffness, now.stiffness_N_m);
  CHECK(self.exact_pull_N == Approx(52 * 4.4482216152605).epsilon(kRoundOff));
  CHECK(self.rounded_pull_lb == 52.0);
}

TEST_CASE("The dwell is the impact duration the rigid model derives from the same bed") {
  const io::DesignFile f = read(R"({"tension_lb": 52, "pattern": "16x19"})");
  CHECK(read_bed(f.design).dwell_s ==
        Approx(evaluate(f.design, Fidelity::kRigid).impact_duration_s).epsilon(kRoundOff));
}

TEST_CASE(
    "A dwell shorter than the ball's own, or a stiffness past the strongest string, is out of "
    "reach") {
  const io::DesignFile f = read(R"({"tension_lb": 52})");
  CHECK_FALSE(tension_for(f.design, BedQuantity::kDwell, 1e-4).reachable);
  CHECK_FALSE(tension_for(f.design, BedQuantity::kStiffness, 1e9).reachable);
  CHECK_FALSE(tension_for(f.design, BedQuantity::kRing, 1.0).reachable);
  CHECK_THROWS(tension_for(f.design, BedQuantity::kRing, -1.0));
}

}  // namespace
}  // namespace sweetspot::studies
