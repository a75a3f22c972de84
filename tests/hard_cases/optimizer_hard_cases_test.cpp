// Hard cases of the optimizer at the study level: a flat objective, a study
// whose constraints cannot hold together, and a start on a bound. Each study
// is written inline on the Table I top-row design and checked against an
// answer known without the optimizer (exact values, or a brute-force grid
// evaluated here with evaluate()). The problem-level equivalents are in
// tests/optimize_test.cpp; these go through read_study, make_problem and
// run_optimization as `sweetspot optimize` does.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "reports/optimization_report.hpp"
#include "studies/optimization.hpp"
#include "studies/study.hpp"
#include "studies/sweep.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {
namespace {

// The folder the inline studies' "design" paths are relative to.
std::string designs() { return std::string(SWEETSPOT_SOURCE_DIR) + "/designs"; }

studies::Study inline_study(const char* text) {
  return studies::read_study(nlohmann::json::parse(text), "hard-case study", designs());
}

// Every number the optimizer reports is finite and the point lies in the box.
void check_finite_and_inside(const studies::Study& study, const studies::OptimizationResult& r) {
  CHECK(std::isfinite(r.summary.objective));
  REQUIRE(r.start_objective.has_value());
  CHECK(std::isfinite(*r.start_objective));
  REQUIRE(r.summary.x.size() == study.variables.size());
  for (std::size_t i = 0; i < study.variables.size(); ++i) {
    INFO(study.variables[i].pointer);
    CHECK(std::isfinite(r.summary.x[i]));
    CHECK(r.summary.x[i] >= study.variables[i].min);
    CHECK(r.summary.x[i] <= study.variables[i].max);
  }
  for (const double c : r.summary.constraints) CHECK(std::isfinite(c));
  for (const double h : r.summary.history) CHECK(std::isfinite(h));
  CHECK(r.summary.evaluations > 0);
  CHECK(r.summary.evaluations <= study.options.max_evaluations);
  CHECK_FALSE(optimizer::is_failure(r.summary.termination));
}

// x_i = lo + (hi - lo) i / (points - 1), both ends included exactly.
std::vector<double> grid(double lo, double hi, int points) {
  std::vector<double> x(points);
  for (int i = 0; i < points; ++i) x[i] = i + 1 == points ? hi : lo + (hi - lo) * i / (points - 1);
  return x;
}

// ------------------------------------------------------------ flat objective

// A flat objective: minimising the mass while a variable that cannot change
// it varies. Every point of the box is optimal, so the objective is the
// design's mass bit for bit, at the start, in the history and at the end,
// and the run ends on a tolerance, not on the evaluation budget.
void check_flat(const char* study_text, double start) {
  const studies::Study study = inline_study(study_text);
  const double mass =
      evaluate(studies::design_at(study, std::vector<double>{start}).design).mass_kg;
  const studies::OptimizationResult r = run_optimization(study);
  check_finite_and_inside(study, r);
  CHECK(r.summary.objective == mass);
  CHECK(r.start_objective == std::optional(mass));
  CHECK(r.summary.feasible);
  for (const double h : r.summary.history) CHECK(h == mass);
  CHECK(r.summary.evaluations < study.options.max_evaluations);
  CHECK(evaluate(r.best.design).mass_kg == mass);
}

TEST_CASE(
    "A flat objective stops on a point of the same value, from inside the box or on a bound") {
  // Where the ball hits does not change the mass.
  check_flat(R"({
    "design": "table1/row1.json",
    "variables": [{"path": "/impact/from_tip_m", "min": 0.01, "max": 0.30, "start": 0.05}],
    "objective": {"output": "mass_kg", "goal": "minimize"}})",
             0.05);
  // Nor does the ball's speed; the start sits on the upper bound.
  check_flat(R"({
    "design": "table1/row1.json",
    "variables": [{"path": "/ball/speed_m_s", "min": 10, "max": 70, "start": 70}],
    "objective": {"output": "mass_kg", "goal": "minimize"}})",
             70.0);
}

// ------------------------------------------------------------ infeasible study

TEST_CASE(
    "Constraints that cannot hold together give an infeasible result with the least violation") {
  // mass_kg >= 0.35 and mass_kg <= 0.30 cannot both hold; each alone can
  // within [0.25, 0.40]. Both tolerances are 1e-6 kg (the default 1e-6 x
  // max(1, |limit|)), so the scaled violation is max(0.35 - m, m - 0.30) / 1e-6,
  // least at m = 0.325 with 0.025 kg on each side: exact, and what a grid
  // over m containing 0.325 finds.
  const studies::Study study = inline_study(R"({
    "design": "table1/row1.json",
    "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.40, "start": 0.38}],
    "objective": {"output": "peak_wrist_force_N", "goal": "minimize"},
    "constraints": [{"output": "mass_kg", "min": 0.35}, {"output": "mass_kg", "max": 0.30}]})");
  const studies::OptimizationResult r = run_optimization(study);
  check_finite_and_inside(study, r);
  CHECK_FALSE(r.summary.feasible);
  REQUIRE(r.constraints.size() == 2);
  const double m = r.summary.x[0];
  const double worst = std::max(0.35 - m, m - 0.30);
  // Brute force: the least worst violation on a grid over the box.
  double grid_worst = std::numeric_limits<double>::infinity();
  for (const double x : grid(0.25, 0.40, 121)) {  // step 1.25 g: 0.325 is a grid point
    const double mass = evaluate(studies::design_at(study, std::vector<double>{x}).design).mass_kg;
    grid_worst = std::min(grid_worst, std::max(0.35 - mass, mass - 0.30));
  }
  CHECK(grid_worst == Approx(0.025).epsilon(1e-12));
  INFO("best mass " << m << " kg, worst violation " << worst << " kg; "
                    << r.summary.brief_report());
  // The optimizer never does worse than the grid, beyond its step tolerance
  // (x_tolerance_rel 1e-7 of the 0.15 kg range).
  CHECK(worst <= grid_worst + 1e-7 * 0.15);
  CHECK(m == Approx(0.325).margin(1e-7 * 0.15));
  // Both limits are broken there, by the same amount, and the report says so.
  CHECK_FALSE(r.constraints[0].satisfied);
  CHECK_FALSE(r.constraints[1].satisfied);
  CHECK(r.outcome == studies::Outcome::kInfeasible);
  CHECK(r.constraints[0].tolerance == 1e-6);
  CHECK(r.constraints[0].violation == Approx(0.025).margin(1e-7 * 0.15));
  CHECK(r.constraints[1].violation == Approx(0.025).margin(1e-7 * 0.15));
  CHECK(reports::optimization_report(study, r, io::Format::kMarkdown, false)
            .find("No design meets the constraints; the least violating one is") !=
        std::string::npos);
}

TEST_CASE(
    "Two conflicting constraints on different outputs: the least violation beats a 61 x 61 grid") {
  // A light frame (mass_kg <= 0.26) cannot swing heavily (swingweight_kg_cm2
  // >= 380) within Table I's box. Violations are scaled by their tolerances
  // (1e-6 kg and 3.8e-4 kg cm^2: 1e-6 x max(1, |limit|)), and the reported
  // design must violate no more, in that measure, than the best point of a
  // 61 x 61 grid over the box (brute force with evaluate()), up to the
  // change of the violation over the optimizer's step tolerance.
  const studies::Study study = inline_study(R"({
    "design": "table1/row1.json",
    "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.40},
                  {"path": "/implement/head_to_handle_mass_ratio", "min": 0.8, "max": 1.2}],
    "objective": {"output": "peak_wrist_force_N", "goal": "minimize"},
    "constraints": [{"output": "mass_kg", "max": 0.26}, {"output": "swingweight_kg_cm2", "min": 380}]})");
  const auto violation = [](const Evaluation& e) {
    const double swingweight_kg_cm2 = e.swingweight_kg_m2 * 1e4;
    return std::max(std::max(0.0, e.mass_kg - 0.26) / 1e-6,
                    std::max(0.0, 380.0 - swingweight_kg_cm2) / 3.8e-4);
  };
  const studies::OptimizationResult r = run_optimization(study);
  check_finite_and_inside(study, r);
  CHECK_FALSE(r.summary.feasible);
  double grid_least = std::numeric_limits<double>::infinity();
  for (const double m : grid(0.25, 0.40, 61)) {
    for (const double q : grid(0.8, 1.2, 61)) {
      grid_least = std::min(
          grid_least,
          violation(evaluate(studies::design_at(study, std::vector<double>{m, q}).design)));
    }
  }
  const double found = violation(evaluate(r.best.design));
  INFO("least scaled violation: optimizer " << found << ", grid " << grid_least << "; "
                                            << r.summary.brief_report());
  // A step of 1e-7 of the mass range (1.5e-8 kg) moves the mass term by 0.015.
  CHECK(found <= grid_least + 0.015);
  CHECK_FALSE(r.constraints[0].satisfied);
  CHECK_FALSE(r.constraints[1].satisfied);
}

// ------------------------------------------------------------ start on a bound

// The optimum of peak_wrist_force_N over the implement's mass alone, on a
// fine grid evaluated here.
struct GridOptimum {
  double x = 0.0;
  double value = std::numeric_limits<double>::infinity();
};
GridOptimum wrist_force_grid(const studies::Study& study, double lo, double hi, int points) {
  GridOptimum best;
  for (const double x : grid(lo, hi, points)) {
    const double value =
        evaluate(studies::design_at(study, std::vector<double>{x}).design).peak_wrist_force_N;
    if (value < best.value) best = {x, value};
  }
  return best;
}

TEST_CASE("A start on the bound where the optimum lies is accepted and kept") {
  // Brute force: peak_wrist_force_N over M in [0.25, 0.40] kg on a 301-point
  // grid (0.5 g steps), both bounds included; the optimum is on a bound, which
  // the optimizer must keep to its step tolerance (1e-7 of the range).
  const char* kStudy = R"({
    "design": "table1/row1.json",
    "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.40, "start": %START%}],
    "objective": {"output": "peak_wrist_force_N", "goal": "minimize"}})";
  const auto with_start = [&](double start) {
    std::string text = kStudy;
    text.replace(text.find("%START%"), 7, std::to_string(start));
    return inline_study(text.c_str());
  };
  const studies::Study probe = with_start(0.25);
  const GridOptimum best = wrist_force_grid(probe, 0.25, 0.40, 301);
  REQUIRE((best.x == 0.25 || best.x == 0.40));
  const double other = best.x == 0.25 ? 0.40 : 0.25;
  for (const double start : {best.x, other}) {
    INFO("start " << start << " kg, grid optimum " << best.value << " N at " << best.x << " kg");
    const studies::Study study = with_start(start);
    REQUIRE(study.variables[0].start == start);
    const studies::OptimizationResult r = run_optimization(study);
    check_finite_and_inside(study, r);
    CHECK(r.start_x[0] == start);
    CHECK(r.summary.x[0] == Approx(best.x).margin(1e-7 * 0.15));
    // The grid contains the optimum exactly, so the optimizer matches it to
    // the objective's change over that step tolerance.
    CHECK(r.summary.objective == Approx(best.value).epsilon(1e-6));
    CHECK(r.summary.objective <= best.value * (1 + 1e-6));
  }
}

TEST_CASE("Starts on either bound of a variable with an interior optimum both find it") {
  // A target inside the reachable range: (F0 - target)^2 over M, the target
  // halfway between the peak impact forces at the two bounds, so the optimum
  // (F0 = target) is interior. Brute force on a 1501-point grid (0.1 g steps)
  // comes within one step of it; the optimizer, continuous, must not do worse.
  const char* kStudy = R"({
    "design": "table1/row1.json",
    "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.40, "start": %START%}],
    "objective": {"output": "peak_impact_force_N", "goal": "target", "target": %TARGET%}})";
  const auto make = [&](double start, double target) {
    std::string text = kStudy;
    text.replace(text.find("%START%"), 7, std::to_string(start));
    text.replace(text.find("%TARGET%"), 8, std::to_string(target));
    return inline_study(text.c_str());
  };
  // A target between the forces at the two bounds, so the optimum is interior.
  const studies::Study probe = make(0.25, 0.0);
  const double f_lo =
      evaluate(studies::design_at(probe, std::vector<double>{0.25}).design).peak_impact_force_N;
  const double f_hi =
      evaluate(design_at(probe, std::vector<double>{0.40}).design).peak_impact_force_N;
  const double target = std::round(0.5 * (f_lo + f_hi));  // whole newtons: written exactly
  for (const double start : {0.25, 0.40}) {
    INFO("start " << start << " kg, target " << target << " N");
    const studies::Study study = make(start, target);
    const studies::OptimizationResult r = run_optimization(study);
    check_finite_and_inside(study, r);
    double grid_best = std::numeric_limits<double>::infinity();
    for (const double x : grid(0.25, 0.40, 1501)) {
      const double f =
          evaluate(design_at(study, std::vector<double>{x}).design).peak_impact_force_N;
      grid_best = std::min(grid_best, (f - target) * (f - target));
    }
    INFO("optimizer " << r.summary.objective << " N^2 at " << r.summary.x[0] << " kg, grid "
                      << grid_best << " N^2");
    CHECK(r.summary.objective <= grid_best + 1e-12);
    CHECK(r.summary.x[0] > 0.25);
    CHECK(r.summary.x[0] < 0.40);
  }
}

}  // namespace
}  // namespace sweetspot::io
