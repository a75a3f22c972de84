// The optimisation report says what the optimizer found, in words first.
#include "reports/optimization_report.hpp"

#include <string>

#include <catch2/catch.hpp>

#include "studies/optimization.hpp"
#include "studies/study.hpp"

namespace sweetspot::io {
namespace {

std::string studies() { return std::string(SWEETSPOT_SOURCE_DIR) + "/designs/studies/"; }

TEST_CASE("The report of an infeasible study says that no design is feasible") {
  Study study = load_study(studies() + "4-robust-lowest-worst-wrist-force.json");
  study.constraints[0].max = 100.0;  // no racquet in the box swings that lightly
  const OptimizationResult r = run_optimization(study);
  REQUIRE_FALSE(r.summary.feasible);
  CHECK(optimization_report(study, r, Format::kMarkdown, false).find("No feasible design") != std::string::npos);
}

}  // namespace
}  // namespace sweetspot::io
