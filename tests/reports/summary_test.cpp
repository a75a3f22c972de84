#include "reports/summary.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "io/design_reader.hpp"
#include "studies/frame_curves.hpp"
#include "studies/sweet_spots.hpp"

namespace sweetspot::reports {
namespace {

io::DesignFile design_from(const char* text) {
  return io::read_design(io::Json::parse(text), "test.json");
}

constexpr const char* kSpecSheet = R"({
  "name": "spec sheet",
  "implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5, "swingweight_kg_cm2": 325},
  "frame": {"fundamental_free_Hz": 150},
  "strings": {"tension_lb": 52}})";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE(
    "Positions are rounded to half a centimetre, forces to two figures, ratios to two "
    "decimals") {
  CHECK(cm_text(0.306761) == "30.5 cm");
  CHECK(cm_text(0.129363) == "13 cm");
  CHECK(cm_text(0.0) == "0 cm");
  CHECK(newton_text(474.449) == "470 N");
  CHECK(newton_text(1334.95) == "1300 N");
  CHECK(newton_text(5.44) == "5.4 N");
  CHECK(newton_text(0.2) == "0 N");
  CHECK(ratio_text(0.188157) == "0.19");
  CHECK(ratio_text(-0.001) == "0.00");  // never "-0.00"
}

TEST_CASE(
    "The centre of the strings of a 100 sq in head is the head ellipse's half length inside "
    "the hoop") {
  // Closed form of head_geometry.hpp's string bed: one hoop width (1.5 cm) plus the
  // semi-length a = sqrt(A k / pi) (pi a c = A, a = k c) below the tip, A = 100 sq in,
  // aspect k = 1.35.
  const double area = 100 * 0.0254 * 0.0254;
  const double expected = 0.015 + std::sqrt(area * 1.35 / std::numbers::pi);
  // A spec sheet without strings: the default head of exactly 100 sq in.
  CHECK(studies::centre_of_strings_from_tip_m(design_from(
            R"({"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
                "swingweight_kg_cm2": 325}})")) == Approx(expected).epsilon(1e-12));
  // With strings, the string bed's head (its default radius, 0.1433 m, is 100 sq in to 4 digits).
  CHECK(studies::centre_of_strings_from_tip_m(design_from(kSpecSheet)) ==
        Approx(expected).epsilon(1e-4));
  CHECK(expected == Approx(0.1815).margin(1e-4));
  // A head given on the implement is used as it is: 110 sq in, aspect 1.2, a 2 cm hoop.
  const double a110 = std::sqrt(110 * 0.0254 * 0.0254 * 1.2 / std::numbers::pi);
  CHECK(studies::centre_of_strings_from_tip_m(design_from(
            R"({"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
                "swingweight_kg_cm2": 325, "headsize_sq_in": 110, "head_aspect_ratio": 1.2,
                "hoop_width_cm": 2}})")) == Approx(0.02 + a110).epsilon(1e-12));
}

TEST_CASE(
    "A racquet without an impact is hit at the centre of its strings, the paper's designs "
    "keep 5 cm from the tip") {
  const io::DesignFile racquet = (design_from(kSpecSheet));
  CHECK(racquet.design.implement.length_m() - racquet.design.impact_from_butt_m ==
        Approx(studies::centre_of_strings_from_tip_m(racquet)));
  CHECK(contains(racquet.provenance.at("impact/from_butt_m"), "centre of the strings"));

  const io::DesignFile paper = (design_from(
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8}})"));
  CHECK(paper.design.impact_from_butt_m == Approx(0.65));

  const io::DesignFile given = (design_from(
      R"({"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
          "swingweight_kg_cm2": 325}, "impact": {"from_tip_cm": 5}})"));
  CHECK(given.design.implement.length_m() - given.design.impact_from_butt_m == Approx(0.05));
}

TEST_CASE(
    "The sweet spots: no wrist force at the hand-held COP, and the node's distance from it "
    "is the COP-node gap") {
  const io::DesignFile design = (design_from(kSpecSheet));
  const Evaluation asked = io::evaluate_design_file(design, "", 1e-6);
  const studies::SweetSpots spots = studies::find_sweet_spots(design, asked, 1e-6);
  REQUIRE(spots.cop_hand);
  REQUIRE(spots.node_hand);
  REQUIRE(spots.centre_of_strings);
  // Cross (2004) Eq. (11): F_w / F vanishes at the COP of Eq. (13).
  CHECK(spots.cop_hand->evaluation.wrist_force_ratio == Approx(0.0).margin(1e-12));
  CHECK(spots.cop_hand->from_tip_m ==
        Approx(asked.length_m - *asked.cop_hand_from_butt_m).epsilon(1e-12));
  CHECK(spots.node_hand->from_tip_m ==
        Approx(asked.length_m - *asked.modal->node_hand_from_butt_m).epsilon(1e-12));
  CHECK(spots.best_rebound.has_value() == (fidelity_of(asked) == Fidelity::kCollision));
  const studies::SweetSpots modal =
      studies::find_sweet_spots(design, io::evaluate_design_file(design, "modal", 1e-6), 1e-6);
  CHECK_FALSE(modal.best_rebound);  // the collision fidelity's

  const std::string text = sweet_spot_paragraph(design, spots);
  CHECK(contains(text, cm_text(spots.cop_hand->from_tip_m) + " from the tip"));
  CHECK(contains(text, cm_text(spots.node_hand->from_tip_m) + " from the tip"));
  CHECK(
      contains(text, cm_text(spots.cop_hand->from_tip_m - spots.node_hand->from_tip_m) + " apart"));
  CHECK(contains(text, newton_text(spots.node_hand->evaluation.peak_wrist_force_N)));
  CHECK(contains(text, "no impact was given"));
  // The shot is from the impact the tables are for, named as the default it is.
  CHECK(contains(text, "from the centre of the strings it leaves at"));
  CHECK_FALSE(contains(text, "asked about"));
}

TEST_CASE(
    "A paper design without an impact is hit where the paper's Table I hits, 5 cm from the tip") {
  const io::DesignFile design = design_from(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}})");
  const Evaluation asked = io::evaluate_design_file(design, "", 1e-6);
  CHECK(asked.length_m - asked.impact_from_butt_m == Approx(0.05).epsilon(1e-12));
  const std::string text =
      sweet_spot_paragraph(design, studies::find_sweet_spots(design, asked, 1e-6));
  CHECK(contains(text,
                 "At 5 cm from the tip, where the paper's Table I hits (no impact was given, "
                 "so the tables below are for this one)"));
  CHECK_FALSE(contains(text, "asked about"));
  CHECK_FALSE(contains(text, "(5 cm"));
  // An impact given only by its offset, 0, was given: its place along the axis was not.
  const io::DesignFile offset = design_from(R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "impact": {"off_axis_cm": 0}})");
  const std::string on_axis = sweet_spot_paragraph(
      offset, studies::find_sweet_spots(offset, io::evaluate_design_file(offset, "", 1e-6), 1e-6));
  CHECK(contains(on_axis, "the impact's distance from the tip was not given"));
  CHECK_FALSE(contains(on_axis, "no impact was given"));
}

TEST_CASE("Without the stiffness the sentences say which input would locate the node") {
  const io::DesignFile design = design_from(
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8}})");
  const Evaluation asked = io::evaluate_design_file(design, "", 1e-6);
  const studies::SweetSpots spots = studies::find_sweet_spots(design, asked, 1e-6);
  CHECK_FALSE(spots.node_hand);
  CHECK_FALSE(spots.centre_of_strings);
  const std::string text = sweet_spot_paragraph(design, spots);
  CHECK(contains(text, "frame.fundamental_free_Hz"));
  CHECK(contains(text, "5 cm from the tip"));
}

}  // namespace sweetspot::reports

namespace sweetspot::reports {

TEST_CASE(
    "The point of best rebound: the golden-section search agrees with a brute-force scan, near "
    "the fundamental's node") {
  const io::DesignFile design =
      io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json");
  const Evaluation asked = io::evaluate_design_file(design, "collision", 1e-6);
  const studies::SweetSpots spots = studies::find_sweet_spots(design, asked, 1e-6);
  REQUIRE(spots.best_rebound);
  const double found = spots.best_rebound->from_tip_m;
  // Brute force: every 2.5 mm along the string bed's axis (head_geometry.hpp:
  // one hoop width below the tip to 2a further).
  const HeadShape head = studies::head_shape_of(design);
  const double a = std::sqrt(head.area_m2 * head.aspect_ratio / std::numbers::pi);
  double best_x = 0.0, best_cor = -1.0;
  for (double x = head.hoop_width_m; x <= head.hoop_width_m + 2.0 * a; x += 0.0025) {
    io::DesignFile moved = design;
    moved.design.impact_from_butt_m = asked.length_m - x;
    const double cor = io::evaluate_design_file(moved, "collision", 1e-6).apparent_cor;
    if (cor > best_cor) best_cor = cor, best_x = x;
  }
  // The search's tolerance (0.5 cm) plus the scan's half step.
  CHECK(found == Approx(best_x).margin(studies::kBestReboundTolerance_m + 0.00125));
  CHECK(spots.best_rebound->evaluation.apparent_cor >= best_cor - 1e-3);
  const std::string text = sweet_spot_paragraph(design, spots);
  CHECK(contains(text, "comes back fastest"));
  CHECK(contains(text, cm_text(found) + " from the tip"));
  CHECK(contains(text, newton_text(spots.best_rebound->evaluation.peak_wrist_force_N)));
  // Where it lies. Cross, Am. J. Phys. 68, 1025 (2000): the frame's COR e is
  // largest at the fundamental's node (collision_test.cpp checks it to 1 cm);
  // the rebound speed is the apparent COR e_A = (e M_eff - m) / (M_eff + m)
  // (Eq. 16), and M_eff grows towards the handle, so e_A peaks between the node
  // and the throat: on this racquet 5.5 cm throat-side of the hand-held node
  // (17.7 cm against 12.2 cm from the tip), inside the string bed. Checked: at
  // the node e is higher and e_A lower than at the point found, and the point is
  // throat-side of the node by less than the string bed's semi-length a.
  REQUIRE(spots.node_hand);
  CHECK(spots.node_hand->evaluation.cor > spots.best_rebound->evaluation.cor);
  CHECK(spots.node_hand->evaluation.apparent_cor < spots.best_rebound->evaluation.apparent_cor);
  CHECK(found > spots.node_hand->from_tip_m);
  CHECK(found - spots.node_hand->from_tip_m < a);
  CHECK_THROWS_WITH(studies::best_rebound_on_axis(design, 1e-6, 0.0),
                    Catch::Contains("tolerance_m"));
}

TEST_CASE(
    "A hit the ball goes on through is not called a rebound, and an impact given across "
    "the axis alone is said to be placed along it by default") {
  // The light junior frame hit near the throat's edge, 12 cm off the axis: the
  // racquet gives way faster than the ball is pushed back (e_A < 0).
  io::DesignFile design = design_from(R"({
    "implement": {"length_in": 25, "mass_g": 230, "balance_cm": 33, "swingweight_kg_cm2": 250,
                  "headsize_sq_in": 105},
    "frame": {"fundamental_free_Hz": 145.9}, "strings": {"tension_lb": 50},
    "impact": {"from_tip_m": 0.2436, "off_axis_m": -0.1188}})");
  Evaluation asked = io::evaluate_design_file(design, "collision", 1e-6);
  REQUIRE(asked.apparent_cor < -0.005);
  REQUIRE(asked.shot_speed_m_s * 3.6 < -0.5);
  std::string text = sweet_spot_paragraph(design, studies::find_sweet_spots(design, asked, 1e-6));
  INFO(text);
  CHECK(contains(text, "the ball does not come back: it goes on at " +
                           ratio_text(-asked.apparent_cor) + " of its speed"));
  CHECK(contains(text, "it goes on past the racquet at"));
  CHECK(contains(text, "12 cm off the axis"));
  CHECK_FALSE(contains(text, "comes back at -"));
  CHECK_FALSE(contains(text, "leaves at -"));
  // Only across the axis: the place along it is the default, said as such.
  design = design_from(R"({
    "implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5, "swingweight_kg_cm2": 325,
                  "headsize_sq_in": 100},
    "frame": {"RA": 66}, "strings": {"tension_lb": 52}, "impact": {"off_axis_cm": 3}})");
  asked = io::evaluate_design_file(design, "collision", 1e-6);
  text = sweet_spot_paragraph(design, studies::find_sweet_spots(design, asked, 1e-6));
  INFO(text);
  CHECK(contains(text,
                 "from the tip and 3 cm off the axis (the impact's distance from the tip "
                 "was not given"));
  CHECK_FALSE(contains(text, "no impact was given"));
}

TEST_CASE(
    "The best rebound and the power point are the largest along the string bed where the rebound "
    "has two humps") {
  // A light, soft junior frame: the rebound dips mid-strings (0.21) between a
  // hump towards the tip (0.30) and a higher one at the throat (0.42). A search
  // that assumes one hump had answered the lower. (Its 145.9 Hz is what RA 60
  // gives a 230 g adult frame; a junior's own RA is not used, its length being
  // outside the relation's.)
  const io::DesignFile design = design_from(R"({
    "implement": {"length_in": 25, "mass_g": 230, "balance_cm": 33, "swingweight_kg_cm2": 250,
                  "headsize_sq_in": 105},
    "frame": {"fundamental_free_Hz": 145.9}, "strings": {"tension_lb": 50}})");
  const Evaluation asked = io::evaluate_design_file(design, "collision", 1e-6);
  const studies::SweetSpots spots = studies::find_sweet_spots(design, asked, 1e-6);
  REQUIRE(spots.best_rebound);
  REQUIRE(spots.power_point);
  // Brute force every 2.5 mm over the axis the search covers.
  const studies::AxisSpan span = studies::hit_span(design);
  double best_cor = -1.0, best_shot = 0.0, cor_x = 0.0, shot_x = 0.0, dip = 1.0;
  for (double x = span.from_tip_m; x <= span.to_tip_m; x += 0.0025) {
    io::DesignFile moved = design;
    moved.design.impact_from_butt_m = asked.length_m - x;
    const Evaluation e = io::evaluate_design_file(moved, "collision", 1e-6);
    if (e.apparent_cor > best_cor) best_cor = e.apparent_cor, cor_x = x;
    if (e.shot_speed_m_s > best_shot) best_shot = e.shot_speed_m_s, shot_x = x;
    if (std::abs(x - 0.185) < 0.01) dip = std::min(dip, e.apparent_cor);
  }
  CHECK(dip < best_cor - 0.1);  // two humps indeed
  CHECK(spots.best_rebound->from_tip_m ==
        Approx(cor_x).margin(studies::kBestReboundTolerance_m + 0.00125));
  CHECK(spots.best_rebound->evaluation.apparent_cor >= best_cor - 1e-3);
  CHECK(spots.power_point->from_tip_m ==
        Approx(shot_x).margin(studies::kBestReboundTolerance_m + 0.00125));
  CHECK(spots.power_point->evaluation.shot_speed_m_s >= best_shot * (1.0 - 1e-3));
}

}  // namespace sweetspot::reports

namespace sweetspot::reports {

TEST_CASE("Off a swinging racquet the answer gives the speed ball and strings meet at") {
  // A serve: the ball at rest, the racquet swung at 14 rad/s about a pivot 60 cm beyond the
  // butt. The COP's meeting speed is the racquet's there, omega (pivot + x_cop).
  const io::DesignFile design = design_from(R"({
    "implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5, "swingweight_kg_cm2": 325},
    "frame": {"fundamental_free_Hz": 150}, "strings": {"tension_lb": 52},
    "swing": {"angular_speed_rad_s": 14, "pivot_beyond_butt_cm": 60}, "ball": {"speed_m_s": 0}})");
  const auto spots = studies::find_sweet_spots(design, evaluate(design.design), 1e-6);
  const std::string text = sweet_spot_paragraph(design, spots);
  INFO(text);
  REQUIRE(spots.cop_hand);
  const double meet = 14 * (0.60 + (0.6858 - spots.cop_hand->from_tip_m));
  char expected[64];
  std::snprintf(expected, sizeof expected, "(they meet at %.3g m/s there)", meet);
  CHECK(contains(text, expected));
  CHECK(contains(text, "of the speed it meets the strings at"));
  CHECK_FALSE(contains(text, "of its speed"));
  CHECK_FALSE(contains(text, "For a ball at 0 m/s"));
}

TEST_CASE("Off a swinging bat the answer speaks of the implement, not of a racquet's strings") {
  // The same swing on a beam of two sections with no head and no strings (the
  // paper's beam): it has no strings for the ball to meet.
  const io::DesignFile design = design_from(R"({
    "implement": {"sections": [{"length_m": 0.72, "mass_kg": 0.328}]},
    "frame": {"fundamental_free_Hz": 193},
    "swing": {"angular_speed_rad_s": 14, "pivot_beyond_butt_cm": 60}, "ball": {"speed_m_s": 0}})");
  const auto spots = studies::find_sweet_spots(design, evaluate(design.design), 1e-6);
  const std::string text = sweet_spot_paragraph(design, spots);
  INFO(text);
  REQUIRE(spots.cop_hand);
  CHECK(contains(text, "onto the swinging implement (they meet at"));
  CHECK(contains(text, "of the speed it meets the implement at"));
  CHECK_FALSE(contains(text, "racquet"));
  CHECK_FALSE(contains(text, "strings"));
}

}  // namespace sweetspot::reports

namespace sweetspot::reports {

TEST_CASE("A power point found with a given COR says the COR was taken the same everywhere") {
  // A COR given for the frame (modal): e_A peaks near the balance, and so does the shot.
  const io::DesignFile given = design_from(R"({
    "implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5, "swingweight_kg_cm2": 320},
    "frame": {"cor": 0.8, "fundamental_free_Hz": 155}})");
  const std::string modal = sweet_spot_paragraph(
      given, studies::find_sweet_spots(given, evaluate(given.design, Fidelity::kModal), 1e-6));
  INFO(modal);
  CHECK(contains(modal, "the power point"));
  CHECK(contains(modal, "takes the frame's COR as the same at every point"));
  // The solved collision (a tension and a stiffness, no COR): no such caveat.
  const io::DesignFile solved = design_from(kSpecSheet);
  const std::string collision = sweet_spot_paragraph(
      solved,
      studies::find_sweet_spots(solved, evaluate(solved.design, Fidelity::kCollision), 1e-6));
  INFO(collision);
  CHECK(contains(collision, "the power point"));
  CHECK_FALSE(contains(collision, "takes the frame's COR as the same"));
}

}  // namespace sweetspot::reports

namespace sweetspot::reports {

TEST_CASE("A sweet spot the model cannot answer is said why in cm, as the rest of the answer") {
  // 3 kg under the grip puts the centre of percussion beyond the strings: the
  // model's reason gives the bed's span and the spot in metres, the answer in cm.
  const io::DesignFile design = design_from(R"({
    "implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5, "swingweight_kg_cm2": 325,
                  "headsize_sq_in": 100, "point_masses": [{"clock": "grip", "mass_g": 3000}]},
    "frame": {"fundamental_free_Hz": 150}, "strings": {"tension_lb": 52}})");
  const auto spots = studies::find_sweet_spots(design, evaluate(design.design), 1e-6);
  REQUIRE_FALSE(spots.unanswered.empty());
  const studies::UnansweredSpot& spot = spots.unanswered.front();
  INFO(spot.why);
  REQUIRE(spot.why.find(" m from the tip") != std::string::npos);
  const std::string text = sweet_spot_paragraph(design, spots);
  INFO(text);
  CHECK(text.find("The model cannot answer a hit at the " + spot.what + ", " +
                  cm_text(spot.from_tip_m) +
                  " from the tip: a ball on the strings must land on "
                  "them, 1.5 to ") != std::string::npos);
  CHECK(text.find(" cm from the tip along the axis, got " + cm_text(spot.from_tip_m)) !=
        std::string::npos);
  CHECK(text.find(" m from the tip") == std::string::npos);
}

}  // namespace sweetspot::reports
