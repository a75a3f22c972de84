// The optimisation report says what the optimizer found, in words first.
#include "reports/optimization_report.hpp"

#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "io/design_reader.hpp"
#include "io/outputs.hpp"
#include "studies/optimization.hpp"
#include "studies/study.hpp"

namespace sweetspot::reports {
namespace {

std::string studies() { return std::string(SWEETSPOT_SOURCE_DIR) + "/designs/studies/"; }

TEST_CASE("The report of an infeasible study leads with it and names each violated constraint") {
  studies::Study study = studies::load_study(studies() + "4-robust-lowest-worst-wrist-force.json");
  study.constraints[0].max = 100.0;  // no racquet in the box swings that lightly
  const studies::OptimizationResult r = run_optimization(study);
  REQUIRE(r.outcome == studies::Outcome::kInfeasible);
  REQUIRE(r.constraints[0].value.has_value());
  const std::string md = reports::optimization_report(study, r, io::Format::kMarkdown, false);
  CHECK(md.find("**Answer.** No design meets the constraints; the least violating one is "
                "`/implement/mass_kg` = ") != std::string::npos);
  // The constraint, its value, how far outside its limit and the tolerance it was judged by.
  CHECK(md.find(fmt::format(
            "`swingweight_kg_cm2 <= 100` is {} kg cm^2, outside its limit by {} (tolerance 0.0001)",
            io::significant(*r.constraints[0].value, 4),
            io::significant(*r.constraints[0].value - 100, 4))) != std::string::npos);
  CHECK(md.find("the lowest") == std::string::npos);
  const nlohmann::json j =
      nlohmann::json::parse(reports::optimization_report(study, r, io::Format::kJson, false));
  CHECK(j["outcome"] == "infeasible");
  CHECK(j["feasible"] == false);
  CHECK(j["constraints"][0]["tolerance"].get<double>() == Approx(1e-4).epsilon(1e-12));
  CHECK(j["constraints"][0]["violation"] == *r.constraints[0].value - 100);
}

TEST_CASE("The convergence plot shows the constraint violation beside the objective") {
  studies::Study study = studies::load_study(studies() + "4-robust-lowest-worst-wrist-force.json");
  study.constraints[0].max = 100.0;
  const studies::OptimizationResult r = run_optimization(study);
  const io::Plot plot = reports::convergence_plot(study, r);
  REQUIRE(plot.series.size() == 2);
  CHECK_FALSE(plot.series[0].right_axis);
  CHECK(plot.series[1].right_axis);
  CHECK(plot.log_y2);
  CHECK_FALSE(plot.y2_label.empty());
  // Infeasible throughout: every point of the violation is drawn, the last the least.
  REQUIRE(plot.series[1].y.size() == r.summary.history.size());
  for (const auto& y : plot.series[1].y) CHECK(y.has_value());
  CHECK(*plot.series[1].y.back() ==
        Approx(r.constraints[0].violation / r.constraints[0].tolerance).epsilon(1e-9));
  CHECK(io::gnuplot_script(plot, "c.png").find("axes x1y2") != std::string::npos);
  // Without constraints, the objective alone.
  study.constraints.clear();
  CHECK(reports::convergence_plot(study, studies::run_optimization(study)).series.size() == 1);
}

TEST_CASE("A report never shows the optimizer's penalty as a value") {
  const studies::Study study = studies::read_study(nlohmann::json::parse(R"({
      "design": {"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.25}]}, "impact": {"from_butt_m": 0.35},
                 "ball": {"speed_m_s": 50}},
      "variables": [{"path": "/ball/speed_m_s", "min": 40, "max": 60}],
      "objective": {"output": "rotation_axis_free_from_butt_m"}})"),
                                                   "study.json", studies());
  const studies::OptimizationResult r = run_optimization(study);
  REQUIRE(r.outcome == studies::Outcome::kNoValue);
  const std::string md = reports::optimization_report(study, r, io::Format::kMarkdown, false);
  CHECK(md.find("**Answer.** No valid design was found") != std::string::npos);
  CHECK(md.find("e+12") == std::string::npos);
  CHECK(md.find("1000000000000") == std::string::npos);
  const nlohmann::json j =
      nlohmann::json::parse(reports::optimization_report(study, r, io::Format::kJson, false));
  CHECK(j["outcome"] == "no_value");
  CHECK(j["objective_value"].is_null());
  CHECK(j["start_objective_value"].is_null());
}

TEST_CASE("A target's convergence is plotted as the distance from it, unsquared, in cm") {
  // Study 3a minimises (cop_node_gap_m - 0)^2; a reader wants the gap itself.
  const studies::Study study =
      studies::load_study(studies() + "3a-cop-on-node-table1-racquet.json");
  const studies::OptimizationResult r = run_optimization(study);
  const io::Plot plot = reports::convergence_plot(study, r);
  REQUIRE(!plot.series.empty());
  REQUIRE(plot.series[0].y.back());
  // The best design's gap, evaluated afresh: the plot's last point, in cm.
  const auto gap =
      io::find_output("cop_node_gap_m")->value(evaluate_design_file(r.best, "modal", 1e-6));
  REQUIRE(gap);
  CHECK(*plot.series[0].y.back() == Approx(std::abs(*gap) * 100.0).epsilon(1e-6));
  CHECK(plot.y_label == "COP–node gap (cm): distance from its target 0 cm");
}

}  // namespace
}  // namespace sweetspot::reports
