#include "studies/tension_study.hpp"

#include "io/design_reader.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {
namespace {

// The design strung at `tension_N` with a free fundamental `f1_Hz`, solved.
TensionPoint solve(Design d, double tension_N, double f1_Hz) {
  d.stiffness.EI_N_m2.reset();
  d.stiffness.fundamental_free_Hz = f1_Hz;
  if (!d.strings) d.strings = StringBed{};
  d.strings->tension_N = tension_N;
  d.cor_given = false;
  d.cor_rigid.reset();
  const Evaluation e = evaluate(d, Fidelity::kCollision);
  const CollisionResult& c = *e.details->collision;
  double frame_J = 0.0;
  for (const double mode : c.mode_energy_J) frame_J += mode;
  return {tension_N,
          f1_Hz,
          e.rebound_speed_m_s,
          c.contact_time_s,
          frame_J,
          e.peak_wrist_force_N,
          c.peak_force_N,
          c.peak_ball_compression_m};
}

// The free fundamental [Hz] in [lo, hi] at which the Table I racquet's COR
// at its impact point is `target` (bisection; e rises with f1 there).
std::optional<double> fundamental_for(const Design& d, double tension_N, double target, double lo,
                                      double hi) {
  auto cor = [&](double f1) {
    Design x = d;
    x.stiffness.EI_N_m2.reset();
    x.stiffness.fundamental_free_Hz = f1;
    x.strings = StringBed{};
    x.strings->tension_N = tension_N;
    x.cor_given = false;
    return evaluate(x, Fidelity::kCollision).cor - target;
  };
  double flo = cor(lo), fhi = cor(hi);
  if (flo * fhi > 0) return std::nullopt;
  for (int i = 0; i < 30 && hi - lo > 0.1; ++i) {
    const double mid = 0.5 * (lo + hi), fm = cor(mid);
    (fm * flo <= 0 ? hi : lo) = mid;
    if (fm * flo > 0) flo = fm;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TensionStudy tension_study(const std::string& designs_dir) {
  const io::DesignFile racquet = io::load_design(designs_dir + "/racquets/tour-100.json");
  const Design& d = racquet.design;
  TensionStudy study;
  study.ball_speed_m_s = d.ball.speed_m_s;
  study.tensions_N = {180, 190, 200, 210, 220, 230, 240, 250, 260, 270, 280, 290, 300};
  study.frequencies_Hz = {100, 125, 155, 175, 200};
  for (const double f1 : study.frequencies_Hz)
    for (const double t : study.tensions_N) study.grid.push_back(solve(d, t, f1));
  study.low = solve(d, 180.0, 155.0);
  study.high = solve(d, 280.0, 155.0);
  for (const double mass : {0.001, 0.002, 0.004, 0.008}) {
    for (const double zeta : {0.0, 0.008, 0.02}) {
      Design x = d;
      x.string_bed_mass_kg = mass;
      x.string_bed_damping_ratio = zeta;
      study.bed.push_back(
          {mass, zeta, solve(x, 180.0, 155.0), solve(x, 280.0, 155.0), solve(x, 250.0, 155.0)});
    }
  }
  const io::DesignFile table1 = io::load_design(designs_dir + "/table1/row1.json");
  for (const double t : {180.0, 250.0}) {
    study.table1.push_back({t, fundamental_for(table1.design, t, 0.8, 50.0, 1000.0),
                            fundamental_for(table1.design, t, 0.6, 50.0, 1000.0)});
  }
  return study;
}

}  // namespace sweetspot::studies
