// The second dimension: the head as an ellipse, clock positions, the polar
// inertia, and the twist term of the effective mass. Oracles: the ellipse's
// area, the parallel-axis sum m y^2, the impulse-momentum equations of a free
// rigid body (which give M_eff independently of the formula), and the
// identity that an impact on the axis is exactly today's model.
#include "sweetspot/head_geometry.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <vector>

#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/kernels.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot {
namespace {

constexpr double kRoundOff = 1e-12;  // relative, for sums of a few terms

// A wooden rod tapering from 4 cm to 8 cm across over 80 cm: a bat's shape,
// at most 4 cm of radius.
RoundProfile tapered_rod() { return {{{0.0, 0.04}, {0.8, 0.08}}, 650.0, 1.2e10}; }
constexpr double kSquareInch_m2 = 0.0254 * 0.0254;

// A 27 in racquet of 320 g, 100 in^2 head, Table I's player and ball.
Design racquet_design() {
  Design d{Implement::paper_racquet(0.6858, 0.320, 1.0)};
  d.head = HeadShape{100.0 * kSquareInch_m2};
  d.impact_from_butt_m = 0.6858 - 0.16;
  return d;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST_CASE(
    "The string bed's ellipse has the head's area, its aspect and its end a hoop below the tip") {
  const HeadShape head{100.0 * kSquareInch_m2, 1.35, 0.015};
  const HeadEllipse bed = string_bed(head, 0.6858);
  CHECK(std::numbers::pi * bed.semi_length_m * bed.semi_width_m ==
        Approx(head.area_m2).epsilon(kRoundOff));
  CHECK(bed.semi_length_m / bed.semi_width_m == Approx(1.35).epsilon(kRoundOff));
  CHECK(bed.center_from_butt_m + bed.semi_length_m == Approx(0.6858 - 0.015).epsilon(kRoundOff));
  CHECK(on_string_bed(bed, bed.center_from_butt_m, 0.0));
  CHECK_FALSE(on_string_bed(bed, bed.center_from_butt_m, 1.01 * bed.semi_width_m));
}

TEST_CASE("Clock positions: 12 at the tip's hoop, 6 at the throat, 3 and 9 on the sides") {
  const HeadShape head{100.0 * kSquareInch_m2};
  const double L = 0.6858;
  const HeadEllipse bed = string_bed(head, L);
  const double A = bed.semi_length_m + 0.5 * head.hoop_width_m;
  const double C = bed.semi_width_m + 0.5 * head.hoop_width_m;
  const FacePoint twelve = clock_position(head, L, 12.0);
  CHECK(twelve.from_butt_m == Approx(L - 0.5 * head.hoop_width_m).epsilon(kRoundOff));
  CHECK(twelve.off_axis_m == 0.0);
  CHECK(clock_position(head, L, 0.0).from_butt_m == twelve.from_butt_m);
  const FacePoint six = clock_position(head, L, 6.0);
  CHECK(six.from_butt_m == Approx(bed.center_from_butt_m - A).epsilon(kRoundOff));
  const FacePoint three = clock_position(head, L, 3.0), nine = clock_position(head, L, 9.0);
  CHECK(three.off_axis_m == C);
  CHECK(nine.off_axis_m == -C);
  CHECK(three.from_butt_m == bed.center_from_butt_m);
  // 2 and 10 mirror each other and lie on the hoop's ellipse.
  const FacePoint two = clock_position(head, L, 2.0), ten = clock_position(head, L, 10.0);
  CHECK(two.from_butt_m == Approx(ten.from_butt_m).epsilon(kRoundOff));
  CHECK(two.off_axis_m == Approx(-ten.off_axis_m).epsilon(kRoundOff));
  CHECK(two.off_axis_m > 0.0);
  const double u = (two.from_butt_m - bed.center_from_butt_m) / A, v = two.off_axis_m / C;
  CHECK(u * u + v * v == Approx(1.0).epsilon(kRoundOff));
  CHECK_THROWS_WITH(clock_position(head, L, 13.0), Catch::Contains("clock"));
}

TEST_CASE("A head longer than the implement is refused, naming the head size") {
  CHECK_THROWS_WITH(string_bed(HeadShape{100.0 * kSquareInch_m2}, 0.30),
                    Catch::StartsWith("headsize"));
  CHECK_THROWS_WITH(string_bed(HeadShape{-1.0}, 0.70), Catch::StartsWith("headsize"));
}

TEST_CASE(
    "The polar estimate of a round head with a thin hoop is M R^2 / 4 plus the strings' m R^2 / "
    "4") {
  // A circle (aspect 1, no hoop width): the mean of y^2 round a circle is R^2 / 2.
  const HeadShape round{0.06, 1.0, 0.0};
  const double R = std::sqrt(0.06 / std::numbers::pi);
  const double M = 0.3;
  const double expected = kHoopMassShare * M * R * R / 2.0 + kStringSetMass_kg * R * R / 4.0;
  CHECK(estimated_polar_inertia_kg_m2(round, 0.7, M) == Approx(expected).epsilon(1e-12));
}

TEST_CASE("The estimate of a typical 100 in^2, 320 g racquet lies among retailer twistweights") {
  // Retailer spec sheets list 13-16 kg cm^2 for 300-340 g, 98-100 in^2 racquets.
  const double I = estimated_polar_inertia_kg_m2(HeadShape{100.0 * kSquareInch_m2}, 0.6858, 0.32);
  CHECK(I * 1e4 > 13.0);
  CHECK(I * 1e4 < 17.0);
}

TEST_CASE("A lead pair at 3 and 9 o'clock raises the polar inertia by exactly 2 m r^2") {
  Design bare = racquet_design();
  bare.twistweight_kg_m2 = 14.5e-4;
  const double m = 0.002;
  const FacePoint three = clock_position(*bare.head, 0.6858, 3.0);
  const FacePoint nine = clock_position(*bare.head, 0.6858, 9.0);
  Design taped = bare;
  taped.implement = Implement::paper_racquet(0.6858, 0.320, 1.0,
                                             {PointMass{three.from_butt_m, m, three.off_axis_m},
                                              PointMass{nine.from_butt_m, m, nine.off_axis_m}});
  const double r = three.off_axis_m;
  CHECK(*polar_inertia_kg_m2(taped) - *polar_inertia_kg_m2(bare) ==
        Approx(2.0 * m * r * r).epsilon(kRoundOff));
  // The same with the polar inertia estimated from the head (the frame's mass is unchanged).
  bare.twistweight_kg_m2.reset();
  taped.twistweight_kg_m2.reset();
  CHECK(polar_inertia_estimated(taped));
  CHECK(*polar_inertia_kg_m2(taped) - *polar_inertia_kg_m2(bare) ==
        Approx(2.0 * m * r * r).epsilon(kRoundOff));
  // Lead at 12 o'clock is on the axis: it leaves the polar inertia alone.
  const FacePoint twelve = clock_position(*bare.head, 0.6858, 12.0);
  Design tip = bare;
  tip.implement = Implement::paper_racquet(
      0.6858, 0.320, 1.0, {PointMass{twelve.from_butt_m, 0.01, twelve.off_axis_m}});
  CHECK(*polar_inertia_kg_m2(tip) == *polar_inertia_kg_m2(bare));
}

TEST_CASE("M_eff off the axis is the impulse over the impact point's speed of a free rigid body") {
  // Impulse-momentum for a free body kicked by J at (b, y): V = J/M, w = J b / I_cm
  // (Eqs. 1-2), w_roll = J y / I_polar; the impact point moves at V + w b + w_roll y,
  // and M_eff = J / v. Kinetic energy is J^2 / (2 M_eff).
  const MassProperties body{0.32, 0.34, 0.015};
  const double I_polar = 14e-4;
  for (const double x : {0.40, 0.52, 0.60}) {
    for (const double y : {-0.08, -0.02, 0.03, 0.1}) {
      INFO("x = " << x << ", y = " << y);
      const double J = 1.0;
      const RigidKick kick = free_kick(body, x);
      const double b = x - body.com_from_butt_m;
      const double roll = J * y / I_polar;
      const double v =
          J * kick.com_velocity_per_impulse + J * kick.angular_velocity_per_impulse * b + roll * y;
      const double M_eff = effective_mass(body, x, y, I_polar);
      CHECK(M_eff == Approx(J / v).epsilon(kRoundOff));
      const double kinetic = 0.5 * body.mass_kg * std::pow(J / body.mass_kg, 2) +
                             0.5 * body.I_cm_kg_m2 * std::pow(J * b / body.I_cm_kg_m2, 2) +
                             0.5 * I_polar * roll * roll;
      CHECK(kinetic == Approx(J * J / (2.0 * M_eff)).epsilon(kRoundOff));
      CHECK(M_eff < effective_mass(body, x));
    }
  }
}

TEST_CASE("On the axis every output is today's, bit for bit, whatever the head and twistweight") {
  Design plain{Implement::paper_racquet(0.70, 0.25, 0.8)};
  Design twisted = plain;
  twisted.head = HeadShape{0.06};
  twisted.twistweight_kg_m2 = 15e-4;
  for (const bool tension : {false, true}) {
    INFO("string tension: " << tension);
    if (tension) {
      plain.strings = StringBed{};
      twisted.strings = StringBed{};
    }
    const Evaluation a = evaluate(plain), b = evaluate(twisted);
    for (const auto& [x, y] : {std::pair{a.effective_mass_kg, b.effective_mass_kg},
                               {a.apparent_cor, b.apparent_cor},
                               {a.impulse_N_s, b.impulse_N_s},
                               {a.peak_impact_force_N, b.peak_impact_force_N},
                               {a.impact_duration_s, b.impact_duration_s},
                               {a.wrist_force_ratio, b.wrist_force_ratio},
                               {a.peak_wrist_force_N, b.peak_wrist_force_N}}) {
      CHECK(same_bits(x, y));
    }
    CHECK_FALSE(a.polar_inertia_kg_m2);
    CHECK(*b.polar_inertia_kg_m2 == 15e-4);
    CHECK(b.twist_rate_rad_s == 0.0);
    CHECK(b.peak_twist_torque_N_m == 0.0);
  }
}

TEST_CASE("An impact off the axis lowers M_eff, e_A and F0 through the twist, evenly in y") {
  Design d = racquet_design();
  d.twistweight_kg_m2 = 14e-4;
  const Evaluation centre = evaluate(d);
  d.impact_off_axis_m = 0.05;
  const Evaluation right = evaluate(d);
  d.impact_off_axis_m = -0.05;
  const Evaluation left = evaluate(d);
  const double expected =
      1.0 / (1.0 / centre.effective_mass_kg + 0.05 * 0.05 / 14e-4);  // 1/M_eff adds y^2/I_polar
  CHECK(right.effective_mass_kg == Approx(expected).epsilon(kRoundOff));
  CHECK(right.apparent_cor == Approx(apparent_cor(0.8, expected, 0.057)).epsilon(kRoundOff));
  CHECK(right.apparent_cor < centre.apparent_cor);
  CHECK(right.peak_impact_force_N < centre.peak_impact_force_N);
  CHECK(same_bits(right.effective_mass_kg, left.effective_mass_kg));
  CHECK(same_bits(right.peak_wrist_force_N, left.peak_wrist_force_N));
  // The handle rolls at J y / I_polar, one way or the other; the torque is F0 |y|.
  CHECK(right.twist_rate_rad_s == Approx(right.impulse_N_s * 0.05 / 14e-4).epsilon(kRoundOff));
  CHECK(left.twist_rate_rad_s == -right.twist_rate_rad_s);
  CHECK(right.peak_twist_torque_N_m == Approx(right.peak_impact_force_N * 0.05).epsilon(kRoundOff));
  // The wrist force's share of F0 is Eq. (11), unchanged by the twist.
  CHECK(right.wrist_force_ratio == centre.wrist_force_ratio);
}

TEST_CASE("A string tension sets the duration from the twisted effective mass") {
  Design d = racquet_design();
  d.twistweight_kg_m2 = 14e-4;
  d.strings = StringBed{};
  d.impact_off_axis_m = 0.06;
  const Evaluation e = evaluate(d);
  const double M_eff =
      effective_mass(d.implement.mass_properties(), d.impact_from_butt_m, 0.06, 14e-4);
  CHECK(e.impact_duration_s ==
        Approx(tension_impact_duration(*d.strings, d.ball.mass_kg, M_eff).duration_s)
            .epsilon(kRoundOff));
}

TEST_CASE("An impact off the axis without a polar inertia is refused, naming impact/off_axis_m") {
  Design d{Implement::paper_racquet(0.70, 0.25, 0.8)};
  d.impact_off_axis_m = 0.03;
  CHECK_THROWS_WITH(evaluate(d), Catch::StartsWith("impact/off_axis_m"));
  d.impact_off_axis_m = 2.0;  // off an implement 0.7 m long
  d.twistweight_kg_m2 = 14e-4;
  CHECK_THROWS_WITH(evaluate(d), Catch::StartsWith("impact/off_axis_m"));
}

// The upper edge of the convex hull of `points` at x: the highest point of
// every segment between two of them that spans x (brute force, O(n^2)).
double hull_top(const std::vector<FacePoint>& points, double x) {
  double top = -1.0;
  for (const FacePoint& a : points) {
    for (const FacePoint& b : points) {
      if (a.from_butt_m <= x && x <= b.from_butt_m && a.from_butt_m < b.from_butt_m) {
        const double t = (x - a.from_butt_m) / (b.from_butt_m - a.from_butt_m);
        top = std::max(top, a.off_axis_m + t * (b.off_axis_m - a.off_axis_m));
      }
    }
  }
  return top;
}

TEST_CASE(
    "A racquet's outline is its handle, the hull of the handle's end and the hoop, and 0 off it") {
  const double L = 0.6858;
  const HeadShape head{100.0 * kSquareInch_m2};
  const HeadEllipse bed = string_bed(head, L);
  const double A = bed.semi_length_m + head.hoop_width_m;
  const double C = bed.semi_width_m + head.hoop_width_m;
  // The largest grip's octagon, 4 3/4 in around: its corners' circumradius.
  const double side = 4.75 * 0.0254 / 8.0;
  const double grip = side / (2.0 * std::sin(std::numbers::pi / 8.0));
  CHECK(face_half_width_m(head, L, 0.0) == Approx(grip).epsilon(kRoundOff));
  CHECK(face_half_width_m(head, L, kHandleLength_m) == Approx(grip).epsilon(kRoundOff));
  CHECK(face_half_width_m(head, L, bed.center_from_butt_m) == Approx(C).epsilon(kRoundOff));
  CHECK(face_half_width_m(head, L, L) == Approx(0.0).margin(1e-6));
  CHECK(face_half_width_m(head, L, -0.01) == 0.0);
  CHECK(face_half_width_m(head, L, L + 0.01) == 0.0);
  // Beyond the handle, the convex hull of the handle's end and the hoop's
  // outer edge, sampled densely: the tangent's closed form against brute force.
  std::vector<FacePoint> hull{{kHandleLength_m, grip}, {kHandleLength_m, -grip}};
  constexpr int kSamples = 2000;
  for (int i = 0; i < kSamples; ++i) {
    const double t = 2.0 * std::numbers::pi * i / kSamples;
    hull.push_back({bed.center_from_butt_m + A * std::cos(t), C * std::sin(t)});
  }
  for (double x = kHandleLength_m + 0.005; x < L - 0.005; x += 0.01) {
    INFO("x = " << x);
    // The sampled polygon lies inside the ellipse: within its chord's sagitta.
    CHECK(face_half_width_m(head, L, x) == Approx(hull_top(hull, x)).margin(2e-6));
  }
}

TEST_CASE(
    "Lead sits where it is put: a racquet's handle, throat or hoop, a round implement's radius") {
  Design d = racquet_design();
  const double L = d.implement.length_m();
  const auto with_lead = [&](double from_butt_m, double off_axis_m) {
    Design lead = d;
    lead.implement = Implement::paper_racquet(L, 0.320, 1.0, {{from_butt_m, 0.005, off_axis_m}});
    return lead;
  };
  const double grip = face_half_width_m(*d.head, L, 0.02);
  CHECK_NOTHROW(evaluate(with_lead(0.02, 0.99 * grip), Fidelity::kRigid));
  CHECK_THROWS_WITH(evaluate(with_lead(0.02, 1.01 * grip), Fidelity::kRigid),
                    Catch::StartsWith("implement/point_masses/0/off_axis_m: must be in") &&
                        Catch::Contains("its handle, as wide as the largest grip"));
  const FacePoint three = clock_position(*d.head, L, 3.0);
  CHECK_NOTHROW(evaluate(with_lead(three.from_butt_m, three.off_axis_m), Fidelity::kRigid));
  // At its widest, the hoop's outer edge: the string bed's semi-width and the hoop.
  const HeadEllipse bed = string_bed(*d.head, L);
  const double edge = bed.semi_width_m + d.head->hoop_width_m;
  CHECK_NOTHROW(evaluate(with_lead(bed.center_from_butt_m, -0.999 * edge), Fidelity::kRigid));
  CHECK_THROWS_WITH(evaluate(with_lead(bed.center_from_butt_m, -1.001 * edge), Fidelity::kRigid),
                    Catch::StartsWith("implement/point_masses/0/off_axis_m"));
  // Without a head: the largest head the rules allow, 12.5 in across its frame.
  d.head.reset();
  CHECK_THROWS_WITH(evaluate(with_lead(0.02, 0.138), Fidelity::kRigid),
                    Catch::Contains("the largest hoop the rules allow"));
  const HeadEllipse legal = string_bed(kLargestLegalHead, L);
  CHECK(legal.semi_width_m + kLargestLegalHead.hoop_width_m == Approx(6.25 * 0.0254));
  CHECK_NOTHROW(
      evaluate(with_lead(legal.center_from_butt_m, 0.999 * 6.25 * 0.0254), Fidelity::kRigid));
  CHECK_THROWS_WITH(
      evaluate(with_lead(legal.center_from_butt_m, 1.001 * 6.25 * 0.0254), Fidelity::kRigid),
      Catch::StartsWith("implement/point_masses/0/off_axis_m"));
  // A round implement: its radius where the lead sits, 2 cm at the butt and
  // 3.5 cm at 0.6 m of the rod tapering from 4 to 8 cm across.
  CHECK(profile_diameter_m(tapered_rod(), 0.6) == Approx(0.07).epsilon(kRoundOff));
  CHECK(profile_diameter_m(tapered_rod(), 0.9) == 0.0);
  Design rod{Implement::from_profile(tapered_rod(), {{0.6, 0.005, 0.0349}})};
  rod.impact_from_butt_m = 0.7;
  CHECK_NOTHROW(evaluate(rod, Fidelity::kRigid));
  rod.implement = Implement::from_profile(tapered_rod(), {{0.0, 0.005, 0.0201}});
  CHECK_THROWS_WITH(evaluate(rod, Fidelity::kRigid),
                    Catch::Contains("its radius there") && Catch::Contains("0.02]"));
}

TEST_CASE("A head ends beyond the hand, and off the axis a ball lands on the largest legal head") {
  Design d = racquet_design();
  const double L = d.implement.length_m();
  // The largest head of its aspect whose hoop ends at the hand: 2 (a + w) = L - hand.
  const double a = 0.5 * (L - d.hand.center_from_butt_m) - d.head->hoop_width_m;
  const double largest_m2 = std::numbers::pi * a * a / d.head->aspect_ratio;
  d.head->area_m2 = 0.999 * largest_m2;
  CHECK_NOTHROW(evaluate(d, Fidelity::kRigid));
  d.head->area_m2 = 1.001 * largest_m2;
  try {
    evaluate(d, Fidelity::kRigid);
    FAIL("a head over the hand was accepted");
  } catch (const FieldError& error) {
    CHECK(error.field() == "implement/headsize");
    REQUIRE(error.range());
    CHECK(error.range()->max == Approx(largest_m2).epsilon(kRoundOff));
  }
  // Without a head, a twistweight: the largest head the rules allow, whose
  // strung ellipse and hoop end at the tip, so nothing off the axis lands
  // at the tip or on the handle.
  d.head.reset();
  d.twistweight_kg_m2 = 15e-4;
  const HeadEllipse legal = string_bed(kLargestLegalHead, L);
  const double edge = legal.semi_width_m + kLargestLegalHead.hoop_width_m;
  d.impact_from_butt_m = legal.center_from_butt_m;
  d.impact_off_axis_m = 0.999 * edge;
  CHECK_NOTHROW(evaluate(d, Fidelity::kRigid));
  for (const double x : {L, 0.08, legal.center_from_butt_m}) {
    d.impact_from_butt_m = x;
    d.impact_off_axis_m = x == legal.center_from_butt_m ? 1.001 * edge : 0.01;
    CHECK_THROWS_WITH(evaluate(d, Fidelity::kRigid),
                      Catch::StartsWith("impact/off_axis_m: must be in") &&
                          Catch::Contains("the largest hoop the rules allow"));
  }
}

TEST_CASE("A shorter racquet's handle is shorter in proportion, and no head reaches over it") {
  // A 19 in junior: its handle is 19/27 of 18 cm, over which the largest
  // legal head, 16.5 in long with its hoop, would reach (to 6.4 cm from the butt).
  const double L = 19 * 0.0254;
  const double handle = kHandleLength_m * 19.0 / 27.0;
  const double grip = face_half_width_m(kLargestLegalHead, L, 0.0);
  CHECK(face_half_width_m(kLargestLegalHead, L, 0.999 * handle) == grip);
  CHECK(face_half_width_m(kLargestLegalHead, L, 1.001 * handle) > grip);
  CHECK(face_half_width_m(kLargestLegalHead, 27 * 0.0254, 0.999 * kHandleLength_m) == grip);
  CHECK(grip_half_width_m() == grip);
  // Without a head given, the largest legal head where it fits beyond the
  // handle (27 in), else the largest of its aspect and hoop that ends at the
  // handle (19 in), else none (an implement of 3 cm).
  const std::optional<HeadShape> full = largest_legal_head(27 * 0.0254);
  REQUIRE(full);
  CHECK(full->area_m2 == kLargestLegalHead.area_m2);
  const std::optional<HeadShape> junior = largest_legal_head(L);
  REQUIRE(junior);
  CHECK(junior->area_m2 < kLargestLegalHead.area_m2);
  CHECK(junior->aspect_ratio == kLargestLegalHead.aspect_ratio);
  const HeadEllipse bed = string_bed(*junior, L);
  CHECK(bed.center_from_butt_m - bed.semi_length_m - junior->hoop_width_m ==
        Approx(handle).epsilon(kRoundOff));
  CHECK_FALSE(largest_legal_head(0.03));
}

TEST_CASE("A round implement is not hit off its axis, and twists at most as a shell of it") {
  Design d{Implement::from_profile(tapered_rod())};
  d.impact_from_butt_m = 0.2;
  d.twistweight_kg_m2 = 2e-4;
  CHECK_NOTHROW(evaluate(d, Fidelity::kRigid));
  // Its surface's normal passes through its axis: no flat face to twist.
  d.impact_off_axis_m = 0.01;
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kRigid),
                    Catch::StartsWith("impact/off_axis_m: must be 0 on a round implement"));
  // All the mass 4 cm off the axis is the most twistweight it can have.
  const double mass = d.implement.mass_properties().mass_kg;
  d.impact_off_axis_m = 0.0;
  d.twistweight_kg_m2 = mass * 0.04 * 0.04 * 1.0001;
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kRigid),
                    Catch::StartsWith("implement/twistweight_kg_m2"));
  d.twistweight_kg_m2 = mass * 0.04 * 0.04 * 0.9999;
  CHECK_NOTHROW(evaluate(d, Fidelity::kRigid));
}

TEST_CASE("A round implement has no head, no string bed and no solved collision") {
  Design d{Implement::from_profile(tapered_rod())};
  d.impact_from_butt_m = 0.65;
  CHECK(is_round(d));
  CHECK_NOTHROW(evaluate(d, Fidelity::kModal));
  // A head would make it a racquet, and strings a racquet's hit.
  Design headed = d;
  headed.head = HeadShape{};
  CHECK_THROWS_WITH(evaluate(headed, Fidelity::kRigid),
                    Catch::StartsWith("implement/headsize: an implement given by its profile is "
                                      "round (a bat, a rod) and has no head"));
  Design strung = d;
  strung.strings = StringBed{};
  CHECK_THROWS_WITH(evaluate(strung, Fidelity::kRigid),
                    Catch::StartsWith("strings/tension_N: an implement given by its profile is "
                                      "round (a bat, a rod) and has no string bed"));
  // The solved collision is a ball on a string bed: the bat's is refused
  // naming its profile, before its frame COR.
  d.cor_given = false;
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kCollision),
                    Catch::StartsWith("implement/profile: the solved collision is a ball on a "
                                      "string bed"));
  d.cor_given = true;
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kCollision), Catch::StartsWith("implement/profile"));
  // A racquet of sections is not round.
  CHECK_FALSE(is_round(Design{Implement::paper_racquet(0.70, 0.25, 0.8)}));
}

TEST_CASE(
    "The arrays and the cases give the same twisted outcomes, and no twist given is zero twist") {
  Design d = racquet_design();
  d.twistweight_kg_m2 = 14e-4;
  d.impact_off_axis_m = 0.04;
  const RigidCase twisted = rigid_case(d);
  d.impact_off_axis_m = 0.0;
  const RigidCase straight = rigid_case(d);
  CHECK(twisted.impact_twist_per_kg == Approx(0.04 * 0.04 / 14e-4).epsilon(kRoundOff));
  const std::vector<RigidCase> cases{twisted, straight};
  std::vector<RigidOutcome> out(2);
  rigid_outcomes(cases, out);
  CHECK(same_bits(out[0].effective_mass_kg, rigid_outcome(twisted).effective_mass_kg));
  CHECK(same_bits(out[1].peak_wrist_force_N, rigid_outcome(straight).peak_wrist_force_N));
  // Structure of arrays, with and without the twist span.
  const auto column = [&](auto field) {
    return std::vector<double>{field(straight), field(straight)};
  };
  const auto M = column([](const RigidCase& c) { return c.body.mass_kg; });
  const auto cm = column([](const RigidCase& c) { return c.body.com_from_butt_m; });
  const auto I = column([](const RigidCase& c) { return c.body.I_cm_kg_m2; });
  const auto hx = column([](const RigidCase& c) { return c.hand.from_butt_m; });
  const auto hm = column([](const RigidCase& c) { return c.hand.mass_kg; });
  const auto Me = column([](const RigidCase& c) { return c.forearm_equivalent_mass_kg; });
  const auto bm = column([](const RigidCase& c) { return c.ball_mass_kg; });
  const auto bv = column([](const RigidCase& c) { return c.ball_speed_m_s; });
  const auto e = column([](const RigidCase& c) { return c.cor; });
  const auto T = column([](const RigidCase& c) { return c.impact_duration_s; });
  const auto x = column([](const RigidCase& c) { return c.impact_from_butt_m; });
  const std::vector<double> twist{0.0, twisted.impact_twist_per_kg};
  std::vector<double> o[7], p[7];
  for (auto& v : o) v.assign(2, 0.0);
  for (auto& v : p) v.assign(2, 0.0);
  RigidCases without{M, cm, I, hx, hm, Me, bm, bv, e, T, x};
  RigidCases with = without;
  with.impact_twist_per_kg = twist;
  rigid_outcomes(without, RigidOutcomes{o[0], o[1], o[2], o[3], o[4], o[5], o[6]});
  rigid_outcomes(with, RigidOutcomes{p[0], p[1], p[2], p[3], p[4], p[5], p[6]});
  CHECK(same_bits(o[0][0], p[0][0]));
  CHECK(same_bits(o[6][0], p[6][0]));
  CHECK(same_bits(p[0][1], rigid_outcome(twisted).effective_mass_kg));
  CHECK(p[0][1] < o[0][1]);
}

}  // namespace
}  // namespace sweetspot
