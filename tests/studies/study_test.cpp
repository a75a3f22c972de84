// Evidence that the optimum is right: every shipped study against brute force
// on a grid of the same model, gradients against central differences, KKT
// conditions at the optimum, and agreement from several starts.
#include "studies/study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/input_error.hpp"
#include "studies/optimization.hpp"
#include "studies/sweep.hpp"
#include "sweetspot/roots.hpp"

namespace sweetspot::studies {
namespace {

std::string studies() { return std::string(SWEETSPOT_SOURCE_DIR) + "/designs/studies/"; }

double objective_at(const studies::Study& study, std::vector<double> x) {
  return studies::objective_of(study, studies::design_at(study, x));
}

// The optimizer may beat a grid (it is continuous) but never lose to it by
// more than its own convergence tolerance, relative to the objective.
constexpr double kBeatsGridTolerance = 1e-6;

// Brute force: the best objective over a full grid of `points` per variable,
// keeping only points that satisfy `feasible`.
template <class Feasible>
double grid_minimum(const studies::Study& study, int points, Feasible&& feasible) {
  const std::size_t n = study.variables.size();
  std::vector<int> index(n, 0);
  double best = std::numeric_limits<double>::infinity();
  while (true) {
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) {
      const studies::StudyVariable& v = study.variables[i];
      x[i] = v.min + (v.max - v.min) * index[i] / (points - 1);
    }
    const io::DesignFile d = design_at(study, x);
    if (feasible(d)) best = std::min(best, objective_of(study, d));
    std::size_t i = 0;
    while (i < n && ++index[i] == points) index[i++] = 0;
    if (i == n) break;
  }
  return best;
}

TEST_CASE("Study 1: the optimizer agrees with a 5^6 grid and the paper's bottom row of Table I") {
  const studies::Study study =
      studies::load_study(studies() + "1-lowest-wrist-force-table1-ranges.json");
  const studies::OptimizationResult r = run_optimization(study);
  const double grid = grid_minimum(study, 5, [](const io::DesignFile&) { return true; });
  CHECK(r.summary.objective <= grid * (1 + kBeatsGridTolerance));
  // The optimum is a corner of the box, which the grid contains.
  CHECK(r.summary.objective == Approx(grid).epsilon(kBeatsGridTolerance));
  // Table I, bottom row: 250 N, printed to the newton.
  CHECK(r.summary.objective == Approx(250.0).margin(1.0));
}

TEST_CASE("Study 1: every variable sits on the bound its derivative points to (KKT)") {
  const studies::Study study =
      studies::load_study(studies() + "1-lowest-wrist-force-table1-ranges.json");
  const studies::OptimizationResult r = run_optimization(study);
  const optimizer::Problem problem = make_problem(study);
  std::vector<double> grad(r.summary.x.size());
  optimizer::difference_gradient(
      [&](std::span<const double> x) {
        return objective_at(study, {x.begin(), x.end()});
      },
      r.summary.x, problem.lower, problem.upper, 1e-6, grad);
  for (std::size_t i = 0; i < grad.size(); ++i) {
    INFO(study.variables[i].pointer << ": gradient " << grad[i]);
    const studies::StudyVariable& v = study.variables[i];
    const double slack = 1e-6 * (v.max - v.min);
    if (r.summary.x[i] <= v.min + slack)
      CHECK(grad[i] >= 0.0);  // at the lower bound: f rises inward
    else if (r.summary.x[i] >= v.max - slack)
      CHECK(grad[i] <= 0.0);  // at the upper bound: f falls outward
    else
      CHECK(std::abs(grad[i]) <= 1e-3 * std::abs(r.summary.objective));
  }
}

TEST_CASE("Study 1: an inactive constraint changes nothing") {
  studies::Study study = studies::load_study(studies() + "1-lowest-wrist-force-table1-ranges.json");
  const studies::OptimizationResult free = run_optimization(study);
  study.constraints.push_back(studies::StudyConstraint{io::find_output("swingweight_kg_cm2"),
                                                       std::nullopt, 1000.0, std::nullopt, 1e-6});
  const studies::OptimizationResult constrained = run_optimization(study);
  CHECK(constrained.summary.objective ==
        Approx(free.summary.objective).epsilon(kBeatsGridTolerance));
  REQUIRE(constrained.constraints.size() == 1);
  CHECK_FALSE(constrained.constraints[0].active);
}

TEST_CASE("Study 2: fixed mass and swingweight, against a grid that solves the two equalities") {
  const studies::Study study =
      studies::load_study(studies() + "2-lowest-wrist-force-fixed-feel.json");
  const studies::OptimizationResult r = run_optimization(study);
  REQUIRE(r.summary.feasible);
  CHECK(r.constraints[0].value == Approx(0.305).epsilon(1e-6));
  CHECK(r.constraints[1].value == Approx(320.0).epsilon(1e-6));
  // Brute force over (ratio, tape position); the total mass fixes the frame
  // mass from the tape mass, and the swingweight then fixes the tape mass.
  const studies::StudyVariable& ratio = study.variables[1];
  const studies::StudyVariable& position = study.variables[2];
  constexpr int kPoints = 41;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kPoints; ++i) {
    for (int j = 0; j < kPoints; ++j) {
      const double q = ratio.min + (ratio.max - ratio.min) * i / (kPoints - 1);
      const double p = position.min + (position.max - position.min) * j / (kPoints - 1);
      const auto x_for = [&](double tape) { return std::vector<double>{0.305 - tape, q, p, tape}; };
      const auto swingweight_gap = [&](double tape) {
        return *io::find_output("swingweight_kg_cm2")
                    ->value(studies::evaluate_in(study, studies::design_at(study, x_for(tape)))) -
               320.0;
      };
      const auto tape =
          find_root(swingweight_gap, study.variables[3].min, study.variables[3].max, 1e-12);
      if (!tape || 0.305 - *tape < study.variables[0].min || 0.305 - *tape > study.variables[0].max)
        continue;
      best = std::min(best, objective_at(study, x_for(*tape)));
    }
  }
  REQUIRE(std::isfinite(best));
  CHECK(r.summary.objective <= best * (1 + kBeatsGridTolerance));
  // A 41 x 41 grid lands within 0.5 % of a smooth optimum.
  CHECK(r.summary.objective == Approx(best).epsilon(5e-3));
}

TEST_CASE("Study 2: the same optimum from several seeds") {
  studies::Study study = studies::load_study(studies() + "2-lowest-wrist-force-fixed-feel.json");
  const double reference = studies::run_optimization(study).summary.objective;
  for (const unsigned long seed : {2ul, 17ul, 123ul}) {
    study.options.seed = seed;
    CHECK(run_optimization(study).summary.objective == Approx(reference).epsilon(1e-6));
  }
}

TEST_CASE(
    "Studies 3: the COP cannot be put on the node, and the optimizer finds the closest corner") {
  for (const char* name :
       {"3a-cop-on-node-table1-racquet.json", "3b-cop-on-node-paper-beam.json"}) {
    INFO(name);
    const studies::Study study = studies::load_study(studies() + name);
    CHECK(study.fidelity == Fidelity::kModal);
    const studies::OptimizationResult r = run_optimization(study);
    const double grid = grid_minimum(study, 5, [](const io::DesignFile&) { return true; });
    CHECK(r.summary.objective <= grid * (1 + kBeatsGridTolerance));
    CHECK(r.summary.objective == Approx(grid).epsilon(1e-4));
  }
}

TEST_CASE("Study 4: the robust optimum against a grid, and its swingweight limit is active") {
  studies::Study study = studies::load_study(studies() + "4-robust-lowest-worst-wrist-force.json");
  const studies::OptimizationResult r = run_optimization(study);
  REQUIRE(r.summary.feasible);
  const double grid = grid_minimum(study, 61, [&](const io::DesignFile& d) {
    return *io::find_output("swingweight_kg_cm2")->value(evaluate(d.design)) <= 330.0;
  });
  CHECK(r.summary.objective <= grid * (1 + kBeatsGridTolerance));
  // On a 61 x 61 grid the constraint boundary is resolved to about 1/60 of a range.
  CHECK(r.summary.objective == Approx(grid).epsilon(2e-3));
  REQUIRE(r.constraints.size() == 1);
  CHECK(r.constraints[0].active);
  // Active means binding: without it the worst-case force falls further.
  study.constraints.clear();
  CHECK(studies::run_optimization(study).summary.objective < r.summary.objective * (1 - 1e-3));
}

TEST_CASE("The worst case over impacts is the largest of the per-impact values") {
  const studies::Study study =
      studies::load_study(studies() + "4-robust-lowest-worst-wrist-force.json");
  const io::DesignFile d = studies::design_at(study, std::vector<double>{0.3, 1.0});
  double worst = 0.0;
  for (int k = 0; k < 13; ++k) {
    Design at = d.design;
    at.impact_from_butt_m = at.implement.length_m() - (0.10 + 0.12 * k / 12);
    worst = std::max(worst, evaluate(at).peak_wrist_force_N);
  }
  CHECK(studies::objective_of(study, d) == worst);
}

TEST_CASE("Study gradients agree with a wide-step Richardson central difference") {
  const studies::Study study =
      studies::load_study(studies() + "2-lowest-wrist-force-fixed-feel.json");
  const optimizer::Problem problem = make_problem(study);
  std::vector<double> x{0.29, 1.05, 0.6, 0.01};
  std::vector<double> grad(4);
  const auto f = [&](std::span<const double> y) {
    return objective_at(study, {y.begin(), y.end()});
  };
  optimizer::difference_gradient(f, x, problem.lower, problem.upper, 1e-6, grad);
  for (std::size_t i = 0; i < 4; ++i) {
    const double h = 1e-3 * (problem.upper[i] - problem.lower[i]);
    const auto central = [&](double step) {
      std::vector<double> a = x, b = x;
      a[i] += step;
      b[i] -= step;
      return (f(a) - f(b)) / (2 * step);
    };
    // Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term.
    const double richardson = (4 * central(h / 2) - central(h)) / 3;
    CHECK(grad[i] == Approx(richardson).epsilon(1e-5));
  }
}

TEST_CASE("Bad studies are refused with the study's JSON path") {
  const auto error_of = [](const char* text) {
    try {
      studies::read_study(nlohmann::json::parse(text), "study.json", studies());
    } catch (const io::InputError& e) {
      return e.pointer() + ": " + e.detail();
    }
    return std::string("(no error)");
  };
  CHECK_THAT(error_of(R"({"design": "../table1/row1.json", "variables": [{"path": "/implement/nope",
              "min": 0, "max": 1}]})"),
             Catch::StartsWith("/variables/0/path") && Catch::Contains("not in the design"));
  CHECK_THAT(error_of(R"({"design": "../table1/row1.json", "variables": [{"path": "/name",
              "min": 0, "max": 1}]})"),
             Catch::StartsWith("/variables/0/path") && Catch::Contains("expected a number"));
  CHECK_THAT(error_of(R"({"design": "../table1/row1.json", "variables": [{"path": "/frame/cor",
              "min": 0.9, "max": 0.6}]})"),
             Catch::StartsWith("/variables/0/min") && Catch::Contains("must be < max"));
  CHECK_THAT(error_of(R"({"design": "../table1/row1.json", "variables": [{"path": "/frame/cor",
              "min": 0.6, "max": 0.8}], "objective": {"output": "happiness"}})"),
             Catch::StartsWith("/objective/output") && Catch::Contains("unknown output"));
  CHECK_THAT(error_of(R"({"design": "../table1/row1.json", "variables": [{"path": "/frame/cor",
              "min": 0.6, "max": 0.8}], "algorithm": "LD_MAGIC"})"),
             Catch::StartsWith("/algorithm"));
  CHECK_THAT(error_of(R"({"design": "nowhere.json", "variables": []})"),
             Catch::StartsWith("/design"));
  CHECK_THAT(error_of(R"({"design": "../table1/row1.json", "variables": [{"path": "/frame/cor",
              "min": 0.6, "max": 0.8}], "constraints": [{"output": "mass_kg"}]})"),
             Catch::StartsWith("/constraints/0"));
}

TEST_CASE("optimize refuses a bound the design cannot take alone, which a sweep walks") {
  const auto study_of = [](const char* variable) {
    return studies::read_study(
        nlohmann::json::parse(std::string(R"({"design": "../table1/row1.json", "variables": [)") +
                              variable +
                              R"(], "objective": {"output": "peak_wrist_force_N"},
                              "outputs": ["peak_wrist_force_N"]})"),
        "study.json", studies());
  };
  const auto refusal = [](const studies::Study& study) {
    try {
      run_optimization(study);
    } catch (const io::InputError& e) {
      return e.pointer() + ": " + e.detail();
    }
    return std::string("(no error)");
  };
  // The design's own range of each input (a mass > 0 kg, a COR in [0, 1]).
  CHECK(refusal(study_of(R"({"path": "/implement/mass_kg", "min": -1, "max": 0.4})")) ==
        "/variables/0: min -1 is no value of /implement/mass_kg (the design's other inputs as "
        "given): must be > 0 kg, got -1 kg");
  CHECK_THAT(refusal(study_of(R"({"path": "/frame/cor", "min": 0.6, "max": 1.2})")),
             Catch::StartsWith("/variables/0: max 1.2 is no value of /frame/cor") &&
                 Catch::EndsWith("must be in [0, 1], got 1.2"));
  // A sweep of the same range says where each point is refused.
  const studies::Study sweep = study_of(R"({"path": "/frame/cor", "min": 0.6, "max": 1.2,
      "points": 4})");
  std::ostringstream rows;
  CHECK_NOTHROW(studies::run_sweep(sweep, rows, [](std::size_t, std::size_t) {}));
  CHECK(rows.str().find("must be in [0, 1]") != std::string::npos);
}

TEST_CASE("An infeasible study says so and returns the least violating design") {
  studies::Study study = studies::load_study(studies() + "4-robust-lowest-worst-wrist-force.json");
  study.constraints[0].max = 100.0;  // no racquet in the box swings that lightly
  const studies::OptimizationResult r = run_optimization(study);
  CHECK_FALSE(r.summary.feasible);
  CHECK(r.outcome == studies::Outcome::kInfeasible);
  REQUIRE(r.constraints.size() == 1);
  const studies::ConstraintReport& c = r.constraints[0];
  CHECK_FALSE(c.satisfied);
  REQUIRE(c.value.has_value());
  CHECK(c.limit == 100.0);
  CHECK(c.tolerance == studies::kDefaultConstraintTolerance * 100.0);
  CHECK(c.violation == *c.value - 100.0);
  // The least violating design swings as lightly as the box allows: the
  // lightest frame with its mass towards the handle, a corner of the box.
  CHECK(*c.value ==
        Approx(*io::find_output("swingweight_kg_cm2")
                    ->value(studies::evaluate_in(
                        study, studies::design_at(study, std::vector<double>{0.25, 0.8}))))
            .epsilon(1e-9));
}

// A study whose one variable cannot change the swingweight (the ball's
// speed), so the swingweight is the design's own and the judgement of a
// constraint on it is exact arithmetic.
studies::Study study_with_swingweight_limit(const std::string& constraint) {
  return studies::read_study(nlohmann::json::parse(R"({"design": "../table1/row1.json",
      "variables": [{"path": "/ball/speed_m_s", "min": 40, "max": 60}],
      "objective": {"output": "peak_wrist_force_N"},
      "constraints": [)" + constraint + "]}"),
                             "study.json", studies());
}

TEST_CASE("A constraint missed by less than its default tolerance, 1e-6 of the limit, is met") {
  const double swingweight =
      *io::find_output("swingweight_kg_cm2")
           ->value(evaluate(io::load_design(studies() + "../table1/row1.json").design));
  const auto run = [&](double limit, const std::string& extra) {
    return studies::run_optimization(
        study_with_swingweight_limit(R"({"output": "swingweight_kg_cm2", "min": )" +
                                     fmt::format("{:.17g}", limit) + extra + "}"));
  };
  // Short of the limit by 3e-8 of it (the "309.99999 >= 310" of the issue): met.
  const studies::OptimizationResult within = run(swingweight * (1 + 3e-8), "");
  REQUIRE(within.constraints.size() == 1);
  CHECK(within.constraints[0].limit == swingweight * (1 + 3e-8));
  CHECK(within.constraints[0].tolerance == 1e-6 * within.constraints[0].limit);
  CHECK(within.constraints[0].violation > 0.0);
  CHECK(within.constraints[0].satisfied);
  CHECK(within.outcome == studies::Outcome::kOptimum);
  CHECK(within.summary.feasible);
  // Short by 2e-6 of it: twice the tolerance, violated.
  const studies::OptimizationResult beyond = run(swingweight * (1 + 2e-6), "");
  CHECK_FALSE(beyond.constraints[0].satisfied);
  CHECK(beyond.outcome == studies::Outcome::kInfeasible);
  // The study's own tolerance overrides the default.
  const studies::OptimizationResult loose = run(swingweight * (1 + 2e-6), R"(, "tolerance": 0.01)");
  CHECK(loose.constraints[0].tolerance == 0.01);
  CHECK(loose.constraints[0].satisfied);
}

TEST_CASE(
    "An objective with no value anywhere is reported as no valid design, never as the penalty") {
  // A uniform beam hit at its centre of mass turns about no axis: the free
  // rotation axis is at infinity whatever the ball's speed.
  const studies::Study study = studies::read_study(nlohmann::json::parse(R"({
      "design": {"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.25}]}, "impact": {"from_butt_m": 0.35},
                 "ball": {"speed_m_s": 50}},
      "variables": [{"path": "/ball/speed_m_s", "min": 40, "max": 60}],
      "objective": {"output": "rotation_axis_free_from_butt_m"}})"),
                                                   "study.json", studies());
  REQUIRE_FALSE(
      io::find_output("rotation_axis_free_from_butt_m")
          ->value(studies::evaluate_in(study, studies::design_at(study, std::vector<double>{50}))));
  const studies::OptimizationResult r = run_optimization(study);
  CHECK(r.outcome == studies::Outcome::kNoValue);
  CHECK_THAT(r.no_value, Catch::Contains("rotation_axis_free_from_butt_m"));
  CHECK_FALSE(r.start_objective.has_value());
}

TEST_CASE(
    "auto costs at most twice the best single algorithm on every shipped study, and finds the best "
    "optimum") {
  // The single algorithms run from the study's start; "best" is the cheapest
  // that reaches the best objective any of them (or auto) finds. Where the
  // optimum lies on equality constraints, an algorithm may end anywhere
  // within their tolerance (1e-6 of the limit), which moves the objective by
  // about as much: optima agreeing to 1e-5 are the same.
  constexpr double kSameOptimum = 1e-5;  // relative
  for (const char* name :
       {"1-lowest-wrist-force-table1-ranges.json", "2-lowest-wrist-force-fixed-feel.json",
        "3a-cop-on-node-table1-racquet.json", "3b-cop-on-node-paper-beam.json",
        "4-robust-lowest-worst-wrist-force.json"}) {
    studies::Study study = studies::load_study(studies() + name);
    const optimizer::Problem problem = make_problem(study);
    const bool equality =
        std::any_of(study.constraints.begin(), study.constraints.end(),
                    [](const studies::StudyConstraint& c) { return c.equals.has_value(); });
    std::vector<std::string> singles{"LN_COBYLA"};
    if (problem.smooth) singles.push_back("LD_SLSQP");
    if (problem.smooth && !equality) singles.push_back("LD_MMA");
    if (study.constraints.empty()) singles.push_back("LN_BOBYQA");
    study.options.algorithm = "auto";
    const studies::OptimizationResult automatic = run_optimization(study);
    REQUIRE(automatic.summary.feasible);
    std::vector<std::pair<std::string, studies::OptimizationResult>> runs;
    double best = automatic.summary.objective;
    for (const std::string& algorithm : singles) {
      study.options.algorithm = algorithm;
      runs.emplace_back(algorithm, studies::run_optimization(study));
      if (runs.back().second.summary.feasible)
        best = std::min(best, runs.back().second.summary.objective);
    }
    const double reached = best + kSameOptimum * std::max(1.0, std::abs(best));
    int cheapest = std::numeric_limits<int>::max();
    std::string report =
        std::string(name) + ": auto " + std::to_string(automatic.summary.evaluations);
    for (const auto& [algorithm, r] : runs) {
      report += ", " + algorithm + " " + std::to_string(r.summary.evaluations);
      if (r.summary.feasible && r.summary.objective <= reached) {
        cheapest = std::min(cheapest, r.summary.evaluations);
      }
    }
    INFO(report << " (" << automatic.summary.algorithm << ")");
    CHECK(automatic.summary.objective <= reached);
    CHECK(automatic.summary.evaluations <= 2 * cheapest);
  }
}

TEST_CASE("Sweep values outside the variable's bounds are refused with their JSON path") {
  const auto error_of = [](const char* values) {
    try {
      studies::read_study(
          nlohmann::json::parse(
              std::string(R"({"design": "../table1/row1.json", "outputs": ["mass_kg"],
          "variables": [{"path": "/frame/cor", "min": 0.6, "max": 0.8},
                        {"path": "/hand/mass_kg", "min": 0.3, "max": 0.6, "values": )") +
              values + "}]}"),
          "study.json", studies());
    } catch (const io::InputError& e) {
      return e.pointer() + ": " + e.detail();
    }
    return std::string("(no error)");
  };
  CHECK(error_of("[0.3, 0.45, 0.6]") == "(no error)");
  CHECK_THAT(error_of("[0.3, 0.7, 0.5]"), Catch::StartsWith("/variables/1/values/1:") &&
                                              Catch::Contains("0.7") &&
                                              Catch::Contains("[0.3, 0.6]"));
  CHECK_THAT(error_of("[0.29, 0.5]"), Catch::StartsWith("/variables/1/values/0:"));
  CHECK_THAT(error_of("[0.5, \"x\"]"),
             Catch::StartsWith("/variables/1/values/1:") && Catch::Contains("finite number"));
}

TEST_CASE(
    "An impact spread off the implement is refused naming its end and the implement's length") {
  const auto error_of = [](const char* range) {
    try {
      studies::read_study(nlohmann::json::parse(std::string(R"({"design": "../table1/row1.json",
          "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.4}],
          "objective": {"output": "peak_wrist_force_N", "over_impacts": {"from_tip_m": )") +
                                                range + "}}}"),
                          "study.json", studies());
    } catch (const io::InputError& e) {
      return e.pointer() + ": " + e.detail();
    }
    return std::string("(no error)");
  };
  CHECK(error_of("[0.1, 0.7]") == "(no error)");  // the butt itself is on the implement
  CHECK_THAT(error_of("[0.1, 5.0]"), Catch::StartsWith("/objective/over_impacts/from_tip_m/1:") &&
                                         Catch::Contains("5") && Catch::Contains("0.7 m long"));
  CHECK_THAT(error_of("[-0.1, 0.2]"), Catch::StartsWith("/objective/over_impacts/from_tip_m/0:"));
  CHECK_THAT(error_of("[0.2, 0.1]"), Catch::StartsWith("/objective/over_impacts/from_tip_m/1:"));
}

TEST_CASE("A robust objective over a spread of hits off a swung racquet is evaluate() at each") {
  // Each hit of the spread meets the ball at its own speed, v_in + V(x): the
  // worst case is the largest of evaluate() at the spread's points.
  const studies::Study study = studies::read_study(
      nlohmann::json::parse(R"({"design": {"implement": {"length_m": 0.7, "mass_kg": 0.25,
          "head_to_handle_mass_ratio": 0.8}, "frame": {"cor": 0.8},
          "strings": {"impact_duration_ms": 4}, "hand": {"mass_kg": 0.5}, "ball": {"speed_m_s": 20},
          "swing": {"angular_speed_rad_s": 20, "pivot_beyond_butt_m": 0.6}},
        "fidelity": "rigid",
        "variables": [{"path": "/hand/mass_kg", "min": 0.3, "max": 0.6}],
        "objective": {"output": "peak_wrist_force_N",
                      "over_impacts": {"from_tip_m": [0.05, 0.3], "points": 6, "reduce": "max"}}})"),
      "study.json", studies());
  const io::DesignFile file = studies::design_at(study, std::vector<double>{0.5});
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    Design at = file.design;
    at.impact_from_butt_m = 0.7 - (0.05 + 0.05 * k);
    worst = std::max(worst, evaluate(at, Fidelity::kRigid).peak_wrist_force_N);
  }
  CHECK(studies::objective_of(study, file) == Approx(worst).epsilon(1e-12));

  // At rest, the shared rigid path over the hits: the shot of the assumed
  // groundstroke at each hit, as evaluate() gives it (it had been 0).
  io::Json text = nlohmann::json::parse(R"({"design": "../table1/row1.json", "fidelity": "rigid",
      "variables": [{"path": "/hand/mass_kg", "min": 0.3, "max": 0.6}],
      "objective": {"output": "shot_speed_m_s", "goal": "maximize",
                    "over_impacts": {"from_tip_m": [0.1, 0.22], "points": 3, "reduce": "mean"}}})");
  const studies::Study at_rest = studies::read_study(text, "study.json", studies());
  const io::DesignFile row = studies::design_at(at_rest, std::vector<double>{0.5});
  double mean = 0.0;
  for (int k = 0; k < 3; ++k) {
    Design at = row.design;
    at.impact_from_butt_m = 0.7 - (0.1 + 0.06 * k);
    mean += evaluate(at, Fidelity::kRigid).shot_speed_m_s / 3.0;
  }
  CHECK(mean > 20.0);
  // Maximised: the objective to minimise is its negative.
  CHECK(studies::objective_of(at_rest, row) == Approx(-mean).epsilon(1e-12));
}

TEST_CASE("Optimizer tolerances are refused under their own keys") {
  const auto error_of = [](const char* tolerances) {
    try {
      studies::read_study(nlohmann::json::parse(std::string(R"({"design": "../table1/row1.json",
          "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.4}],
          "objective": {"output": "peak_wrist_force_N"}, "tolerances": )") +
                                                tolerances + "}"),
                          "study.json", studies());
    } catch (const io::InputError& e) {
      return e.pointer() + ": " + e.detail();
    }
    return std::string("(no error)");
  };
  CHECK(error_of(R"({"max_seconds": 1e-9, "max_evaluations": 1})") == "(no error)");
  CHECK_THAT(error_of(R"({"x_rel": 0})"), Catch::StartsWith("/tolerances/x_rel:"));
  CHECK_THAT(error_of(R"({"f_rel": -1})"), Catch::StartsWith("/tolerances/f_rel:"));
  CHECK_THAT(error_of(R"({"max_seconds": 0})"), Catch::StartsWith("/tolerances/max_seconds:"));
  CHECK_THAT(error_of(R"({"max_evaluations": 0})"),
             Catch::StartsWith("/tolerances/max_evaluations:"));
  CHECK_THAT(error_of(R"({"max_evaluations": 2.5})"),
             Catch::StartsWith("/tolerances/max_evaluations:"));
}

TEST_CASE(
    "A sweep along the impact shares each row's design and writes what reading every point "
    "writes") {
  // The oracle is the sweep that reads and evaluates every point on its own:
  // sharing a row's design (ImpactSweep), computing the rigid outcome alone and splitting the grid
  // among threads must change no byte, including the rows that fail (off the implement, a negative
  // ball speed) and a second sweep whose first variable is not the impact.
  const char* texts[] = {
      R"({"design": {"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
                     "ball": {"speed_m_s": 50}, "impact": {"from_tip_cm": 5}},
          "outputs": ["peak_wrist_force_N", "rotation_axis_free_from_butt_m", "shot_speed_m_s"],
          "variables": [{"path": "/impact/from_tip_cm", "min": -5, "max": 80, "points": 87},
                        {"path": "/ball/speed_m_s", "values": [-1, 10, 50]}]})",
      R"({"design": {"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
                     "impact": {"from_butt_m": 0.3}},
          "outputs": ["peak_impact_force_N"],
          "variables": [{"path": "/impact/from_butt_m", "min": 0, "max": 0.7, "points": 30}]})",
      R"({"design": "../table1/row1.json", "outputs": ["wrist_force_ratio"],
          "variables": [{"path": "/hand/mass_kg", "min": 0, "max": 0.6, "points": 25},
                        {"path": "/impact/from_tip_m", "values": [0.05, 0.8]}]})",
      // A swung racquet: each impact meets the ball at its own speed, v_in + V(x).
      R"({"design": {"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
                     "hand": {"mass_kg": 0.5}, "ball": {"speed_m_s": 20}, "impact": {"from_tip_cm": 5},
                     "swing": {"angular_speed_rad_s": 20, "pivot_beyond_butt_m": 0.6}},
          "outputs": ["peak_wrist_force_N", "impulse_N_s"],
          "variables": [{"path": "/impact/from_tip_cm", "min": -5, "max": 80, "points": 30},
                        {"path": "/hand/mass_kg", "values": [0.4, 0.5]}]})"};
  for (const char* text : texts) {
    const studies::Study study =
        studies::read_study(nlohmann::json::parse(text), "sweep.json", studies());
    const auto sweep = [&](studies::SweepOptions options) {
      std::ostringstream csv;
      const std::vector<io::Plot> plots = studies::run_sweep(
          study, csv, [](std::size_t, std::size_t) {}, options);
      std::vector<std::vector<std::optional<double>>> y;
      for (const io::Plot& plot : plots) {
        for (const io::PlotSeries& series : plot.series) y.push_back(series.y);
      }
      return std::pair{csv.str(), y};
    };
    const auto reference = sweep(studies::SweepOptions{1, false, false, false});
    const bool has_failed_rows = reference.first.find("must be") != std::string::npos;
    CHECK(has_failed_rows == (text != texts[1]));  // the first and last grids reach bad points
    for (const studies::SweepOptions options :
         {studies::SweepOptions{1, true}, studies::SweepOptions{3, true},
          studies::SweepOptions{2, false}, studies::SweepOptions{1, false, true, true}}) {
      INFO(text << " with " << options.threads << " threads, sharing " << options.share_rows);
      const auto result = sweep(options);
      CHECK(result.first == reference.first);
      CHECK(result.second == reference.second);
    }
  }
}

TEST_CASE("A variable in another unit than the design's varies the same quantity in that unit") {
  // The design gives the tension in N; the study varies it in lb (1 lb = 4.4482216152605 N).
  const auto study_over = [](const std::string& path) {
    return studies::read_study(nlohmann::json::parse(R"({"design": {"implement": {"length_m": 0.7,
        "mass_kg": 0.3, "head_to_handle_mass_ratio": 0.8}, "strings": {"tension_N": 230}},
        "variables": [{"path": ")" + path + R"(", "min": 1, "max": 500}],
        "objective": {"output": "peak_wrist_force_N"}})"),
                               "study.json", studies());
  };
  const studies::Study in_lb = study_over("/strings/tension_lb");
  const studies::Study in_kg = study_over("/strings/tension_kg");
  const studies::Study in_N = study_over("/strings/tension_N");
  const auto duration = [](const studies::Study& study, double x) {
    return evaluate_in(study, design_at(study, std::vector<double>{x})).impact_duration_s;
  };
  CHECK(duration(in_lb, 50) == Approx(duration(in_N, 50 * 4.4482216152605)).epsilon(1e-12));
  CHECK(duration(in_kg, 22) == Approx(duration(in_N, 22 * 9.80665)).epsilon(1e-12));
  // The start is the design's own tension, in the variable's unit.
  CHECK(in_lb.design_document["strings"]["tension_lb"].get<double>() ==
        Approx(230 / 4.4482216152605).epsilon(1e-12));
  CHECK_FALSE(in_lb.design_document["strings"].contains("tension_N"));
}

TEST_CASE("Study 7: lead tape for power with the solved collision in the loop, against a grid") {
  // Maximise the rebound speed (the solved collision, fidelity collision) over
  // the tape's position and mass under swingweight <= 335 kg cm^2. Brute force
  // on a 41 x 41 grid of the same model; the optimiser, continuous, may beat it
  // by what the grid misses of the constraint boundary (1/40 of a range) but
  // must not lose to it.
  const studies::Study study = studies::load_study(studies() + "7-lead-tape-for-power.json");
  const studies::OptimizationResult r = run_optimization(study);
  REQUIRE(r.summary.feasible);
  const double grid = grid_minimum(study, 41, [](const io::DesignFile& d) {
    return *io::find_output("swingweight_kg_cm2")->value(evaluate(d.design, Fidelity::kRigid)) <=
           335.0;
  });
  // Objectives in their minimised form: minus the rebound speed.
  CHECK(r.summary.objective <= grid + kBeatsGridTolerance * std::abs(grid));
  CHECK(r.summary.objective == Approx(grid).epsilon(2e-3));
  REQUIRE(r.constraints.size() == 1);
  CHECK(r.constraints[0].active);
}

}  // namespace
}  // namespace sweetspot::studies

namespace sweetspot::studies {

TEST_CASE(
    "Sweep grids are the decimals they stand for: 0.1 to 0.5 in 5 points is 0.1, 0.2, "
    "0.3, 0.4, 0.5 exactly") {
  const studies::Study study = studies::read_study(io::Json::parse(R"({
    "design": {"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8}},
    "variables": [{"path": "/implement/mass_kg", "min": 0.1, "max": 0.5, "points": 5},
                  {"path": "/implement/length_m", "min": 0.6, "max": 0.7, "points": 11}],
    "outputs": ["mass_kg"]})"),
                                                   "grid.json", ".");
  // lo + (hi - lo) i / (n - 1) in binary gives 0.30000000000000004 for the third.
  CHECK(0.1 + (0.5 - 0.1) * 2.0 / 4.0 != 0.3);
  CHECK(study.variables[0].values == std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5});
  for (int i = 0; i <= 10; ++i) {
    CHECK(study.variables[1].values[i] == std::stod(fmt::format("0.{}", 60 + i)));
  }
}

TEST_CASE("A sweep path in another of the field table's keys of the same quantity sweeps it") {
  // rpm over rad/s, square centimetres over square inches: the design's value
  // is rewritten in the variable's key by the scales the reader applies, and
  // starts the search there.
  const studies::Study study = studies::read_study(io::Json::parse(R"({
    "design": {"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
                             "swingweight_kg_cm2": 325, "headsize_sq_in": 100},
               "frame": {"cor": 0.8}, "strings": {"impact_duration_ms": 4},
               "swing": {"angular_speed_rpm": 150, "pivot_beyond_butt_cm": 60}},
    "variables": [{"path": "/swing/angular_speed_rad_s", "min": 10, "max": 20, "points": 3},
                  {"path": "/implement/headsize_cm2", "min": 600, "max": 700, "points": 3}],
    "outputs": ["twistweight_kg_cm2"]})"),
                                                   "respell-table.json", ".");
  CHECK(study.variables[0].start == Approx(150 * 2 * 3.141592653589793 / 60).epsilon(1e-15));
  CHECK(study.variables[1].start == Approx(645.16).epsilon(1e-15));
  // A place in points head-light is another form (it needs the length): not converted.
  CHECK_THROWS_WITH(studies::read_study(io::Json::parse(R"({
    "design": {"implement": {"length_in": 27, "mass_g": 318, "balance_pts_hl": 4,
                             "swingweight_kg_cm2": 325}},
    "variables": [{"path": "/implement/balance_cm", "values": [33]}],
    "outputs": ["mass_kg"]})"),
                                        "pts.json", "."),
                    Catch::Contains("is not in the design"));
}

TEST_CASE("A sweep path in another unit of a key the design gives sweeps that key") {
  const studies::Study study = studies::read_study(io::Json::parse(R"({
    "design": {"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
               "impact": {"from_tip_cm": 5}},
    "variables": [{"path": "/impact/from_tip_m", "min": 0.1, "max": 0.3, "points": 3}],
    "outputs": ["impact_from_tip_m"]})"),
                                                   "respell.json", ".");
  // The design's 5 cm is outside [0.1, 0.3] m: the start is the middle.
  CHECK(study.variables[0].start == Approx(0.2));
  std::ostringstream csv;
  studies::run_sweep(
      study, csv, [](std::size_t, std::size_t) {}, studies::SweepOptions{1});
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);
  CHECK(line == "/impact/from_tip_m,impact_from_tip_m,error");
  for (const double expected : {0.1, 0.2, 0.3}) {
    std::getline(lines, line);
    CHECK(line.substr(0, 4) == fmt::format("{},", expected));
    CHECK(std::stod(line.substr(4)) == Approx(expected).epsilon(1e-12));
    CHECK(line.back() == ',');  // no error
  }
}

}  // namespace sweetspot::studies
