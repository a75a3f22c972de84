// Oracles: the contact time of two masses and a spring integrated step by
// step, the membrane formula's scaling, and the inverse in tension against a
// bracketing root search.
#include "sweetspot/string_bed.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "sweetspot/implement.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/roots.hpp"

namespace sweetspot {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRoundOff = 1e-12;
// RK4 at 1e5 steps per contact, the end located by linear interpolation of the force.
constexpr double kTimeStepping = 1e-7;
constexpr double kBallMass = 0.057;

// M_eff of the Table I racquet (0.70 m, 0.25 kg, M1/M2 = 0.8) 5 cm from the tip, Eq. (17).
double table_one_effective_mass() {
  return effective_mass(Implement::paper_racquet(0.70, 0.25, 0.8).mass_properties(), 0.65);
}

// Ball (m) and implement point (M) joined by a spring k while it is compressed:
// the time from first contact until the spring is unloaded.
double stepped_contact_time(double m, double M, double k) {
  double x = 0.0, v = 1.0;  // compression and its rate (relative speed 1 m/s)
  const double mu = m * M / (m + M);
  const double h = kPi * std::sqrt(mu / k) / 1e5;
  double t = 0.0;
  auto acc = [&](double c) { return -k * c / mu; };
  while (true) {
    const double k1x = v, k1v = acc(x);
    const double k2x = v + h / 2 * k1v, k2v = acc(x + h / 2 * k1x);
    const double k3x = v + h / 2 * k2v, k3v = acc(x + h / 2 * k2x);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x);
    const double x_next = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v_next = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x_next <= 0.0 && t > 0.0) return t + h * x / (x - x_next);
    x = x_next;
    v = v_next;
    t += h;
  }
}

TEST_CASE(
    "The contact time is pi sqrt(mu / k), as two masses and a spring integrated step by step") {
  for (const double M : {0.05, 0.0710, 0.3, 1e3}) {
    for (const double k : {1e4, 2.4e4, 4e4}) {
      const double closed = spring_contact_duration(kBallMass, M, k);
      CHECK(closed ==
            Approx(kPi * std::sqrt(kBallMass * M / (kBallMass + M) / k)).epsilon(kRoundOff));
      CHECK(stepped_contact_time(kBallMass, M, k) == Approx(closed).epsilon(kTimeStepping));
    }
  }
}

TEST_CASE("The string-bed duration is pi sqrt(mu / k) with ball and strings in series") {
  const StringBed bed;
  const double M = table_one_effective_mass();
  const TensionDuration d = tension_impact_duration(bed, kBallMass, M);
  const double k_strings = 2.0 * kPi * (bed.tension_N / bed.string_spacing_m) /
                           std::log(bed.head_radius_m / bed.contact_radius_m);
  CHECK(d.string_bed_stiffness_N_m == Approx(k_strings).epsilon(kRoundOff));
  const double k = 1.0 / (1.0 / kTennisBallStiffness_N_m + 1.0 / k_strings);
  CHECK(d.stiffness_N_m == Approx(k).epsilon(kRoundOff));
  const double mu = kBallMass * M / (kBallMass + M);
  CHECK(d.reduced_mass_kg == Approx(mu).epsilon(kRoundOff));
  CHECK(d.duration_s == Approx(kPi * std::sqrt(mu / k)).epsilon(kRoundOff));
  // Defaults: ~61 kN/m of strings at 250 N, 3.6 ms 5 cm from the tip.
  CHECK(d.string_bed_stiffness_N_m == Approx(60.9e3).epsilon(1e-3));
  CHECK(d.duration_s == Approx(3.60e-3).epsilon(1e-2));
}

TEST_CASE("Membrane stiffness is proportional to tension and inverse to string spacing") {
  StringBed bed;
  const double k = string_bed_stiffness(bed);
  bed.tension_N *= 2.0;
  CHECK(string_bed_stiffness(bed) == Approx(2.0 * k).epsilon(kRoundOff));
  bed.string_spacing_m *= 2.0;
  CHECK(string_bed_stiffness(bed) == Approx(k).epsilon(kRoundOff));
  // A larger head is softer, a larger contact stiffer.
  StringBed big_head;
  big_head.head_radius_m *= 1.2;
  CHECK(string_bed_stiffness(big_head) < k);
  StringBed wide_contact;
  wide_contact.contact_radius_m *= 1.2;
  CHECK(string_bed_stiffness(wide_contact) > k);
}

TEST_CASE("Tighter strings shorten the impact, down to the ball's own contact time") {
  const double M = table_one_effective_mass();
  StringBed bed;
  double previous = 1.0;
  for (const double tension : {20.0, 50.0, 100.0, 200.0, 300.0, 1e4, 1e8}) {
    bed.tension_N = tension;
    const double T = tension_impact_duration(bed, kBallMass, M).duration_s;
    CHECK(T < previous);
    previous = T;
  }
  CHECK(previous ==
        Approx(spring_contact_duration(kBallMass, M, kTennisBallStiffness_N_m)).epsilon(1e-5));
}

TEST_CASE("The tension for a duration inverts the duration and agrees with a root search") {
  const double M = table_one_effective_mass();
  const StringBed bed;
  for (const double T : {0.0036, 0.004, 0.005, 0.006}) {
    const auto closed = tension_for_duration(bed, T, kBallMass, M);
    REQUIRE(closed);
    StringBed at = bed;
    at.tension_N = *closed;
    CHECK(tension_impact_duration(at, kBallMass, M).duration_s == Approx(T).epsilon(kRoundOff));
    const auto searched = find_root(
        [&](double tension) {
          StringBed b = bed;
          b.tension_N = tension;
          return tension_impact_duration(b, kBallMass, M).duration_s - T;
        },
        1.0, 1e5, 1e-9);
    REQUIRE(searched);
    CHECK(*searched == Approx(*closed).epsilon(1e-9));
  }
  // No tension makes the contact shorter than the ball alone allows.
  const double floor = spring_contact_duration(kBallMass, M, kTennisBallStiffness_N_m);
  CHECK_FALSE(tension_for_duration(bed, 0.999 * floor, kBallMass, M));
}

TEST_CASE("Table I's 4 ms falls at about 156 N and 6 ms at about 45 N, 5 cm from the tip") {
  // Regression values of the model with the default head and ball (see the report).
  const double M = table_one_effective_mass();
  const StringBed bed;
  CHECK(*tension_for_duration(bed, 0.004, kBallMass, M) == Approx(156.2).margin(0.5));
  CHECK(*tension_for_duration(bed, 0.006, kBallMass, M) == Approx(45.3).margin(0.5));
}

// The deflection of a square membrane (side a, tension per length N, rim
// fixed) under a point force F at its centre, averaged over the circle of
// radius r0 about it, from the double sine series of the membrane equation:
//   w(x, y) = 4 F / (N a^2) sum_{m,n odd} s_m s_n sin(m pi x/a) sin(n pi y/a)
//             / ((m pi/a)^2 + (n pi/a)^2),  s_m = sin(m pi / 2).
double square_membrane_mean_deflection(double a, double N, double F, double r0, int terms) {
  constexpr int kAngles = 16;  // the circle's mean of a smooth periodic function
  double sum = 0.0;
  for (int k = 0; k < kAngles; ++k) {
    const double phi = 2.0 * kPi * (k + 0.5) / kAngles;
    const double x = a / 2 + r0 * std::cos(phi), y = a / 2 + r0 * std::sin(phi);
    double w = 0.0;
    for (int m = 1; m <= terms; m += 2) {
      const double sm = ((m / 2) % 2 == 0 ? 1.0 : -1.0) * std::sin(m * kPi * x / a);
      for (int n = 1; n <= terms; n += 2) {
        const double sn = ((n / 2) % 2 == 0 ? 1.0 : -1.0) * std::sin(n * kPi * y / a);
        w += sm * sn / ((m * m + n * n) * kPi * kPi / (a * a));
      }
    }
    sum += 4.0 * F / (N * a * a) * w;
  }
  return sum / kAngles;
}

TEST_CASE(
    "A square membrane's stiffness lies between the model's equal-area circle and the inscribed "
    "circle's, as the Fourier series gives it") {
  // The membrane's deflection at r0 is F ln(r_c / r0) / (2 pi N), r_c the
  // square's conformal radius at its centre, which lies between its inradius
  // a/2 and its equal-area radius a/sqrt(pi) (the area theorem): the model's
  // equal-area formula is the lower bound of the exact stiffness.
  const double a = 0.254, r0 = 0.03, T = 250.0, d = 0.0165, N = T / d;
  StringBed bed;
  bed.tension_N = T;
  bed.string_spacing_m = d;
  bed.head_radius_m = a / std::sqrt(kPi);
  bed.contact_radius_m = r0;
  const double exact = 1.0 / square_membrane_mean_deflection(a, N, 1.0, r0, 801);
  const double model = string_bed_stiffness(bed);
  CHECK(exact >= model);
  CHECK(exact <= 2.0 * kPi * N / std::log(a / 2.0 / r0));
  // The conformal radius the series implies, over the side.
  const double r_c = r0 * std::exp(2.0 * kPi * N / exact);
  CHECK(r_c / a > 0.5);
  CHECK(r_c / a < 1.0 / std::sqrt(kPi));
}

TEST_CASE("A square membrane rings at sqrt(T / mu) / (2 a), and a hybrid at its separated mode") {
  // The (1,1) mode of N_m w_xx + N_c w_yy = sigma w_tt on a square of side a:
  // (2 pi f)^2 sigma = (N_m + N_c) (pi / a)^2. Equal families: Cross's
  // f = sqrt(T / (4 m L)), m = mu L, L = a.
  const double a = 0.254;
  StringBed bed;
  bed.head_radius_m = a / std::sqrt(kPi);
  CHECK(string_bed_ring_frequency(bed) ==
        Approx(std::sqrt(bed.tension_N / bed.main_linear_density_kg_m) / (2.0 * a))
            .epsilon(kRoundOff));
  bed.cross_tension_ratio = 1.1;
  bed.cross_spacing_ratio = 1.2;
  bed.cross_linear_density_kg_m = 1.8e-3;
  const double d_m = bed.string_spacing_m / std::sqrt(1.2),
               d_c = bed.string_spacing_m * std::sqrt(1.2);
  const double N_m = bed.tension_N / d_m, N_c = 1.1 * bed.tension_N / d_c;
  const double sigma = bed.main_linear_density_kg_m / d_m + 1.8e-3 / d_c;
  CHECK(string_bed_ring_frequency(bed) ==
        Approx(std::sqrt((N_m + N_c) * kPi * kPi / (a * a) / sigma) / (2.0 * kPi))
            .epsilon(kRoundOff));
  // And the stiffness is the one of tension sqrt(N_m N_c) (the scaled Laplace equation).
  StringBed plain = bed;
  plain.cross_tension_ratio = 1.0;
  plain.tension_N = std::sqrt(N_m * N_c) * bed.string_spacing_m;
  CHECK(string_bed_stiffness(bed) == Approx(string_bed_stiffness(plain)).epsilon(kRoundOff));
}

TEST_CASE("A hybrid with equal mains and crosses is the plain bed, to the bit") {
  StringBed plain;
  StringBed hybrid;
  hybrid.cross_tension_ratio = 1.0;
  hybrid.cross_spacing_ratio = 1.0;
  hybrid.cross_linear_density_kg_m = hybrid.main_linear_density_kg_m;
  CHECK(string_bed_stiffness(hybrid) == string_bed_stiffness(plain));
  CHECK(string_bed_ring_frequency(hybrid) == string_bed_ring_frequency(plain));
  CHECK(string_bed_strings_mass(hybrid) == string_bed_strings_mass(plain));
}

TEST_CASE("The tension for a stiffness or a ring, put back, gives it to round-off") {
  StringBed bed;
  bed.cross_tension_ratio = 54.0 / 52.0;
  bed.cross_spacing_ratio = 1.3;
  bed.cross_linear_density_kg_m = 1.6e-3;
  for (const double T : {60.0, 231.3, 900.0}) {
    StringBed at = bed;
    at.tension_N = T;
    CHECK(tension_for_stiffness(bed, string_bed_stiffness(at)) == Approx(T).epsilon(kRoundOff));
    CHECK(tension_for_ring(bed, string_bed_ring_frequency(at)) == Approx(T).epsilon(kRoundOff));
  }
}

TEST_CASE("A 1.30 mm nylon string weighs 1.51 g/m, a string's mass grows as its gauge squared") {
  CHECK(string_linear_density(StringMaterial::kNylon, 1.30e-3) ==
        Approx(kDefaultStringLinearDensity_kg_m).epsilon(kRoundOff));
  CHECK(kDefaultStringLinearDensity_kg_m == Approx(1.5132e-3).epsilon(1e-4));
  CHECK(string_linear_density(StringMaterial::kPolyester, 1.25e-3) /
            string_linear_density(StringMaterial::kPolyester, 1.30e-3) ==
        Approx(1.25 * 1.25 / (1.30 * 1.30)).epsilon(kRoundOff));
}

TEST_CASE("Bad string beds and masses are refused with the field's name") {
  StringBed bed;
  bed.tension_N = -1.0;
  CHECK_THROWS_WITH(string_bed_stiffness(bed), Catch::Contains("bed.tension_N"));
  bed = StringBed{};
  bed.head_radius_m = 0.02;
  CHECK_THROWS_WITH(string_bed_stiffness(bed), Catch::Contains("bed.head_radius_m"));
  CHECK_THROWS_WITH(tension_impact_duration(StringBed{}, 0.0, 0.07),
                    Catch::Contains("ball_mass_kg"));
  CHECK_THROWS_WITH(tension_for_duration(StringBed{}, 0.0, 0.057, 0.07),
                    Catch::Contains("duration_s"));
  CHECK_THROWS_WITH(series_stiffness(4e4, 0.0), Catch::Contains("string_bed_stiffness_N_m"));
  bed = StringBed{};
  bed.cross_tension_ratio = 0.0;
  CHECK_THROWS_WITH(string_bed_ring_frequency(bed), Catch::Contains("bed.cross_tension_ratio"));
  bed = StringBed{};
  bed.main_linear_density_kg_m = std::nan("");
  CHECK_THROWS_WITH(string_bed_ring_frequency(bed),
                    Catch::Contains("bed.main_linear_density_kg_m"));
  bed = StringBed{};
  bed.tension_loss = 0.9;
  CHECK_THROWS_WITH(string_bed_stiffness(bed), Catch::Contains("bed.tension_loss"));
  CHECK_THROWS_WITH(tension_for_ring(StringBed{}, -1.0), Catch::Contains("frequency_Hz"));
}

}  // namespace
}  // namespace sweetspot
