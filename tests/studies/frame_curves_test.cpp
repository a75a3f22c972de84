// The impact moved along the frame: each point the rigid model's or the
// solved collision's, as evaluate() gives it there.
#include "studies/frame_curves.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "io/design_reader.hpp"

namespace sweetspot::studies {
namespace {

io::DesignFile tour_100() {
  return io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
}

// Checks each point of `curve` whose distance from the tip `wanted` accepts
// against evaluate() of the design hit there at `fidelity`: the same rebound
// and wrist force, bit for bit. Returns how many were checked.
template <typename Wanted>
int check_against_evaluate(const Design& d, const std::vector<FramePoint>& curve, Fidelity fidelity,
                           Wanted wanted) {
  int checked = 0;
  for (const FramePoint& p : curve) {
    if (!wanted(p.from_tip_m)) continue;
    Design at = d;
    at.impact_from_butt_m = d.implement.length_m() - p.from_tip_m;
    const Evaluation e = evaluate(at, fidelity);
    CHECK(p.apparent_cor == e.apparent_cor);
    CHECK(p.peak_wrist_force_N == e.peak_wrist_force_N);
    ++checked;
  }
  return checked;
}

TEST_CASE("The curves along the frame are the rigid model's, and zero wrist force at the COP") {
  const io::DesignFile file = tour_100();
  const Design& d = file.design;
  const std::vector<FramePoint> curve = frame_curves(d, 0.01);
  const double L = d.implement.length_m();
  REQUIRE(curve.size() == static_cast<std::size_t>(std::ceil(L / 0.01)) + 1);
  CHECK(curve.front().from_tip_m == 0.0);
  CHECK(curve.back().from_tip_m == L);
  // Each point is Eq. (11) and Eq. (16) at its impact, evaluated afresh.
  for (const FramePoint& p : {curve[5], curve[30], curve[60]}) {
    Design at = d;
    at.impact_from_butt_m = L - p.from_tip_m;
    const Evaluation e = evaluate(at, Fidelity::kRigid);
    CHECK(p.wrist_force_ratio == e.wrist_force_ratio);
    CHECK(p.apparent_cor == e.apparent_cor);
  }
  // The ratio changes sign across the hand-held COP (Eq. 13), and only there.
  const Evaluation e = evaluate(d, Fidelity::kRigid);
  REQUIRE(e.cop_hand_from_butt_m);
  const double cop_from_tip = L - *e.cop_hand_from_butt_m;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const bool crosses = curve[i - 1].wrist_force_ratio * curve[i].wrist_force_ratio < 0;
    const bool cop_between =
        curve[i - 1].from_tip_m < cop_from_tip && cop_from_tip < curve[i].from_tip_m;
    CHECK(crosses == cop_between);
  }
  CHECK_THROWS_AS(frame_curves(d, 0.0), std::invalid_argument);
}

TEST_CASE("A strung design's curves are the solved collision's, as evaluate() gives them") {
  // The numbers on the page and the curves under them must agree: a design
  // solved at collision fidelity draws its curves from the same collision.
  const io::DesignFile file =
      io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json");
  const Design& d = file.design;
  REQUIRE(needed_fidelity(d) == Fidelity::kCollision);
  // Along the strings, where a string bed's hit lands (hit_span()).
  const std::vector<FramePoint> curve = frame_curves(d, 0.01, Fidelity::kCollision, hit_span(file));
  // 5, 15, 25, ... cm from the tip.
  CHECK(check_against_evaluate(d, curve, Fidelity::kCollision, [](double from_tip_m) {
          return std::lround(from_tip_m * 100) % 10 == 5;
        }) >= 4);
}

TEST_CASE("A derived COR's curves are the response model's at each point, as evaluate() gives") {
  // With cor_rigid the rigid model alone has no answer: the page drew nothing
  // (refused) where evaluate answers at the response level.
  io::DesignFile file = tour_100();
  Design& d = file.design;
  d.cor_rigid = 0.85;
  d.cor_given = false;
  const Evaluation asked = evaluate(d, Fidelity::kResponse);
  const std::vector<FramePoint> curve = frame_curves(d, 0.05, frame_curve_fidelity(asked));
  CHECK(check_against_evaluate(d, curve, Fidelity::kResponse, [](double) { return true; }) > 5);
}

TEST_CASE("A swung strung racquet's curves are its collisions at the speed they meet there") {
  io::DesignFile file =
      io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json");
  Design& d = file.design;
  d.ball.speed_m_s = 20.0;
  d.swing = Swing{15.0, 0.6, std::nullopt};
  const std::vector<FramePoint> curve = frame_curves(d, 0.05, Fidelity::kCollision, hit_span(file));
  CHECK(check_against_evaluate(d, curve, Fidelity::kCollision, [](double from_tip_m) {
          return from_tip_m >= 0.05 && from_tip_m <= 0.3;
        }) >= 4);
}

}  // namespace
}  // namespace sweetspot::studies
