#include "reports/response_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/format.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::reports {
namespace {

// One pound-force [N], for tensions as stringers quote them.
constexpr double kNewtonsPerPoundForce = io::kPoundForce_N;

}  // namespace

std::string response_csv(const studies::ResponseData& data) {
  std::string csv = "impact_from_butt_m,t_s,point_from_butt_m,v_dc_m_s,v_ac_m_s,v_m_s\n";
  for (const ImpactResponse& r : data.responses) {
    const double x = data.request.impacts_from_butt_m.empty()
                         ? data.design.design.impact_from_butt_m
                         : data.request.impacts_from_butt_m[&r - &data.responses[0]];
    for (const PointVelocity& p : r.points) {
      for (std::size_t i = 0; i < r.time_s.size(); ++i) {
        csv += fmt::format("{},{},{},{},{},{}\n", io::exact(x), io::exact(r.time_s[i]),
                           io::exact(p.from_butt_m), io::exact(p.dc_m_s[i]), io::exact(p.ac_m_s[i]),
                           io::exact(p.dc_m_s[i] + p.ac_m_s[i]));
      }
    }
  }
  return csv;
}

std::vector<io::Plot> response_plots(const studies::ResponseData& data) {
  const double L = data.design.design.implement.length_m();
  std::vector<io::Plot> plots;
  for (std::size_t k = 0; k < data.request.points_from_butt_m.size(); ++k) {
    const double point = data.request.points_from_butt_m[k];
    // Shift the traces apart by a little more than the largest swing, as the paper does.
    double swing = 0.0;
    for (const ImpactResponse& r : data.responses) {
      for (std::size_t i = 0; i < r.time_s.size(); ++i) {
        swing = std::max(swing, std::abs(r.points[k].dc_m_s[i] + r.points[k].ac_m_s[i]));
      }
    }
    // Each impact's trace sits below the one before (the first impact at the
    // top, as the key lists them), shifted by a little more than the largest
    // swing, with a dotted line of its colour at its own zero.
    const double shift = data.responses.size() > 1 ? 1.2 * swing : 0.0;
    io::Plot plot{
        fmt::format("Velocity {:.0f} cm from the tip ({:.0f} cm from the handle end), {} "
                    "(cf. Cross 2004 Figs. {})",
                    (L - point) * 100, point * 100, data.request.hand_held ? "hand-held" : "free",
                    data.request.hand_held ? "6 and 7" : "3 and 4"),
        "time (ms)",
        shift > 0 ? fmt::format("velocity (m/s), traces {} m/s apart", io::significant(shift, 2))
                  : std::string("velocity (m/s)"),
        std::nullopt,
        std::nullopt,
        {},
        {},
        {}};
    plot.key_title = shift > 0 ? "impact d (dotted: its zero)" : "impact";
    plot.key_position = "outside right";
    for (std::size_t j = 0; j < data.responses.size(); ++j) {
      const ImpactResponse& r = data.responses[j];
      const double x = data.request.impacts_from_butt_m.empty()
                           ? data.design.design.impact_from_butt_m
                           : data.request.impacts_from_butt_m[j];
      const double offset = -shift * static_cast<double>(j);
      io::PlotSeries s{fmt::format("d = {:.0f} cm", (L - x) * 100), {}, {}, "lines lw 1.5"};
      s.color = io::plot_color(j);
      for (std::size_t i = 0; i < r.time_s.size(); ++i) {
        s.x.push_back(r.time_s[i] * 1e3);
        s.y.push_back(r.points[k].dc_m_s[i] + r.points[k].ac_m_s[i] + offset);
      }
      plot.series.push_back(std::move(s));
      // The rigid body's (dc) part dashed in the same colour: the vibration's
      // (ac) part is the solid line's swing about it, as Cross draws the two.
      io::PlotSeries dc{j == 0 ? "dc part (dashed)" : "", {}, {}, "lines lw 1 dt 2"};
      dc.color = io::plot_color(j);
      for (std::size_t i = 0; i < r.time_s.size(); ++i) {
        dc.x.push_back(r.time_s[i] * 1e3);
        dc.y.push_back(r.points[k].dc_m_s[i] + offset);
      }
      plot.series.push_back(std::move(dc));
    }
    for (std::size_t j = 0; j < data.responses.size() && shift > 0; ++j) {
      const double offset = -shift * static_cast<double>(j);
      io::PlotSeries zero{"", {}, {}, "lines lw 1 dt 3"};
      zero.color = io::plot_color(j);
      zero.x = {data.time_s.front() * 1e3, data.time_s.back() * 1e3};
      zero.y = {offset, offset};
      plot.series.push_back(std::move(zero));
    }
    plots.push_back(std::move(plot));
  }
  return plots;
}

namespace {

// response-free and response-hand-held: the paper beam's motion.
void write_beam_motion(const studies::PaperBeamResponses& beam, const ReportWriter& write,
                       std::vector<ReportEntry>& entries) {
  // The paper's figures of the beam's motion: impacts every 6 cm from d = 4 cm,
  // observed 2 and 16 cm from the handle end; T about 8 ms (Sec. IV).
  for (const bool held : {false, true}) {
    const studies::ResponseData& data = held ? beam.hand_held : beam.free;
    const std::vector<io::Plot> plots = response_plots(data);
    const std::string stem = held ? "response-hand-held" : "response-free";
    write.text(stem + ".csv", response_csv(data));
    write.plot(stem + "-at-2cm.png", plots[0]);
    write.plot(stem + "-at-16cm.png", plots[1]);
    entries.push_back(
        {fmt::format("[{0}.csv]({0}.csv), [2 cm]({0}-at-2cm.png), [16 cm]({0}-at-16cm.png)", stem),
         held ? "The hand-held beam's velocity 2 and 16 cm from the handle end for impacts every 6 "
                "cm (Cross "
                "2004 Figs. 6 and 7, 3.2 m/s): the hand damps the vibration and the handle end "
                "barely moves."
              : "The free beam's velocity 2 and 16 cm from the handle end for impacts every 6 cm "
                "(Cross 2004 "
                "Figs. 3 and 4, 1.2 m/s, T = 8 ms): at d = 22 cm the dc velocity 2 cm from the end "
                "is "
                "almost zero (its COP is at 23.3 cm); at the nodes (d = 16 and 56 cm) the "
                "fundamental is "
                "absent."});
  }
}

// The fundamentals that give the paper's 0.8 and 0.6 at each cor_rigid, and
// in `found` the sentence for cor_rigid 0.90.
std::string fundamentals_md(const studies::CorFromStiffness& computed, std::string& found) {
  std::string md =
      "\n| cor_rigid | fundamental for e = 0.8 (Table I, stiff) | fundamental for e = 0.6 "
      "(flexible) |\n"
      "|---:|---:|---:|\n";
  for (const studies::FundamentalsForCor& fundamentals : computed.fundamentals) {
    const double er = fundamentals.cor_rigid;
    const std::optional<double>&stiff = fundamentals.stiff_Hz, &flexible = fundamentals.flexible_Hz;
    const auto hz = [](const std::optional<double>& f) {
      return f ? fmt::format("{:.0f} Hz", *f) : std::string("none");
    };
    md += fmt::format("| {:.2f} | {} | {} |\n", er, hz(stiff), hz(flexible));
    if (er == 0.90)
      found = fmt::format("with cor_rigid 0.90, e = 0.8 at {} and e = 0.6 at {}", hz(stiff),
                          hz(flexible));
  }
  return md;
}

// cor-from-stiffness: the derived COR against the free fundamental.
void write_cor_from_stiffness(const studies::CorFromStiffness& computed, const ReportWriter& write,
                              std::vector<ReportEntry>& entries) {
  // The derived COR: the Table I racquet with a flexible frame, hit 5 cm from the tip.
  std::string csv = "fundamental_free_Hz,cor_rigid,cor,vibration_share,peak_impact_force_N\n";
  std::string md =
      "# The COR from the frame's stiffness\n\n"
      "The Table I racquet (0.70 m, 0.25 kg, M1/M2 = 0.8, uniform EI) hit 5 cm from the tip by a "
      "57 g ball "
      "at 50 m/s, T = 4 ms. The COR at the impact point is the COR the ball and strings would have "
      "on a "
      "rigid frame (`cor_rigid`) lowered by the energy the free frame keeps as vibration, solved "
      "together "
      "with the impact force (docs/model.md: the derived COR).\n\n"
      "| free fundamental (Hz) | e (cor_rigid 0.85) | vibration share | e (cor_rigid 0.90) | "
      "vibration share |\n"
      "|---:|---:|---:|---:|---:|\n";
  io::PlotSeries e85{"cor_rigid 0.85", {}, {}, "lines lw 2"};
  io::PlotSeries e90{"cor_rigid 0.90", {}, {}, "lines lw 2"};
  for (const studies::CorAtFundamental& row : computed.rows) {
    const double f = row.fundamental_free_Hz;
    const DerivedCor &a = row.at_085, &b = row.at_090;
    for (const DerivedCor* c : {&a, &b}) {
      csv +=
          fmt::format("{},{},{},{},{}\n", io::exact(f), io::exact(c->cor_rigid), io::exact(c->cor),
                      io::exact(c->vibration_share), io::exact(c->pulse.peak_force_N));
    }
    md += fmt::format("| {:.0f} | {:.3f} | {:.1f} % | {:.3f} | {:.1f} % |\n", f, a.cor,
                      100 * a.vibration_share, b.cor, 100 * b.vibration_share);
    e85.x.push_back(f);
    e85.y.push_back(a.cor);
    e90.x.push_back(f);
    e90.y.push_back(b.cor);
  }
  std::string found;
  md += fundamentals_md(computed, found);
  md +=
      "\nFree racquet frames run about 100-180 Hz. In this model a frame reaches the paper's "
      "\"flexible\" "
      "0.6 inside that range, but the \"stiff\" 0.8 only above it: the model lets the frame keep "
      "more "
      "energy than a real one, because the force is prescribed (the frame's give does not soften "
      "and "
      "lengthen the impact) and the ball loads a point of a one-dimensional beam rather than a "
      "hoop.\n";
  write.text("cor-from-stiffness.md", md);
  write.text("cor-from-stiffness.csv", csv);
  write.plot(
      "cor-from-stiffness.png",
      io::Plot{
          "Derived COR against the free fundamental (Table I racquet, 5 cm from the tip, T = 4 ms)",
          "free fundamental (Hz)",
          "COR e at the impact point",
          std::nullopt,
          std::pair{0.0, 1.0},
          {e85, e90},
          {},
          {{100.0, "100 Hz"}, {180.0, "180 Hz"}}});
  entries.push_back(
      {"[cor-from-stiffness.md](cor-from-stiffness.md), [.csv](cor-from-stiffness.csv), "
       "[.png](cor-from-stiffness.png)",
       "The COR derived from the frame's stiffness for the Table I racquet: " + found + "."});
}

// duration-from-tension: the impact duration against the string tension.
void write_duration_from_tension(const studies::DurationFromTension& computed,
                                 const ReportWriter& write, std::vector<ReportEntry>& entries) {
  // The impact duration from the string tension.
  const double M_eff = computed.effective_mass_kg;
  std::string tcsv = "tension_N,tension_lb,impact_duration_s,string_bed_stiffness_N_m\n";
  std::string tmd =
      "# The impact duration from the string tension\n\n"
      "Ball and string bed as springs in series meeting the effective mass at the impact point "
      "(Eq. 17): "
      "T = pi sqrt(mu/k). The string bed is a tensioned membrane (100 in^2 head, strings 16.5 mm "
      "apart, the "
      "ball's contact 3 cm in radius); the ball is a 40 kN/m spring. The Table I racquet 5 cm from "
      "the tip "
      "(M_eff = " +
      io::significant(M_eff, 3) +
      " kg).\n\n| tension (N) | tension (lb) | T (ms) | string bed (kN/m) "
      "|\n|---:|---:|---:|---:|\n";
  io::PlotSeries series{"T against tension", {}, {}, "lines lw 2"};
  for (const studies::DurationAtTension& row : computed.rows) {
    const double t = row.tension_N;
    const TensionDuration& r = row.duration;
    tcsv += fmt::format("{},{},{},{}\n", io::exact(t), io::exact(t / kNewtonsPerPoundForce),
                        io::exact(r.duration_s), io::exact(r.string_bed_stiffness_N_m));
    tmd += fmt::format("| {:.0f} | {:.0f} | {:.2f} | {:.1f} |\n", t, t / kNewtonsPerPoundForce,
                       r.duration_s * 1e3, r.string_bed_stiffness_N_m / 1e3);
    series.x.push_back(t);
    series.y.push_back(r.duration_s * 1e3);
  }
  const std::optional<double>&t4 = computed.tension_for_4_ms_N, &t6 = computed.tension_for_6_ms_N;
  const auto show = [](const std::optional<double>& t) {
    return t ? fmt::format("{:.0f} N ({:.0f} lb)", *t, *t / kNewtonsPerPoundForce)
             : std::string("no tension");
  };
  const std::string where = fmt::format("T = 4 ms at {}, T = 6 ms at {}", show(t4), show(t6));
  tmd += "\nTable I's durations: " + where +
         ". Players string at 200-300 N (45-65 lb), where this model gives 3.5-3.8 ms: the paper's "
         "6 ms "
         "\"soft strings\" needs a softer ball or a longer contact than springs in series give.\n";
  write.text("duration-from-tension.md", tmd);
  write.text("duration-from-tension.csv", tcsv);
  write.plot("duration-from-tension.png", [&] {
    io::Plot plot{"Impact duration against string tension (Table I racquet, 5 cm from the tip)",
                  "string tension (N)",
                  "impact duration T (ms)",
                  std::nullopt,
                  std::nullopt,
                  {series},
                  {},
                  {}};
    plot.x2 = io::SecondXAxis{"string tension (lb, as stringers quote it)",
                              1.0 / kNewtonsPerPoundForce, 10.0};
    return plot;
  }());
  entries.push_back(
      {"[duration-from-tension.md](duration-from-tension.md), [.csv](duration-from-tension.csv), "
       "[.png](duration-from-tension.png)",
       "The impact duration derived from string tension: " + where + "."});
}

}  // namespace

std::vector<ReportEntry> write_response_reports(const studies::ResponseReports& computed,
                                                const ReportWriter& write) {
  std::vector<ReportEntry> entries;
  write_beam_motion(computed.beam, write, entries);
  write_cor_from_stiffness(computed.cor, write, entries);
  write_duration_from_tension(computed.duration, write, entries);
  return entries;
}

}  // namespace sweetspot::reports
