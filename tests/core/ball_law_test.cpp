// The ball's law as the collision's integrator sees it (core/collision/ball_law.hpp)
// and its force over a step (core/collision/contact_force.hpp), against identities:
// the force is the energy's derivative and the stiffness the force's, the damping
// part's derivative is its difference quotient, the step's estimates invert the
// energy, and the discrete gradient's work over a step is the change in stored energy.
#include "core/collision/ball_law.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/collision/contact_force.hpp"

namespace sweetspot::collision_detail {
namespace {

// The calibrated ball, linear and Hunt-Crossley springs, and exponents without a
// fast path (pow).
const BallContactLaw kLaws[] = {kTennisBallLaw,
                                {40e3, 1.0, 30.0, 0.0},
                                {3e5, 1.5, 100.0, 1.5},
                                {2e6, 2.3, 500.0, 0.7},
                                {1e7, 3.0, 0.0, 3.0}};

double central(auto f, double x, double e) { return (f(x + e) - f(x - e)) / (2.0 * e); }

TEST_CASE("The power law's force is its energy's derivative and its stiffness the force's") {
  for (const BallContactLaw& l : kLaws) {
    const PowerLaw law(l);
    for (const double x : {1e-4, 3e-3, 1.2e-2}) {
      const double e = 1e-5 * x;
      CHECK(law.force(x) ==
            Approx(central([&](double y) { return law.energy(y); }, x, e)).epsilon(1e-8));
      CHECK(law.stiffness(x) ==
            Approx(central([&](double y) { return law.force(y); }, x, e)).epsilon(1e-8));
      CHECK(law.force(x) == Approx(l.stiffness * std::pow(x, l.exponent)).epsilon(1e-14));
      // Energy and force together are the same numbers, to the bit.
      CHECK(law.elastic_at(x).energy == law.energy(x));
      CHECK(law.elastic_at(x).force == law.force(x));
      CHECK(law.secant_stiffness(x) * x == Approx(law.force(x)).epsilon(1e-14));
    }
    for (const double x : {0.0, -1e-3}) {
      CHECK(law.energy(x) == 0.0);
      CHECK(law.force(x) == 0.0);
      CHECK(law.stiffness(x) == 0.0);
      CHECK(law.elastic_at(x).force == 0.0);
    }
  }
}

TEST_CASE("The damping part over a step is b xm^p dx / h with its difference quotient in x1") {
  const double h = 2e-5, x0 = 4e-3;
  for (const BallContactLaw& l : kLaws) {
    const PowerLaw law(l);
    const auto damping = [&](double x1) {
      return law.step_damping(0.5 * (x0 + x1), x1 - x0, 1.0 / h).force;
    };
    for (const double x1 : {3e-3, 4.5e-3, 6e-3}) {
      const double xm = 0.5 * (x0 + x1), dx = x1 - x0;
      const StepDamping d = law.step_damping(xm, dx, 1.0 / h);
      CHECK(d.force == Approx(l.damping * std::pow(xm, l.damping_exponent) * dx / h)
                           .epsilon(1e-13)
                           .margin(1e-300));
      CHECK(d.d_force_dx1 == Approx(central(damping, x1, 1e-9)).epsilon(1e-6).margin(1e-9));
    }
    // No damping out of contact.
    CHECK(law.step_damping(-1e-4, 1e-4, 1.0 / h).force == 0.0);
    CHECK(law.step_damping(0.0, 1e-4, 1.0 / h).d_force_dx1 == 0.0);
  }
}

TEST_CASE("The peak compression stores the kinetic energy 1/2 m v^2") {
  for (const BallContactLaw& l : kLaws) {
    const PowerLaw law(l);
    for (const double v : {1.0, 20.0, 50.0}) {
      const double m = 0.057;
      CHECK(law.energy(law.peak_compression(m, v)) == Approx(0.5 * m * v * v).epsilon(1e-13));
    }
  }
}

TEST_CASE("Without damping the step force's work is the stored energy's change") {
  for (const BallContactLaw& l : kLaws) {
    const PowerLaw law(BallContactLaw{l.stiffness, l.exponent, 0.0, l.damping_exponent});
    for (const auto& [x0, x1] : {std::pair{1e-3, 2e-3}, std::pair{5e-3, 3e-3},
                                 std::pair{-1e-3, 2e-3}, std::pair{2e-3, -5e-4}}) {
      const double u0 = law.energy(x0), u1 = law.energy(x1);
      const StepForce s = step_force(law, x0, u0, x1, 1.0 / 1e-5);
      CHECK(s.force * (x1 - x0) == Approx(u1 - u0).epsilon(1e-12));
    }
  }
}

TEST_CASE("The solved step force is the root of F = Phi(a - c F)") {
  const double h = 1e-5, x0 = 3e-3;
  for (const BallContactLaw& l : kLaws) {
    const PowerLaw law(l);
    const double u0 = law.energy(x0);
    for (const double a : {2e-3, 3.5e-3, 8e-3}) {
      const double c = 1e-8;
      // From Phi(a), the top of the bracket [0, Phi(a)] the root lies in.
      const double guess = step_force(law, x0, u0, a, 1.0 / h).force;
      const double F = solve_force(law, x0, u0, a, c, h, guess, 1e-6);
      const double phi = step_force(law, x0, u0, a - c * F, 1.0 / h).force;
      CHECK(F >= 0.0);
      CHECK(F <= guess);
      CHECK(F == Approx(phi).epsilon(1e-12).margin(1e-9));
    }
  }
}

}  // namespace
}  // namespace sweetspot::collision_detail
