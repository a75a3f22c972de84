// The shot off a swinging racquet (swing.hpp): the closed form, and the same
// answer from the rigid collision of a moving racquet solved by hand.
#include "sweetspot/swing.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/mass_properties.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {
namespace {

constexpr double kRoundOff = 1e-12;

TEST_CASE("The racquet's speed is omega times the distance from the pivot") {
  const Swing swing{14.0, 0.60, std::nullopt};
  CHECK(racquet_speed_m_s(swing, 0.0) == Approx(14.0 * 0.60).epsilon(kRoundOff));
  CHECK(racquet_speed_m_s(swing, 0.50) == Approx(14.0 * 1.10).epsilon(kRoundOff));
  // The assumed groundstroke moves at the measured 15.4 m/s 50 cm from the butt.
  CHECK(racquet_speed_m_s(kTypicalGroundstroke, 0.50) == Approx(15.4).epsilon(kRoundOff));
}

TEST_CASE("The shot speed is Brody's e_A v_in + (1 + e_A) V") {
  CHECK(shot_speed_m_s(0.4, 10.0, 20.0) == Approx(0.4 * 10.0 + 1.4 * 20.0).epsilon(kRoundOff));
  // A serve (v_in = 0) off a racquet that gives no rebound at rest (e_A = 0):
  // the ball leaves at the racquet's speed.
  CHECK(shot_speed_m_s(0.0, 0.0, 30.0) == Approx(30.0).epsilon(kRoundOff));
  // A racquet at rest gives back the laboratory's rebound e_A v_in.
  CHECK(shot_speed_m_s(0.38, 25.0, 0.0) == Approx(0.38 * 25.0).epsilon(kRoundOff));
}

TEST_CASE("A rigid collision of a moving free racquet, solved by hand, gives the same shot") {
  // Momentum and angular momentum of the free racquet with the impulse J, and
  // the COR e between the ball and the impact point (Cross 1999): the ball's
  // outgoing speed, against the closed form with Eq. (16)'s e_A.
  const MassProperties racquet{0.34, 0.32, 0.0155};
  const double m = 0.057, e = 0.85, omega = 18.0, pivot = 0.45, v_in = 20.0;
  for (const double x : {0.40, 0.50, 0.55, 0.62}) {
    const double b = x - racquet.com_from_butt_m;
    const double v_cm = omega * (pivot + racquet.com_from_butt_m);  // the centre of mass
    const double V = v_cm + omega * b;                              // the impact point
    // Ball towards the racquet at -v_in (the racquet moves at +V). With J the
    // impulse on the ball: m u2 = -m v_in + J; M v_cm' = M v_cm - J;
    // I w' = I w - J b; u2 - V' = e (V + v_in).
    const double inv_M_eff = 1.0 / racquet.mass_kg + b * b / racquet.I_cm_kg_m2;
    const double J = (1.0 + e) * (V + v_in) / (1.0 / m + inv_M_eff);
    const double u2 = -v_in + J / m;
    const double V_after = V - J * inv_M_eff;
    CHECK(u2 - V_after == Approx(e * (V + v_in)).epsilon(1e-12));  // the COR holds
    const double eA = apparent_cor(e, effective_mass(racquet, x), m);
    CHECK(shot_speed_m_s(eA, v_in, racquet_speed_m_s(Swing{omega, pivot, std::nullopt}, x)) ==
          Approx(u2).epsilon(1e-12));
  }
}

TEST_CASE("Swing speed scales as swingweight^-0.27 (Cross & Bower 2006)") {
  const Swing measured{15.0, 0.5, 0.032};
  // The same racquet: the measured swing.
  CHECK(scaled_to_swingweight(measured, 0.032).angular_speed_rad_s ==
        Approx(15.0).epsilon(kRoundOff));
  // 10 % more swingweight: 0.9747 of the speed (1.1^-0.27).
  CHECK(scaled_to_swingweight(measured, 0.0352).angular_speed_rad_s ==
        Approx(15.0 * std::pow(1.1, -0.27)).epsilon(kRoundOff));
  CHECK(std::pow(1.1, -0.27) == Approx(0.9746).margin(1e-4));
  // Without a reference the swing is kept.
  CHECK(scaled_to_swingweight(Swing{15.0, 0.5, std::nullopt}, 0.05).angular_speed_rad_s == 15.0);
}

TEST_CASE("A swing out of range is refused, naming the field") {
  CHECK_THROWS_WITH(validate(Swing{0.0, 0.5, std::nullopt}),
                    Catch::Contains("swing/angular_speed_rad_s"));
  CHECK_THROWS_WITH(validate(Swing{1e3, 0.5, std::nullopt}),
                    Catch::Contains("swing/angular_speed_rad_s"));
  CHECK_THROWS_WITH(validate(Swing{15.0, -0.1, std::nullopt}),
                    Catch::Contains("swing/pivot_beyond_butt_m"));
  CHECK_THROWS_WITH(validate(Swing{15.0, NAN, std::nullopt}),
                    Catch::Contains("swing/pivot_beyond_butt_m"));
  CHECK_THROWS_WITH(validate(Swing{15.0, 0.5, -1.0}),
                    Catch::Contains("swing/reference_swingweight_kg_m2"));
}

TEST_CASE("evaluate() solves a swung design at the relative speed and gives Brody's shot") {
  Design d{Implement::paper_racquet(0.70, 0.34, 0.8)};
  d.impact_from_butt_m = 0.50;
  d.ball.speed_m_s = 15.0;
  d.swing = Swing{14.0, 0.60, std::nullopt};
  const Evaluation e = evaluate(d);
  const double V = 14.0 * 1.10;
  CHECK_FALSE(e.swing_assumed);
  CHECK(e.racquet_speed_m_s == Approx(V).epsilon(kRoundOff));
  CHECK(e.incoming_speed_m_s == 15.0);
  // The impact is the laboratory's at the relative speed v_in + V.
  Design lab = d;
  lab.swing.reset();
  lab.ball.speed_m_s = 15.0 + V;
  const Evaluation at_rest = evaluate(lab);
  CHECK(e.apparent_cor == at_rest.apparent_cor);
  CHECK(e.peak_impact_force_N == at_rest.peak_impact_force_N);
  CHECK(e.shot_speed_m_s ==
        Approx(e.apparent_cor * 15.0 + (1.0 + e.apparent_cor) * V).epsilon(kRoundOff));
  // Without a swing, the assumed groundstroke, said to be assumed.
  CHECK(at_rest.swing_assumed);
  CHECK(at_rest.racquet_speed_m_s ==
        Approx(racquet_speed_m_s(kTypicalGroundstroke, 0.50)).epsilon(kRoundOff));
  // A serve: no incoming ball.
  d.ball.speed_m_s = 0.0;
  CHECK(evaluate(d).shot_speed_m_s == Approx((1.0 + e.apparent_cor) * V).epsilon(kRoundOff));
}

}  // namespace
}  // namespace sweetspot
