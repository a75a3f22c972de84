// The shot off a swinging racquet along the string bed: the power point
// against the closed form, and Bower & Cross (2005) in play.
#include "sweetspot/swing.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "io/design_reader.hpp"
#include "studies/sweet_spots.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::studies {
namespace {

const std::string kStrung =
    std::string(SWEETSPOT_SOURCE_DIR) + "/designs/racquets/tour-100-strung.json";
const std::string kSpecs = std::string(SWEETSPOT_SOURCE_DIR) + "/designs/racquets/tour-100.json";
constexpr double kRelTol = 1e-6;

TEST_CASE(
    "Rigid model: the power point is beyond the centre of mass by the root of dv_out/dx = 0") {
  // With a given COR e the rigid model's e_A = (e - u) / (1 + u), u = m / M_eff,
  // 1/M_eff = 1/M + b^2 / I_cm, peaks at the centre of mass (b = 0); with
  // V = omega (p + x), dv_out/dx = 0 gives
  //   b = omega I_cm (1 + u) / (2 m (v_in + omega (p + x_cm + b))),
  // solved here by fixed-point iteration, independent of the search.
  io::DesignFile file = io::load_design(kSpecs);
  file.fidelity = "rigid";
  const Evaluation e = io::evaluate_design_file(file, "rigid", kRelTol);
  const auto power = power_point_on_axis(file, "rigid", kRelTol, 1e-4);
  REQUIRE(power);
  const double M = e.mass_kg, I = e.I_cm_kg_m2, m = file.design.ball.mass_kg;
  const double v_in = file.design.ball.speed_m_s, omega = kTypicalGroundstroke.angular_speed_rad_s;
  const double p = kTypicalGroundstroke.pivot_beyond_butt_m, x_cm = e.balance_from_butt_m;
  double b = 0.0;
  for (int k = 0; k < 100; ++k) {
    const double u = m / M + m * b * b / I;
    b = omega * I * (1.0 + u) / (2.0 * m * (v_in + omega * (p + x_cm + b)));
  }
  const double predicted_from_tip = e.length_m - (x_cm + b);
  INFO("b = " << b << " m");
  CHECK(b > 0.0);  // tip-side of the best rebound (the centre of mass)
  // The search's bracket is 1e-4 m wide: its midpoint within half of it.
  CHECK(power->from_tip_m == Approx(predicted_from_tip).margin(1e-4));
}

TEST_CASE(
    "Solved collision: the power point is tip-side of the best rebound by (1+e_A) w / (-e_A'' "
    "(v_in+V))") {
  // The model's own prediction from the curvature of e_A at its peak x_r
  // (e_A'' by central differences of the solved collision, h = 2 cm):
  // dv_out/dx = e_A'(v_in + V) + (1 + e_A) omega = 0 with e_A' = e_A'' (x - x_r).
  const io::DesignFile file = io::load_design(kStrung);
  const auto best = best_rebound_on_axis(file, kRelTol, 1e-3);
  const auto power = power_point_on_axis(file, "collision", kRelTol, 1e-3);
  REQUIRE(best);
  REQUIRE(power);
  auto eA_at = [&](double from_tip) {
    io::DesignFile moved = file;
    moved.design.impact_from_butt_m = moved.design.implement.length_m() - from_tip;
    return io::evaluate_design_file(moved, "collision", kRelTol).apparent_cor;
  };
  const double h = 0.02, x_r = best->from_tip_m;
  const double curvature = (eA_at(x_r - h) - 2.0 * eA_at(x_r) + eA_at(x_r + h)) / (h * h);
  REQUIRE(curvature < 0.0);
  const double eA = best->evaluation.apparent_cor;
  const double omega = kTypicalGroundstroke.angular_speed_rad_s;
  const double V = racquet_speed_m_s(kTypicalGroundstroke, best->evaluation.impact_from_butt_m);
  const double predicted_shift =
      (1.0 + eA) * omega / (-curvature * (file.design.ball.speed_m_s + V));
  const double shift = best->from_tip_m - power->from_tip_m;  // > 0: nearer the tip
  INFO("predicted " << predicted_shift << " m, found " << shift << " m");
  CHECK(shift > 0.0);
  // Both searches to 1 mm (0.5 mm each), and the quadratic model of e_A over
  // the shift's few millimetres: within 2 mm.
  CHECK(shift == Approx(predicted_shift).margin(0.002));
}

TEST_CASE("Bower & Cross (2005) in play: 180 N against 280 N gives their +2.7 % shot") {
  // Bower & Cross, J. Sports Sci. 23, 765-771 (2005): returned cross-court off
  // a ball machine, 108.1 km/h at 180 N against 105.3 km/h at 280 N (+2.66 %).
  // Compared: the model's shot speed at 180 N over its shot at 280 N, with the
  // same swing, solved so that the 280 N racquet gives their 105.3 km/h, for a
  // ball coming at 5, 10 and 15 m/s (the machine's speed is not given). The
  // gain is accepted within 1 percentage point of theirs: they give no
  // uncertainty of the gain itself (their shots spread by +-10 km/h).
  constexpr double kMeasuredGain = 108.1 / 105.3 - 1.0;
  constexpr double kGainTolerance = 0.01;
  const io::DesignFile base = io::load_design(kStrung);
  for (const double v_in : {5.0, 10.0, 15.0}) {
    auto shot = [&](double tension_N, double omega) {
      io::DesignFile file = base;
      file.design.strings->tension_N = tension_N;
      file.design.ball.speed_m_s = v_in;
      file.design.swing = Swing{omega, 0.60, std::nullopt};
      return io::evaluate_design_file(file, "collision", kRelTol).shot_speed_m_s;
    };
    // The swing that gives 105.3 km/h at 280 N (bisection: the shot grows with omega).
    double lo = 1.0, hi = 60.0;
    for (int k = 0; k < 40; ++k) {
      const double mid = 0.5 * (lo + hi);
      (shot(280.0, mid) < 105.3 / 3.6 ? lo : hi) = mid;
    }
    const double omega = 0.5 * (lo + hi);
    const double gain = shot(180.0, omega) / shot(280.0, omega) - 1.0;
    INFO("v_in " << v_in << " m/s: omega " << omega << " rad/s, 180 N at "
                 << 3.6 * shot(180.0, omega) << " km/h, gain " << 100.0 * gain << " %");
    CHECK(gain > 0.0);
    CHECK(gain == Approx(kMeasuredGain).margin(kGainTolerance));
    // The laboratory's apparent-COR gain (5.6 % in docs/model.md) is not this quantity.
    CHECK(gain < 0.04);
  }
}

}  // namespace
}  // namespace sweetspot::studies
