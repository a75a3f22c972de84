// Figs. 5 and 11 of Cross (2004) from the shipped beam design, against the
// numbers the paper prints in Sections III and V.B.
#include "reports/paper_reports.hpp"

#include <catch2/catch.hpp>

#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::reports {
namespace {

// The paper prints these positions to 1 mm.
constexpr double kHalfMillimetre = 0.5e-3;

io::DesignFile beam() {
  return io::load_design(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/paper-beam.json");
}

TEST_CASE("Fig. 11: free and hand-held axes coincide at d = 22.8 cm, 3.2 cm from the handle end") {
  const auto crossing = reports::figure11_crossing(beam());
  REQUIRE(crossing);
  CHECK(crossing->d_m == Approx(0.228).margin(kHalfMillimetre));
  CHECK(crossing->s_m == Approx(0.032).margin(kHalfMillimetre));
}

TEST_CASE("Fig. 5: v2/v16 is 1 for an impact in the middle of the beam") {
  const reports::Figure figure = reports::figure5(beam());
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

TEST_CASE("The shipped Table I designs carry the printed values and reproduce them") {
  const auto rows = reports::compute_table1(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/table1");
  REQUIRE(rows.size() == reports::kTableIRows);
  for (const Table1Row& row : rows) {
    INFO("row " << row.row);
    REQUIRE(row.paper_F0_N);
    REQUIRE(row.paper_Fw_N);
    CHECK(row.evaluation.peak_impact_force_N == Approx(*row.paper_F0_N).margin(1.0));
    CHECK(row.evaluation.peak_wrist_force_N == Approx(*row.paper_Fw_N).margin(1.0));
  }
}

TEST_CASE("The figures quote the paper's numbers beside the paper's beam only") {
  const io::DesignFile paper = beam();
  CHECK(reports::figure5(paper).summary.find("(paper: COP 23.3 cm from the end)") !=
        std::string::npos);
  CHECK(reports::figure11(paper).summary.find("(paper: 22.8 cm and 3.2 cm)") != std::string::npos);
  io::DesignFile other = paper;  // another beam in its place: nothing to compare with
  other.reference = io::Json();
  for (const std::string& summary :
       {reports::figure5(other).summary, reports::figure11(other).summary}) {
    CHECK(summary.find("paper") == std::string::npos);
    CHECK(summary.find("nan") == std::string::npos);
  }
}

}  // namespace
}  // namespace sweetspot::reports
