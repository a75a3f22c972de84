// Test problems with known optima, stated with their formula.
#include "optimizer/optimize.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <string_view>
#include <thread>

namespace sweetspot {
namespace {

constexpr double kOptimumTolerance = 1e-5;  // on x, for x_tolerance_rel = 1e-7 and O(1) optima

// Rosenbrock: f = (1 - x)^2 + 100 (y - x^2)^2, minimum 0 at (1, 1).
optimizer::Problem rosenbrock() {
  optimizer::Problem p;
  p.lower = {-2.0, -1.0};
  p.upper = {2.0, 3.0};
  p.start = {-1.2, 1.0};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double>) {
    f = (1 - x[0]) * (1 - x[0]) + 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]);
  };
  return p;
}

TEST_CASE("Rosenbrock's curved valley is followed to (1, 1) by auto, SLSQP and BOBYQA") {
  // MMA and COBYLA crawl along this valley and stop on their step tolerances
  // well short of the end; they are checked on a quadratic below.
  for (const char* algorithm : {"auto", "LD_SLSQP", "LN_BOBYQA"}) {
    INFO(algorithm);
    optimizer::OptimizeOptions options;
    options.algorithm = algorithm;
    options.x_tolerance_rel = 1e-10;
    options.f_tolerance_rel = 1e-14;
    const optimizer::Summary s = minimize(rosenbrock(), options);
    CHECK(s.x[0] == Approx(1.0).margin(1e-3));
    CHECK(s.x[1] == Approx(1.0).margin(2e-3));
    CHECK(s.feasible);
    CHECK(s.history.size() == static_cast<std::size_t>(s.evaluations));
  }
}

TEST_CASE("Every local algorithm finds the minimum of a tilted quadratic bowl at (0.3, -0.4)") {
  // f = (x - 0.3)^2 + 3 (y + 0.4)^2 + (x - 0.3)(y + 0.4): positive definite, minimum 0.
  optimizer::Problem p;
  p.lower = {-1, -1};
  p.upper = {1, 1};
  p.start = {0.9, 0.8};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double>) {
    const double u = x[0] - 0.3, v = x[1] + 0.4;
    f = u * u + 3 * v * v + u * v;
  };
  for (const char* algorithm :
       {"auto", "LD_SLSQP", "LD_MMA", "LD_LBFGS", "LN_BOBYQA", "LN_COBYLA", "LN_NELDERMEAD"}) {
    INFO(algorithm);
    optimizer::OptimizeOptions options;
    options.algorithm = algorithm;
    options.x_tolerance_rel = 1e-10;
    options.f_tolerance_rel = 1e-15;
    const optimizer::Summary s = minimize(p, options);
    CHECK(s.x[0] == Approx(0.3).margin(kOptimumTolerance));
    CHECK(s.x[1] == Approx(-0.4).margin(kOptimumTolerance));
  }
}

TEST_CASE("A linear objective on the unit disc stops on the boundary at (-1/√2, -1/√2)") {
  // min x + y subject to x^2 + y^2 - 1 <= 0: KKT gives x = y = -1/sqrt(2).
  optimizer::Problem p;
  p.lower = {-2, -2};
  p.upper = {2, 2};
  p.start = {0.5, 0.5};
  p.constraints = {{"disc", optimizer::ConstraintKind::kAtMostZero, 1e-10}};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double> c) {
    f = x[0] + x[1];
    c[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
  };
  for (const char* algorithm : {"auto", "LD_SLSQP", "LN_COBYLA"}) {
    INFO(algorithm);
    optimizer::OptimizeOptions options;
    options.algorithm = algorithm;
    const optimizer::Summary s = minimize(p, options);
    CHECK(s.x[0] == Approx(-std::sqrt(0.5)).margin(kOptimumTolerance));
    CHECK(s.x[1] == Approx(-std::sqrt(0.5)).margin(kOptimumTolerance));
    CHECK(s.feasible);
  }
}

TEST_CASE("An equality constraint x + y = 1 with f = x^2 + y^2 gives (1/2, 1/2)") {
  optimizer::Problem p;
  p.lower = {-3, -3};
  p.upper = {3, 3};
  p.start = {2, -1};
  p.constraints = {{"line", optimizer::ConstraintKind::kZero, 1e-10}};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double> c) {
    f = x[0] * x[0] + x[1] * x[1];
    c[0] = x[0] + x[1] - 1.0;
  };
  const optimizer::Summary s = minimize(p, optimizer::OptimizeOptions{});
  CHECK(s.x[0] == Approx(0.5).margin(kOptimumTolerance));
  CHECK(s.x[1] == Approx(0.5).margin(kOptimumTolerance));
  CHECK(std::abs(s.constraints[0]) <= 1e-10);
}

TEST_CASE("Difference gradients match the analytic gradient, one-sided at a bound") {
  // f = sin(x) e^y, grad = (cos(x) e^y, sin(x) e^y).
  const auto f = [](std::span<const double> x) { return std::sin(x[0]) * std::exp(x[1]); };
  const std::vector<double> lower{-1, -1}, upper{1, 1};
  for (const std::vector<double>& x :
       {std::vector<double>{0.3, -0.2}, std::vector<double>{1.0, -1.0}}) {
    std::vector<double> grad(2);
    optimizer::difference_gradient(f, x, lower, upper, 1e-6, grad);
    // Central differences err by O(h^2) = 1e-12, one-sided by O(h) = 1e-6.
    const bool on_bound = x[0] == 1.0;
    const double tolerance = on_bound ? 1e-5 : 1e-8;
    CHECK(grad[0] == Approx(std::cos(x[0]) * std::exp(x[1])).margin(tolerance));
    CHECK(grad[1] == Approx(std::sin(x[0]) * std::exp(x[1])).margin(tolerance));
  }
}

TEST_CASE("The evaluation budget counts difference evaluations and is never exceeded") {
  optimizer::OptimizeOptions options;
  options.max_evaluations = 25;
  const optimizer::Summary s = minimize(rosenbrock(), options);
  CHECK(s.evaluations <= 25);
  CHECK(s.termination == optimizer::Termination::kMaxEvaluations);
}

TEST_CASE("A time budget too short for one step ends cleanly with the start as the best point") {
  // 1e-9 s is spent before the first evaluation ends: the start is evaluated
  // all the same (a run always has a best point), then the budget stops the
  // search, constrained or not, local, global or auto.
  optimizer::Problem constrained = rosenbrock();
  constrained.constraints = {{"x + y <= 1", optimizer::ConstraintKind::kAtMostZero, 1e-9}};
  constrained.evaluate = [](std::span<const double> x, double& f, std::span<double> c) {
    f = (1 - x[0]) * (1 - x[0]) + 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]);
    c[0] = x[0] + x[1] - 1.0;
  };
  for (const optimizer::Problem& p : {rosenbrock(), constrained}) {
    // GN_DIRECT_L takes bounds only.
    const char* global = p.constraints.empty() ? "GN_DIRECT_L" : "GN_ISRES";
    for (const char* algorithm : {"auto", "LD_SLSQP", "LN_COBYLA", global}) {
      for (const double seconds : {1e-9, 1e-5}) {
        INFO(algorithm << ", " << p.constraints.size() << " constraints, max_seconds " << seconds);
        optimizer::OptimizeOptions options;
        options.algorithm = algorithm;
        options.max_seconds = seconds;
        const optimizer::Summary s = minimize(p, options);
        REQUIRE(s.x.size() == 2);
        CHECK(s.evaluations >= 1);
        CHECK(s.history.size() == static_cast<std::size_t>(s.evaluations));
        CHECK(s.violation_history.size() == static_cast<std::size_t>(s.evaluations));
        CHECK(std::isfinite(s.objective));
        CHECK(s.termination == optimizer::Termination::kMaxTime);
        if (seconds == 1e-9) {
          CHECK(s.evaluations == 1);
          CHECK(s.x == p.start);
        }
      }
    }
  }
}

TEST_CASE("An evaluation budget of one evaluates the start and nothing else") {
  optimizer::OptimizeOptions options;
  options.max_evaluations = 1;
  for (const char* algorithm : {"auto", "LD_SLSQP", "GN_DIRECT_L"}) {
    INFO(algorithm);
    options.algorithm = algorithm;
    const optimizer::Summary s = minimize(rosenbrock(), options);
    CHECK(s.evaluations == 1);
    CHECK(s.x == rosenbrock().start);
    CHECK(s.termination == optimizer::Termination::kMaxEvaluations);
  }
}

TEST_CASE("Every termination reason has a message of its own") {
  // kTerminations lists the enum in declaration order, so it holds them all.
  for (std::size_t i = 0; i < optimizer::kTerminations.size(); ++i)
    CHECK(static_cast<std::size_t>(optimizer::kTerminations[i]) == i);
  std::set<std::string_view> seen;
  for (const optimizer::Termination t : optimizer::kTerminations) {
    INFO(static_cast<int>(t));
    CHECK_FALSE(optimizer::message(t).empty());
    CHECK(seen.insert(optimizer::message(t)).second);
  }
}

TEST_CASE("Every budget short of what a search needs ends it with kMaxEvaluations, on its path") {
  // The unlimited search needs N evaluations and stops on a tolerance; with a
  // budget b < N the same search is cut short: kMaxEvaluations, at most b
  // evaluations, its history the first evaluations of the unlimited one, and
  // its best point, feasible, usable. auto may spend its last evaluation
  // otherwise: NLopt's own count, which includes the cached start, can end
  // the local search one evaluation early, and a Halton sample takes it.
  for (const char* algorithm : {"auto", "LD_SLSQP", "LN_BOBYQA"}) {
    INFO(algorithm);
    optimizer::OptimizeOptions options;
    options.algorithm = algorithm;
    const optimizer::Summary full = minimize(rosenbrock(), options);
    REQUIRE(full.termination != optimizer::Termination::kMaxEvaluations);
    REQUIRE(full.usable());
    REQUIRE(full.evaluations >= 2);
    for (int budget = 1; budget < full.evaluations; ++budget) {
      INFO("budget " << budget << " of " << full.evaluations);
      options.max_evaluations = budget;
      const optimizer::Summary s = minimize(rosenbrock(), options);
      CHECK(s.termination == optimizer::Termination::kMaxEvaluations);
      CHECK(s.termination_text().starts_with(optimizer::message(s.termination)));
      CHECK(s.evaluations <= budget);
      REQUIRE(s.history.size() == static_cast<std::size_t>(s.evaluations));
      const int same = std::string_view(algorithm) == "auto" ? s.evaluations - 1 : s.evaluations;
      CHECK(std::equal(s.history.begin(), s.history.begin() + same, full.history.begin()));
      CHECK(s.usable());
    }
  }
}

TEST_CASE("A summary is usable when its point is feasible and the run did not fail") {
  // x >= 3 asked of x in [0, 1] (the infeasible case below): never usable,
  // whatever ended the run; x >= 0.5 instead: usable.
  optimizer::Problem p;
  p.lower = {0};
  p.upper = {1};
  p.start = {0.75};
  double limit = 3.0;
  p.constraints = {{"x >= limit", optimizer::ConstraintKind::kAtMostZero, 1e-9}};
  p.evaluate = [&limit](std::span<const double> x, double& f, std::span<double> c) {
    f = x[0];
    c[0] = limit - x[0];
  };
  const optimizer::Summary infeasible = minimize(p, optimizer::OptimizeOptions{});
  CHECK_FALSE(infeasible.feasible);
  CHECK_FALSE(infeasible.usable());
  limit = 0.5;
  optimizer::Summary feasible = minimize(p, optimizer::OptimizeOptions{});
  REQUIRE(feasible.feasible);
  CHECK(feasible.usable());
  CHECK(feasible.x[0] == Approx(0.5).margin(kOptimumTolerance));
  for (const optimizer::Termination t : optimizer::kTerminations) {
    INFO(optimizer::message(t));
    feasible.termination = t;
    CHECK(feasible.usable() == !optimizer::is_failure(t));
  }
}

TEST_CASE(
    "The violation history follows the best point: zero once feasible, its excess over tolerance "
    "when not") {
  // min x + y on the unit disc from (0.5, 0.5), which is feasible (0.5 <= 1).
  optimizer::Problem disc;
  disc.lower = {-2, -2};
  disc.upper = {2, 2};
  disc.start = {0.5, 0.5};
  disc.constraints = {{"disc", optimizer::ConstraintKind::kAtMostZero, 1e-10}};
  disc.evaluate = [](std::span<const double> x, double& f, std::span<double> c) {
    f = x[0] + x[1];
    c[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
  };
  const optimizer::Summary feasible = minimize(disc, optimizer::OptimizeOptions{});
  REQUIRE(feasible.violation_history.size() == static_cast<std::size_t>(feasible.evaluations));
  CHECK(feasible.violation_history.front() == 0.0);
  CHECK(feasible.violation_history.back() <= 1.0);
  // x >= 3 on [0, 1]: the least violating x = 1 is 2 short, 2e9 tolerances.
  optimizer::Problem p;
  p.lower = {0};
  p.upper = {1};
  p.start = {0.5};
  p.constraints = {{"x >= 3", optimizer::ConstraintKind::kAtMostZero, 1e-9}};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double> c) {
    f = x[0];
    c[0] = 3.0 - x[0];
  };
  const optimizer::Summary s = optimizer::minimize(p, optimizer::OptimizeOptions{});
  REQUIRE_FALSE(s.violation_history.empty());
  CHECK(s.violation_history.front() == Approx(2.5e9).epsilon(1e-12));
  CHECK(s.violation_history.back() == Approx(2.0e9).epsilon(1e-6));
}

TEST_CASE("A flat objective terminates at a finite point") {
  optimizer::Problem p = rosenbrock();
  p.evaluate = [](std::span<const double>, double& f, std::span<double>) { f = 3.0; };
  const optimizer::Summary s = minimize(p, optimizer::OptimizeOptions{});
  CHECK(s.objective == 3.0);
  CHECK(std::isfinite(s.x[0]));
  CHECK(s.evaluations < optimizer::OptimizeOptions{}.max_evaluations);
}

TEST_CASE("An infeasible problem reports the least violating point as infeasible") {
  // x >= 3 asked of x in [0, 1]: the best is x = 1, still infeasible.
  optimizer::Problem p;
  p.lower = {0};
  p.upper = {1};
  p.start = {0.5};
  p.constraints = {{"x >= 3", optimizer::ConstraintKind::kAtMostZero, 1e-9}};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double> c) {
    f = x[0];
    c[0] = 3.0 - x[0];
  };
  const optimizer::Summary s = minimize(p, optimizer::OptimizeOptions{});
  CHECK_FALSE(s.feasible);
  CHECK(s.x[0] == Approx(1.0).margin(kOptimumTolerance));
}

TEST_CASE("A start on a bound is accepted and an optimum on that bound is kept") {
  // min (x - 2)^2 on [0, 1] from x = 1: the optimum is the bound itself.
  optimizer::Problem p;
  p.lower = {0};
  p.upper = {1};
  p.start = {1};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double>) {
    f = (x[0] - 2) * (x[0] - 2);
  };
  const optimizer::Summary s = minimize(p, optimizer::OptimizeOptions{});
  CHECK(s.x[0] == 1.0);
}

TEST_CASE("The same seed gives the same search, evaluation for evaluation") {
  optimizer::OptimizeOptions options;
  options.algorithm = "GN_ISRES";
  options.max_evaluations = 400;
  options.seed = 7;
  const optimizer::Summary a = minimize(rosenbrock(), options);
  const optimizer::Summary b = minimize(rosenbrock(), options);
  CHECK(a.x == b.x);
  CHECK(a.evaluations == b.evaluations);
}

// f = sum_i a_i x_i on [0, 1]^n: its minimum is the vertex x_i = 1 where
// a_i < 0, else 0.
optimizer::Problem tilted_box(std::vector<double> a, std::vector<double> start) {
  optimizer::Problem p;
  p.lower.assign(a.size(), 0.0);
  p.upper.assign(a.size(), 1.0);
  p.start = std::move(start);
  p.evaluate = [a](std::span<const double> x, double& f, std::span<double>) {
    f = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) f += a[i] * x[i];
  };
  return p;
}

TEST_CASE(
    "auto ends at the vertex a monotone objective points to, checked against its neighbours") {
  // Linear: the start's differences point straight at the optimum, the
  // vertex (1, 0, 1, 0, 1, 0); 1 + n + 1 + n evaluations reach and check it.
  const std::vector<double> a = {-1.0, 2.0, -0.5, 3.0, -4.0, 0.25};
  const optimizer::Summary s =
      minimize(tilted_box(a, std::vector<double>(6, 0.5)), optimizer::OptimizeOptions{});
  CHECK(s.x == std::vector<double>{1, 0, 1, 0, 1, 0});
  CHECK(s.objective == -5.5);
  CHECK(s.termination == optimizer::Termination::kVertexFirstOrder);
  // The global check costs as much as the local stage: 14 + 14 samples.
  CHECK(s.evaluations == 28);
  CHECK(s.algorithm.find("1 vertex walked downhill") != std::string::npos);
}

TEST_CASE("The vertex walk follows a sign that changes at the first vertex") {
  // f = -x0 + 2 x1 (0.5 - x0) on [0, 1]^2, bilinear, so its minimum is a
  // vertex: -2 at (1, 1) (brute force below). At the start (0.1, 0.5) it
  // falls along x0 and rises along x1: the walk goes to (1, 0), where it
  // falls inward along x1, then to (1, 1), where no inward step improves.
  optimizer::Problem p;
  p.lower = {0.0, 0.0};
  p.upper = {1.0, 1.0};
  p.start = {0.1, 0.5};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double>) {
    f = -x[0] + 2 * x[1] * (0.5 - x[0]);
  };
  const optimizer::Summary s = minimize(p, optimizer::OptimizeOptions{});
  double brute = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 400; ++i) {
    for (int j = 0; j <= 400; ++j) {
      double f = 0.0;
      const std::vector<double> x = {i / 400.0, j / 400.0};
      p.evaluate(x, f, {});
      brute = std::min(brute, f);
    }
  }
  CHECK(s.objective == brute);
  CHECK(s.x == std::vector<double>{1, 1});
  CHECK(s.algorithm.find("2 vertices walked downhill") != std::string::npos);
  CHECK(s.termination == optimizer::Termination::kVertexFirstOrder);
}

TEST_CASE("An interior optimum ends the vertex walk and the local search finds it") {
  // The bowl about (0.3, 0.6) on [0, 1]^2: from (0.9, 0.1) the walk goes to
  // (0, 1), better than the start, then points to (1, 0), which is worse:
  // BOBYQA goes on from (0, 1).
  optimizer::Problem p;
  p.lower = {0.0, 0.0};
  p.upper = {1.0, 1.0};
  p.start = {0.9, 0.1};
  p.evaluate = [](std::span<const double> x, double& f, std::span<double>) {
    f = (x[0] - 0.3) * (x[0] - 0.3) + 2 * (x[1] - 0.6) * (x[1] - 0.6);
  };
  const optimizer::Summary s = minimize(p, optimizer::OptimizeOptions{});
  CHECK(s.x[0] == Approx(0.3).margin(kOptimumTolerance));
  CHECK(s.x[1] == Approx(0.6).margin(kOptimumTolerance));
  CHECK(s.algorithm.find("1 vertex walked downhill (the next no better), then LN_BOBYQA") !=
        std::string::npos);
}

TEST_CASE("Threads give the same search, evaluation for evaluation, when the problem forks") {
  // An evaluation slower than a thread start (a sleep) makes auto use the
  // forks for its differences and samples; the book is kept in point order.
  const auto slow = [](std::span<const double> x, double& f, std::span<double> c) {
    std::this_thread::sleep_for(std::chrono::microseconds(300));
    f = (x[0] - 0.3) * (x[0] - 0.3) + (x[1] + 0.2) * (x[1] + 0.2) + x[0] * x[1];
    if (!c.empty()) c[0] = x[0] + x[1] - 0.5;  // <= 0
  };
  for (const bool constrained : {false, true}) {
    INFO("constrained " << constrained);
    optimizer::Problem p;
    p.lower = {-1.0, -1.0};
    p.upper = {1.0, 1.0};
    p.start = {0.8, 0.8};
    if (constrained) p.constraints = {{"sum", optimizer::ConstraintKind::kAtMostZero, 1e-9}};
    p.evaluate = slow;
    std::atomic<int> forks = 0;
    p.fork = [&]() -> optimizer::EvaluateFunction {
      ++forks;
      return slow;
    };
    // Budgets that end the search inside a batch of points, and one that does not.
    for (const int budget : {2, 5, 9, 300}) {
      INFO("budget " << budget);
      optimizer::OptimizeOptions one;
      one.max_evaluations = budget;
      optimizer::OptimizeOptions four = one;
      four.threads = 4;
      forks = 0;
      const optimizer::Summary a = minimize(p, one);
      CHECK(forks == 0);
      const optimizer::Summary b = minimize(p, four);
      CHECK(forks <= 3);  // one per extra thread the largest batch of points used
      if (budget == 300) CHECK(forks == 3);
      CHECK(a.evaluations <= budget);
      CHECK(a.x == b.x);
      CHECK(a.objective == b.objective);
      CHECK(a.evaluations == b.evaluations);
      CHECK(a.history == b.history);
      CHECK(a.algorithm == b.algorithm);
      CHECK(a.termination == b.termination);
      CHECK(a.termination_text() == b.termination_text());
    }
  }
}

TEST_CASE("Bad problems and options are refused with the argument named") {
  optimizer::Problem p = rosenbrock();
  optimizer::OptimizeOptions options;
  options.algorithm = "LD_NONSENSE";
  CHECK_THROWS_WITH(optimizer::minimize(p, options),
                    Catch::Contains("algorithm") && Catch::Contains("LD_NONSENSE"));
  p.start = {5.0, 0.0};
  CHECK_THROWS_WITH(optimizer::minimize(p, optimizer::OptimizeOptions{}),
                    Catch::Contains("variables/0/start"));
  p = rosenbrock();
  p.lower[1] = 4.0;
  CHECK_THROWS_WITH(optimizer::minimize(p, optimizer::OptimizeOptions{}),
                    Catch::Contains("variables/1: min must be < max"));
  p = rosenbrock();
  p.constraints = {{"c", optimizer::ConstraintKind::kAtMostZero, 1e-9}};
  options.algorithm = "LN_BOBYQA";  // bounds only
  p.evaluate = [](std::span<const double>, double& f, std::span<double> c) {
    f = 0;
    c[0] = -1;
  };
  CHECK_THROWS_WITH(optimizer::minimize(p, options),
                    Catch::Contains("does not take nonlinear constraints"));
  options = optimizer::OptimizeOptions{};
  options.threads = 0;
  CHECK_THROWS_WITH(optimizer::minimize(rosenbrock(), options),
                    Catch::Contains("threads") && Catch::Contains("got 0"));
}

}  // namespace
}  // namespace sweetspot
