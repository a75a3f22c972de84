#include "studies/response.hpp"

#include "sweetspot/errors.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::studies {
namespace {

// Modes summed in the response (the paper saw one; the rest show 1.5/T at work).
constexpr int kResponseModes = 6;

std::vector<double> times(double until_s, int samples) {
  std::vector<double> t(samples);
  for (int i = 0; i < samples; ++i) t[i] = until_s * i / (samples - 1);
  return t;
}

// The Table I racquet with a flexible frame (150 Hz), hit 5 cm from the tip.
io::DesignFile flexible_table1_racquet(const std::string& designs_dir) {
  io::DesignFile racquet = io::load_design(designs_dir + "/table1/row1.json");
  racquet.design.stiffness.fundamental_free_Hz = 150.0;
  return racquet;
}

}  // namespace

ResponseData compute_response(const io::DesignFile& file, const ResponseRequest& request) {
  try {
    if (file.design.support.kind == Support::Kind::kRigidSurface)
      throw FieldError("support", "a rigid surface has no implement, so no response");
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

PaperBeamResponses paper_beam_responses(const std::string& designs_dir) {
  const io::DesignFile beam = io::load_design(designs_dir + "/paper-beam.json");
  const auto at = [&](bool held) {
    io::DesignFile file = beam;
    file.design.impact_duration_s = 0.008;
    file.design.ball.speed_m_s = held ? 3.2 : 1.2;  // Sec. II
    ResponseRequest request;
    request.hand_held = held;
    request.until_s = 0.03;
    for (double d = 0.04; d < 0.72; d += 0.06) request.impacts_from_butt_m.push_back(0.72 - d);
    return compute_response(file, request);
  };
  return PaperBeamResponses{at(false), at(true)};  // in order: braces evaluate left to right
}

CorFromStiffness cor_from_stiffness(const std::string& designs_dir) {
  const io::DesignFile racquet = flexible_table1_racquet(designs_dir);
  const ResponseModel model = response_model(racquet.design, ResponseOptions{});
  const Design& d = racquet.design;
  CorFromStiffness study;
  for (double f = 80.0; f <= 300.0; f += 10.0) {
    const ResponseModel scaled = with_fundamental(model, f);
    CorAtFundamental row{
        f, derive_cor(scaled, d.impact_from_butt_m, 0.85, d.ball, d.impact_duration_s), {}};
    row.at_090 = derive_cor(scaled, d.impact_from_butt_m, 0.90, d.ball, d.impact_duration_s);
    study.rows.push_back(row);
  }
  for (const double er : {0.85, 0.90}) {
    FundamentalsForCor found{er, {}, {}};
    found.stiff_Hz = fundamental_for_cor(model, d.impact_from_butt_m, er, d.ball,
                                         d.impact_duration_s, 0.8, 50, 1000, 1e-3);
    found.flexible_Hz = fundamental_for_cor(model, d.impact_from_butt_m, er, d.ball,
                                            d.impact_duration_s, 0.6, 50, 1000, 1e-3);
    study.fundamentals.push_back(found);
  }
  return study;
}

DurationFromTension duration_from_tension(const std::string& designs_dir) {
  const io::DesignFile racquet = flexible_table1_racquet(designs_dir);
  const Design& d = racquet.design;
  DurationFromTension study;
  study.effective_mass_kg = effective_mass(d.implement.mass_properties(), d.impact_from_butt_m);
  const StringBed bed;
  for (double t = 50.0; t <= 400.0; t += 25.0) {
    StringBed b = bed;
    b.tension_N = t;
    study.rows.push_back({t, tension_impact_duration(b, d.ball.mass_kg, study.effective_mass_kg)});
  }
  study.tension_for_4_ms_N =
      tension_for_duration(bed, 0.004, d.ball.mass_kg, study.effective_mass_kg);
  study.tension_for_6_ms_N =
      tension_for_duration(bed, 0.006, d.ball.mass_kg, study.effective_mass_kg);
  return study;
}

ResponseReports response_reports(const std::string& designs_dir) {
  return ResponseReports{paper_beam_responses(designs_dir), cor_from_stiffness(designs_dir),
                         duration_from_tension(designs_dir)};
}

}  // namespace sweetspot::studies
