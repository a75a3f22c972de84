#include "reports/response_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/format.hpp"
#include "io/json_reader.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::reports {
namespace {

// One pound-force [N], for tensions as stringers quote them.
constexpr double kNewtonsPerPoundForce = io::kPoundForce_N;

// Modes summed in the response (the paper saw one; the rest show 1.5/T at work).
constexpr int kResponseModes = 6;

std::vector<double> times(double until_s, int samples) {
  std::vector<double> t(samples);
  for (int i = 0; i < samples; ++i) t[i] = until_s * i / (samples - 1);
  return t;
}

}  // namespace

ResponseData compute_response(const io::DesignFile& file, const ResponseRequest& request) {
  try {
    ResponseData data{file, request, times(request.until_s, request.samples), {}, {}, {}};
    ResponseOptions options;
    options.support =
        request.hand_held ? ResponseOptions::Support::kHandHeld : ResponseOptions::Support::kFree;
    options.modes = kResponseModes;
    const ResponseModel model = response_model(file.design, options);
    std::vector<double> impacts = request.impacts_from_butt_m;
    if (impacts.empty()) impacts.push_back(file.design.impact_from_butt_m);
    for (const double x : impacts) {
      Design at = file.design;
      at.impact_from_butt_m = x;
      const Evaluation e = evaluate(at, needed_fidelity(at));
      const HalfSinePulse pulse{e.peak_impact_force_N, e.impact_duration_s};
      data.peak_force_N.push_back(pulse.peak_force_N);
      data.duration_s.push_back(pulse.duration_s);
      data.responses.push_back(
          impact_response(model, x, pulse, request.points_from_butt_m, data.time_s));
    }
    return data;
  } catch (const std::invalid_argument& e) {
    rethrow_in(file, e);
  }
}

std::string response_csv(const ResponseData& data) {
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

std::vector<io::Plot> response_plots(const ResponseData& data) {
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

std::vector<ReportEntry> write_response_reports(const std::string& designs_dir,
                                                const ReportWriter& write) {
  std::vector<ReportEntry> entries;

  // The paper's figures of the beam's motion: impacts every 6 cm from d = 4 cm,
  // observed 2 and 16 cm from the handle end; T about 8 ms (Sec. IV).
  const io::DesignFile beam = io::load_design(designs_dir + "/paper-beam.json");
  for (const bool held : {false, true}) {
    io::DesignFile file = beam;
    file.design.impact_duration_s = 0.008;
    file.design.ball.speed_m_s = held ? 3.2 : 1.2;  // Sec. II
    ResponseRequest request;
    request.hand_held = held;
    request.until_s = 0.03;
    for (double d = 0.04; d < 0.72; d += 0.06) request.impacts_from_butt_m.push_back(0.72 - d);
    const ResponseData data = compute_response(file, request);
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

  // The derived COR: the Table I racquet with a flexible frame, hit 5 cm from the tip.
  io::DesignFile racquet = io::load_design(designs_dir + "/table1/row1.json");
  racquet.design.stiffness.fundamental_free_Hz = 150.0;
  const ResponseModel model = response_model(racquet.design, ResponseOptions{});
  const Design& d = racquet.design;
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
  for (double f = 80.0; f <= 300.0; f += 10.0) {
    const ResponseModel scaled = with_fundamental(model, f);
    const DerivedCor a =
        derive_cor(scaled, d.impact_from_butt_m, 0.85, d.ball, d.impact_duration_s);
    const DerivedCor b =
        derive_cor(scaled, d.impact_from_butt_m, 0.90, d.ball, d.impact_duration_s);
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
  md +=
      "\n| cor_rigid | fundamental for e = 0.8 (Table I, stiff) | fundamental for e = 0.6 "
      "(flexible) |\n"
      "|---:|---:|---:|\n";
  std::string found;
  for (const double er : {0.85, 0.90}) {
    const auto stiff = fundamental_for_cor(model, d.impact_from_butt_m, er, d.ball,
                                           d.impact_duration_s, 0.8, 50, 1000, 1e-3);
    const auto flexible = fundamental_for_cor(model, d.impact_from_butt_m, er, d.ball,
                                              d.impact_duration_s, 0.6, 50, 1000, 1e-3);
    const auto hz = [](const std::optional<double>& f) {
      return f ? fmt::format("{:.0f} Hz", *f) : std::string("none");
    };
    md += fmt::format("| {:.2f} | {} | {} |\n", er, hz(stiff), hz(flexible));
    if (er == 0.90)
      found = fmt::format("with cor_rigid 0.90, e = 0.8 at {} and e = 0.6 at {}", hz(stiff),
                          hz(flexible));
  }
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

  // The impact duration from the string tension.
  const double M_eff = effective_mass(d.implement.mass_properties(), d.impact_from_butt_m);
  const StringBed bed;
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
  for (double t = 50.0; t <= 400.0; t += 25.0) {
    StringBed b = bed;
    b.tension_N = t;
    const TensionDuration r = tension_impact_duration(b, d.ball.mass_kg, M_eff);
    tcsv += fmt::format("{},{},{},{}\n", io::exact(t), io::exact(t / kNewtonsPerPoundForce),
                        io::exact(r.duration_s), io::exact(r.string_bed_stiffness_N_m));
    tmd += fmt::format("| {:.0f} | {:.0f} | {:.2f} | {:.1f} |\n", t, t / kNewtonsPerPoundForce,
                       r.duration_s * 1e3, r.string_bed_stiffness_N_m / 1e3);
    series.x.push_back(t);
    series.y.push_back(r.duration_s * 1e3);
  }
  const auto t4 = tension_for_duration(bed, 0.004, d.ball.mass_kg, M_eff);
  const auto t6 = tension_for_duration(bed, 0.006, d.ball.mass_kg, M_eff);
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
  return entries;
}

}  // namespace sweetspot::reports
