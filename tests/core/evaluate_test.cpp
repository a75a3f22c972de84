// Cross (2004) Table I: the force on the strings F0 and on the arm F_w for a
// 70 cm racquet struck 5 cm from the tip by a 57 g ball at 50 m/s.
#include "sweetspot/evaluate.hpp"

#include <array>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "sweetspot/collision.hpp"
#include "sweetspot/kernels.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot {
namespace {

// The paper prints forces rounded to whole newtons.
constexpr double kPrintedForceTolerance_N = 1.0;

struct TableRow {
  double mass_kg, ratio, cor, duration_ms, hand_kg, forearm_kg, F0_N, Fw_N;
};

// Transcribed from Table I of the paper.
constexpr TableRow kTableI[] = {
    {0.25, 0.8, 0.8, 4.0, 0.5, 0.5, 1117, 568}, {0.40, 0.8, 0.8, 4.0, 0.5, 0.5, 1341, 524},
    {0.25, 1.2, 0.8, 4.0, 0.5, 0.5, 1198, 521}, {0.25, 0.8, 0.6, 4.0, 0.5, 0.5, 993, 504},
    {0.25, 0.8, 0.8, 6.0, 0.5, 0.5, 744, 378},  {0.25, 0.8, 0.8, 4.0, 0.4, 0.5, 1117, 550},
    {0.25, 0.8, 0.8, 4.0, 0.5, 0.4, 1117, 511}, {0.40, 1.2, 0.6, 6.0, 0.4, 0.4, 837, 250},
};

Design table_design(const TableRow& row) {
  return Design{Implement::paper_racquet(0.70, row.mass_kg, row.ratio),
                row.cor,
                row.duration_ms / 1000.0,
                Hand{row.hand_kg, 0.07},
                row.forearm_kg,
                Ball{0.057, 50.0},
                0.70 - 0.05};
}

TEST_CASE("Table I: every row's F0 and F_w within 1 N of the printed values") {
  int row_number = 1;
  for (const TableRow& row : kTableI) {
    INFO("Table I row " << row_number++);
    const Evaluation e = evaluate(table_design(row));
    CHECK(e.peak_impact_force_N == Approx(row.F0_N).margin(kPrintedForceTolerance_N));
    CHECK(e.peak_wrist_force_N == Approx(row.Fw_N).margin(kPrintedForceTolerance_N));
  }
}

TEST_CASE("The Table I top row has the largest arm force and the bottom row the smallest") {
  double top = evaluate(table_design(kTableI[0])).peak_wrist_force_N;
  double bottom = evaluate(table_design(kTableI[7])).peak_wrist_force_N;
  for (const TableRow& row : kTableI) {
    const double Fw = evaluate(table_design(row)).peak_wrist_force_N;
    CHECK(Fw <= top);
    CHECK(Fw >= bottom);
  }
}

TEST_CASE("The hand and forearm change neither F0 nor the apparent COR") {
  // Section VI: the ball leaves before the wave reflected off the hand returns.
  Design a = table_design(kTableI[0]);
  Design b = a;
  b.hand = Hand{0.0, 0.07};
  b.forearm_equivalent_mass_kg = 0.0;
  CHECK(evaluate(a).peak_impact_force_N == evaluate(b).peak_impact_force_N);
  CHECK(evaluate(b).peak_wrist_force_N == 0.0);
}

TEST_CASE("Evaluating at the hand-held COP gives zero wrist force and the wrist as the axis") {
  Design d = table_design(kTableI[0]);
  d.impact_from_butt_m = *evaluate(d).cop_hand_from_butt_m;
  const Evaluation e = evaluate(d);
  CHECK(e.peak_wrist_force_N == 0.0);
  REQUIRE(e.rotation_axis_hand_from_butt_m);
  CHECK(*e.rotation_axis_hand_from_butt_m == Approx(0.0).margin(1e-12));
}

TEST_CASE("An impact at the centre of mass of a free racquet reports the axis at infinity") {
  Design d = table_design(kTableI[0]);
  d.hand = Hand{0.0, 0.07};
  d.forearm_equivalent_mass_kg = 0.0;
  d.impact_from_butt_m = d.implement.mass_properties().com_from_butt_m;
  const Evaluation e = evaluate(d);
  CHECK_FALSE(e.rotation_axis_free_from_butt_m.has_value());
  CHECK_FALSE(e.rotation_axis_hand_from_butt_m.has_value());
  CHECK(e.effective_mass_kg == e.mass_kg);
  CHECK(std::isfinite(e.peak_impact_force_N));
}

TEST_CASE("Out-of-range design values are refused with their JSON path") {
  Design d = table_design(kTableI[0]);
  d.cor = 1.5;
  CHECK_THROWS_WITH(evaluate(d), Catch::StartsWith("frame/cor"));
  d = table_design(kTableI[0]);
  d.impact_from_butt_m = 0.71;
  CHECK_THROWS_WITH(evaluate(d), Catch::StartsWith("impact/from_butt_m"));
  d = table_design(kTableI[0]);
  d.hand.mass_kg = -0.5;
  CHECK_THROWS_WITH(evaluate(d), Catch::StartsWith("hand/mass_kg") && Catch::Contains("-0.5"));
  d = table_design(kTableI[0]);
  d.impact_duration_s = std::nan("");
  CHECK_THROWS_WITH(evaluate(d), Catch::StartsWith("strings/impact_duration_s"));
}

}  // namespace
}  // namespace sweetspot

namespace sweetspot {
namespace {

TEST_CASE("An impact sweep gives exactly what evaluating each impact gives") {
  for (const TableRow& row : kTableI) {
    const Design d = table_design(row);
    const ImpactSweep sweep(d);
    for (double x = 0.0; x <= 0.70; x += 0.035) {
      Design at = d;
      at.impact_from_butt_m = x;
      const Evaluation a = sweep.at(x);
      const Evaluation b = evaluate_unchecked(at);
      CHECK(a.peak_wrist_force_N == b.peak_wrist_force_N);
      CHECK(a.peak_impact_force_N == b.peak_impact_force_N);
      CHECK(a.rotation_axis_hand_from_butt_m == b.rotation_axis_hand_from_butt_m);
      CHECK(a.cop_hand_from_butt_m == b.cop_hand_from_butt_m);
    }
  }
  Design derived = table_design(kTableI[0]);
  derived.cor_rigid = 0.85;
  CHECK_THROWS_AS(ImpactSweep(derived), std::invalid_argument);
  // A swung racquet meets the ball at a speed that moves with the impact
  // point: no shared rigid path answers it, evaluate() does.
  Design swung = table_design(kTableI[0]);
  swung.swing = Swing{20.0, 0.6, std::nullopt};
  CHECK_FALSE(impact_sweep_answers(swung));
  CHECK_THROWS_AS(ImpactSweep(swung), std::invalid_argument);
  Evaluation untouched;
  CHECK_FALSE(evaluate_rigid_outcome(swung, untouched));
}

TEST_CASE("Many rigid cases at once give exactly what evaluating each design gives") {
  // The oracle is evaluate() of the same design: rigid_outcomes() must be the
  // same arithmetic, bit for bit, whatever the row, hand or impact.
  std::vector<Design> designs;
  for (const TableRow& row : kTableI) {
    for (const double from_tip : {0.0, 0.05, 0.20, 0.45}) {
      Design d = table_design(row);
      d.impact_from_butt_m = d.implement.length_m() - from_tip;
      designs.push_back(d);
    }
  }
  Design strung = table_design(kTableI[0]);
  strung.strings = StringBed{};  // the duration is derived from the tension, as evaluate() does
  designs.push_back(strung);
  std::vector<RigidCase> cases;
  for (const Design& d : designs) cases.push_back(rigid_case(d));
  std::vector<RigidOutcome> out(cases.size());
  rigid_outcomes(cases, out);
  for (std::size_t i = 0; i < designs.size(); ++i) {
    INFO("design " << i);
    const Evaluation e = evaluate(designs[i]);
    CHECK(out[i].effective_mass_kg == e.effective_mass_kg);
    CHECK(out[i].apparent_cor == e.apparent_cor);
    CHECK(out[i].impulse_N_s == e.impulse_N_s);
    CHECK(out[i].peak_impact_force_N == e.peak_impact_force_N);
    CHECK(out[i].cop_hand_from_butt_m == e.cop_hand_from_butt_m.value());
    CHECK(out[i].wrist_force_ratio == e.wrist_force_ratio);
    CHECK(out[i].peak_wrist_force_N == e.peak_wrist_force_N);
    CHECK(cases[i].impact_duration_s == e.impact_duration_s);
  }
  CHECK(cases.back().impact_duration_s != kTableI[0].duration_ms / 1000.0);
}

TEST_CASE("Rigid cases laid out as arrays give exactly what evaluating each design gives") {
  // The oracle is evaluate(): the vectorised loop over arrays must be the same
  // arithmetic, bit for bit, including a hand of no mass, no forearm and an
  // impact at the centre of mass (the special cases it selects rather than branches on).
  std::vector<Design> designs;
  for (const TableRow& row : kTableI) {
    for (const double from_tip : {0.0, 0.05, 0.20, 0.45}) {
      Design d = table_design(row);
      d.impact_from_butt_m = d.implement.length_m() - from_tip;
      designs.push_back(d);
    }
  }
  Design no_hand = table_design(kTableI[1]);
  no_hand.hand.mass_kg = 0.0;
  designs.push_back(no_hand);
  Design no_forearm = table_design(kTableI[2]);
  no_forearm.forearm_equivalent_mass_kg = 0.0;
  designs.push_back(no_forearm);
  Design at_com = table_design(kTableI[3]);
  at_com.impact_from_butt_m = at_com.implement.mass_properties().com_from_butt_m;
  designs.push_back(at_com);
  const std::size_t n = designs.size();
  std::vector<std::vector<double>> in(11, std::vector<double>(n));
  std::vector<std::vector<double>> out(7, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const RigidCase c = rigid_case(designs[i]);
    const double fields[11] = {
        c.body.mass_kg, c.body.com_from_butt_m,       c.body.I_cm_kg_m2,   c.hand.from_butt_m,
        c.hand.mass_kg, c.forearm_equivalent_mass_kg, c.ball_mass_kg,      c.ball_speed_m_s,
        c.cor,          c.impact_duration_s,          c.impact_from_butt_m};
    for (std::size_t k = 0; k < 11; ++k) in[k][i] = fields[k];
  }
  rigid_outcomes(
      RigidCases{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8], in[9], in[10]},
      RigidOutcomes{out[0], out[1], out[2], out[3], out[4], out[5], out[6]});
  for (std::size_t i = 0; i < n; ++i) {
    INFO("design " << i);
    const Evaluation e = evaluate(designs[i]);
    CHECK(out[0][i] == e.effective_mass_kg);
    CHECK(out[1][i] == e.apparent_cor);
    CHECK(out[2][i] == e.impulse_N_s);
    CHECK(out[3][i] == e.peak_impact_force_N);
    CHECK(out[4][i] == e.cop_hand_from_butt_m.value());
    CHECK(out[5][i] == e.wrist_force_ratio);
    CHECK(out[6][i] == e.peak_wrist_force_N);
  }
  CHECK(out[5][n - 2] == 0.0);
  std::vector<double> short_span(n - 1);
  CHECK_THROWS_WITH(
      rigid_outcomes(RigidCases{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8],
                                in[9], short_span},
                     RigidOutcomes{out[0], out[1], out[2], out[3], out[4], out[5], out[6]}),
      Catch::Contains("impact_from_butt_m"));
}

TEST_CASE("Thousands of rigid cases as arrays, twisted or not, match rigid_outcome() bit for bit") {
  // The oracle is the scalar rigid_outcome() of each case. Enough cases that
  // the vectorised body of the loop runs, not only its scalar remainder, with
  // the special cases it selects rather than branches on (no hand, no
  // forearm, an impact through the centre of mass) spread among them, and the
  // loop without a twist span against the one given zeros.
  std::vector<RigidCase> cases;
  for (int i = 0; i < 2053; ++i) {
    const TableRow& row = kTableI[i % 8];
    Design d = table_design(row);
    d.hand.mass_kg = 0.3 + 0.05 * (i % 5);
    d.impact_from_butt_m = 0.30 + 0.003 * (i % 113);
    if (i % 97 == 3) d.hand.mass_kg = 0.0;
    if (i % 89 == 5) d.forearm_equivalent_mass_kg = 0.0;
    if (i % 83 == 7) d.impact_from_butt_m = d.implement.mass_properties().com_from_butt_m;
    if (i % 3 == 1) {
      d.twistweight_kg_m2 = 14e-4 + 1e-5 * (i % 11);
      d.impact_off_axis_m = 0.002 * (i % 21) - 0.02;
    }
    cases.push_back(rigid_case(d));
  }
  const std::size_t n = cases.size();
  std::vector<std::vector<double>> in(12, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const RigidCase& c = cases[i];
    const double fields[12] = {
        c.body.mass_kg, c.body.com_from_butt_m,       c.body.I_cm_kg_m2,    c.hand.from_butt_m,
        c.hand.mass_kg, c.forearm_equivalent_mass_kg, c.ball_mass_kg,       c.ball_speed_m_s,
        c.cor,          c.impact_duration_s,          c.impact_from_butt_m, c.impact_twist_per_kg};
    for (std::size_t k = 0; k < 12; ++k) in[k][i] = fields[k];
  }
  const auto same_bits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  const auto outcome_fields = [](const RigidOutcome& o) {
    return std::array<double, 7>{o.effective_mass_kg,   o.apparent_cor,         o.impulse_N_s,
                                 o.peak_impact_force_N, o.cop_hand_from_butt_m, o.wrist_force_ratio,
                                 o.peak_wrist_force_N};
  };
  std::vector<std::vector<double>> twisted(7, std::vector<double>(n));
  rigid_outcomes(RigidCases{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8], in[9],
                            in[10], in[11]},
                 RigidOutcomes{twisted[0], twisted[1], twisted[2], twisted[3], twisted[4],
                               twisted[5], twisted[6]});
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto expected = outcome_fields(rigid_outcome(cases[i]));
    for (std::size_t k = 0; k < 7; ++k) differ += same_bits(twisted[k][i], expected[k]) ? 0 : 1;
  }
  CHECK(differ == 0);
  // On the axis: no twist span, and the same cases with explicit zeros.
  const std::vector<double> zeros(n, 0.0);
  std::vector<std::vector<double>> on_axis(7, std::vector<double>(n));
  std::vector<std::vector<double>> zero_twist(7, std::vector<double>(n));
  const RigidCases without{in[0], in[1], in[2], in[3], in[4], in[5],
                           in[6], in[7], in[8], in[9], in[10]};
  RigidCases with_zeros = without;
  with_zeros.impact_twist_per_kg = zeros;
  rigid_outcomes(without, RigidOutcomes{on_axis[0], on_axis[1], on_axis[2], on_axis[3], on_axis[4],
                                        on_axis[5], on_axis[6]});
  rigid_outcomes(with_zeros,
                 RigidOutcomes{zero_twist[0], zero_twist[1], zero_twist[2], zero_twist[3],
                               zero_twist[4], zero_twist[5], zero_twist[6]});
  differ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    RigidCase straight = cases[i];
    straight.impact_twist_per_kg = 0.0;
    const auto expected = outcome_fields(rigid_outcome(straight));
    for (std::size_t k = 0; k < 7; ++k) {
      differ += same_bits(on_axis[k][i], expected[k]) ? 0 : 1;
      differ += same_bits(zero_twist[k][i], expected[k]) ? 0 : 1;
    }
  }
  CHECK(differ == 0);
}

TEST_CASE(
    "evaluate() of a validated design gives what evaluate() gives, every field, at every "
    "fidelity") {
  // The oracle is evaluate(): for a design validate() accepts, skipping the
  // second validation changes nothing, rigid or not, given COR or derived.
  const auto bits = [](double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
  };
  const auto opt = [&](const std::optional<double>& x) {
    return x ? bits(*x) : std::uint64_t{0xDEADBEEF};
  };
  // Every number of the evaluation as its bits, absent ones marked.
  const auto fields = [&](const Evaluation& e) {
    return std::vector<std::uint64_t>{bits(e.length_m),
                                      bits(e.mass_kg),
                                      bits(e.balance_from_butt_m),
                                      bits(e.I_cm_kg_m2),
                                      bits(e.swingweight_kg_m2),
                                      bits(e.impact_from_butt_m),
                                      bits(e.impact_from_com_m),
                                      opt(e.cop_free_from_butt_m),
                                      opt(e.rotation_axis_free_from_butt_m),
                                      bits(e.effective_mass_kg),
                                      bits(e.apparent_cor),
                                      bits(e.rebound_speed_m_s),
                                      bits(e.impulse_N_s),
                                      bits(e.peak_impact_force_N),
                                      bits(e.system_mass_kg),
                                      bits(e.system_com_from_butt_m),
                                      bits(e.system_I_cm_kg_m2),
                                      opt(e.cop_hand_from_butt_m),
                                      opt(e.rotation_axis_hand_from_butt_m),
                                      bits(e.wrist_force_ratio),
                                      bits(e.peak_wrist_force_N),
                                      bits(e.impact_off_axis_m),
                                      opt(e.polar_inertia_kg_m2),
                                      bits(e.twist_rate_rad_s),
                                      bits(e.peak_twist_torque_N_m),
                                      bits(e.cor),
                                      bits(e.impact_duration_s),
                                      opt(e.vibration_energy_J),
                                      opt(e.vibration_share),
                                      e.modal ? bits(e.modal->fundamental_free_Hz) : 0,
                                      e.modal ? opt(e.modal->node_hand_from_butt_m) : 0,
                                      std::uint64_t{e.cor_derived},
                                      std::uint64_t{e.impact_duration_derived},
                                      std::uint64_t{e.polar_inertia_estimated}};
  };
  const auto same = [&](const Evaluation& a, const Evaluation& b) {
    return fields(a) == fields(b);
  };
  for (const TableRow& row : kTableI) {
    Design d = table_design(row);
    CHECK(same(evaluate(d, Fidelity::kRigid, {.validated = true}), evaluate(d, Fidelity::kRigid)));
    d.twistweight_kg_m2 = 15e-4;
    d.impact_off_axis_m = 0.03;
    CHECK(same(evaluate(d, Fidelity::kRigid, {.validated = true}), evaluate(d, Fidelity::kRigid)));
  }
  Design strung = table_design(kTableI[0]);
  strung.strings = StringBed{};
  CHECK(same(evaluate(strung, Fidelity::kRigid, {.validated = true}),
             evaluate(strung, Fidelity::kRigid)));
  CHECK(evaluate(strung, Fidelity::kRigid, {.validated = true}).impact_duration_derived);
  Design stiff = table_design(kTableI[1]);
  stiff.stiffness.EI_N_m2 = 152.0;
  CHECK(same(evaluate(stiff, Fidelity::kModal, {.validated = true}),
             evaluate(stiff, Fidelity::kModal)));
  stiff.cor_rigid = 0.85;
  CHECK(same(evaluate(stiff, Fidelity::kResponse, {.validated = true}),
             evaluate(stiff, Fidelity::kResponse)));
  CHECK_THROWS_WITH(evaluate(stiff, Fidelity::kRigid, {.validated = true}),
                    Catch::StartsWith("frame/cor_rigid"));
}

TEST_CASE("Rigid cases refuse a derived COR, a bad design and a short output span") {
  Design derived = table_design(kTableI[0]);
  derived.cor_rigid = 0.85;
  CHECK_THROWS_WITH(rigid_case(derived), Catch::Contains("frame/cor_rigid"));
  Design bad = table_design(kTableI[0]);
  bad.ball.speed_m_s = -1.0;
  CHECK_THROWS_WITH(rigid_case(bad), Catch::Contains("ball/speed_m_s"));
  const std::vector<RigidCase> cases(3, rigid_case(table_design(kTableI[0])));
  std::vector<RigidOutcome> out(2);
  CHECK_THROWS_WITH(rigid_outcomes(cases, out), Catch::Contains("3 cases but room for 2"));
}

}  // namespace
}  // namespace sweetspot

namespace sweetspot {
namespace {

// Energy ledger of the response model (impact_response.hpp, derived COR).
constexpr double kLedgerRoundOff = 1e-12;

TEST_CASE("The frame never keeps more energy than the ball loses, from 0.3 to 100 m") {
  int refused = 0, answered = 0;
  for (const double length : {0.3, 0.5, 0.7, 1.0, 2.0, 5.0, 10.0, 30.0, 100.0}) {
    for (const bool derived : {true, false}) {
      INFO(length << " m, " << (derived ? "cor_rigid 0.85" : "cor 0.8"));
      Design d{Implement::from_sections({Section{length, 0.25, {}}}, {})};
      d.stiffness.EI_N_m2 = 152.0;
      d.impact_from_butt_m = length - 0.05;
      d.hand.center_from_butt_m = 0.07;
      if (derived) d.cor_rigid = 0.85;
      try {
        const Evaluation e = evaluate(d, Fidelity::kResponse);
        ++answered;
        const double v1 = d.ball.speed_m_s;
        const double incident = 0.5 * d.ball.mass_kg * v1 * v1;
        const double ball_loss = incident * (1.0 - e.apparent_cor * e.apparent_cor);
        REQUIRE(e.vibration_energy_J);
        CHECK(*e.vibration_energy_J >= 0.0);
        CHECK(*e.vibration_energy_J <= ball_loss * (1.0 + kLedgerRoundOff));
        CHECK(*e.vibration_share >= 0.0);
        CHECK(*e.vibration_share <= 1.0);
        CHECK(e.cor >= 0.0);
        CHECK(e.cor <= (derived ? 0.85 : 0.8));
      } catch (const std::invalid_argument& error) {
        ++refused;
        const std::string why = error.what();
        CHECK(why.find(derived ? "frame/cor_rigid:" : "frame/cor:") == 0);
        CHECK(why.find("does not hold") != std::string::npos);
      }
    }
  }
  // The racquet-sized frames are answered, the long soft ones refused.
  CHECK(answered >= 4);
  CHECK(refused >= 4);
}

TEST_CASE(
    "A derived COR at the edge of the model's validity falls to 0 continuously, never below") {
  // e^2 + a (1 + e)^2 = e_r^2: as a = mu kappa rises to e_r^2, e falls to 0.
  Design d{Implement::from_sections({Section{0.7, 0.25, {}}}, {})};
  d.stiffness.EI_N_m2 = 152.0;
  d.cor_rigid = 0.85;
  double previous = 0.85;
  for (const double EI : {152.0, 100.0, 70.0, 50.0}) {
    d.stiffness.EI_N_m2 = EI;
    try {
      const Evaluation e = evaluate(d, Fidelity::kResponse);
      CHECK(e.cor < previous);
      CHECK(e.cor >= 0.0);
      previous = e.cor;
    } catch (const std::invalid_argument& error) {
      CHECK(std::string(error.what()).find("frame/cor_rigid:") == 0);
    }
  }
}

}  // namespace
}  // namespace sweetspot

namespace sweetspot {

TEST_CASE("The solved collision's peak ball compression stays below a rigid wall's closed form") {
  // A ball of law F = k x^n (+ damping, which only takes energy) stores at
  // most its incident kinetic energy: k x^(n+1) / (n+1) <= m v^2 / 2, so its
  // compression is at most that against an immovable wall,
  // x_wall = ((n+1) m v^2 / (2k))^(1/(n+1)); on strings it is less.
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  d.stiffness.RA = 66.0;
  d.strings = StringBed{};
  d.cor_given = false;
  const BallContactLaw& law = d.ball_contact;
  for (const double from_tip : {0.10, 0.17, 0.25}) {
    for (const double speed : {10.0, 30.0, 50.0}) {
      d.impact_from_butt_m = d.implement.length_m() - from_tip;
      d.ball.speed_m_s = speed;
      const Evaluation e = evaluate(d, Fidelity::kCollision);
      REQUIRE(e.details);
      REQUIRE(e.details->collision);
      const CollisionResult& r = *e.details->collision;
      const double n = law.exponent;
      const double x_wall = std::pow(
          (n + 1.0) * d.ball.mass_kg * speed * speed / (2.0 * law.stiffness), 1.0 / (n + 1));
      INFO(from_tip << " m from the tip at " << speed << " m/s");
      CHECK(r.peak_ball_compression_m > 0.0);
      CHECK(r.peak_ball_compression_m < x_wall);
      CHECK(r.peak_string_deflection_m > 0.0);
    }
  }
}

}  // namespace sweetspot

namespace sweetspot {

TEST_CASE("An evaluation records the fidelity that answered it") {
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  d.stiffness.RA = 66.0;
  for (const Fidelity f : {Fidelity::kRigid, Fidelity::kModal, Fidelity::kResponse}) {
    const Evaluation e = evaluate(d, f);
    CHECK(e.fidelity == f);
    CHECK(fidelity_of(e) == f);
    CHECK(e.modal.has_value() == (f != Fidelity::kRigid));
    CHECK(e.vibration_energy_J.has_value() == (f == Fidelity::kResponse));
  }
  d.strings = StringBed{};
  d.cor_given = false;
  const Evaluation solved = evaluate(d, Fidelity::kCollision);
  CHECK(solved.fidelity == Fidelity::kCollision);
  CHECK((solved.details && solved.details->collision));
  CHECK(evaluate(d, resolve_fidelity("auto", d)).fidelity == Fidelity::kCollision);
}

}  // namespace sweetspot

namespace sweetspot {

TEST_CASE("Paper racquets column-wise: every case answered is evaluate()'s, bit for bit") {
  // The oracle is evaluate() of the design built as the reader builds it
  // (Implement::paper_racquet): a case the column-wise kernel answers must be
  // one evaluate() answers with the same numbers; a case evaluate() refuses
  // must be left to it. Random cases in and well beyond the model's range,
  // with the values the checks turn on (0, the bounds, NaN, infinities).
  std::mt19937_64 random(2004);
  const auto pick = [&](std::initializer_list<double> specials, double lo, double hi) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(random) < 0.15) {
      std::uniform_int_distribution<std::size_t> k(0, specials.size() - 1);
      return *(specials.begin() + k(random));
    }
    return lo + (hi - lo) * u(random);
  };
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr std::size_t n = 20000;
  std::vector<std::vector<double>> in(11, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double L = pick({0.0, -0.7, 1e-3, 100.0, 101.0, nan, inf}, 0.2, 1.2);
    in[0][i] = L;
    in[1][i] = pick({0.0, 1e-3, 9e-4, 1e6, 2e6, -0.3, nan}, 0.05, 1.5);
    in[2][i] = pick({0.0, 1e-6, 1e-7, 1e6, 1e7, -1.0, inf}, 0.1, 3.0);
    in[3][i] = pick({0.0, -0.1, 1e6, 2e6, nan}, 0.0, 1.0);
    in[4][i] = pick({0.0, -0.01, L, 2.0 * L, nan}, 0.0, 0.2);
    in[5][i] = pick({0.0, -1.0, 1e12, 2e12, nan}, 0.0, 2.0);
    in[6][i] = pick({1e-4, 5e-5, 1e6, 0.0, nan}, 0.03, 0.2);
    in[7][i] = pick({1e-3, 1e-4, 1e4, 2e4, 0.0, inf}, 5.0, 70.0);
    in[8][i] = pick({0.0, 1.0, 1.0000001, -0.1, nan}, 0.3, 1.0);
    in[9][i] = pick({1e-9, 1e-10, 10.0, 11.0, 0.0, nan}, 0.002, 0.008);
    in[10][i] = pick({0.0, L, -1e-9, L * 1.01, nan}, 0.0, L);
  }
  std::vector<std::vector<double>> out(7, std::vector<double>(n));
  std::vector<unsigned char> answered(n);
  paper_rigid_outcomes(
      PaperRigidCases{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8], in[9], in[10]},
      RigidOutcomes{out[0], out[1], out[2], out[3], out[4], out[5], out[6]}, answered);
  std::size_t answers = 0, refusals = 0;
  for (std::size_t i = 0; i < n; ++i) {
    INFO("case " << i << ": L " << in[0][i] << ", M " << in[1][i] << ", r " << in[2][i]);
    std::optional<Evaluation> e;
    try {
      e = evaluate(Design{Implement::paper_racquet(in[0][i], in[1][i], in[2][i]), in[8][i],
                          in[9][i], Hand{in[3][i], in[4][i]}, in[5][i], Ball{in[6][i], in[7][i]},
                          in[10][i]});
    } catch (const std::exception& error) {
      ++refusals;
      INFO("evaluate() refuses it: " << error.what());
      CHECK(!answered[i]);
    }
    if (!answered[i]) continue;
    ++answers;
    REQUIRE(e);
    CHECK(out[0][i] == e->effective_mass_kg);
    CHECK(out[1][i] == e->apparent_cor);
    CHECK(out[2][i] == e->impulse_N_s);
    CHECK(out[3][i] == e->peak_impact_force_N);
    CHECK(out[4][i] == e->cop_hand_from_butt_m.value());
    CHECK(out[5][i] == e->wrist_force_ratio);
    CHECK(out[6][i] == e->peak_wrist_force_N);
  }
  // Both kinds of case are drawn often enough for the test to mean something.
  CHECK(answers > n / 10);
  CHECK(refusals > n / 10);
}

TEST_CASE("paper_rigid_outcomes: a setting given once is that setting in every case, bit for bit") {
  std::mt19937_64 random(1861);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr std::size_t n = 3001;  // not a whole number of blocks
  std::vector<double> L(n), M(n), r(n), x(n);
  for (std::size_t i = 0; i < n; ++i) {
    L[i] = 0.3 + 0.9 * u(random);
    M[i] = i % 97 == 0 ? -0.3 : 0.05 + 1.4 * u(random);  // some cases refused
    r[i] = 0.1 + 2.9 * u(random);
    x[i] = i % 89 == 0 ? 1.01 * L[i] : L[i] * u(random);
  }
  // hand mass, hand place, forearm, ball mass, ball speed, COR, duration: the
  // paper's, then each out of its range once (every case left to evaluate()).
  const std::vector<std::array<double, 7>> settings = {
      {0.3, 0.07, 0.5, 0.057, 50.0, 0.8, 0.004},       {0.0, 0.0, 0.0, 0.16, 5.0, 1.0, 0.001},
      {-0.1, 0.07, 0.5, 0.057, 50.0, 0.8, 0.004},      {0.3, 0.07, 2e12, 0.057, 50.0, 0.8, 0.004},
      {0.3, 0.07, 0.5, 0.0, 50.0, 0.8, 0.004},         {0.3, 0.07, 0.5, 0.057, 2e4, 0.8, 0.004},
      {0.3, 0.07, 0.5, 0.057, 50.0, 1.0000001, 0.004}, {0.3, 0.07, 0.5, 0.057, 50.0, 0.8, 0.0}};
  for (const auto& s : settings) {
    INFO("settings " << s[0] << ' ' << s[1] << ' ' << s[2] << ' ' << s[3] << ' ' << s[4] << ' '
                     << s[5] << ' ' << s[6]);
    std::vector<std::vector<double>> each(7);
    std::vector<std::vector<double>> once(7);
    for (std::size_t k = 0; k < 7; ++k) {
      each[k].assign(n, s[k]);
      once[k].assign(1, s[k]);
    }
    const auto run = [&](const std::vector<std::vector<double>>& given,
                         std::vector<std::vector<double>>& out, std::vector<unsigned char>& ok) {
      out.assign(7, std::vector<double>(n));
      ok.assign(n, 2);
      paper_rigid_outcomes(PaperRigidCases{L, M, r, given[0], given[1], given[2], given[3],
                                           given[4], given[5], given[6], x},
                           RigidOutcomes{out[0], out[1], out[2], out[3], out[4], out[5], out[6]},
                           ok);
    };
    std::vector<std::vector<double>> by_case, by_once, by_mixed;
    std::vector<unsigned char> ok_case, ok_once, ok_mixed;
    run(each, by_case, ok_case);
    run(once, by_once, ok_once);
    std::vector<std::vector<double>> mixed = once;
    mixed[4] = each[4];  // the ball's speed per case, the rest once
    run(mixed, by_mixed, ok_mixed);
    CHECK(ok_once == ok_case);
    CHECK(ok_mixed == ok_case);
    std::size_t answered = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!ok_case[i]) continue;
      ++answered;
      for (std::size_t k = 0; k < 7; ++k) {
        INFO("case " << i << ", output " << k);
        CHECK(std::bit_cast<std::uint64_t>(by_once[k][i]) ==
              std::bit_cast<std::uint64_t>(by_case[k][i]));
        CHECK(std::bit_cast<std::uint64_t>(by_mixed[k][i]) ==
              std::bit_cast<std::uint64_t>(by_case[k][i]));
      }
    }
    const bool valid =
        s[0] >= 0.0 && s[2] < 1e12 && s[3] > 0.0 && s[4] < 1e4 && s[5] <= 1.0 && s[6] > 0.0;
    if (valid) {
      CHECK(answered > n / 2);
      CHECK(answered < n);  // the cases drawn to be refused are
    } else {
      CHECK(answered == 0);
    }
  }
  // A setting's span holds one value or one per case.
  std::vector<double> two(2, 0.3), one(1, 0.3), out(n);
  std::vector<unsigned char> ok(n);
  CHECK_THROWS_AS(
      paper_rigid_outcomes(PaperRigidCases{L, M, r, two, one, one, one, one, one, one, x},
                           RigidOutcomes{out, out, out, out, out, out, out}, ok),
      std::invalid_argument);
}

}  // namespace sweetspot
