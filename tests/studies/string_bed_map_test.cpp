// The string-bed map: each point is evaluate() at (x, y); a head symmetric
// about the long axis gives a map symmetric in y, exactly.
#include "studies/string_bed_map.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/string_bed.hpp"
#include "sweetspot/swing.hpp"

namespace sweetspot::studies {
namespace {

constexpr double kRoundOff = 1e-12;

Design racquet() {
  Design d{Implement::paper_racquet(0.6858, 0.32, 1.0)};
  d.head = HeadShape{100 * 0.0254 * 0.0254};
  d.impact_from_butt_m = 0.52;
  return d;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

studies::StringBedMapOptions grid(int columns, int rows, Fidelity fidelity = Fidelity::kRigid) {
  studies::StringBedMapOptions options;
  options.columns = columns;
  options.rows = rows;
  options.fidelity = fidelity;
  return options;
}

TEST_CASE("Every map point is the evaluation of an impact there") {
  Design d = racquet();
  const studies::StringBedMap map = string_bed_map(d, grid(9, 7));
  REQUIRE(map.points.size() == 63);
  int on_bed = 0;
  for (const studies::StringBedMapPoint& p : map.points) {
    if (!p.on_bed) continue;
    ++on_bed;
    Design at = d;
    at.impact_from_butt_m = p.from_butt_m;
    at.impact_off_axis_m = p.off_axis_m;
    const Evaluation e = evaluate(at);
    CHECK(p.apparent_cor == Approx(e.apparent_cor).epsilon(kRoundOff));
    CHECK(p.peak_wrist_force_N == Approx(e.peak_wrist_force_N).epsilon(kRoundOff));
    CHECK(p.peak_twist_torque_N_m == Approx(e.peak_twist_torque_N_m).epsilon(kRoundOff));
  }
  // A 9 x 7 grid of cell centres over an ellipse covers about pi/4 of it.
  CHECK(on_bed > 63 / 2);
  CHECK(on_bed < 63);
}

TEST_CASE("A map of a symmetric head is symmetric in y, bit for bit") {
  Design d = racquet();
  d.strings = StringBed{};  // the duration from the tension varies over the bed too
  const studies::StringBedMap map = string_bed_map(d, grid(20, 15));
  for (int j = 0; j < map.rows; ++j) {
    for (int i = 0; i < map.columns; ++i) {
      const studies::StringBedMapPoint& a = map.points[j * map.columns + i];
      const studies::StringBedMapPoint& b = map.points[(map.rows - 1 - j) * map.columns + i];
      CHECK(a.off_axis_m == -b.off_axis_m);
      CHECK(a.on_bed == b.on_bed);
      CHECK(same_bits(a.apparent_cor, b.apparent_cor));
      CHECK(same_bits(a.peak_wrist_force_N, b.peak_wrist_force_N));
    }
  }
}

TEST_CASE("Power falls and shock is least along the hand-held COP's line") {
  const studies::StringBedMap map = string_bed_map(racquet(), grid(30, 31));
  // The middle row is the long axis (31 rows: y = 0 exactly).
  const int mid = 15;
  CHECK(map.points[mid * 30].off_axis_m == 0.0);
  for (int i = 0; i < 30; ++i) {
    const studies::StringBedMapPoint& axis = map.points[mid * 30 + i];
    const studies::StringBedMapPoint& off = map.points[(mid + 3) * 30 + i];
    if (!off.on_bed) continue;
    CHECK(off.apparent_cor < axis.apparent_cor);
  }
  REQUIRE(map.cop_hand_from_butt_m);
}

TEST_CASE("The feel map is the vibration energy of the response model at each point") {
  Design d = racquet();
  d.stiffness.fundamental_free_Hz = 150.0;
  const studies::StringBedMap map = string_bed_map(d, grid(8, 5, Fidelity::kModal));
  REQUIRE(map.node_free_from_butt_m);
  for (const studies::StringBedMapPoint& p : map.points) {
    if (!p.on_bed) continue;
    Design at = d;
    at.impact_from_butt_m = p.from_butt_m;
    at.impact_off_axis_m = p.off_axis_m;
    if (!p.vibration_energy_J) {
      // Past the energy ledger's limit evaluate() refuses the design too.
      CHECK_THROWS_WITH(evaluate(at, Fidelity::kResponse), Catch::StartsWith("frame/cor"));
      continue;
    }
    const Evaluation e = evaluate(at, Fidelity::kResponse);
    CHECK(*p.vibration_energy_J == Approx(*e.vibration_energy_J).epsilon(1e-9));
  }
}

TEST_CASE("A collision map is evaluate() at collision fidelity at each point, bit for bit") {
  Design d = racquet();
  d.strings = StringBed{};
  d.stiffness.fundamental_free_Hz = 150.0;
  d.cor_given = false;
  // Free, or in the hand's grip (whose impact moves implement and hand: its
  // own effective mass).
  d.support.kind = GENERATE(Support::Kind::kFree, Support::Kind::kHand);
  const studies::StringBedMap map = string_bed_map(d, grid(6, 5, Fidelity::kCollision));
  REQUIRE(map.node_free_from_butt_m);
  int checked = 0;
  for (const studies::StringBedMapPoint& p : map.points) {
    if (!p.on_bed) continue;
    Design at = d;
    at.impact_from_butt_m = p.from_butt_m;
    at.impact_off_axis_m = p.off_axis_m;
    const Evaluation e = evaluate(at, Fidelity::kCollision);
    CHECK(same_bits(p.apparent_cor, e.apparent_cor));
    CHECK(same_bits(p.effective_mass_kg, e.effective_mass_kg));
    CHECK(same_bits(p.peak_wrist_force_N, e.peak_wrist_force_N));
    CHECK(same_bits(*p.vibration_energy_J, *e.vibration_energy_J));
    CHECK(same_bits(p.peak_twist_torque_N_m, e.peak_twist_torque_N_m));
    ++checked;
  }
  CHECK(checked > 10);
  // Symmetric head, symmetric map.
  for (int j = 0; j < map.rows; ++j) {
    for (int i = 0; i < map.columns; ++i) {
      const studies::StringBedMapPoint& a = map.points[j * map.columns + i];
      const studies::StringBedMapPoint& b = map.points[(map.rows - 1 - j) * map.columns + i];
      if (a.on_bed) CHECK(same_bits(a.apparent_cor, b.apparent_cor));
    }
  }
}

TEST_CASE("A swung racquet's map is evaluate() at each point, at the speed they meet there") {
  // The ball at 20 m/s onto a racquet turning at 20 rad/s about a pivot 60 cm
  // beyond the butt: the meeting speed, 20 + 20 (0.6 + x), moves with x.
  Design d = racquet();
  d.ball.speed_m_s = 20.0;
  d.swing = Swing{20.0, 0.6, std::nullopt};
  const bool solved = GENERATE(false, true);
  if (solved) {
    d.strings = StringBed{};
    d.stiffness.fundamental_free_Hz = 150.0;
    d.cor_given = false;
  }
  const Fidelity fidelity = solved ? Fidelity::kCollision : Fidelity::kRigid;
  const studies::StringBedMap map = string_bed_map(d, grid(5, 3, fidelity));
  Design at_rest = d;
  at_rest.swing.reset();
  const studies::StringBedMap unswung = string_bed_map(at_rest, grid(5, 3, fidelity));
  int checked = 0;
  for (std::size_t k = 0; k < map.points.size(); ++k) {
    const studies::StringBedMapPoint& p = map.points[k];
    if (!p.on_bed) continue;
    Design at = d;
    at.impact_from_butt_m = p.from_butt_m;
    at.impact_off_axis_m = p.off_axis_m;
    const Evaluation e = evaluate(at, fidelity);
    CHECK(p.apparent_cor == Approx(e.apparent_cor).epsilon(kRoundOff));
    CHECK(p.peak_wrist_force_N == Approx(e.peak_wrist_force_N).epsilon(kRoundOff));
    CHECK(p.peak_twist_torque_N_m == Approx(e.peak_twist_torque_N_m).epsilon(kRoundOff));
    if (solved) CHECK(same_bits(*p.vibration_energy_J, *e.vibration_energy_J));
    // The meeting speed is more than twice the ball's: the wrist takes more.
    CHECK(p.peak_wrist_force_N > 1.5 * unswung.points[k].peak_wrist_force_N);
    ++checked;
  }
  CHECK(checked > 5);
}

TEST_CASE("A map refused at a point names the first point evaluate() refuses, on any threads") {
  // The ball at 40 m/s onto a strung racquet turning at 60 rad/s: towards the
  // tip they meet near 100 m/s, where the ball would be squeezed past its
  // radius. The map refuses as evaluate() does at the first such point of its
  // grid (columns from the butt, rows across), and says which.
  Design d = racquet();
  d.ball.speed_m_s = 40.0;
  d.swing = Swing{60.0, 0.6, std::nullopt};
  d.strings = StringBed{};
  d.stiffness.fundamental_free_Hz = 150.0;
  d.cor_given = false;
  const int columns = 5, rows = 3;
  Design at_rest = d;
  at_rest.swing.reset();
  const studies::StringBedMap layout = string_bed_map(at_rest, grid(columns, rows));
  std::string expected_field, expected_where;
  for (int i = 0; i < columns && expected_field.empty(); ++i) {
    for (int j = 0; j < rows && expected_field.empty(); ++j) {
      const studies::StringBedMapPoint& p =
          layout.points[static_cast<std::size_t>(j * columns + i)];
      if (!p.on_bed) continue;
      Design at = d;
      at.impact_from_butt_m = p.from_butt_m;
      at.impact_off_axis_m = p.off_axis_m;
      try {
        (void)evaluate(at, Fidelity::kCollision);
      } catch (const ModelRefusal& refusal) {
        expected_field = refusal.field();
        char where[96];
        std::snprintf(where, sizeof where, "at the map's point %.3g cm from the tip",
                      (d.implement.length_m() - p.from_butt_m) * 100.0);
        expected_where = where;
      }
    }
  }
  REQUIRE(expected_field == "swing/angular_speed_rad_s");
  studies::StringBedMapOptions options = grid(columns, rows, Fidelity::kCollision);
  options.threads = GENERATE(1, 4);
  CHECK_THROWS_MATCHES(string_bed_map(d, options), ModelRefusal,
                       Catch::Matchers::Predicate<ModelRefusal>(
                           [&](const ModelRefusal& refusal) {
                             return refusal.field() == expected_field &&
                                    refusal.detail().find(expected_where) != std::string::npos;
                           },
                           "names " + expected_field + " and " + expected_where));
}

TEST_CASE("A map shared among threads is the map of one thread, bit for bit, and says how far") {
  Design d = racquet();
  d.strings = StringBed{};
  d.stiffness.fundamental_free_Hz = 150.0;
  d.cor_given = false;
  const studies::StringBedMap one = string_bed_map(d, grid(13, 9, Fidelity::kCollision));
  for (const int threads : {2, 3, 16}) {
    studies::StringBedMapOptions options = grid(13, 9, Fidelity::kCollision);
    options.threads = threads;
    std::vector<std::size_t> done;
    options.progress = [&](std::size_t points, std::size_t total) {
      CHECK(total == 13u * 9u);
      done.push_back(points);
    };
    const studies::StringBedMap many = string_bed_map(d, options);
    REQUIRE(many.points.size() == one.points.size());
    for (std::size_t k = 0; k < one.points.size(); ++k) {
      const studies::StringBedMapPoint& a = one.points[k];
      const studies::StringBedMapPoint& b = many.points[k];
      REQUIRE(a.on_bed == b.on_bed);
      CHECK(same_bits(a.from_butt_m, b.from_butt_m));
      CHECK(same_bits(a.off_axis_m, b.off_axis_m));
      if (!a.on_bed) continue;
      CHECK(same_bits(a.apparent_cor, b.apparent_cor));
      CHECK(same_bits(a.peak_wrist_force_N, b.peak_wrist_force_N));
      CHECK(same_bits(*a.vibration_energy_J, *b.vibration_energy_J));
    }
    // From nothing to every point, never backwards.
    REQUIRE(done.size() >= 2);
    CHECK(done.front() == 0);
    CHECK(done.back() == 13u * 9u);
    CHECK(std::is_sorted(done.begin(), done.end()));
  }
}

TEST_CASE("The solved collision's power peaks between the hand-held COP and the node") {
  // The rigid model at a fixed COR rises towards the throat (M_eff grows
  // towards the handle); the solved collision loses energy to the frame's
  // vibration away from the node, so its rebound peaks between them.
  Design d = racquet();
  d.strings = StringBed{};
  d.stiffness.fundamental_free_Hz = 150.0;
  d.cor_given = false;
  const studies::StringBedMap map = string_bed_map(d, grid(30, 31, Fidelity::kCollision));
  const int mid = 15;
  int best = -1;
  for (int i = 0; i < 30; ++i) {
    const studies::StringBedMapPoint& p = map.points[mid * 30 + i];
    if (p.on_bed && (best < 0 || p.apparent_cor > map.points[mid * 30 + best].apparent_cor))
      best = i;
  }
  REQUIRE(best >= 0);
  CHECK(best > 0);
  CHECK(best < 29);
  // Between the hand-held COP (no jolt, towards the handle) and the node (no
  // vibration, towards the tip).
  REQUIRE(map.cop_hand_from_butt_m);
  REQUIRE(map.node_free_from_butt_m);
  const double x = map.points[mid * 30 + best].from_butt_m;
  CHECK(*map.cop_hand_from_butt_m < x);
  CHECK(x < *map.node_free_from_butt_m);
}

TEST_CASE("A map needs the head or a twistweight, and a grid of at least 2 x 2") {
  Design d{Implement::paper_racquet(0.6858, 0.32, 1.0)};
  CHECK_THROWS_WITH(studies::string_bed_map(d),
                    Catch::StartsWith("implement: ") && Catch::Contains("headsize_sq_in"));
  CHECK_THROWS_WITH(studies::string_bed_map(racquet(), grid(1, 50)),
                    Catch::StartsWith("--columns"));
}

}  // namespace
}  // namespace sweetspot::studies
