// Table I and Fig. 11 of Cross (2004) from the shipped designs, against the
// numbers the paper prints.
#include "studies/paper.hpp"

#include <catch2/catch.hpp>
#include <string>

namespace sweetspot::studies {
namespace {

// The paper prints these positions to 1 mm.
constexpr double kHalfMillimetre = 0.5e-3;

io::DesignFile beam() {
  return io::load_design(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/paper-beam.json");
}

TEST_CASE("Fig. 11: free and hand-held axes coincide at d = 22.8 cm, 3.2 cm from the handle end") {
  const auto crossing = figure11_crossing(beam());
  REQUIRE(crossing);
  CHECK(crossing->d_m == Approx(0.228).margin(kHalfMillimetre));
  CHECK(crossing->s_m == Approx(0.032).margin(kHalfMillimetre));
}

TEST_CASE("The shipped Table I designs carry the printed values and reproduce them") {
  const auto rows = compute_table1(std::string(SWEETSPOT_SOURCE_DIR) + "/designs/table1");
  REQUIRE(rows.size() == kTableIRows);
  for (const Table1Row& row : rows) {
    INFO("row " << row.row);
    REQUIRE(row.paper_F0_N);
    REQUIRE(row.paper_Fw_N);
    CHECK(row.evaluation.peak_impact_force_N == Approx(*row.paper_F0_N).margin(1.0));
    CHECK(row.evaluation.peak_wrist_force_N == Approx(*row.paper_Fw_N).margin(1.0));
  }
}

}  // namespace
}  // namespace sweetspot::studies
