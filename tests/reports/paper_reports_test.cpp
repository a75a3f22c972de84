// Figs. 5 and 11 of Cross (2004) from the shipped beam design, against the
// numbers the paper prints in Sections III and V.B.
#include "reports/paper_reports.hpp"

#include <catch2/catch.hpp>

#include "io/format.hpp"
#include "studies/paper.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"
#include "sweetspot/swing.hpp"

namespace sweetspot::reports {
namespace {

// The paper prints these positions to 1 mm.
constexpr double kHalfMillimetre = 0.5e-3;

io::DesignFile beam() {
  return io::load_design(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/paper-beam.json");
}

TEST_CASE("Fig. 5: v2/v16 is 1 for an impact in the middle of the beam") {
  const reports::Figure figure = reports::figure5(beam(), studies::figure5_data(beam()));
  // The CSV row for d = 0.36 m.
  CHECK(figure.csv.find("\n0.36,0.36,1\n") != std::string::npos);
}

TEST_CASE("Fig. 11: for every impact the hand-held axis lies nearer the handle than the free one") {
  // Section V.B: "The rotation axis for the hand-held beam is located under the
  // hand or near the handle end of the beam for all impact points" from the free
  // end up to the hand-held COP.
  const io::DesignFile b = beam();
  const MassProperties system = hand_held_system(b.design);
  const double cop = *hand_held_cop_from_butt(system);
  for (double x = cop; x <= 0.72; x += 0.01) {
    const double s = *hand_held_rotation_axis_from_butt(system, 0.5, x);
    CHECK(s >= -kHalfMillimetre);
    CHECK(s <= 0.07);  // no further than the hand's centre
  }
}

TEST_CASE("The figures quote the paper's numbers beside the paper's beam only") {
  const io::DesignFile paper = beam();
  CHECK(reports::figure5(paper, studies::figure5_data(paper))
            .summary.find("(paper: COP 23.3 cm from the end)") != std::string::npos);
  CHECK(reports::figure11(paper, studies::figure11_data(paper))
            .summary.find("(paper: 22.8 cm and 3.2 cm)") != std::string::npos);
  io::DesignFile other = paper;  // another beam in its place: nothing to compare with
  other.reference = io::Json();
  for (const std::string& summary :
       {reports::figure5(other, studies::figure5_data(other)).summary,
        reports::figure11(other, studies::figure11_data(other)).summary}) {
    CHECK(summary.find("paper") == std::string::npos);
    CHECK(summary.find("nan") == std::string::npos);
  }
}

TEST_CASE("Table I's caption says what its rows were computed for") {
  // The shipped rows: the paper's set-up, as its Section IV states it.
  std::vector<studies::Table1Row> rows =
      studies::compute_table1(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/table1");
  const auto caption = [&] {
    const std::string md = reports::table1_report(rows, io::Format::kMarkdown);
    const std::size_t from = md.find("\n\n") + 2;
    return md.substr(from, md.find(" Masses in kg") - from);
  };
  CHECK(caption() ==
        "A 70 cm racquet struck 5 cm from the tip by a 57 g ball at 50 m/s relative to the "
        "strings; hand centre 7 cm from the butt, wrist at the butt.");
  // Rows edited away from it say so, each by its row, with the speed a swung
  // racquet adds at the impact as evaluate() computed it.
  Design& swung = rows[2].design.design;
  swung.ball.speed_m_s = 30.0;
  swung.swing = Swing{15.0, 0.6, std::nullopt};
  rows[2].evaluation = evaluate(swung);
  Design& moved = rows[4].design.design;
  moved.impact_from_butt_m = moved.implement.length_m() - 0.10;
  moved.hand.center_from_butt_m = 0.08;
  rows[4].evaluation = evaluate(moved);
  CHECK(caption() ==
        "A 70 cm racquet struck 5 cm (row 5: 10 cm) from the tip by a 57 g ball at "
        "50 m/s relative to the strings (row 3: 30 m/s onto the racquet swung at " +
            io::significant(rows[2].evaluation.racquet_speed_m_s, 4) +
            " m/s there); hand centre 7 cm (row 5: 8 cm) from the butt, wrist at "
            "the butt.");
  // Rows that are not the paper's are not said to agree with it to its rounding.
  const std::string md = reports::table1_report(rows, io::Format::kMarkdown);
  CHECK(md.find("within the paper's rounding") == std::string::npos);
  CHECK(md.find("more than the paper's rounding to whole newtons") != std::string::npos);
}

TEST_CASE("Table I's e and T are those each row was computed with") {
  // A row strung at a tension derives its duration (Eq. 17's M_eff and the
  // bed's stiffness): T is that duration, as evaluate() gives it, not the
  // file's absent one.
  std::vector<studies::Table1Row> rows =
      studies::compute_table1(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/table1");
  Design& strung = rows[2].design.design;
  strung.strings = StringBed{};
  rows[2].evaluation = evaluate(strung);
  const std::string csv = reports::table1_report(rows, io::Format::kCsv);
  const std::size_t line = csv.find("\n3,");
  REQUIRE(line != std::string::npos);
  const std::string row3 = csv.substr(line + 1, csv.find('\n', line + 1) - line - 1);
  INFO(row3);
  CHECK(row3.find("," + io::exact(rows[2].evaluation.impact_duration_s) + ",") !=
        std::string::npos);
  CHECK(rows[2].evaluation.impact_duration_s != strung.impact_duration_s);
}

}  // namespace
}  // namespace sweetspot::reports
