// The ball's law as the collision's integrator sees it (core/collision/ball_law.hpp)
// and its force over a step (core/collision/contact_force.hpp), against identities:
// the force is the energy's derivative and the stiffness the force's, the damping
// part's derivative is its difference quotient, the step's estimates invert the
// energy, and the discrete gradient's work over a step is the change in stored energy.
#include "core/collision/ball_law.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "core/collision/contact_force.hpp"
#include "sweetspot/collision.hpp"

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

// ------------------------------------------------------------ the hysteretic ball

// The calibrated hysteretic ball, one with its every branch at its minimum
// exponent, and a deader one.
HystereticBallLaw hysteretic_with_offset(double offset) {
  HystereticBallLaw h = kHystereticTennisBallLaw.hysteretic;
  h.unloading_offset = offset;
  return h;
}
const HystereticBallLaw kHystereticLaws[] = {kHystereticTennisBallLaw.hysteretic,
                                             hysteretic_with_offset(-10.0),
                                             hysteretic_with_offset(3.0)};

TEST_CASE("The hysteretic ball's force is its energy's derivative on either side of its peak") {
  for (const HystereticBallLaw& h : kHystereticLaws) {
    HystereticLaw law(h);
    // Loading from rest: the backbone, whose work is the energy.
    for (const double x : {3e-4, 2e-3, 1.5e-2}) {
      CHECK(law.force(x) == Approx(law.backbone(x)).epsilon(1e-14));
      CHECK(law.energy(x) == Approx(law.backbone_work(x)).epsilon(1e-14));
      CHECK(law.force(x) ==
            Approx(central([&](double y) { return law.energy(y); }, x, 1e-6 * x)).epsilon(1e-7));
    }
    // After a peak of 8 mm: the unloading branch below it, elastic, and the
    // backbone's work added beyond it; continuous at the peak.
    law.commit(8e-3);
    CHECK(law.peak() == 8e-3);
    for (const double x : {5e-4, 3e-3, 7.5e-3, 9e-3}) {
      const double e = 1e-6 * x;
      CHECK(law.force(x) ==
            Approx(central([&](double y) { return law.energy(y); }, x, e)).epsilon(1e-7));
      CHECK(law.stiffness(x) ==
            Approx(central([&](double y) { return law.force(y); }, x, e)).epsilon(1e-6));
      CHECK(law.elastic_at(x).energy == law.energy(x));
      CHECK(law.force(x) <= law.backbone(x) * (1.0 + 1e-15));  // never above loading
    }
    CHECK(law.force(8e-3) == Approx(law.backbone(8e-3)).epsilon(1e-14));
    CHECK(law.energy(8e-3 * (1.0 - 1e-12)) == Approx(law.energy(8e-3)).epsilon(1e-9));
    // A peak never falls in contact; off the surface the ball forgets it.
    law.commit(4e-3);
    CHECK(law.peak() == 8e-3);
    law.commit(-1e-6);
    CHECK(law.peak() == 0.0);
    CHECK(law.energy(-1e-6) == 0.0);
    CHECK(law.force(5e-3) == Approx(law.backbone(5e-3)).epsilon(1e-14));
  }
}

TEST_CASE("The hysteretic ball's peak compression stores the kinetic energy on its backbone") {
  const HystereticLaw law(kHystereticTennisBallLaw.hysteretic);
  for (const double v : {1.0, 7.06, 50.0}) {
    const double m = 0.057;
    CHECK(law.backbone_work(law.peak_compression(m, v)) == Approx(0.5 * m * v * v).epsilon(1e-10));
  }
}

TEST_CASE("Loaded and unloaded slowly, the hysteretic ball loses its loop's area, step by step") {
  // Quasi-static steps of the discrete gradient (no rate: h -> infinity): the
  // work sum F dx less the energy stored after each commit is the ledger's
  // loss; over the ITF's loop to 1 in and back to 0 it is the loop's area.
  for (const HystereticBallLaw& h : kHystereticLaws) {
    HystereticLaw law(h);
    double x = 0.0, u = 0.0, work = 0.0, lost = 0.0;
    const auto step_to = [&](double x1) {
      const StepForce s = step_force(law, x, u, x1, 0.0);
      work += s.force * (x1 - x);
      law.commit(x1);
      const double u1 = law.energy(x1);
      lost += s.force * (x1 - x) - (u1 - u);
      x = x1;
      u = u1;
    };
    const double top = kItfStaticMaxCompression_m;
    for (int i = 1; i <= 400; ++i) step_to(top * i / 400.0);
    const double loading_work = work;
    CHECK(loading_work == Approx(law.backbone_work(top)).epsilon(1e-12));
    for (int i = 399; i >= 0; --i) step_to(top * i / 400.0);
    // Every step's loss is >= 0 and their sum is loading less unloading work.
    CHECK(lost == Approx(work).epsilon(1e-12));
    CHECK(lost > 0.0);
    CHECK(lost < loading_work);
  }
}

TEST_CASE("The ITF's slow test on the relaxed hysteretic ball: its loop and its area") {
  const StaticLoop loop = static_loop(kHystereticTennisBallLaw);
  // The calibration: the middles of the ITF's 5.6-7.4 mm and 8.0-10.8 mm.
  CHECK(loop.forward_deformation_m == Approx(6.5e-3).epsilon(1e-12));
  CHECK(loop.return_deformation_m == Approx(9.4e-3).epsilon(1e-12));
  // The area of the wall's loop in closed form: k xm^2 / 2 - k xm^2 / (q + 1).
  const HystereticBallLaw& h = kHystereticTennisBallLaw.hysteretic;
  const double xm = kItfStaticMaxCompression_m, k = h.wall_stiffness, q = h.wall_unloading;
  CHECK(loop.loop_energy_J == Approx(0.5 * k * xm * xm - k * xm * xm / (q + 1.0)).epsilon(1e-12));
  // The power law has no loop: forward = return, (F / k)^(1/n).
  const StaticLoop none = static_loop(kTennisBallLaw);
  CHECK(none.forward_deformation_m == none.return_deformation_m);
  CHECK(none.loop_energy_J == 0.0);
  CHECK(none.forward_deformation_m ==
        Approx(std::pow(kItfStaticForce_N / kTennisBallLaw.stiffness, 1.0 / 1.5)).epsilon(1e-14));
}

TEST_CASE("The ITF's slow test on the two-mass ball: its wall in series with the internal spring") {
  const StaticLoop loop = static_loop(kTwoMassTennisBallLaw);
  // The calibration: the middles of the ITF's 5.6-7.4 mm and 8.0-10.8 mm.
  CHECK(loop.forward_deformation_m == Approx(6.5e-3).epsilon(1e-9));
  CHECK(loop.return_deformation_m == Approx(9.4e-3).epsilon(1e-9));
  // In series: the internal spring G(d) = k_i d + k_3 d^3 carries the test's
  // force over d, the wall the rest, up to 1 in in all; the loop is the wall's,
  // k xw^2 / 2 - k xw^2 / (q + 1) at the wall's share xw.
  const HystereticBallLaw& h = kTwoMassTennisBallLaw.hysteretic;
  const BallBody& b = kTwoMassTennisBallLaw.body;
  const auto G = [&](double d) {
    return d * (b.internal_stiffness + b.internal_cubic_stiffness * d * d);
  };
  const double d80 = loop.forward_deformation_m - kItfStaticForce_N / h.wall_stiffness;
  CHECK(G(d80) == Approx(kItfStaticForce_N).epsilon(1e-12));
  const double k = h.wall_stiffness, q = h.wall_unloading;
  // xw solves xw + d(k xw) = 1 in, d(F) the internal spring's compression at F.
  double lo = 0.0, hi = kItfStaticMaxCompression_m;
  for (int i = 0; i < 200; ++i) {
    const double xw = 0.5 * (lo + hi), f = k * xw;
    double dlo = 0.0, dhi = f / b.internal_stiffness;
    for (int j = 0; j < 200; ++j) (G(0.5 * (dlo + dhi)) < f ? dlo : dhi) = 0.5 * (dlo + dhi);
    (xw + 0.5 * (dlo + dhi) < kItfStaticMaxCompression_m ? lo : hi) = xw;
  }
  const double xw = 0.5 * (lo + hi);
  CHECK(loop.loop_energy_J == Approx(0.5 * k * xw * xw - k * xw * xw / (q + 1.0)).epsilon(1e-9));
  // With no internal compliance to speak of, the wall's own loop.
  BallContactLaw stiff = kTwoMassTennisBallLaw;
  stiff.body.internal_stiffness = 1e15;
  stiff.body.internal_cubic_stiffness = 0.0;
  BallContactLaw one = stiff;
  one.form = BallLawForm::kHysteretic;
  one.body = BallBody{};
  CHECK(static_loop(stiff).forward_deformation_m ==
        Approx(static_loop(one).forward_deformation_m).epsilon(1e-9));
  CHECK(static_loop(stiff).return_deformation_m ==
        Approx(static_loop(one).return_deformation_m).epsilon(1e-9));
}

TEST_CASE("A ball's body: two masses for the two-mass law, one for the others") {
  BallContactLaw law = kTwoMassTennisBallLaw;
  CHECK(law.validate().empty());
  law.body.front_mass_fraction = 1.0;
  CHECK(law.validate().find("front_mass_fraction") != std::string::npos);
  law = kTwoMassTennisBallLaw;
  law.body.internal_stiffness = 0.0;
  CHECK(law.validate().find("internal_stiffness") != std::string::npos);
  law = kTwoMassTennisBallLaw;
  law.body.internal_cubic_stiffness = -1.0;
  CHECK(law.validate().find("internal_cubic_stiffness") != std::string::npos);
  law = kTwoMassTennisBallLaw;
  law.body.internal_damping_ratio = 1.0;
  CHECK(law.validate().find("internal_damping_ratio") != std::string::npos);
  law = kHystereticTennisBallLaw;
  law.body.front_mass_fraction = 0.5;  // a hysteretic ball of one mass given a second
  CHECK(law.validate().find("one mass") != std::string::npos);
  CHECK(std::string(to_string(BallLawForm::kTwoMass)) == "two_mass");
}

TEST_CASE("The hysteretic law refuses a branch above its backbone and a field out of range") {
  BallContactLaw law = kHystereticTennisBallLaw;
  CHECK(law.validate().empty());
  law.hysteretic.stiffening_unloading = 1.9;
  CHECK(law.validate().find("stiffening_unloading") != std::string::npos);
  law = kHystereticTennisBallLaw;
  law.hysteretic.shell_compression = 0.0;
  CHECK(law.validate().find("shell_compression") != std::string::npos);
  law = kHystereticTennisBallLaw;
  law.hysteretic.unloading_offset = std::nan("");
  CHECK(law.validate().find("unloading_offset") != std::string::npos);
  law.hysteretic.unloading_offset = std::numeric_limits<double>::infinity();  // plastic
  CHECK(law.validate().empty());
}

}  // namespace
}  // namespace sweetspot::collision_detail
