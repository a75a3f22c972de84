// A ModeCache reuses the frame's modes only for a design whose modes are the
// same: evaluations through one give the numbers of evaluations without it,
// bit for bit, and solve again exactly when an input of the modes changes.
#include "sweetspot/mode_cache.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "sweetspot/evaluate.hpp"

namespace sweetspot {
namespace {

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same_bits(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || same_bits(*a, *b));
}

// The numbers an evaluation at collision, response or modal fidelity adds to
// the rigid one, and those that depend on the collision.
void check_same(const Evaluation& a, const Evaluation& b) {
  CHECK(same_bits(a.apparent_cor, b.apparent_cor));
  CHECK(same_bits(a.cor, b.cor));
  CHECK(same_bits(a.impact_duration_s, b.impact_duration_s));
  CHECK(same_bits(a.peak_impact_force_N, b.peak_impact_force_N));
  CHECK(same_bits(a.peak_wrist_force_N, b.peak_wrist_force_N));
  CHECK(same_bits(a.impulse_N_s, b.impulse_N_s));
  CHECK(same_bits(a.vibration_energy_J, b.vibration_energy_J));
  REQUIRE(a.modal.has_value() == b.modal.has_value());
  if (a.modal) {
    CHECK(same_bits(a.modal->fundamental_free_Hz, b.modal->fundamental_free_Hz));
    CHECK(same_bits(a.modal->fundamental_hand_Hz, b.modal->fundamental_hand_Hz));
    CHECK(same_bits(a.modal->node_free_from_butt_m, b.modal->node_free_from_butt_m));
    CHECK(same_bits(a.modal->node_hand_from_butt_m, b.modal->node_hand_from_butt_m));
    CHECK(same_bits(a.modal->hand_damping_ratio, b.modal->hand_damping_ratio));
  }
}

Design strung_racquet() {
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};  // tour-100.json
  d.stiffness.RA = 66.0;
  d.impact_from_butt_m = d.implement.length_m() - 0.17;
  d.strings = StringBed{};
  d.cor_given = false;
  return d;
}

}  // namespace

TEST_CASE(
    "A mode cache gives the numbers of a fresh evaluation, bit for bit, and solves only "
    "when the frame changes") {
  ModeCache cache;
  const Design base = strung_racquet();
  // Each step: the change, and whether it changes an input of the modes.
  const std::vector<std::pair<std::function<void(Design&)>, bool>> steps{
      {[](Design&) {}, true},  // the first design: solved
      {[](Design& d) { d.impact_from_butt_m -= 0.03; }, false},
      {[](Design& d) { d.ball.speed_m_s = 30.0; }, false},
      {[](Design& d) { d.strings->tension_N *= 1.1; }, false},
      {[](Design& d) { d.impact_off_axis_m = 0.0; }, false},
      {[](Design& d) { d.stiffness.RA = 62.0; }, true},
      {[](Design& d) { d.hand.grip_stiffness_N_m2 *= 2.0; }, true},
      {[](Design& d) { d.hand.center_from_butt_m += 0.01; }, true},
      {[](Design& d) {
         d.implement = Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320}, {{0.6, 0.004}});
       },
       true},
      {[](Design& d) { d.ball.mass_kg = 0.058; }, false},
  };
  Design d = base;
  std::size_t expected_solves = 0;
  for (const auto& [change, frame_changes] : steps) {
    change(d);
    const std::size_t before = cache.solves();
    const Evaluation cached = evaluate(d, Fidelity::kCollision, {.rel_tol = 1e-6, .modes = &cache});
    const Evaluation fresh = evaluate(d, Fidelity::kCollision, {.rel_tol = 1e-6});
    check_same(cached, fresh);
    // A collision solves the free response model and the hand-held modes.
    CHECK(cache.solves() - before == (frame_changes ? 2u : 0u));
    expected_solves += frame_changes ? 2 : 0;
  }
  CHECK(cache.solves() == expected_solves);
  CHECK(cache.reuses() == 2 * steps.size() - expected_solves);
}

TEST_CASE("A mode cache serves the modal and response fidelities as they are without it") {
  ModeCache cache;
  Design d = strung_racquet();
  d.strings.reset();
  d.cor_given = true;
  for (const Fidelity fidelity : {Fidelity::kModal, Fidelity::kResponse, Fidelity::kModal}) {
    for (const double from_tip : {0.12, 0.17, 0.22}) {
      d.impact_from_butt_m = d.implement.length_m() - from_tip;
      check_same(evaluate(d, fidelity, {.rel_tol = 1e-6, .modes = &cache}),
                 evaluate(d, fidelity, {.rel_tol = 1e-6}));
    }
  }
  // One modal solve and one response model, each reused from then on.
  CHECK(cache.solves() == 2);
}

TEST_CASE("A mode cache keeps nothing from a design whose modes it could not solve") {
  ModeCache cache;
  Design d = strung_racquet();
  d.hand.grip_length_m = 10.0;  // off the implement: the modes refuse it
  CHECK_THROWS(evaluate(d, Fidelity::kCollision, {.rel_tol = 1e-6, .modes = &cache}));
  CHECK_THROWS(evaluate(d, Fidelity::kCollision, {.rel_tol = 1e-6, .modes = &cache}));
  d.hand.grip_length_m = 0.10;
  check_same(evaluate(d, Fidelity::kCollision, {.rel_tol = 1e-6, .modes = &cache}),
             evaluate(d, Fidelity::kCollision, {.rel_tol = 1e-6}));
}

}  // namespace sweetspot
